// Opening a crease pattern drawn in Origami Simulator's SVG convention in a real browser (issue
// 34): Open… lists it, the page shows the CLI's counts for the file, folds it, and saves it back
// as SVG, which the CLI reads as the same sheet.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { copyFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { foldkit, browserSuite, openApp, idle, shown, webDir } from './harness.js';

const fixture = join(webDir, '..', '..', 'shared', 'fixtures', 'svg', 'OrigamiSimulator__squareBase.svg');
const suite = browserSuite();

test('an Origami Simulator SVG opens, folds and saves back as SVG', { timeout: 180000, skip: !existsSync(fixture) && 'no ../shared/fixtures' }, async () => {
  const { root, server } = await suite.serve('import', [], (dir) => copyFileSync(fixture, join(dir, 'squareBase.svg')));
  const cli = foldkit(['info', join(root, 'squareBase.svg'), '--json']).json;
  const page = await openApp(suite.browser(), server.url);
  await page.$eval('#name', (e) => { e.value = 'square'; });
  // Open… lists the files foldkit reads (GET /api's formats) when it gets the focus.
  await page.focus('#open');
  await page.waitForFunction(() => [...document.querySelectorAll('#open option')].some((o) => o.value === 'squareBase.svg'));
  await page.select('#open', 'squareBase.svg');
  await page.waitForFunction(() => window.foldkit.model.triangles.length > 0);
  await page.evaluate(() => window.foldkit.checkNow());
  await idle(page);
  assert.equal(await shown(page, 'n-actors'), cli.actors);
  assert.equal(await shown(page, 'n-joints'), cli.joints);

  // Fold it half way (projected folding), which simulates valid.
  await page.$eval('#fraction', (e) => { e.value = '0.5'; });
  await page.click('#fold');
  await page.waitForFunction(() => window.foldkit.simulation !== null, { timeout: 60000 });
  await idle(page);
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), 'valid');

  // Save → SVG writes square.svg under the root, with the folded state's targets.
  await page.click('[data-save="svg"]');
  await idle(page);
  assert.ok(existsSync(join(root, 'square.svg')), 'square.svg saved');
  const back = foldkit(['info', join(root, 'square.svg'), '--json']).json;
  assert.equal(back.actors, cli.actors);
  assert.equal(back.joints, cli.joints);
  assert.deepEqual(back.interior_vertex_degrees, cli.interior_vertex_degrees);
  assert.deepEqual(page.errors, []);
});
