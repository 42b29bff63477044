// Joints that span several edges: a run of edges along one line between the same two actors is
// one crease, one joint (as foldkit reads a joint through a corner). PatternModel keeps one
// properties object per run; these find runs, extend them and split those an edit broke.
import { dist, cross3 } from './polygon.js';

/** The IDs of the two actors an edge lies between, ascending. */
export const actorsOf = (model, e) => e.triangles.map((t) => model.triangles[t].actor).sort((a, b) => a - b);
const pairOf = (model, e) => actorsOf(model, e).join(' ');

/**
 * The properties of the crease that edge e continues: a shared edge with properties at one of e's
 * ends (`at`: shared edges by vertex), between the same two actors and on e's line beyond that
 * end; or null.
 */
export function continuedCrease(model, e, at, tol) {
  const mine = pairOf(model, e);
  for (const [v, w] of [[e.i, e.j], [e.j, e.i]])
    for (const f of at.get(v) ?? []) {
      const p = f !== e && model._props.get(f.key);
      if (!p || pairOf(model, f) !== mine) continue;
      const u = f.i === v ? f.j : f.i;
      if (straightThrough(model.vertices[w], model.vertices[v], model.vertices[u], tol)) return p;
    }
  return null;
}

/**
 * Edges of one ID as runs, each one line of edges between the same two actors joined end to end;
 * the run with the smallest end (x, then y) first, so that the split is deterministic.
 */
export function splitRuns(model, edges, tol) {
  const groups = new Map();
  for (const e of edges) {
    const pair = pairOf(model, e);
    (groups.get(pair) ?? groups.set(pair, []).get(pair)).push(e);
  }
  const runs = [];
  for (const group of groups.values())
    for (const part of connected(group)) {
      if (part.length === 1 || isStraightRun(model, part, tol)) runs.push(part);
      else for (const e of part) runs.push([e]);
    }
  const first = (run) => {
    const p = run.flatMap((e) => [model.vertices[e.i], model.vertices[e.j]]);
    return p.reduce((m, q) => (q.x < m.x || (q.x === m.x && q.y < m.y) ? q : m));
  };
  return runs
    .map((run) => ({ run, p: first(run) }))
    .sort((r, s) => r.p.x - s.p.x || r.p.y - s.p.y)
    .map((r) => r.run);
}

// How many of the edges meet at each vertex, and the vertices only one of them reaches.
function degrees(edges) {
  const degree = new Map();
  for (const e of edges) for (const v of [e.i, e.j]) degree.set(v, (degree.get(v) ?? 0) + 1);
  return { degree, ends: [...degree].filter(([, d]) => d === 1).map(([v]) => v) };
}

// Whether connected edges form a path along one line: two ends, every other vertex on two edges
// of it and straight through.
function isStraightRun(model, edges, tol) {
  const { degree, ends } = degrees(edges);
  if (ends.length !== 2 || [...degree.values()].some((d) => d > 2)) return false;
  const a = model.vertices[ends[0]], b = model.vertices[ends[1]], len = dist(a, b);
  return [...degree.keys()].every((v) => Math.abs(cross3(a, b, model.vertices[v])) <= tol * len);
}

/** The two ends of a run of edges (the vertices on one edge of it); a single edge's own ends. */
export function runEnds(edges) {
  const { ends } = degrees(edges);
  return ends.length === 2 ? ends : [edges[0].i, edges[0].j];
}

// Whether the path w → v → u runs straight through v (u beyond v, on the line of w and v).
function straightThrough(w, v, u, tol) {
  const dx = v.x - w.x, dy = v.y - w.y, ex = u.x - v.x, ey = u.y - v.y;
  return dx * ex + dy * ey > 0 && Math.abs(dx * ey - dy * ex) <= tol * (Math.hypot(dx, dy) + Math.hypot(ex, ey));
}

// Edges in groups that share vertices (connected components).
function connected(edges) {
  const parent = edges.map((_, k) => k);
  const root = (k) => (parent[k] === k ? k : (parent[k] = root(parent[k])));
  const owner = new Map();
  edges.forEach((e, k) => {
    for (const v of [e.i, e.j]) {
      if (owner.has(v)) parent[root(k)] = root(owner.get(v));
      else owner.set(v, k);
    }
  });
  const parts = new Map();
  edges.forEach((e, k) => (parts.get(root(k)) ?? parts.set(root(k), []).get(root(k))).push(e));
  return [...parts.values()];
}
