// How the side panel writes numbers, and its two rows about the state the 3D view shows
// ("DOF (this state)", "Closure error (this state)"). Those rows belong to the state on screen or
// say that they do not (issue 32: the flat sheet's DOF and closure stayed on screen beside a
// folded frame whenever a verb re-checked the pattern after a simulation).

/** A number as the panel shows it: '–' for none, three significant digits for a fraction. */
export function format(value, digits = 3) {
  if (value === undefined || value === null) return '–';
  if (typeof value === 'number' && !Number.isInteger(value)) return value.toExponential(digits - 1);
  return String(value);
}

/** What the rows say while foldkit has not measured the state on screen. */
export const PENDING = '…';
/** Why the rows are empty beside the commanded end of folds not yet simulated. */
export const PREVIEW = 'the commanded end state, not checked yet: press Simulate';
/** … and beside a sequence just opened, which foldkit simulates next (once the pattern passes). */
export const SIMULATING = 'the end state the sequence commands, not checked yet: foldkit simulates it next';
/** The DOF row of a frame whose loops do not close: a DOF means nothing there. */
export const NOT_CLOSED = '—, not closed here: the sequence is invalid here';

/**
 * The rows about the state on screen. Whoever changes what the 3D view shows says so (showFlat,
 * showFrame, showPreview) and gets a token; foldkit's answer for a state is shown only while that
 * state is still on screen (flatMeasured, frameMeasured), so a late or stale answer never lands
 * beside another state.
 */
export class StateNumbers {
  /** `dof`, `closure`: the two cells (anything with textContent and title). */
  constructor({ dof, closure }) {
    this.cells = { dof, closure };
    this.shown = { kind: 'flat', answer: null };
    this.render();
  }

  /** The view shows the flat sheet; its numbers come with the pattern's check (flatMeasured). */
  showFlat() {
    if (this.shown.kind !== 'flat') this.shown = { kind: 'flat', answer: null };
    this.render();
    return this.shown;
  }

  /** The view shows frame `frame` of the simulation `sim`: the token a measurement of that frame
   * answers to. The same frame again keeps its numbers. */
  showFrame(sim, frame) {
    const s = this.shown;
    if (!(s.kind === 'frame' && s.sim === sim && s.frame === frame)) this.shown = { kind: 'frame', sim, frame, answer: null };
    this.render();
    return this.shown;
  }

  /** The view shows a state no one has checked (the commanded end of folds not yet simulated);
   * `why`: the rows' tooltip (default: press Simulate). */
  showPreview(why = PREVIEW) {
    this.shown = { kind: 'preview', answer: null, why };
    this.render();
    return this.shown;
  }

  /** The pattern's check ({dof, closure_error} of the flat sheet); shown while the flat sheet is. */
  flatMeasured(answer) {
    if (this.shown.kind !== 'flat') return false;
    this.shown.answer = { dof: answer.dof, closure_error: answer.closure_error, tolerance: Infinity };
    this.render();
    return true;
  }

  /** foldkit's answer ({dof, closure_error}) for the frame of `token`, judged against the
   * simulation's closure tolerance (radians); shown only while that frame is on screen. */
  frameMeasured(token, answer, tolerance) {
    if (token !== this.shown) return false;
    token.answer = { dof: answer.dof, closure_error: answer.closure_error, tolerance };
    this.render();
    return true;
  }

  /** Whether the state on screen has its numbers. */
  get measured() {
    return this.shown.answer !== null;
  }

  render() {
    const { dof, closure } = this.cells;
    const a = this.shown.answer;
    if (a) {
      const closed = !(a.closure_error > a.tolerance);
      dof.textContent = closed ? format(a.dof) : NOT_CLOSED;
      dof.title = closed ? '' : `the loops of this frame miss closure by ${format(a.closure_error)} rad, more than the simulator's tolerance ${format(a.tolerance)} rad`;
      closure.textContent = format(a.closure_error);
      closure.title = '';
      return;
    }
    const waiting = this.shown.kind === 'frame';
    const why = waiting ? 'foldkit measures this frame when the scrubber rests' : this.shown.kind === 'preview' ? this.shown.why : '';
    for (const cell of [dof, closure]) {
      cell.textContent = waiting ? PENDING : format(null);
      cell.title = why;
    }
  }
}
