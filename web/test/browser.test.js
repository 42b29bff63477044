// The whole app in a real browser (Debian's chromium through puppeteer-core, WebGL on the CPU):
// `foldkit serve` on a free port, the page driven by mouse and keyboard like a user, and every
// number the page shows compared with the CLI's own answer on the same files.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { copyFileSync, mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { foldkit, browserSuite, openApp, idle, shown, webDir } from './harness.js';

const suite = browserSuite();
const serve = (...args) => suite.serve(...args);
const limit = { timeout: 180000 };  // per test; every wait inside is bounded too

// The page's screenshot is a picture, not a blank canvas: many colours, and sheet-coloured pixels
// well away from the background.
async function assertNotBlank(page, what) {
  const stats = await page.evaluate(async () => {
    const image = new Image();
    image.src = window.foldkit.view.screenshot();
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const g = canvas.getContext('2d');
    g.drawImage(image, 0, 0);
    const data = g.getImageData(0, 0, canvas.width, canvas.height).data;
    const background = data.slice(0, 3);
    const colours = new Set();
    let differ = 0;
    for (let k = 0; k < data.length; k += 4) {
      colours.add((data[k] << 16) | (data[k + 1] << 8) | data[k + 2]);
      if (Math.abs(data[k] - background[0]) + Math.abs(data[k + 1] - background[1]) + Math.abs(data[k + 2] - background[2]) > 30) differ++;
    }
    return { colours: colours.size, share: differ / (data.length / 4), width: canvas.width };
  });
  assert.ok(stats.width > 100, `${what}: screenshot ${stats.width} px wide`);
  assert.ok(stats.colours > 20, `${what}: ${stats.colours} colours`);
  assert.ok(stats.share > 0.02, `${what}: only ${(100 * stats.share).toFixed(2)} % of the pixels are not background`);
}

// Screenshots for docs/SERVE.md, when the test is run with FOLDKIT_SCREENSHOTS=DIR.
async function keepScreenshot(page, name) {
  const dir = process.env.FOLDKIT_SCREENSHOTS;
  if (!dir) return;
  mkdirSync(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`) });
}

// The CLI's numbers for a pattern and sequence under `root`.
function cliNumbers(root, pattern, sequence) {
  const info = foldkit(['info', join(root, pattern), '--json']).json;
  const sim = foldkit(['simulate', join(root, pattern), join(root, sequence), '--json'], { expect: [0, 3] }).json;
  const dof = foldkit(['dof', join(root, pattern), '--state', join(root, sequence), '--json']).json;
  return { info, sim, dof };
}

// The page shows numbers with 3 significant digits.
function close(shownValue, exact) {
  return exact === 0 ? shownValue === 0 : Math.abs(shownValue - exact) <= 0.006 * Math.abs(exact);
}

test('the files named on the command line open, simulate, and show the CLI\'s numbers', limit, async () => {
  const { root, server } = await serve('demo', ['miura.pmml', 'miura-folded.cmml'], (dir) => {
    foldkit(['generate', 'miura', '--rows', '4', '--cols', '4', '-o', join(dir, 'miura.pmml')]);
    foldkit(['fold', join(dir, 'miura.pmml'), '--fraction', '0.9', '-o', join(dir, 'miura-folded.cmml')]);
  });
  const page = await openApp(suite.browser(), server.url);
  await page.waitForFunction(() => window.foldkit.simulation !== null);
  await idle(page);
  const cli = cliNumbers(root, 'miura.pmml', 'miura-folded.cmml');
  assert.equal(await shown(page, 'n-joints'), cli.info.joints);
  assert.equal(await shown(page, 'n-actors'), cli.info.actors);
  assert.equal(await shown(page, 'n-collisions'), cli.sim.collision_count);
  assert.ok(close(await shown(page, 'closure-max'), cli.sim.max_closure_error), 'closure error of the sequence');
  // The scrubber rests on the end state: its DOF is the CLI's at the sequence's end state, and
  // closed as foldkit's end state is.
  assert.equal(await shown(page, 'n-dof'), cli.dof.dof);
  assert.ok((await shown(page, 'closure-state')) <= Math.max(1e-9, 10 * cli.dof.closure_error));
  // The page's end state, joint by joint (its frames matched to its joints, in foldkit's sign),
  // is the simulator's: the mountains and valleys are where the CLI has them.
  const pageEnd = await page.evaluate(() => window.foldkit.model.joints().map((j, k) => [j.id, (window.foldkit.simulation.final[k] * 180) / Math.PI]));
  const cliEnd = new Map(cli.sim.final_angles.map((a) => [a.joint, a.angle]));
  assert.equal(pageEnd.length, cliEnd.size);
  for (const [id, angle] of pageEnd) assert.ok(Math.abs(angle - cliEnd.get(id)) < 1e-9, `joint ${id}: page ${angle}, CLI ${cliEnd.get(id)}`);
  assert.ok(pageEnd.some(([, a]) => a > 30) && pageEnd.some(([, a]) => a < -30), 'both mountains and valleys are folded');
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), 'valid');
  await assertNotBlank(page, 'folded Miura-ori');
  await keepScreenshot(page, 'serve-miura');
  assert.deepEqual(page.errors, []);
});

// Model point → the page's pixel for the mouse.
async function at(page, x, y) {
  return page.evaluate((p) => window.foldkit.editor.toClient(p), { x, y });
}

async function click(page, x, y, modifiers = []) {
  const p = await at(page, x, y);
  for (const key of modifiers) await page.keyboard.down(key);
  await page.mouse.click(p.x, p.y);
  for (const key of modifiers) await page.keyboard.up(key);
}

async function drag(page, from, to) {
  const a = await at(page, ...from);
  const b = await at(page, ...to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move((a.x + b.x) / 2, (a.y + b.y) / 2, { steps: 4 });
  await page.mouse.move(b.x, b.y, { steps: 4 });
  await page.mouse.up();
}

async function tool(page, name) {
  await page.click(`[data-tool="${name}"]`);
}

// Names the session and drags out a 2 × 2 grid lattice of unit cells from (0, 0) to (2, 2).
async function gridOfFour(page, name) {
  await page.$eval('#name', (e, value) => { e.value = value; }, name);
  await page.$eval('#lattice', (e) => { e.value = 'rows=2 cols=2 diagonals=none'; });
  await tool(page, 'grid');
  await drag(page, [0, 0], [2, 2]);
}

// Names the session and picks `kind` from the Generate menu with `options`; resolves once drawn.
async function generated(page, name, kind, options) {
  await page.$eval('#name', (e, value) => { e.value = value; }, name);
  await page.$eval('#generate-params', (e, value) => { e.value = value; }, options);
  await page.select('#generate', kind);
  await page.waitForFunction(() => window.foldkit.model.triangles.length > 0);
}

async function checked(page) {
  return page.evaluate(() => window.foldkit.checkNow());
}

test('a pattern drawn with the mouse, grouped, folded and simulated matches the CLI on the files it saved', limit, async () => {
  const { root, server } = await serve('draw');
  const page = await openApp(suite.browser(), server.url);
  await gridOfFour(page, 'drawn');
  // A triangle beside it, sharing the grid's edge (2, 0)-(2, 1): clicks snap to the 0.5 grid.
  await tool(page, 'triangle');
  await click(page, 2, 0);
  await click(page, 3, 0);
  await click(page, 2, 1);
  // The third click closes the triangle; under load the page may take a moment to commit it.
  await page.waitForFunction(() => window.foldkit.model.actors().length === 5);
  let check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  // Fit frames the drawing: its corners then span most of the 2D view's width or height.
  await page.click('#fit');
  const span = await page.evaluate(() => {
    const e = window.foldkit.editor, c = e.canvas.getBoundingClientRect();
    const a = e.toClient({ x: 0, y: 0 }), b = e.toClient({ x: 3, y: 2 });
    return Math.max(Math.abs(b.x - a.x) / c.width, Math.abs(b.y - a.y) / c.height);
  });
  assert.ok(span > 0.8 && span <= 1, `the drawing spans ${span} of the view`);
  // 4 cells and the triangle; joints: 4 between the cells and 1 to the triangle.
  assert.equal(await shown(page, 'n-actors'), 5);
  assert.equal(await shown(page, 'n-joints'), 5);
  // Group the two lower cells (both triangles of each, whichever way the cells are split): the
  // crease between them goes.
  await tool(page, 'select');
  await click(page, 0.5, 0.1);
  for (const [x, y] of [[0.5, 0.9], [1.5, 0.1], [1.5, 0.9]]) await click(page, x, y, ['Shift']);
  await page.click('[data-action="group"]');
  check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  assert.equal(await shown(page, 'n-actors'), 4);
  assert.equal(await shown(page, 'n-joints'), 4);
  // Undo and redo the grouping.
  await page.click('#undo');
  assert.equal((await checked(page)).info.joints, 5);
  await page.click('#redo');
  assert.equal((await checked(page)).info.joints, 4);
  const info = foldkit(['info', join(root, 'drawn.pmml'), '--json']).json;
  assert.equal(info.joints, 4);
  assert.equal(info.actors, 4);
  // Fold the triangle up by 60 degrees (a valley), in event 1, and simulate.
  await click(page, 2, 0.5);
  const crease = await page.evaluate(() => {
    const [id] = window.foldkit.editor.selection.joints;
    const j = window.foldkit.model.joints().find((x) => x.id === id);
    return { id, ends: [[j.a.x, j.a.y], [j.b.x, j.b.y]].sort((p, q) => p[1] - q[1]) };
  });
  assert.deepEqual(crease.ends, [[2, 0], [2, 1]], 'the click picked the triangle\'s crease');
  await page.$eval('#fold-angle', (e) => { e.value = '-60'; });
  await page.$eval('#fold-speed', (e) => { e.value = '30'; });
  await page.$eval('#event-number', (e) => { e.value = '1'; });
  await page.click('#set-fold');
  // Deleting the triangle takes its crease, undo brings both back, and the fold with them.
  await click(page, 2.3, 0.2);
  await page.click('[data-action="delete"]');
  assert.equal((await checked(page)).info.joints, 3);
  await page.click('#undo');
  const logText = () => page.$eval('#log', (e) => e.textContent);
  await page.click('[data-save="trajectory"]');
  assert.match(await logText(), /nothing simulated yet/);
  await page.evaluate(() => window.foldkit.simulateNow());
  await idle(page);
  // The simulated trajectory is offered as foldkit wrote it: every frame, with its time.
  await page.click('[data-save="trajectory"]');
  await idle(page);
  assert.match(await logText(), /saved .*drawn-frames\.fold/);
  const trajectory = JSON.parse(readFileSync(join(root, 'drawn-frames.fold'), 'utf8'));
  assert.ok(trajectory.file_frames.length > 2 && trajectory.file_frames.every((f) => Number.isFinite(f['foldkit:time'])));
  const cli = cliNumbers(root, 'drawn.pmml', 'drawn.cmml');
  assert.equal(cli.sim.events.length, 1);
  assert.equal(await shown(page, 'n-joints'), cli.info.joints);
  assert.equal(await shown(page, 'n-collisions'), cli.sim.collision_count);
  assert.ok(close(await shown(page, 'closure-max'), cli.sim.max_closure_error));
  assert.equal(await shown(page, 'n-dof'), cli.dof.dof);
  assert.ok(close(await shown(page, 'closure-state'), cli.dof.closure_error) || (await shown(page, 'closure-state')) < 1e-9);
  // Only the triangle's crease moved, to -60° (the CLI's end state on the files the page saved).
  for (const a of cli.sim.final_angles) assert.ok(Math.abs(a.angle - (a.joint === crease.id ? -60 : 0)) < 1e-6, JSON.stringify(cli.sim.final_angles));
  // A valley: in the page's 3D view the triangle rises (by sin 60° at its far corner) and the rest
  // stays in the plane (the first actor, a grid cell, is the kinematic root, as in foldkit).
  const { minZ, maxZ } = await page.evaluate(() => window.foldkit.view.stats());
  assert.ok(Math.abs(maxZ - Math.sin(Math.PI / 3)) < 1e-3 && Math.abs(minZ) < 1e-6, `z from ${minZ} to ${maxZ}`);
  // Saved as FOLD through foldkit convert: the CLI reads it back as the same pattern.
  await page.click('[data-save="fold"]');
  await idle(page);
  const again = foldkit(['info', join(root, 'drawn.fold'), '--json']).json;
  assert.equal(again.joints, 4);
  assert.equal(again.triangles, info.triangles);
  await assertNotBlank(page, 'folded drawing');
  await keepScreenshot(page, 'serve-drawn');
  // Once the folds change, the last trajectory is not theirs: it is not offered.
  await click(page, 2, 0.5);
  await page.$eval('#fold-angle', (e) => { e.value = '-45'; });
  await page.click('#set-fold');
  await page.click('[data-save="trajectory"]');
  assert.match(await logText(), /folds changed since the last simulation/);
  assert.deepEqual(page.errors, []);
});

test('a pattern foldkit refuses lists its problems at their lines and marks them', limit, async () => {
  const { server } = await serve('bad');
  const page = await openApp(suite.browser(), server.url);
  // Two triangles that overlap: foldkit names the overlap, the page lists it.
  await tool(page, 'triangle');
  for (const [x, y] of [[0, 0], [2, 0], [0, 2], [0.5, 0.5], [2.5, 0.5], [0.5, 2.5]]) await click(page, x, y);
  const check = await checked(page);
  assert.equal(check.ok, false);
  const items = await page.$$eval('#problems li', (list) => list.map((e) => e.textContent));
  assert.ok(items.length >= 1, 'problems listed');
  assert.match(items.join('\n'), /line \d+: .*overlap/);
  assert.equal(await page.$eval('#n-joints', (e) => e.textContent), '–');
  assert.deepEqual(page.errors, []);
});

test('a generated strip folded through itself shows the CLI\'s collisions on the view and the timeline', limit, async () => {
  const { root, server } = await serve('collide');
  const page = await openApp(suite.browser(), server.url);
  await generated(page, 'strip', 'strip', 'panels=3');
  assert.equal((await checked(page)).info.joints, 2);
  // Both creases to 170°, mountain, in one event: the outer panels pass through each other.
  await page.evaluate(() => window.foldkit.editor.select({ joints: window.foldkit.model.joints().map((j) => j.id) }));
  await page.$eval('#fold-angle', (e) => { e.value = '170'; });
  await page.click('#set-fold');
  await page.evaluate(() => window.foldkit.simulateNow());
  await idle(page);
  const cli = cliNumbers(root, 'strip.pmml', 'strip.cmml');
  assert.ok(cli.sim.collision_count > 0, 'the CLI sees the collision');
  assert.equal(await shown(page, 'n-collisions'), cli.sim.collision_count);
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), `invalid: ${cli.sim.status}`);
  const marks = await page.$$eval('.collision-mark', (list) => list.length);
  assert.equal(marks, cli.sim.collisions.length);
  // At the end the colliding panels are drawn red and the contact points marked; at the start, not.
  const highlighted = () => page.evaluate(() => window.foldkit.view.stats().highlighted);
  assert.ok((await highlighted()) > 0, 'colliding facets highlighted at the end');
  await page.evaluate(() => window.foldkit.timeline.seek(0));
  assert.equal(await highlighted(), 0);
  await keepScreenshot(page, 'serve-collision');
  assert.deepEqual(page.errors, []);
});

test('a Miura-ori drawn from the grid lattice folds as foldkit\'s own Miura-ori generator', limit, async () => {
  const { root, server } = await serve('miura-drawn');
  const page = await openApp(suite.browser(), server.url);
  await gridOfFour(page, 'drawn-miura');
  // The middle column of corners half a cell up: the cells become parallelograms, the middle row
  // of creases a zig-zag.
  await tool(page, 'select');
  await click(page, 1, 0);
  await click(page, 1, 1, ['Shift']);
  await click(page, 1, 2, ['Shift']);
  await tool(page, 'move');
  await drag(page, [1, 1], [1, 1.5]);
  // Mountains and the one valley of a Miura-ori vertex: the lower straight crease is the valley.
  await tool(page, 'select');
  await click(page, 1, 1);
  await page.click('[data-assign="V"]');
  await click(page, 1, 2);
  await click(page, 0.5, 1.25, ['Shift']);
  await click(page, 1.5, 1.25, ['Shift']);
  await page.click('[data-assign="M"]');
  const check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  assert.equal(check.info.interior_vertices, 1);
  // Projected folding to 0.9 from the page, then its simulation.
  await page.$eval('#fraction', (e) => { e.value = '0.9'; });
  await page.click('#fold');
  await page.waitForFunction(() => window.foldkit.simulation !== null, { timeout: 60000 });
  await idle(page);
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), 'valid');
  // The oracle: foldkit's generator makes the same sheet (a parallelogram angle of atan 2), and
  // its fold to 0.9 puts every crease (found by its end points) at the angle the page's fold did.
  const oracle = join(root, 'oracle');
  mkdirSync(oracle);
  foldkit(['generate', 'miura', '--rows', '2', '--cols', '2', '--angle', String((Math.atan(2) * 180) / Math.PI), '-o', join(oracle, 'm.pmml')]);
  foldkit(['fold', join(oracle, 'm.pmml'), '--fraction', '0.9', '-o', join(oracle, 'f.cmml')]);
  const theirs = foldkit(['simulate', join(oracle, 'm.pmml'), join(oracle, 'f.cmml'), '--json']).json;
  const ends = (text) => new Map([...text.matchAll(/<ID>(\d+)<\/ID>\s*<Coords>([^<]*)<\/Coords>/g)].map((m) => {
    const c = m[2].trim().split(/\s+/).map((v) => Math.round(Number(v) * 1e6) / 1e6);
    const [a, b] = [[c[0], c[1]], [c[2], c[3]]].sort((p, q) => p[0] - q[0] || p[1] - q[1]);
    return [Number(m[1]), JSON.stringify([a, b])];
  }));
  const theirEnds = ends(readFileSync(join(oracle, 'm.pmml'), 'utf8'));
  const byPlace = new Map(theirs.final_angles.map((a) => [theirEnds.get(a.joint), a.angle]));
  const ours = await page.evaluate(() => window.foldkit.model.joints().map((j, k) => ({
    ends: [[j.a.x, j.a.y], [j.b.x, j.b.y]], angle: (window.foldkit.simulation.final[k] * 180) / Math.PI })));
  assert.equal(ours.length, 4);
  for (const { ends: e, angle } of ours) {
    const key = JSON.stringify(e.map(([x, y]) => [Math.round(x * 1e6) / 1e6, Math.round(y * 1e6) / 1e6]).sort((p, q) => p[0] - q[0] || p[1] - q[1]));
    assert.ok(byPlace.has(key), `no crease of the generator's Miura-ori at ${key}`);
    assert.ok(Math.abs(angle - byPlace.get(key)) < 1e-6, `crease ${key}: page ${angle}, generator ${byPlace.get(key)}`);
  }
  assert.ok(ours.some((o) => o.angle > 90) && ours.some((o) => o.angle < -90), 'folded well past halfway');
  // And the CLI agrees with the page on the files the page saved.
  const cli = cliNumbers(root, 'drawn-miura.pmml', 'drawn-miura-fold.cmml');
  assert.equal(await shown(page, 'n-dof'), cli.dof.dof);
  assert.ok(close(await shown(page, 'closure-max'), cli.sim.max_closure_error));
  await assertNotBlank(page, 'drawn Miura-ori');
  await keepScreenshot(page, 'serve-miura-drawn');
  assert.deepEqual(page.errors, []);
});

test('Plan and Stiffness answer as the CLI does on the files the page saved', limit, async () => {
  const { root, server } = await serve('plan');
  const page = await openApp(suite.browser(), server.url);
  // The planner list is the server's (GET /api: the planners' own table, which `foldkit bench
  // --list` lists too), in its order, foldkit's default chosen (the plan below runs it by no
  // other word), the planners foldkit refuses greyed with the reason as their tooltip.
  const listed = await page.$$eval('#planner option', (os) => os.map((o) => ({ name: o.value, disabled: o.disabled, title: o.title })));
  assert.deepEqual(listed.map((o) => o.name), foldkit(['bench', '--list', '--json']).json.planners.sampling);
  assert.equal(await page.$eval('#planner', (e) => e.value), 'RRTConnect');
  const served = (await (await fetch(`${server.url}api`)).json()).planners;
  assert.deepEqual(listed.map((o) => o.title), served.map((p) => p.refused));
  assert.ok(listed.some((o) => o.disabled) && listed.every((o) => o.disabled === (o.title !== '')), JSON.stringify(listed));
  await generated(page, 'm', 'miura', 'rows=2 cols=2');
  // A closed goal from Fold, then a plan from flat to it: the same planner, time and seed give
  // the CLI's plan, waypoint for waypoint.
  await page.$eval('#fraction', (e) => { e.value = '0.5'; });
  await page.click('#fold');
  await page.waitForFunction(() => window.foldkit.simulation !== null, { timeout: 60000 });
  await idle(page);
  await page.$eval('#plan-time', (e) => { e.value = '2'; });
  await page.$eval('#plan-seed', (e) => { e.value = '7'; });
  await page.evaluate(() => { window.foldkit.simulation = null; });
  await page.click('#plan');
  await page.waitForFunction(() => window.foldkit.simulation !== null, { timeout: 90000 });
  await idle(page);
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), 'valid');
  const planned = await page.evaluate(() => window.foldkit.sequence.events.length);
  const cliPlan = join(root, 'cli-plan.cmml');
  const plan = foldkit(['plan', join(root, 'm.pmml'), '--goal', join(root, 'm-fold.cmml'), '--planner', 'RRTConnect', '--time', '2', '--seed', '7',
    '-o', cliPlan, '--json']).json;
  assert.equal(readFileSync(cliPlan, 'utf8'), readFileSync(join(root, 'm-plan.cmml'), 'utf8'), 'the page\'s plan is the CLI\'s');
  assert.ok(planned >= 1 && plan.ok !== false, JSON.stringify(plan).slice(0, 200));
  // Stiffness of the planned end state, actor 1 fixed, a load on actor 4.
  await page.$eval('#fixed', (e) => { e.value = '1'; });
  await page.$eval('#load-actor', (e) => { e.value = '4'; });
  await page.$eval('#force', (e) => { e.value = '0 0 -1'; });
  await page.click('#stiffness');
  await page.waitForFunction(() => window.foldkit.stiffness !== undefined, { timeout: 60000 });
  await idle(page);
  const ours = await page.evaluate(() => window.foldkit.stiffness);
  const theirs = foldkit(['stiffness', join(root, 'm.pmml'), join(root, 'm.loadcase'), '--state', join(root, 'm-plan.cmml'), '--json']).json;
  assert.equal(ours.converged, true);
  assert.equal(ours.max_displacement, theirs.max_displacement);
  assert.equal(await page.evaluate(() => window.foldkit.view.stats().displacements), theirs.modules.length);
  assert.deepEqual(page.errors, []);
});

// Without GET /api's answer (or with a server's that lists no planners) the planner list keeps
// index.html's one choice, by no name: a plan from the page then runs foldkit's default.
test('Without the server\'s list of planners the page offers foldkit\'s default', limit, async () => {
  const { server } = await serve('no-planners');
  const page = await suite.browser().newPage();
  page.setDefaultTimeout(30000);
  // GET /api answered 500, in the page itself (puppeteer's request interception stalled the
  // page's worker here): without module workers the page asks on its own thread (boot.js).
  await page.evaluateOnNewDocument(() => {
    window.Worker = undefined;
    const fetched = window.fetch.bind(window);
    window.fetch = (url, init) => (String(url) === '/api'
      ? Promise.resolve(new Response('{"error": "down for the test", "exit": 1}', { status: 500, headers: { 'Content-Type': 'application/json' } }))
      : fetched(url, init));
  });
  await page.goto(server.url, { waitUntil: 'load' });
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
  const choices = () => page.$$eval('#planner option', (os) => os.map((o) => [o.value, o.textContent]));
  assert.deepEqual(await choices(), [['', 'default']]);
  assert.match(await page.$eval('#log', (e) => e.textContent), /down for the test/);
  // An answer without `planners` leaves the list as it is; one with them fills it.
  const filled = await page.evaluate(async () => {
    const { fillPlanners } = await import('/src/planners.js');
    const select = document.getElementById('planner');
    const none = fillPlanners(select, { verbs: [] });
    const some = fillPlanners(select, { planners: [{ name: 'A', default: false, refused: 'cannot' }, { name: 'B', default: true, refused: '' }] });
    return { none, some, value: select.value, disabled: [...select.options].map((o) => o.disabled) };
  });
  assert.deepEqual(filled, { none: false, some: true, value: 'B', disabled: [true, false] });
  await page.close();
});

// The corners of the model, as sorted "x,y" keys rounded to 1e-9.
async function corners(page) {
  return page.evaluate(() => {
    const m = window.foldkit.model;
    const used = new Set(m.triangles.flatMap((t) => t.v));
    return [...used].map((i) => `${(Math.round(m.vertices[i].x * 1e9) / 1e9) + 0},${(Math.round(m.vertices[i].y * 1e9) / 1e9) + 0}`).sort();
  });
}

function keys(points) {
  return points.map(([x, y]) => `${(Math.round(x * 1e9) / 1e9) + 0},${(Math.round(y * 1e9) / 1e9) + 0}`).sort();
}

test('every drawing tool, driven by the mouse, makes a pattern foldkit accepts and moves corners where geometry says', limit, async () => {
  const { server } = await serve('tools');
  const page = await openApp(suite.browser(), server.url);
  const hint = () => page.$eval('#hint', (e) => e.textContent);
  // Polygon: an L of six corners, closed with Enter: ear-clipped into 4 triangles, one actor.
  const L = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]];
  await tool(page, 'polygon');
  for (const [x, y] of L) await click(page, x, y);
  await page.keyboard.press('Enter');
  let check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  assert.deepEqual([check.info.actors, check.info.triangles, check.info.joints], [1, 4, 0]);
  assert.deepEqual(await corners(page), keys(L));
  // Measure: two corners give their distance, a third the angle at the second.
  await tool(page, 'measure');
  for (const [x, y] of [[0, 0], [2, 0], [2, 1]]) await click(page, x, y);
  assert.match(await hint(), /Length 2, 1; angle 90°/);
  // Rotate the selection a quarter turn about the centre of its box (1, 1): Shift snaps to 15°.
  const selectAll = async (r = 2.4) => {
    await tool(page, 'select');
    await drag(page, [-r, -r], [r, r]);
  };
  const about = (f) => keys(L.map(([x, y]) => f(x - 1, y - 1)).map(([x, y]) => [x + 1, y + 1]));
  await selectAll();
  await tool(page, 'rotate');
  await page.keyboard.down('Shift');
  await drag(page, [2.3, 1], [1.02, 2.3]);
  await page.keyboard.up('Shift');
  assert.deepEqual(await corners(page), about((x, y) => [-y, x]));
  await page.click('#undo');
  assert.deepEqual(await corners(page), keys(L));
  // Scale by 2 (drag from 1 to 2 away from the centre, Shift rounds to 0.1), then mirror in x.
  await selectAll();
  await tool(page, 'scale');
  await page.keyboard.down('Shift');
  await drag(page, [2, 1], [3, 1]);
  await page.keyboard.up('Shift');
  assert.deepEqual(await corners(page), about((x, y) => [2 * x, 2 * y]));
  await page.click('#undo');
  await selectAll();
  await tool(page, 'mirror');
  await click(page, 1, 0.5);
  assert.deepEqual(await corners(page), about((x, y) => [-x, y]));
  check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  await page.click('#undo');
  // Split the bottom edge at its middle, then merge the new corner back: still a valid pattern.
  await tool(page, 'split');
  await click(page, 1, 0);
  assert.deepEqual(await corners(page), keys([...L, [1, 0]]));
  check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  assert.equal(check.info.triangles, 5);
  await tool(page, 'merge');
  await click(page, 1, 0);
  await click(page, 0, 0);
  assert.deepEqual(await corners(page), keys(L));
  check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  assert.equal(check.info.triangles, 4);
  // Circular lattice: 2 rings of 6 spokes dragged out to radius 2 away from the L is the pattern
  // `foldkit generate circular --rings 2 --spokes 6 --ring-width 1` makes, count for count.
  await selectAll();
  await page.click('[data-action="delete"]');
  await page.$eval('#lattice', (e) => { e.value = 'rings=2 spokes=6'; });
  await tool(page, 'circular');
  await drag(page, [0, 0], [2, 0]);
  check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  const dir = suite.root('circular');
  foldkit(['generate', 'circular', '--rings', '2', '--spokes', '6', '--ring-width', '1', '-o', join(dir, 'c.pmml')]);
  const theirs = foldkit(['info', join(dir, 'c.pmml'), '--json']).json;
  for (const key of ['actors', 'joints', 'triangles', 'vertices', 'interior_vertices', 'boundary_edges'])
    assert.equal(check.info[key], theirs[key], key);
  // Copy and paste: a second lattice beside the first, grouped as the first is.
  await selectAll(2.6);
  assert.equal(await page.evaluate(() => window.foldkit.editor.selection.triangles.length), theirs.triangles);
  await page.click('[data-action="copy"]');
  await page.click('[data-action="paste"]');
  check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  assert.deepEqual([check.info.actors, check.info.joints], [2 * theirs.actors, 2 * theirs.joints]);
  assert.deepEqual(page.errors, []);
});

test('the paper\'s bird base, opened from a FOLD file, folds in the page as the CLI folds the file', limit, async () => {
  const fixture = join(webDir, '..', '..', 'shared', 'fixtures', 'fold', 'osbo_rigid-origami__birdBase.fold');
  const { root, server } = await serve('bird', ['birdBase.fold'], (dir) => copyFileSync(fixture, join(dir, 'birdBase.fold')));
  const page = await openApp(suite.browser(), server.url);
  const check = await checked(page);
  assert.ok(check.ok, JSON.stringify(check.problems));
  const info = foldkit(['info', join(root, 'birdBase.fold'), '--json']).json;
  assert.deepEqual([check.info.actors, check.info.joints, check.info.interior_vertices], [info.actors, info.joints, info.interior_vertices]);
  await page.$eval('#fraction', (e) => { e.value = '0.5'; });
  await page.click('#fold');
  await page.waitForFunction(() => window.foldkit.simulation !== null, { timeout: 60000 });
  await idle(page);
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), 'valid');
  // The CLI on the FOLD file itself (joints numbered by edge, as the page's are).
  foldkit(['fold', join(root, 'birdBase.fold'), '--fraction', '0.5', '-o', join(root, 'cli.cmml')]);
  const sim = foldkit(['simulate', join(root, 'birdBase.fold'), join(root, 'cli.cmml'), '--json']).json;
  const theirs = new Map(sim.final_angles.map((a) => [a.joint, a.angle]));
  const ours = await page.evaluate(() => window.foldkit.model.joints().map((j, k) => [j.id, (window.foldkit.simulation.final[k] * 180) / Math.PI]));
  assert.equal(ours.length, theirs.size);
  for (const [id, angle] of ours) assert.ok(Math.abs(angle - theirs.get(id)) < 1e-6, `joint ${id}: page ${angle}, CLI ${theirs.get(id)}`);
  assert.ok(ours.some(([, a]) => Math.abs(a) > 45), 'folded');
  assert.equal(await shown(page, 'n-dof'), foldkit(['dof', join(root, 'birdBase.fold'), '--state', join(root, 'cli.cmml'), '--json']).json.dof);
  await keepScreenshot(page, 'serve-bird-base');
  assert.deepEqual(page.errors, []);
});
