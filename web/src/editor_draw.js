// The 2D editor's drawing on its canvas: crease styles, facet tints, batched paths, labels,
// problem rings and the tools' previews. These are Editor2D's methods (see editor2d.js),
// written as a class only to hold them: editor2d.js copies them onto Editor2D.prototype, so
// `this` is always the Editor2D.

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
const FILL_BATCH = 256;
const STROKE_BATCH = 1024;

/** The drawing methods of Editor2D (see editor2d.js); not to be constructed. */
export class EditorDraw {
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
    const jointByKey = new Map(m.joints().flatMap((j) => j.keys.map((key) => [key, j])));
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
