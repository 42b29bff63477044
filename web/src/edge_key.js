// Keys of undirected edges between vertex indices: the model's maps of edges and joint
// properties use them.

// Numeric edge keys (lo * 2^26 + hi) stay exact below 2^53 and avoid string garbage on big models.
const KEY_BASE = 2 ** 26;

/** The key of the undirected edge between vertex indices a and b. */
export function edgeKey(a, b) {
  return a < b ? a * KEY_BASE + b : b * KEY_BASE + a;
}

/** The vertex indices [lo, hi] of an edge key. */
export function keyEnds(key) {
  const lo = Math.floor(key / KEY_BASE);
  return [lo, key - lo * KEY_BASE];
}
