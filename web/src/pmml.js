// PMML, foldkit's crease-pattern file: reading its text into plain specs (the model builds
// itself from them) and the number formatting and escaping its writer uses.
import { parseXml } from './xml.js';

/** The crease assignments PMML allows: mountain, valley, flat, unassigned. */
export const ASSIGNMENTS = new Set(['M', 'V', 'F', 'U']);
/** The largest actor or joint ID foldkit reads (a 32-bit signed integer). */
export const INT_MAX = 2 ** 31 - 1;
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const INTEGER = /^[+-]?\d+$/;

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

function readInteger(el, expected = 'an integer') {
  const t = leafText(el);
  const v = INTEGER.test(t) ? Number(t) : NaN;
  if (!Number.isSafeInteger(v) || Math.abs(v) > INT_MAX) throw new Error(`${el.line}: <${el.name}> must be ${expected}, found '${t.slice(0, 40)}'`);
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

const JOINT_TAGS = new Set(['ID', 'Coords', 'ActorIDs', 'SpringConst', 'DampConst', 'Assignment', 'MaxTorque']);

// One number of an element that holds one (C++: "<X> must hold one number, found N").
function readNumber(el) {
  const values = readNumbers(el);
  if (values.length !== 1) throw new Error(`${el.line}: <${el.name}> must hold one number, found ${values.length}`);
  return values[0];
}

// foldkit's extensions for the dynamic model, children of <PMML> (docs/FORMATS.md), as the C++
// reader (io/src/pmml.cpp) reads them: each at most once, anywhere among the children; false for
// any other element. Their ranges (density positive, the fixed actor an actor of the pattern)
// are foldkit validate's to check, at their lines, as the C++ reader leaves them to build_pattern.
function readPhysics(el, physics) {
  const once = (set) => {
    if (set) throw new Error(`${el.line}: <PMML> has more than one <${el.name}>`);
  };
  if (el.name === 'Density') {
    once(physics.density !== null);
    physics.density = readNumber(el);
  } else if (el.name === 'Gravity') {
    once(physics.gravity !== null);
    physics.gravity = readNumbers(el, 3);
  } else if (el.name === 'FixedActor') {
    once(physics.fixedActor !== null);
    physics.fixedActor = readInteger(el, 'an actor ID');
  } else {
    return false;
  }
  return true;
}

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
  // foldkit's extension: the joint's motor torque limit in the dynamic model, N·m (foldkit
  // validate checks that it is positive, at its line).
  if (el.children.some((c) => c.name === 'MaxTorque')) joint.maxTorque = readNumber(onlyChild(el, 'MaxTorque'));
  return joint;
}

/**
 * Read PMML text into a spec: {title, actors: [{id, triangles: [{c: [6 numbers], line}], line}],
 * joints: [{id, coords: [4 numbers], actors: [2 IDs], spring, damping, assignment, maxTorque?, line}],
 * physics: {density, gravity: [x, y, z], fixedActor}} (foldkit's extensions, each null where the
 * file has none; a joint's maxTorque is absent where it has none).
 * Throws Error('LINE: message') on malformed input.
 */
export function readPMML(text) {
  const root = parseXml(text);
  if (root.name !== 'PMML') throw new Error(`${root.line}: the root element is <${root.name}>, expected <PMML>`);
  const spec = { title: '', actors: [], joints: [], physics: { density: null, gravity: null, fixedActor: null } };
  let titled = false;
  for (const c of elementsOf(root)) {
    if (c.name === 'Title') {
      if (titled) throw new Error(`${c.line}: <PMML> has more than one <Title>`);
      titled = true;
      spec.title = leafText(c);
    } else if (c.name === 'Actor') spec.actors.push(readActorSpec(c));
    else if (c.name === 'Joint') spec.joints.push(readJointSpec(c));
    else if (!readPhysics(c, spec.physics)) throw new Error(`${c.line}: unknown element <${c.name}> in <PMML>`);
  }
  return spec;
}

/** A finite number as PMML text; throws Error('toPMML: WHAT is not a finite number') otherwise. */
export function formatNumber(n, what) {
  if (!Number.isFinite(n)) throw new Error(`toPMML: ${what} is not a finite number`);
  return String(n); // shortest text that reads back to the same double
}

/** Text escaped for an XML element or a double-quoted attribute. */
export function escapeXml(text) {
  return text.replace(/[&<>"\r]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', '\r': '&#13;' })[c]);
}
