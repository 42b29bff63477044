// What every part of the page shares: its state (`app`, window.foldkit for the browser tests),
// its elements, the log, the one-request-at-a-time runner of foldkit verbs and whether one may
// run on the pattern.
import { PatternModel } from './model.js';
import { emptySequence } from './cmml.js';
import * as session from './session.js';
import { format } from './numbers.js';

/** The page's element with this id. */
export const $ = (id) => document.getElementById(id);

// Everything the page knows; `window.foldkit` exposes it to the browser tests.
export const app = {
  model: new PatternModel(),
  sequence: emptySequence(),
  sequenceEdits: 0,   // edits of `sequence` so far (a simulation remembers the count it ran on)
  currentEvent: 1,
  check: null,        // the last checkPattern() answer
  simulation: null,   // the last session.simulate() answer
  stateDof: null,     // dof of the state the scrubber rests on (its frame: stateNumbers.shown)
  formats: [],        // the file formats foldkit reads and writes (GET /api; formats.js)
  busy: 0,
  errors: [],
};
window.foldkit = app;

/** The server-side files of the page's session, named after the name field. */
export const files = () => session.sessionFiles($('name').value.trim() || 'untitled');

/** Shows one line in the page's log. */
export function log(text) {
  $('log').textContent = text;
}

/** Shows a number foldkit reported in the element `id`. */
export function setNumber(id, value) {
  $(id).textContent = format(value);
}

// Runs one request at a time from the UI; a failure is shown, never thrown at the user.
export async function task(label, work) {
  app.busy++;
  document.body.classList.add('busy');
  try {
    return await work();
  } catch (e) {
    app.errors.push(`${label}: ${e.message}`);
    log(`${label}: ${e.message}`);
    return null;
  } finally {
    app.busy--;
    if (!app.busy) document.body.classList.remove('busy');
  }
}

/** Whether a verb may run on the pattern (`check`: app.checkNow()'s answer); says why not (no
 * answer: an edit or a failed request came in between, and the log already tells which). */
export function checkedValid(check) {
  if (check && !check.ok) log('the pattern is not valid: see the problems listed');
  else if (!check && app.model.triangles.length === 0) log('draw or open a pattern first');
  return Boolean(check && check.ok);
}
