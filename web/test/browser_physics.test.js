// The physics switch in a real browser (Debian's chromium through puppeteer-core) on `foldkit
// serve --port 0`: a generated two-panel strip hanging from its first panel (gravity along +x),
// its second panel lifted by one motor to −120°, simulated with physics on, first with a torque
// that lifts it and then with one that stalls, then with the fast solver on a lighter sheet; the
// torque plot and the stall marks against `foldkit simulate --model dynamic` on the files the
// page saved.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { foldkit, browserSuite, openApp, idle } from './harness.js';

const suite = browserSuite();
const limit = { timeout: 180000 };  // per test; every wait inside is bounded too

// The most torque lifting the hanging panel takes, m·g·d (when it is horizontal, at −90°): a unit
// square at 1 kg/m² under 9.81 m/s², its centroid 0.5 m from the crease.
const LIFT = 9.81 * 0.5;
const GRAVITY = '9.81 0 0';

// Screenshots for docs/SERVE.md, when the test is run with FOLDKIT_SCREENSHOTS=DIR.
async function keepScreenshot(page, name) {
  const dir = process.env.FOLDKIT_SCREENSHOTS;
  if (!dir) return;
  mkdirSync(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`) });
}

// The CLI's report and series on the page's files, with the physics options the page was given
// (`extra`: the CLI's words for the density and the solver, when not the defaults).
function cliRun(root, torque, extra = []) {
  const series = join(root, 'oracle-series.json');
  const args = ['simulate', join(root, 'flap.pmml'), join(root, 'flap.cmml'), '--model', 'dynamic', '--gravity', GRAVITY.replaceAll(' ', ','),
    '--max-torque', String(torque), ...extra, '--series', series, '--json'];
  const run = foldkit(args, { expect: [0, 3] });
  return { exit: run.exit, result: run.json, series: JSON.parse(readFileSync(series, 'utf8')) };
}

// What the page shows of a physical run: the plot's curves (their joints and point counts), its
// stall marks, the timeline's stall marks (with their labels and places) and the verdicts.
function shownPhysics(page) {
  return page.evaluate(() => {
    const q = (selector) => [...document.querySelectorAll(selector)];
    return {
      panelHidden: document.getElementById('torque-panel').hidden,
      curves: q('#torque-plot .torque-series').map((p) => ({ joint: Number(p.dataset.joint), points: (p.getAttribute('d').match(/[ML]/g) || []).length })),
      plotStalls: q('#torque-plot .stall-mark').map((l) => ({ joint: Number(l.dataset.joint), time: Number(l.dataset.time) })),
      timelineStalls: q('#timeline .stall-mark').map((m) => ({ joint: Number(m.dataset.joint), time: Number(m.dataset.time), left: parseFloat(m.style.left), label: m.textContent })),
      plotted: document.getElementById('torque-joints').textContent,
      verdict: document.getElementById('verdict').textContent,
      physicsVerdict: document.getElementById('physics-verdict').textContent,
      log: document.getElementById('log').textContent,
      duration: window.foldkit.simulation ? window.foldkit.simulation.result.duration : null,
      stalls: window.foldkit.simulation ? window.foldkit.simulation.result.stalls : null,
    };
  });
}

async function setField(page, id, value) {
  await page.$eval(`#${id}`, (e, v) => { e.value = v; }, value);
}

async function simulate(page) {
  await page.click('#simulate');
  await idle(page);
}

test('the physics switch simulates a flap against gravity: its torque plotted, its stall on the timeline', limit, async () => {
  const { root, server } = await suite.serve('physics');
  const page = await openApp(suite.browser(), server.url);
  await setField(page, 'name', 'flap');
  await setField(page, 'generate-params', 'panels=2');
  await page.select('#generate', 'strip');
  await page.waitForFunction(() => window.foldkit.model.triangles.length > 0);
  await idle(page);
  // Select the crease with the mouse and lift panel 2 to −120° at 30°/s.
  const p = await page.evaluate(() => window.foldkit.editor.toClient({ x: 1, y: 0.5 }));
  await page.mouse.click(p.x, p.y);
  assert.deepEqual(await page.evaluate(() => window.foldkit.editor.selection.joints), [1]);
  await setField(page, 'fold-angle', '-120');
  await setField(page, 'fold-speed', '30');
  await page.click('#set-fold');

  // The switch shows the physical fields; wrong ones are refused with the reason, nothing run.
  assert.equal(await page.$eval('#physics-fields', (e) => e.hidden), true, 'kinematic: no physics fields');
  await page.select('#sim-model', 'physics');
  assert.equal(await page.$eval('#physics-fields', (e) => e.hidden), false);
  assert.match(await page.$eval('#collisions', (e) => e.parentElement.title), /--contacts/, 'physics: the box asks for contacts');
  await setField(page, 'gravity', '0 -9.81');
  await simulate(page);
  assert.match((await shownPhysics(page)).log, /^gravity: give three numbers X Y Z in m\/s²/);
  assert.equal(await page.evaluate(() => window.foldkit.simulation), null, 'nothing simulated');
  await setField(page, 'gravity', GRAVITY);
  await setField(page, 'max-torque', '-1');
  await simulate(page);
  assert.match((await shownPhysics(page)).log, /^max torque: give a positive number of N·m/);

  // Enough torque (1.05 m·g·d): lifted; the plot has the joint's series, frame by frame, no stall.
  const lifting = Number((1.05 * LIFT).toFixed(4));
  await setField(page, 'max-torque', String(lifting));
  await simulate(page);
  let cli = cliRun(root, lifting);
  let shown = await shownPhysics(page);
  assert.equal(cli.exit, 0);
  assert.equal(shown.verdict, 'valid');
  assert.equal(shown.panelHidden, false);
  assert.deepEqual(shown.curves, [{ joint: 1, points: cli.series.time.length }]);
  assert.equal(shown.plotted, '1');
  assert.deepEqual(shown.plotStalls, []);
  assert.deepEqual(shown.timelineStalls, []);
  assert.match(shown.physicsVerdict, /^every joint reached its angle; the largest torque 5\.\d+ N·m \(joint 1\)/);
  // The page's series is the CLI's: the same frames and torques.
  const pageSeries = await page.evaluate(() => window.foldkit.simulation.series);
  assert.deepEqual(pageSeries.time, cli.series.time);
  assert.deepEqual(pageSeries.joints[0].torque, cli.series.joints[0].torque);

  // Too little (0.95 m·g·d): the motor stalls; the stall is on the plot and the timeline at the
  // time the server reported, which is the CLI's.
  const stalling = Number((0.95 * LIFT).toFixed(4));
  await setField(page, 'max-torque', String(stalling));
  await simulate(page);
  cli = cliRun(root, stalling);
  shown = await shownPhysics(page);
  assert.equal(cli.exit, 3);
  assert.equal(shown.verdict, 'invalid: no-progress');
  assert.equal(shown.stalls.length, 1);
  const stall = shown.stalls[0];
  assert.deepEqual(stall, cli.result.stalls[0]);
  assert.equal(stall.joint, 1);
  // It stalls near the horizontal, where holding the panel takes m·g·d, well into the run.
  assert.ok(Math.abs(stall.needed_torque - LIFT) < 0.01 * LIFT, `needs m·g·d: ${stall.needed_torque}`);
  assert.ok(stall.angle < -70 && stall.angle > -100 && stall.time > 1, `stalled at ${stall.angle}° at ${stall.time} s`);
  assert.deepEqual(shown.curves, [{ joint: 1, points: cli.series.time.length }]);
  assert.deepEqual(shown.plotStalls, [{ joint: 1, time: stall.time }]);
  assert.equal(shown.timelineStalls.length, 1);
  const mark = shown.timelineStalls[0];
  assert.deepEqual([mark.joint, mark.time, mark.label], [1, stall.time, `joint 1, ${stall.time.toFixed(2)} s`]);
  assert.ok(Math.abs(mark.left - (100 * stall.time) / shown.duration) < 1e-9, `mark at ${mark.left} %`);
  assert.match(shown.physicsVerdict, new RegExp(`^joint 1 stalled at ${stall.time.toFixed(2)} s \\(event 1\\).*it needs 4\\.9\\d* N·m, has ${Number(stalling.toPrecision(3))} N·m$`));
  // The plot's cursor follows the scrubber: at the start its x is the plot's left edge.
  const cursorAt = () => page.$eval('#torque-plot .cursor', (l) => Number(l.getAttribute('x1')));
  const end = await cursorAt();
  await page.evaluate(() => window.foldkit.timeline.seek(0));
  assert.ok((await cursorAt()) < end, 'the cursor moved back with the scrubber');
  await page.evaluate(() => window.foldkit.timeline.seek(1e9));
  await keepScreenshot(page, 'serve-physics-stall');

  // The fast solver and a lighter sheet: a density that is not a positive number is refused;
  // at 0.8 kg/m² the same 0.95·m·g·d (at 1 kg/m²) lifts the flap (it needs 0.8·m·g·d), in 10 ms
  // steps, and the page's report and series are the CLI's with the same options.
  assert.equal(await page.$eval('#physics-solver', (e) => e.value), 'exact', 'exact by default');
  assert.deepEqual(await page.$$eval('#physics-solver option', (os) => os.map((o) => [o.value, o.textContent])),
    [['exact', 'exact (direct, 1 ms)'], ['direct-10ms', 'direct, 10 ms (every crease a motor)'], ['fast', 'fast (iterative + projection, 10 ms)']]);
  await page.select('#physics-solver', 'fast');
  await setField(page, 'density', '0');
  await simulate(page);
  assert.match((await shownPhysics(page)).log, /^density: give a positive number of kg\/m² \(of sheet\), not "0"/);
  await setField(page, 'density', '0.8');
  await simulate(page);
  cli = cliRun(root, stalling, ['--density', '0.8', '--solver', 'iterative', '--iterations', '20', '--time-step', '0.01', '--projection-interval', '0.01']);
  shown = await shownPhysics(page);
  const fast = await page.evaluate(() => window.foldkit.simulation);
  assert.equal(cli.exit, 0, cli.result.message);
  assert.equal(shown.verdict, 'valid');
  assert.deepEqual(shown.stalls, []);
  assert.deepEqual(shown.timelineStalls, []);
  assert.equal(fast.result.time_step, 0.01);
  assert.equal(fast.result.joints[0].angle, cli.result.joints[0].angle);
  assert.equal(fast.result.joints[0].peak_torque, cli.result.joints[0].peak_torque);
  assert.ok(Math.abs(fast.result.joints[0].angle + 120) < 0.01, `at −120°: ${fast.result.joints[0].angle}°`);
  assert.deepEqual(fast.series.time, cli.series.time);
  assert.deepEqual(fast.series.joints[0].torque, cli.series.joints[0].torque);
  assert.deepEqual(shown.curves, [{ joint: 1, points: cli.series.time.length }]);
  // Every frame on the 10 ms steps, 10 ms apart.
  const gaps = fast.series.time.slice(1).map((t, k) => t - fast.series.time[k]);
  fast.series.time.forEach((t, k) => assert.ok(Math.abs(t * 100 - Math.round(t * 100)) < 1e-6, `frame ${k} at ${t} s`));
  assert.ok(gaps.every((g) => Math.abs(g - 0.01) < 1e-9), 'frames 10 ms apart');
  assert.ok(fast.series.time.length > 300, `${fast.series.time.length} frames over ${fast.result.duration} s`);

  // Back to kinematic: the same folds replayed as commanded; no torque, no stall marks.
  await page.select('#sim-model', 'kinematic');
  assert.equal(await page.$eval('#physics-fields', (e) => e.hidden), true);
  await simulate(page);
  shown = await shownPhysics(page);
  assert.equal(shown.verdict, 'valid');
  assert.equal(shown.panelHidden, true);
  assert.deepEqual(shown.timelineStalls, []);
  assert.deepEqual(page.errors, []);
});
