// The crease-pattern model of the web editor: triangles grouped into actors, with joints on
// the edges that two different actors share. Pure: no DOM, no three.js, so node tests run it.
// This module holds PatternModel's state, reading and writing, and queries; the edits that add
// and change geometry are plain functions of the model in model_edits.js (addPolygon(model, …)).
// It also re-exports the helpers, History and snapPoint, so imports from './model.js' keep working.
import { dist, boxOf, toleranceOf, cross3 } from './polygon.js';
import { edgeKey, keyEnds } from './edge_key.js';
import { ASSIGNMENTS, INT_MAX } from './pmml.js';
import { readModel, writeModel } from './model_pmml.js';
import { actorsOf, runEnds, continuedCrease, splitRuns } from './joint_runs.js';

export { MERGE_TOLERANCE, earClip, signedArea } from './polygon.js';
export { edgeKey } from './edge_key.js';
export { parseXml } from './xml.js';
export { History } from './history.js';
export { snapPoint } from './snap.js';

/** Default joint properties, as foldkit's generators write them. */
export const JOINT_DEFAULTS = Object.freeze({ spring: 1, damping: 0.1, assignment: 'U' });

/**
 * A crease pattern: vertices, triangles (each in an actor) and joint properties keyed by edge.
 * A joint is one crease: an edge two different actors share, or a run of such edges along one
 * line between the same two actors (a file's joint through a corner, an edge split in two), which
 * then share one ID, as foldkit reads them. Edits keep joint IDs stable: an edge's joint keeps its
 * ID for as long as the edge exists.
 */
export class PatternModel {
  /** An empty pattern, optionally titled. */
  constructor({ title = '' } = {}) {
    /** @type {{x: number, y: number}[]} */
    this.vertices = [];
    /** @type {{v: number[], actor: number}[]} */
    this.triangles = [];
    this.title = title;
    /** foldkit's PMML extensions for the dynamic model (docs/FORMATS.md): the sheet's density
     * (kg/m²), gravity ([x, y, z], m/s²) and fixed actor (an ID), each null where unset (the
     * file had none); written back as read. */
    this.physics = { density: null, gravity: null, fixedActor: null };
    /** Problems fromPMML tolerated (each 'LINE: message'); foldkit validate reports them as errors. */
    this.warnings = [];
    // Properties are kept for every edge that still exists, shared or not, so that an edge
    // that stops being a crease (group) and becomes one again (ungroup) keeps its ID.
    this._props = new Map();
    this._nextJointId = 1;
    this._version = 0;
    this._topo = null;
    this._joints = null;
  }

  /** A counter bumped by every edit: caches compare it. */
  get version() {
    return this._version;
  }

  /** Tell the model that vertices or triangles were changed directly (drops caches, assigns joint IDs). */
  touch() {
    this._commit();
  }

  // ------------------------------------------------------------------ reading and writing

  /** Parse PMML text; throws Error('LINE: message') on malformed input (model_pmml.js). */
  static fromPMML(text) {
    return readModel(text);
  }

  /** PMML text: actors in ID order with their triangles, then the joints in ID order (a run of edges as one segment). */
  toPMML() {
    return writeModel(this);
  }

  /** Plain JSON of the whole state (undo, saving editor state); flat arrays keep it small. */
  snapshot() {
    const vertices = new Array(this.vertices.length * 2);
    this.vertices.forEach((p, i) => {
      vertices[2 * i] = p.x;
      vertices[2 * i + 1] = p.y;
    });
    const triangles = new Array(this.triangles.length * 4);
    this.triangles.forEach((t, i) => {
      triangles[4 * i] = t.v[0];
      triangles[4 * i + 1] = t.v[1];
      triangles[4 * i + 2] = t.v[2];
      triangles[4 * i + 3] = t.actor;
    });
    const edges = [], spring = [], damping = [], maxTorque = [];
    let assignment = '';
    for (const [key, p] of this._props) {
      edges.push(...keyEnds(key), p.id);
      spring.push(p.spring);
      damping.push(p.damping);
      assignment += p.assignment;
      maxTorque.push(p.maxTorque ?? null);
    }
    const physics = { ...this.physics, gravity: this.physics.gravity && [...this.physics.gravity] };
    return { title: this.title, vertices, triangles, joints: { edges, spring, damping, assignment, maxTorque }, nextJointId: this._nextJointId, physics };
  }

  /** A model from snapshot(). */
  static fromSnapshot(obj) {
    const m = new PatternModel();
    m.restore(obj);
    return m;
  }

  /** Replace this model's state by a snapshot() in place (callers keep their reference). */
  restore(obj) {
    this.title = obj.title ?? '';
    this.vertices = [];
    for (let i = 0; i < obj.vertices.length; i += 2) this.vertices.push({ x: obj.vertices[i], y: obj.vertices[i + 1] });
    this.triangles = [];
    for (let i = 0; i < obj.triangles.length; i += 4)
      this.triangles.push({ v: [obj.triangles[i], obj.triangles[i + 1], obj.triangles[i + 2]], actor: obj.triangles[i + 3] });
    this._props = new Map();
    const j = obj.joints;
    for (let k = 0; k < j.spring.length; ++k) {
      const p = { id: j.edges[3 * k + 2], spring: j.spring[k], damping: j.damping[k], assignment: j.assignment[k] };
      if (j.maxTorque && j.maxTorque[k] !== null && j.maxTorque[k] !== undefined) p.maxTorque = j.maxTorque[k];
      this._props.set(edgeKey(j.edges[3 * k], j.edges[3 * k + 1]), p);
    }
    const ph = obj.physics ?? {};
    this.physics = { density: ph.density ?? null, gravity: ph.gravity ? [...ph.gravity] : null, fixedActor: ph.fixedActor ?? null };
    this._nextJointId = obj.nextJointId;
    this.warnings = [];
    this._commit();
    return this;
  }

  /** An independent copy. */
  clone() {
    return PatternModel.fromSnapshot(this.snapshot());
  }

  // ------------------------------------------------------------------ queries

  /** Edges with their triangles (1 or 2, more in invalid input) and kind: 'boundary', 'joint' or 'internal'. Cached; do not mutate. */
  edges() {
    return this._topology().edges;
  }

  /**
   * The joints in ID order: each an edge shared by two different actors, or a run of such edges
   * along one line between the same two actors (`keys` lists its edges, `key` is the first; `a`,
   * `b` and `va`, `vb` are the run's ends). Cached; do not mutate.
   */
  joints() {
    if (this._joints && this._joints.version === this._version) return this._joints.list;
    const runs = new Map();
    for (const e of this.edges()) {
      if (e.kind !== 'joint') continue;
      const p = this._props.get(e.key);
      const run = runs.get(p.id);
      if (run) run.edges.push(e);
      else runs.set(p.id, { p, edges: [e] });
    }
    const list = [];
    for (const [id, { p, edges }] of runs) {
      let [va, vb] = runEnds(edges);
      const A = this.vertices[va], B = this.vertices[vb];
      // Coordinates in (x, y) order, not index order: the text then survives a read that renumbers.
      if (B.x < A.x || (B.x === A.x && B.y < A.y)) [va, vb] = [vb, va];
      const actors = actorsOf(this, edges[0]);
      list.push({ id, a: { ...this.vertices[va] }, b: { ...this.vertices[vb] }, va, vb, actors,
        spring: p.spring, damping: p.damping, assignment: p.assignment, maxTorque: p.maxTorque ?? null, key: edges[0].key, keys: edges.map((e) => e.key) });
    }
    list.sort((x, y) => x.id - y.id);
    this._joints = { version: this._version, list, byId: new Map(list.map((j) => [j.id, j])) };
    return list;
  }

  /** The edge between vertices i and j (an element of edges()), or null. */
  edgeBetween(i, j) {
    return this._topology().byKey.get(edgeKey(i, j)) ?? null;
  }

  /** The joint on the edge between vertices i and j, or null. */
  jointOnEdge(i, j) {
    const e = this.edgeBetween(i, j);
    return e && e.kind === 'joint' ? this.joint(this._props.get(e.key).id) : null;
  }

  /** The joint with this ID, or null. */
  joint(id) {
    this.joints();
    return this._joints.byId.get(id) ?? null;
  }

  /** Set a joint's spring, damping, assignment ('M', 'V', 'F' or 'U') and/or motor torque limit
   * (`maxTorque`, N·m, positive; null: none, the run's --max-torque). */
  setJoint(id, { spring, damping, assignment, maxTorque } = {}) {
    const j = this.joint(id);
    if (!j) throw new Error(`no joint ${id}`);
    if (spring !== undefined && !(Number.isFinite(spring) && spring >= 0)) throw new Error('spring constant must be finite and non-negative');
    if (damping !== undefined && !(Number.isFinite(damping) && damping >= 0)) throw new Error('damping constant must be finite and non-negative');
    if (assignment !== undefined && !ASSIGNMENTS.has(assignment)) throw new Error('assignment must be M, V, F or U');
    if (maxTorque !== undefined && maxTorque !== null && !(Number.isFinite(maxTorque) && maxTorque > 0))
      throw new Error('maximum torque must be positive and finite (N·m)');
    for (const key of j.keys) {
      const p = this._props.get(key);
      if (spring !== undefined) p.spring = spring;
      if (damping !== undefined) p.damping = damping;
      if (assignment !== undefined) p.assignment = assignment;
      if (maxTorque === null) delete p.maxTorque;
      else if (maxTorque !== undefined) p.maxTorque = maxTorque;
    }
    this._version++;
    return this.joint(id);
  }

  /** Sorted actor IDs. */
  actors() {
    return [...this._trianglesByActor().keys()].sort((a, b) => a - b);
  }

  /** Indices of the triangles of an actor. */
  trianglesOf(actorId) {
    return this._trianglesByActor().get(actorId) ?? [];
  }

  /** The smallest actor ID above every one in use (1 for an empty model). */
  nextActorId() {
    let max = 0;
    for (const t of this.triangles) if (t.actor > max) max = t.actor;
    return max + 1;
  }

  /** Distance between vertices i and j. */
  length(i, j) {
    return dist(this.vertices[i], this.vertices[j]);
  }

  /** The angle i-j-k at vertex j, in degrees (0 to 180). */
  angleAt(i, j, k) {
    const a = this.vertices[i], b = this.vertices[j], c = this.vertices[k];
    const ux = a.x - b.x, uy = a.y - b.y, wx = c.x - b.x, wy = c.y - b.y;
    return (Math.atan2(Math.abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180) / Math.PI;
  }

  /** Area of triangle t (positive). */
  triangleArea(t) {
    const [a, b, c] = this.triangles[t].v.map((i) => this.vertices[i]);
    return Math.abs(cross3(a, b, c)) / 2;
  }

  /** {min: {x, y}, max: {x, y}, minX, minY, maxX, maxY} of the vertices triangles use, or null when there are none. */
  bounds() {
    const b = boxOf(this._usedPoints());
    return b && { min: { x: b.minX, y: b.minY }, max: { x: b.maxX, y: b.maxY }, ...b };
  }

  /** The vertex-merge tolerance now (1e-9 × bounding-box diagonal). */
  tolerance() {
    return toleranceOf(boxOf(this._usedPoints()));
  }

  /** Index of the nearest vertex within radius of p, or -1. */
  nearestVertex(p, radius = Infinity) {
    let best = -1, bestD = radius;
    const used = this._usedVertices();
    for (let i = 0; i < this.vertices.length; ++i) {
      if (!used[i]) continue;
      const d = dist(this.vertices[i], p);
      if (d <= bestD) {
        best = i;
        bestD = d;
      }
    }
    return best;
  }

  /** The nearest edge within radius of p: {i, j, t, distance} (t along i→j), or null. */
  nearestEdge(p, radius = Infinity) {
    let best = null;
    for (const e of this.edges()) {
      const a = this.vertices[e.i], b = this.vertices[e.j];
      const dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const t = len2 > 0 ? Math.min(1, Math.max(0, ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2)) : 0;
      const d = Math.hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
      if (d <= radius && (!best || d < best.distance)) best = { i: e.i, j: e.j, t, distance: d };
    }
    return best;
  }

  /** Index of a triangle containing p (boundary included), or -1. */
  triangleAt(p) {
    for (let t = 0; t < this.triangles.length; ++t) {
      const [a, b, c] = this.triangles[t].v.map((i) => this.vertices[i]);
      const s = Math.sign(cross3(a, b, c));
      const eps = 1e-12 * (Math.abs(a.x) + Math.abs(a.y) + 1);
      if (cross3(a, b, p) * s >= -eps && cross3(b, c, p) * s >= -eps && cross3(c, a, p) * s >= -eps) return t;
    }
    return -1;
  }

  // ------------------------------------------------------------------ internals

  _commit() {
    this._version++;
    this._topo = null;
    this._joints = null;
    this._byActor = null;
    this._used = null;
    this._syncJoints();
  }

  _takeJointId() {
    if (this._nextJointId > INT_MAX) {
      // Past foldkit's integer range, reuse the smallest free positive ID instead.
      const used = new Set([...this._props.values()].map((p) => p.id));
      let id = 1;
      while (used.has(id)) ++id;
      return id;
    }
    return this._nextJointId++;
  }

  // Forget properties of edges that no longer exist. A new shared edge that continues a crease
  // (along its line, between the same two actors) joins it, the others get the next IDs. A run
  // an edit broke (no longer one line between two actors) splits: its first part keeps the ID.
  _syncJoints() {
    const topo = this._topology();
    for (const key of this._props.keys()) if (!topo.byKey.has(key)) this._props.delete(key);
    const shared = topo.edges.filter((e) => e.kind === 'joint');
    const at = new Map();
    for (const e of shared) for (const v of [e.i, e.j]) (at.get(v) ?? at.set(v, []).get(v)).push(e);
    const fresh = shared.filter((e) => !this._props.has(e.key));
    const tol = fresh.length ? this.tolerance() : 0;
    while (fresh.length) {
      let joined = true;
      while (joined) {
        joined = false;
        for (let k = fresh.length - 1; k >= 0; --k) {
          const p = continuedCrease(this, fresh[k], at, tol);
          if (!p) continue;
          this._props.set(fresh[k].key, p);
          fresh.splice(k, 1);
          joined = true;
        }
      }
      if (fresh.length) this._props.set(fresh.shift().key, { id: this._takeJointId(), ...JOINT_DEFAULTS });
    }
    const byId = new Map();
    for (const e of shared) {
      const id = this._props.get(e.key).id;
      (byId.get(id) ?? byId.set(id, []).get(id)).push(e);
    }
    let runTol = tol;
    for (const edges of byId.values()) {
      if (edges.length === 1) continue;
      if (!runTol) runTol = this.tolerance();
      const runs = splitRuns(this, edges, runTol);
      runs.forEach((run, k) => {
        const base = this._props.get(run[0].key);
        const p = k === 0 ? base : { ...base, id: this._takeJointId() };
        for (const e of run) this._props.set(e.key, p);
      });
    }
  }

  _topology() {
    if (this._topo && this._topo.version === this._version) return this._topo;
    const byKey = new Map(), edges = [];
    this.triangles.forEach((tri, t) => {
      for (let k = 0; k < 3; ++k) {
        const a = tri.v[k], b = tri.v[(k + 1) % 3], key = edgeKey(a, b);
        let e = byKey.get(key);
        if (!e) {
          e = { i: Math.min(a, b), j: Math.max(a, b), key, triangles: [], kind: 'boundary' };
          byKey.set(key, e);
          edges.push(e);
        }
        e.triangles.push(t);
      }
    });
    for (const e of edges) {
      if (e.triangles.length !== 2) continue;
      e.kind = this.triangles[e.triangles[0]].actor !== this.triangles[e.triangles[1]].actor ? 'joint' : 'internal';
    }
    this._topo = { version: this._version, edges, byKey };
    return this._topo;
  }

  _trianglesByActor() {
    if (this._byActor && this._byActor.version === this._version) return this._byActor.map;
    const map = new Map();
    this.triangles.forEach((t, i) => {
      const list = map.get(t.actor);
      if (list) list.push(i);
      else map.set(t.actor, [i]);
    });
    this._byActor = { version: this._version, map };
    return map;
  }

  _usedVertices() {
    if (this._used && this._used.version === this._version && this._used.flags.length === this.vertices.length) return this._used.flags;
    const flags = new Uint8Array(this.vertices.length);
    for (const t of this.triangles) for (const i of t.v) flags[i] = 1;
    this._used = { version: this._version, flags };
    return flags;
  }

  _usedPoints() {
    const used = this._usedVertices();
    return this.vertices.filter((_, i) => used[i]);
  }
}
