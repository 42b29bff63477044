// Fold sequences as the page edits them, CMML (the paper's Table 2) and the FOLD frames that
// `foldkit simulate --frames` writes. foldkit reads and checks every file the page writes; the
// reader here only needs to read back what foldkit and the page wrote.

/** A sequence: events in increasing number, each a list of folds {joint, angle (degrees,
 * positive = mountain), speed (degrees per second: the file's <Velocity>)}. A joint an event does not name keeps
 * its angle, as CMML defines. */
export function emptySequence() {
  return { title: '', events: [] };
}

function escapeXml(text) {
  return String(text).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

/** The sequence as CMML text. */
export function writeCMML(sequence) {
  const lines = ['<?xml version="1.0" encoding="UTF-8"?>', '<CMML>'];
  if (sequence.title) lines.push(`  <Title>${escapeXml(sequence.title)}</Title>`);
  for (const event of sequence.events) {
    for (const fold of event.folds) {
      lines.push('  <Fold>', `    <EventNumber>${event.number}</EventNumber>`, `    <ID>${fold.joint}</ID>`,
        `    <FoldAngle>${String(fold.angle)}</FoldAngle>`, `    <Velocity>${String(fold.speed)}</Velocity>`, '  </Fold>');
    }
  }
  lines.push('</CMML>', '');
  return lines.join('\n');
}

function unescapeXml(text) {
  return text.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"').replace(/&apos;/g, "'").replace(/&amp;/g, '&');
}

// The text of the first <tag>…</tag> in text[from, to) that holds no markup, trimmed (what the
// pattern <tag>([^<]*)</tag> finds); null when there is none. `tag`: ['<Tag>', '</Tag>']. Plain
// index searches: a 40 × 40 Miura-ori's fold is 309,000 <Fold> elements (49 MB), which regular
// expressions per field read in 0.35–0.7 s.
function field(text, from, to, [open, close]) {
  for (let at = text.indexOf(open, from); at >= 0 && at < to; at = text.indexOf(open, at + 1)) {
    const start = at + open.length, end = text.indexOf('<', start);
    if (end >= 0 && end + close.length <= to && text.startsWith(close, end)) return text.slice(start, end).trim();
  }
  return null;
}

const tag = (name) => [`<${name}>`, `</${name}>`];
const EVENT = tag('EventNumber'), ID = tag('ID'), ANGLE = tag('FoldAngle'), SPEED = tag('Velocity');

function number(text, from, to, which) {
  const value = field(text, from, to, which);
  if (value === null) throw new Error(`a <Fold> has no ${which[0]}`);
  return Number(value);
}

/**
 * Reads CMML piece by piece as it arrives (push each piece of text, then finish()), so that a
 * large file is read while it downloads: a piece is read up to its last complete </Fold>, the
 * rest waits for the next piece (as does a piece that ends inside a comment or a <Title>).
 * Reads what readCMML reads, whatever the pieces.
 */
export class CmmlReader {
  constructor() {
    this._pending = '';
    this._title = null;
    this._root = false;  // a <CMML> element seen
    // Per fold in file order: its event number, joint, angle and speed (packed() groups them).
    this._events = [];
    this._joints = [];
    this._angles = [];
    this._speeds = [];
  }

  /** Reads `text`, the next piece of the file. @throws {Error} on a <Fold> without a number */
  push(text) {
    const pending = (this._pending += text);
    let cut = pending.lastIndexOf('</Fold>');
    if (cut < 0) return;
    cut += 7;
    // A cut inside a comment or a title would read half of it: wait for more.
    const comment = pending.lastIndexOf('<!--', cut);
    const commentEnd = comment >= 0 ? pending.indexOf('-->', comment + 4) : 0;
    if (commentEnd < 0 || commentEnd + 3 > cut) return;
    const title = this._title === null ? pending.indexOf('<Title>') : -1;
    const titleEnd = title >= 0 && title < cut ? pending.indexOf('</Title>', title) : 0;
    if (titleEnd < 0 || titleEnd + 8 > cut) return;
    this._read(pending.slice(0, cut));
    this._pending = pending.slice(cut);
  }

  /** The sequence read. @throws {Error} when the text was not CMML */
  finish() {
    return unpackSequence(this.packed());
  }

  /** The sequence read, as flat arrays (see unpackSequence), to move between threads without
   * copying. @throws {Error} when the text was not CMML */
  packed() {
    this._read(this._pending);
    this._pending = '';
    if (!this._root) throw new Error('not a CMML file (no <CMML> element)');
    const numbers = Float64Array.from(new Set(this._events)).sort();
    const index = new Map(Array.from(numbers, (number, e) => [number, e]));
    const counts = new Uint32Array(numbers.length), next = new Uint32Array(numbers.length);
    for (const number of this._events) counts[index.get(number)]++;
    for (let e = 1; e < numbers.length; ++e) next[e] = next[e - 1] + counts[e - 1];
    const n = this._events.length, joints = new Float64Array(n), angles = new Float64Array(n), speeds = new Float64Array(n);
    for (let k = 0, e = -1, number = NaN; k < n; ++k) {
      if (this._events[k] !== number) e = index.get((number = this._events[k]));
      const at = next[e]++;
      joints[at] = this._joints[k];
      angles[at] = this._angles[k];
      speeds[at] = this._speeds[k];
    }
    return { title: this._title ?? '', numbers, counts, joints, angles, speeds };
  }

  _read(text) {
    const body = text.includes('<!--') ? text.replace(/<!--[\s\S]*?-->/g, '') : text;
    this._root ||= body.includes('<CMML>');
    if (this._title === null) {
      const title = body.match(/<Title>([\s\S]*?)<\/Title>/);
      if (title) this._title = unescapeXml(title[1].trim());
    }
    for (let at = body.indexOf('<Fold>'); at >= 0;) {
      const end = body.indexOf('</Fold>', at + 6);
      if (end < 0) break;
      const event = number(body, at, end, EVENT), joint = number(body, at, end, ID);
      const angle = number(body, at, end, ANGLE), speed = number(body, at, end, SPEED);
      if (!(Number.isFinite(event) && Number.isFinite(joint) && Number.isFinite(angle) && Number.isFinite(speed)))
        throw new Error('a <Fold> holds a value that is not a number');
      this._events.push(event);
      this._joints.push(joint);
      this._angles.push(angle);
      this._speeds.push(speed);
      at = body.indexOf('<Fold>', end + 7);
    }
  }
}

/** Reads CMML written by foldkit or by writeCMML (comments and the XML declaration allowed). */
export function readCMML(text) {
  const reader = new CmmlReader();
  reader._pending = text;
  return reader.finish();
}

/** The sequence of CmmlReader.packed()'s flat arrays: {title, numbers (per event, increasing),
 * counts (folds per event), joints, angles, speeds (per fold, event after event, each event's
 * in file order)}. */
export function unpackSequence(packed) {
  let k = 0;
  const events = Array.from(packed.numbers, (number, e) => {
    const folds = new Array(packed.counts[e]);
    for (let i = 0; i < folds.length; ++i, ++k) folds[i] = { joint: packed.joints[k], angle: packed.angles[k], speed: packed.speeds[k] };
    return { number, folds };
  });
  return { title: packed.title, events };
}

/** The angle (degrees) of every joint after each event: a joint keeps its angle until an event
 * names it. `jointIds` fixes the order; returns one array per event. */
export function anglesAfterEvents(sequence, jointIds) {
  const at = new Map(jointIds.map((id) => [id, 0]));
  return sequence.events.map((event) => {
    for (const fold of event.folds) if (at.has(fold.joint)) at.set(fold.joint, fold.angle);
    return jointIds.map((id) => at.get(id));
  });
}

/** Sets (or replaces) joint `joint`'s fold in the event numbered `number`, creating the event. */
export function setFold(sequence, number, fold) {
  let event = sequence.events.find((e) => e.number === number);
  if (!event) {
    event = { number, folds: [] };
    sequence.events.push(event);
    sequence.events.sort((a, b) => a.number - b.number);
  }
  event.folds = event.folds.filter((f) => f.joint !== fold.joint);
  event.folds.push(fold);
  return event;
}

function coordKey(p, scale) {
  return `${Math.round(p[0] / scale)},${Math.round(p[1] / scale)}`;
}

/** The frames of a FOLD trajectory (`foldkit simulate --frames`) as radians per joint in
 * foldkit's sign (positive = mountain; FOLD's is the opposite), matched to `joints` ({a, b} end
 * points) by the coordinates of their ends, which foldkit writes as read. Returns
 * {frames: Float64Array[], final: Float64Array, times: seconds per frame, or null}. */
export function foldFrameAngles(fold, joints) {
  const coords = fold.vertices_coords;
  let extent = 0;
  for (const p of coords) extent = Math.max(extent, Math.abs(p[0]), Math.abs(p[1]));
  const scale = Math.max(extent, 1e-300) * 1e-9;
  const edgeOf = new Map();
  fold.edges_vertices.forEach(([u, v], e) => {
    const a = coordKey(coords[u], scale);
    const b = coordKey(coords[v], scale);
    edgeOf.set(a < b ? `${a}|${b}` : `${b}|${a}`, e);
  });
  const index = joints.map((j) => {
    const a = coordKey([j.a.x, j.a.y], scale);
    const b = coordKey([j.b.x, j.b.y], scale);
    const e = edgeOf.get(a < b ? `${a}|${b}` : `${b}|${a}`);
    if (e === undefined) throw new Error(`joint ${j.id} has no edge in the trajectory: the pattern changed since it was simulated`);
    return e;
  });
  const toRadians = (degrees) => {
    const out = new Float64Array(index.length);
    index.forEach((e, k) => { out[k] = (0 - (degrees[e] || 0)) * Math.PI / 180; });  // 0 - x: never -0
    return out;
  };
  const frames = (fold.file_frames || []).map((f) => toRadians(f.edges_foldAngle || fold.edges_foldAngle));
  // foldkit simulate gives each frame its time ("foldkit:time"); other writers do not.
  const times = (fold.file_frames || []).map((f) => f['foldkit:time']);
  return { frames, final: toRadians(fold.edges_foldAngle || []), times: times.length && times.every(Number.isFinite) ? times : null };
}
