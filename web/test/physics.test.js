// physics.js and torque_plot.js against foldkit itself: the physics fields become the CLI's
// options (or a message), the *fast* solver choice folds as the *exact* one does (a flap lifted
// against gravity, a Miura-ori 4 × 4 folded by one motor), and the torque plot drawn from `simulate --model dynamic --series
// X.json` puts every point at its series' time and torque and the stall mark at the time the
// report gives.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, writeFileSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { spawnSync } from 'node:child_process';
import { physicsOptions, physicsDefaults, physicsVerdict, stallText, stallLabel, SOLVERS, DRIVES, DEFAULT_GRAVITY } from '../src/physics.js';
import { plottedJoints, curvePoints, pathData, plotFrame, torquePlotSvg } from '../src/torque_plot.js';

const cli = process.env.FOLDKIT_CLI;

// A two-panel strip, panel 2 lifted to −60° at 30°/s against g = 9.81 m/s² (1 kg/m²): the
// motor needs m·g·d = 4.905 N·m. Returns the report and the series at `torque` N·m.
function flap(torque) {
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-physics-'));
  const pmml = join(dir, 'flap.pmml');
  const cmml = join(dir, 'lift.cmml');
  const series = join(dir, 'lift.json');
  assert.equal(spawnSync(cli, ['generate', 'strip', '--panels', '2', '-o', pmml]).status, 0);
  writeFileSync(cmml, '<CMML><Title>lift</Title><Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>-60</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n');
  const args = ['simulate', pmml, cmml, ...['--model', 'dynamic', '--gravity', '0,0,-9.81', '--max-torque', String(torque)], '--series', series, '--json'];
  const r = spawnSync(cli, args, { encoding: 'utf8', timeout: 60000 });
  assert.ok(r.status === 0 || r.status === 3, r.stderr);
  return { result: JSON.parse(r.stdout), series: JSON.parse(readFileSync(series, 'utf8')), exit: r.status };
}

// The page's options as the CLI's words: every key is the CLI's own long option name (the served
// API takes the same names), true a flag.
function cliWords(options) {
  return Object.entries(options).flatMap(([key, value]) => (value === true ? [`--${key}`] : [`--${key}`, String(value)]));
}

// `simulate` with the options the page's fields build: the report and, when asked, the series.
function simulatePage(pmml, cmml, fields, extra = []) {
  const { options, error } = physicsOptions(fields);
  assert.equal(error, undefined);
  const series = cmml.replace(/\.cmml$/, `-${fields.solver}-series.json`);
  const r = spawnSync(cli, ['simulate', pmml, cmml, ...cliWords(options), ...extra, '--series', series, '--json'], { encoding: 'utf8', timeout: 120000 });
  assert.ok(r.status === 0 || r.status === 3, r.stderr);
  return { result: JSON.parse(r.stdout), series: JSON.parse(readFileSync(series, 'utf8')), exit: r.status };
}

test('the physics fields become simulate\'s options, or say what is wrong', () => {
  const exact = { solver: 'direct', 'time-step': 0.001 };
  const fast = { solver: 'iterative', iterations: 20, 'time-step': 0.01, 'projection-interval': 0.01 };
  assert.deepEqual(SOLVERS, { exact, 'direct-10ms': { solver: 'direct', 'time-step': 0.01 }, fast });
  assert.deepEqual(physicsOptions({ gravity: '0 0 -9.81', torque: '4', density: '1', solver: 'exact' }).options,
    { model: 'dynamic', drive: 'motor', gravity: '0,0,-9.81', 'max-torque': 4, density: 1, ...exact });
  assert.deepEqual(physicsOptions({ gravity: ' 1, -2.5,3e0 ', torque: '0.5', density: ' 0.08 ', solver: 'fast' }).options,
    { model: 'dynamic', drive: 'motor', gravity: '1,-2.5,3', 'max-torque': 0.5, density: 0.08, ...fast });
  assert.deepEqual(physicsOptions({ gravity: '', torque: '1', density: '2.5e-1', solver: 'fast' }).options,
    { model: 'dynamic', drive: 'motor', 'max-torque': 1, density: 0.25, ...fast }, 'empty gravity: none');
  assert.deepEqual(physicsOptions({ gravity: '', torque: '1000', solver: 'direct-10ms' }).options,
    { model: 'dynamic', drive: 'motor', 'max-torque': 1000, density: 1, solver: 'direct', 'time-step': 0.01 });
  assert.deepEqual(physicsOptions({ gravity: '', torque: '1' }).options, { model: 'dynamic', drive: 'motor', 'max-torque': 1, density: 1, ...exact },
    'the model\'s defaults: 1 kg/m², exact');
  for (const gravity of ['0 -9.81', '0 0 -9.81 1', 'down', '0 0 NaN', '0 0 Infinity'])
    assert.match(physicsOptions({ gravity, torque: '1' }).error, /^gravity: give three numbers X Y Z in m\/s²/, gravity);
  for (const torque of ['', '0', '-1', 'lots', 'Infinity'])
    assert.match(physicsOptions({ gravity: '0 0 -9.81', torque }).error, /^max torque: give a positive number of N·m/, torque);
  for (const density of ['', ' ', '0', '-1', 'paper', 'NaN', 'Infinity'])
    assert.equal(physicsOptions({ gravity: '0 0 -9.81', torque: '1', density }).error,
      `density: give a positive number of kg/m² (of sheet), not "${density.trim()}"`, density);
  for (const solver of ['', 'iterative', 'toString', '__proto__'])
    assert.equal(physicsOptions({ gravity: '', torque: '1', solver }).error, `solver: choose one of exact, direct-10ms, fast, not "${solver}"`, solver);
  for (const drive of ['', 'motors', 'Spring', 'includes'])
    assert.equal(physicsOptions({ gravity: '', torque: '1', drive }).error, `drive: choose one of motor, spring, not "${drive}"`, drive);
  assert.deepEqual(DRIVES, ['motor', 'spring']);
  assert.equal(physicsOptions({ gravity: '', torque: '1', drive: 'spring' }).options.drive, 'spring');
  // The first wrong field is the one named.
  assert.match(physicsOptions({ gravity: 'down', torque: '0', density: '0', solver: 'x' }).error, /^gravity/);
  assert.match(physicsOptions({ gravity: '', torque: '1', density: '0', solver: 'x' }).error, /^density/);
});

test('the fixed actor, ground and scale fields become --fixed, --ground and --scale; the pattern\'s own values are the fields\' defaults', () => {
  const base = { gravity: '', torque: '1' };
  const exact = SOLVERS.exact;
  // Empty: not sent (the pattern's <FixedActor> or the first actor; no ground; scale 1).
  assert.deepEqual(physicsOptions({ ...base, fixed: ' ', ground: '', scale: '' }).options, { model: 'dynamic', drive: 'motor', 'max-torque': 1, density: 1, ...exact });
  assert.deepEqual(physicsOptions({ ...base, fixed: ' 2 ', ground: '-0.25', scale: '0.5' }).options,
    { model: 'dynamic', drive: 'motor', 'max-torque': 1, density: 1, fixed: '2', ground: -0.25, scale: 0.5, ...exact });
  assert.equal(physicsOptions({ ...base, fixed: 'None' }).options.fixed, 'none');
  assert.equal(physicsOptions({ ...base, fixed: '+7' }).options.fixed, '7');
  assert.equal(physicsOptions({ ...base, ground: '0' }).options.ground, 0);
  for (const fixed of ['first', '1.5', '1 2', '1e3'])
    assert.equal(physicsOptions({ ...base, fixed }).error, `fixed actor: give an actor ID or "none", or leave it empty for the first actor; not "${fixed}"`, fixed);
  for (const ground of ['low', '1 2', 'inf', 'NaN'])
    assert.match(physicsOptions({ ...base, ground }).error, /^ground: give the ground's height in metres, or leave it empty for none/, ground);
  for (const scale of ['0', '-1', 'big', 'inf'])
    assert.equal(physicsOptions({ ...base, scale }).error, `scale: give a positive number of metres per pattern unit, not "${scale}"`, scale);
  // The fields a pattern opens with: its own values, else the page's.
  assert.deepEqual(physicsDefaults({ density: 0.08, gravity: [9.81, 0, -0.5], fixedActor: 2 }), { density: '0.08', gravity: '9.81 0 -0.5', fixed: '2' });
  assert.deepEqual(physicsDefaults({ density: null, gravity: null, fixedActor: null }), { density: '1', gravity: DEFAULT_GRAVITY, fixed: '' });
  // … which the page then sends as the file says them.
  const d = physicsDefaults({ density: 0.08, gravity: [9.81, 0, -0.5], fixedActor: 2 });
  assert.deepEqual(physicsOptions({ ...d, torque: '1' }).options, { model: 'dynamic', drive: 'motor', gravity: '9.81,0,-0.5', 'max-torque': 1, density: 0.08, fixed: '2', ...exact });
});

test('the fixed actor and the scale change the torque a lift needs, as the page sends them', { skip: !cli && 'FOLDKIT_CLI not set' }, () => {
  // The flap of flap() at 4.66 N·m (0.95 m·g·d) lifted to −60°: held by actor 1 it stalls;
  // with nothing held (--fixed none) the sheet falls freely and the motor lifts it; at scale 2
  // (4 times the mass, twice the lever: 8 m·g·d at the horizontal) it stalls much sooner.
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-physics-'));
  const pmml = join(dir, 'flap.pmml');
  const cmml = join(dir, 'lift.cmml');
  assert.equal(spawnSync(cli, ['generate', 'strip', '--panels', '2', '-o', pmml]).status, 0);
  writeFileSync(cmml, '<CMML><Title>lift</Title><Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>-120</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n');
  const run = (fields) => simulatePage(pmml, cmml, { gravity: '9.81 0 0', torque: '4.66', solver: 'exact', ...fields });
  const held = run({});
  assert.equal(held.exit, 3);
  assert.equal(held.result.fixed, 1);
  assert.ok(Math.abs(held.result.stalls[0].needed_torque - 4.905) < 0.05, `${held.result.stalls[0].needed_torque}`);
  const free = run({ fixed: 'none' });
  assert.equal(free.exit, 0, free.result.message);
  assert.equal(free.result.fixed, 'none');
  const scaled = run({ scale: '2', ground: '-5' });
  assert.equal(scaled.exit, 3);
  assert.deepEqual([scaled.result.scale, scaled.result.ground], [2, -5]);
  const [s1, s2] = [held.result.stalls[0], scaled.result.stalls[0]];
  assert.ok(s2.needed_torque > 1.5 * 4.905 && s2.angle > s1.angle + 30, `scale 2: ${s2.needed_torque} N·m at ${s2.angle}°`);
});

test('the 10 ms solver choices lift the flap as the exact one: the same final angle, torques, stall; density\'s effect', { skip: !cli && 'FOLDKIT_CLI not set' }, (t) => {
  // The two-panel strip of flap(), its panel lifted to −60° at 30°/s against 9.81 m/s²; the
  // exact run is the reference (its torques are m·g·d·cos θ within 1 %, test/apps).
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-physics-'));
  const pmml = join(dir, 'flap.pmml');
  const cmml = join(dir, 'lift.cmml');
  assert.equal(spawnSync(cli, ['generate', 'strip', '--panels', '2', '-o', pmml]).status, 0);
  writeFileSync(cmml, '<CMML><Title>lift</Title><Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>-60</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n');
  const run = (solver, torque, density = '1') => simulatePage(pmml, cmml, { gravity: '0 0 -9.81', torque: String(torque), density, solver });
  const mgd = 9.81 * 0.5;  // a unit square at 1 kg/m², its centroid 0.5 m from the crease
  const exact = run('exact', 5);
  const fast = run('fast', 5);
  assert.deepEqual([exact.exit, fast.exit], [0, 0]);
  assert.deepEqual([exact.result.time_step, fast.result.time_step], [0.001, 0.01]);
  const rad = Math.PI / 180;
  const [a, b] = [exact.result.joints[0], fast.result.joints[0]];
  t.diagnostic(`final angle exact ${a.angle}°, fast ${b.angle}°; peak torque ${a.peak_torque}, ${b.peak_torque} N·m; ` +
    `duration ${exact.result.duration}, ${fast.result.duration} s`);
  assert.ok(Math.abs(a.angle - b.angle) * rad < 1e-4, `final angles within 1e-4 rad: ${a.angle}°, ${b.angle}°`);
  assert.ok(Math.abs(b.angle + 60) * rad < 1e-4, 'fast: at its angle (reach tolerance 1e-4 rad)');
  assert.ok(Math.abs(a.peak_torque - b.peak_torque) < 0.01 * mgd, `peak torques within 1 % of m·g·d: ${a.peak_torque}, ${b.peak_torque}`);
  assert.ok(Math.abs(exact.result.duration - fast.result.duration) < 0.05, 'durations within 50 ms');
  // While the panel rises at its speed (30°/s within 1 % over the frames either side, the motor
  // below its limit in this frame and the last: caught up, the stop not begun), the fast run's
  // torque is m·g·d·cos θ at its own angle within 1 %, as the exact run's is.
  for (const { series } of [exact, fast]) {
    const { time } = series;
    const { angle, torque } = series.joints[0];
    const rate = (k) => (angle[k + 1] - angle[k - 1]) / (time[k + 1] - time[k - 1]);
    const steady = time.map((_, k) => k).filter((k) => k > 0 && k + 1 < time.length && Math.abs(rate(k) + 30) < 0.3 &&
      Math.abs(torque[k - 1]) < 0.99 * 5 && Math.abs(torque[k]) < 0.99 * 5);
    assert.ok(steady.length > 100, `${steady.length} steady frames`);
    for (const k of steady)
      assert.ok(Math.abs(-torque[k] - mgd * Math.cos(angle[k] * rad)) < 0.01 * mgd, `t ${series.time[k]} s: ${torque[k]} N·m at ${angle[k]}°`);
  }
  // The fast run's series: every frame on its 10 ms steps, 10 ms apart (the check that records a
  // frame allows half a step of rounding: 0.01 summed six times once slipped the 0.06 s frame to 0.07 s).
  const gaps = fast.series.time.slice(1).map((time, k) => time - fast.series.time[k]);
  fast.series.time.forEach((time, k) => assert.ok(Math.abs(time * 100 - Math.round(time * 100)) < 1e-6, `frame ${k} at ${time} s`));
  gaps.forEach((gap, k) => assert.ok(Math.abs(gap - 0.01) < 1e-9, `frame ${k + 1}: ${gap} s after the last`));
  // Too little torque: both stall at the start, needing m·g·d within 1 %.
  const [se, sf] = [run('exact', 4), run('fast', 4)];
  assert.deepEqual([se.exit, sf.exit], [3, 3]);
  for (const s of [se.result.stalls[0], sf.result.stalls[0]]) assert.ok(Math.abs(s.needed_torque - mgd) < 0.01 * mgd, `needs ${s.needed_torque} N·m`);
  // The direct solver at 10 ms: the same angle, peak and stall.
  const [coarse, coarseStall] = [run('direct-10ms', 5), run('direct-10ms', 4)];
  assert.deepEqual([coarse.exit, coarse.result.time_step, coarseStall.exit], [0, 0.01, 3]);
  assert.ok(Math.abs(coarse.result.joints[0].angle - a.angle) * rad < 1e-4, `direct, 10 ms: ${coarse.result.joints[0].angle}°`);
  assert.ok(Math.abs(coarse.result.joints[0].peak_torque - a.peak_torque) < 0.01 * mgd);
  assert.ok(Math.abs(coarseStall.result.stalls[0].needed_torque - mgd) < 0.01 * mgd);
  // Density scales the mass: at 0.8 kg/m² the 4 N·m motor lifts the flap (m·g·d = 3.92 N·m).
  const light = run('fast', 4, '0.8');
  assert.equal(light.exit, 0, light.result.message);
  assert.ok(light.result.joints[0].peak_torque > 0.8 * mgd && light.result.joints[0].peak_torque <= 4 + 1e-6);
});

test('the drive field: springs settle where k(θ − θ*) = m·g·d·cos θ, where a 1 N·m motor stalls at once', { skip: !cli && 'FOLDKIT_CLI not set' }, (t) => {
  // The flap of flap(), its crease a spring k = 2·m·g·d, critically damped (I = 1/3 kg·m² for
  // a unit square about its edge), pulled to −60° against gravity. The spring's equilibrium
  // solves k(θ − θ*) = m·g·d·cos θ (Newton below, not foldkit's code); `simulate` reports it as a
  // stall with the torque the spring has, k·|θ − θ*|, against what holding needs, m·g·d·cos θ.
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-physics-'));
  const pmml = join(dir, 'flap.pmml');
  const cmml = join(dir, 'lift.cmml');
  assert.equal(spawnSync(cli, ['generate', 'strip', '--panels', '2', '-o', pmml]).status, 0);
  const mgd = 9.81 * 0.5, k = 2 * mgd, c = 2 * Math.sqrt(k / 3);
  const text = readFileSync(pmml, 'utf8');
  assert.match(text, /<SpringConst>[^<]*<\/SpringConst>/);
  writeFileSync(pmml, text.replace(/<SpringConst>[^<]*/, `<SpringConst>${k}`).replace(/<DampConst>[^<]*/, `<DampConst>${c}`));
  writeFileSync(cmml, '<CMML><Title>lift</Title><Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>-60</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n');
  const run = (drive, gravity) => simulatePage(pmml, cmml, { gravity, torque: '1', solver: 'exact', drive });
  const rad = Math.PI / 180, target = -60 * rad;
  // θ < 0 lifts the flap; gravity pulls it back towards flat with m·g·d·cos θ.
  let theta = target;
  for (let i = 0; i < 50; ++i) theta -= (k * (theta - target) - mgd * Math.cos(theta)) / (k + mgd * Math.sin(theta));
  const sprung = run('spring', '0 0 -9.81');
  t.diagnostic(`spring settles at ${sprung.result.joints[0].angle}°, closed form ${theta / rad}°`);
  assert.equal(sprung.exit, 3);
  assert.equal(sprung.result.drive, 'spring');
  assert.ok(Math.abs(sprung.result.joints[0].angle * rad - theta) < 2e-3, `${sprung.result.joints[0].angle}° against ${theta / rad}°`);
  const stall = sprung.result.stalls[0];
  assert.ok(Math.abs(stall.needed_torque - mgd * Math.cos(theta)) < 0.01 * mgd, `needs ${stall.needed_torque} N·m`);
  assert.ok(Math.abs(stall.available_torque - k * (theta - target)) < 0.01 * mgd, `has ${stall.available_torque} N·m`);
  // Without gravity the spring reaches its angle; a 1 N·m motor cannot lift the flap at all.
  const free = run('spring', '');
  assert.equal(free.exit, 0, free.result.message);
  assert.ok(Math.abs(free.result.joints[0].angle + 60) * rad < 1e-3, `${free.result.joints[0].angle}°`);
  const motor = run('motor', '0 0 -9.81');
  assert.equal(motor.exit, 3);
  assert.equal(motor.result.drive, 'motor');
  assert.ok(Math.abs(motor.result.stalls[0].needed_torque - mgd) < 0.01 * mgd, `the motor needs ${motor.result.stalls[0].needed_torque} N·m`);
});

test('the fast solver folds a Miura-ori 4 × 4 by one motor as the exact one, loops closed', { skip: !cli && 'FOLDKIT_CLI not set' }, (t) => {
  // The scene of microbench/one_motor_miura.hpp: `foldkit fold` to half way is the kinematic
  // fold; one motor drives the first actor's most folded crease to its angle there at 0.5 rad/s,
  // from `fold`'s state a little past flat (0.064 of the way, 0.2 rad: the flat sheet is a
  // bifurcation), gravity off, torque 1e6 N·m.
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-physics-'));
  const pmml = join(dir, 'miura.pmml');
  const [half, start, cmml] = ['half.cmml', 'start.cmml', 'one.cmml'].map((f) => join(dir, f));
  assert.equal(spawnSync(cli, ['generate', 'miura', '--rows', '4', '--cols', '4', '-o', pmml]).status, 0);
  assert.equal(spawnSync(cli, ['fold', pmml, '--fraction', '0.5', '--no-collision', '-o', half]).status, 0);
  assert.equal(spawnSync(cli, ['fold', pmml, '--fraction', '0.064', '--no-collision', '-o', start]).status, 0);
  const end = new Map([...readFileSync(half, 'utf8').matchAll(/<ID>(\d+)<\/ID>\s*<FoldAngle>([^<]+)</g)].map((m) => [Number(m[1]), Number(m[2])]));
  const onFirst = [...readFileSync(pmml, 'utf8').matchAll(/<Joint>\s*<ID>(\d+)<\/ID>[\s\S]*?<ActorIDs>(\d+) (\d+)</g)]
    .filter((m) => m[2] === '1' || m[3] === '1').map((m) => Number(m[1]));
  const drive = onFirst.reduce((best, j) => (Math.abs(end.get(j)) > Math.abs(end.get(best)) ? j : best));
  writeFileSync(cmml, `<CMML><Title>one motor</Title><Fold><EventNumber>1</EventNumber><ID>${drive}</ID><FoldAngle>${end.get(drive)}</FoldAngle>` +
    `<Velocity>${(0.5 * 180) / Math.PI}</Velocity></Fold></CMML>\n`);
  const run = (solver) => simulatePage(pmml, cmml, { gravity: '', torque: '1e6', solver }, ['--start', start]);
  const [exact, fast] = [run('exact'), run('fast')];
  assert.deepEqual([exact.exit, fast.exit], [0, 0], fast.result.message);
  const rad = Math.PI / 180;
  const worst = (r, angleOf) => Math.max(...r.result.joints.map((j) => Math.abs(j.angle - angleOf(j.joint)) * rad));
  const apart = worst(fast, (id) => exact.result.joints.find((j) => j.joint === id).angle);
  const fromFold = worst(fast, (id) => end.get(id));
  t.diagnostic(`fast against exact ${apart.toExponential(2)} rad, against fold ${fromFold.toExponential(2)} rad; drift ` +
    `${fast.result.max_closure_error.toExponential(2)} rad; ${exact.result.seconds.toFixed(3)} s exact, ${fast.result.seconds.toFixed(3)} s fast`);
  assert.ok(apart < 1e-3, `every joint's final angle within 1e-3 rad of the exact run's: ${apart} rad`);
  assert.ok(fromFold < 1e-3, `and of the kinematic fold's: ${fromFold} rad`);
  assert.ok(fast.result.max_closure_error <= 1e-4, `loops closed: ${fast.result.max_closure_error} rad`);
  assert.ok(Math.abs(exact.result.duration - fast.result.duration) < 0.1, 'durations within 0.1 s');
});

test('a stall is worded with its joint, time and torques; a run without one with its peak', { skip: !cli && 'FOLDKIT_CLI not set' }, () => {
  const stalled = flap(4);
  assert.equal(stalled.exit, 3);
  const s = stalled.result.stalls[0];
  assert.equal(stallText(s), `joint 1 stalled at ${s.time.toFixed(2)} s (event 1) at ${Number(s.angle.toPrecision(3))}° of -60°: ` +
    `it needs ${Number(s.needed_torque.toPrecision(3))} N·m, has 4 N·m`);
  assert.match(stallText(s), /needs 4\.9 N·m/);  // m·g·d = 4.905
  assert.equal(stallLabel(s), `joint 1, ${s.time.toFixed(2)} s`);
  assert.equal(physicsVerdict(stalled.result), stallText(s));
  const lifted = flap(5);
  assert.equal(lifted.exit, 0);
  const peak = lifted.result.joints[0].peak_torque;
  assert.ok(peak > 4.9 && peak < 5.01, `peak ${peak} N·m: between m·g·d and the limit`);
  assert.equal(physicsVerdict(lifted.result), `every joint reached its angle; the largest torque ${Number(peak.toPrecision(3))} N·m (joint 1) of 5 N·m`);
  assert.equal(physicsVerdict({ status: 'closure-violated', message: 'the loops opened' }), 'the loops opened');
});

test('a motor blocked by the ground is worded with what it touches', { skip: !cli && 'FOLDKIT_CLI not set' }, () => {
  // Panel 2 of a strip (scale 0.5 m) turned down 60° toward a ground 0.25 m below: its far edge
  // lands on the ground near 30°, and the motor is blocked there (a collision, exit 3).
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-physics-'));
  const pmml = join(dir, 'strip.pmml');
  const cmml = join(dir, 'down.cmml');
  assert.equal(spawnSync(cli, ['generate', 'strip', '--panels', '2', '-o', pmml]).status, 0);
  writeFileSync(cmml, '<CMML><Title>down</Title><Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>60</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n');
  const r = spawnSync(cli, ['simulate', pmml, cmml, '--model', 'dynamic', '--scale', '0.5', '--ground', '-0.25', '--json'],
    { encoding: 'utf8', timeout: 60000 });
  assert.equal(r.status, 3, r.stderr);
  const result = JSON.parse(r.stdout);
  const s = result.stalls[0];
  assert.deepEqual(s.blocked_by, [2]);
  assert.ok(Math.abs(s.angle - 30) < 1, `blocked at ${s.angle}°, near asin(0.25 / 0.5) = 30°`);
  assert.equal(physicsVerdict(result), `joint 1 blocked at ${s.time.toFixed(2)} s (event 1) at ${Number(s.angle.toPrecision(3))}° of 60°: ` +
    'actor 2 touches the ground');
});

test('the plotted joints: the selected ones the series has, else the stalled and the hardest pulling', () => {
  const series = { time: [0], event: [1], joints: [1, 2, 3, 4, 5, 6].map((joint) => ({ joint, angle: [0], torque: [0] })) };
  const result = { stalls: [{ joint: 5 }], joints: [1, 2, 3, 4, 5, 6].map((joint) => ({ joint, peak_torque: [0.1, 3, 0, 2, 1, 4][joint - 1] })) };
  assert.deepEqual(plottedJoints([3, 99, 1], result, series), [3, 1]);
  assert.deepEqual(plottedJoints([1, 2, 3, 4, 5, 6], result, series, 2), [1, 2]);
  assert.deepEqual(plottedJoints([], result, series), [5, 6, 2, 4], 'stalled first, then by peak torque, at most 4, none of zero torque');
  assert.deepEqual(plottedJoints([], { stalls: [], joints: [] }, series), []);
});

test('a long curve keeps every pixel column\'s extremes; a short one every point', () => {
  const x = (t) => t;
  const y = (v) => -v;
  const times = Array.from({ length: 1000 }, (_, k) => k / 10);   // 100 px, 10 points per column
  const values = times.map((t, k) => (k === 517 ? 50 : k === 733 ? -40 : Math.sin(t)));
  const points = curvePoints(times, values, x, y, 100);
  assert.ok(points.length <= 4 * 101, `${points.length} points`);
  assert.ok(points.some(([, py]) => py === -50) && points.some(([, py]) => py === 40), 'both spikes kept');
  for (let k = 1; k < points.length; k++) assert.ok(points[k][0] >= points[k - 1][0], 'in time order');
  assert.deepEqual(curvePoints([0, 1, 2], [3, 4, 5], x, y, 100), [[0, -3], [1, -4], [2, -5]]);
  assert.equal(pathData([[0, 1], [2.25, 3.333]]), 'M0.00 1.00 L2.25 3.33');
});

// The numbers of an SVG path "M x y L x y …".
const pathPoints = (d) => d.split(/ ?[ML]/).filter(Boolean).map((p) => p.trim().split(' ').map(Number));

test('the plot of foldkit\'s series: every point at its time and torque, the stall at the report\'s time', { skip: !cli && 'FOLDKIT_CLI not set' }, () => {
  const { result, series } = flap(4);
  const [width, height] = [270, 150];
  const svg = torquePlotSvg({ series, joints: [1], stalls: result.stalls, limit: result.max_torque, width, height });
  const paths = [...svg.matchAll(/<path class="torque-series" data-joint="(\d+)"[^>]* d="([^"]*)"/g)];
  assert.equal(paths.length, 1);
  assert.equal(paths[0][1], '1');
  const points = pathPoints(paths[0][2]);
  const torque = series.joints[0].torque;
  assert.equal(points.length, series.time.length, 'a short series: every frame a point');
  // Back from pixels to data through the same frame the plot used (its range holds the torques
  // and the ±4 N·m limit, padded 5 %).
  const low = Math.min(...torque, -4);
  const high = Math.max(...torque, 4);
  const pad = 0.05 * (high - low);
  const f = plotFrame({ width, height, duration: series.time[series.time.length - 1], low: low - pad, high: high + pad });
  const perPixel = (high - low + 2 * pad) / (f.bottom - f.top);
  points.forEach(([px, py], k) => {
    assert.ok(Math.abs(px - f.x(series.time[k])) <= 0.005 + 1e-9, `frame ${k}: x`);
    assert.ok(Math.abs(py - f.y(torque[k])) <= 0.005 + 1e-9, `frame ${k}: y`);
  });
  assert.ok(perPixel < 0.1, 'a pixel is less than 0.1 N·m');
  const stall = svg.match(/<line class="stall-mark" data-joint="1" data-time="([^"]*)" x1="([^"]*)"/);
  assert.ok(stall, 'the stall is marked');
  assert.equal(Number(stall[1]), result.stalls[0].time);
  assert.ok(Math.abs(Number(stall[2]) - f.x(result.stalls[0].time)) <= 0.005);
  assert.equal([...svg.matchAll(/class="limit"/g)].length, 2, 'the motor limit, both signs');
  // A joint not plotted has no stall mark; a limit far beyond the curves is left out.
  assert.doesNotMatch(torquePlotSvg({ series, joints: [], stalls: result.stalls, limit: 4 }), /stall-mark/);
  assert.doesNotMatch(torquePlotSvg({ series, joints: [1], stalls: [], limit: 1e6 }), /class="limit"/);
});
