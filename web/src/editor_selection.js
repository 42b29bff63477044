// The 2D editor's selection and what lies under its pointer: selection bookkeeping, hover,
// snapping and hit testing. These are Editor2D's methods (see editor2d.js), written as a class
// only to hold them: editor2d.js copies them onto Editor2D.prototype, so `this` is always the
// Editor2D.
import { snapPoint } from './snap.js';

/** How near (CSS pixels) the pointer must come to a vertex to pick it. */
export const PICK_VERTEX_PX = 7;
/** How near (CSS pixels) the pointer must come to an edge to pick it. */
export const PICK_EDGE_PX = 5;
/** How near (CSS pixels) a placed point snaps to a target, and a click closes a polygon at its first corner. */
export const SNAP_PX = 10;

/** The selection and hit-testing methods of Editor2D (see editor2d.js); not to be constructed. */
export class EditorSelection {
  // ------------------------------------------------------------------ selection

  _selectedTriangles() {
    return [...this._sel.triangles].filter((t) => t < this._model.triangles.length);
  }

  _selectedVertices() {
    const set = new Set(this._sel.vertices);
    for (const t of this._sel.triangles) for (const i of this._model.triangles[t]?.v ?? []) set.add(i);
    for (const id of this._sel.joints) {
      const j = this._model.joint(id);
      if (j) set.add(j.va).add(j.vb);
    }
    return [...set].filter((i) => i < this._model.vertices.length);
  }

  _centreOf(verts) {
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (const i of verts) {
      const p = this._model.vertices[i];
      minX = Math.min(minX, p.x);
      maxX = Math.max(maxX, p.x);
      minY = Math.min(minY, p.y);
      maxY = Math.max(maxY, p.y);
    }
    return { x: (minX + maxX) / 2, y: (minY + maxY) / 2 };
  }

  _setSelection({ joints = [], triangles = [], vertices = [] } = {}) {
    const before = this._selectionKey();
    this._sel = { joints: new Set(joints), triangles: new Set(triangles), vertices: new Set(vertices) };
    this._pruneSelection();
    this._requestDraw();
    if (this._selectionKey() !== before) this.onSelect(this.selection);
  }

  _selectionKey() {
    const s = this._sel;
    return [[...s.joints].sort(), [...s.triangles].sort(), [...s.vertices].sort()].join('|');
  }

  _pruneSelection() {
    const m = this._model;
    for (const id of this._sel.joints) if (!m.joint(id)) this._sel.joints.delete(id);
    for (const t of this._sel.triangles) if (t >= m.triangles.length) this._sel.triangles.delete(t);
    for (const i of this._sel.vertices) if (i >= m.vertices.length) this._sel.vertices.delete(i);
  }

  // ------------------------------------------------------------------ hover and hit testing

  _hoverAt(s, e) {
    const p = this._toModel(s.x, s.y);
    const placing = ['triangle', 'polygon', 'grid', 'circular', 'split'].includes(this.tool);
    const hover = { s, p, snapped: placing ? this._snapped(p) : null, hit: placing ? null : this._hitTest(s, e) };
    const key = JSON.stringify([hover.snapped, hover.hit]);
    const rubberBand = this._points.length > 0;
    const changed = !this._hover || this._hover.key !== key;
    hover.key = key;
    this._hover = hover;
    // Redraw only when the highlight, the snap marker or a rubber band follows the pointer.
    if (changed || rubberBand) this._requestDraw();
  }

  _snapped(p, exclude = null) {
    const r = SNAP_PX / this.view.scale;
    const q = snapPoint(p, this._snap, this._model, r, exclude);
    return q === p ? { x: p.x, y: p.y, kind: null } : q;
  }

  // What lies under the pointer: a vertex, else a joint, else a triangle (null when nothing).
  _hitTest(s) {
    const m = this._model;
    const p = this._toModel(s.x, s.y);
    const v = m.nearestVertex(p, PICK_VERTEX_PX / this.view.scale);
    if (v >= 0) return { kind: 'vertex', index: v };
    const e = m.nearestEdge(p, PICK_EDGE_PX / this.view.scale);
    if (e) {
      const j = m.jointOnEdge(e.i, e.j);
      if (j) return { kind: 'joint', id: j.id };
    }
    const t = m.triangleAt(p);
    if (t >= 0) return { kind: 'triangle', index: t };
    return e ? { kind: 'edge', i: e.i, j: e.j } : null;
  }

  _toggleHit(hit, add) {
    const sel = this._selectionCopy(add);
    if (hit) {
      const which = { vertex: [sel.vertices, hit.index], joint: [sel.joints, hit.id], triangle: [sel.triangles, hit.index] };
      const [list, item] = which[hit.kind] ?? [null];
      if (list) {
        const at = list.indexOf(item);
        if (at >= 0 && add) list.splice(at, 1);
        else if (at < 0) list.push(item);
      }
    }
    this._setSelection(sel);
  }

  // The selection as lists to extend (keep = true), or empty lists.
  _selectionCopy(keep) {
    const s = this._sel;
    return keep ? { joints: [...s.joints], triangles: [...s.triangles], vertices: [...s.vertices] } : { joints: [], triangles: [], vertices: [] };
  }

  // Whether a hit item is part of the selection: a vertex or a crease of a selected triangle is.
  _hitInSelection(hit) {
    const verts = new Set(this._selectedVertices());
    const m = this._model;
    if (hit.kind === 'vertex') return verts.has(hit.index);
    if (hit.kind === 'joint') {
      const j = m.joint(hit.id);
      return this._sel.joints.has(hit.id) || Boolean(j && verts.has(j.va) && verts.has(j.vb));
    }
    if (hit.kind === 'triangle') return this._sel.triangles.has(hit.index) || m.triangles[hit.index].v.every((i) => verts.has(i));
    return false;
  }
}
