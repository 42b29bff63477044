// Forward kinematics (web/src/kinematics.js) against closed forms and against foldkit's own
// folded states (fixtures/kinematics, made by the C++ CLI: see the README there).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { buildTree, closureGap, facetPoses, foldedVertices, sideOf } from '../src/kinematics.js';

const fixture = (name) => JSON.parse(readFileSync(new URL(`fixtures/kinematics/${name}`, import.meta.url), 'utf8'));
const H = Math.PI / 2;

// A unit square cut by one crease x = 0.5, the crease running (0.5, 0) → (0.5, 1) unless reversed.
function square({ reversed = false } = {}) {
  return {
    vertices: [[0, 0], [0.5, 0], [1, 0], [0, 1], [0.5, 1], [1, 1]],
    actors: [{ id: 1, triangles: [[0, 1, 4], [0, 4, 3]] }, { id: 2, triangles: [[1, 2, 5], [1, 5, 4]] }],
    joints: [{ id: 1, v: reversed ? [4, 1] : [1, 4], actors: [0, 1], assignment: 'M' }],
  };
}

// Three unit panels in a row, creases at x = 1 and x = 2.
function strip() {
  const vertices = [];
  for (let x = 0; x <= 3; ++x) vertices.push([x, 0], [x, 1]); // vertex 2x: (x, 0), 2x + 1: (x, 1)
  const actors = [0, 1, 2].map((x) => ({ id: x + 1, triangles: [[2 * x, 2 * x + 2, 2 * x + 3], [2 * x, 2 * x + 3, 2 * x + 1]] }));
  const joints = [1, 2].map((x) => ({ id: x, v: [2 * x, 2 * x + 1], actors: [x - 1, x], assignment: x === 1 ? 'M' : 'V' }));
  return { vertices, actors, joints };
}

// The image of flat point p under actor a's pose.
function image(poses, a, [x, y]) {
  const o = 16 * a;
  return [0, 1, 2].map((r) => poses[o + r] * x + poses[o + 4 + r] * y + poses[o + 12 + r]);
}

function assertClose(actual, expected, tol, what) {
  assert.equal(actual.length, expected.length, what);
  for (let i = 0; i < actual.length; ++i)
    assert.ok(Math.abs(actual[i] - expected[i]) <= tol, `${what}: [${actual}] != [${expected}]`);
}

const diagonal = (pattern) => {
  const xs = pattern.vertices.map((p) => p[0]), ys = pattern.vertices.map((p) => p[1]);
  return Math.hypot(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
};

test('one crease: mountain +90° puts the moved facet below the sheet, valley above', () => {
  for (const reversed of [false, true]) {
    const p = square({ reversed });
    const tree = buildTree(p);
    assert.deepEqual([...tree.order], [0, 1]);
    assert.deepEqual([...tree.parent], [-1, 0]);
    assert.deepEqual([...tree.parentJoint], [-1, 0]);
    assert.deepEqual([...tree.inTree], [1]);
    const mountain = facetPoses(p, tree, [H]);
    assertClose(image(mountain, 0, [0, 0]), [0, 0, 0], 1e-15, 'root stays put');
    assertClose(image(mountain, 1, [1, 0]), [0.5, 0, -0.5], 1e-15, `mountain (reversed ${reversed})`);
    assertClose(image(mountain, 1, [1, 1]), [0.5, 1, -0.5], 1e-15, `mountain (reversed ${reversed})`);
    assertClose(image(mountain, 1, [0.5, 1]), [0.5, 1, 0], 1e-15, 'the crease stays put');
    assertClose(image(facetPoses(p, tree, [-H]), 1, [1, 1]), [0.5, 1, 0.5], 1e-15, 'valley');
    assertClose(image(facetPoses(p, tree, [Math.PI]), 1, [1, 1]), [0, 1, 0], 1e-15, 'folded flat');
    assertClose(image(facetPoses(p, tree, [0]), 1, [1, 1]), [1, 1, 0], 0, 'flat');
  }
  // Rooted at the other facet, a mountain fold still sends the moving facet down.
  const p = square();
  const tree = buildTree(p, 1);
  assert.deepEqual([...tree.order], [1, 0]);
  assert.equal(tree.side[0], -1);
  assertClose(image(facetPoses(p, tree, [H]), 0, [0, 0]), [0.5, 0, -0.5], 1e-15, 'root 1, mountain');
});

test('sideOf follows the crease direction, not the actor order', () => {
  assert.equal(sideOf(square(), 0, 0), -1); // left of (0.5, 0) → (0.5, 1)
  assert.equal(sideOf(square(), 0, 1), 1);
  assert.equal(sideOf(square({ reversed: true }), 0, 0), 1);
  const broken = square();
  broken.joints[0].v = [0, 3]; // the left edge: actor 2 has no triangle on it
  assert.throws(() => sideOf(broken, 0, 1), /actor 2 has no edge on joint 1/);
});

test('strip of three panels: a mountain then a valley at 90° make a step', () => {
  const p = strip();
  const tree = buildTree(p);
  assert.deepEqual([...tree.order], [0, 1, 2]);
  assert.deepEqual([...tree.parent], [-1, 0, 1]);
  const poses = facetPoses(p, tree, [H, -H]);
  assertClose(image(poses, 1, [2, 0]), [1, 0, -1], 1e-15, 'middle panel hangs down');
  assertClose(image(poses, 2, [2, 1]), [1, 1, -1], 1e-15, 'last panel starts under the first crease');
  assertClose(image(poses, 2, [3, 1]), [2, 1, -1], 1e-15, 'and runs parallel to the sheet');
  // Both mountain: a U, the last panel back under the first, facing it.
  assertClose(image(facetPoses(p, tree, [H, H]), 2, [3, 0]), [0, 0, -1], 1e-15, 'U shape');
  assert.ok(closureGap(p, poses, [H, -H]) <= 1e-15); // a tree has no loop to break
});

test('buildTree: a forest roots later components at their lowest actor index', () => {
  // Two separate squares; the second's actors are 2 and 3, its joint listed first.
  const a = square(), b = square();
  const p = {
    vertices: [...a.vertices, ...b.vertices.map(([x, y]) => [x + 2, y])],
    actors: [...a.actors, ...b.actors.map((t) => ({ id: t.id + 2, triangles: t.triangles.map((tri) => tri.map((v) => v + 6)) }))],
    joints: [{ id: 7, v: [7, 10], actors: [3, 2] }, { id: 8, v: [1, 4], actors: [0, 1] }],
  };
  const tree = buildTree(p, 1);
  assert.deepEqual([...tree.order], [1, 0, 2, 3]);
  assert.deepEqual([...tree.parent], [1, -1, -1, 2]);
  assert.deepEqual([...tree.parentJoint], [1, -1, -1, 0]);
  assert.throws(() => buildTree(p, 4), RangeError);
});

test('buildTree visits an actor’s joints in joint order (breadth first)', () => {
  // The Miura 4×4 fixture: actor 0's joints in file order decide who is reached through what.
  const p = fixture('miura-4x4.pattern.json');
  const tree = buildTree(p);
  assert.equal(tree.order[0], 0);
  const seen = new Set([0]);
  for (const a of tree.order) {
    if (a !== 0) assert.ok(seen.has(tree.parent[a]), 'a parent comes before its children');
    seen.add(a);
  }
  // Tree edges: one per non-root actor, and each parent joint really joins child and parent.
  assert.equal(tree.inTree.reduce((s, x) => s + x, 0), p.actors.length - 1);
  for (let b = 1; b < p.actors.length; ++b) {
    const j = p.joints[tree.parentJoint[b]];
    assert.deepEqual([...j.actors].sort(), [b, tree.parent[b]].sort());
  }
  // Children of the root are its neighbours in the order of the joints that reach them.
  const first = p.joints.map((j, i) => [j, i]).filter(([j]) => j.actors.includes(0)).map(([j]) => j.actors.find((x) => x !== 0));
  assert.deepEqual([...tree.order.slice(1, 1 + first.length)], first);
});

for (const [name, pattern, state] of [
  ['Miura-ori 4×4 folded to 0.9', 'miura-4x4.pattern.json', 'miura-4x4-0.9.angles.json'],
  ['waterbomb 3×4 folded to 0.5', 'waterbomb-3x4.pattern.json', 'waterbomb-3x4-0.5.angles.json'],
]) {
  test(`foldkit fold's ${name} is closed, and a changed angle is not`, () => {
    const p = fixture(pattern), { jointIds, angles } = fixture(state);
    assert.deepEqual(jointIds, p.joints.map((j) => j.id));
    // foldkit fold follows the assignment: mountains positive, valleys negative.
    p.joints.forEach((j, i) => {
      if (j.assignment === 'M') assert.ok(angles[i] > 0, `joint ${j.id} is a mountain`);
      if (j.assignment === 'V') assert.ok(angles[i] < 0, `joint ${j.id} is a valley`);
    });
    const size = diagonal(p), tree = buildTree(p);
    const poses = facetPoses(p, tree, angles);
    const gap = closureGap(p, poses, angles);
    assert.ok(gap <= 1e-9 * size, `closure gap ${gap}`);
    assert.ok(closureGap(p, poses) <= gap, 'the angle check only adds to the crease ends');

    // One angle off by 0.1 rad, a tree joint (moves facets) or not (only the angle check sees it).
    const loopJoint = p.joints.findIndex((_, j) => !tree.inTree[j]);
    const treeJoint = tree.parentJoint[tree.order[1]];
    for (const j of [loopJoint, treeJoint]) {
      const changed = [...angles];
      changed[j] += 0.1;
      const bad = closureGap(p, facetPoses(p, tree, changed), changed);
      assert.ok(bad > 1e-3 * size, `joint ${p.joints[j].id} changed by 0.1: gap ${bad}`);
    }

    // On a closed state the tree does not matter: from another root the poses differ by one
    // rigid motion, pose_r[a] = pose_r[0] · pose_0[a].
    const last = p.actors.length - 1;
    const other = facetPoses(p, buildTree(p, last), angles);
    assert.ok(closureGap(p, other, angles) <= 1e-9 * size);
    for (let a = 0; a < p.actors.length; ++a)
      for (const t of p.actors[a].triangles)
        for (const v of t) {
          const viaRoot0 = image(poses, a, p.vertices[v]);
          const moved = image(other, 0, [0, 0]).map((c, r) => c + [0, 1, 2].reduce((s, k) => s + other[r + 4 * k] * viaRoot0[k], 0));
          assertClose(image(other, a, p.vertices[v]), moved, 1e-9 * size, `actor ${a} from root ${last}`);
        }
  });
}

test('facets stay rigid: edge lengths and orientation are kept, whatever the angles', () => {
  const states = [
    [fixture('miura-4x4.pattern.json'), fixture('miura-4x4-0.9.angles.json').angles],
    [fixture('waterbomb-3x4.pattern.json'), fixture('waterbomb-3x4-0.5.angles.json').angles],
  ];
  // An arbitrary, unclosed state too: rigidity does not depend on closure.
  const p = fixture('waterbomb-3x4.pattern.json');
  states.push([p, p.joints.map((_, i) => Math.sin(7.3 * i + 1) * 3)]);
  for (const [pattern, angles] of states) {
    const poses = facetPoses(pattern, buildTree(pattern), angles);
    const triangles = pattern.actors.reduce((s, a) => s + a.triangles.length, 0);
    const folded = foldedVertices(pattern, poses, new Float64Array(9 * triangles));
    let w = 0;
    for (let a = 0; a < pattern.actors.length; ++a) {
      const o = 16 * a, R = [0, 1, 2].map((r) => [0, 1, 2].map((k) => poses[o + r + 4 * k]));
      const det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) - R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
        R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
      assert.ok(Math.abs(det - 1) < 1e-12, `actor ${a}: det ${det}`);
      assert.deepEqual([poses[o + 3], poses[o + 7], poses[o + 11], poses[o + 15]], [0, 0, 0, 1]);
      for (const t of pattern.actors[a].triangles) {
        const corners = [0, 1, 2].map((k) => folded.slice(w + 3 * k, w + 3 * k + 3));
        w += 9;
        for (let k = 0; k < 3; ++k) {
          const [p0, p1] = [pattern.vertices[t[k]], pattern.vertices[t[(k + 1) % 3]]];
          const flat = Math.hypot(p1[0] - p0[0], p1[1] - p0[1]);
          const [q0, q1] = [corners[k], corners[(k + 1) % 3]];
          const bent = Math.hypot(q1[0] - q0[0], q1[1] - q0[1], q1[2] - q0[2]);
          assert.ok(Math.abs(bent - flat) <= 1e-12 * flat, `actor ${a}: edge ${flat} became ${bent}`);
        }
      }
    }
    assert.equal(w, folded.length);
  }
});

test('foldedVertices and facetPoses fill the arrays they are given', () => {
  const p = strip(), tree = buildTree(p);
  const poses = new Float64Array(16 * 3).fill(NaN), corners = new Float32Array(9 * 6);
  assert.equal(facetPoses(p, tree, [H, -H], poses), poses);
  assert.equal(foldedVertices(p, poses, corners), corners);
  const fresh = foldedVertices(p, poses);
  assert.ok(fresh instanceof Float32Array && fresh.length === 54);
  assert.deepEqual([...fresh], [...corners]);
  // Layout: actor 2's first triangle (corners (2,0), (3,0), (3,1)) starts at 9 × 4.
  assertClose([...corners.slice(36, 45)], [1, 0, -1, 2, 0, -1, 2, 1, -1], 1e-6, 'actor 2, triangle 0');
});

test('an empty sheet has an empty tree and no poses; a root out of range is refused', () => {
  const empty = { vertices: [], actors: [], joints: [] };
  const tree = buildTree(empty);
  assert.equal(tree.order.length, 0);
  assert.equal(facetPoses(empty, tree, new Float64Array(0)).length, 0);
  assert.throws(() => buildTree(empty, 1), RangeError);
});
