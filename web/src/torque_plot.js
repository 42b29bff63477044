// The physical simulation's torque plot: the torque (N·m) of a few joints against time (s), as
// `foldkit simulate --model dynamic --series X.json` wrote it, with the motors' limit and the
// stalls marked. The markup is built as text by pure functions, so that node's tests check it
// against the CLI's own series without a browser.

/** Colours of the plotted joints, in order (the legend names each). */
export const COLOURS = ['#1f62c4', '#d2691e', '#2e8b57', '#b22280', '#6a5acd', '#8b4513', '#008b8b', '#c71585'];

/** At most this many joints are plotted at once (more lines are no longer readable). */
export const MAX_PLOTTED = COLOURS.length;

/**
 * The joints to plot: the selected ones that the series has (in selection order, at most
 * `limit`); with none selected, the stalled joints and then those of the largest peak torque
 * (simulate's `joints`), up to 4. `result`: simulate's JSON; `series`: the series file.
 */
export function plottedJoints(selected, result, series, limit = MAX_PLOTTED) {
  const known = new Set(series.joints.map((j) => j.joint));
  const chosen = selected.filter((id) => known.has(id));
  if (chosen.length) return chosen.slice(0, limit);
  const out = [];
  for (const s of result.stalls || []) if (!out.includes(s.joint) && known.has(s.joint)) out.push(s.joint);
  const byPeak = [...(result.joints || [])].filter((j) => j.peak_torque > 0).sort((a, b) => b.peak_torque - a.peak_torque);
  for (const j of byPeak) if (!out.includes(j.joint) && known.has(j.joint)) out.push(j.joint);
  return out.slice(0, Math.min(4, limit));
}

/**
 * The points of one curve on a plot `columns` pixels wide: every point when there are few, else
 * per pixel column its first, lowest, highest and last point (in time order), so no peak is lost
 * however long the series. `x`, `y`: data → pixels.
 */
export function curvePoints(times, values, x, y, columns) {
  const points = [];
  if (times.length <= 4 * columns) {
    for (let k = 0; k < times.length; k++) points.push([x(times[k]), y(values[k])]);
    return points;
  }
  let column = null;
  let bucket = [];
  const flush = () => {
    if (!bucket.length) return;
    let lo = bucket[0];
    let hi = bucket[0];
    for (const k of bucket) {
      if (values[k] < values[lo]) lo = k;
      if (values[k] > values[hi]) hi = k;
    }
    const keep = [...new Set([bucket[0], lo, hi, bucket[bucket.length - 1]])].sort((a, b) => a - b);
    for (const k of keep) points.push([x(times[k]), y(values[k])]);
    bucket = [];
  };
  for (let k = 0; k < times.length; k++) {
    const c = Math.floor(x(times[k]));
    if (c !== column) flush();
    column = c;
    bucket.push(k);
  }
  flush();
  return points;
}

/** SVG path data through `points`, to 0.01 px. */
export function pathData(points) {
  return points.map(([px, py], k) => `${k ? 'L' : 'M'}${px.toFixed(2)} ${py.toFixed(2)}`).join(' ');
}

// Round numbers for an axis's ends: 3 significant digits.
const label = (v) => (v === 0 ? '0' : Number(v.toPrecision(3)).toString());

/** The plot's frame: pixels inside the axes and data → pixel maps. */
export function plotFrame({ width, height, duration, low, high }) {
  const left = 58;
  const right = width - 6;
  const top = 8;
  const bottom = height - 18;
  const span = high > low ? high - low : 1;
  return {
    left, right, top, bottom,
    x: (t) => left + ((right - left) * (duration > 0 ? t / duration : 0)),
    y: (v) => bottom - ((bottom - top) * (v - low)) / span,
  };
}

/**
 * The torque plot as SVG markup (the inside of an <svg> `width` × `height`): one path per joint
 * of `joints` (class "torque-series", data-joint), the motors' limit ±`limit` N·m dashed when it
 * is within reach of the curves, one mark per stall of a plotted joint (class "stall-mark",
 * data-joint, data-time) and a cursor line (class "cursor") at `time`.
 */
export function torquePlotSvg({ series, joints, stalls = [], limit = null, width = 280, height = 150, time = 0 }) {
  const times = series.time;
  const duration = times.length ? times[times.length - 1] : 0;
  const curves = joints.map((id) => series.joints.find((j) => j.joint === id)).filter(Boolean);
  let low = 0;
  let high = 0;
  for (const c of curves) for (const v of c.torque) { if (v < low) low = v; if (v > high) high = v; }
  const reach = Math.max(high, -low);
  const showLimit = limit > 0 && limit <= 1.5 * reach;
  if (showLimit) { high = Math.max(high, limit); low = Math.min(low, -limit); }
  const pad = (high - low) * 0.05 || 1;
  const f = plotFrame({ width, height, duration, low: low - pad, high: high + pad });
  const out = [];
  out.push(`<rect class="plot-area" x="${f.left}" y="${f.top}" width="${f.right - f.left}" height="${f.bottom - f.top}"/>`);
  out.push(`<line class="zero" x1="${f.left}" x2="${f.right}" y1="${f.y(0).toFixed(2)}" y2="${f.y(0).toFixed(2)}"/>`);
  if (showLimit)
    for (const v of [limit, -limit])
      out.push(`<line class="limit" x1="${f.left}" x2="${f.right}" y1="${f.y(v).toFixed(2)}" y2="${f.y(v).toFixed(2)}"><title>motor limit ${label(v)} N·m</title></line>`);
  curves.forEach((c, k) => {
    const d = pathData(curvePoints(times, c.torque, f.x, f.y, f.right - f.left));
    out.push(`<path class="torque-series" data-joint="${c.joint}" stroke="${COLOURS[k % COLOURS.length]}" d="${d}"><title>joint ${c.joint}</title></path>`);
  });
  for (const s of stalls) {
    if (!curves.some((c) => c.joint === s.joint)) continue;
    const px = f.x(s.time).toFixed(2);
    out.push(`<line class="stall-mark" data-joint="${s.joint}" data-time="${s.time}" x1="${px}" x2="${px}" y1="${f.top}" y2="${f.bottom}"><title>joint ${s.joint} stalled at ${s.time.toFixed(3)} s</title></line>`);
  }
  out.push(`<line class="cursor" x1="${f.x(time).toFixed(2)}" x2="${f.x(time).toFixed(2)}" y1="${f.top}" y2="${f.bottom}"/>`);
  out.push(`<text class="axis" x="${f.left - 3}" y="${f.top + 8}" text-anchor="end">${label(high + pad)} N·m</text>`);
  out.push(`<text class="axis" x="${f.left - 3}" y="${f.bottom}" text-anchor="end">${label(low - pad)} N·m</text>`);
  out.push(`<text class="axis" x="${f.left - 3}" y="${(f.y(0) + 3).toFixed(2)}" text-anchor="end">0</text>`);
  out.push(`<text class="axis" x="${f.left}" y="${height - 4}">0</text>`);
  out.push(`<text class="axis" x="${f.right}" y="${height - 4}" text-anchor="end">${label(duration)} s</text>`);
  curves.forEach((c, k) => {
    out.push(`<text class="legend" x="${f.left + 6 + 52 * k}" y="${f.top + 10}" fill="${COLOURS[k % COLOURS.length]}">joint ${c.joint}</text>`);
  });
  return out.join('');
}

/** Draws into an <svg> element; `show` redraws, `setTime` moves the cursor only. */
export class TorquePlot {
  constructor(svg) {
    this.svg = svg;
    this.shown = null;
  }

  /** Plots `joints` of `series` (see torquePlotSvg for the rest). */
  show({ series, joints, stalls, limit, time = 0 }) {
    const width = Number(this.svg.getAttribute('width'));
    const height = Number(this.svg.getAttribute('height'));
    this.svg.innerHTML = torquePlotSvg({ series, joints, stalls, limit, width, height, time });
    const times = series.time;
    this.shown = { width, height, duration: times.length ? times[times.length - 1] : 0 };
    this.svg.hidden = false;
  }

  /** Moves the cursor to `time` seconds. */
  setTime(time) {
    const cursor = this.svg.querySelector('.cursor');
    if (!cursor || !this.shown) return;
    const f = plotFrame({ ...this.shown, low: 0, high: 1 });
    const px = f.x(Math.max(0, Math.min(this.shown.duration, time))).toFixed(2);
    cursor.setAttribute('x1', px);
    cursor.setAttribute('x2', px);
  }

  clear() {
    this.svg.replaceChildren();
    this.svg.hidden = true;
    this.shown = null;
  }
}
