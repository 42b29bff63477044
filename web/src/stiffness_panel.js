// The run panel's Stiffness: the folded end state's static equilibrium under a load on one actor
// with others fixed (foldkit stiffness), drawn as each module's displacement in the 3D view.
import { $, app, files, log, task, checkedValid } from './page.js';
import * as session from './session.js';
import { format } from './numbers.js';

/** Solves the end state under the run panel's load and draws each module's displacement. */
export async function stiffnessNow() {
  const check = await app.checkNow();
  if (!checkedValid(check)) return;
  const fixed = $('fixed').value.split(/[\s,]+/).filter(Boolean).map(Number);
  const load = Number($('load-actor').value);
  const force = $('force').value.trim().split(/\s+/).map(Number);
  if (!fixed.length || !Number.isInteger(load) || force.length !== 3 || !force.every(Number.isFinite))
    return log('stiffness: give fixed actor IDs, the loaded actor and a force "fx fy fz"');
  const r = await task('stiffness', () => session.stiffness(app.model, app.sequence, files(), { fixed, load, force }));
  if (!r) return;
  const b = app.model.bounds();
  const size = Math.hypot(b.maxX - b.minX, b.maxY - b.minY);
  const scale = r.max_displacement > 0 ? (0.1 * size) / r.max_displacement : 1;
  const index = new Map(app.model.actors().map((id, k) => [id, k]));
  app.stiffness = r;
  app.view.showDisplacements(r.modules.map((m) => ({ actor: index.get(m.id), dx: m.displacement[0], dy: m.displacement[1], dz: m.displacement[2] })), scale);
  log(`stiffness: ${r.message}, largest displacement ${format(r.max_displacement)} (drawn ×${format(scale)}), condition ~${format(r.condition_estimate)}`);
}
