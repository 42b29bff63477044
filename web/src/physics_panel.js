// The run panel's physics switch beside Simulate: kinematic (foldkit's fast referee) or physics
// (`simulate --model dynamic`: masses, gravity, torque-limited motors; the sheet's density, the
// scale, the fixed actor, a ground, the start state, motors or springs (physics.js's DRIVES) and
// the solver, as physics.js's SOLVERS; the
// pattern's own density, gravity and fixed actor are the fields' defaults). After a physical run the
// page shows its verdict, the selected joints' torque against time and the stalls on the
// timeline; the numbers are foldkit's (`--json` and the series it wrote, NAME-series.json).
import { $, app, log } from './page.js';
import { physicsOptions, physicsDefaults, physicsVerdict, stallLabel } from './physics.js';
import { TorquePlot, plottedJoints } from './torque_plot.js';

const plot = new TorquePlot($('torque-plot'));

/** Whether the switch (kinematic / physics) says physics. */
export const physicsOn = () => $('sim-model').value === 'physics';

/** `simulate`'s options from the run panel, or null (with the reason in the log) when a
 * physics field is wrong. Kinematic: collision checks as ticked; physics: the model's own
 * options, with facet–facet contacts (`--contacts`) as the collisions box is ticked. */
export function simulateOptions() {
  const ticked = $('collisions').checked;
  if (!physicsOn()) return ticked ? {} : { 'no-collision': true };
  const { options, error } = physicsOptions({ gravity: $('gravity').value, torque: $('max-torque').value,
    density: $('density').value, fixed: $('fixed-actor').value, ground: $('ground').value, scale: $('physics-scale').value,
    solver: $('physics-solver').value, drive: $('physics-drive').value });
  if (error) {
    log(error);
    return null;
  }
  return ticked ? { ...options, contacts: true } : options;
}

/** Whether a physical run starts from the state the 3D view shows (--start) rather than flat. */
export const startFromShown = () => physicsOn() && $('physics-start').checked;

/** The physics fields from a pattern just opened or generated: its own density, gravity and
 * fixed actor (PMML's extensions) where it has them, else the page's defaults (physics.js,
 * physicsDefaults); the run then sends what the file says unless a field is changed. */
export function physicsFromPattern(model) {
  const d = physicsDefaults(model.physics);
  $('density').value = d.density;
  $('gravity').value = d.gravity;
  $('fixed-actor').value = d.fixed;
}

function showSwitch() {
  const on = physicsOn();
  $('physics-fields').hidden = !on;
  $('collisions').parentElement.title = on
    ? 'physics: facets touch and push instead of passing through (--contacts)'
    : 'check every step for self-collision';
}

/** Wires the switch (the fields show only with physics on). */
export function wirePhysics() {
  $('sim-model').addEventListener('change', showSwitch);
  showSwitch();
}

// The joints the plot shows: the selected ones, else those that stalled or pulled hardest.
function draw(sim, time) {
  const joints = plottedJoints(app.editor.selection.joints || [], sim.result, sim.series);
  plot.show({ series: sim.series, joints, stalls: sim.result.stalls || [], limit: sim.result.max_torque, time });
  $('torque-joints').textContent = joints.length ? joints.join(', ') : 'none';
}

/** Shows a simulation's physics (or takes the last one's away): the verdict, the torque plot,
 * the stalls on the timeline. */
export function showPhysics(sim, time = 0) {
  const series = sim && sim.series;
  $('torque-panel').hidden = !series;
  if (!series) {
    plot.clear();
    app.timeline.markStalls([], stallLabel);
    return;
  }
  $('physics-verdict').textContent = physicsVerdict(sim.result);
  $('physics-verdict').classList.toggle('stalled', (sim.result.stalls || []).length > 0);
  app.timeline.markStalls(sim.result.stalls || [], stallLabel);
  draw(sim, time);
}

/** The plot follows the joints selected (a physical run on screen only). */
export function physicsSelectionChanged() {
  const sim = app.simulation;
  if (sim && sim.series) draw(sim, app.timeline.timeAt(app.timeline.frame));
}

/** The plot's cursor at the time the 3D view shows. */
export function physicsTime(time) {
  plot.setTime(time);
}
