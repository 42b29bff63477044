// The physics switch's arguments and words: what the page's fields become as `simulate`'s
// options (`--model dynamic`, `--gravity`, `--max-torque`, `--density`, `--fixed`, `--ground`,
// `--scale`, `--drive`, and the solver's
// `--solver`, `--iterations`, `--time-step`, `--projection-interval`; docs/SIMULATION.md "Dynamic
// simulation"), and what a physical run's stalls say. Pure, for node's tests.

/** The model `simulate` runs when the physics switch is on. */
export const PHYSICS_MODEL = 'dynamic';

/**
 * The solver choices, as `simulate`'s options (the CLI's names). *exact*: ODE's direct solver at
 * the model's default 1 ms steps (the torque checks and the pendulum are measured on it; its cost
 * grows with the cube of the joints). *direct-10ms*: the same solver at 10 ms steps, ten times
 * cheaper, for sequences whose every crease a motor drives (what *Fold* loads), where *fast* gets
 * stuck. *fast*: the iterative solver, 20 sweeps, 10 ms steps, the loops projected closed every
 * step (docs/SIMULATION.md "Meeting the real-time targets"): a sheet folded by a few motors, its
 * other creases free. Each sent in full, so that the label says what runs whatever the model's
 * defaults become (docs/SERVE.md, "Physics").
 */
export const SOLVERS = {
  exact: { solver: 'direct', 'time-step': 0.001 },
  'direct-10ms': { solver: 'direct', 'time-step': 0.01 },
  fast: { solver: 'iterative', iterations: 20, 'time-step': 0.01, 'projection-interval': 0.01 },
};

/**
 * What drives an event's joints, as `simulate --drive` names it: *motor*, a torque-limited motor
 * at the CMML's speed (`--max-torque`, a joint's own <MaxTorque>); *spring*, each crease's torsion
 * spring towards the event's angle, −k(θ − θ*) − c·θ̇ with the PMML's SpringConst k (N·m/rad)
 * and DampConst c (N·m·s/rad), which the joint panel edits (docs/SIMULATION.md, "Dynamic
 * simulation"). The first is the default.
 */
export const DRIVES = ['motor', 'spring'];

// A field's positive number, or null.
function positive(text) {
  const value = Number(text);
  return text && Number.isFinite(value) && value > 0 ? value : null;
}

/** The page's gravity where the pattern's file has none (m/s², "X Y Z"). */
export const DEFAULT_GRAVITY = '0 0 -9.81';

/**
 * The physics fields' text from a pattern's own values (PatternModel.physics: foldkit's PMML
 * extensions <Density>, <Gravity>, <FixedActor>, each null where the file has none): the file's
 * value where it has one, else the page's default (density 1 kg/m², gravity DEFAULT_GRAVITY, the
 * fixed actor empty: the first actor). So a field left as the pattern opened sends the file's
 * own value, which `simulate` would have used anyway.
 */
export function physicsDefaults(physics = {}) {
  return {
    density: physics.density != null ? String(physics.density) : '1',
    gravity: physics.gravity != null ? physics.gravity.map(String).join(' ') : DEFAULT_GRAVITY,
    fixed: physics.fixedActor != null ? String(physics.fixedActor) : '',
  };
}

/**
 * `simulate`'s options from the physics fields (their text as typed): {options} to add to the
 * request, or {error} saying what is wrong. `gravity`: "X Y Z" (or X,Y,Z) in m/s², empty for
 * none; `torque`: the motors' limit in N·m, positive (joints with their own PMML <MaxTorque>
 * keep it); `density`: the sheet's areal density in kg/m², positive (default 1, the model's);
 * `fixed`: the actor held in place, an actor ID or "none" (empty: not sent, the pattern's
 * <FixedActor> or the first actor); `ground`: a ground plane's height in metres (empty: none);
 * `scale`: metres per pattern unit, positive (empty: not sent, 1); `solver`: a key of SOLVERS
 * (default exact); `drive`: one of DRIVES (default motor), always sent.
 */
export function physicsOptions({ gravity, torque, density = '1', fixed = '', ground = '', scale = '', solver = 'exact', drive = 'motor' }) {
  const options = { model: PHYSICS_MODEL, drive };
  const g = gravity.trim();
  if (g) {
    const parts = g.split(/[\s,]+/);
    const values = parts.map(Number);
    if (parts.length !== 3 || !values.every(Number.isFinite))
      return { error: `gravity: give three numbers X Y Z in m/s² (such as 0 0 -9.81), or leave it empty for none; not "${g}"` };
    options.gravity = values.map(String).join(',');
  }
  const t = torque.trim();
  const limit = positive(t);
  if (limit === null) return { error: `max torque: give a positive number of N·m, not "${t}"` };
  options['max-torque'] = limit;
  const d = density.trim();
  const areal = positive(d);
  if (areal === null) return { error: `density: give a positive number of kg/m² (of sheet), not "${d}"` };
  options.density = areal;
  const f = fixed.trim();
  if (f) {
    if (f.toLowerCase() === 'none') options.fixed = 'none';
    else if (/^[+-]?\d+$/.test(f) && Number.isSafeInteger(Number(f))) options.fixed = String(Number(f));
    else return { error: `fixed actor: give an actor ID or "none", or leave it empty for the first actor; not "${f}"` };
  }
  const z = ground.trim();
  if (z) {
    const height = Number(z);
    if (!Number.isFinite(height)) return { error: `ground: give the ground's height in metres, or leave it empty for none; not "${z}"` };
    options.ground = height;
  }
  const s = scale.trim();
  if (s) {
    const metres = positive(s);
    if (metres === null) return { error: `scale: give a positive number of metres per pattern unit, not "${s}"` };
    options.scale = metres;
  }
  if (!Object.hasOwn(SOLVERS, solver))
    return { error: `solver: choose one of ${Object.keys(SOLVERS).join(', ')}, not "${solver}"` };
  if (!DRIVES.includes(drive)) return { error: `drive: choose one of ${DRIVES.join(', ')}, not "${drive}"` };
  return { options: { ...options, ...SOLVERS[solver] } };
}

// Numbers as the panel words them: three significant digits.
const n = (v) => Number(v.toPrecision(3)).toString();

/** One stall in words: which joint, when, where, and the torque it needed against its limit. */
export function stallText(s) {
  // A stall with contacts (--contacts, --ground) may be a blocked motor: the actors it pushes against.
  if (s.blocked_by && s.blocked_by.length)
    return `joint ${s.joint} blocked at ${s.time.toFixed(2)} s (event ${s.event}) at ${n(s.angle)}° of ${n(s.target)}°: ` +
      (s.blocked_by.length > 1 ? `actors ${s.blocked_by.join(' and ')} touch` : `actor ${s.blocked_by[0]} touches the ground`);
  return `joint ${s.joint} stalled at ${s.time.toFixed(2)} s (event ${s.event}) at ${n(s.angle)}° of ${n(s.target)}°: ` +
    `it needs ${n(s.needed_torque)} N·m, has ${n(s.available_torque)} N·m`;
}

/** A timeline mark's label: the joint and the time. */
export function stallLabel(s) {
  return `joint ${s.joint}, ${s.time.toFixed(2)} s`;
}

/** The physical run's verdict in one line (simulate's JSON `result`). */
export function physicsVerdict(result) {
  const stalls = result.stalls || [];
  if (stalls.length) return stalls.map(stallText).join('; ');
  if (result.status !== 'success') return result.message || result.status;
  const joints = result.joints || [];
  const peak = joints.reduce((best, j) => (!best || j.peak_torque > best.peak_torque ? j : best), null);
  const most = peak ? `; the largest torque ${n(peak.peak_torque)} N·m (joint ${peak.joint}) of ${n(result.max_torque)} N·m` : '';
  return `every joint reached its angle${most}`;
}
