// PMML reading and writing of the editor's PatternModel (PatternModel.fromPMML and toPMML call
// these): welding the file's triangles, tracing each joint along the edges it covers, and the
// file's warnings; writing actors and joints in ID order. Part of model.js, split by concern
// (it reaches into the model's internals: _props, _commit, _takeJointId, …).
import { dist, boxOf, toleranceOf, Welder } from './polygon.js';
import { edgeKey } from './edge_key.js';
import { readPMML, formatNumber, escapeXml } from './pmml.js';
import { PatternModel } from './model.js';

/** A PatternModel of PMML text; throws Error('LINE: message') on malformed input. */
export function readModel(text) {
  const spec = readPMML(text);
  const model = new PatternModel({ title: spec.title });
  model.physics = { ...spec.physics };
  const seenActor = new Map(), seenJoint = new Map();
  for (const a of spec.actors) {
    if (seenActor.has(a.id)) model.warnings.push(`${a.line}: duplicate actor ID ${a.id} (also at line ${seenActor.get(a.id)})`);
    else seenActor.set(a.id, a.line);
  }
  const corners = [];
  for (const a of spec.actors) for (const t of a.triangles) for (let k = 0; k < 6; k += 2) corners.push({ x: t.c[k], y: t.c[k + 1] });
  const tol = toleranceOf(boxOf(corners));
  const welder = new Welder(model.vertices, tol);
  for (const a of spec.actors)
    for (const t of a.triangles) {
      const v = [0, 2, 4].map((k) => welder.insert({ x: t.c[k], y: t.c[k + 1] }));
      if (v[0] === v[1] || v[1] === v[2] || v[0] === v[2]) model.warnings.push(`${t.line}: degenerate triangle dropped`);
      else model.triangles.push({ v, actor: a.id });
    }
  const topo = model._topology();
  const renamed = [];
  for (const j of spec.joints) {
    const duplicate = seenJoint.has(j.id);
    if (duplicate) model.warnings.push(`${j.line}: duplicate joint ID ${j.id} (also at line ${seenJoint.get(j.id)}): given a new ID`);
    const chain = traceSegment(model, welder, topo, { x: j.coords[0], y: j.coords[1] }, { x: j.coords[2], y: j.coords[3] });
    if (!chain) {
      model.warnings.push(`${j.line}: joint ${j.id} does not lie on edges of the triangles: dropped`);
      continue;
    }
    // Every edge of the joint's segment shares one properties object: one crease, one ID.
    const props = { id: duplicate ? 0 : j.id, spring: j.spring, damping: j.damping, assignment: j.assignment };
    if (j.maxTorque !== undefined) props.maxTorque = j.maxTorque;
    for (let k = 0; k + 1 < chain.length; ++k) {
      const key = edgeKey(chain[k], chain[k + 1]);
      if (model._props.has(key)) model.warnings.push(`${j.line}: joint ${j.id} covers an edge another joint already covers`);
      else model._props.set(key, props);
    }
    if (duplicate) renamed.push(props);
    else {
      model._nextJointId = Math.max(model._nextJointId, j.id + 1);
      seenJoint.set(j.id, j.line);
    }
  }
  // A duplicate ID is replaced once the file's IDs are known.
  for (const props of renamed) props.id = model._takeJointId();
  model._commit();
  return model;
}

/** PMML text of `model`: the title, foldkit's physics extensions where set, actors in ID order
 * with their triangles, then the joints in ID order (each with its MaxTorque where set). */
export function writeModel(model) {
  const out = ['<?xml version="1.0" encoding="UTF-8"?>', '<PMML>'];
  if (model.title) out.push(`  <Title>${escapeXml(model.title)}</Title>`);
  // foldkit's extensions, after the title and only when set, as foldkit writes them: a plain
  // PMML writes back as the paper's Table 1.
  const { density, gravity, fixedActor } = model.physics;
  if (density !== null) out.push(`  <Density>${formatNumber(density, 'density')}</Density>`);
  if (gravity !== null) out.push(`  <Gravity>${gravity.map((g) => formatNumber(g, 'gravity')).join(' ')}</Gravity>`);
  if (fixedActor !== null) out.push(`  <FixedActor>${fixedActor}</FixedActor>`);
  const byActor = model._trianglesByActor();
  for (const id of [...byActor.keys()].sort((a, b) => a - b)) {
    out.push('  <Actor>', `    <ID>${id}</ID>`);
    for (const t of byActor.get(id)) {
      const c = model.triangles[t].v.map((i) => model.vertices[i]);
      const nums = c.flatMap((p) => [p.x, p.y]).map((n) => formatNumber(n, `actor ${id} triangle coordinate`));
      out.push(`    <Triangle>${nums.join(' ')}</Triangle>`);
    }
    out.push('  </Actor>');
  }
  for (const j of model.joints()) {
    const f = (n, what) => formatNumber(n, `joint ${j.id} ${what}`);
    out.push('  <Joint>', `    <ID>${j.id}</ID>`,
      `    <Coords>${[j.a.x, j.a.y, j.b.x, j.b.y].map((n) => f(n, 'coordinate')).join(' ')}</Coords>`,
      `    <ActorIDs>${j.actors[0]} ${j.actors[1]}</ActorIDs>`,
      `    <SpringConst>${f(j.spring, 'spring constant')}</SpringConst>`,
      `    <DampConst>${f(j.damping, 'damping constant')}</DampConst>`);
    if (j.assignment !== 'U') out.push(`    <Assignment>${j.assignment}</Assignment>`);
    if (j.maxTorque !== null) out.push(`    <MaxTorque>${f(j.maxTorque, 'maximum torque')}</MaxTorque>`);
    out.push('  </Joint>');
  }
  out.push('</PMML>', '');
  return out.join('\n');
}

// Follows edges along a joint's segment from one end to the other: a joint may span several
// collinear edges when a vertex lies on it.
function traceSegment(model, welder, topo, p, q) {
  const v0 = welder.find(p), v1 = welder.find(q);
  if (v0 < 0 || v1 < 0 || v0 === v1) return null;
  if (topo.byKey.has(edgeKey(v0, v1))) return [v0, v1];
  if (!topo.neighbours) {
    topo.neighbours = new Map();
    for (const e of topo.edges) {
      for (const [a, b] of [[e.i, e.j], [e.j, e.i]]) {
        if (!topo.neighbours.has(a)) topo.neighbours.set(a, []);
        topo.neighbours.get(a).push(b);
      }
    }
  }
  const o = model.vertices[v0], end = model.vertices[v1];
  const len = dist(o, end), dx = (end.x - o.x) / len, dy = (end.y - o.y) / len, tol = welder.tol;
  const chain = [v0];
  let cur = v0, reached = 0;
  while (cur !== v1) {
    let next = -1, nextAlong = Infinity;
    for (const w of topo.neighbours.get(cur) ?? []) {
      const rx = model.vertices[w].x - o.x, ry = model.vertices[w].y - o.y;
      const along = rx * dx + ry * dy;
      if (Math.abs(dx * ry - dy * rx) <= tol && along > reached + tol && along <= len + tol && along < nextAlong) {
        next = w;
        nextAlong = along;
      }
    }
    if (next < 0) return null;
    chain.push(next);
    cur = next;
    reached = nextAlong;
  }
  return chain;
}
