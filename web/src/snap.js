// Snapping of placed points to the grid, the model's vertices and its edges' midpoints.
import { dist } from './polygon.js';

/**
 * The nearest snap target to p within radius: a grid point (spacing `grid`, or null for none),
 * a model vertex, or an edge midpoint. Returns {x, y, kind, index?} or p itself when none is near.
 * On a tie a vertex wins over a midpoint, and a midpoint over a grid point. Vertices in `exclude`
 * (a Set of indices, e.g. the ones being dragged) and edges touching them are not targets.
 */
export function snapPoint(p, { grid = null, vertices = true, midpoints = true } = {}, model = null, radius = Infinity, exclude = null) {
  let best = null, bestD = radius;
  if (model && vertices) {
    const used = model._usedVertices();
    for (let i = 0; i < model.vertices.length; ++i) {
      if (!used[i] || (exclude && exclude.has(i))) continue;
      const d = dist(model.vertices[i], p);
      if (d <= bestD && (!best || d < bestD)) {
        best = { x: model.vertices[i].x, y: model.vertices[i].y, kind: 'vertex', index: i };
        bestD = d;
      }
    }
  }
  if (model && midpoints) {
    for (const e of model.edges()) {
      if (exclude && (exclude.has(e.i) || exclude.has(e.j))) continue;
      const a = model.vertices[e.i], b = model.vertices[e.j];
      const m = { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
      const d = dist(m, p);
      if (d < bestD) {
        best = { x: m.x, y: m.y, kind: 'midpoint', edge: [e.i, e.j] };
        bestD = d;
      }
    }
  }
  if (grid > 0) {
    const g = { x: Math.round(p.x / grid) * grid, y: Math.round(p.y / grid) * grid };
    if (dist(g, p) < bestD) best = { x: g.x, y: g.y, kind: 'grid' };
  }
  return best ?? p;
}
