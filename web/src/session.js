// One pattern being edited and its files under the server's root: NAME.pmml, NAME.cmml,
// NAME-frames.fold, … Every number the page shows comes back from foldkit through these calls.
import * as api from './api.js';
import { writeCMML, CmmlReader, unpackSequence, foldFrameAngles } from './cmml.js';
import { readSequenceAside } from './reader.js';
import { PatternModel } from './model.js';
import { formatOf, extensions } from './formats.js';
import { PHYSICS_MODEL } from './physics.js';

/** Files of the session named `name` in `folder` (relative to the server's root); the page writes
 * and overwrites them as it goes. */
export function sessionFiles(name, folder = '') {
  const base = (folder ? `${folder}/` : '') + name;
  return {
    pattern: `${base}.pmml`, sequence: `${base}.cmml`, frames: `${base}-frames.fold`, state: `${base}-state.cmml`,
    folded: `${base}-fold.cmml`, plan: `${base}-plan.cmml`, loadcase: `${base}.loadcase`, fold: `${base}.fold`, svg: `${base}.svg`,
    series: `${base}-series.json`, start: `${base}-start.cmml`,
  };
}

/** Where foldkit reads `sequence` from: the file it came from while unedited (`sequence.file`,
 * a fold of a large sheet is tens of MB), else the session's CMML, written now. Folds of joints
 * the pattern no longer has (an edit removed them; undo may bring them back) are left out of
 * what foldkit reads. */
export async function sequencePath(sequence, files, model) {
  const alive = new Set(model.joints().map((j) => j.id));
  const live = sequence.events.map((e) => ({ number: e.number, folds: e.folds.filter((f) => alive.has(f.joint)) }))
    .filter((e) => e.folds.length);
  const dropped = sequence.events.reduce((n, e) => n + e.folds.length, 0) - live.reduce((n, e) => n + e.folds.length, 0);
  if (sequence.file && !dropped) return sequence.file;
  await api.writeFile(files.sequence, writeCMML({ title: sequence.title, events: live }));
  return files.sequence;
}

/** The pattern in the form the 3D view and the kinematics take (actors and joints by index). */
export function viewPattern(model) {
  const actorIds = model.actors();
  const actorIndex = new Map(actorIds.map((id, k) => [id, k]));
  const actors = actorIds.map((id) => ({ id, triangles: model.trianglesOf(id).map((t) => [...model.triangles[t].v]) }));
  const joints = model.joints().map((j) => ({ id: j.id, v: [j.va, j.vb], actors: j.actors.map((a) => actorIndex.get(a)), assignment: j.assignment }));
  return { vertices: model.vertices.map((p) => [p.x, p.y]), actors, joints };
}

/** Writes the pattern and asks foldkit to check it: {ok, problems: [{line, message}], info, dof}.
 * Invalid patterns answer with every problem and its line (no info, no DOF). */
export async function checkPattern(model, files) {
  await api.writeFile(files.pattern, model.toPMML());
  try {
    await api.verb('validate', { files: [files.pattern] });
  } catch (e) {
    if (!(e instanceof api.ApiError) || e.status !== 400) throw e;
    const listed = e.result && e.result.files ? e.result.files.flatMap((f) => f.errors) : [];
    return { ok: false, problems: listed.length ? listed : [{ line: 0, message: e.message }] };
  }
  const info = (await api.verb('info', { pattern: files.pattern })).result;
  const dof = (await api.verb('dof', { pattern: files.pattern })).result;
  return { ok: true, problems: [], info, dof };
}

// One state (joint id → degrees) as a CMML of one event.
function stateCMML(jointIds, degrees) {
  // Within rounding of ±180° a trajectory's angle may lie just outside CMML's [-180, 180].
  const angle = (d) => Math.max(-180, Math.min(180, d));
  return writeCMML({ title: 'state', events: [{ number: 0, folds: jointIds.map((joint, k) => ({ joint, angle: angle(degrees[k]), speed: 1 })) }] });
}

/** DOF and closure error of one state (joint id → degrees), from `foldkit dof --state`. */
export async function stateDof(files, jointIds, degrees) {
  await api.writeFile(files.state, stateCMML(jointIds, degrees));
  return (await api.verb('dof', { pattern: files.pattern, state: files.state })).result;
}

/** The trajectory frames the page asks `simulate` for (--max-frames): 600, fewer for a large
 * sheet, so that frames × joints stays within 400,000 angles, yet at least 100. Every frame is
 * every edge's angle as FOLD text: a 40 × 40 Miura-ori's 359 frames were 27 MB, 0.3 s to send
 * and parse; its 121 frames now (9 MB, 0.1 s) still play it smoothly. The verdict, the
 * collisions and the final state do not depend on it. */
export function frameBudget(joints) {
  return Math.max(100, Math.min(600, Math.floor(400000 / Math.max(1, joints))));
}

/** Simulates the sequence: {result (simulate's JSON), exit, frames (radians per joint, in
 * `joints` order), final, times (seconds per frame), series}. `options` are simulate's arguments
 * (e.g. {'no-collision': true}); with {model: 'dynamic'} foldkit also writes every joint's angle
 * and torque every 0.01 s (`--series NAME-series.json`), which is `series` ({time, event,
 * joints: [{joint, angle, torque}]}); else `series` is null. `start`: the state the dynamic
 * model starts from (degrees per joint, in model.joints() order), written as NAME-start.cmml
 * and sent as `start`; null: flat. */
export async function simulate(model, sequence, files, options = {}, start = null) {
  const path = await sequencePath(sequence, files, model);
  if (start) {
    await api.writeFile(files.start, stateCMML(model.joints().map((j) => j.id), start));
    options = { ...options, start: files.start };
  }
  const physical = options.model === PHYSICS_MODEL;
  const run = await api.verb('simulate', { pattern: files.pattern, sequence: path, frames: files.frames,
    'max-frames': frameBudget(model.joints().length), ...(physical ? { series: files.series } : {}), ...options });
  const trajectory = JSON.parse(await api.readFile(files.frames));
  const { frames, final, times } = foldFrameAngles(trajectory, model.joints());
  const series = physical ? JSON.parse(await api.readFile(files.series)) : null;
  return { result: run.result, exit: run.exit, log: run.log, frames, final, times, series };
}

/** Projected folding to `fraction` of the way (foldkit fold): the sequence it wrote. */
export async function foldTo(files, fraction, options = {}) {
  const run = await api.verb('fold', { pattern: files.pattern, fraction, output: files.folded, ...options });
  const sequence = run.exit === 0 ? await readSequence(files.folded) : null;
  return { run, sequence };
}

/** Plans from flat to the sequence's end state (foldkit plan): the planned sequence, or null
 * with the planner's reason (exit 4). */
export async function plan(model, sequence, files, options) {
  const goal = await sequencePath(sequence, files, model);
  const run = await api.verb('plan', { pattern: files.pattern, goal, output: files.plan, ...options });
  return { run, sequence: run.exit === 0 ? await readSequence(files.plan) : null };
}

/** Static equilibrium of the folded end state under a load (foldkit stiffness). */
export async function stiffness(model, sequence, files, { fixed, load, force }) {
  const loadcase = ['<LoadCase>', `  <Fixed>${fixed.join(' ')}</Fixed>`, '  <Load>', `    <ActorID>${load}</ActorID>`,
    `    <Force>${force.map(String).join(' ')}</Force>`, '  </Load>', '</LoadCase>', ''].join('\n');
  await api.writeFile(files.loadcase, loadcase);
  const args = { pattern: files.pattern, loadcase: files.loadcase };
  if (sequence.events.length) args.state = await sequencePath(sequence, files, model);
  return (await api.verb('stiffness', args)).result;
}

// Reads a CMML file as it downloads, on a thread of its own where the browser has them
// (reader.js), else on this one.
function readCMMLFile(path) {
  const aside = readSequenceAside(path);
  if (aside) return aside;
  const reader = new CmmlReader();
  return api.readFilePieces(path, (text) => reader.push(text)).then(() => reader.finish());
}

/** A CMML file of the root, remembered as the sequence's file until the page edits it. */
export async function readSequence(path) {
  const sequence = await readCMMLFile(path);
  sequence.file = path;
  return sequence;
}

/** What boot.js's `opening` read early, as open() answers it: {pattern: a promise of {model}, or
 * null where the pattern is converted (open() it), sequence: a promise of {sequence}, or null}.
 * Marks when each part came in (performance.mark, for web/bench/open.mjs). */
export function openedEarly(boot) {
  const mark = (name) => (value) => { performance.mark(`foldkit:${name}`); return value; };
  return {
    pattern: boot.patternText && boot.patternText.then(mark('pattern-text')).then((text) => ({ model: PatternModel.fromPMML(text) })),
    sequence: boot.packedSequence && boot.packedSequence.then(mark('sequence-read'))
      .then((packed) => ({ sequence: { ...unpackSequence(packed), file: boot.sequence } })),
  };
}

/** A generated pattern (foldkit generate KIND), written as the session's PMML and read back. */
export async function generate(kind, parameters, files) {
  await api.verb('generate', { kind, ...parameters, output: files.pattern });
  return PatternModel.fromPMML(await api.readFile(files.pattern));
}

/** Opens a file of the root by its format (`formats`: GET /api's): a crease pattern → {model}
 * (PMML as it is, any other through foldkit convert to the session's PMML), a sequence (CMML) →
 * {sequence}. */
export async function open(path, files, formats) {
  const format = formatOf(formats, path);
  if (format && format.sequence) return { sequence: await readSequence(path) };
  if (format && format.reads_patterns) {
    if (format.name === 'PMML') return { model: PatternModel.fromPMML(await api.readFile(path)) };
    await api.verb('convert', { input: path, output: files.pattern });
    return { model: PatternModel.fromPMML(await api.readFile(files.pattern)) };
  }
  throw new Error(`${path}: open a ${extensions(formats, (f) => f.reads_patterns || f.sequence)} file`);
}

/** Exports through foldkit convert: FOLD (with one frame per event when there is a sequence) or
 * SVG (of the end state); returns the file's text. */
export async function exportAs(kind, model, sequence, files) {
  const output = kind === 'fold' ? files.fold : files.svg;
  if (sequence.events.length) {
    await api.verb('convert', { input: await sequencePath(sequence, files, model), pattern: files.pattern, output });
  } else {
    await api.verb('convert', { input: files.pattern, output });
  }
  return api.readFile(output);
}
