// The physics switch's arguments and words: what the page's fields become as `simulate`'s
// options (`--model dynamic`, `--gravity`, `--max-torque`, docs/SIMULATION.md "Dynamic
// simulation"), and what a physical run's stalls say. Pure, for node's tests.

/** The model `simulate` runs when the physics switch is on. */
export const PHYSICS_MODEL = 'dynamic';

/**
 * `simulate`'s options from the physics fields (their text as typed): {options} to add to the
 * request, or {error} saying what is wrong. `gravity`: "X Y Z" (or X,Y,Z) in m/s², empty for
 * none; `torque`: the motors' limit in N·m, positive.
 */
export function physicsOptions({ gravity, torque }) {
  const options = { model: PHYSICS_MODEL };
  const g = gravity.trim();
  if (g) {
    const parts = g.split(/[\s,]+/);
    const values = parts.map(Number);
    if (parts.length !== 3 || !values.every(Number.isFinite))
      return { error: `gravity: give three numbers X Y Z in m/s² (such as 0 0 -9.81), or leave it empty for none; not "${g}"` };
    options.gravity = values.map(String).join(',');
  }
  const t = torque.trim();
  const limit = Number(t);
  if (!t || !Number.isFinite(limit) || !(limit > 0)) return { error: `max torque: give a positive number of N·m, not "${t}"` };
  options['max-torque'] = limit;
  return { options };
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
