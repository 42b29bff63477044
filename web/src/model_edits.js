// The edits of a PatternModel that add and change geometry, as plain functions of the model
// (addPolygon(model, points), …), with the welding, edge splitting and renumbering under them.
// They reach into the model's internals (_commit, _props, _usedPoints, …): model.js and this file
// are one unit, split by concern (state and queries there, geometric edits here).
import { cross3, dist, boxOf, toleranceOf, checkPoint, Welder, earClip, signedArea, cleanPolygon } from './polygon.js';
import { edgeKey, keyEnds } from './edge_key.js';

// ------------------------------------------------------------------ adding geometry

/** Triangulate a simple polygon (ear clipping) into actorId or a new actor; returns new triangle indices. */
export function addPolygon(model, points, actorId = undefined) {
  const box = boxOf(points.map((p) => checkPoint(p, 'polygon corner')));
  const pts = cleanPolygon(points, toleranceOf(boxOf(model._usedPoints(), box)));
  if (signedArea(pts) < 0) pts.reverse(); // counter-clockwise triangles, as foldkit stores them
  const tris = earClip(pts, toleranceOf(box));
  const actor = actorId ?? model.nextActorId();
  return appendAndCommit(model, pts, tris.map((v) => ({ v, actor })));
}

/** Add one triangle (a new actor unless actorId is given); returns [its index]. */
export function addTriangle(model, p, q, r, actorId = undefined) {
  const pts = [checkPoint(p, 'triangle corner'), checkPoint(q, 'triangle corner'), checkPoint(r, 'triangle corner')];
  const tol = toleranceOf(boxOf(pts));
  if (Math.abs(cross3(...pts)) <= tol * Math.max(dist(pts[0], pts[1]), dist(pts[1], pts[2]), dist(pts[2], pts[0])))
    throw new Error('degenerate triangle (zero area)');
  if (cross3(...pts) < 0) pts.reverse();
  return appendAndCommit(model, pts, [{ v: [0, 1, 2], actor: actorId ?? model.nextActorId() }]);
}

/**
 * A cols × rows lattice filling the rectangle from (x, y) of size w × h. Each cell is one actor;
 * with diagonals ('/', '\\' or 'x') every triangle is its own actor so the diagonals are creases.
 * Returns the new triangle indices.
 */
export function addGrid(model, { x = 0, y = 0, cols = 1, rows = 1, w = 1, h = 1, diagonals = 'none' } = {}) {
  if (!(Number.isInteger(cols) && cols >= 1 && Number.isInteger(rows) && rows >= 1)) throw new Error('cols and rows must be positive integers');
  if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(w) && Number.isFinite(h)) || w === 0 || h === 0)
    throw new Error('the grid needs a finite, non-empty rectangle');
  if (!['none', '/', '\\', 'x'].includes(diagonals)) throw new Error("diagonals must be 'none', '/', '\\\\' or 'x'");
  if (w < 0) [x, w] = [x + w, -w];
  if (h < 0) [y, h] = [y + h, -h];
  const pts = [];
  const at = (c, r) => r * (cols + 1) + c;
  for (let r = 0; r <= rows; ++r)
    for (let c = 0; c <= cols; ++c) pts.push({ x: c === cols ? x + w : x + (c * w) / cols, y: r === rows ? y + h : y + (r * h) / rows });
  let actor = model.nextActorId();
  const tris = [];
  for (let r = 0; r < rows; ++r)
    for (let c = 0; c < cols; ++c) {
      const p00 = at(c, r), p10 = at(c + 1, r), p11 = at(c + 1, r + 1), p01 = at(c, r + 1);
      if (diagonals === 'x') {
        pts.push({ x: (pts[p00].x + pts[p10].x) / 2, y: (pts[p00].y + pts[p01].y) / 2 });
        const m = pts.length - 1;
        for (const [a, b] of [[p00, p10], [p10, p11], [p11, p01], [p01, p00]]) tris.push({ v: [a, b, m], actor: actor++ });
      } else if (diagonals === '\\') {
        tris.push({ v: [p00, p10, p01], actor }, { v: [p10, p11, p01], actor: actor + 1 });
        actor += 2;
      } else {
        const split = diagonals === '/';
        tris.push({ v: [p00, p10, p11], actor }, { v: [p00, p11, p01], actor: split ? actor + 1 : actor });
        actor += split ? 2 : 1;
      }
    }
  return appendAndCommit(model, pts, tris);
}

/**
 * A circular lattice at (x, y): `rings` rings of equal width up to `radius`, crossed by `spokes`
 * spokes; one actor per cell, the centre cells triangles. Returns the new triangle indices.
 */
export function addCircular(model, { x = 0, y = 0, rings = 1, spokes = 6, radius = 1 } = {}) {
  if (!(Number.isInteger(rings) && rings >= 1)) throw new Error('rings must be a positive integer');
  if (!(Number.isInteger(spokes) && spokes >= 3)) throw new Error('spokes must be an integer of at least 3');
  if (!(Number.isFinite(radius) && radius > 0 && Number.isFinite(x) && Number.isFinite(y))) throw new Error('radius must be positive');
  const pts = [{ x, y }];
  const at = (ring, s) => 1 + (ring - 1) * spokes + (s % spokes);
  const width = radius / rings;
  for (let ring = 1; ring <= rings; ++ring)
    for (let s = 0; s < spokes; ++s) {
      const angle = (2 * Math.PI * s) / spokes;
      pts.push({ x: x + ring * width * Math.cos(angle), y: y + ring * width * Math.sin(angle) });
    }
  let actor = model.nextActorId();
  const tris = [];
  for (let s = 0; s < spokes; ++s) tris.push({ v: [0, at(1, s), at(1, s + 1)], actor: actor++ });
  const d2 = (i, j) => (pts[i].x - pts[j].x) ** 2 + (pts[i].y - pts[j].y) ** 2;
  for (let ring = 1; ring < rings; ++ring)
    for (let s = 0; s < spokes; ++s, ++actor) {
      const q = [at(ring, s), at(ring + 1, s), at(ring + 1, s + 1), at(ring, s + 1)];
      // The shorter diagonal, ties to q0-q2, as foldkit's generator splits its quads.
      const [p0, p1, p2, p3] = d2(q[0], q[2]) <= d2(q[1], q[3]) ? q : [q[1], q[2], q[3], q[0]];
      tris.push({ v: [p0, p1, p2], actor }, { v: [p0, p2, p3], actor });
    }
  return appendAndCommit(model, pts, tris);
}

/** Copy triangles into a clipboard object: their corners, actor grouping and joint properties. */
export function copyTriangles(model, indices) {
  const vmap = new Map(), vertices = [], groups = new Map(), triangles = [];
  const set = new Set(indices);
  for (const t of [...set].sort((a, b) => a - b)) {
    const tri = model.triangles[t];
    if (!tri) continue;
    const v = tri.v.map((i) => {
      if (!vmap.has(i)) {
        vmap.set(i, vertices.length);
        vertices.push({ ...model.vertices[i] });
      }
      return vmap.get(i);
    });
    if (!groups.has(tri.actor)) groups.set(tri.actor, groups.size);
    triangles.push({ v, group: groups.get(tri.actor) });
  }
  const edges = [];
  for (const e of model.edges()) {
    const p = model._props.get(e.key);
    if (p && e.kind === 'joint' && e.triangles.every((t) => set.has(t)))
      edges.push({ a: vmap.get(e.i), b: vmap.get(e.j), joint: p.id, spring: p.spring, damping: p.damping, assignment: p.assignment, maxTorque: p.maxTorque });
  }
  return { vertices, triangles, edges, bounds: boxOf(vertices) };
}

/** Paste a clipboard moved by (dx, dy): one new actor per copied actor; returns new triangle indices. */
export function paste(model, clipboard, dx = 0, dy = 0) {
  const pts = clipboard.vertices.map((p) => ({ x: p.x + dx, y: p.y + dy }));
  const first = model.nextActorId();
  const tris = clipboard.triangles.map((t) => ({ v: [...t.v], actor: first + t.group }));
  const { triangles, vmap } = appendTriangles(model, pts, tris);
  const topo = model._topology();
  // One new joint per copied joint: the edges of a run stay one crease.
  const copies = new Map();
  for (const e of clipboard.edges ?? []) {
    const key = edgeKey(vmap[e.a], vmap[e.b]);
    const edge = topo.byKey.get(key);
    if (!edge || edge.kind !== 'joint' || model._props.has(key)) continue;
    const id = e.joint ?? key;
    if (!copies.has(id)) {
      const props = { id: model._takeJointId(), spring: e.spring, damping: e.damping, assignment: e.assignment };
      if (e.maxTorque !== undefined && e.maxTorque !== null) props.maxTorque = e.maxTorque;
      copies.set(id, props);
    }
    model._props.set(key, copies.get(id));
  }
  model._commit();
  return triangles;
}

// ------------------------------------------------------------------ editing

/** Delete triangles (and the vertices no triangle uses any more); returns how many were deleted. */
export function deleteTriangles(model, indices) {
  const drop = new Set([...indices].filter((t) => t >= 0 && t < model.triangles.length));
  if (!drop.size) return 0;
  model.triangles = model.triangles.filter((_, t) => !drop.has(t));
  compact(model);
  model._commit();
  return drop.size;
}

/** Move vertices by (dx, dy), then weld them onto unmoved vertices they land on; returns their new indices. */
export function moveVertices(model, indices, dx, dy) {
  if (!Number.isFinite(dx) || !Number.isFinite(dy)) throw new Error('moveVertices: not a finite offset');
  const set = new Set(indices);
  for (const i of set) {
    model.vertices[i].x += dx;
    model.vertices[i].y += dy;
  }
  return settle(model, set);
}

/**
 * Mirror ('x' flips x, 'y' flips y), scale and rotate (radians, counter-clockwise) vertices about
 * a point (default: the centre of their bounding box); returns their new indices.
 */
export function transformVertices(model, indices, { rotate = 0, scale = 1, mirror = null, about = null } = {}) {
  const set = new Set(indices);
  if (!set.size) return [];
  if (!Number.isFinite(rotate) || !Number.isFinite(scale) || scale === 0) throw new Error('transformVertices: bad rotation or scale');
  if (mirror !== null && mirror !== 'x' && mirror !== 'y') throw new Error("mirror must be 'x' or 'y'");
  const box = boxOf([...set].map((i) => model.vertices[i]));
  const o = about ?? { x: (box.minX + box.maxX) / 2, y: (box.minY + box.maxY) / 2 };
  const c = Math.cos(rotate), s = Math.sin(rotate);
  const mx = mirror === 'x' ? -1 : 1, my = mirror === 'y' ? -1 : 1;
  for (const i of set) {
    const p = model.vertices[i];
    const x = (p.x - o.x) * mx * scale, y = (p.y - o.y) * my * scale;
    p.x = o.x + c * x - s * y;
    p.y = o.y + s * x + c * y;
  }
  // A mirrored triangle would turn clockwise; keep the orientation the triangle had.
  if (mx * my < 0)
    for (const t of model.triangles) if (t.v.every((i) => set.has(i))) [t.v[1], t.v[2]] = [t.v[2], t.v[1]];
  return settle(model, set);
}

/** Merge vertex j into vertex i, dropping triangles that collapse; returns i's index afterwards. */
export function mergeVertices(model, i, j) {
  if (i === j) return i;
  if (!model.vertices[i] || !model.vertices[j]) throw new Error('mergeVertices: no such vertex');
  const map = new Int32Array(model.vertices.length).map((_, k) => k);
  map[j] = i;
  remap(model, map);
  const renumber = compact(model);
  model._commit();
  return renumber[i];
}

/** Insert a vertex at t along edge i→j and split the triangles using that edge; returns its index. */
export function splitEdge(model, i, j, t = 0.5) {
  if (!(t > 0 && t < 1)) throw new Error('splitEdge: t must lie strictly between 0 and 1');
  const edge = model._topology().byKey.get(edgeKey(i, j));
  if (!edge) throw new Error(`no edge between vertices ${i} and ${j}`);
  const a = model.vertices[i], b = model.vertices[j];
  const tol = model.tolerance();
  model.vertices.push({ x: a.x + t * (b.x - a.x), y: a.y + t * (b.y - a.y) });
  const m = model.vertices.length - 1;
  // Both pieces stay the one crease they were: the same joint, the same ID.
  const props = model._props.get(edge.key);
  model._props.delete(edge.key);
  for (const ti of edge.triangles) splitTriangle(model, ti, new Map([[edge.key, [m]]]), tol);
  if (props) {
    model._props.set(edgeKey(i, m), props);
    model._props.set(edgeKey(m, j), props);
  }
  model._commit();
  return m;
}

/** Put triangles into one new actor (the next free ID); returns that ID. */
export function group(model, triangleIndices) {
  const id = model.nextActorId();
  for (const t of triangleIndices) if (model.triangles[t]) model.triangles[t].actor = id;
  model._commit();
  return id;
}

/** Make each triangle of an actor its own actor (the first keeps the ID); returns the actor IDs. */
export function ungroup(model, actorId) {
  const tris = model.trianglesOf(actorId);
  let next = model.nextActorId();
  const ids = tris.map((t, k) => (k === 0 ? actorId : next++));
  tris.forEach((t, k) => (model.triangles[t].actor = ids[k]));
  model._commit();
  return ids;
}

// ------------------------------------------------------------------ internals of edits

function appendAndCommit(model, points, tris) {
  const { triangles } = appendTriangles(model, points, tris);
  model._commit();
  return triangles;
}

// Welds the points onto existing vertices, adds the triangles (dropping ones that collapse),
// then splits edges where a vertex lies inside another's boundary edge, so that triangles
// always meet corner to corner. Does not commit.
function appendTriangles(model, points, tris) {
  const tol = toleranceOf(boxOf(points, boxOf(model._usedPoints())));
  const start = model.vertices.length;
  const welder = new Welder(model.vertices, tol, unusedSet(model));
  const vmap = points.map((p) => welder.insert(checkPoint(p, 'corner')));
  const added = new Set();
  for (const t of tris) {
    const v = t.v.map((k) => vmap[k]);
    if (v[0] === v[1] || v[1] === v[2] || v[0] === v[2]) continue;
    model.triangles.push({ v, actor: t.actor });
    added.add(model.triangles.length - 1);
  }
  model._version++;
  const moved = new Set();
  for (let i = start; i < model.vertices.length; ++i) moved.add(i);
  fixTJunctions(model, added, moved, tol);
  return { triangles: [...added].sort((a, b) => a - b), vmap };
}

function unusedSet(model) {
  const used = model._usedVertices(), set = new Set();
  for (let i = 0; i < model.vertices.length; ++i) if (!used[i]) set.add(i);
  return set;
}

// Boundary edges of changed triangles against every vertex, and every boundary edge against
// changed vertices: a vertex strictly inside such an edge splits the triangle that owns it.
function fixTJunctions(model, changedTris, changedVertices, tol) {
  if (!(tol > 0)) return;
  const topo = model._topology();
  const used = model._usedVertices();
  const all = [];
  for (let i = 0; i < model.vertices.length; ++i) if (used[i]) all.push(i);
  const changed = [...changedVertices].filter((i) => used[i]);
  const splits = new Map(); // triangle → Map(edge key → [vertex indices along the edge])
  for (const e of topo.edges) {
    if (e.triangles.length !== 1) continue;
    const t = e.triangles[0];
    const candidates = changedTris.has(t) || changedVertices.has(e.i) || changedVertices.has(e.j) ? all : changed;
    const inside = verticesInside(model, e.i, e.j, candidates, tol);
    if (!inside.length) continue;
    if (!splits.has(t)) splits.set(t, new Map());
    splits.get(t).set(e.key, inside);
  }
  for (const [t, edgeSplits] of splits) {
    const created = splitTriangle(model, t, edgeSplits, tol);
    if (changedTris.has(t)) for (const c of created) changedTris.add(c);
  }
}

// Vertex indices strictly inside segment i→j, ordered from i to j.
function verticesInside(model, i, j, candidates, tol) {
  const a = model.vertices[i], b = model.vertices[j];
  const len = dist(a, b);
  if (!(len > 2 * tol)) return [];
  const dx = (b.x - a.x) / len, dy = (b.y - a.y) / len;
  const minX = Math.min(a.x, b.x) - tol, maxX = Math.max(a.x, b.x) + tol;
  const minY = Math.min(a.y, b.y) - tol, maxY = Math.max(a.y, b.y) + tol;
  const found = [];
  for (const v of candidates) {
    if (v === i || v === j) continue;
    const p = model.vertices[v];
    if (p.x < minX || p.x > maxX || p.y < minY || p.y > maxY) continue;
    const rx = p.x - a.x, ry = p.y - a.y, along = rx * dx + ry * dy;
    if (Math.abs(dx * ry - dy * rx) <= tol && along > tol && along < len - tol) found.push([along, v]);
  }
  return found.sort((x, y) => x[0] - y[0]).map((f) => f[1]);
}

// Replaces triangle t by the triangulation of its outline with extra vertices on its edges
// (edgeSplits: edge key → vertices ordered along the edge, from either end). Joint properties
// of a split edge pass to its pieces, which stay one joint (one ID).
// Returns the indices of the triangles added besides t.
function splitTriangle(model, t, edgeSplits, tol) {
  const tri = model.triangles[t];
  const ring = [];
  for (let k = 0; k < 3; ++k) {
    const a = tri.v[k], b = tri.v[(k + 1) % 3], key = edgeKey(a, b);
    ring.push(a);
    let mids = edgeSplits.get(key);
    if (!mids) continue;
    const from = (i) => dist(model.vertices[i], model.vertices[a]);
    if (mids.length > 1 && from(mids[0]) > from(mids[mids.length - 1])) mids = [...mids].reverse();
    ring.push(...mids);
    const p = model._props.get(key);
    if (p) {
      model._props.delete(key);
      const chain = [a, ...mids, b];
      for (let s = 0; s + 1 < chain.length; ++s) {
        const k2 = edgeKey(chain[s], chain[s + 1]);
        if (!model._props.has(k2)) model._props.set(k2, p);
      }
    }
  }
  const pts = ring.map((i) => model.vertices[i]);
  const sign = Math.sign(cross3(...tri.v.map((i) => model.vertices[i])));
  const pieces = earClip(pts, tol).map((v) => {
    const tr = v.map((k) => ring[k]);
    if (Math.sign(cross3(...tr.map((i) => model.vertices[i]))) !== sign) [tr[1], tr[2]] = [tr[2], tr[1]];
    return tr;
  });
  tri.v = pieces[0];
  const created = [];
  for (let k = 1; k < pieces.length; ++k) {
    model.triangles.push({ v: pieces[k], actor: tri.actor });
    created.push(model.triangles.length - 1);
  }
  model._version++;
  return created;
}

// After a move: weld moved vertices onto unmoved ones they now touch, drop collapsed
// triangles, split edges the moved geometry now touches, and renumber.
function settle(model, set) {
  const tol = model.tolerance();
  const used = model._usedVertices();
  const skip = new Set();
  for (let i = 0; i < model.vertices.length; ++i) if (set.has(i) || !used[i]) skip.add(i);
  const welder = new Welder(model.vertices, tol, skip);
  const map = new Int32Array(model.vertices.length).map((_, k) => k);
  let welded = false;
  for (const i of set) {
    const target = welder.find(model.vertices[i]);
    if (target >= 0) {
      map[i] = target;
      welded = true;
    }
  }
  if (welded) remap(model, map);
  else model._version++;
  const movedVertices = new Set([...set].map((i) => map[i]));
  const movedTris = new Set();
  model.triangles.forEach((t, k) => {
    if (t.v.some((i) => movedVertices.has(i))) movedTris.add(k);
  });
  fixTJunctions(model, movedTris, movedVertices, tol);
  const renumber = compact(model);
  model._commit();
  return [...set].map((i) => renumber[map[i]]);
}

// Applies a vertex map (old → new index) to triangles and joint properties; drops triangles
// that collapse and exact duplicates. Neither compacts nor commits.
function remap(model, map) {
  const seen = new Set();
  model.triangles = model.triangles.filter((t) => {
    t.v = t.v.map((i) => map[i]);
    const [a, b, c] = t.v;
    if (a === b || b === c || a === c) return false;
    const key = [a, b, c].sort((x, y) => x - y).join(',');
    if (seen.has(key)) return false;
    seen.add(key);
    return true;
  });
  const props = new Map();
  // Properties of an edge that already had a key at its destination win over moved ones.
  const entries = [...model._props].sort(([k1], [k2]) => {
    const [a1, b1] = keyEnds(k1), [a2, b2] = keyEnds(k2);
    return Number(map[a1] !== a1 || map[b1] !== b1) - Number(map[a2] !== a2 || map[b2] !== b2);
  });
  for (const [key, p] of entries) {
    const [a, b] = keyEnds(key);
    const na = map[a], nb = map[b];
    if (na === nb) continue;
    const k = edgeKey(na, nb);
    if (!props.has(k)) props.set(k, p);
  }
  model._props = props;
  model._version++;
}

// Drops vertices no triangle uses; returns the old → new index map.
function compact(model) {
  const n = model.vertices.length;
  const used = new Uint8Array(n);
  for (const t of model.triangles) for (const i of t.v) used[i] = 1;
  const map = new Int32Array(n).fill(-1);
  const vertices = [];
  for (let i = 0; i < n; ++i)
    if (used[i]) {
      map[i] = vertices.length;
      vertices.push(model.vertices[i]);
    }
  if (vertices.length === n) return map;
  model.vertices = vertices;
  for (const t of model.triangles) t.v = t.v.map((i) => map[i]);
  const props = new Map();
  for (const [key, p] of model._props) {
    const [a, b] = keyEnds(key);
    if (map[a] >= 0 && map[b] >= 0) props.set(edgeKey(map[a], map[b]), p);
  }
  model._props = props;
  model._version++;
  return map;
}
