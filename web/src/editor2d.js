// The 2D crease-pattern editor: draws a PatternModel on a <canvas> with the Canvas 2D API and
// edits it with pointer, wheel and keyboard. Model y points up (as in PMML); the view flips it.
import { PatternModel, History, snapPoint } from './model.js';

/** The tools setTool() accepts. */
export const TOOLS = ['select', 'triangle', 'polygon', 'grid', 'circular', 'move', 'rotate', 'scale', 'mirror', 'merge', 'split', 'measure'];

// Origami Simulator's crease colours; facets in light pastels so the creases stand out.
const STYLE = {
  background: '#f2f2f2',
  gridLine: '#e2e2e2',
  boundary: '#000000',
  internal: '#cfcfcf',
  M: '#ff0000',
  V: '#0000ff',
  F: '#8c8c8c',
  U: '#8c8c8c',
  vertex: '#404040',
  selected: '#ff8c00',
  hover: 'rgba(255, 140, 0, 0.45)',
  problem: '#ff0000',
  snap: '#d4007a',
  preview: '#ff8c00',
};
const TINTS = ['#fbf3df', '#e4f1fb', '#e9f6e2', '#fbe8e8', '#efe8fa', '#e2f5f2', '#fbeedf', '#f3f7dc'];
const PICK_VERTEX_PX = 7;
const PICK_EDGE_PX = 5;
const SNAP_PX = 10;
const DRAG_PX = 4;
const FILL_BATCH = 256;
const STROKE_BATCH = 1024;

const HINTS = {
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

function isEditable(target) {
  if (!target || !target.tagName) return false;
  const tag = target.tagName.toLowerCase();
  return tag === 'input' || tag === 'textarea' || tag === 'select' || target.isContentEditable;
}

/** The 2D editor on a canvas; see the module comment. */
export class Editor2D {
  /** Draws `model` on `canvas` and listens for input; callbacks: onChange(model), onSelect(selection), onStatus(text). */
  constructor(canvas, { model = new PatternModel(), onChange = () => {}, onSelect = () => {}, onStatus = () => {} } = {}) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.onChange = onChange;
    this.onSelect = onSelect;
    this.onStatus = onStatus;
    /** Lattice parameters of the grid and circular tools, and the mirror tool's axis. */
    this.options = { rows: 2, cols: 2, diagonals: 'none', rings: 2, spokes: 8, mirror: 'x' };
    /** Milliseconds the last draw() took. */
    this.lastDrawMs = 0;
    this.history = new History();
    this._model = model;
    this._snap = { grid: 0.5, vertices: true, midpoints: true };
    this._jointLabels = false;
    this.tool = 'select';
    this.view = { scale: 50, ox: 0, oy: 0 };
    this._sel = { joints: new Set(), triangles: new Set(), vertices: new Set() };
    this._problems = [];
    this._action = null;
    this._points = [];
    this._picked = [];
    this._hover = null;
    this._clipboard = null;
    this._space = false;
    this._styleCache = null;
    this._screen = new Float64Array(0);
    this._raf = 0;
    this._size = { w: 0, h: 0, dpr: 1 };
    this.history.push(model.snapshot());
    this._listen();
    if (!(canvas.tabIndex >= 0)) canvas.tabIndex = 0;
    canvas.style.touchAction = 'none';
    if (!canvas.style.outline) canvas.style.outline = 'none';
    this.resize();
    this.fit();
  }

  // ------------------------------------------------------------------ public state

  /** The model being edited. */
  get model() {
    return this._model;
  }

  /** Edit another model: history and selection start afresh (the view stays; call fit()). */
  setModel(model) {
    this._cancel();
    this._model = model;
    this.history.clear();
    this.history.push(model.snapshot());
    this._problems = [];
    this._setSelection({ joints: [], triangles: [], vertices: [] });
    this._requestDraw();
  }

  /** Snapping of placing tools: {grid: spacing or null, vertices: bool, midpoints: bool}. */
  get snap() {
    return this._snap;
  }

  set snap(value) {
    this._snap = { grid: null, vertices: true, midpoints: true, ...value };
    this._requestDraw();
  }

  /** Whether joint IDs are drawn beside the creases. */
  get jointLabels() {
    return this._jointLabels;
  }

  set jointLabels(on) {
    this._jointLabels = Boolean(on);
    this._requestDraw();
  }

  /** The selection: {joints: [ids], triangles: [indices], vertices: [indices], actors: [ids of selected triangles]}. */
  get selection() {
    const triangles = [...this._sel.triangles].sort((a, b) => a - b);
    const actors = [...new Set(triangles.map((t) => this._model.triangles[t].actor))].sort((a, b) => a - b);
    return {
      joints: [...this._sel.joints].sort((a, b) => a - b),
      triangles,
      vertices: [...this._sel.vertices].sort((a, b) => a - b),
      actors,
    };
  }

  /** Select programmatically: {joints, triangles, vertices, actors (all their triangles)}; replaces the selection. */
  select({ joints = [], triangles = [], vertices = [], actors = [] } = {}) {
    const tris = [...triangles];
    for (const a of actors) tris.push(...this._model.trianglesOf(a));
    this._setSelection({ joints, triangles: tris, vertices });
  }

  /** Choose a tool by name (see TOOLS); cancels any action in progress. */
  setTool(name) {
    if (!TOOLS.includes(name)) throw new Error(`unknown tool '${name}'`);
    this._cancel();
    this.tool = name;
    this.canvas.style.cursor = name === 'select' ? 'default' : name === 'move' ? 'move' : 'crosshair';
    this.onStatus(HINTS[name]);
    this._requestDraw();
  }

  /** Draw a red ring at a model point (a validation problem's place). */
  markProblem({ x, y }) {
    if (Number.isFinite(x) && Number.isFinite(y)) this._problems.push({ x, y });
    this._requestDraw();
  }

  /** Remove every problem ring. */
  clearProblems() {
    this._problems = [];
    this._requestDraw();
  }

  /** Redraw on the next frame, after the model was changed from outside the editor. */
  refresh() {
    this._pruneSelection();
    this._requestDraw();
  }

  /** Record an edit made from outside the editor: push it to the history, redraw, call onChange. */
  commit() {
    this._edited();
  }

  // ------------------------------------------------------------------ view

  /** Match the canvas's backing store to its CSS size and the device pixel ratio. */
  resize() {
    const c = this.canvas;
    const dpr = (typeof window !== 'undefined' && window.devicePixelRatio) || 1;
    let w = c.clientWidth, h = c.clientHeight;
    if (!w || !h) {
      w = c.width / this._size.dpr || 300;
      h = c.height / this._size.dpr || 150;
    } else if (!this._size.w && w === c.width && h === c.height && dpr !== 1) {
      // Sized by its attributes alone: pin the CSS size before the backing store grows.
      c.style.width = `${w}px`;
      c.style.height = `${h}px`;
    }
    const bw = Math.max(1, Math.round(w * dpr)), bh = Math.max(1, Math.round(h * dpr));
    if (c.width !== bw) c.width = bw;
    if (c.height !== bh) c.height = bh;
    const first = !this._size.w;
    if (!first) {
      // Keep the model point at the centre where it was.
      this.view.ox += (w - this._size.w) / 2;
      this.view.oy += (h - this._size.h) / 2;
    }
    this._size = { w, h, dpr };
    this._requestDraw();
  }

  /** Frame the model's bounds in the canvas. */
  fit() {
    const { w, h } = this._size;
    const b = this._model.bounds();
    const margin = 24;
    if (!b) {
      this.view.scale = Math.min(w, h) / 10;
      this.view.ox = w / 2;
      this.view.oy = h / 2;
    } else {
      const bw = b.maxX - b.minX, bh = b.maxY - b.minY;
      const sx = bw > 0 ? (w - 2 * margin) / bw : Infinity, sy = bh > 0 ? (h - 2 * margin) / bh : Infinity;
      let s = Math.min(sx, sy);
      if (!Number.isFinite(s) || s <= 0) s = 50;
      this.view.scale = s;
      this.view.ox = w / 2 - ((b.minX + b.maxX) / 2) * s;
      this.view.oy = h / 2 + ((b.minY + b.maxY) / 2) * s;
    }
    this._requestDraw();
  }

  /** Client (page viewport) pixel coordinates of a model point. */
  toClient({ x, y }) {
    const r = this.canvas.getBoundingClientRect();
    const s = this._toScreen({ x, y });
    return { x: r.left + this.canvas.clientLeft + s.x, y: r.top + this.canvas.clientTop + s.y };
  }

  /** The model point under client (page viewport) pixel coordinates. */
  fromClient(clientX, clientY) {
    const r = this.canvas.getBoundingClientRect();
    return this._toModel(clientX - r.left - this.canvas.clientLeft, clientY - r.top - this.canvas.clientTop);
  }

  _toModel(sx, sy) {
    return { x: (sx - this.view.ox) / this.view.scale, y: (this.view.oy - sy) / this.view.scale };
  }

  _toScreen(p) {
    return { x: this.view.ox + p.x * this.view.scale, y: this.view.oy - p.y * this.view.scale };
  }

  _zoomAt(sx, sy, factor) {
    const p = this._toModel(sx, sy);
    this.view.scale = Math.min(1e9, Math.max(1e-9, this.view.scale * factor));
    this.view.ox = sx - p.x * this.view.scale;
    this.view.oy = sy + p.y * this.view.scale;
    this._requestDraw();
  }

  // ------------------------------------------------------------------ history and actions

  /** Undo the last edit. */
  undo() {
    this._cancel();
    const s = this.history.undo();
    if (s) this._restored(s);
    else this.onStatus('Nothing to undo');
  }

  /** Redo the last undone edit. */
  redo() {
    this._cancel();
    const s = this.history.redo();
    if (s) this._restored(s);
    else this.onStatus('Nothing to redo');
  }

  /** Put the selected triangles (and those of selected actors) into one new actor. */
  groupSelection() {
    const tris = this._selectedTriangles();
    if (!tris.length) return this.onStatus('Group: select triangles first');
    const id = this._model.group(tris);
    this._edited();
    this.onStatus(`Grouped ${tris.length} triangle${tris.length === 1 ? '' : 's'} into actor ${id}`);
  }

  /** Make every triangle of each selected actor an actor of its own. */
  ungroupSelection() {
    const actors = this.selection.actors;
    if (!actors.length) return this.onStatus('Ungroup: select triangles of an actor first');
    let n = 0;
    for (const a of actors) n += this._model.ungroup(a).length;
    this._edited();
    this.onStatus(`Ungrouped ${actors.length} actor${actors.length === 1 ? '' : 's'} into ${n}`);
  }

  /** Copy the selected triangles (with their grouping and creases) to the editor's clipboard. */
  copySelection() {
    const tris = this._selectedTriangles();
    if (!tris.length) return this.onStatus('Copy: select triangles first');
    this._clipboard = this._model.copyTriangles(tris);
    this.onStatus(`Copied ${tris.length} triangle${tris.length === 1 ? '' : 's'}`);
  }

  /** Paste the clipboard, by default just right of the whole pattern; selects the pasted triangles. */
  paste(dx = undefined, dy = 0) {
    const clip = this._clipboard;
    if (!clip || !clip.triangles.length) return this.onStatus('Paste: copy something first');
    if (dx === undefined) {
      const b = this._model.bounds();
      const width = clip.bounds.maxX - clip.bounds.minX;
      const gap = this._snap.grid > 0 ? this._snap.grid : 0.1 * width || 1;
      dx = b ? b.maxX - clip.bounds.minX + gap : 0;
      // Land on the snap grid when the copy's corners were on it.
      if (this._snap.grid > 0) dx = Math.ceil(dx / this._snap.grid) * this._snap.grid;
    }
    const tris = this._model.paste(clip, dx, dy);
    this._setSelection({ triangles: tris });
    this._edited();
    this.onStatus(`Pasted ${tris.length} triangle${tris.length === 1 ? '' : 's'}`);
  }

  /** Delete the selected triangles and those around selected vertices. */
  deleteSelection() {
    const tris = new Set(this._selectedTriangles());
    if (this._sel.vertices.size)
      this._model.triangles.forEach((t, k) => {
        if (t.v.some((i) => this._sel.vertices.has(i))) tris.add(k);
      });
    if (!tris.size) return this.onStatus('Delete: select triangles or vertices first');
    this._model.deleteTriangles([...tris]);
    this._setSelection({});
    this._edited();
    this.onStatus(`Deleted ${tris.size} triangle${tris.size === 1 ? '' : 's'}`);
  }

  /** Set the assignment ('M', 'V', 'F' or 'U') of the selected joints. */
  setAssignment(assignment) {
    const ids = [...this._sel.joints].filter((id) => this._model.joint(id));
    if (!ids.length) return this.onStatus('Assignment: select joints first');
    for (const id of ids) this._model.setJoint(id, { assignment });
    this._edited();
    this.onStatus(`${ids.length} joint${ids.length === 1 ? '' : 's'} set to ${assignment}`);
  }

  /**
   * Transform the selection about its centre: {rotate (radians, counter-clockwise), scale,
   * mirror: 'x' (flip x) or 'y'}.
   */
  applyTransform({ rotate = 0, scale = 1, mirror = null } = {}) {
    const verts = this._selectedVertices();
    if (!verts.length) return this.onStatus('Transform: select something first');
    const about = this._centreOf(verts);
    this._applyVertexEdit(verts, () => this._model.transformVertices(verts, { rotate, scale, mirror, about }));
  }

  /** Select every triangle. */
  selectAll() {
    this._setSelection({ triangles: this._model.triangles.map((_, t) => t) });
  }

  /** Remove listeners and stop drawing. */
  destroy() {
    for (const [target, type, fn, opts] of this._listeners) target.removeEventListener(type, fn, opts);
    this._listeners = [];
    if (this._resizeObserver) this._resizeObserver.disconnect();
    if (this._raf) cancelAnimationFrame(this._raf);
    this._raf = 0;
  }

  // ------------------------------------------------------------------ edit plumbing

  _edited() {
    this.history.push(this._model.snapshot());
    this._pruneSelection();
    this._requestDraw();
    this.onChange(this._model);
  }

  _restored(snapshot) {
    this._model.restore(snapshot);
    this._setSelection({ joints: [...this._sel.joints] });
    this._pruneSelection();
    this._requestDraw();
    this.onChange(this._model);
  }

  // Vertex edits may weld or renumber: keep the selection only while indices still mean the same.
  _applyVertexEdit(verts, edit) {
    const nv = this._model.vertices.length, nt = this._model.triangles.length;
    const moved = edit();
    if (this._model.vertices.length !== nv || this._model.triangles.length !== nt)
      this._setSelection({ joints: [...this._sel.joints], vertices: moved.filter((i) => i >= 0) });
    this._edited();
  }

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

  // ------------------------------------------------------------------ input

  _listen() {
    this._listeners = [];
    const on = (target, type, fn, opts) => {
      target.addEventListener(type, fn, opts);
      this._listeners.push([target, type, fn, opts]);
    };
    const c = this.canvas;
    on(c, 'pointerdown', (e) => this._onDown(e));
    on(c, 'pointermove', (e) => this._onMove(e));
    on(c, 'pointerup', (e) => this._onUp(e));
    on(c, 'pointercancel', () => this._cancel());
    on(c, 'pointerleave', () => {
      if (!this._action && this._hover) {
        this._hover = null;
        this._requestDraw();
      }
    });
    on(c, 'wheel', (e) => this._onWheel(e), { passive: false });
    on(c, 'dblclick', (e) => this._onDoubleClick(e));
    on(c, 'contextmenu', (e) => e.preventDefault());
    if (typeof window !== 'undefined') {
      on(window, 'keydown', (e) => this._onKey(e));
      on(window, 'keyup', (e) => {
        if (e.key === ' ') this._space = false;
      });
      on(window, 'resize', () => this.resize());
      on(window, 'blur', () => (this._space = false));
    }
    if (typeof ResizeObserver !== 'undefined') {
      this._resizeObserver = new ResizeObserver(() => this.resize());
      this._resizeObserver.observe(c);
    }
  }

  _local(e) {
    const r = this.canvas.getBoundingClientRect();
    return { x: e.clientX - r.left - this.canvas.clientLeft, y: e.clientY - r.top - this.canvas.clientTop };
  }

  _onDown(e) {
    if (this.canvas.focus) this.canvas.focus({ preventScroll: true });
    const s = this._local(e);
    try {
      this.canvas.setPointerCapture(e.pointerId);
    } catch {
      // Synthetic events have no active pointer to capture.
    }
    if (e.button === 1 || e.button === 2 || (e.button === 0 && this._space)) {
      e.preventDefault();
      this._action = { kind: 'pan', sx: s.x, sy: s.y, ox: this.view.ox, oy: this.view.oy };
      return;
    }
    if (e.button !== 0) return;
    e.preventDefault();
    const handler = this[`_down_${this.tool}`];
    if (handler) handler.call(this, s, e);
  }

  _onMove(e) {
    const s = this._local(e);
    const a = this._action;
    if (a && a.kind === 'pan') {
      this.view.ox = a.ox + s.x - a.sx;
      this.view.oy = a.oy + s.y - a.sy;
      this._requestDraw();
      return;
    }
    const handler = this[`_move_${this.tool}`];
    if (a && handler) handler.call(this, s, e);
    else this._hoverAt(s, e);
  }

  _onUp(e) {
    const s = this._local(e);
    const a = this._action;
    try {
      this.canvas.releasePointerCapture(e.pointerId);
    } catch {
      // Nothing was captured.
    }
    if (!a) return;
    if (a.kind === 'pan') {
      this._action = null;
      return;
    }
    const handler = this[`_up_${this.tool}`];
    if (handler) handler.call(this, s, e);
  }

  _onWheel(e) {
    e.preventDefault();
    const s = this._local(e);
    const unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? this._size.h : 1;
    this._zoomAt(s.x, s.y, Math.exp(-e.deltaY * unit * 0.0015));
  }

  _onDoubleClick(e) {
    const s = this._local(e);
    if (this.tool === 'polygon') this._closePolygon();
    else if (this.tool === 'select') {
      const t = this._model.triangleAt(this._toModel(s.x, s.y));
      if (t >= 0) this.select({ actors: [this._model.triangles[t].actor] });
    }
  }

  _onKey(e) {
    if (isEditable(e.target)) return;
    const ctrl = e.ctrlKey || e.metaKey;
    const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
    const overCanvas = e.target === this.canvas || e.target === document.body || e.target === document.documentElement;
    if (key === ' ' && overCanvas) {
      this._space = true;
      e.preventDefault();
      return;
    }
    let handled = true;
    if (ctrl && key === 'z') e.shiftKey ? this.redo() : this.undo();
    else if (ctrl && key === 'y') this.redo();
    else if (ctrl && key === 'c' && overCanvas) this.copySelection();
    else if (ctrl && key === 'v' && overCanvas) this.paste();
    else if (ctrl && key === 'a' && overCanvas) this.selectAll();
    else if (key === 'Escape') {
      if (this._action || this._points.length || this._picked.length) this._cancel();
      else this._setSelection({});
    } else if (key === 'Enter' && this.tool === 'polygon') this._closePolygon();
    else if (key === 'Backspace' && this.tool === 'polygon' && this._points.length) {
      this._points.pop();
      this._requestDraw();
    } else if ((key === 'Delete' || key === 'Backspace') && overCanvas && !this._action) this.deleteSelection();
    else handled = false;
    if (handled) e.preventDefault();
  }

  // Ends whatever the pointer was doing; previews of moved vertices are put back.
  _cancel() {
    const a = this._action;
    if (a && a.originals) this._restorePositions(a);
    this._action = null;
    this._points = [];
    this._picked = [];
    this._requestDraw();
  }

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
    this._tryEdit('Triangle', () => this._model.addTriangle(a, b, c), (tris) => this._setSelection({ triangles: tris }));
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
    this._tryEdit('Polygon', () => this._model.addPolygon(pts), (tris) => this._setSelection({ triangles: tris }));
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
    this._tryEdit('Grid', () => this._model.addGrid(spec), (tris) => this._setSelection({ triangles: tris }));
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
    this._tryEdit('Circular lattice', () => this._model.addCircular(spec), (tris) => this._setSelection({ triangles: tris }));
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
    this._applyVertexEdit(a.verts, () => this._model.moveVertices(a.verts, a.dx, a.dy));
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
    this._applyVertexEdit(a.verts, () => this._model.transformVertices(a.verts, { rotate: a.angle, about: a.centre }));
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
    this._applyVertexEdit(a.verts, () => this._model.transformVertices(a.verts, { scale: a.factor, about: a.centre }));
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
    const kept = this._model.mergeVertices(v, from);
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
    const mid = m.splitEdge(e.i, e.j, t);
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

  // ------------------------------------------------------------------ drawing

  _requestDraw() {
    this._dirty = true;
    if (this._raf || typeof requestAnimationFrame === 'undefined') return;
    this._raf = requestAnimationFrame(() => {
      this._raf = 0;
      if (this._dirty) this.draw();
    });
  }

  // Per model version: edges split by style, triangles by tint, joints by edge.
  _styles() {
    const m = this._model;
    if (this._styleCache && this._styleCache.model === m && this._styleCache.version === m.version) return this._styleCache;
    const lists = { boundary: [], internal: [], M: [], V: [], F: [], U: [] };
    const jointByKey = new Map(m.joints().map((j) => [j.key, j]));
    for (const e of m.edges()) {
      if (e.kind === 'joint') lists[jointByKey.get(e.key).assignment].push(e.i, e.j);
      else lists[e.kind].push(e.i, e.j);
    }
    const tint = this._tints(m);
    const byTint = TINTS.map(() => []);
    m.triangles.forEach((t, k) => byTint[tint.get(t.actor)].push(k));
    const edges = {};
    for (const [k, v] of Object.entries(lists)) edges[k] = Int32Array.from(v);
    this._styleCache = { model: m, version: m.version, edges, byTint: byTint.map((l) => Int32Array.from(l)) };
    return this._styleCache;
  }

  // Greedy colouring of the actor adjacency graph so that neighbouring actors differ in tint.
  _tints(m) {
    const near = new Map();
    for (const j of m.joints()) {
      const [a, b] = j.actors;
      if (!near.has(a)) near.set(a, new Set());
      if (!near.has(b)) near.set(b, new Set());
      near.get(a).add(b);
      near.get(b).add(a);
    }
    const tint = new Map();
    for (const a of m.actors()) {
      const taken = new Set([...(near.get(a) ?? [])].map((b) => tint.get(b)));
      let k = ((a % TINTS.length) + TINTS.length) % TINTS.length;
      for (let n = 0; n < TINTS.length && taken.has(k); ++n) k = (k + 1) % TINTS.length;
      tint.set(a, k);
    }
    return tint;
  }

  /** Draw now (normally done on the next animation frame after a change). */
  draw() {
    const t0 = typeof performance !== 'undefined' ? performance.now() : Date.now();
    this._dirty = false;
    const ctx = this.ctx, { w, h, dpr } = this._size, m = this._model;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.setLineDash([]);
    ctx.globalAlpha = 1;
    ctx.fillStyle = STYLE.background;
    ctx.fillRect(0, 0, w, h);
    this._drawGrid(ctx, w, h);
    const n = m.vertices.length;
    if (this._screen.length < 2 * n) this._screen = new Float64Array(Math.max(2 * n, 2 * this._screen.length));
    const xy = this._screen, { scale, ox, oy } = this.view;
    for (let i = 0; i < n; ++i) {
      xy[2 * i] = ox + m.vertices[i].x * scale;
      xy[2 * i + 1] = oy - m.vertices[i].y * scale;
    }
    const st = this._styles();
    st.byTint.forEach((tris, k) => this._fillTriangles(ctx, tris, TINTS[k]));
    this._drawSelectionUnder(ctx, xy);
    this._strokeEdges(ctx, st.edges.internal, STYLE.internal, 0.75, []);
    this._strokeEdges(ctx, st.edges.U, STYLE.U, 1.5, [1.5, 3]);
    this._strokeEdges(ctx, st.edges.F, STYLE.F, 1.5, [1.5, 3]);
    this._strokeEdges(ctx, st.edges.V, STYLE.V, 1.5, [7, 4]);
    this._strokeEdges(ctx, st.edges.M, STYLE.M, 1.5, []);
    this._strokeEdges(ctx, st.edges.boundary, STYLE.boundary, 1.5, []);
    this._drawVertices(ctx, xy, n);
    this._drawSelectionOver(ctx, xy);
    if (this._jointLabels) this._drawJointLabels(ctx, w, h);
    this._drawProblems(ctx);
    this._drawToolState(ctx);
    this.lastDrawMs = (typeof performance !== 'undefined' ? performance.now() : Date.now()) - t0;
  }

  _drawGrid(ctx, w, h) {
    const g = this._snap.grid;
    const step = g * this.view.scale;
    if (!(g > 0) || step < 8) return;
    const a = this._toModel(0, h), b = this._toModel(w, 0);
    ctx.beginPath();
    for (let x = Math.ceil(a.x / g) * g; x <= b.x; x += g) {
      const sx = Math.round(this.view.ox + x * this.view.scale) + 0.5;
      ctx.moveTo(sx, 0);
      ctx.lineTo(sx, h);
    }
    for (let y = Math.ceil(a.y / g) * g; y <= b.y; y += g) {
      const sy = Math.round(this.view.oy - y * this.view.scale) + 0.5;
      ctx.moveTo(0, sy);
      ctx.lineTo(w, sy);
    }
    ctx.strokeStyle = STYLE.gridLine;
    ctx.lineWidth = 1;
    ctx.stroke();
  }

  // Filling costs grow faster than the path (Chrome's rasteriser): fill in batches.
  _fillTriangles(ctx, tris, colour) {
    if (!tris.length) return;
    const xy = this._screen, T = this._model.triangles;
    ctx.fillStyle = colour;
    const w = this._size.w, h = this._size.h;
    let n = 0;
    ctx.beginPath();
    for (let k = 0; k < tris.length; ++k) {
      const v = T[tris[k]].v;
      const ax = xy[2 * v[0]], ay = xy[2 * v[0] + 1], bx = xy[2 * v[1]], by = xy[2 * v[1] + 1], cx = xy[2 * v[2]], cy = xy[2 * v[2] + 1];
      if ((ax < 0 && bx < 0 && cx < 0) || (ax > w && bx > w && cx > w) || (ay < 0 && by < 0 && cy < 0) || (ay > h && by > h && cy > h)) continue;
      if (++n % FILL_BATCH === 0) {
        ctx.fill();
        ctx.beginPath();
      }
      ctx.moveTo(ax, ay);
      ctx.lineTo(bx, by);
      ctx.lineTo(cx, cy);
      ctx.closePath();
    }
    ctx.fill();
  }

  // Dashes are drawn as short solid segments: setLineDash is several times slower to rasterise.
  // Edges off the canvas are skipped and long ones clipped, so dashes stay few when zoomed in;
  // an edge shorter than two dash periods is drawn solid (its colour still tells its kind).
  _strokeEdges(ctx, pairs, colour, width, dash) {
    if (!pairs.length) return;
    const xy = this._screen, pad = width + 2;
    const x0c = -pad, y0c = -pad, x1c = this._size.w + pad, y1c = this._size.h + pad;
    const on = dash.length ? dash[0] : 0, period = dash.length ? dash[0] + dash[1] : 0;
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.lineCap = 'butt';
    ctx.beginPath();
    let segments = 0;
    for (let k = 0; k < pairs.length; k += 2) {
      const ax = xy[2 * pairs[k]], ay = xy[2 * pairs[k] + 1], bx = xy[2 * pairs[k + 1]], by = xy[2 * pairs[k + 1] + 1];
      if ((ax < x0c && bx < x0c) || (ax > x1c && bx > x1c) || (ay < y0c && by < y0c) || (ay > y1c && by > y1c)) continue;
      if (++segments % STROKE_BATCH === 0) {
        ctx.stroke();
        ctx.beginPath();
      }
      const dx = bx - ax, dy = by - ay, len = period ? Math.hypot(dx, dy) : 0;
      if (!period || len < 2 * period) {
        ctx.moveTo(ax, ay);
        ctx.lineTo(bx, by);
        continue;
      }
      // Liang–Barsky: the part of the edge inside the padded canvas, as distances from a.
      let t0 = 0, t1 = 1;
      const clip = (p, q) => {
        if (p === 0) return q >= 0;
        const r = q / p;
        if (p < 0) t0 = Math.max(t0, r);
        else t1 = Math.min(t1, r);
        return t0 <= t1;
      };
      if (!(clip(-dx, ax - x0c) && clip(dx, x1c - ax) && clip(-dy, ay - y0c) && clip(dy, y1c - ay))) continue;
      const ux = dx / len, uy = dy / len, end = t1 * len;
      // Dashes keep their phase from the edge's start, so they do not crawl while panning.
      for (let d = Math.floor((t0 * len) / period) * period; d < end; d += period) {
        const e = Math.min(d + on, len);
        ctx.moveTo(ax + ux * d, ay + uy * d);
        ctx.lineTo(ax + ux * e, ay + uy * e);
      }
    }
    ctx.stroke();
  }

  _drawVertices(ctx, xy, n) {
    const b = this._model.bounds();
    if (!b || !n) return;
    // Dots only while vertices are a few pixels apart on average.
    const spacing = (Math.hypot(b.maxX - b.minX, b.maxY - b.minY) * this.view.scale) / Math.sqrt(n);
    if (spacing < 10) return;
    ctx.beginPath();
    for (let i = 0; i < n; ++i) ctx.rect(xy[2 * i] - 1.5, xy[2 * i + 1] - 1.5, 3, 3);
    ctx.fillStyle = STYLE.vertex;
    ctx.fill();
  }

  _drawSelectionUnder(ctx, xy) {
    const m = this._model;
    const hoverHit = !this._action && this._hover && this._hover.hit;
    if (hoverHit && hoverHit.kind === 'triangle' && m.triangles[hoverHit.index]) {
      ctx.globalAlpha = 0.25;
      this._fillTriangles(ctx, [hoverHit.index], STYLE.selected);
      ctx.globalAlpha = 1;
    }
    if (this._sel.triangles.size) {
      ctx.globalAlpha = 0.4;
      this._fillTriangles(ctx, [...this._sel.triangles].filter((t) => t < m.triangles.length), STYLE.selected);
      ctx.globalAlpha = 1;
    }
    const pairs = [];
    for (const id of this._sel.joints) {
      const j = m.joint(id);
      if (j) pairs.push(j.va, j.vb);
    }
    this._strokeEdges(ctx, pairs, STYLE.selected, 7, []);
    if (hoverHit && hoverHit.kind === 'joint') {
      const j = m.joint(hoverHit.id);
      if (j) this._strokeEdges(ctx, [j.va, j.vb], STYLE.hover, 7, []);
    }
  }

  _drawSelectionOver(ctx, xy) {
    const m = this._model;
    const ring = (i, colour, r) => {
      if (i < 0 || i >= m.vertices.length) return;
      ctx.beginPath();
      ctx.arc(xy[2 * i], xy[2 * i + 1], r, 0, 2 * Math.PI);
      ctx.fillStyle = colour;
      ctx.fill();
    };
    for (const i of this._sel.vertices) ring(i, STYLE.selected, 4.5);
    const hoverHit = !this._action && this._hover && this._hover.hit;
    if (hoverHit && hoverHit.kind === 'vertex') ring(hoverHit.index, STYLE.hover, 6);
    for (const i of this._picked) ring(i, STYLE.snap, 5);
  }

  _drawJointLabels(ctx, w, h) {
    const joints = this._model.joints();
    const b = this._model.bounds();
    // Labels of joints closer than a label's width would only overlap.
    if (!b || (Math.hypot(b.maxX - b.minX, b.maxY - b.minY) * this.view.scale) / Math.sqrt(joints.length + 1) < 24) return;
    ctx.font = '11px sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.lineWidth = 3;
    ctx.strokeStyle = 'rgba(255,255,255,0.85)';
    ctx.fillStyle = '#222';
    let drawn = 0;
    for (const j of joints) {
      const a = this._model.vertices[j.va], b = this._model.vertices[j.vb];
      const s = this._toScreen({ x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 });
      if (s.x < 0 || s.y < 0 || s.x > w || s.y > h) continue;
      if (++drawn > 3000) break;
      ctx.strokeText(String(j.id), s.x, s.y);
      ctx.fillText(String(j.id), s.x, s.y);
    }
  }

  _drawProblems(ctx) {
    if (!this._problems.length) return;
    ctx.beginPath();
    for (const p of this._problems) {
      const s = this._toScreen(p);
      ctx.moveTo(s.x + 10, s.y);
      ctx.arc(s.x, s.y, 10, 0, 2 * Math.PI);
    }
    ctx.strokeStyle = STYLE.problem;
    ctx.lineWidth = 2.5;
    ctx.stroke();
  }

  _drawSnapMarker(ctx, q) {
    if (!q || !q.kind) return;
    const s = this._toScreen(q);
    ctx.beginPath();
    if (q.kind === 'vertex') ctx.rect(s.x - 5, s.y - 5, 10, 10);
    else if (q.kind === 'midpoint') {
      ctx.moveTo(s.x, s.y - 6);
      ctx.lineTo(s.x + 6, s.y + 5);
      ctx.lineTo(s.x - 6, s.y + 5);
      ctx.closePath();
    } else {
      ctx.moveTo(s.x - 6, s.y);
      ctx.lineTo(s.x + 6, s.y);
      ctx.moveTo(s.x, s.y - 6);
      ctx.lineTo(s.x, s.y + 6);
    }
    ctx.strokeStyle = STYLE.snap;
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }

  _drawToolState(ctx) {
    const a = this._action;
    const hover = this._hover && this._hover.snapped;
    ctx.strokeStyle = STYLE.preview;
    ctx.fillStyle = 'rgba(255, 140, 0, 0.12)';
    ctx.lineWidth = 1.5;
    if (this.tool === 'triangle' || this.tool === 'polygon') {
      const pts = [...this._points];
      if (hover) pts.push(hover);
      if (pts.length) {
        ctx.beginPath();
        pts.forEach((p, k) => {
          const s = this._toScreen(p);
          if (k) ctx.lineTo(s.x, s.y);
          else ctx.moveTo(s.x, s.y);
        });
        if (pts.length > 2) {
          ctx.closePath();
          ctx.fill();
        }
        ctx.setLineDash([5, 4]);
        ctx.stroke();
        ctx.setLineDash([]);
        for (const p of this._points) {
          const s = this._toScreen(p);
          ctx.fillStyle = STYLE.preview;
          ctx.fillRect(s.x - 3, s.y - 3, 6, 6);
        }
      }
    }
    if (a && a.kind === 'box') {
      ctx.setLineDash([4, 3]);
      ctx.strokeRect(Math.min(a.sx, a.x), Math.min(a.sy, a.y), Math.abs(a.x - a.sx), Math.abs(a.y - a.sy));
      ctx.setLineDash([]);
    }
    if (a && a.kind === 'grid') this._drawGridPreview(ctx, a);
    if (a && a.kind === 'circular') this._drawCircularPreview(ctx, a);
    if (a && (a.kind === 'rotate' || a.kind === 'scale')) {
      const c = this._toScreen(a.centre);
      ctx.beginPath();
      ctx.moveTo(c.x - 8, c.y);
      ctx.lineTo(c.x + 8, c.y);
      ctx.moveTo(c.x, c.y - 8);
      ctx.lineTo(c.x, c.y + 8);
      ctx.stroke();
    }
    if (this.tool === 'measure' && this._picked.length > 1) {
      ctx.beginPath();
      this._picked.forEach((i, k) => {
        const s = this._toScreen(this._model.vertices[i]);
        if (k) ctx.lineTo(s.x, s.y);
        else ctx.moveTo(s.x, s.y);
      });
      ctx.strokeStyle = STYLE.snap;
      ctx.stroke();
    }
    if (a && a.kind === 'move') this._drawSnapMarker(ctx, a.snapped);
    else if (a && a.kind === 'grid') this._drawSnapMarker(ctx, a.to);
    else if (!a) this._drawSnapMarker(ctx, hover);
  }

  _drawGridPreview(ctx, a) {
    const o = this.options;
    const cols = Math.max(1, Math.round(o.cols)), rows = Math.max(1, Math.round(o.rows));
    const p = this._toScreen(a.from), q = this._toScreen(a.to);
    ctx.beginPath();
    for (let c = 0; c <= cols; ++c) {
      const x = p.x + ((q.x - p.x) * c) / cols;
      ctx.moveTo(x, p.y);
      ctx.lineTo(x, q.y);
    }
    for (let r = 0; r <= rows; ++r) {
      const y = p.y + ((q.y - p.y) * r) / rows;
      ctx.moveTo(p.x, y);
      ctx.lineTo(q.x, y);
    }
    ctx.fillRect(Math.min(p.x, q.x), Math.min(p.y, q.y), Math.abs(q.x - p.x), Math.abs(q.y - p.y));
    ctx.stroke();
  }

  _drawCircularPreview(ctx, a) {
    const o = this.options;
    const rings = Math.max(1, Math.round(o.rings)), spokes = Math.max(3, Math.round(o.spokes));
    const c = this._toScreen(a.centre), r = a.radius * this.view.scale;
    ctx.beginPath();
    for (let k = 1; k <= rings; ++k) {
      const rk = (r * k) / rings;
      for (let s = 0; s <= spokes; ++s) {
        const ang = (2 * Math.PI * s) / spokes;
        const x = c.x + rk * Math.cos(ang), y = c.y - rk * Math.sin(ang);
        if (s) ctx.lineTo(x, y);
        else ctx.moveTo(x, y);
      }
    }
    for (let s = 0; s < spokes; ++s) {
      const ang = (2 * Math.PI * s) / spokes;
      ctx.moveTo(c.x, c.y);
      ctx.lineTo(c.x + r * Math.cos(ang), c.y - r * Math.sin(ang));
    }
    ctx.stroke();
  }
}
