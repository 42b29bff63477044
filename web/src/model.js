// The crease-pattern model of the web editor: triangles grouped into actors, with joints on
// the edges that two different actors share. Pure: no DOM, no three.js, so node tests run it.

/** Default joint properties, as foldkit's generators write them. */
export const JOINT_DEFAULTS = Object.freeze({ spring: 1, damping: 0.1, assignment: 'U' });

/** Vertices closer than this fraction of the bounding-box diagonal are one vertex (foldkit's rule). */
export const MERGE_TOLERANCE = 1e-9;

const ASSIGNMENTS = new Set(['M', 'V', 'F', 'U']);
// Numeric edge keys (lo * 2^26 + hi) stay exact below 2^53 and avoid string garbage on big models.
const KEY_BASE = 2 ** 26;
const INT_MAX = 2 ** 31 - 1;
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const INTEGER = /^[+-]?\d+$/;

/** The key of the undirected edge between vertex indices a and b. */
export function edgeKey(a, b) {
  return a < b ? a * KEY_BASE + b : b * KEY_BASE + a;
}

function keyEnds(key) {
  const lo = Math.floor(key / KEY_BASE);
  return [lo, key - lo * KEY_BASE];
}

function cross3(a, b, c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

function dist(a, b) {
  return Math.hypot(a.x - b.x, a.y - b.y);
}

function boxOf(points, box = null) {
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

function toleranceOf(box) {
  if (!box) return 0;
  const d = Math.hypot(box.maxX - box.minX, box.maxY - box.minY);
  return Number.isFinite(d) ? MERGE_TOLERANCE * d : 0;
}

function checkPoint(p, what) {
  if (!p || !Number.isFinite(p.x) || !Number.isFinite(p.y)) throw new Error(`${what}: not a finite point`);
  return { x: p.x, y: p.y };
}

function formatNumber(n, what) {
  if (!Number.isFinite(n)) throw new Error(`toPMML: ${what} is not a finite number`);
  return String(n); // shortest text that reads back to the same double
}

function escapeXml(text) {
  return text.replace(/[&<>"\r]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', '\r': '&#13;' })[c]);
}

// Welds points into a shared vertex list with a uniform hash grid (first come, first kept),
// as foldkit's reader does, so that separately drawn triangles share their corners.
class Welder {
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

// Drops repeated consecutive corners (and a closing copy of the first), then refuses polygons
// that touch or cross themselves: ear clipping would produce overlapping triangles from them.
function cleanPolygon(points, tol) {
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

// ---------------------------------------------------------------------------------------------
// A small element-only XML reader: enough for PMML, and it works in node (no DOMParser).

const NAME = /[A-Za-z_:][-A-Za-z0-9_.:]*/y;
const ENTITY = /&(#x[0-9a-fA-F]+|#[0-9]+|amp|lt|gt|quot|apos);/y;
const NAMED = { amp: '&', lt: '<', gt: '>', quot: '"', apos: "'" };

class XmlReader {
  constructor(text) {
    this.text = text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
    this.pos = 0;
    this.newlines = [];
    for (let i = this.text.indexOf('\n'); i >= 0; i = this.text.indexOf('\n', i + 1)) this.newlines.push(i);
  }

  lineAt(pos) {
    let lo = 0, hi = this.newlines.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (this.newlines[mid] < pos) lo = mid + 1;
      else hi = mid;
    }
    return lo + 1;
  }

  fail(pos, message) {
    throw new Error(`${this.lineAt(pos)}: ${message}`);
  }

  startsWith(s) {
    return this.text.startsWith(s, this.pos);
  }

  skipPast(close, what) {
    const end = this.text.indexOf(close, this.pos);
    if (end < 0) this.fail(this.pos, `unterminated ${what}`);
    this.pos = end + close.length;
  }

  skipSpace() {
    while (this.pos < this.text.length && ' \t\r\n'.includes(this.text[this.pos])) ++this.pos;
  }

  name() {
    NAME.lastIndex = this.pos;
    const m = NAME.exec(this.text);
    if (!m) this.fail(this.pos, `expected a name after '${this.text.slice(this.pos - 1, this.pos)}'`);
    this.pos += m[0].length;
    return m[0];
  }

  decode(raw, at) {
    if (!raw.includes('&')) return raw;
    let out = '';
    for (let i = 0; i < raw.length; ) {
      const amp = raw.indexOf('&', i);
      if (amp < 0) {
        out += raw.slice(i);
        break;
      }
      out += raw.slice(i, amp);
      ENTITY.lastIndex = amp;
      const m = ENTITY.exec(raw);
      if (!m) this.fail(at + amp, `bad entity reference '${raw.slice(amp, amp + 12)}'`);
      const body = m[1];
      if (body[0] === '#') {
        const code = body[1] === 'x' ? parseInt(body.slice(2), 16) : parseInt(body.slice(1), 10);
        if (!(code > 0 && code <= 0x10ffff) || (code >= 0xd800 && code <= 0xdfff))
          this.fail(at + amp, `character reference '${m[0]}' is not allowed`);
        out += String.fromCodePoint(code);
      } else out += NAMED[body];
      i = amp + m[0].length;
    }
    return out;
  }

  // Comments, processing instructions and a DOCTYPE may stand around the root element.
  skipMisc() {
    for (;;) {
      this.skipSpace();
      if (this.startsWith('<!--')) this.skipPast('-->', 'comment');
      else if (this.startsWith('<?')) this.skipPast('?>', 'processing instruction');
      else if (this.startsWith('<!DOCTYPE')) {
        const close = this.text.indexOf('>', this.pos), bracket = this.text.indexOf('[', this.pos);
        if (bracket >= 0 && (close < 0 || bracket < close)) this.skipPast(']>', 'DOCTYPE');
        else this.skipPast('>', 'DOCTYPE');
      } else return;
    }
  }

  attributes(el) {
    for (;;) {
      const before = this.pos;
      this.skipSpace();
      const c = this.text[this.pos];
      if (c === '>' || (c === '/' && this.text[this.pos + 1] === '>') || c === undefined) return;
      if (this.pos === before) this.fail(this.pos, `expected '>' in <${el.name}>`);
      const attr = this.name();
      this.skipSpace();
      if (this.text[this.pos] !== '=') this.fail(this.pos, `attribute '${attr}' of <${el.name}> has no value`);
      ++this.pos;
      this.skipSpace();
      const q = this.text[this.pos];
      if (q !== '"' && q !== "'") this.fail(this.pos, `attribute '${attr}' of <${el.name}> is not quoted`);
      const end = this.text.indexOf(q, this.pos + 1);
      if (end < 0) this.fail(this.pos, `unterminated attribute '${attr}'`);
      el.attributes[attr] = this.decode(this.text.slice(this.pos + 1, end), this.pos + 1);
      this.pos = end + 1;
    }
  }

  /** The root element: {name, attributes, children, text, line}. */
  parse() {
    this.skipMisc();
    if (this.pos >= this.text.length) this.fail(this.pos, 'the file is empty');
    if (this.text[this.pos] !== '<') this.fail(this.pos, 'text before the root element');
    const stack = [];
    let root = null;
    while (this.pos < this.text.length) {
      const top = stack[stack.length - 1];
      if (this.text[this.pos] !== '<') {
        let end = this.text.indexOf('<', this.pos);
        if (end < 0) end = this.text.length;
        top.text += this.decode(this.text.slice(this.pos, end), this.pos);
        top.hasText ||= /\S/.test(this.text.slice(this.pos, end));
        this.pos = end;
      } else if (this.startsWith('<!--')) this.skipPast('-->', 'comment');
      else if (this.startsWith('<![CDATA[')) {
        const start = this.pos + 9;
        this.skipPast(']]>', 'CDATA section');
        top.text += this.text.slice(start, this.pos - 3);
        top.hasText = true;
      } else if (this.startsWith('<?')) this.skipPast('?>', 'processing instruction');
      else if (this.startsWith('</')) {
        const at = this.pos;
        this.pos += 2;
        const name = this.name();
        this.skipSpace();
        if (this.text[this.pos] !== '>') this.fail(this.pos, `expected '>' after </${name}`);
        ++this.pos;
        if (name !== top.name) this.fail(at, `expected </${top.name}> (opened at line ${top.line}), found </${name}>`);
        stack.pop();
        if (!stack.length) break;
      } else if (this.startsWith('<!')) this.fail(this.pos, "unexpected '<!'");
      else {
        const at = this.pos;
        ++this.pos;
        const el = { name: this.name(), attributes: {}, children: [], text: '', hasText: false, line: this.lineAt(at) };
        this.attributes(el);
        if (this.pos >= this.text.length) this.fail(at, `unterminated start tag <${el.name}>`);
        if (top) top.children.push(el);
        else root = el;
        if (this.text[this.pos] === '/') this.pos += 2;
        else {
          ++this.pos;
          stack.push(el);
        }
        if (!stack.length) break;
      }
    }
    if (stack.length) {
      const open = stack[stack.length - 1];
      throw new Error(`${open.line}: <${open.name}> is not closed`);
    }
    this.skipMisc();
    if (this.pos < this.text.length) this.fail(this.pos, 'content after the root element');
    return root;
  }
}

/** Parse XML text into {name, attributes, children, text, line} elements; throws Error('LINE: message'). */
export function parseXml(text) {
  return new XmlReader(String(text)).parse();
}

function leafText(el) {
  if (el.children.length) throw new Error(`${el.children[0].line}: <${el.name}> must hold text, not the element <${el.children[0].name}>`);
  return el.text.trim();
}

function elementsOf(el) {
  if (el.hasText) throw new Error(`${el.line}: unexpected text inside <${el.name}>`);
  return el.children;
}

function onlyChild(el, tag) {
  const found = elementsOf(el).filter((c) => c.name === tag);
  if (!found.length) throw new Error(`${el.line}: <${el.name}> has no <${tag}>`);
  if (found.length > 1) throw new Error(`${found[1].line}: <${el.name}> has more than one <${tag}>`);
  return found[0];
}

function readInteger(el) {
  const t = leafText(el);
  const v = INTEGER.test(t) ? Number(t) : NaN;
  if (!Number.isSafeInteger(v) || Math.abs(v) > INT_MAX) throw new Error(`${el.line}: <${el.name}> must be an integer, found '${t.slice(0, 40)}'`);
  return v;
}

function readNumbers(el, count) {
  const t = leafText(el);
  const tokens = t ? t.split(/[ \t\r\n]+/) : [];
  const values = tokens.map((tok) => {
    const v = NUMBER.test(tok) ? Number(tok) : NaN;
    if (!Number.isFinite(v)) throw new Error(`${el.line}: <${el.name}>: '${tok.slice(0, 40)}' is not a finite number`);
    return v;
  });
  if (count !== undefined && values.length !== count)
    throw new Error(`${el.line}: <${el.name}> needs ${count} number${count === 1 ? '' : 's'}, found ${values.length}`);
  return values;
}

function readActorSpec(el) {
  const actor = { id: readInteger(onlyChild(el, 'ID')), triangles: [], line: el.line };
  for (const c of elementsOf(el)) {
    if (c.name === 'ID') continue;
    if (c.name !== 'Triangle') throw new Error(`${c.line}: unknown element <${c.name}> in <Actor>`);
    actor.triangles.push({ c: readNumbers(c, 6), line: c.line });
  }
  if (!actor.triangles.length) throw new Error(`${el.line}: <Actor> ${actor.id} has no <Triangle>`);
  return actor;
}

const JOINT_TAGS = new Set(['ID', 'Coords', 'ActorIDs', 'SpringConst', 'DampConst', 'Assignment']);

function readJointSpec(el) {
  for (const c of elementsOf(el)) if (!JOINT_TAGS.has(c.name)) throw new Error(`${c.line}: unknown element <${c.name}> in <Joint>`);
  const ids = onlyChild(el, 'ActorIDs');
  const actorIds = leafText(ids).split(/\s+/).filter(Boolean);
  if (actorIds.length !== 2 || !actorIds.every((t) => INTEGER.test(t)))
    throw new Error(`${ids.line}: <ActorIDs> must hold two integer actor IDs`);
  const joint = {
    id: readInteger(onlyChild(el, 'ID')),
    coords: readNumbers(onlyChild(el, 'Coords'), 4),
    actors: actorIds.map(Number),
    spring: readNumbers(onlyChild(el, 'SpringConst'), 1)[0],
    damping: readNumbers(onlyChild(el, 'DampConst'), 1)[0],
    assignment: 'U',
    line: el.line,
  };
  if (el.children.some((c) => c.name === 'Assignment')) {
    const a = onlyChild(el, 'Assignment');
    joint.assignment = leafText(a);
    if (!ASSIGNMENTS.has(joint.assignment)) throw new Error(`${a.line}: <Assignment> must be M, V, F or U, found '${joint.assignment.slice(0, 40)}'`);
  }
  return joint;
}

function readPMML(text) {
  const root = parseXml(text);
  if (root.name !== 'PMML') throw new Error(`${root.line}: the root element is <${root.name}>, expected <PMML>`);
  const spec = { title: '', actors: [], joints: [] };
  let titled = false;
  for (const c of elementsOf(root)) {
    if (c.name === 'Title') {
      if (titled) throw new Error(`${c.line}: <PMML> has more than one <Title>`);
      titled = true;
      spec.title = leafText(c);
    } else if (c.name === 'Actor') spec.actors.push(readActorSpec(c));
    else if (c.name === 'Joint') spec.joints.push(readJointSpec(c));
    else throw new Error(`${c.line}: unknown element <${c.name}> in <PMML>`);
  }
  return spec;
}

// ---------------------------------------------------------------------------------------------

/**
 * A crease pattern: vertices, triangles (each in an actor) and joint properties keyed by edge.
 * Edits keep joint IDs stable: an edge's joint keeps its ID for as long as the edge exists.
 */
export class PatternModel {
  /** An empty pattern, optionally titled. */
  constructor({ title = '' } = {}) {
    /** @type {{x: number, y: number}[]} */
    this.vertices = [];
    /** @type {{v: number[], actor: number}[]} */
    this.triangles = [];
    this.title = title;
    /** Problems fromPMML tolerated (each 'LINE: message'); foldkit validate reports them as errors. */
    this.warnings = [];
    // Properties are kept for every edge that still exists, shared or not, so that an edge
    // that stops being a crease (group) and becomes one again (ungroup) keeps its ID.
    this._props = new Map();
    this._nextJointId = 1;
    this._version = 0;
    this._topo = null;
    this._joints = null;
  }

  /** A counter bumped by every edit: caches compare it. */
  get version() {
    return this._version;
  }

  /** Tell the model that vertices or triangles were changed directly (drops caches, assigns joint IDs). */
  touch() {
    this._commit();
  }

  // ------------------------------------------------------------------ reading and writing

  /** Parse PMML text; throws Error('LINE: message') on malformed input. */
  static fromPMML(text) {
    const spec = readPMML(text);
    const model = new PatternModel({ title: spec.title });
    const seenActor = new Map(), seenJoint = new Map();
    for (const a of spec.actors) {
      if (seenActor.has(a.id)) model.warnings.push(`${a.line}: duplicate actor ID ${a.id} (also at line ${seenActor.get(a.id)})`);
      else seenActor.set(a.id, a.line);
    }
    const corners = [];
    for (const a of spec.actors) for (const t of a.triangles) for (let k = 0; k < 6; k += 2) corners.push({ x: t.c[k], y: t.c[k + 1] });
    const tol = toleranceOf(boxOf(corners));
    const welder = new Welder(model.vertices, tol);
    for (const a of spec.actors)
      for (const t of a.triangles) {
        const v = [0, 2, 4].map((k) => welder.insert({ x: t.c[k], y: t.c[k + 1] }));
        if (v[0] === v[1] || v[1] === v[2] || v[0] === v[2]) model.warnings.push(`${t.line}: degenerate triangle dropped`);
        else model.triangles.push({ v, actor: a.id });
      }
    const topo = model._topology();
    const fresh = [];
    for (const j of spec.joints) {
      if (seenJoint.has(j.id)) {
        model.warnings.push(`${j.line}: duplicate joint ID ${j.id} (also at line ${seenJoint.get(j.id)}): given a new ID`);
      }
      const chain = model._traceSegment(welder, topo, { x: j.coords[0], y: j.coords[1] }, { x: j.coords[2], y: j.coords[3] });
      if (!chain) {
        model.warnings.push(`${j.line}: joint ${j.id} does not lie on edges of the triangles: dropped`);
        continue;
      }
      const props = { spring: j.spring, damping: j.damping, assignment: j.assignment };
      for (let k = 0; k + 1 < chain.length; ++k) {
        const key = edgeKey(chain[k], chain[k + 1]);
        if (model._props.has(key)) {
          model.warnings.push(`${j.line}: joint ${j.id} covers an edge another joint already covers`);
          continue;
        }
        const first = k === 0 && !seenJoint.has(j.id);
        model._props.set(key, { id: first ? j.id : 0, ...props });
        if (first) model._nextJointId = Math.max(model._nextJointId, j.id + 1);
        else fresh.push(key);
      }
      if (!seenJoint.has(j.id)) seenJoint.set(j.id, j.line);
    }
    // Further edges of a joint spanning collinear edges get new IDs once the file's IDs are known.
    for (const key of fresh) model._props.get(key).id = model._takeJointId();
    model._commit();
    return model;
  }

  /** PMML text: actors in ID order with their triangles, then one joint per edge shared by two actors. */
  toPMML() {
    const out = ['<?xml version="1.0" encoding="UTF-8"?>', '<PMML>'];
    if (this.title) out.push(`  <Title>${escapeXml(this.title)}</Title>`);
    const byActor = this._trianglesByActor();
    for (const id of [...byActor.keys()].sort((a, b) => a - b)) {
      out.push('  <Actor>', `    <ID>${id}</ID>`);
      for (const t of byActor.get(id)) {
        const c = this.triangles[t].v.map((i) => this.vertices[i]);
        const nums = c.flatMap((p) => [p.x, p.y]).map((n) => formatNumber(n, `actor ${id} triangle coordinate`));
        out.push(`    <Triangle>${nums.join(' ')}</Triangle>`);
      }
      out.push('  </Actor>');
    }
    for (const j of this.joints()) {
      const f = (n, what) => formatNumber(n, `joint ${j.id} ${what}`);
      out.push('  <Joint>', `    <ID>${j.id}</ID>`,
        `    <Coords>${[j.a.x, j.a.y, j.b.x, j.b.y].map((n) => f(n, 'coordinate')).join(' ')}</Coords>`,
        `    <ActorIDs>${j.actors[0]} ${j.actors[1]}</ActorIDs>`,
        `    <SpringConst>${f(j.spring, 'spring constant')}</SpringConst>`,
        `    <DampConst>${f(j.damping, 'damping constant')}</DampConst>`);
      if (j.assignment !== 'U') out.push(`    <Assignment>${j.assignment}</Assignment>`);
      out.push('  </Joint>');
    }
    out.push('</PMML>', '');
    return out.join('\n');
  }

  /** Plain JSON of the whole state (undo, saving editor state); flat arrays keep it small. */
  snapshot() {
    const vertices = new Array(this.vertices.length * 2);
    this.vertices.forEach((p, i) => {
      vertices[2 * i] = p.x;
      vertices[2 * i + 1] = p.y;
    });
    const triangles = new Array(this.triangles.length * 4);
    this.triangles.forEach((t, i) => {
      triangles[4 * i] = t.v[0];
      triangles[4 * i + 1] = t.v[1];
      triangles[4 * i + 2] = t.v[2];
      triangles[4 * i + 3] = t.actor;
    });
    const edges = [], spring = [], damping = [];
    let assignment = '';
    for (const [key, p] of this._props) {
      edges.push(...keyEnds(key), p.id);
      spring.push(p.spring);
      damping.push(p.damping);
      assignment += p.assignment;
    }
    return { title: this.title, vertices, triangles, joints: { edges, spring, damping, assignment }, nextJointId: this._nextJointId };
  }

  /** A model from snapshot(). */
  static fromSnapshot(obj) {
    const m = new PatternModel();
    m.restore(obj);
    return m;
  }

  /** Replace this model's state by a snapshot() in place (callers keep their reference). */
  restore(obj) {
    this.title = obj.title ?? '';
    this.vertices = [];
    for (let i = 0; i < obj.vertices.length; i += 2) this.vertices.push({ x: obj.vertices[i], y: obj.vertices[i + 1] });
    this.triangles = [];
    for (let i = 0; i < obj.triangles.length; i += 4)
      this.triangles.push({ v: [obj.triangles[i], obj.triangles[i + 1], obj.triangles[i + 2]], actor: obj.triangles[i + 3] });
    this._props = new Map();
    const j = obj.joints;
    for (let k = 0; k < j.spring.length; ++k)
      this._props.set(edgeKey(j.edges[3 * k], j.edges[3 * k + 1]),
        { id: j.edges[3 * k + 2], spring: j.spring[k], damping: j.damping[k], assignment: j.assignment[k] });
    this._nextJointId = obj.nextJointId;
    this.warnings = [];
    this._commit();
    return this;
  }

  /** An independent copy. */
  clone() {
    return PatternModel.fromSnapshot(this.snapshot());
  }

  // ------------------------------------------------------------------ queries

  /** Edges with their triangles (1 or 2, more in invalid input) and kind: 'boundary', 'joint' or 'internal'. Cached; do not mutate. */
  edges() {
    return this._topology().edges;
  }

  /** One joint per edge shared by two different actors, in ID order. Cached; do not mutate. */
  joints() {
    if (this._joints && this._joints.version === this._version) return this._joints.list;
    const list = [];
    for (const e of this.edges()) {
      if (e.kind !== 'joint') continue;
      const p = this._props.get(e.key);
      let [va, vb] = [e.i, e.j];
      const A = this.vertices[va], B = this.vertices[vb];
      // Coordinates in (x, y) order, not index order: the text then survives a read that renumbers.
      if (B.x < A.x || (B.x === A.x && B.y < A.y)) [va, vb] = [vb, va];
      const actors = e.triangles.map((t) => this.triangles[t].actor).sort((x, y) => x - y);
      list.push({ id: p.id, a: { ...this.vertices[va] }, b: { ...this.vertices[vb] }, va, vb, actors,
        spring: p.spring, damping: p.damping, assignment: p.assignment, key: e.key });
    }
    list.sort((x, y) => x.id - y.id);
    this._joints = { version: this._version, list, byId: new Map(list.map((j) => [j.id, j])) };
    return list;
  }

  /** The edge between vertices i and j (an element of edges()), or null. */
  edgeBetween(i, j) {
    return this._topology().byKey.get(edgeKey(i, j)) ?? null;
  }

  /** The joint on the edge between vertices i and j, or null. */
  jointOnEdge(i, j) {
    const e = this.edgeBetween(i, j);
    return e && e.kind === 'joint' ? this.joint(this._props.get(e.key).id) : null;
  }

  /** The joint with this ID, or null. */
  joint(id) {
    this.joints();
    return this._joints.byId.get(id) ?? null;
  }

  /** Set a joint's spring, damping and/or assignment ('M', 'V', 'F' or 'U'). */
  setJoint(id, { spring, damping, assignment } = {}) {
    const j = this.joint(id);
    if (!j) throw new Error(`no joint ${id}`);
    if (spring !== undefined && !(Number.isFinite(spring) && spring >= 0)) throw new Error('spring constant must be finite and non-negative');
    if (damping !== undefined && !(Number.isFinite(damping) && damping >= 0)) throw new Error('damping constant must be finite and non-negative');
    if (assignment !== undefined && !ASSIGNMENTS.has(assignment)) throw new Error('assignment must be M, V, F or U');
    const p = this._props.get(j.key);
    if (spring !== undefined) p.spring = spring;
    if (damping !== undefined) p.damping = damping;
    if (assignment !== undefined) p.assignment = assignment;
    this._version++;
    return this.joint(id);
  }

  /** Sorted actor IDs. */
  actors() {
    return [...this._trianglesByActor().keys()].sort((a, b) => a - b);
  }

  /** Indices of the triangles of an actor. */
  trianglesOf(actorId) {
    return this._trianglesByActor().get(actorId) ?? [];
  }

  /** The smallest actor ID above every one in use (1 for an empty model). */
  nextActorId() {
    let max = 0;
    for (const t of this.triangles) if (t.actor > max) max = t.actor;
    return max + 1;
  }

  /** Distance between vertices i and j. */
  length(i, j) {
    return dist(this.vertices[i], this.vertices[j]);
  }

  /** The angle i-j-k at vertex j, in degrees (0 to 180). */
  angleAt(i, j, k) {
    const a = this.vertices[i], b = this.vertices[j], c = this.vertices[k];
    const ux = a.x - b.x, uy = a.y - b.y, wx = c.x - b.x, wy = c.y - b.y;
    return (Math.atan2(Math.abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180) / Math.PI;
  }

  /** Area of triangle t (positive). */
  triangleArea(t) {
    const [a, b, c] = this.triangles[t].v.map((i) => this.vertices[i]);
    return Math.abs(cross3(a, b, c)) / 2;
  }

  /** {min: {x, y}, max: {x, y}, minX, minY, maxX, maxY} of the vertices triangles use, or null when there are none. */
  bounds() {
    const b = boxOf(this._usedPoints());
    return b && { min: { x: b.minX, y: b.minY }, max: { x: b.maxX, y: b.maxY }, ...b };
  }

  /** The vertex-merge tolerance now (1e-9 × bounding-box diagonal). */
  tolerance() {
    return toleranceOf(boxOf(this._usedPoints()));
  }

  /** Index of the nearest vertex within radius of p, or -1. */
  nearestVertex(p, radius = Infinity) {
    let best = -1, bestD = radius;
    const used = this._usedVertices();
    for (let i = 0; i < this.vertices.length; ++i) {
      if (!used[i]) continue;
      const d = dist(this.vertices[i], p);
      if (d <= bestD) {
        best = i;
        bestD = d;
      }
    }
    return best;
  }

  /** The nearest edge within radius of p: {i, j, t, distance} (t along i→j), or null. */
  nearestEdge(p, radius = Infinity) {
    let best = null;
    for (const e of this.edges()) {
      const a = this.vertices[e.i], b = this.vertices[e.j];
      const dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const t = len2 > 0 ? Math.min(1, Math.max(0, ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2)) : 0;
      const d = Math.hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
      if (d <= radius && (!best || d < best.distance)) best = { i: e.i, j: e.j, t, distance: d };
    }
    return best;
  }

  /** Index of a triangle containing p (boundary included), or -1. */
  triangleAt(p) {
    for (let t = 0; t < this.triangles.length; ++t) {
      const [a, b, c] = this.triangles[t].v.map((i) => this.vertices[i]);
      const s = Math.sign(cross3(a, b, c));
      const eps = 1e-12 * (Math.abs(a.x) + Math.abs(a.y) + 1);
      if (cross3(a, b, p) * s >= -eps && cross3(b, c, p) * s >= -eps && cross3(c, a, p) * s >= -eps) return t;
    }
    return -1;
  }

  // ------------------------------------------------------------------ adding geometry

  /** Triangulate a simple polygon (ear clipping) into actorId or a new actor; returns new triangle indices. */
  addPolygon(points, actorId = undefined) {
    const box = boxOf(points.map((p) => checkPoint(p, 'polygon corner')));
    const pts = cleanPolygon(points, toleranceOf(boxOf(this._usedPoints(), box)));
    if (signedArea(pts) < 0) pts.reverse(); // counter-clockwise triangles, as foldkit stores them
    const tris = earClip(pts, toleranceOf(box));
    const actor = actorId ?? this.nextActorId();
    return this._addAndCommit(pts, tris.map((v) => ({ v, actor })));
  }

  /** Add one triangle (a new actor unless actorId is given); returns [its index]. */
  addTriangle(p, q, r, actorId = undefined) {
    const pts = [checkPoint(p, 'triangle corner'), checkPoint(q, 'triangle corner'), checkPoint(r, 'triangle corner')];
    const tol = toleranceOf(boxOf(pts));
    if (Math.abs(cross3(...pts)) <= tol * Math.max(dist(pts[0], pts[1]), dist(pts[1], pts[2]), dist(pts[2], pts[0])))
      throw new Error('degenerate triangle (zero area)');
    if (cross3(...pts) < 0) pts.reverse();
    return this._addAndCommit(pts, [{ v: [0, 1, 2], actor: actorId ?? this.nextActorId() }]);
  }

  /**
   * A cols × rows lattice filling the rectangle from (x, y) of size w × h. Each cell is one actor;
   * with diagonals ('/', '\\' or 'x') every triangle is its own actor so the diagonals are creases.
   * Returns the new triangle indices.
   */
  addGrid({ x = 0, y = 0, cols = 1, rows = 1, w = 1, h = 1, diagonals = 'none' } = {}) {
    if (!(Number.isInteger(cols) && cols >= 1 && Number.isInteger(rows) && rows >= 1)) throw new Error('cols and rows must be positive integers');
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(w) && Number.isFinite(h)) || w === 0 || h === 0)
      throw new Error('the grid needs a finite, non-empty rectangle');
    if (!['none', '/', '\\', 'x'].includes(diagonals)) throw new Error("diagonals must be 'none', '/', '\\\\' or 'x'");
    if (w < 0) [x, w] = [x + w, -w];
    if (h < 0) [y, h] = [y + h, -h];
    const pts = [];
    const at = (c, r) => r * (cols + 1) + c;
    for (let r = 0; r <= rows; ++r)
      for (let c = 0; c <= cols; ++c) pts.push({ x: c === cols ? x + w : x + (c * w) / cols, y: r === rows ? y + h : y + (r * h) / rows });
    let actor = this.nextActorId();
    const tris = [];
    for (let r = 0; r < rows; ++r)
      for (let c = 0; c < cols; ++c) {
        const p00 = at(c, r), p10 = at(c + 1, r), p11 = at(c + 1, r + 1), p01 = at(c, r + 1);
        if (diagonals === 'x') {
          pts.push({ x: (pts[p00].x + pts[p10].x) / 2, y: (pts[p00].y + pts[p01].y) / 2 });
          const m = pts.length - 1;
          for (const [a, b] of [[p00, p10], [p10, p11], [p11, p01], [p01, p00]]) tris.push({ v: [a, b, m], actor: actor++ });
        } else if (diagonals === '\\') {
          tris.push({ v: [p00, p10, p01], actor }, { v: [p10, p11, p01], actor: actor + 1 });
          actor += 2;
        } else {
          const split = diagonals === '/';
          tris.push({ v: [p00, p10, p11], actor }, { v: [p00, p11, p01], actor: split ? actor + 1 : actor });
          actor += split ? 2 : 1;
        }
      }
    return this._addAndCommit(pts, tris);
  }

  /**
   * A circular lattice at (x, y): `rings` rings of equal width up to `radius`, crossed by `spokes`
   * spokes; one actor per cell, the centre cells triangles. Returns the new triangle indices.
   */
  addCircular({ x = 0, y = 0, rings = 1, spokes = 6, radius = 1 } = {}) {
    if (!(Number.isInteger(rings) && rings >= 1)) throw new Error('rings must be a positive integer');
    if (!(Number.isInteger(spokes) && spokes >= 3)) throw new Error('spokes must be an integer of at least 3');
    if (!(Number.isFinite(radius) && radius > 0 && Number.isFinite(x) && Number.isFinite(y))) throw new Error('radius must be positive');
    const pts = [{ x, y }];
    const at = (ring, s) => 1 + (ring - 1) * spokes + (s % spokes);
    const width = radius / rings;
    for (let ring = 1; ring <= rings; ++ring)
      for (let s = 0; s < spokes; ++s) {
        const angle = (2 * Math.PI * s) / spokes;
        pts.push({ x: x + ring * width * Math.cos(angle), y: y + ring * width * Math.sin(angle) });
      }
    let actor = this.nextActorId();
    const tris = [];
    for (let s = 0; s < spokes; ++s) tris.push({ v: [0, at(1, s), at(1, s + 1)], actor: actor++ });
    const d2 = (i, j) => (pts[i].x - pts[j].x) ** 2 + (pts[i].y - pts[j].y) ** 2;
    for (let ring = 1; ring < rings; ++ring)
      for (let s = 0; s < spokes; ++s, ++actor) {
        const q = [at(ring, s), at(ring + 1, s), at(ring + 1, s + 1), at(ring, s + 1)];
        // The shorter diagonal, ties to q0-q2, as foldkit's generator splits its quads.
        const [p0, p1, p2, p3] = d2(q[0], q[2]) <= d2(q[1], q[3]) ? q : [q[1], q[2], q[3], q[0]];
        tris.push({ v: [p0, p1, p2], actor }, { v: [p0, p2, p3], actor });
      }
    return this._addAndCommit(pts, tris);
  }

  /** Copy triangles into a clipboard object: their corners, actor grouping and joint properties. */
  copyTriangles(indices) {
    const vmap = new Map(), vertices = [], groups = new Map(), triangles = [];
    const set = new Set(indices);
    for (const t of [...set].sort((a, b) => a - b)) {
      const tri = this.triangles[t];
      if (!tri) continue;
      const v = tri.v.map((i) => {
        if (!vmap.has(i)) {
          vmap.set(i, vertices.length);
          vertices.push({ ...this.vertices[i] });
        }
        return vmap.get(i);
      });
      if (!groups.has(tri.actor)) groups.set(tri.actor, groups.size);
      triangles.push({ v, group: groups.get(tri.actor) });
    }
    const edges = [];
    for (const e of this.edges()) {
      const p = this._props.get(e.key);
      if (p && e.kind === 'joint' && e.triangles.every((t) => set.has(t)))
        edges.push({ a: vmap.get(e.i), b: vmap.get(e.j), spring: p.spring, damping: p.damping, assignment: p.assignment });
    }
    return { vertices, triangles, edges, bounds: boxOf(vertices) };
  }

  /** Paste a clipboard moved by (dx, dy): one new actor per copied actor; returns new triangle indices. */
  paste(clipboard, dx = 0, dy = 0) {
    const pts = clipboard.vertices.map((p) => ({ x: p.x + dx, y: p.y + dy }));
    const first = this.nextActorId();
    const tris = clipboard.triangles.map((t) => ({ v: [...t.v], actor: first + t.group }));
    const { triangles, vmap } = this._add(pts, tris);
    const topo = this._topology();
    for (const e of clipboard.edges ?? []) {
      const key = edgeKey(vmap[e.a], vmap[e.b]);
      const edge = topo.byKey.get(key);
      if (edge && edge.kind === 'joint' && !this._props.has(key))
        this._props.set(key, { id: this._takeJointId(), spring: e.spring, damping: e.damping, assignment: e.assignment });
    }
    this._commit();
    return triangles;
  }

  // ------------------------------------------------------------------ editing

  /** Delete triangles (and the vertices no triangle uses any more); returns how many were deleted. */
  deleteTriangles(indices) {
    const drop = new Set([...indices].filter((t) => t >= 0 && t < this.triangles.length));
    if (!drop.size) return 0;
    this.triangles = this.triangles.filter((_, t) => !drop.has(t));
    this._compact();
    this._commit();
    return drop.size;
  }

  /** Move vertices by (dx, dy), then weld them onto unmoved vertices they land on; returns their new indices. */
  moveVertices(indices, dx, dy) {
    if (!Number.isFinite(dx) || !Number.isFinite(dy)) throw new Error('moveVertices: not a finite offset');
    const set = new Set(indices);
    for (const i of set) {
      this.vertices[i].x += dx;
      this.vertices[i].y += dy;
    }
    return this._settle(set);
  }

  /**
   * Mirror ('x' flips x, 'y' flips y), scale and rotate (radians, counter-clockwise) vertices about
   * a point (default: the centre of their bounding box); returns their new indices.
   */
  transformVertices(indices, { rotate = 0, scale = 1, mirror = null, about = null } = {}) {
    const set = new Set(indices);
    if (!set.size) return [];
    if (!Number.isFinite(rotate) || !Number.isFinite(scale) || scale === 0) throw new Error('transformVertices: bad rotation or scale');
    if (mirror !== null && mirror !== 'x' && mirror !== 'y') throw new Error("mirror must be 'x' or 'y'");
    const box = boxOf([...set].map((i) => this.vertices[i]));
    const o = about ?? { x: (box.minX + box.maxX) / 2, y: (box.minY + box.maxY) / 2 };
    const c = Math.cos(rotate), s = Math.sin(rotate);
    const mx = mirror === 'x' ? -1 : 1, my = mirror === 'y' ? -1 : 1;
    for (const i of set) {
      const p = this.vertices[i];
      const x = (p.x - o.x) * mx * scale, y = (p.y - o.y) * my * scale;
      p.x = o.x + c * x - s * y;
      p.y = o.y + s * x + c * y;
    }
    // A mirrored triangle would turn clockwise; keep the orientation the triangle had.
    if (mx * my < 0)
      for (const t of this.triangles) if (t.v.every((i) => set.has(i))) [t.v[1], t.v[2]] = [t.v[2], t.v[1]];
    return this._settle(set);
  }

  /** Merge vertex j into vertex i, dropping triangles that collapse; returns i's index afterwards. */
  mergeVertices(i, j) {
    if (i === j) return i;
    if (!this.vertices[i] || !this.vertices[j]) throw new Error('mergeVertices: no such vertex');
    const map = new Int32Array(this.vertices.length).map((_, k) => k);
    map[j] = i;
    this._remap(map);
    const renumber = this._compact();
    this._commit();
    return renumber[i];
  }

  /** Insert a vertex at t along edge i→j and split the triangles using that edge; returns its index. */
  splitEdge(i, j, t = 0.5) {
    if (!(t > 0 && t < 1)) throw new Error('splitEdge: t must lie strictly between 0 and 1');
    const edge = this._topology().byKey.get(edgeKey(i, j));
    if (!edge) throw new Error(`no edge between vertices ${i} and ${j}`);
    const a = this.vertices[i], b = this.vertices[j];
    const tol = this.tolerance();
    this.vertices.push({ x: a.x + t * (b.x - a.x), y: a.y + t * (b.y - a.y) });
    const m = this.vertices.length - 1;
    // The piece at i keeps the joint's ID; the piece at j gets a new ID with the same properties.
    const props = this._props.get(edge.key);
    this._props.delete(edge.key);
    for (const ti of edge.triangles) this._splitTriangle(ti, new Map([[edge.key, [m]]]), tol);
    if (props) {
      this._props.set(edgeKey(i, m), props);
      this._props.set(edgeKey(m, j), { ...props, id: this._takeJointId() });
    }
    this._commit();
    return m;
  }

  /** Put triangles into one new actor (the next free ID); returns that ID. */
  group(triangleIndices) {
    const id = this.nextActorId();
    for (const t of triangleIndices) if (this.triangles[t]) this.triangles[t].actor = id;
    this._commit();
    return id;
  }

  /** Make each triangle of an actor its own actor (the first keeps the ID); returns the actor IDs. */
  ungroup(actorId) {
    const tris = this.trianglesOf(actorId);
    let next = this.nextActorId();
    const ids = tris.map((t, k) => (k === 0 ? actorId : next++));
    tris.forEach((t, k) => (this.triangles[t].actor = ids[k]));
    this._commit();
    return ids;
  }

  // ------------------------------------------------------------------ internals

  _commit() {
    this._version++;
    this._topo = null;
    this._joints = null;
    this._byActor = null;
    this._used = null;
    this._syncJoints();
  }

  _takeJointId() {
    if (this._nextJointId > INT_MAX) {
      // Past foldkit's integer range, reuse the smallest free positive ID instead.
      const used = new Set([...this._props.values()].map((p) => p.id));
      let id = 1;
      while (used.has(id)) ++id;
      return id;
    }
    return this._nextJointId++;
  }

  // Forget properties of edges that no longer exist; give every new shared edge the next ID.
  _syncJoints() {
    const topo = this._topology();
    for (const key of this._props.keys()) if (!topo.byKey.has(key)) this._props.delete(key);
    for (const e of topo.edges)
      if (e.kind === 'joint' && !this._props.has(e.key)) this._props.set(e.key, { id: this._takeJointId(), ...JOINT_DEFAULTS });
  }

  _topology() {
    if (this._topo && this._topo.version === this._version) return this._topo;
    const byKey = new Map(), edges = [];
    this.triangles.forEach((tri, t) => {
      for (let k = 0; k < 3; ++k) {
        const a = tri.v[k], b = tri.v[(k + 1) % 3], key = edgeKey(a, b);
        let e = byKey.get(key);
        if (!e) {
          e = { i: Math.min(a, b), j: Math.max(a, b), key, triangles: [], kind: 'boundary' };
          byKey.set(key, e);
          edges.push(e);
        }
        e.triangles.push(t);
      }
    });
    for (const e of edges) {
      if (e.triangles.length !== 2) continue;
      e.kind = this.triangles[e.triangles[0]].actor !== this.triangles[e.triangles[1]].actor ? 'joint' : 'internal';
    }
    this._topo = { version: this._version, edges, byKey };
    return this._topo;
  }

  _trianglesByActor() {
    if (this._byActor && this._byActor.version === this._version) return this._byActor.map;
    const map = new Map();
    this.triangles.forEach((t, i) => {
      const list = map.get(t.actor);
      if (list) list.push(i);
      else map.set(t.actor, [i]);
    });
    this._byActor = { version: this._version, map };
    return map;
  }

  _usedVertices() {
    if (this._used && this._used.version === this._version && this._used.flags.length === this.vertices.length) return this._used.flags;
    const flags = new Uint8Array(this.vertices.length);
    for (const t of this.triangles) for (const i of t.v) flags[i] = 1;
    this._used = { version: this._version, flags };
    return flags;
  }

  _usedPoints() {
    const used = this._usedVertices();
    return this.vertices.filter((_, i) => used[i]);
  }

  // Follows edges along a joint's segment from one end to the other: a joint may span several
  // collinear edges when a vertex lies on it.
  _traceSegment(welder, topo, p, q) {
    const v0 = welder.find(p), v1 = welder.find(q);
    if (v0 < 0 || v1 < 0 || v0 === v1) return null;
    if (topo.byKey.has(edgeKey(v0, v1))) return [v0, v1];
    if (!topo.neighbours) {
      topo.neighbours = new Map();
      for (const e of topo.edges) {
        for (const [a, b] of [[e.i, e.j], [e.j, e.i]]) {
          if (!topo.neighbours.has(a)) topo.neighbours.set(a, []);
          topo.neighbours.get(a).push(b);
        }
      }
    }
    const o = this.vertices[v0], end = this.vertices[v1];
    const len = dist(o, end), dx = (end.x - o.x) / len, dy = (end.y - o.y) / len, tol = welder.tol;
    const chain = [v0];
    let cur = v0, reached = 0;
    while (cur !== v1) {
      let next = -1, nextAlong = Infinity;
      for (const w of topo.neighbours.get(cur) ?? []) {
        const rx = this.vertices[w].x - o.x, ry = this.vertices[w].y - o.y;
        const along = rx * dx + ry * dy;
        if (Math.abs(dx * ry - dy * rx) <= tol && along > reached + tol && along <= len + tol && along < nextAlong) {
          next = w;
          nextAlong = along;
        }
      }
      if (next < 0) return null;
      chain.push(next);
      cur = next;
      reached = nextAlong;
    }
    return chain;
  }

  _addAndCommit(points, tris) {
    const { triangles } = this._add(points, tris);
    this._commit();
    return triangles;
  }

  // Welds the points onto existing vertices, adds the triangles (dropping ones that collapse),
  // then splits edges where a vertex lies inside another's boundary edge, so that triangles
  // always meet corner to corner. Does not commit.
  _add(points, tris) {
    const tol = toleranceOf(boxOf(points, boxOf(this._usedPoints())));
    const start = this.vertices.length;
    const welder = new Welder(this.vertices, tol, this._unusedSet());
    const vmap = points.map((p) => welder.insert(checkPoint(p, 'corner')));
    const added = new Set();
    for (const t of tris) {
      const v = t.v.map((k) => vmap[k]);
      if (v[0] === v[1] || v[1] === v[2] || v[0] === v[2]) continue;
      this.triangles.push({ v, actor: t.actor });
      added.add(this.triangles.length - 1);
    }
    this._version++;
    const moved = new Set();
    for (let i = start; i < this.vertices.length; ++i) moved.add(i);
    this._fixTJunctions(added, moved, tol);
    return { triangles: [...added].sort((a, b) => a - b), vmap };
  }

  _unusedSet() {
    const used = this._usedVertices(), set = new Set();
    for (let i = 0; i < this.vertices.length; ++i) if (!used[i]) set.add(i);
    return set;
  }

  // Boundary edges of changed triangles against every vertex, and every boundary edge against
  // changed vertices: a vertex strictly inside such an edge splits the triangle that owns it.
  _fixTJunctions(changedTris, changedVertices, tol) {
    if (!(tol > 0)) return;
    const topo = this._topology();
    const used = this._usedVertices();
    const all = [];
    for (let i = 0; i < this.vertices.length; ++i) if (used[i]) all.push(i);
    const changed = [...changedVertices].filter((i) => used[i]);
    const splits = new Map(); // triangle → Map(edge key → [vertex indices along the edge])
    for (const e of topo.edges) {
      if (e.triangles.length !== 1) continue;
      const t = e.triangles[0];
      const candidates = changedTris.has(t) || changedVertices.has(e.i) || changedVertices.has(e.j) ? all : changed;
      const inside = this._verticesInside(e.i, e.j, candidates, tol);
      if (!inside.length) continue;
      if (!splits.has(t)) splits.set(t, new Map());
      splits.get(t).set(e.key, inside);
    }
    for (const [t, edgeSplits] of splits) {
      const created = this._splitTriangle(t, edgeSplits, tol);
      if (changedTris.has(t)) for (const c of created) changedTris.add(c);
    }
  }

  // Vertex indices strictly inside segment i→j, ordered from i to j.
  _verticesInside(i, j, candidates, tol) {
    const a = this.vertices[i], b = this.vertices[j];
    const len = dist(a, b);
    if (!(len > 2 * tol)) return [];
    const dx = (b.x - a.x) / len, dy = (b.y - a.y) / len;
    const minX = Math.min(a.x, b.x) - tol, maxX = Math.max(a.x, b.x) + tol;
    const minY = Math.min(a.y, b.y) - tol, maxY = Math.max(a.y, b.y) + tol;
    const found = [];
    for (const v of candidates) {
      if (v === i || v === j) continue;
      const p = this.vertices[v];
      if (p.x < minX || p.x > maxX || p.y < minY || p.y > maxY) continue;
      const rx = p.x - a.x, ry = p.y - a.y, along = rx * dx + ry * dy;
      if (Math.abs(dx * ry - dy * rx) <= tol && along > tol && along < len - tol) found.push([along, v]);
    }
    return found.sort((x, y) => x[0] - y[0]).map((f) => f[1]);
  }

  // Replaces triangle t by the triangulation of its outline with extra vertices on its edges
  // (edgeSplits: edge key → vertices ordered along the edge, from either end). Joint properties
  // of a split edge pass to its pieces: the first piece keeps the ID, the others get new IDs.
  // Returns the indices of the triangles added besides t.
  _splitTriangle(t, edgeSplits, tol) {
    const tri = this.triangles[t];
    const ring = [];
    for (let k = 0; k < 3; ++k) {
      const a = tri.v[k], b = tri.v[(k + 1) % 3], key = edgeKey(a, b);
      ring.push(a);
      let mids = edgeSplits.get(key);
      if (!mids) continue;
      const from = (i) => dist(this.vertices[i], this.vertices[a]);
      if (mids.length > 1 && from(mids[0]) > from(mids[mids.length - 1])) mids = [...mids].reverse();
      ring.push(...mids);
      const p = this._props.get(key);
      if (p) {
        this._props.delete(key);
        const chain = [a, ...mids, b];
        for (let s = 0; s + 1 < chain.length; ++s) {
          const k2 = edgeKey(chain[s], chain[s + 1]);
          if (!this._props.has(k2)) this._props.set(k2, { ...p, id: s === 0 ? p.id : this._takeJointId() });
        }
      }
    }
    const pts = ring.map((i) => this.vertices[i]);
    const sign = Math.sign(cross3(...tri.v.map((i) => this.vertices[i])));
    const pieces = earClip(pts, tol).map((v) => {
      const tr = v.map((k) => ring[k]);
      if (Math.sign(cross3(...tr.map((i) => this.vertices[i]))) !== sign) [tr[1], tr[2]] = [tr[2], tr[1]];
      return tr;
    });
    tri.v = pieces[0];
    const created = [];
    for (let k = 1; k < pieces.length; ++k) {
      this.triangles.push({ v: pieces[k], actor: tri.actor });
      created.push(this.triangles.length - 1);
    }
    this._version++;
    return created;
  }

  // After a move: weld moved vertices onto unmoved ones they now touch, drop collapsed
  // triangles, split edges the moved geometry now touches, and renumber.
  _settle(set) {
    const tol = this.tolerance();
    const used = this._usedVertices();
    const skip = new Set();
    for (let i = 0; i < this.vertices.length; ++i) if (set.has(i) || !used[i]) skip.add(i);
    const welder = new Welder(this.vertices, tol, skip);
    const map = new Int32Array(this.vertices.length).map((_, k) => k);
    let welded = false;
    for (const i of set) {
      const target = welder.find(this.vertices[i]);
      if (target >= 0) {
        map[i] = target;
        welded = true;
      }
    }
    if (welded) this._remap(map);
    else this._version++;
    const movedVertices = new Set([...set].map((i) => map[i]));
    const movedTris = new Set();
    this.triangles.forEach((t, k) => {
      if (t.v.some((i) => movedVertices.has(i))) movedTris.add(k);
    });
    this._fixTJunctions(movedTris, movedVertices, tol);
    const renumber = this._compact();
    this._commit();
    return [...set].map((i) => renumber[map[i]]);
  }

  // Applies a vertex map (old → new index) to triangles and joint properties; drops triangles
  // that collapse and exact duplicates. Neither compacts nor commits.
  _remap(map) {
    const seen = new Set();
    this.triangles = this.triangles.filter((t) => {
      t.v = t.v.map((i) => map[i]);
      const [a, b, c] = t.v;
      if (a === b || b === c || a === c) return false;
      const key = [a, b, c].sort((x, y) => x - y).join(',');
      if (seen.has(key)) return false;
      seen.add(key);
      return true;
    });
    const props = new Map();
    // Properties of an edge that already had a key at its destination win over moved ones.
    const entries = [...this._props].sort(([k1], [k2]) => {
      const [a1, b1] = keyEnds(k1), [a2, b2] = keyEnds(k2);
      return Number(map[a1] !== a1 || map[b1] !== b1) - Number(map[a2] !== a2 || map[b2] !== b2);
    });
    for (const [key, p] of entries) {
      const [a, b] = keyEnds(key);
      const na = map[a], nb = map[b];
      if (na === nb) continue;
      const k = edgeKey(na, nb);
      if (!props.has(k)) props.set(k, p);
    }
    this._props = props;
    this._version++;
  }

  // Drops vertices no triangle uses; returns the old → new index map.
  _compact() {
    const n = this.vertices.length;
    const used = new Uint8Array(n);
    for (const t of this.triangles) for (const i of t.v) used[i] = 1;
    const map = new Int32Array(n).fill(-1);
    const vertices = [];
    for (let i = 0; i < n; ++i)
      if (used[i]) {
        map[i] = vertices.length;
        vertices.push(this.vertices[i]);
      }
    if (vertices.length === n) return map;
    this.vertices = vertices;
    for (const t of this.triangles) t.v = t.v.map((i) => map[i]);
    const props = new Map();
    for (const [key, p] of this._props) {
      const [a, b] = keyEnds(key);
      if (map[a] >= 0 && map[b] >= 0) props.set(edgeKey(map[a], map[b]), p);
    }
    this._props = props;
    this._version++;
    return map;
  }
}

// ---------------------------------------------------------------------------------------------

/** Bounded undo/redo stack of snapshots: push the state after every edit, the initial one too. */
export class History {
  /** An empty history keeping at most `limit` states. */
  constructor(limit = 200) {
    this.limit = limit;
    this._states = [];
    this._index = -1;
  }

  /** Record a state; drops any redo states and the oldest state past the limit. */
  push(snapshot) {
    this._states.length = this._index + 1;
    this._states.push(snapshot);
    if (this._states.length > this.limit) this._states.splice(0, this._states.length - this.limit);
    this._index = this._states.length - 1;
  }

  /** The state before the current one (now current), or null. */
  undo() {
    if (!this.canUndo) return null;
    return this._states[--this._index];
  }

  /** The state after the current one (now current), or null. */
  redo() {
    if (!this.canRedo) return null;
    return this._states[++this._index];
  }

  /** The current state, or null. */
  get current() {
    return this._states[this._index] ?? null;
  }

  /** Whether undo() has a state to return. */
  get canUndo() {
    return this._index > 0;
  }

  /** Whether redo() has a state to return. */
  get canRedo() {
    return this._index < this._states.length - 1;
  }

  /** Forget every state. */
  clear() {
    this._states = [];
    this._index = -1;
  }
}

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
