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

function field(block, tag) {
  const match = block.match(new RegExp(`<${tag}>([^<]*)</${tag}>`));
  if (!match) throw new Error(`a <Fold> has no <${tag}>`);
  return match[1].trim();
}

/** Reads CMML written by foldkit or by writeCMML (comments and the XML declaration allowed). */
export function readCMML(text) {
  const body = text.replace(/<!--[\s\S]*?-->/g, '');
  if (!/<CMML>/.test(body)) throw new Error('not a CMML file (no <CMML> element)');
  const title = unescapeXml((body.match(/<Title>([\s\S]*?)<\/Title>/) || [null, ''])[1].trim());
  const byNumber = new Map();
  for (const match of body.matchAll(/<Fold>([\s\S]*?)<\/Fold>/g)) {
    const number = Number(field(match[1], 'EventNumber'));
    const fold = { joint: Number(field(match[1], 'ID')), angle: Number(field(match[1], 'FoldAngle')),
      speed: Number(field(match[1], 'Velocity')) };
    if (![number, fold.joint, fold.angle, fold.speed].every(Number.isFinite)) throw new Error('a <Fold> holds a value that is not a number');
    if (!byNumber.has(number)) byNumber.set(number, []);
    byNumber.get(number).push(fold);
  }
  const events = [...byNumber.keys()].sort((a, b) => a - b).map((number) => ({ number, folds: byNumber.get(number) }));
  return { title, events };
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
