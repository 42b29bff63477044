// The side panel's numbers about "this state" in a real browser (issue 32): they belong to the
// frame the 3D view shows, or say that they do not, whatever verb runs in between. The oracle is
// the CLI's `foldkit dof --state` on the same angles.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { foldkit, browserSuite, openApp, idle, shown } from './harness.js';
import { readCMML, writeCMML } from '../src/cmml.js';
import { PENDING, NOT_CLOSED } from '../src/numbers.js';

const suite = browserSuite();
let root = null;

// The CLI's DOF and closure error of one state: the page's frame `k` (radians per joint, in the
// page's joint order), written as a one-event CMML by this test.
async function cliAtFrame(page, k) {
  const { ids, radians } = await page.evaluate((frame) => ({
    ids: window.foldkit.model.joints().map((j) => j.id),
    radians: Array.from(window.foldkit.simulation.frames[frame]),
  }), k);
  const path = join(root, `frame-${k}.cmml`);
  writeFileSync(path, writeCMML({ title: 'frame', events: [{ number: 1, folds: ids.map((joint, i) => ({ joint, angle: (radians[i] * 180) / Math.PI, speed: 1 })) }] }));
  return foldkit(['dof', join(root, 'miura.pmml'), '--state', path, '--json']).json;
}

async function scrub(page, frame, rest = true) {
  await page.evaluate((f, end) => {
    const slider = document.querySelector('#timeline input[type=range]');
    slider.value = f;
    slider.dispatchEvent(new Event('input'));
    if (end) slider.dispatchEvent(new Event('change'));
  }, frame, rest);
  await idle(page);
}

const text = (page, id) => page.$eval(`#${id}`, (e) => e.textContent);
const close = (a, b) => Math.abs(a - b) <= 0.006 * Math.abs(b) || (b < 1e-9 && a < 1e-9);

test('a sequence that jumps from flat to a fold: the numbers follow the frame on screen', { timeout: 180000 }, async () => {
  // One event from flat straight to the folded state: closure is violated along the way.
  const { server } = await suite.serve('numbers', ['miura.pmml', 'jump.cmml'], (dir) => {
    root = dir;
    foldkit(['generate', 'miura', '--rows', '4', '--cols', '6', '-o', join(root, 'miura.pmml')]);
    foldkit(['fold', join(root, 'miura.pmml'), '--fraction', '0.9', '-o', join(root, 'folded.cmml')]);
    const folded = readCMML(readFileSync(join(root, 'folded.cmml'), 'utf8'));
    rmSync(join(root, 'folded.cmml'));
    const end = new Map();
    for (const e of folded.events) for (const f of e.folds) end.set(f.joint, f.angle);
    writeFileSync(join(root, 'jump.cmml'), writeCMML({ title: 'jump', events: [{ number: 1, folds: [...end].map(([joint, angle]) => ({ joint, angle, speed: 30 })) }] }));
  });
  const sim = foldkit(['simulate', join(root, 'miura.pmml'), join(root, 'jump.cmml'), '--json'], { expect: [3] }).json;
  const flat = foldkit(['dof', join(root, 'miura.pmml'), '--json']).json;
  const atEnd = foldkit(['dof', join(root, 'miura.pmml'), '--state', join(root, 'jump.cmml'), '--json']).json;
  assert.notEqual(flat.dof, atEnd.dof, 'the flat sheet and the folded end differ in DOF');
  const page = await openApp(suite.browser(), server.url);
  await page.waitForFunction(() => window.foldkit.simulation !== null);
  await idle(page);
  assert.match(await text(page, 'verdict'), /^invalid/);
  const frames = await page.evaluate(() => window.foldkit.simulation.frames.length);
  assert.equal(await page.evaluate(() => window.foldkit.timeline.frame), frames - 1);
  // The scrubber rests on the folded end: its numbers, not the flat sheet's.
  assert.equal(await shown(page, 'n-dof'), atEnd.dof);
  assert.ok(close(await shown(page, 'closure-state'), atEnd.closure_error));

  // Saving re-checks the pattern (the flat sheet's DOF): the folded frame keeps its numbers.
  await page.click('[data-save="cmml"]');
  await idle(page);
  assert.equal(await shown(page, 'n-dof'), atEnd.dof, 'the pattern\'s check must not replace the frame\'s DOF');
  assert.ok(close(await shown(page, 'closure-state'), atEnd.closure_error));

  // Dragging (no rest yet): the end's numbers are not left beside another frame.
  const middle = Math.floor(frames / 3);
  await scrub(page, middle, false);
  assert.equal(await text(page, 'n-dof'), PENDING);
  assert.equal(await text(page, 'closure-state'), PENDING);
  // At rest: the frame's closure error as the CLI computes it, and no DOF (the loops do not close).
  await scrub(page, middle);
  const there = await cliAtFrame(page, middle);
  assert.ok(there.closure_error > sim.closure_tolerance, `frame ${middle} is not closed (${there.closure_error} rad)`);
  assert.equal(await text(page, 'n-dof'), NOT_CLOSED);
  assert.ok(close(await shown(page, 'closure-state'), there.closure_error), `closure ${await shown(page, 'closure-state')} vs CLI ${there.closure_error}`);

  // The first frame is the flat sheet: the CLI's flat numbers.
  await scrub(page, 0);
  assert.equal(await shown(page, 'n-dof'), flat.dof);
  assert.ok(close(await shown(page, 'closure-state'), flat.closure_error));
  assert.deepEqual(page.errors, []);
});
