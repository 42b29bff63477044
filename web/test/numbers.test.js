// numbers.js: the rows about the state on screen show that state's numbers or say they have
// none; an answer for a state no longer on screen is dropped (issue 32).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { StateNumbers, format, PENDING, NOT_CLOSED } from '../src/numbers.js';

const cells = () => ({ dof: { textContent: '', title: '' }, closure: { textContent: '', title: '' } });
const flat = { dof: 42, closure_error: 0 };

test('format: a dash for none, integers as they are, fractions to three digits', () => {
  assert.equal(format(null), '–');
  assert.equal(format(undefined), '–');
  assert.equal(format(42), '42');
  assert.equal(format(0.0052359877), '5.24e-3');
});

test('the flat sheet\'s check is shown only while the view shows the flat sheet', () => {
  const c = cells();
  const n = new StateNumbers(c);
  assert.equal(c.dof.textContent, '–');
  assert.ok(n.flatMeasured(flat));
  assert.deepEqual([c.dof.textContent, c.closure.textContent], ['42', '0']);
  // A simulation's frame on screen: the pattern's check (every verb asks it again) changes nothing.
  const sim = {};
  n.showFrame(sim, 10);
  assert.deepEqual([c.dof.textContent, c.closure.textContent], [PENDING, PENDING]);
  assert.equal(n.flatMeasured(flat), false);
  assert.deepEqual([c.dof.textContent, c.closure.textContent], [PENDING, PENDING]);
  // Back to the flat sheet (the pattern was edited): the numbers wait for the next check.
  n.showFlat();
  assert.equal(c.dof.textContent, '–');
});

test('a frame\'s answer lands only while that frame is on screen', () => {
  const c = cells();
  const n = new StateNumbers(c);
  const sim = {};
  const early = n.showFrame(sim, 3);
  const late = n.showFrame(sim, 7);  // scrubbed on before foldkit answered for frame 3
  assert.equal(n.frameMeasured(early, { dof: 1, closure_error: 1e-12 }, 1e-3), false);
  assert.equal(c.dof.textContent, PENDING);
  assert.ok(n.frameMeasured(late, { dof: 1, closure_error: 1e-12 }, 1e-3));
  assert.deepEqual([c.dof.textContent, c.closure.textContent], ['1', '1.00e-12']);
  assert.ok(n.measured);
  // The same frame again keeps its numbers; another simulation's frame 7 does not.
  assert.equal(n.showFrame(sim, 7), late);
  assert.equal(c.dof.textContent, '1');
  n.showFrame({}, 7);
  assert.equal(c.dof.textContent, PENDING);
  // The commanded end of folds not yet simulated has no numbers.
  n.showPreview();
  assert.equal(c.dof.textContent, '–');
  assert.match(c.dof.title, /Simulate/);
});

test('a frame that does not close shows its closure error and no DOF', () => {
  const c = cells();
  const n = new StateNumbers(c);
  const token = n.showFrame({}, 100);
  n.frameMeasured(token, { dof: 0, closure_error: 0.501 }, 1e-3);
  assert.equal(c.dof.textContent, NOT_CLOSED);
  assert.match(c.dof.title, /5\.01e-1 rad/);
  assert.equal(c.closure.textContent, '5.01e-1');
  // Within the tolerance it is closed: its DOF is shown.
  n.frameMeasured(token, { dof: 1, closure_error: 9e-4 }, 1e-3);
  assert.equal(c.dof.textContent, '1');
});
