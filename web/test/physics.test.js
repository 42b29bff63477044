// physics.js and torque_plot.js against foldkit itself: the physics fields become the CLI's
// options (or a message), and the torque plot drawn from `simulate --model dynamic --series
// X.json` puts every point at its series' time and torque and the stall mark at the time the
// report gives.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, writeFileSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { spawnSync } from 'node:child_process';
import { physicsOptions, physicsVerdict, stallText, stallLabel } from '../src/physics.js';
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

test('the physics fields become simulate\'s options, or say what is wrong', () => {
  assert.deepEqual(physicsOptions({ gravity: '0 0 -9.81', torque: '4' }).options, { model: 'dynamic', gravity: '0,0,-9.81', 'max-torque': 4 });
  assert.deepEqual(physicsOptions({ gravity: ' 1, -2.5,3e0 ', torque: '0.5' }).options, { model: 'dynamic', gravity: '1,-2.5,3', 'max-torque': 0.5 });
  assert.deepEqual(physicsOptions({ gravity: '', torque: '1' }).options, { model: 'dynamic', 'max-torque': 1 }, 'empty gravity: none');
  for (const gravity of ['0 -9.81', '0 0 -9.81 1', 'down', '0 0 NaN', '0 0 Infinity'])
    assert.match(physicsOptions({ gravity, torque: '1' }).error, /^gravity: give three numbers X Y Z in m\/s²/, gravity);
  for (const torque of ['', '0', '-1', 'lots', 'Infinity'])
    assert.match(physicsOptions({ gravity: '0 0 -9.81', torque }).error, /^max torque: give a positive number of N·m/, torque);
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
