// The physics switch in a real browser (Debian's chromium through puppeteer-core) on `foldkit
// serve --port 0`: a generated two-panel strip hanging from its first panel (gravity along +x),
// its second panel lifted by one motor to −120°, simulated with physics on, first with a torque
// that lifts it and then with one that stalls, then with the fast solver on a lighter sheet; the
// torque plot and the stall marks against `foldkit simulate --model dynamic` on the files the
// page saved. Then a PMML with foldkit's physics extensions (<Density>, <Gravity>, <FixedActor>,
// a crease's <MaxTorque>): opened, kept and written back, its values the fields' defaults and
// used; the fixed actor, ground, scale and start-from-the-state-shown fields as the requests
// the page sends and as foldkit's report of what it used; a malformed extension refused at its
// line.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
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

  // The drive: motors by default; springs send --drive spring, and the page's run is the CLI's
  // with it (the strip's crease a 1 N·m/rad spring: gravity holds the flap near flat, a stall).
  assert.equal(await page.$eval('#physics-drive', (e) => e.value), 'motor', 'motors by default');
  assert.deepEqual(await page.$$eval('#physics-drive option', (os) => os.map((o) => o.value)), ['motor', 'spring']);
  await page.select('#physics-drive', 'spring');
  await simulate(page);
  const sprung = await page.evaluate(() => window.foldkit.simulation);
  cli = cliRun(root, stalling, ['--density', '0.8', '--solver', 'iterative', '--iterations', '20', '--time-step', '0.01',
    '--projection-interval', '0.01', '--drive', 'spring']);
  assert.equal(sprung.result.drive, 'spring');
  assert.equal(cli.exit, 3, 'a 1 N·m/rad spring does not lift the flap');
  assert.equal(sprung.result.joints[0].angle, cli.result.joints[0].angle);
  assert.deepEqual(sprung.result.stalls, cli.result.stalls);
  assert.deepEqual(sprung.series.time, cli.series.time);
  await page.select('#physics-drive', 'motor');

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

// A flap whose PMML carries foldkit's extensions (docs/FORMATS.md): its density, gravity and held
// actor, and its crease's own motor limit. Actor 2 is held and gravity is along −x, so panel 1
// hangs from it as panel 2 hangs above: lifting it needs 0.9·m·g·d = 4.41 N·m, which the
// crease's own 4.2 N·m lacks.
const EXTENDED = `<?xml version="1.0" encoding="UTF-8"?>
<PMML>
  <Title>flap</Title>
  <Density>0.9</Density>
  <Gravity>-9.81 0 0</Gravity>
  <FixedActor>2</FixedActor>
  <Actor>
    <ID>1</ID>
    <Triangle>0 0 1 0 1 1</Triangle>
    <Triangle>0 0 1 1 0 1</Triangle>
  </Actor>
  <Actor>
    <ID>2</ID>
    <Triangle>1 0 2 0 2 1</Triangle>
    <Triangle>1 0 2 1 1 1</Triangle>
  </Actor>
  <Joint>
    <ID>1</ID>
    <Coords>1 0 1 1</Coords>
    <ActorIDs>1 2</ActorIDs>
    <SpringConst>1</SpringConst>
    <DampConst>0.1</DampConst>
    <MaxTorque>4.2</MaxTorque>
  </Joint>
</PMML>
`;
const LIFT_CMML = '<CMML><Title>lift</Title><Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>120</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n';

test('a PMML with foldkit\'s physics extensions opens, keeps them, and gives the physics fields; fixed actor, ground, scale and start are sent', limit, async () => {
  const { root, server } = await suite.serve('extensions', ['flap.pmml', 'flap.cmml'], (dir) => {
    writeFileSync(join(dir, 'flap.pmml'), EXTENDED);
    writeFileSync(join(dir, 'flap.cmml'), LIFT_CMML);
    // The same with a malformed gravity, at line 5.
    writeFileSync(join(dir, 'bad.pmml'), EXTENDED.replace('<Gravity>-9.81 0 0</Gravity>', '<Gravity>-9.81 0</Gravity>'));
  });
  const page = await openApp(suite.browser(), server.url);
  const requests = [];
  page.on('request', (r) => { if (r.method() === 'POST' && new URL(r.url()).pathname === '/api/simulate') requests.push(JSON.parse(r.postData())); });

  // Opened: the model holds the extensions, the physics fields show the file's values, the
  // crease's own limit is in the joint panel; the PMML the page wrote back (its session's
  // file) has them as foldkit writes them.
  assert.deepEqual(await page.evaluate(() => window.foldkit.model.physics), { density: 0.9, gravity: [-9.81, 0, 0], fixedActor: 2 });
  assert.equal(await page.evaluate(() => window.foldkit.model.joint(1).maxTorque), 4.2);
  const field = (id) => page.$eval(`#${id}`, (e) => e.value);
  assert.deepEqual([await field('density'), await field('gravity'), await field('fixed-actor')], ['0.9', '-9.81 0 0', '2']);
  const name = await field('name');  // the session's name: the page does not overwrite what it opened
  assert.notEqual(name, 'flap');
  const written = readFileSync(join(root, `${name}.pmml`), 'utf8');
  assert.match(written, /<Title>flap<\/Title>\n {2}<Density>0\.9<\/Density>\n {2}<Gravity>-9\.81 0 0<\/Gravity>\n {2}<FixedActor>2<\/FixedActor>\n/);
  assert.match(written, /<MaxTorque>4\.2<\/MaxTorque>/);
  foldkit(['validate', join(root, `${name}.pmml`)]);
  const p = await page.evaluate(() => window.foldkit.editor.toClient({ x: 1, y: 0.5 }));
  await page.mouse.click(p.x, p.y);
  assert.equal(await field('joint-torque'), '4.2');

  // Physics on, the fields as the file gave them (max torque left at 1 N·m: the crease keeps its
  // own 4.2): the lift stalls needing 0.9·m·g·d, with 4.2 N·m, panel 1 lifted (actor 2 held).
  await page.select('#sim-model', 'physics');
  await simulate(page);
  let shown = await shownPhysics(page);
  let result = await page.evaluate(() => window.foldkit.simulation.result);
  let sent = requests.at(-1);
  assert.deepEqual([sent.density, sent.gravity, sent.fixed, sent['max-torque']], [0.9, '-9.81,0,0', '2', 1]);
  assert.ok(!('ground' in sent) && !('start' in sent), 'no ground, no start');
  assert.equal(shown.verdict, 'invalid: no-progress');
  assert.equal(result.fixed, 2);
  assert.equal(result.stalls[0].available_torque, 4.2);
  assert.ok(Math.abs(result.stalls[0].needed_torque - 0.9 * LIFT) < 0.01 * LIFT, `needs 0.9·m·g·d: ${result.stalls[0].needed_torque}`);

  // Wrong fields are refused with the reason, nothing sent.
  const before = requests.length;
  for (const [id, value, message] of [['fixed-actor', 'first', /^fixed actor: give an actor ID or "none"/], ['ground', 'low', /^ground: give the ground's height in metres/],
    ['physics-scale', '0', /^scale: give a positive number of metres per pattern unit, not "0"/]]) {
    const old = await field(id);
    await setField(page, id, value);
    await simulate(page);
    assert.match((await shownPhysics(page)).log, message);
    await setField(page, id, old);
  }
  assert.equal(requests.length, before);

  // Nothing held: the sheet falls freely and the same crease lifts it (no stall): the fixed actor
  // changed the torque the lift needs.
  await setField(page, 'fixed-actor', 'none');
  await simulate(page);
  result = await page.evaluate(() => window.foldkit.simulation.result);
  assert.equal(requests.at(-1).fixed, 'none');
  assert.equal(result.fixed, 'none');
  assert.equal((await shownPhysics(page)).verdict, 'valid', result.message);
  assert.deepEqual(result.stalls, []);

  // Start from the state shown: the scrubber at the end (120°), sent as NAME-start.cmml with that
  // angle; the motor is there already, so the run is short.
  const duration = result.duration;
  await page.evaluate(() => window.foldkit.timeline.seek(1e9));
  const shownAngle = await page.evaluate(() => (window.foldkit.view.angles()[0] * 180) / Math.PI);
  assert.ok(Math.abs(shownAngle - 120) < 0.5, `shown at ${shownAngle}°`);
  await page.$eval('#physics-start', (e) => { e.checked = true; });
  await simulate(page);
  sent = requests.at(-1);
  assert.equal(sent.start, `${name}-start.cmml`);
  const start = readFileSync(join(root, `${name}-start.cmml`), 'utf8');
  const angle = Number(start.match(/<FoldAngle>([^<]+)<\/FoldAngle>/)[1]);
  assert.ok(Math.abs(angle - shownAngle) < 1e-6, `start at ${angle}°`);
  result = await page.evaluate(() => window.foldkit.simulation.result);
  assert.equal(result.status, 'success', result.message);
  assert.ok(result.duration < duration / 2, `${result.duration} s from the state shown, ${duration} s from flat`);
  await page.$eval('#physics-start', (e) => { e.checked = false; });

  // Scale and ground: sent, and used.
  await setField(page, 'fixed-actor', '');
  await setField(page, 'physics-scale', '0.5');
  await setField(page, 'ground', '-2');
  await simulate(page);
  sent = requests.at(-1);
  assert.deepEqual([sent.scale, sent.ground, 'fixed' in sent, 'start' in sent], [0.5, -2, false, false]);
  result = await page.evaluate(() => window.foldkit.simulation.result);
  assert.deepEqual([result.scale, result.ground, result.fixed], [0.5, -2, 2]);

  // The joint panel sets the crease's own limit, written to the PMML.
  await setField(page, 'joint-torque', '7.5');
  await page.click('#set-joint');
  await page.evaluate(() => window.foldkit.checkNow());
  await idle(page);
  assert.match(readFileSync(join(root, `${name}.pmml`), 'utf8'), /<MaxTorque>7\.5<\/MaxTorque>/);

  // A malformed extension: the file is refused at its line, the pattern on screen kept.
  await page.focus('#open');
  await page.waitForFunction(() => [...document.querySelectorAll('#open option')].some((o) => o.value === 'bad.pmml'));
  await page.select('#open', 'bad.pmml');
  await idle(page);
  assert.match((await shownPhysics(page)).log, /5: <Gravity> needs 3 numbers, found 2/);
  assert.deepEqual(await page.evaluate(() => window.foldkit.model.physics), { density: 0.9, gravity: [-9.81, 0, 0], fixedActor: 2 });
  assert.deepEqual(page.errors.filter((e) => !/needs 3 numbers/.test(e)), []);
});
