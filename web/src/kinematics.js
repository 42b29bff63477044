// Forward kinematics of a crease pattern: a pure ES module (no DOM, no three.js), a line-by-line
// port of foldkit's geometry/src/kinematics.cpp so that the browser folds exactly as the C++ does.
//
// Pattern (plain JSON, built by the app from the PMML model):
//   { vertices: [[x, y], ...],                                   // the flat sheet, z = 0
//     actors:   [{id, triangles: [[i, j, k], ...]}],             // rigid facets
//     joints:   [{id, v: [i, j], actors: [ia, ib], assignment}] } // ia, ib: indices into actors
// Angles: radians, one per joint in joint order; 0 = flat, positive = mountain.
// Poses: a Float64Array of 16 numbers per actor, each a column-major 4×4 rigid motion
// (three.js Matrix4.fromArray(poses, 16 * actor) reads one), taking the flat sheet to the fold.

/**
 * Which side of joint `joint`'s crease actor `actor` lies on: foldkit's side_of(). With
 * d = unit(v[1] - v[0]), the actor's triangle with an edge on the crease segment decides by its
 * third corner: left of the axis (seen from +z) gives -1, right gives +1.
 * @param {object} pattern
 * @param {number} joint joint index
 * @param {number} actor actor index
 * @returns {-1|1}
 * @throws {Error} when the actor has no triangle edge on the crease
 */
export function sideOf(pattern, joint, actor) {
  const V = pattern.vertices;
  const j = pattern.joints[joint];
  const [ax, ay] = V[j.v[0]];
  const ux = V[j.v[1]][0] - ax, uy = V[j.v[1]][1] - ay;
  const length = Math.hypot(ux, uy), tol = 1e-9 * length;
  const dx = ux / length, dy = uy / length;
  const across = (p) => dx * (p[1] - ay) - dy * (p[0] - ax); // > 0: left
  const onCrease = (p) => {
    const along = dx * (p[0] - ax) + dy * (p[1] - ay);
    return Math.abs(across(p)) <= tol && along >= -tol && along <= length + tol;
  };
  // The triangle with an edge on the crease tells the side, even for an actor that reaches round
  // to the other side of the crease line further away.
  for (const t of pattern.actors[actor].triangles)
    for (let k = 0; k < 3; ++k)
      if (onCrease(V[t[k]]) && onCrease(V[t[(k + 1) % 3]])) return across(V[t[(k + 2) % 3]]) > 0 ? -1 : 1;
  throw new Error(`sideOf: actor ${pattern.actors[actor].id} has no edge on joint ${j.id}`);
}

/**
 * The kinematic tree: foldkit's make_tree(). A breadth-first spanning forest of the facet graph
 * (one node per actor, one edge per joint) from actor `root`; every other component is rooted at
 * its lowest actor index. An actor's edges are visited in joint order, as foldkit adds them.
 * @param {object} pattern
 * @param {number} [root=0] actor index of the root
 * @returns {{order: Int32Array, parent: Int32Array, parentJoint: Int32Array, side: Float64Array,
 *            inTree: Uint8Array}} order: actors in visiting order (a parent before its children);
 *   parent / parentJoint: per actor, -1 for a root; side: per actor, ±1 (sideOf of its parent
 *   joint; 1 for a root); inTree: per joint, 1 when it is a tree edge (its angle moves facets).
 */
export function buildTree(pattern, root = 0) {
  const n = pattern.actors.length, m = pattern.joints.length;
  // An empty sheet (the editor's, before anything is drawn) has an empty tree.
  if (!(root >= 0 && root < n) && !(n === 0 && root === 0)) throw new RangeError('buildTree: root actor index out of range');
  // Adjacency lists in joint order (boost's vecS out-edge lists keep insertion order).
  const adjacency = Array.from({ length: n }, () => []);
  pattern.joints.forEach((j, index) => {
    adjacency[j.actors[0]].push(index);
    if (j.actors[1] !== j.actors[0]) adjacency[j.actors[1]].push(index);
  });
  const tree = {
    order: new Int32Array(n),
    parent: new Int32Array(n).fill(-1),
    parentJoint: new Int32Array(n).fill(-1),
    side: new Float64Array(n).fill(1),
    inTree: new Uint8Array(m),
  };
  const seen = new Uint8Array(n);
  let head = 0, tail = 0; // tree.order doubles as the BFS queue
  for (let start = n === 0 ? 0 : -1; start < n; ++start) {
    const r = start < 0 ? root : start;
    if (seen[r]) continue;
    seen[r] = 1;
    tree.order[tail++] = r;
    while (head < tail) {
      const a = tree.order[head++];
      for (const j of adjacency[a]) {
        const [p, q] = pattern.joints[j].actors;
        const b = p === a ? q : p;
        if (seen[b]) continue;
        seen[b] = 1;
        tree.parent[b] = a;
        tree.parentJoint[b] = j;
        tree.side[b] = sideOf(pattern, j, b);
        tree.inTree[j] = 1;
        tree.order[tail++] = b;
      }
    }
  }
  return tree;
}

// Scratch joint motion: facetPoses runs every frame and must not allocate.
const M = new Float64Array(16);

// foldkit's joint_motion(): the rotation by `angle` (right-hand rule) about the unit direction
// d = unit(a1 - a0) through a0 (z = 0), i.e. [R | a0 - R a0], written column-major into m
// (its 3×4 part; the last row is never read).
function jointMotion(a0, a1, angle, m) {
  const px = a0[0], py = a0[1];
  let dx = a1[0] - px, dy = a1[1] - py;
  const len = Math.sqrt(dx * dx + dy * dy);
  dx /= len; dy /= len;
  const c = Math.cos(angle), s = Math.sin(angle), C = 1 - c;
  // Rodrigues with d = (dx, dy, 0): R = c I + s [d]x + (1 - c) d dᵀ, by columns.
  m[0] = c + C * dx * dx; m[1] = C * dx * dy;     m[2] = -s * dy;
  m[4] = C * dx * dy;     m[5] = c + C * dy * dy; m[6] = s * dx;
  m[8] = s * dy;          m[9] = -s * dx;         m[10] = c;
  m[12] = px - (m[0] * px + m[4] * py);
  m[13] = py - (m[1] * px + m[5] * py);
  m[14] = -(m[2] * px + m[6] * py);
  return m;
}

/**
 * Facet poses: foldkit's facet_poses(). A root stays put; each other actor b gets
 * pose[parent] · R(axis of its parent joint, side[b] · angle), R the right-hand rotation about
 * the crease's unit direction v[0] → v[1] through v[0] (z = 0).
 * Allocation-free when `out` is given (it runs every animation frame).
 * @param {object} pattern
 * @param {ReturnType<typeof buildTree>} tree
 * @param {ArrayLike<number>} angles radians, one per joint
 * @param {Float64Array} [out] 16 × actors numbers to fill
 * @returns {Float64Array} column-major 4×4 per actor
 */
export function facetPoses(pattern, tree, angles, out) {
  const n = pattern.actors.length;
  const P = out ?? new Float64Array(16 * n);
  const V = pattern.vertices, joints = pattern.joints, { order, parent, parentJoint, side } = tree;
  for (let k = 0; k < n; ++k) {
    const b = order[k], o = 16 * b;
    const j = parentJoint[b];
    if (j < 0) { // a root: identity
      P.fill(0, o, o + 16);
      P[o] = P[o + 5] = P[o + 10] = P[o + 15] = 1;
      continue;
    }
    const jv = joints[j].v;
    jointMotion(V[jv[0]], V[jv[1]], side[b] * angles[j], M);
    // pose[b] = pose[parent] · M, both column-major.
    const q = 16 * parent[b];
    for (let row = 0; row < 3; ++row) {
      const m0 = P[q + row], m1 = P[q + 4 + row], m2 = P[q + 8 + row];
      P[o + row] = m0 * M[0] + m1 * M[1] + m2 * M[2];
      P[o + 4 + row] = m0 * M[4] + m1 * M[5] + m2 * M[6];
      P[o + 8 + row] = m0 * M[8] + m1 * M[9] + m2 * M[10];
      P[o + 12 + row] = m0 * M[12] + m1 * M[13] + m2 * M[14] + P[q + 12 + row];
    }
    P[o + 3] = P[o + 7] = P[o + 11] = 0;
    P[o + 15] = 1;
  }
  return P;
}

/**
 * The folded triangles: every triangle's three corners moved by its actor's pose, in actor order
 * then triangle order, corners in the pattern's order: 9 floats (x, y, z × 3) per triangle, what
 * a non-indexed three.js BufferGeometry position attribute holds.
 * @param {object} pattern
 * @param {Float64Array} poses from facetPoses()
 * @param {Float32Array|Float64Array} [out] 9 × triangles numbers to fill (allocation-free)
 * @returns {Float32Array|Float64Array}
 */
export function foldedVertices(pattern, poses, out) {
  let count = 0;
  if (!out) {
    for (const a of pattern.actors) count += a.triangles.length;
    out = new Float32Array(9 * count);
  }
  const V = pattern.vertices, actors = pattern.actors;
  let w = 0;
  for (let a = 0; a < actors.length; ++a) {
    const o = 16 * a, tris = actors[a].triangles;
    for (let t = 0; t < tris.length; ++t)
      for (let k = 0; k < 3; ++k) {
        const p = V[tris[t][k]], x = p[0], y = p[1];
        out[w++] = poses[o] * x + poses[o + 4] * y + poses[o + 12];
        out[w++] = poses[o + 1] * x + poses[o + 5] * y + poses[o + 13];
        out[w++] = poses[o + 2] * x + poses[o + 6] * y + poses[o + 14];
      }
  }
  return out;
}

// The image of the flat point (x, y, 0) under pose `o` of P, into v.
function apply(P, o, x, y, v) {
  v[0] = P[o] * x + P[o + 4] * y + P[o + 12];
  v[1] = P[o + 1] * x + P[o + 5] * y + P[o + 13];
  v[2] = P[o + 2] * x + P[o + 6] * y + P[o + 14];
  return v;
}

/**
 * How far the poses are from a closed state: the largest distance, over every joint and both
 * ends of its crease, between the end's image through one actor and through the other (0 up to
 * round-off when the poses come from a closed state; tree joints give 0 by construction).
 * With `angles`, each joint's stated angle is checked too: the point at one crease length left
 * of v[0], carried by actor ib's pose, is compared with where actor ia's pose followed by the
 * joint's rotation puts it — a non-tree joint's angle does not move any facet, so the crease
 * ends alone cannot see it.
 * @param {object} pattern
 * @param {Float64Array} poses from facetPoses()
 * @param {ArrayLike<number>} [angles] radians, one per joint
 * @returns {number} pattern length units
 */
export function closureGap(pattern, poses, angles) {
  const V = pattern.vertices, e = [0, 0, 0], f = [0, 0, 0];
  let gap = 0;
  const dist = () => Math.hypot(e[0] - f[0], e[1] - f[1], e[2] - f[2]);
  pattern.joints.forEach((j, index) => {
    const oa = 16 * j.actors[0], ob = 16 * j.actors[1];
    for (const v of j.v) {
      const [x, y] = V[v];
      apply(poses, oa, x, y, e);
      apply(poses, ob, x, y, f);
      gap = Math.max(gap, dist());
    }
    if (!angles) return;
    // pose[ib] should be pose[ia] · joint motion (the relation facetPoses builds for a child ib).
    const a0 = V[j.v[0]], a1 = V[j.v[1]];
    jointMotion(a0, a1, sideOf(pattern, index, j.actors[1]) * angles[index], M);
    const x = a0[0] - (a1[1] - a0[1]), y = a0[1] + (a1[0] - a0[0]); // one crease length left of v[0]
    apply(M, 0, x, y, f);
    const g = [f[0], f[1], f[2]];
    apply(poses, oa, 0, 0, e); // e = pose[ia] · g: translation, then the rotation by columns
    for (let r = 0; r < 3; ++r) e[r] += poses[oa + r] * g[0] + poses[oa + 4 + r] * g[1] + poses[oa + 8 + r] * g[2];
    apply(poses, ob, x, y, f);
    gap = Math.max(gap, dist());
  });
  return gap;
}
