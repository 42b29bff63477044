// The page: the 2D editor, the 3D view, the numbers foldkit reports, the fold sequence and its
// timeline. The browser draws and edits; every check and computation is a foldkit verb.
import * as api from './api.js';
import { Editor2D } from './editor2d.js';
import { View3D } from './view3d.js';
import { Timeline } from './timeline.js';
import { emptySequence, setFold, readCMML, writeCMML, anglesAfterEvents } from './cmml.js';
import * as session from './session.js';
import { StateNumbers, SIMULATING } from './numbers.js';
import { opensPattern, opensSequence } from './formats.js';
import { fillPlanners } from './planners.js';
import { opening } from './boot.js';
import { $, app, files, log, setNumber, task, checkedValid } from './page.js';
import { showProblemList } from './problems.js';
import { parameters, download, baseName } from './page_fields.js';
import { stiffnessNow } from './stiffness_panel.js';
import { simulateOptions, showPhysics, physicsSelectionChanged, physicsTime, wirePhysics, physicsFromPattern, startFromShown } from './physics_panel.js';

// --- the pattern -----------------------------------------------------------------------------

const editor = new Editor2D($('canvas2d'), {
  model: app.model,
  onChange: (model) => patternChanged(model),
  onSelect: (selection) => selectionChanged(selection),
  onStatus: (text) => { $('hint').textContent = text; },
});
const view = new View3D($('view3d'));
// DOF and closure error of the state the 3D view shows, never of another (numbers.js).
const stateNumbers = new StateNumbers({ dof: $('n-dof'), closure: $('closure-state') });
app.editor = editor;
app.view = view;
app.stateNumbers = stateNumbers;

let checkTimer = null;
function patternChanged(model) {
  app.model = model;
  app.simulation = null;
  app.stateDof = null;
  timeline.setTrajectory(0, 0, []);
  showPhysics(null);
  // Folds of joints an edit removed stay in the sequence (undo may bring the joints back); foldkit
  // is given the others (session.sequencePath).
  showSequence();
  view.setPattern(session.viewPattern(model));
  view.setAngles(new Float64Array(model.joints().length));
  stateNumbers.showFlat();
  for (const id of ['n-actors', 'n-joints', 'closure-max', 'n-collisions', 'verdict']) setNumber(id, null);
  clearTimeout(checkTimer);
  checkTimer = setTimeout(() => checkNow(), 300);
}

// Whether `model` at `version` is still what the page shows (the editor edits it in place).
function current(model, version) {
  return model === app.model && model.version === version;
}

// The check of one version of the pattern, shared by whoever asks while it runs or after.
let lastCheck = null;

/** Saves the pattern and shows foldkit's verdict on it; resolves when the numbers are shown. */
async function checkNow() {
  clearTimeout(checkTimer);
  const model = app.model;
  const version = model.version;
  if (!model.triangles.length) return null;
  const name = files().pattern;
  if (!lastCheck || lastCheck.model !== model || lastCheck.version !== version || lastCheck.name !== name)
    lastCheck = { model, version, name, answer: task('check', () => session.checkPattern(model, files())) };
  const asked = lastCheck;
  const check = await asked.answer;
  if (!check && lastCheck === asked) lastCheck = null;  // a failed request is asked again next time
  // An edit while foldkit checked: its answer is about a pattern no longer shown.
  if (!check || !current(model, version)) return null;
  app.check = check;
  showProblems(check.problems);
  if (check.ok) {
    setNumber('n-actors', check.info.actors);
    setNumber('n-joints', check.info.joints);
    stateNumbers.flatMeasured(check.dof);  // only while the view shows the flat sheet
  }
  return check;
}
app.checkNow = checkNow;

function showProblems(problems) {
  showProblemList($('problems'), editor, app.model, problems);
}

// --- joints and the sequence -----------------------------------------------------------------

function selectionChanged(selection) {
  const ids = selection.joints || [];
  $('selected-joints').textContent = ids.length ? ids.join(', ') : 'none';
  const joints = app.model.joints().filter((j) => ids.includes(j.id));
  if (joints.length) {
    $('spring').value = joints[0].spring;
    $('damping').value = joints[0].damping;
    $('joint-torque').value = joints[0].maxTorque ?? '';
    const event = app.sequence.events.find((e) => e.number === app.currentEvent);
    const fold = event && event.folds.find((f) => f.joint === joints[0].id);
    if (fold) {
      $('fold-angle').value = fold.angle;
      $('fold-speed').value = fold.speed;
    }
  }
  if (selection.actors && selection.actors.length && !$('load-actor').value) $('load-actor').value = selection.actors[selection.actors.length - 1];
  physicsSelectionChanged();
}

// The sequence no longer matches the file it was read from, nor the last simulation.
function sequenceEdited() {
  delete app.sequence.file;
  app.sequenceEdits++;
}

function showSequence() {
  timeline.setEvents(app.sequence, app.currentEvent);
  $('event-number').value = app.currentEvent;
}

/** Sets the selected joints' fold in the current event (the fold panel's inputs). */
function setSelectedFolds() {
  const ids = editor.selection.joints || [];
  if (!ids.length) return log('select one or more joints first (Select tool, click a crease)');
  const angle = Number($('fold-angle').value);
  const speed = Number($('fold-speed').value);
  if (!(angle >= -180 && angle <= 180)) return log('the fold angle must be in [-180, 180] degrees');
  if (!(speed > 0)) return log('the speed must be positive (degrees per second)');
  app.currentEvent = Number($('event-number').value) || 0;
  for (const joint of ids) setFold(app.sequence, app.currentEvent, { joint, angle, speed });
  sequenceEdited();
  showSequence();
  previewEnd();
}

function unsetSelectedFolds() {
  const ids = new Set(editor.selection.joints || []);
  const event = app.sequence.events.find((e) => e.number === app.currentEvent);
  if (event) event.folds = event.folds.filter((f) => !ids.has(f.joint));
  app.sequence.events = app.sequence.events.filter((e) => e.folds.length);
  sequenceEdited();
  showSequence();
}

// Before a simulation, the 3D view shows the commanded end state (not yet checked by foldkit).
function previewEnd(why) {
  const joints = app.model.joints();
  const after = anglesAfterEvents(app.sequence, joints.map((j) => j.id));
  const last = after.length ? after[after.length - 1] : joints.map(() => 0);
  view.setAngles(Float64Array.from(last, (d) => (d * Math.PI) / 180));
  stateNumbers.showPreview(why);
}

function moveEvent(delta) {
  const events = app.sequence.events;
  const k = events.findIndex((e) => e.number === app.currentEvent);
  const other = events[k + delta];
  if (k < 0 || !other) return;
  [events[k].folds, other.folds] = [other.folds, events[k].folds];
  sequenceEdited();
  app.currentEvent = other.number;
  showSequence();
}

const timeline = new Timeline($('timeline'), {
  onEvent: (number) => { app.currentEvent = number; showSequence(); },
  onScrub: (frame) => showFrame(frame),
  onScrubEnd: (frame) => measureState(frame),
});
app.timeline = timeline;

// --- simulation and the 3D view --------------------------------------------------------------

// The frame index the view shows for scrubber position `frame`.
function frameIndex(sim, frame) {
  return Math.min(frame, sim.frames.length - 1);
}

function showFrame(frame) {
  const sim = app.simulation;
  if (!sim || !sim.frames.length) return;
  view.setAngles(sim.frames[frameIndex(sim, frame)]);
  stateNumbers.showFrame(sim, frameIndex(sim, frame));  // the numbers wait for the scrubber to rest
  const t = timeline.timeAt(frame);
  const actorIndex = new Map(app.model.actors().map((id, k) => [id, k]));
  physicsTime(t);
  const hit = (sim.result.collisions || []).filter((c) => c.time <= t + 1e-9);  // none in a physical report
  if (hit.length) view.highlight({ actors: hit.flatMap((c) => c.actors.map((a) => actorIndex.get(a))), points: hit.map((c) => c.point) });
  else view.clearHighlight();
  timeline.showClock();
}

// foldkit's DOF and closure error at the state the scrubber rests on; shown only if that frame
// is still on screen when the answer comes.
async function measureState(frame) {
  const sim = app.simulation;
  if (!sim || !sim.frames.length) return null;
  const k = frameIndex(sim, frame);
  const token = stateNumbers.showFrame(sim, k);
  if (token.answer) return app.stateDof;
  const joints = app.model.joints();
  const degrees = Array.from(sim.frames[k], (r) => (r * 180) / Math.PI);
  const dof = await task('dof', () => session.stateDof(sim.files, joints.map((j) => j.id), degrees));
  if (dof && stateNumbers.frameMeasured(token, dof, sim.result.closure_tolerance)) app.stateDof = dof;
  return dof;
}

/** Simulates the sequence and shows its trajectory, collisions and closure. */
async function simulateNow() {
  const check = await checkNow();
  if (!checkedValid(check)) return null;
  if (!app.sequence.events.length) return log('no folds yet: select joints and press "Set fold"');
  const options = simulateOptions();
  if (!options) return null;
  const { model } = app;
  const version = model.version;
  const f = files();
  const { sequence, sequenceEdits } = app;
  // The state shown, in degrees per joint (model.joints() order), when the run starts from it.
  const start = startFromShown() ? Array.from(view.angles(), (r) => (r * 180) / Math.PI) : null;
  const sim = await task('simulate', () => session.simulate(model, sequence, f, options, start));
  if (!sim) return null;
  if (!current(model, version)) return log('the pattern changed while it was simulated: simulate again');
  sim.files = f;
  sim.sequence = sequence;
  sim.sequenceEdits = sequenceEdits;
  app.simulation = sim;
  const r = sim.result;
  setNumber('closure-max', r.max_closure_error);
  setNumber('n-collisions', r.collision_count);
  $('verdict').textContent = r.status === 'success' ? 'valid' : `invalid: ${r.status}`;
  log(sim.log);
  timeline.setTrajectory(sim.frames.length, r.duration, r.collisions || [], sim.times);
  showPhysics(sim, timeline.timeAt(timeline.frame));
  // Framed on the first state (the flat sheet, as a rule the widest), so no frame leaves the view.
  if (sim.frames.length) view.setAngles(sim.frames[0]);
  view.fit();
  showFrame(timeline.frame);
  await measureState(timeline.frame);
  return sim;
}
app.simulateNow = simulateNow;

// A sequence's end state is on screen at once; the trajectory and every number follow from simulate.
async function loadSequence(sequence) {
  app.sequence = sequence;
  app.currentEvent = sequence.events.length ? sequence.events[sequence.events.length - 1].number : 1;
  showSequence();
  previewEnd(SIMULATING);
  performance.mark('foldkit:end-state-shown');
  return simulateNow();
}

async function foldNow() {
  const check = await checkNow();
  if (!checkedValid(check)) return;
  const options = $('collisions').checked ? {} : { 'no-collision': true };
  const out = await task('fold', () => session.foldTo(files(), Number($('fraction').value), options));
  if (!out) return;
  log(out.run.log);
  if (out.sequence) await loadSequence(out.sequence);
}

async function planNow() {
  const check = await checkNow();
  if (!checkedValid(check)) return;
  if (!app.sequence.events.length) return log('plan needs a goal: set folds whose end state is the goal');
  const options = { time: Number($('plan-time').value), seed: Number($('plan-seed').value) };
  // No name (the server's list did not come): plan runs foldkit's default planner.
  if ($('planner').value) options.planner = $('planner').value;
  if (!$('collisions').checked) options['no-collision'] = true;
  const out = await task('plan', () => session.plan(app.model, app.sequence, files(), options));
  if (!out) return;
  log(out.run.log);
  if (out.sequence) await loadSequence(out.sequence);
  else $('verdict').textContent = `no plan (exit ${out.run.exit})`;
}

// --- files -----------------------------------------------------------------------------------

function setModel(model) {
  physicsFromPattern(model);
  editor.setModel(model);
  editor.resize();
  editor.fit();
  patternChanged(model);
  view.fit({ reset: true });
}

async function generateNow(kind) {
  if (!kind) return;
  const model = await task('generate', () => session.generate(kind, parameters($('generate-params').value), files()));
  if (model) {
    app.sequence = emptySequence();
    setModel(model);
  }
  return model;
}
app.generateNow = generateNow;

async function openNow(path, opened = undefined) {  // opened: session.open's answer, asked for already
  if (!path) return;
  const answer = await task('open', () => opened ?? session.open(path, files(), app.formats));
  if (!answer) return;
  if (answer.model) {
    app.sequence = emptySequence();
    setModel(answer.model);
  }
  if (answer.sequence) await loadSequence(answer.sequence);
}

async function listOpenable() {
  const listing = await task('files', () => api.listFiles(''));
  if (!listing) return;
  const select = $('open');
  select.replaceChildren(new Option('Open…', ''));
  const opens = (name) => opensPattern(app.formats, name) || opensSequence(app.formats, name);
  for (const e of listing.entries) if (e.type === 'file' && opens(e.name)) select.append(new Option(e.name, e.name));
}

// The simulated trajectory foldkit wrote (NAME-frames.fold: every frame, its time as
// "foldkit:time"), as long as it is the trajectory of the folds the page holds now.
async function saveTrajectory() {
  const sim = app.simulation;
  if (!sim) return log('nothing simulated yet: press Simulate first');
  if (sim.sequence !== app.sequence || sim.sequenceEdits !== app.sequenceEdits)
    return log('the folds changed since the last simulation: simulate again');
  const text = await task('export', () => api.readFile(sim.files.frames));
  if (text === null) return;
  log(`saved ${sim.files.frames}`);
  download(baseName(sim.files.frames), text, 'application/json');
}

async function save(kind) {
  const f = files();
  if (kind === 'png') return download(`${$('name').value}.png`, view.screenshot());
  if (kind === 'trajectory') return saveTrajectory();
  const check = await checkNow();
  if (!checkedValid(check)) return;
  if (kind === 'pmml') return log(`saved ${f.pattern} (under the server's root)`);
  if (kind === 'cmml') {
    await task('save', () => api.writeFile(f.sequence, writeCMML(app.sequence)));
    return log(`saved ${f.sequence}`);
  }
  const text = await task('export', () => session.exportAs(kind, app.model, app.sequence, f));
  if (text === null) return;
  log(`saved ${kind === 'fold' ? f.fold : f.svg}`);
  download(baseName(kind === 'fold' ? f.fold : f.svg), text, kind === 'fold' ? 'application/json' : 'image/svg+xml');
}

// --- wiring ----------------------------------------------------------------------------------

function lattice() {
  const p = parameters($('lattice').value);
  editor.options = { ...editor.options, ...p };
}

function wire() {
  wirePhysics();
  for (const b of document.querySelectorAll('[data-tool]')) {
    b.addEventListener('click', () => {
      lattice();
      editor.setTool(b.dataset.tool);
      for (const other of document.querySelectorAll('[data-tool]')) other.classList.toggle('active', other === b);
    });
  }
  const actions = { group: () => editor.groupSelection(), ungroup: () => editor.ungroupSelection(), copy: () => editor.copySelection(),
    paste: () => editor.paste(), delete: () => editor.deleteSelection() };
  for (const b of document.querySelectorAll('[data-action]')) b.addEventListener('click', () => actions[b.dataset.action]());
  for (const b of document.querySelectorAll('[data-assign]')) b.addEventListener('click', () => editor.setAssignment(b.dataset.assign));
  for (const b of document.querySelectorAll('[data-save]')) b.addEventListener('click', () => save(b.dataset.save));
  $('snap-grid').addEventListener('change', () => {
    const g = Number($('snap-grid').value);
    editor.snap = { ...editor.snap, grid: g > 0 ? g : null };
  });
  $('lattice').addEventListener('change', lattice);
  $('undo').addEventListener('click', () => editor.undo());
  $('redo').addEventListener('click', () => editor.redo());
  $('fit').addEventListener('click', () => {
    editor.fit();
    view.fit();
  });
  $('generate').addEventListener('change', (e) => { generateNow(e.target.value); e.target.value = ''; });
  $('open').addEventListener('focus', listOpenable);
  $('open').addEventListener('change', (e) => { openNow(e.target.value); e.target.value = ''; });
  $('set-fold').addEventListener('click', setSelectedFolds);
  $('clear-fold').addEventListener('click', unsetSelectedFolds);
  $('set-joint').addEventListener('click', () => {
    const spring = Number($('spring').value);
    const damping = Number($('damping').value);
    if (!(spring >= 0 && damping >= 0 && Number.isFinite(spring) && Number.isFinite(damping)))
      return log('spring and damping must be finite and not negative');
    // The joint's own motor limit (PMML <MaxTorque>); empty: none, the run's max torque.
    const torqueText = $('joint-torque').value.trim();
    const maxTorque = torqueText ? Number(torqueText) : null;
    if (maxTorque !== null && !(Number.isFinite(maxTorque) && maxTorque > 0))
      return log(`max torque: give a positive number of N·m, or leave it empty for the run's; not "${torqueText}"`);
    for (const id of editor.selection.joints || []) app.model.setJoint(id, { spring, damping, maxTorque });
    editor.commit();  // an undoable edit like any other; it tells patternChanged
  });
  $('event-number').addEventListener('change', () => { app.currentEvent = Number($('event-number').value) || 0; showSequence(); });
  $('add-event').addEventListener('click', () => {
    const last = app.sequence.events.length ? app.sequence.events[app.sequence.events.length - 1].number : 0;
    app.currentEvent = last + 1;
    showSequence();
  });
  $('delete-event').addEventListener('click', () => {
    app.sequence.events = app.sequence.events.filter((e) => e.number !== app.currentEvent);
    sequenceEdited();
    showSequence();
  });
  $('event-earlier').addEventListener('click', () => moveEvent(-1));
  $('event-later').addEventListener('click', () => moveEvent(1));
  $('simulate').addEventListener('click', simulateNow);
  $('fold').addEventListener('click', foldNow);
  $('plan').addEventListener('click', planNow);
  $('stiffness').addEventListener('click', stiffnessNow);
}

async function start() {
  wire();
  lattice();
  app.interactiveAt = performance.now();  // ms after navigation began: the page answers input from here
  editor.snap = { ...editor.snap, grid: Number($('snap-grid').value) || null };
  // The command line's first pattern, then its first sequence, asked for early by boot.js.
  const boot = await task('server', () => opening);
  if (boot) {
    app.formats = boot.server.formats;
    fillPlanners($('planner'), boot.server);
  }
  if (boot && boot.pattern) {
    $('name').value = boot.name;
    const opened = session.openedEarly(boot);
    await openNow(boot.pattern, opened.pattern);
    performance.mark('foldkit:pattern-shown');
    if (boot.sequence) {
      clearTimeout(checkTimer);  // its simulation checks the pattern first: not now, while it is read
      await openNow(boot.sequence, opened.sequence);
    }
  }
  app.ready = true;
  document.body.dataset.ready = 'true';
}

app.readCMML = readCMML;
start();
