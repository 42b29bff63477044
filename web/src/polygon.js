// Plane geometry of the crease-pattern model: small vector helpers, bounding boxes and the
// vertex-merge tolerance, welding points into vertices, and simple polygons (area, cleaning,
// ear clipping). Pure: no DOM.

/** Vertices closer than this fraction of the bounding-box diagonal are one vertex (foldkit's rule). */
export const MERGE_TOLERANCE = 1e-9;

/** Twice the signed area of triangle a, b, c: positive when it turns counter-clockwise. */
export function cross3(a, b, c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/** Distance between points a and b. */
export function dist(a, b) {
  return Math.hypot(a.x - b.x, a.y - b.y);
}

/** The bounding box {minX, minY, maxX, maxY} of points, or `box` grown in place to hold them; null when neither has any. */
export function boxOf(points, box = null) {
  let b = box;
  for (const p of points) {
    if (!b) b = { minX: p.x, minY: p.y, maxX: p.x, maxY: p.y };
    else {
      if (p.x < b.minX) b.minX = p.x;
      if (p.y < b.minY) b.minY = p.y;
      if (p.x > b.maxX) b.maxX = p.x;
      if (p.y > b.maxY) b.maxY = p.y;
    }
  }
  return b;
}

/** The vertex-merge tolerance of a bounding box: MERGE_TOLERANCE × its diagonal (0 for none). */
export function toleranceOf(box) {
  if (!box) return 0;
  const d = Math.hypot(box.maxX - box.minX, box.maxY - box.minY);
  return Number.isFinite(d) ? MERGE_TOLERANCE * d : 0;
}

/** A plain {x, y} copy of p; throws Error('WHAT: not a finite point') unless both are finite. */
export function checkPoint(p, what) {
  if (!p || !Number.isFinite(p.x) || !Number.isFinite(p.y)) throw new Error(`${what}: not a finite point`);
  return { x: p.x, y: p.y };
}

/**
 * Welds points into a shared vertex list with a uniform hash grid (first come, first kept),
 * as foldkit's reader does, so that separately drawn triangles share their corners.
 */
export class Welder {
  constructor(vertices, tol, skip = null) {
    this.vertices = vertices;
    this.tol = tol;
    this.cell = tol > 0 ? tol : 1;
    this.cells = new Map();
    for (let i = 0; i < vertices.length; ++i) if (!skip || !skip.has(i)) this._put(vertices[i], i);
  }

  _key(cx, cy) {
    return `${cx},${cy}`;
  }

  _put(p, i) {
    const k = this._key(Math.floor(p.x / this.cell), Math.floor(p.y / this.cell));
    const list = this.cells.get(k);
    if (list) list.push(i);
    else this.cells.set(k, [i]);
  }

  find(p) {
    const cx = Math.floor(p.x / this.cell), cy = Math.floor(p.y / this.cell);
    let best = -1, bestD = this.tol;
    for (let dx = -1; dx <= 1; ++dx)
      for (let dy = -1; dy <= 1; ++dy) {
        const list = this.cells.get(this._key(cx + dx, cy + dy));
        if (!list) continue;
        for (const i of list) {
          const d = dist(this.vertices[i], p);
          if (d <= bestD && (best < 0 || d < bestD || i < best)) {
            best = i;
            bestD = d;
          }
        }
      }
    return best;
  }

  insert(p) {
    const found = this.find(p);
    if (found >= 0) return found;
    this.vertices.push({ x: p.x, y: p.y });
    this._put(p, this.vertices.length - 1);
    return this.vertices.length - 1;
  }
}

/**
 * Ear-clipping triangulation of a simple polygon (either orientation; collinear corners allowed).
 * Returns index triples into `pts`, each oriented like the polygon; throws when no ear is left.
 */
export function earClip(pts, tol = 0) {
  const n = pts.length;
  if (n < 3) throw new Error('a polygon needs at least 3 corners');
  const sign = Math.sign(signedArea(pts));
  if (sign === 0) throw new Error('degenerate polygon (zero area)');
  const prev = new Int32Array(n), next = new Int32Array(n);
  for (let i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  const out = [];
  let remaining = n, v = 0;
  const isEar = (p, c, q) => {
    const a = pts[p], b = pts[c], d = pts[q];
    const longest = Math.max(dist(a, b), dist(b, d), dist(d, a));
    if (cross3(a, b, d) * sign <= tol * longest) return false;
    const eps = tol * longest;
    for (let r = next[q]; r !== p; r = next[r]) {
      const x = pts[r];
      if (cross3(a, b, x) * sign >= -eps && cross3(b, d, x) * sign >= -eps && cross3(d, a, x) * sign >= -eps) return false;
    }
    return true;
  };
  while (remaining > 3) {
    let found = false;
    for (let k = 0; k < remaining; ++k, v = next[v]) {
      if (!isEar(prev[v], v, next[v])) continue;
      out.push([prev[v], v, next[v]]);
      next[prev[v]] = next[v];
      prev[next[v]] = prev[v];
      v = next[v];
      --remaining;
      found = true;
      break;
    }
    if (!found) throw new Error('cannot triangulate the polygon: is it simple?');
  }
  const last = [prev[v], v, next[v]];
  const [a, b, c] = last.map((i) => pts[i]);
  if (cross3(a, b, c) * sign <= tol * Math.max(dist(a, b), dist(b, c), dist(c, a)))
    throw new Error('cannot triangulate the polygon: is it simple?');
  out.push(last);
  return out;
}

/** Signed area of a polygon (shoelace): positive when counter-clockwise. */
export function signedArea(pts) {
  let s = 0;
  for (let i = 0, n = pts.length; i < n; ++i) {
    const a = pts[i], b = pts[(i + 1) % n];
    s += a.x * b.y - b.x * a.y;
  }
  return s / 2;
}

function segmentsTouch(a, b, c, d, eps) {
  const d1 = cross3(c, d, a), d2 = cross3(c, d, b), d3 = cross3(a, b, c), d4 = cross3(a, b, d);
  const lenCD = dist(c, d), lenAB = dist(a, b);
  const e1 = eps * lenCD, e2 = eps * lenAB;
  if (((d1 > e1 && d2 < -e1) || (d1 < -e1 && d2 > e1)) && ((d3 > e2 && d4 < -e2) || (d3 < -e2 && d4 > e2))) return true;
  const onSeg = (p, q, r, e) =>
    Math.abs(cross3(p, q, r)) <= e * dist(p, q) &&
    Math.min(p.x, q.x) - e <= r.x && r.x <= Math.max(p.x, q.x) + e &&
    Math.min(p.y, q.y) - e <= r.y && r.y <= Math.max(p.y, q.y) + e;
  return onSeg(c, d, a, eps) || onSeg(c, d, b, eps) || onSeg(a, b, c, eps) || onSeg(a, b, d, eps);
}

/**
 * Drops repeated consecutive corners (and a closing copy of the first), then refuses polygons
 * that touch or cross themselves: ear clipping would produce overlapping triangles from them.
 */
export function cleanPolygon(points, tol) {
  const pts = [];
  for (const p of points) {
    const q = checkPoint(p, 'polygon corner');
    if (!pts.length || dist(pts[pts.length - 1], q) > tol) pts.push(q);
  }
  while (pts.length > 1 && dist(pts[0], pts[pts.length - 1]) <= tol) pts.pop();
  const n = pts.length;
  if (n < 3) throw new Error('a polygon needs at least 3 distinct corners');
  for (let i = 0; i < n; ++i) {
    const a = pts[i], b = pts[(i + 1) % n], c = pts[(i + 2) % n];
    // A corner that turns straight back makes a zero-width spike.
    if (Math.abs(cross3(a, b, c)) <= tol * Math.max(dist(a, b), dist(b, c)) &&
        (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0)
      throw new Error('the polygon doubles back on itself');
    for (let j = i + 2; j < n; ++j) {
      if ((j + 1) % n === i) continue;
      if (segmentsTouch(a, b, pts[j], pts[(j + 1) % n], tol)) throw new Error('the polygon intersects itself');
    }
  }
  if (Math.abs(signedArea(pts)) <= tol * tol) throw new Error('degenerate polygon (zero area)');
  return pts;
}
