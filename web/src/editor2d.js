// The 2D crease-pattern editor: draws a PatternModel on a <canvas> with the Canvas 2D API and
// edits it with pointer, wheel and keyboard. Model y points up (as in PMML); the view flips it.
// This module holds the class: its state, public API, view transform and edits; the pointer,
// wheel and keyboard handling is in editor_input.js (functions of the editor); selection and hit
// testing, the tools and the drawing are in editor_selection.js, editor_tools.js and
// editor_draw.js, installed on Editor2D below.
import { PatternModel, History } from './model.js';
import { TOOLS, HINTS, EditorTools } from './editor_tools.js';
import { EditorSelection } from './editor_selection.js';
import { EditorDraw } from './editor_draw.js';
import { copyTriangles, deleteTriangles, group, paste, transformVertices, ungroup } from './model_edits.js';
import { listen } from './editor_input.js';

export { TOOLS } from './editor_tools.js';

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
    listen(this);
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
    this.onStatus(s ? 'Undone' : 'Nothing to undo');
  }

  /** Redo the last undone edit. */
  redo() {
    this._cancel();
    const s = this.history.redo();
    if (s) this._restored(s);
    this.onStatus(s ? 'Redone' : 'Nothing to redo');
  }

  /** Put the selected triangles (and those of selected actors) into one new actor. */
  groupSelection() {
    const tris = this._selectedTriangles();
    if (!tris.length) return this.onStatus('Group: select triangles first');
    const id = group(this._model, tris);
    this._edited();
    this.onStatus(`Grouped ${tris.length} triangle${tris.length === 1 ? '' : 's'} into actor ${id}`);
  }

  /** Make every triangle of each selected actor an actor of its own. */
  ungroupSelection() {
    const actors = this.selection.actors;
    if (!actors.length) return this.onStatus('Ungroup: select triangles of an actor first');
    let n = 0;
    for (const a of actors) n += ungroup(this._model, a).length;
    this._edited();
    this.onStatus(`Ungrouped ${actors.length} actor${actors.length === 1 ? '' : 's'} into ${n}`);
  }

  /** Copy the selected triangles (with their grouping and creases) to the editor's clipboard. */
  copySelection() {
    const tris = this._selectedTriangles();
    if (!tris.length) return this.onStatus('Copy: select triangles first');
    this._clipboard = copyTriangles(this._model, tris);
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
    const tris = paste(this._model, clip, dx, dy);
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
    deleteTriangles(this._model, [...tris]);
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
    this._applyVertexEdit(verts, () => transformVertices(this._model, verts, { rotate, scale, mirror, about }));
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

  // Ends whatever the pointer was doing; previews of moved vertices are put back.
  _cancel() {
    const a = this._action;
    if (a && a.originals) this._restorePositions(a);
    this._action = null;
    this._points = [];
    this._picked = [];
    this._requestDraw();
  }
}

// The selection, tool and drawing methods become Editor2D's own, as if written above.
for (const part of [EditorSelection, EditorTools, EditorDraw])
  for (const [name, method] of Object.entries(Object.getOwnPropertyDescriptors(part.prototype)))
    if (name !== 'constructor') Object.defineProperty(Editor2D.prototype, name, method);
