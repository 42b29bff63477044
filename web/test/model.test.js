// Tests of the crease-pattern model (web/src/model.js). The oracles are foldkit's own files and
// numbers: the fixtures were written by `foldkit generate`, and the expected counts below were
// printed by `foldkit info FILE --json` for those files. With FOLDKIT_CLI set (the path of the
// foldkit binary) the patterns the model writes are also checked by `foldkit validate` and
// `foldkit info`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { PatternModel, History, snapPoint, earClip, signedArea, parseXml } from '../src/model.js';
import { addCircular, addGrid, addPolygon, addTriangle, copyTriangles, deleteTriangles, group, mergeVertices, moveVertices, paste, splitEdge, transformVertices, ungroup } from '../src/model_edits.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const fixture = (name) => fs.readFileSync(path.join(here, 'fixtures', name), 'utf8');
const CLI = process.env.FOLDKIT_CLI ? path.resolve(process.env.FOLDKIT_CLI) : null;
const needsCli = { skip: CLI ? false : 'FOLDKIT_CLI is not set' };

// `foldkit info FILE --json` on each fixture (foldkit generate … -o FILE) said these counts.
const EXPECTED = {
  'miura-3x3.pmml': { actors: 9, joints: 12, triangles: 18, vertices: 16 }, // miura --rows 3 --cols 3
  'waterbomb-2x3.pmml': { actors: 15, joints: 17, triangles: 15, vertices: 14 }, // waterbomb --units 2 --rows 3
  'boat.pmml': { actors: 8, joints: 10, triangles: 12, vertices: 11 }, // boat
  'circular-3x8.pmml': { actors: 24, joints: 40, triangles: 40, vertices: 25 }, // circular --rings 3 --spokes 8
  'grid-2x2.pmml': { actors: 4, joints: 4, triangles: 8, vertices: 9 }, // grid --rows 2 --cols 2
};

function counts(m) {
  return { actors: m.actors().length, joints: m.joints().length, triangles: m.triangles.length, vertices: m.vertices.length };
}

// Each triangle as its exact corner coordinates (sorted) and its actor: independent of numbering.
function triangleSet(m, withActor = true) {
  return m.triangles
    .map((t) => t.v.map((i) => `${m.vertices[i].x} ${m.vertices[i].y}`).sort().join(' | ') + (withActor ? ` @${t.actor}` : ''))
    .sort();
}

function jointRecords(m) {
  return m.joints().map((j) => ({ id: j.id, a: j.a, b: j.b, actors: j.actors, spring: j.spring, damping: j.damping, assignment: j.assignment }));
}

function area(m) {
  return m.triangles.reduce((s, _, t) => s + m.triangleArea(t), 0);
}

// Brute force: no used vertex lies strictly inside any edge, and no edge has more than 2 triangles.
function assertConforming(m) {
  const used = new Set(m.triangles.flatMap((t) => t.v));
  const tol = 1e-9;
  for (const e of m.edges()) {
    assert.ok(e.triangles.length <= 2, `edge ${e.i}-${e.j} has ${e.triangles.length} triangles`);
    const a = m.vertices[e.i], b = m.vertices[e.j];
    const len = Math.hypot(b.x - a.x, b.y - a.y);
    for (const v of used) {
      if (v === e.i || v === e.j) continue;
      const p = m.vertices[v];
      const along = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / len;
      const off = Math.abs((p.x - a.x) * (b.y - a.y) - (p.y - a.y) * (b.x - a.x)) / len;
      assert.ok(!(off < tol && along > tol && along < len - tol), `T-junction: vertex ${v} inside edge ${e.i}-${e.j}`);
    }
  }
}

function pointInPolygon(p, poly) {
  let inside = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const a = poly[i], b = poly[j];
    if (a.y > p.y !== b.y > p.y && p.x < ((b.x - a.x) * (p.y - a.y)) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

function assertThrowsLine(text, line, pattern) {
  assert.throws(() => PatternModel.fromPMML(text), (e) => {
    assert.match(e.message, new RegExp(`^${line}: `), `wrong line in '${e.message}'`);
    if (pattern) assert.match(e.message, pattern);
    return true;
  });
}

// ------------------------------------------------------------------------------ reading

for (const [name, expected] of Object.entries(EXPECTED)) {
  test(`reads ${name} with the counts foldkit info reports`, () => {
    const m = PatternModel.fromPMML(fixture(name));
    assert.deepEqual(counts(m), expected);
    assert.deepEqual(m.warnings, []);
  });
}

test('fixture joints keep their IDs, actors, spring, damping and assignment', () => {
  for (const name of Object.keys(EXPECTED)) {
    const text = fixture(name);
    const m = PatternModel.fromPMML(text);
    // The file itself, read element by element, is the oracle.
    const fileJoints = parseXml(text).children.filter((c) => c.name === 'Joint');
    assert.equal(fileJoints.length, m.joints().length, name);
    for (const el of fileJoints) {
      const get = (tag) => el.children.find((c) => c.name === tag)?.text.trim();
      const j = m.joint(Number(get('ID')));
      assert.ok(j, `${name}: joint ${get('ID')}`);
      const [x1, y1, x2, y2] = get('Coords').split(/\s+/).map(Number);
      const ends = [`${j.a.x} ${j.a.y}`, `${j.b.x} ${j.b.y}`].sort();
      assert.deepEqual(ends, [`${x1} ${y1}`, `${x2} ${y2}`].sort(), `${name}: joint ${j.id} segment`);
      assert.deepEqual(j.actors, get('ActorIDs').split(/\s+/).map(Number).sort((a, b) => a - b));
      assert.equal(j.spring, Number(get('SpringConst')));
      assert.equal(j.damping, Number(get('DampConst')));
      assert.equal(j.assignment, get('Assignment') ?? 'U');
    }
  }
});

test('the Miura fixture has the valley and mountain creases foldkit wrote', () => {
  const m = PatternModel.fromPMML(fixture('miura-3x3.pmml'));
  const j1 = m.joint(1);
  assert.equal(j1.assignment, 'V');
  assert.deepEqual([j1.a, j1.b], [{ x: 1, y: 0.577350269189626 }, { x: 1, y: 1.577350269189626 }]);
  const byKind = {};
  for (const j of m.joints()) byKind[j.assignment] = (byKind[j.assignment] ?? 0) + 1;
  const text = fixture('miura-3x3.pmml');
  assert.equal(byKind.M ?? 0, (text.match(/<Assignment>M</g) ?? []).length);
  assert.equal(byKind.V ?? 0, (text.match(/<Assignment>V</g) ?? []).length);
});

test('a joint spanning two collinear edges stays one joint, and is written as one', () => {
  const m = PatternModel.fromPMML(fixture('collinear-joint.pmml'));
  // foldkit counts one joint: its segment runs through the corner (1,1). Before, the model split it
  // into one joint per edge, so a file saved from the page had a joint more, and a CMML written for
  // the file folded only half of the crease.
  assert.deepEqual(counts(m), { actors: 2, joints: 1, triangles: 6, vertices: 7 });
  const [j] = m.joints();
  assert.equal(j.id, 7);
  assert.deepEqual([j.spring, j.damping, j.assignment, j.actors], [2.5, 0.25, 'M', [1, 2]]);
  assert.deepEqual([j.a, j.b], [{ x: 1, y: 0 }, { x: 1, y: 2 }]);
  assert.equal(j.keys.length, 2);
  const corner = m.nearestVertex({ x: 1, y: 1 });
  assert.equal(m.jointOnEdge(j.va, corner).id, 7);
  assert.equal(m.jointOnEdge(corner, j.vb).id, 7);
  const text = m.toPMML();
  assert.equal((text.match(/<Joint>/g) ?? []).length, 1);
  assert.match(text, /<Coords>1 0 1 2<\/Coords>/);
  // Setting the joint sets both of its edges.
  m.setJoint(7, { assignment: 'V' });
  assert.equal(m.jointOnEdge(corner, j.vb).assignment, 'V');
});

test('a run of edges splits where an edit breaks it; the part with the smallest end keeps the ID', () => {
  const m = PatternModel.fromPMML(fixture('collinear-joint.pmml'));
  // The upper triangle of actor 2 on the crease becomes an actor of its own: the upper edge now
  // lies between actors 1 and 3, another crease.
  const upper = m.trianglesOf(2).find((t) => m.triangles[t].v.some((v) => m.vertices[v].y === 2 && m.vertices[v].x === 1));
  group(m, [upper]);
  const joints = m.joints();
  assert.equal(joints.length, 3, 'the lower half, the upper half, and the new crease inside actor 2');
  const lower = joints.find((j) => j.a.x === 1 && j.b.x === 1 && j.a.y === 0);
  const top = joints.find((j) => j.a.x === 1 && j.b.x === 1 && j.b.y === 2);
  assert.equal(lower.id, 7);
  assert.deepEqual([lower.b, lower.actors], [{ x: 1, y: 1 }, [1, 2]]);
  assert.notEqual(top.id, 7);
  assert.deepEqual([top.a, top.actors, top.assignment, top.spring], [{ x: 1, y: 1 }, [1, 3], 'M', 2.5]);
  // Undone by a snapshot: one joint again.
  const again = PatternModel.fromPMML(fixture('collinear-joint.pmml'));
  const snap = again.snapshot();
  group(again, [upper]);
  again.restore(snap);
  assert.deepEqual(again.joints().map((j) => [j.id, j.keys.length]), [[7, 2]]);
});

test('an edge that continues a crease between the same two actors joins it; paste copies runs whole', () => {
  const m = new PatternModel();
  addPolygon(m, [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 1, y: 1 }, { x: 0, y: 1 }], 1);
  addPolygon(m, [{ x: 1, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 1 }, { x: 1, y: 1 }], 2);
  assert.equal(m.joints().length, 1);
  const id = m.joints()[0].id;
  addTriangle(m, { x: 0, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 2 }, 1);
  addTriangle(m, { x: 1, y: 1 }, { x: 2, y: 1 }, { x: 1, y: 2 }, 2);
  const [j] = m.joints();
  assert.deepEqual([m.joints().length, j.id, j.keys.length, j.a, j.b], [1, id, 2, { x: 1, y: 0 }, { x: 1, y: 2 }]);
  // A crease at a corner, not straight through it, is another joint.
  addTriangle(m, { x: 2, y: 0 }, { x: 3, y: 0 }, { x: 2, y: 1 }, 3);
  assert.equal(m.joints().length, 2);
  const c = PatternModel.fromPMML(fixture('collinear-joint.pmml'));
  paste(c, copyTriangles(c, c.triangles.map((_, t) => t)), 3, 0);
  assert.deepEqual(c.joints().map((x) => x.keys.length), [2, 2]);
  assert.deepEqual(c.joints().map((x) => x.assignment), ['M', 'M']);
});

test('vertices within 1e-9 of the diagonal are welded on read', () => {
  const text = `<PMML><Actor><ID>1</ID><Triangle>0 0 1 0 0 1</Triangle></Actor>
    <Actor><ID>2</ID><Triangle>1.0000000000001 0 1 1 0 1.0000000000001</Triangle></Actor></PMML>`;
  const m = PatternModel.fromPMML(text);
  assert.equal(m.vertices.length, 4);
  assert.equal(m.joints().length, 1, 'the welded shared edge gets a joint');
  assert.equal(m.joints()[0].id, 1);
});

test('reader handles the declaration, comments, CDATA, entities and self-closing tags', () => {
  const text = `\ufeff<?xml version="1.0" encoding="UTF-8"?>
<!-- a comment -->
<!DOCTYPE PMML>
<PMML>
  <Title>A &amp; B &lt;&#x263A;&gt;</Title>
  <!-- <Actor> in a comment is ignored -->
  <Actor>
    <ID> 3 </ID>
    <Triangle><![CDATA[0 0 1 0]]> 0 1</Triangle>
  </Actor>
</PMML>
<!-- trailing comment -->
`;
  const m = PatternModel.fromPMML(text);
  assert.equal(m.title, 'A & B <\u263a>');
  assert.deepEqual(m.actors(), [3]);
  assert.equal(m.triangles.length, 1);
  const back = PatternModel.fromPMML(m.toPMML());
  assert.equal(back.title, m.title);
  assert.equal(parseXml('<a><b/><c x="1"/></a>').children.length, 2);
});

test('malformed input throws with the line number', () => {
  assertThrowsLine('<PMML>\n  <Actor>\n    <ID>1</ID>\n  </Joint>\n</PMML>', 4, /expected <\/Actor>/);
  assertThrowsLine('<PMML>\n<Actor>\n<ID>1</ID>\n<Triangle>0 0 1 0 1</Triangle>\n</Actor>\n</PMML>', 4, /needs 6 numbers/);
  assertThrowsLine('<PMML>\n<Actor>\n<ID>one</ID>\n<Triangle>0 0 1 0 0 1</Triangle>\n</Actor>\n</PMML>', 3, /integer/);
  assertThrowsLine('<PMML>\n<Actor>\n<ID>1</ID>\n<Triangle>0 0 1 0 0 x</Triangle>\n</Actor>\n</PMML>', 4, /not a finite number/);
  assertThrowsLine('<PMML>\n\n<Title>a & b</Title>\n</PMML>', 3, /entity/);
  assertThrowsLine('<PMML>\n<Actor>\n<ID>1</ID>\n<Triangle>0 0 1 0 0 1</Triangle>\n</Actor>\n<Shape/>\n</PMML>', 6, /unknown element <Shape>/);
  assertThrowsLine('<?xml version="1.0"?>\n<PMML>\n<Actor>\n<ID>1</ID>', 3, /<Actor> is not closed/);
  assertThrowsLine('<PMML></PMML>\n<PMML></PMML>', 2, /after the root/);
  assertThrowsLine('\n\n<FOLD></FOLD>', 3, /expected <PMML>/);
  assertThrowsLine('<PMML>\n<!-- never closed\n</PMML>', 2, /unterminated comment/);
  assertThrowsLine('<PMML>\n<Joint>\n<ID>1</ID><Coords>0 0 1 0</Coords><ActorIDs>1</ActorIDs>\n<SpringConst>1</SpringConst><DampConst>0</DampConst>\n</Joint>\n</PMML>', 3, /two integer actor IDs/);
  assertThrowsLine('<PMML>\n<Joint>\n<ID>1</ID><Coords>0 0 1 0</Coords><ActorIDs>1 2</ActorIDs>\n<SpringConst>1</SpringConst>\n</Joint>\n</PMML>', 2, /has no <DampConst>/);
  assertThrowsLine('<PMML><Joint><ID>1</ID><Coords>0 0 1 0</Coords><ActorIDs>1 2</ActorIDs>\n<SpringConst>1</SpringConst><DampConst>0</DampConst>\n<Assignment>X</Assignment></Joint></PMML>', 3, /M, V, F or U/);
  assertThrowsLine('', 1, /empty/);
});

// foldkit's PMML extensions for the dynamic model (docs/FORMATS.md): <Density>, <Gravity> and
// <FixedActor> anywhere among <PMML>'s children, <MaxTorque> in a joint. A two-panel strip.
const EXTENDED = `<?xml version="1.0" encoding="UTF-8"?>
<PMML>
  <Title>strip</Title>
  <Actor>
    <ID>1</ID>
    <Triangle>0 0 1 0 1 1</Triangle>
    <Triangle>0 0 1 1 0 1</Triangle>
  </Actor>
  <FixedActor>2</FixedActor>
  <Actor>
    <ID>2</ID>
    <Triangle>1 0 2 0 2 1</Triangle>
    <Triangle>1 0 2 1 1 1</Triangle>
  </Actor>
  <Gravity>9.81 0 -0.5</Gravity>
  <Joint>
    <ID>1</ID>
    <Coords>1 0 1 1</Coords>
    <ActorIDs>1 2</ActorIDs>
    <SpringConst>1</SpringConst>
    <DampConst>0.1</DampConst>
    <MaxTorque>2.5</MaxTorque>
  </Joint>
  <Density>0.08</Density>
</PMML>
`;

test('foldkit\'s physics extensions are read, kept through edits and undo, and written back where foldkit writes them', () => {
  const m = PatternModel.fromPMML(EXTENDED);
  assert.deepEqual(m.physics, { density: 0.08, gravity: [9.81, 0, -0.5], fixedActor: 2 });
  assert.equal(m.joint(1).maxTorque, 2.5);
  const text = m.toPMML();
  // After the title, in foldkit's order (io/src/pmml.cpp's writer); the joint's after its assignment.
  assert.match(text, /<Title>strip<\/Title>\n {2}<Density>0\.08<\/Density>\n {2}<Gravity>9\.81 0 -0\.5<\/Gravity>\n {2}<FixedActor>2<\/FixedActor>\n {2}<Actor>/);
  assert.match(text, /<DampConst>0\.1<\/DampConst>\n {4}<MaxTorque>2\.5<\/MaxTorque>\n {2}<\/Joint>/);
  const back = PatternModel.fromPMML(text);
  assert.deepEqual(back.physics, m.physics);
  assert.equal(back.joint(1).maxTorque, 2.5);
  assert.equal(back.toPMML(), text, 'the text is stable');
  // Snapshots (undo) keep them; a joint's limit is set and removed as its other properties.
  assert.equal(PatternModel.fromSnapshot(JSON.parse(JSON.stringify(m.snapshot()))).toPMML(), text);
  m.setJoint(1, { maxTorque: 4 });
  assert.match(m.toPMML(), /<MaxTorque>4<\/MaxTorque>/);
  assert.throws(() => m.setJoint(1, { maxTorque: 0 }), /positive/);
  m.setJoint(1, { maxTorque: null });
  assert.ok(!m.toPMML().includes('MaxTorque'), 'none: not written');
  // A copied crease keeps its limit.
  const c = PatternModel.fromPMML(EXTENDED);
  paste(c, copyTriangles(c, c.triangles.map((_, t) => t)), 0, 2);
  assert.deepEqual(c.joints().map((j) => j.maxTorque), [2.5, 2.5]);
  // A plain PMML gets none of them.
  const plain = PatternModel.fromPMML(fixture('boat.pmml'));
  assert.deepEqual(plain.physics, { density: null, gravity: null, fixedActor: null });
  assert.ok(!/Density|Gravity|FixedActor|MaxTorque/.test(plain.toPMML()));
});

test('malformed extensions are refused at their line, as foldkit refuses them', () => {
  const at = (line, element) => EXTENDED.split('\n').map((l, k) => (k + 1 === line ? `  ${element}` : l)).join('\n');
  // Line 3 is the title: an extension put there or beside it.
  const cases = [
    [at(9, '<FixedActor>x</FixedActor>'), 9, /^9: <FixedActor> must be an actor ID, found 'x'$/],
    [at(9, '<FixedActor>1.5</FixedActor>'), 9, /<FixedActor> must be an actor ID/],
    [at(15, '<Gravity>0 -9.81</Gravity>'), 15, /^15: <Gravity> needs 3 numbers, found 2$/],
    [at(15, '<Gravity>0,0,-9.81</Gravity>'), 15, /'0,0,-9\.81' is not a finite number/],
    [at(15, '<Gravity>0 0 inf</Gravity>'), 15, /'inf' is not a finite number/],
    [at(24, '<Density>nan</Density>'), 24, /^24: <Density>: 'nan' is not a finite number$/],
    [at(24, '<Density>1 2</Density>'), 24, /^24: <Density> must hold one number, found 2$/],
    [at(22, '<MaxTorque>fast</MaxTorque>'), 22, /^22: <MaxTorque>: 'fast' is not a finite number$/],
    [at(3, '<Density>1</Density>'), 24, /^24: <PMML> has more than one <Density>$/],
    [at(3, '<Gravity>0 0 -1</Gravity>'), 15, /^15: <PMML> has more than one <Gravity>$/],
    [at(3, '<FixedActor>1</FixedActor>'), 9, /^9: <PMML> has more than one <FixedActor>$/],
    [EXTENDED.replace('<MaxTorque>2.5</MaxTorque>', '<MaxTorque>1</MaxTorque><MaxTorque>2</MaxTorque>'), 22, /<Joint> has more than one <MaxTorque>/],
    [EXTENDED.replace('<Density>', '<Weight>1</Weight><Density>'), 24, /unknown element <Weight> in <PMML>/],
  ];
  for (const [text, line, pattern] of cases) assertThrowsLine(text, line, pattern);
});

test('foldkit reads the extensions the page writes as the page does, and writes them as the page does', needsCli, () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'foldkit-web-'));
  try {
    const file = path.join(dir, 'strip.pmml');
    const m = PatternModel.fromPMML(EXTENDED);
    fs.writeFileSync(file, m.toPMML());
    const v = cli(['validate', file]);
    assert.equal(v.status, 0, v.stdout + v.stderr);
    // foldkit's writer (convert PMML → PMML) writes the same text.
    const out = path.join(dir, 'again.pmml');
    const c = cli(['convert', file, out]);
    assert.equal(c.status, 0, c.stderr);
    assert.equal(fs.readFileSync(out, 'utf8'), m.toPMML());
    // What foldkit refuses at a line, the page refuses at the same line.
    const bad = EXTENDED.replace('<Gravity>9.81 0 -0.5</Gravity>', '<Gravity>9.81 0</Gravity>');
    fs.writeFileSync(file, bad);
    const r = cli(['validate', file]);
    assert.notEqual(r.status, 0);
    assert.match(r.stdout + r.stderr, /strip\.pmml:15: <Gravity> needs 3 numbers, found 2/);
    assertThrowsLine(bad, 15, /<Gravity> needs 3 numbers, found 2/);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

// ------------------------------------------------------------------------------ writing

test('toPMML → fromPMML is identical: triangles, joints, IDs, properties, exact numbers', () => {
  for (const name of [...Object.keys(EXPECTED), 'collinear-joint.pmml']) {
    const m = PatternModel.fromPMML(fixture(name));
    const text = m.toPMML();
    const back = PatternModel.fromPMML(text);
    assert.deepEqual(triangleSet(back), triangleSet(m), name);
    assert.deepEqual(jointRecords(back), jointRecords(m), name);
    assert.deepEqual(counts(back), counts(m), name);
    assert.equal(back.title, m.title);
    assert.equal(back.toPMML(), text, `${name}: the text is stable`);
  }
  // Numbers that need all 17 digits, or an exponent, survive exactly.
  const c = PatternModel.fromPMML(fixture('circular-3x8.pmml'));
  const back = PatternModel.fromPMML(c.toPMML());
  const xs = (m) => m.vertices.map((p) => [p.x, p.y]).flat().sort((a, b) => a - b);
  assert.deepEqual(xs(back), xs(c));
  assert.ok(c.vertices.some((p) => p.y !== 0 && Math.abs(p.y) < 1e-15), 'a tiny coordinate such as 1.2e-16 is kept, not rounded to 0');
});

test('edited joint properties are written and read back', () => {
  const m = PatternModel.fromPMML(fixture('boat.pmml'));
  m.setJoint(3, { spring: 0.30000000000000004, damping: 1e-7, assignment: 'F' });
  const back = PatternModel.fromPMML(m.toPMML());
  assert.deepEqual([back.joint(3).spring, back.joint(3).damping, back.joint(3).assignment], [0.30000000000000004, 1e-7, 'F']);
  assert.throws(() => m.setJoint(3, { assignment: 'Q' }));
  assert.throws(() => m.setJoint(999, { spring: 1 }));
  assert.ok(!m.toPMML().includes('<Assignment>U'), 'U is the default and is not written');
});

test('snapshot → JSON → fromSnapshot gives the same model', () => {
  const m = PatternModel.fromPMML(fixture('miura-3x3.pmml'));
  addPolygon(m, [{ x: 10, y: 0 }, { x: 11, y: 0 }, { x: 11, y: 1 }]);
  const s = JSON.parse(JSON.stringify(m.snapshot()));
  const back = PatternModel.fromSnapshot(s);
  assert.equal(back.toPMML(), m.toPMML());
  assert.deepEqual(back.vertices, m.vertices);
  // The next joint ID travels with the snapshot.
  const a = addTriangle(m, { x: 11, y: 0 }, { x: 12, y: 0 }, { x: 11, y: 1 });
  const b = addTriangle(back, { x: 11, y: 0 }, { x: 12, y: 0 }, { x: 11, y: 1 });
  assert.deepEqual(a, b);
  assert.deepEqual(jointRecords(back), jointRecords(m));
});

// ------------------------------------------------------------------------------ joint IDs

test('joint IDs stay stable across moveVertices and an unrelated addPolygon', () => {
  const m = PatternModel.fromPMML(fixture('miura-3x3.pmml'));
  const before = new Map(m.joints().map((j) => [j.id, [j.va, j.vb].sort().join()]));
  const interior = m.vertices.findIndex((p) => p.x === 1 && p.y === 1.577350269189626);
  assert.ok(interior >= 0);
  moveVertices(m, [interior], 0.05, -0.02);
  const moved = m.joints().filter((j) => j.va === interior || j.vb === interior);
  assert.equal(moved.length, 4, 'a degree-4 Miura vertex has four creases');
  for (const j of moved) assert.ok(j.a.x === 1.05 || j.b.x === 1.05);
  addPolygon(m, [{ x: 20, y: 20 }, { x: 21, y: 20 }, { x: 21, y: 21 }, { x: 20, y: 21 }]);
  const after = new Map(m.joints().map((j) => [j.id, [j.va, j.vb].sort().join()]));
  assert.deepEqual(after, before, 'same IDs on the same edges');
  // A polygon that does share an edge adds one joint, with the next ID (12 was the highest).
  addPolygon(m, [{ x: 3, y: 0.577350269189626 }, { x: 4, y: 0.577350269189626 }, { x: 3, y: 1.577350269189626 }]);
  assert.equal(m.joints().length, 13);
  assert.equal(m.joints().at(-1).id, 13);
});

test('a joint keeps its ID when merges renumber vertices', () => {
  const m = PatternModel.fromPMML(fixture('boat.pmml'));
  // Two triangles far away, then merge a corner of one into the other's: vertices renumber.
  addTriangle(m, { x: 10, y: 0 }, { x: 11, y: 0 }, { x: 10, y: 1 });
  addTriangle(m, { x: 12, y: 0 }, { x: 13, y: 0 }, { x: 12, y: 1 });
  const ids = (mm) => jointRecords(mm).map((j) => `${j.id}:${j.a.x},${j.a.y}-${j.b.x},${j.b.y}`);
  const before = ids(m);
  const first = m.nearestVertex({ x: 0, y: 1 }, 1e-9);
  const other = m.nearestVertex({ x: 0, y: 0 }, 1e-9);
  assert.ok(first >= 0 && other >= 0);
  const keep = m.nearestVertex({ x: 11, y: 0 }, 1e-9), gone = m.nearestVertex({ x: 12, y: 0 }, 1e-9);
  const kept = mergeVertices(m, keep, gone);
  assert.equal(m.vertices.length, 11 + 6 - 1);
  assert.deepEqual(m.vertices[kept], { x: 11, y: 0 });
  assert.deepEqual(ids(m), before);
});

// ------------------------------------------------------------------------------ lattices, group

test('addGrid 2×2 without diagonals matches foldkit generate grid: 4 actors, 4 joints', () => {
  const m = new PatternModel();
  addGrid(m, { x: 0, y: 0, cols: 2, rows: 2, w: 2, h: 2 });
  const g = PatternModel.fromPMML(fixture('grid-2x2.pmml'));
  // Euler for a disc: E = V + T − 1 = 9 + 8 − 1 = 16 edges, 8 on the boundary, 8 inside; the
  // 4 cell diagonals lie inside an actor, so 4 joints remain.
  assert.deepEqual(counts(m), { actors: 4, joints: 4, triangles: 8, vertices: 9 });
  assert.deepEqual(triangleSet(m, false), triangleSet(g, false));
  assert.equal(m.edges().filter((e) => e.kind === 'boundary').length, 8);
  assert.equal(m.edges().filter((e) => e.kind === 'internal').length, 4);
});

test('addGrid with diagonals makes each triangle an actor', () => {
  const cases = { '/': [12, 13, 12, 12], '\\': [12, 13, 12, 12], x: [24, 31, 24, 18], none: [6, 7, 12, 12] };
  for (const [diagonals, [actors, joints, triangles, vertices]] of Object.entries(cases)) {
    const m = new PatternModel();
    addGrid(m, { x: 1, y: 1, cols: 3, rows: 2, w: 3, h: 2, diagonals });
    // V − E + T = 1 and every interior edge between two actors is a joint.
    assert.deepEqual(counts(m), { actors, joints, triangles, vertices }, diagonals);
    assert.equal(m.vertices.length - m.edges().length + m.triangles.length, 1);
    assert.ok(Math.abs(area(m) - 6) < 1e-12);
  }
});

test('addCircular matches foldkit generate circular triangle for triangle', () => {
  const m = new PatternModel();
  addCircular(m, { x: 0, y: 0, rings: 3, spokes: 8, radius: 3 });
  const c = PatternModel.fromPMML(fixture('circular-3x8.pmml'));
  assert.deepEqual(counts(m), EXPECTED['circular-3x8.pmml']);
  assert.deepEqual(triangleSet(m, false), triangleSet(c, false));
  // Centre cells are single triangles, the others quads.
  const sizes = m.actors().map((a) => m.trianglesOf(a).length).sort();
  assert.deepEqual(sizes, [...Array(8).fill(1), ...Array(16).fill(2)]);
});

test('group and ungroup change the joint count as the actors say', () => {
  const m = new PatternModel();
  addGrid(m, { x: 0, y: 0, cols: 2, rows: 2, w: 2, h: 2 });
  const [a1, a2] = m.actors();
  const shared = m.joints().find((j) => j.actors[0] === a1 && j.actors[1] === a2);
  assert.ok(shared);
  const id = group(m, [...m.trianglesOf(a1), ...m.trianglesOf(a2)]);
  assert.equal(id, 5, 'the next free actor ID');
  // Three actors in an L around one cell… the A–B edge is now inside one actor.
  assert.deepEqual([m.actors().length, m.joints().length], [3, 3]);
  const ids = ungroup(m, id);
  assert.equal(ids.length, 4);
  assert.equal(ids[0], id);
  // Four single-triangle actors plus two cells: of the 8 interior edges only the two diagonals
  // of the untouched cells stay inside an actor.
  assert.deepEqual([m.actors().length, m.joints().length], [6, 6]);
  assert.equal(m.joints().find((j) => j.va === shared.va && j.vb === shared.vb).id, shared.id, 'the A–B edge gets its old ID back');
  group(m, m.triangles.map((_, t) => t));
  assert.deepEqual([m.actors().length, m.joints().length], [1, 0]);
});

// ------------------------------------------------------------------------------ polygons

test('ear clipping a concave polygon gives n − 2 triangles covering the shoelace area', () => {
  // A 10-corner star, clockwise, and an L-shape with a collinear corner, counter-clockwise.
  const star = [];
  for (let k = 0; k < 10; ++k) {
    const r = k % 2 ? 0.4 : 1, a = (-2 * Math.PI * k) / 10;
    star.push({ x: r * Math.cos(a), y: r * Math.sin(a) });
  }
  const ell = [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 4, y: 0 }, { x: 4, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 3 }, { x: 0, y: 3 }];
  for (const poly of [star, ell]) {
    const m = new PatternModel();
    const tris = addPolygon(m, poly);
    assert.equal(tris.length, poly.length - 2);
    assert.equal(m.actors().length, 1);
    assert.ok(Math.abs(area(m) - Math.abs(signedArea(poly))) < 1e-12, 'areas add up');
    for (const t of tris) {
      assert.ok(m.triangleArea(t) > 1e-9, 'no sliver');
      const c = m.triangles[t].v.map((i) => m.vertices[i]);
      const centroid = { x: (c[0].x + c[1].x + c[2].x) / 3, y: (c[0].y + c[1].y + c[2].y) / 3 };
      assert.ok(pointInPolygon(centroid, poly), 'inside the polygon');
    }
    assertConforming(m);
  }
  assert.equal(earClip(ell).length, ell.length - 2);
});

test('addPolygon refuses self-intersecting and degenerate input', () => {
  const m = new PatternModel();
  assert.throws(() => addPolygon(m, [{ x: 0, y: 0 }, { x: 1, y: 1 }, { x: 1, y: 0 }, { x: 0, y: 1 }]), /intersects itself/);
  assert.throws(() => addPolygon(m, [{ x: 0, y: 0 }, { x: 3, y: 1 }, { x: 3, y: 0 }, { x: 0, y: 2 }]), /intersects itself/);
  assert.throws(() => addPolygon(m, [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 2, y: 0 }]), /zero area|degenerate|doubles back/);
  assert.throws(() => addPolygon(m, [{ x: 0, y: 0 }, { x: 1, y: 0 }]), /at least 3/);
  assert.throws(() => addPolygon(m, [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 2 }, { x: 1, y: 0 }, { x: 0, y: 2 }]));
  assert.throws(() => addTriangle(m, { x: 0, y: 0 }, { x: 1, y: 1 }, { x: 2, y: 2 }), /degenerate/);
  assert.equal(m.triangles.length, 0, 'nothing was added');
  // A repeated closing corner is not a problem.
  assert.equal(addPolygon(m, [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }, { x: 0, y: 0 }]).length, 1);
});

test('addPolygon snaps to existing corners and splits edges instead of leaving T-junctions', () => {
  const m = new PatternModel();
  addGrid(m, { x: 0, y: 0, cols: 2, rows: 2, w: 2, h: 2 });
  // A square on the right whose left side runs past the grid's corner (2,1).
  const tris = addPolygon(m, [{ x: 2, y: 0 }, { x: 4, y: 0 }, { x: 4, y: 2 }, { x: 2 + 1e-12, y: 2 }]);
  assert.equal(m.vertices.length, 11, 'two corners welded onto the grid');
  assertConforming(m);
  assert.ok(tris.length >= 3, 'the side through (2,1) was split');
  assert.ok(Math.abs(area(m) - 8) < 1e-9);
  assert.equal(m.joints().length, 4 + 2, 'the shared side is two edges, two joints');
  // A corner placed on an existing boundary edge's midpoint splits that edge.
  const n = new PatternModel();
  addTriangle(n, { x: 0, y: 0 }, { x: 2, y: 0 }, { x: 0, y: 2 });
  addTriangle(n, { x: 1, y: 1 }, { x: 2, y: 0 }, { x: 2, y: 2 });
  assertConforming(n);
  assert.equal(n.triangles.length, 3);
  assert.equal(n.joints().length, 1);
});

// ------------------------------------------------------------------------------ editing

test('splitEdge keeps the area, leaves no T-junction and carries the crease', () => {
  const m = PatternModel.fromPMML(fixture('miura-3x3.pmml'));
  const a0 = area(m);
  const j = m.joint(1); // a valley crease between actors 1 and 2
  const mid = splitEdge(m, j.va, j.vb, 0.25);
  assert.equal(m.triangles.length, 20);
  assert.equal(m.vertices.length, 17);
  assert.ok(Math.abs(area(m) - a0) < 1e-12);
  assertConforming(m);
  // Both pieces stay one crease: joint 1, spanning the old edge.
  assert.equal(m.joints().length, 12);
  assert.deepEqual([m.jointOnEdge(j.va, mid).id, m.jointOnEdge(mid, j.vb).id], [1, 1]);
  assert.deepEqual([m.joint(1).keys.length, m.joint(1).assignment], [2, 'V']);
  assert.deepEqual([m.joint(1).a, m.joint(1).b], [j.a, j.b]);
  assert.equal(m.length(j.va, mid), m.length(j.va, j.vb) * 0.25);
  // A boundary edge: one triangle is split.
  const e = m.edges().find((x) => x.kind === 'boundary');
  splitEdge(m, e.i, e.j);
  assert.equal(m.triangles.length, 21);
  assertConforming(m);
  assert.ok(Math.abs(area(m) - a0) < 1e-12);
  assert.throws(() => splitEdge(m, 0, 0), /no edge/);
});

test('mergeVertices joins vertices and drops collapsed triangles', () => {
  const m = new PatternModel();
  addGrid(m, { x: 0, y: 0, cols: 2, rows: 2, w: 2, h: 2 });
  const i = m.nearestVertex({ x: 0, y: 0 }), j = m.nearestVertex({ x: 1, y: 0 });
  const mid = splitEdge(m, i, j);
  assert.equal(m.triangles.length, 9);
  const kept = mergeVertices(m, i, mid);
  assert.equal(m.triangles.length, 8, 'the sliver at the merged edge collapses');
  assert.equal(m.vertices.length, 9);
  assert.deepEqual(m.vertices[kept], { x: 0, y: 0 });
  assert.ok(Math.abs(area(m) - 4) < 1e-12);
  assertConforming(m);
  // Two separate triangles that nearly touch become connected: one shared corner.
  const n = new PatternModel();
  addTriangle(n, { x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 });
  addTriangle(n, { x: 1.01, y: 0.01 }, { x: 2, y: 0 }, { x: 2, y: 1 });
  assert.equal(n.vertices.length, 6);
  const k = mergeVertices(n, n.nearestVertex({ x: 1, y: 0 }), n.nearestVertex({ x: 1.01, y: 0.01 }));
  assert.equal(n.vertices.length, 5);
  assert.equal(n.triangles.filter((t) => t.v.includes(k)).length, 2);
});

test('moveVertices welds a moved corner onto a vertex it lands on', () => {
  const m = new PatternModel();
  addTriangle(m, { x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 });
  addTriangle(m, { x: 1, y: 1 }, { x: 3, y: 1 }, { x: 1, y: 3 });
  const v = [m.nearestVertex({ x: 1, y: 1 }), m.nearestVertex({ x: 1, y: 3 })];
  const [moved] = moveVertices(m, v, 0, -1); // (1,1) → (1,0) welds; (1,3) → (1,2)
  assert.equal(m.vertices.length, 5);
  assert.deepEqual(m.vertices[moved], { x: 1, y: 0 });
});

test('transformVertices rotates, scales and mirrors about a point', () => {
  const m = new PatternModel();
  addTriangle(m, { x: 1, y: 0 }, { x: 2, y: 0 }, { x: 1, y: 1 });
  const all = [0, 1, 2];
  transformVertices(m, all, { rotate: Math.PI / 2, about: { x: 0, y: 0 } });
  const near = (p, q) => Math.abs(p.x - q.x) < 1e-12 && Math.abs(p.y - q.y) < 1e-12;
  assert.ok(near(m.vertices[0], { x: 0, y: 1 }) && near(m.vertices[1], { x: 0, y: 2 }) && near(m.vertices[2], { x: -1, y: 1 }));
  transformVertices(m, all, { scale: 2, about: { x: 0, y: 0 } });
  assert.ok(near(m.vertices[1], { x: 0, y: 4 }));
  assert.ok(Math.abs(m.triangleArea(0) - 2) < 1e-12);
  const orientation = () => signedArea(m.triangles[0].v.map((i) => m.vertices[i]));
  const before = Math.sign(orientation());
  transformVertices(m, all, { mirror: 'x', about: { x: 0, y: 0 } });
  assert.ok(near(m.vertices.find((p) => p.y === 4) ?? { x: NaN, y: NaN }, { x: 0, y: 4 }));
  assert.ok(m.vertices.some((p) => near(p, { x: 2, y: 2 })), 'x flipped');
  assert.equal(Math.sign(orientation()), before, 'the triangle keeps its orientation');
});

test('copy and paste make new actors with the copied grouping and creases', () => {
  const m = PatternModel.fromPMML(fixture('miura-3x3.pmml'));
  const clip = copyTriangles(m, m.triangles.map((_, t) => t));
  assert.equal(clip.triangles.length, 18);
  const pasted = paste(m, clip, 10, 0);
  assert.equal(pasted.length, 18);
  assert.deepEqual(counts(m), { actors: 18, joints: 24, triangles: 36, vertices: 32 });
  const newJoints = m.joints().filter((j) => j.id > 12);
  assert.deepEqual(newJoints.map((j) => j.id), [13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24]);
  const kinds = (list) => list.map((j) => j.assignment).sort().join('');
  assert.equal(kinds(newJoints), kinds(m.joints().filter((j) => j.id <= 12)), 'mountains and valleys copied');
  // Pasting a copy of one actor right beside the grid shares an edge: one new joint.
  const g = new PatternModel();
  addGrid(g, { cols: 1, rows: 1, w: 1, h: 1 });
  paste(g, copyTriangles(g, [0, 1]), 1, 0);
  assert.deepEqual(counts(g), { actors: 2, joints: 1, triangles: 4, vertices: 6 });
});

test('deleteTriangles drops unused vertices and vanished joints', () => {
  const m = PatternModel.fromPMML(fixture('boat.pmml'));
  const del = m.trianglesOf(1).concat(m.trianglesOf(5));
  deleteTriangles(m, del);
  // Actors 1 and 5 held the corner (0,0) alone; joints 1 (1–5), 5 (1–2) and 6 (5–6) are gone.
  assert.deepEqual(counts(m), { actors: 6, joints: 7, triangles: 10, vertices: 10 });
  assert.deepEqual(m.joints().map((j) => j.id), [2, 3, 4, 7, 8, 9, 10]);
});

test('queries: nearest vertex and edge, triangle at a point, length, angle, bounds', () => {
  const m = PatternModel.fromPMML(fixture('grid-2x2.pmml'));
  const c = m.nearestVertex({ x: 1.05, y: 0.98 }, 0.1);
  assert.deepEqual(m.vertices[c], { x: 1, y: 1 });
  assert.equal(m.nearestVertex({ x: 1.5, y: 1.5 }, 0.1), -1);
  const e = m.nearestEdge({ x: 0.5, y: 1.01 }, 0.1);
  assert.ok(Math.abs(e.distance - 0.01) < 1e-12);
  assert.ok(Math.abs(e.t - 0.5) < 1e-12);
  assert.equal(m.nearestEdge({ x: 0.8, y: 1.5 }, 0.1), null);
  const t = m.triangleAt({ x: 1.8, y: 0.2 });
  assert.equal(m.triangles[t].actor, 2);
  assert.equal(m.triangleAt({ x: 5, y: 5 }), -1);
  const o = m.nearestVertex({ x: 0, y: 0 }), r = m.nearestVertex({ x: 1, y: 0 }), d = m.nearestVertex({ x: 1, y: 1 });
  assert.equal(m.length(o, d), Math.SQRT2);
  assert.ok(Math.abs(m.angleAt(r, o, d) - 45) < 1e-12);
  assert.ok(Math.abs(m.angleAt(o, r, d) - 90) < 1e-12);
  const b = m.bounds();
  assert.deepEqual([b.min, b.max], [{ x: 0, y: 0 }, { x: 2, y: 2 }]);
  assert.equal(new PatternModel().bounds(), null);
});

// ------------------------------------------------------------------------------ history, snapping

test('History undoes and redoes, drops the redo branch and is bounded', () => {
  const h = new History(3);
  assert.equal(h.undo(), null);
  h.push('s0');
  h.push('s1');
  h.push('s2');
  assert.ok(h.canUndo && !h.canRedo);
  assert.equal(h.undo(), 's1');
  assert.equal(h.undo(), 's0');
  assert.equal(h.undo(), null);
  assert.ok(!h.canUndo && h.canRedo);
  assert.equal(h.redo(), 's1');
  h.push('s3');
  assert.ok(!h.canRedo, 'a new state drops the redo branch');
  assert.equal(h.redo(), null);
  h.push('s4');
  assert.equal(h.undo(), 's3');
  assert.equal(h.undo(), 's1');
  assert.equal(h.undo(), null, 'only three states are kept');
});

test('History with model snapshots restores earlier models in place', () => {
  const m = new PatternModel();
  const h = new History();
  h.push(m.snapshot());
  addGrid(m, { cols: 2, rows: 2, w: 2, h: 2 });
  h.push(m.snapshot());
  group(m, [0, 1, 2, 3]);
  h.push(m.snapshot());
  m.restore(h.undo());
  assert.deepEqual(counts(m), { actors: 4, joints: 4, triangles: 8, vertices: 9 });
  m.restore(h.undo());
  assert.equal(m.triangles.length, 0);
  m.restore(h.redo());
  m.restore(h.redo());
  assert.deepEqual(counts(m), { actors: 3, joints: 3, triangles: 8, vertices: 9 });
});

test('snapPoint picks the nearest vertex, midpoint or grid point within the radius', () => {
  const m = new PatternModel();
  addTriangle(m, { x: 0, y: 0 }, { x: 2, y: 0 }, { x: 0, y: 2 });
  const all = { grid: 0.5, vertices: true, midpoints: true };
  assert.deepEqual(snapPoint({ x: 1.9, y: 0.1 }, all, m, 0.3), { x: 2, y: 0, kind: 'vertex', index: 1 });
  const mid = snapPoint({ x: 1.05, y: 0.02 }, all, m, 0.3);
  assert.deepEqual([mid.x, mid.y, mid.kind], [1, 0, 'midpoint']);
  assert.deepEqual(snapPoint({ x: 1.6, y: 1.4 }, all, m, 0.3), { x: 1.5, y: 1.5, kind: 'grid' });
  const p = { x: 1.6, y: 1.4 };
  assert.equal(snapPoint(p, { ...all, grid: null }, m, 0.3), p, 'nothing near: the point itself');
  assert.equal(snapPoint({ x: 1.05, y: 0.02 }, { grid: null, vertices: true, midpoints: false }, m, 0.3).kind, undefined);
  // At equal distance a vertex wins over a grid point on the same spot.
  assert.equal(snapPoint({ x: 0.1, y: 0.1 }, all, m, 0.3).kind, 'vertex');
});

// ------------------------------------------------------------------------------ random edits

// Seeded random edits that keep a drawing sane: shapes in separate 2 × 2 slots of a 4 × 3 board
// (so they abut exactly, with different subdivisions), pastes of small actors into free slots,
// group, ungroup, split, deletes and property changes. `check` runs after every edit.
function randomEdits(seed, steps, check) {
  let state = seed;
  const rnd = () => (state = (state * 1103515245 + 12345) % 2147483648) / 2147483648;
  const pick = (list) => list[Math.floor(rnd() * list.length)];
  const m = new PatternModel();
  const taken = new Set();
  const slot = () => {
    for (let k = 0; k < 50; ++k) {
      const s = [Math.floor(rnd() * 4) * 2, Math.floor(rnd() * 3) * 2];
      if (!taken.has(String(s))) return taken.add(String(s)) && s;
    }
    return null;
  };
  const ops = {
    grid: (s) => addGrid(m, { x: s[0], y: s[1], w: 2, h: 2, cols: 1 + Math.floor(rnd() * 3), rows: 1 + Math.floor(rnd() * 3), diagonals: pick(['none', '/', '\\', 'x']) }),
    circular: (s) => addCircular(m, { x: s[0] + 1, y: s[1] + 1, rings: 1 + Math.floor(rnd() * 2), spokes: 3 + Math.floor(rnd() * 6), radius: 0.9 }),
    polygon: (s) => addPolygon(m, [{ x: s[0], y: s[1] }, { x: s[0] + 2, y: s[1] }, { x: s[0] + 2, y: s[1] + 2 }, { x: s[0] + 1, y: s[1] + 0.5 + rnd() }, { x: s[0], y: s[1] + 2 }]),
    paste: (s) => {
      const clip = copyTriangles(m, m.trianglesOf(pick(m.actors())));
      const b = clip.bounds;
      if (b.maxX - b.minX <= 2 && b.maxY - b.minY <= 2) paste(m, clip, s[0] - b.minX, s[1] - b.minY);
    },
  };
  const edits = {
    group: () => {
      const j = pick(m.joints());
      if (j) group(m, [...m.trianglesOf(j.actors[0]), ...m.trianglesOf(j.actors[1])]);
    },
    ungroup: () => ungroup(m, pick(m.actors())),
    split: () => {
      const e = pick(m.edges());
      splitEdge(m, e.i, e.j, 0.2 + 0.6 * rnd());
    },
    assign: () => {
      const j = pick(m.joints());
      if (j) m.setJoint(j.id, { assignment: pick(['M', 'V', 'F', 'U']), spring: rnd() });
    },
    delete: () => deleteTriangles(m, m.trianglesOf(pick(m.actors()))),
  };
  for (let step = 0; step < steps; ++step) {
    const shapes = Object.keys(ops), changes = Object.keys(edits);
    const name = !m.triangles.length || rnd() < 0.4 ? pick(shapes.filter((k) => k !== 'paste' || m.triangles.length)) : pick(changes);
    if (ops[name]) {
      const s = slot();
      if (!s) continue;
      ops[name](s);
    } else if (m.triangles.length) edits[name]();
    check(m, `seed ${seed} step ${step} ${name}`);
  }
  return m;
}

test('random edits keep joint IDs unique, the round trip exact and no T-junctions', () => {
  for (const seed of [1, 2, 3, 4, 5, 6]) {
    let lastIds = new Map();
    randomEdits(seed, 40, (m, what) => {
      const ids = m.joints().map((j) => j.id);
      assert.equal(new Set(ids).size, ids.length, `${what}: duplicate joint IDs`);
      // An edge that was a joint before and still is keeps its ID.
      const now = new Map(m.joints().map((j) => [`${j.a.x},${j.a.y},${j.b.x},${j.b.y}`, j.id]));
      for (const [edge, id] of now) if (lastIds.has(edge)) assert.equal(id, lastIds.get(edge), `${what}: ID changed`);
      lastIds = now;
      const text = m.toPMML();
      assert.equal(PatternModel.fromPMML(text).toPMML(), text, what);
      assertConforming(m);
    });
  }
});

// ------------------------------------------------------------------------------ foldkit CLI

function cli(args) {
  const r = spawnSync(CLI, args, { encoding: 'utf8' });
  if (r.error) throw r.error;
  return r;
}

function checkWithFoldkit(dir, name, model) {
  const file = path.join(dir, `${name}.pmml`);
  fs.writeFileSync(file, model.toPMML());
  const v = cli(['validate', file]);
  assert.equal(v.status, 0, `${name}: foldkit validate says\n${v.stdout}${v.stderr}`);
  const info = cli(['info', file, '--json']);
  assert.equal(info.status, 0, info.stderr);
  const d = JSON.parse(info.stdout);
  assert.deepEqual({ actors: d.actors, joints: d.joints, triangles: d.triangles, vertices: d.vertices }, counts(model), name);
}

test('foldkit validates what the model writes and counts the same joints', needsCli, () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'foldkit-web-'));
  try {
    for (const diagonals of ['none', '/', '\\', 'x']) {
      const m = new PatternModel({ title: `grid ${diagonals}` });
      addGrid(m, { x: -1, y: 0.5, cols: 4, rows: 3, w: 2, h: 1.5, diagonals });
      checkWithFoldkit(dir, `grid-${diagonals === '\\' ? 'back' : diagonals === '/' ? 'slash' : diagonals}`, m);
    }
    for (const [rings, spokes] of [[1, 3], [2, 5], [4, 12]]) {
      const m = new PatternModel();
      addCircular(m, { x: 0.3, y: -0.7, rings, spokes, radius: 2.5 });
      checkWithFoldkit(dir, `circular-${rings}-${spokes}`, m);
    }
    const miura = PatternModel.fromPMML(fixture('miura-3x3.pmml'));
    paste(miura, copyTriangles(miura, miura.triangles.map((_, t) => t)), 3, 0);
    checkWithFoldkit(dir, 'pasted-beside', miura);
    const grouped = new PatternModel();
    addGrid(grouped, { cols: 3, rows: 3, w: 3, h: 3, diagonals: 'x' });
    group(grouped, grouped.trianglesOf(1).concat(grouped.trianglesOf(2), grouped.trianglesOf(3)));
    ungroup(grouped, grouped.actors()[0]);
    checkWithFoldkit(dir, 'grouped', grouped);
    const split = PatternModel.fromPMML(fixture('waterbomb-2x3.pmml'));
    const j = split.joints()[3];
    splitEdge(split, j.va, j.vb, 0.5);
    const b = split.edges().find((e) => e.kind === 'boundary');
    splitEdge(split, b.i, b.j, 0.3);
    checkWithFoldkit(dir, 'split', split);
    const poly = new PatternModel();
    addGrid(poly, { cols: 2, rows: 2, w: 2, h: 2 });
    addPolygon(poly, [{ x: 2, y: 0 }, { x: 3, y: 0.5 }, { x: 3.5, y: 1 }, { x: 3, y: 1.5 }, { x: 2, y: 2 }]);
    addTriangle(poly, { x: 0, y: 2 }, { x: 1, y: 2 }, { x: 0.5, y: 3 });
    checkWithFoldkit(dir, 'polygon-beside-grid', poly);
    checkWithFoldkit(dir, 'collinear', PatternModel.fromPMML(fixture('collinear-joint.pmml')));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

test('foldkit validates every step of random edits', needsCli, () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'foldkit-web-'));
  try {
    for (const seed of [7, 8, 9]) randomEdits(seed, 25, (m, what) => m.triangles.length && checkWithFoldkit(dir, what.replace(/\W+/g, '-'), m));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

test('a 40×40 Miura from foldkit reads back with foldkit info counts', needsCli, () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'foldkit-web-'));
  try {
    const file = path.join(dir, 'big.pmml');
    assert.equal(cli(['generate', 'miura', '--rows', '40', '--cols', '40', '-o', file]).status, 0);
    const d = JSON.parse(cli(['info', file, '--json']).stdout);
    const t0 = performance.now();
    const m = PatternModel.fromPMML(fs.readFileSync(file, 'utf8'));
    const ms = performance.now() - t0;
    assert.deepEqual(counts(m), { actors: d.actors, joints: d.joints, triangles: d.triangles, vertices: d.vertices });
    assert.ok(ms < 2000, `reading took ${ms} ms`);
    const back = PatternModel.fromPMML(m.toPMML());
    assert.deepEqual(jointRecords(back), jointRecords(m));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
