// cmml.js against foldkit itself: the CMML the page writes is read by the CLI as the same
// sequence, and the angles read from a simulated trajectory (FOLD frames, the opposite sign)
// equal the simulator's own final angles per joint.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, writeFileSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { spawnSync } from 'node:child_process';
import { writeCMML, readCMML, CmmlReader, unpackSequence, setFold, anglesAfterEvents, foldFrameAngles } from '../src/cmml.js';

const cli = process.env.FOLDKIT_CLI;
const run = (args) => {
  const r = spawnSync(cli, args, { encoding: 'utf8', timeout: 60000 });
  assert.equal(r.status, 0, `foldkit ${args.join(' ')}: ${r.stderr}`);
  return args.includes('--json') ? JSON.parse(r.stdout) : r;
};

test('setFold keeps one fold per joint and event, events in order', () => {
  const s = { title: 't', events: [] };
  setFold(s, 2, { joint: 1, angle: 30, speed: 10 });
  setFold(s, 1, { joint: 1, angle: 10, speed: 10 });
  setFold(s, 2, { joint: 1, angle: -45, speed: 5 });
  setFold(s, 2, { joint: 3, angle: 90, speed: 5 });
  assert.deepEqual(s.events.map((e) => e.number), [1, 2]);
  assert.deepEqual(s.events[1].folds, [{ joint: 1, angle: -45, speed: 5 }, { joint: 3, angle: 90, speed: 5 }]);
  // Unchanged angles carry through: joint 3 keeps 0 after event 1, joint 1 keeps -45.
  assert.deepEqual(anglesAfterEvents(s, [1, 3]), [[10, 0], [-45, 90]]);
});

test('writeCMML and readCMML round-trip exactly, numbers included', () => {
  const s = { title: 'a & <b>', events: [{ number: 0, folds: [{ joint: 7, angle: 0.1 + 0.2, speed: 1e-3 }] },
    { number: 5, folds: [{ joint: 2, angle: -180, speed: 90 }, { joint: 3, angle: 179.99999999999997, speed: 30 }] }] };
  assert.deepEqual(readCMML(writeCMML(s)), s);
  assert.throws(() => readCMML('<PMML/>'), /not a CMML/);
  assert.throws(() => readCMML('<CMML><Fold><EventNumber>1</EventNumber><ID>x</ID><FoldAngle>1</FoldAngle><Velocity>1</Velocity></Fold></CMML>'), /not a number/);
});

test('foldkit reads the CMML the page writes as the same sequence', { skip: !cli && 'FOLDKIT_CLI is not set' }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-cmml-'));
  run(['generate', 'miura', '--rows', '2', '--cols', '2', '-o', join(dir, 'm.pmml')]);
  const s = { title: 'page', events: [{ number: 1, folds: [{ joint: 1, angle: -30.5, speed: 45 }, { joint: 2, angle: 12.25, speed: 45 }] },
    { number: 2, folds: [{ joint: 1, angle: -40, speed: 20 }] }] };
  writeFileSync(join(dir, 's.cmml'), writeCMML(s));
  run(['validate', join(dir, 's.cmml'), '--pattern', join(dir, 'm.pmml')]);
  run(['convert', join(dir, 's.cmml'), join(dir, 'again.cmml'), '--pattern', join(dir, 'm.pmml')]);
  const again = readCMML(readFileSync(join(dir, 'again.cmml'), 'utf8'));
  // foldkit's one-event CMML of the end state: joint 1 at -40, joint 2 at 12.25, the others 0.
  const end = new Map(again.events.flatMap((e) => e.folds).map((f) => [f.joint, f.angle]));
  assert.equal(end.get(1), -40);
  assert.equal(end.get(2), 12.25);
});

test('trajectory frames read back as the simulator\'s angles, in foldkit\'s sign', { skip: !cli && 'FOLDKIT_CLI is not set' }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'foldkit-frames-'));
  const pmml = join(dir, 'm.pmml');
  run(['generate', 'miura', '--rows', '3', '--cols', '2', '-o', pmml]);
  run(['fold', pmml, '--fraction', '0.6', '-o', join(dir, 'f.cmml')]);
  const sim = run(['simulate', pmml, join(dir, 'f.cmml'), '--frames', join(dir, 't.fold'), '--max-frames', '50', '--json']);
  // The joints' end points straight from the PMML foldkit wrote (not through cmml.js).
  const info = JSON.parse(readFileSync(join(dir, 't.fold'), 'utf8'));
  const joints = sim.final_angles.map(({ joint }) => joint);
  const pattern = readFileSync(pmml, 'utf8');
  const ends = new Map([...pattern.matchAll(/<ID>(\d+)<\/ID>\s*<Coords>([^<]*)<\/Coords>/g)].map((m) => {
    const c = m[2].trim().split(/\s+/).map(Number);
    return [Number(m[1]), { a: { x: c[0], y: c[1] }, b: { x: c[2], y: c[3] } }];
  }));
  const list = joints.map((id) => ({ id, ...ends.get(id) }));
  const { frames, final, times } = foldFrameAngles(info, list);
  assert.ok(frames.length >= 2 && frames.length <= 51, `${frames.length} frames`);
  // Each frame's time: from 0, increasing, the last at the end of the simulation.
  assert.equal(times.length, frames.length);
  assert.equal(times[0], 0);
  for (let k = 1; k < times.length; k++) assert.ok(times[k] > times[k - 1], `frame ${k} at ${times[k]}`);
  assert.ok(Math.abs(times[times.length - 1] - sim.duration) < 1e-9, `${times[times.length - 1]} vs ${sim.duration}`);
  sim.final_angles.forEach(({ angle }, k) => {
    assert.ok(Math.abs((final[k] * 180) / Math.PI - angle) < 1e-9, `joint ${joints[k]}: ${(final[k] * 180) / Math.PI} vs ${angle}`);
    assert.ok(Math.abs((frames[frames.length - 1][k] * 180) / Math.PI - angle) < 1e-9);
    assert.equal(frames[0][k], 0);
  });
  assert.ok(sim.final_angles.some(({ angle }) => angle > 1) && sim.final_angles.some(({ angle }) => angle < -1), 'both signs occur');
  assert.throws(() => foldFrameAngles(info, [{ id: 99, a: { x: 0.5, y: 0.5 }, b: { x: 9, y: 9 } }]), /changed since it was simulated/);
});

test('read piece by piece, CMML reads as it does whole, wherever the pieces end', () => {
  const s = { title: 'pieces & <cuts>', events: [1, 2, 3, 4].map((number) => ({ number, folds: [1, 2, 3].map((joint) => ({ joint, angle: number * 10.125 + joint, speed: 30 })) })) };
  // Comments (one holding a <Fold>, one between fields), the title after a fold, CRLF line ends.
  const text = writeCMML(s).replace('<CMML>', '<CMML>\r\n<!-- <Fold><EventNumber>9</EventNumber></Fold> -->')
    .replace('    <ID>2</ID>', '    <!-- a </Fold> here is no end -->\n    <ID>2</ID>').replace(/\n/g, '\r\n');
  const whole = readCMML(text);
  assert.equal(whole.title, s.title);
  assert.deepEqual(whole.events, s.events);
  for (let size = 1; size <= 97; size += 3) {
    const reader = new CmmlReader();
    for (let k = 0; k < text.length; k += size) reader.push(text.slice(k, k + size));
    assert.deepEqual(reader.finish(), whole, `pieces of ${size}`);
  }
  const late = new CmmlReader();
  late.push('<CMML><Fold><EventNumber>1</EventNumber><ID>4</ID><FoldAngle>5</FoldAngle><Velocity>6</Velocity></Fold><Title>la');
  late.push('te</Title></CMML>');
  assert.deepEqual(late.finish(), { title: 'late', events: [{ number: 1, folds: [{ joint: 4, angle: 5, speed: 6 }] }] });
  const bad = new CmmlReader();
  bad.push('<PMML><Fold><EventNumber>1</EventNumber><ID>4</ID><FoldAngle>5</FoldAngle><Velocity>6</Velocity></Fold>');
  assert.throws(() => bad.finish(), /not a CMML/);
  assert.throws(() => new CmmlReader().push('<CMML><Fold><ID>4</ID></Fold>'), /no <EventNumber>/);
  // Packed into arrays (a worker's answer) and back, exactly; events in order of number, each
  // event's folds in file order wherever they stand in the file.
  const packer = new CmmlReader();
  packer.push(text);
  assert.deepEqual(unpackSequence(packer.packed()), whole);
  const mixed = writeCMML({ title: '', events: [{ number: 5, folds: [{ joint: 1, angle: 1, speed: 1 }] }, { number: -2, folds: [{ joint: 2, angle: 2, speed: 2 }] }] })
    + writeCMML({ title: '', events: [{ number: 5, folds: [{ joint: 3, angle: 3, speed: 3 }] }] });
  assert.deepEqual(readCMML(mixed).events, [{ number: -2, folds: [{ joint: 2, angle: 2, speed: 2 }] },
    { number: 5, folds: [{ joint: 1, angle: 1, speed: 1 }, { joint: 3, angle: 3, speed: 3 }] }]);
});
