// The 2D editor's tools: what a press, drag and release do in each of them (select, placing
// triangles, polygons and lattices, move, rotate, scale, mirror, merge, split, measure).
// Editor2D's input dispatches to _down_TOOL, _move_TOOL and _up_TOOL; the methods are
// written as a class only to hold them: editor2d.js copies them onto Editor2D.prototype, so
// `this` is always the Editor2D.
import { PICK_VERTEX_PX, PICK_EDGE_PX, SNAP_PX } from './editor_selection.js';
import { addCircular, addGrid, addPolygon, addTriangle, mergeVertices, moveVertices, splitEdge, transformVertices } from './model_edits.js';

/** The tools setTool() accepts. */
export const TOOLS = ['select', 'triangle', 'polygon', 'grid', 'circular', 'move', 'rotate', 'scale', 'mirror', 'merge', 'split', 'measure'];

const DRAG_PX = 4;

/** The status line of each tool while it is chosen. */
export const HINTS = {
  select: 'Select: click a joint, triangle or vertex (Shift adds), double-click selects an actor, drag a box',
  triangle: 'Triangle: click three corners',
  polygon: 'Polygon: click corners; double-click, Enter or the first corner closes it, Escape cancels, Backspace undoes a corner',
  grid: 'Grid: drag a rectangle',
  circular: 'Circular lattice: press at the centre and drag out the radius',
  move: 'Move: drag the selection (or the item under the pointer)',
  rotate: 'Rotate: drag around the selection\'s centre (Shift: 15° steps)',
  scale: 'Scale: drag away from or towards the selection\'s centre (Shift: 0.1 steps)',
  mirror: 'Mirror: click to flip the selection left–right (Shift: top–bottom)',
  merge: 'Merge: click the vertex to move, then the vertex to merge it into',
  split: 'Split: click an edge where the new vertex goes',
  measure: 'Measure: click two vertices for a length, a third for the angle at the second',
};

function fmt(x) {
  return String(Number(x.toPrecision(6)));
}

/** The tool methods of Editor2D (see editor2d.js); not to be constructed. */
export class EditorTools {
  // ------------------------------------------------------------------ tools: select

  _down_select(s, e) {
    this._action = { kind: 'press', sx: s.x, sy: s.y, x: s.x, y: s.y, shift: e.shiftKey, hit: this._hitTest(s) };
  }

  _move_select(s) {
    const a = this._action;
    a.x = s.x;
    a.y = s.y;
    if (a.kind === 'press' && Math.hypot(s.x - a.sx, s.y - a.sy) > DRAG_PX) a.kind = 'box';
    this._requestDraw();
  }

  _up_select() {
    const a = this._action;
    this._action = null;
    if (a.kind === 'press') return this._toggleHit(a.hit, a.shift);
    const x0 = Math.min(a.sx, a.x), x1 = Math.max(a.sx, a.x), y0 = Math.min(a.sy, a.y), y1 = Math.max(a.sy, a.y);
    const m = this._model;
    const inside = new Uint8Array(m.vertices.length);
    m.vertices.forEach((p, i) => {
      const q = this._toScreen(p);
      inside[i] = q.x >= x0 && q.x <= x1 && q.y >= y0 && q.y <= y1 ? 1 : 0;
    });
    const sel = this._selectionCopy(a.shift);
    const used = new Set(m.triangles.flatMap((t) => t.v));
    for (const i of used) if (inside[i]) sel.vertices.push(i);
    m.triangles.forEach((t, k) => {
      if (inside[t.v[0]] && inside[t.v[1]] && inside[t.v[2]]) sel.triangles.push(k);
    });
    for (const j of m.joints()) if (inside[j.va] && inside[j.vb]) sel.joints.push(j.id);
    this._setSelection(sel);
  }

  // ------------------------------------------------------------------ tools: placing

  _down_triangle(s) {
    const p = this._snapped(this._toModel(s.x, s.y));
    const last = this._points[this._points.length - 1];
    if (last && Math.hypot(last.x - p.x, last.y - p.y) * this.view.scale < 2) return;
    this._points.push({ x: p.x, y: p.y });
    if (this._points.length < 3) return this._requestDraw();
    const [a, b, c] = this._points;
    this._points = [];
    this._tryEdit('Triangle', () => addTriangle(this._model, a, b, c), (tris) => this._setSelection({ triangles: tris }));
  }

  _down_polygon(s) {
    const p = this._snapped(this._toModel(s.x, s.y));
    const pts = this._points;
    const near = (q) => q && Math.hypot(q.x - p.x, q.y - p.y) * this.view.scale < SNAP_PX;
    if (pts.length >= 3 && near(pts[0])) return this._closePolygon();
    // The second click of a double-click lands on the corner just placed.
    if (pts.length && Math.hypot(pts[pts.length - 1].x - p.x, pts[pts.length - 1].y - p.y) * this.view.scale < 3) return;
    pts.push({ x: p.x, y: p.y });
    this._requestDraw();
  }

  _closePolygon() {
    const pts = this._points;
    this._points = [];
    if (pts.length < 3) {
      this._requestDraw();
      return this.onStatus('Polygon: place at least three corners');
    }
    this._tryEdit('Polygon', () => addPolygon(this._model, pts), (tris) => this._setSelection({ triangles: tris }));
  }

  _down_grid(s) {
    const p = this._snapped(this._toModel(s.x, s.y));
    this._action = { kind: 'grid', from: p, to: p };
  }

  _move_grid(s) {
    this._action.to = this._snapped(this._toModel(s.x, s.y));
    const { from, to } = this._action;
    this.onStatus(`Grid ${fmt(Math.abs(to.x - from.x))} × ${fmt(Math.abs(to.y - from.y))}`);
    this._requestDraw();
  }

  _up_grid(s) {
    this._move_grid(s);
    const { from, to } = this._action;
    this._action = null;
    const w = to.x - from.x, h = to.y - from.y;
    if (Math.abs(w) * this.view.scale < 3 || Math.abs(h) * this.view.scale < 3) {
      this._requestDraw();
      return this.onStatus(HINTS.grid);
    }
    const o = this.options;
    const spec = { x: Math.min(from.x, to.x), y: Math.min(from.y, to.y), w: Math.abs(w), h: Math.abs(h),
      cols: Math.max(1, Math.round(o.cols)), rows: Math.max(1, Math.round(o.rows)), diagonals: o.diagonals || 'none' };
    this._tryEdit('Grid', () => addGrid(this._model, spec), (tris) => this._setSelection({ triangles: tris }));
  }

  _down_circular(s) {
    const c = this._snapped(this._toModel(s.x, s.y));
    this._action = { kind: 'circular', centre: c, radius: 0 };
  }

  _move_circular(s) {
    const a = this._action;
    const p = this._snapped(this._toModel(s.x, s.y));
    a.radius = Math.hypot(p.x - a.centre.x, p.y - a.centre.y);
    this.onStatus(`Radius ${fmt(a.radius)}`);
    this._requestDraw();
  }

  _up_circular(s) {
    this._move_circular(s);
    const { centre, radius } = this._action;
    this._action = null;
    if (radius * this.view.scale < 3) {
      this._requestDraw();
      return this.onStatus(HINTS.circular);
    }
    const o = this.options;
    const spec = { x: centre.x, y: centre.y, radius, rings: Math.max(1, Math.round(o.rings)), spokes: Math.max(3, Math.round(o.spokes)) };
    this._tryEdit('Circular lattice', () => addCircular(this._model, spec), (tris) => this._setSelection({ triangles: tris }));
  }

  // Runs a model edit; a refused one (bad polygon…) is reported, not thrown.
  _tryEdit(what, edit, after = () => {}) {
    let result;
    try {
      result = edit();
    } catch (err) {
      this._requestDraw();
      this.onStatus(`${what}: ${err.message}`);
      return;
    }
    after(result);
    this._edited();
    this.onStatus(`${what} added`);
  }

  // ------------------------------------------------------------------ tools: move, rotate, scale, mirror

  // Starts dragging the selection's vertices; a press on an unselected item selects it first.
  _beginVertexDrag(s, e, kind) {
    const hit = this._hitTest(s);
    if (kind === 'move' && hit && hit.kind !== 'edge' && !this._hitInSelection(hit)) this._toggleHit(hit, e.shiftKey);
    const verts = this._selectedVertices();
    if (!verts.length) {
      this.onStatus(`${kind[0].toUpperCase()}${kind.slice(1)}: select something first`);
      return null;
    }
    const originals = new Float64Array(verts.length * 2);
    verts.forEach((i, k) => {
      originals[2 * k] = this._model.vertices[i].x;
      originals[2 * k + 1] = this._model.vertices[i].y;
    });
    const start = this._toModel(s.x, s.y);
    this._action = { kind, verts, originals, start, centre: this._centreOf(verts), moving: new Set(verts) };
    return this._action;
  }

  _restorePositions(a) {
    a.verts.forEach((i, k) => {
      const p = this._model.vertices[i];
      if (!p) return;
      p.x = a.originals[2 * k];
      p.y = a.originals[2 * k + 1];
    });
  }

  _down_move(s, e) {
    const a = this._beginVertexDrag(s, e, 'move');
    if (!a) return;
    // The grabbed vertex (or the selected vertex nearest the pointer) is what snaps.
    let best = 0, bestD = Infinity;
    a.verts.forEach((i, k) => {
      const d = Math.hypot(a.originals[2 * k] - a.start.x, a.originals[2 * k + 1] - a.start.y);
      if (d < bestD) {
        best = k;
        bestD = d;
      }
    });
    a.anchor = { x: a.originals[2 * best], y: a.originals[2 * best + 1] };
    a.dx = 0;
    a.dy = 0;
  }

  _move_move(s) {
    const a = this._action;
    const p = this._toModel(s.x, s.y);
    this._restorePositions(a);
    const target = { x: a.anchor.x + p.x - a.start.x, y: a.anchor.y + p.y - a.start.y };
    const snapped = this._snapped(target, a.moving);
    a.snapped = snapped;
    a.dx = snapped.x - a.anchor.x;
    a.dy = snapped.y - a.anchor.y;
    for (const i of a.verts) {
      this._model.vertices[i].x += a.dx;
      this._model.vertices[i].y += a.dy;
    }
    this.onStatus(`Move by (${fmt(a.dx)}, ${fmt(a.dy)})`);
    this._requestDraw();
  }

  _up_move(s) {
    this._move_move(s);
    const a = this._action;
    this._action = null;
    this._restorePositions(a);
    if (a.dx === 0 && a.dy === 0) return this._requestDraw();
    this._applyVertexEdit(a.verts, () => moveVertices(this._model, a.verts, a.dx, a.dy));
  }

  _down_rotate(s, e) {
    const a = this._beginVertexDrag(s, e, 'rotate');
    if (a) a.angle = 0;
  }

  _move_rotate(s, e) {
    const a = this._action;
    const p = this._toModel(s.x, s.y), c = a.centre;
    let angle = Math.atan2(p.y - c.y, p.x - c.x) - Math.atan2(a.start.y - c.y, a.start.x - c.x);
    if (e.shiftKey) angle = Math.round(angle / (Math.PI / 12)) * (Math.PI / 12);
    a.angle = angle;
    this._previewTransform(a, { rotate: angle, scale: 1 });
    this.onStatus(`Rotate by ${fmt((angle * 180) / Math.PI)}°`);
  }

  _up_rotate(s, e) {
    this._move_rotate(s, e);
    const a = this._action;
    this._action = null;
    this._restorePositions(a);
    if (!a.angle) return this._requestDraw();
    this._applyVertexEdit(a.verts, () => transformVertices(this._model, a.verts, { rotate: a.angle, about: a.centre }));
  }

  _down_scale(s, e) {
    const a = this._beginVertexDrag(s, e, 'scale');
    if (a) a.factor = 1;
  }

  _move_scale(s, e) {
    const a = this._action;
    const p = this._toModel(s.x, s.y), c = a.centre;
    const d0 = Math.hypot(a.start.x - c.x, a.start.y - c.y);
    let factor = d0 * this.view.scale > 2 ? Math.hypot(p.x - c.x, p.y - c.y) / d0 : 1;
    if (e.shiftKey) factor = Math.round(factor * 10) / 10;
    if (!(factor > 1e-6)) factor = 1e-6;
    a.factor = factor;
    this._previewTransform(a, { rotate: 0, scale: factor });
    this.onStatus(`Scale by ${fmt(factor)}`);
  }

  _up_scale(s, e) {
    this._move_scale(s, e);
    const a = this._action;
    this._action = null;
    this._restorePositions(a);
    if (a.factor === 1) return this._requestDraw();
    this._applyVertexEdit(a.verts, () => transformVertices(this._model, a.verts, { scale: a.factor, about: a.centre }));
  }

  _previewTransform(a, { rotate, scale }) {
    const c = a.centre, cos = Math.cos(rotate) * scale, sin = Math.sin(rotate) * scale;
    a.verts.forEach((i, k) => {
      const x = a.originals[2 * k] - c.x, y = a.originals[2 * k + 1] - c.y;
      this._model.vertices[i].x = c.x + cos * x - sin * y;
      this._model.vertices[i].y = c.y + sin * x + cos * y;
    });
    this._requestDraw();
  }

  _down_mirror(s, e) {
    const axis = this.options.mirror === 'y' ? 'y' : 'x';
    this.applyTransform({ mirror: e.shiftKey ? (axis === 'x' ? 'y' : 'x') : axis });
  }

  // ------------------------------------------------------------------ tools: merge, split, measure

  _pickVertex(s) {
    return this._model.nearestVertex(this._toModel(s.x, s.y), (PICK_VERTEX_PX + 3) / this.view.scale);
  }

  _down_merge(s) {
    const v = this._pickVertex(s);
    if (v < 0) return this.onStatus('Merge: click a vertex');
    if (!this._picked.length) {
      this._picked = [v];
      this._requestDraw();
      return this.onStatus('Merge: now click the vertex to merge it into');
    }
    const [from] = this._picked;
    this._picked = [];
    if (from === v) return this._requestDraw();
    const kept = mergeVertices(this._model, v, from);
    this._setSelection({ vertices: [kept] });
    this._edited();
    this.onStatus('Merged two vertices');
  }

  _down_split(s) {
    const m = this._model;
    const p = this._toModel(s.x, s.y);
    const e = m.nearestEdge(p, (PICK_EDGE_PX + 3) / this.view.scale);
    if (!e) return this.onStatus('Split: click an edge');
    const a = m.vertices[e.i], b = m.vertices[e.j];
    const q = this._snapped(p);
    const dx = b.x - a.x, dy = b.y - a.y;
    let t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy);
    const off = Math.abs((q.x - a.x) * dy - (q.y - a.y) * dx) / Math.hypot(dx, dy);
    if (!(t > 0 && t < 1) || off * this.view.scale > PICK_EDGE_PX + 3) t = e.t;
    if (!(t > 0 && t < 1)) return this.onStatus('Split: click inside an edge, not at its end');
    const mid = splitEdge(m, e.i, e.j, t);
    this._setSelection({ vertices: [mid] });
    this._edited();
    this.onStatus(`Split the edge at ${fmt(t)}`);
  }

  _down_measure(s) {
    const v = this._pickVertex(s);
    if (v < 0) return this.onStatus('Measure: click a vertex');
    if (this._picked.length >= 3) this._picked = [];
    this._picked.push(v);
    const [i, j, k] = this._picked;
    const m = this._model;
    if (this._picked.length === 1) this.onStatus('Measure: click a second vertex');
    else if (this._picked.length === 2) this.onStatus(`Length ${fmt(m.length(i, j))}`);
    else this.onStatus(`Length ${fmt(m.length(i, j))}, ${fmt(m.length(j, k))}; angle ${fmt(m.angleAt(i, j, k))}°`);
    this._requestDraw();
  }
}
