// The whole app in a real browser (Debian's chromium through puppeteer-core, WebGL on the CPU):
// `foldkit serve` on a free port, the page driven by mouse and keyboard like a user, and every
// number the page shows compared with the CLI's own answer on the same files.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { foldkit, tempRoot, startServer, launchBrowser, openApp, idle, shown } from './harness.js';

let browser = null;
const servers = [];

before(async () => {
  browser = await launchBrowser();
});

after(async () => {
  if (browser) await browser.close();
  await Promise.all(servers.map((s) => s.stop()));
});

async function serve(name, files = [], prepare = () => {}) {
  const root = tempRoot(name);
  prepare(root);
  const server = await startServer(root, files);
  servers.push(server);
  return { root, server };
}

// The page's screenshot is a picture, not a blank canvas: many colours, and sheet-coloured pixels
// well away from the background.
async function assertNotBlank(page, what) {
  const stats = await page.evaluate(async () => {
    const image = new Image();
    image.src = window.foldkit.view.screenshot();
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const g = canvas.getContext('2d');
    g.drawImage(image, 0, 0);
    const data = g.getImageData(0, 0, canvas.width, canvas.height).data;
    const background = data.slice(0, 3);
    const colours = new Set();
    let differ = 0;
    for (let k = 0; k < data.length; k += 4) {
      colours.add((data[k] << 16) | (data[k + 1] << 8) | data[k + 2]);
      if (Math.abs(data[k] - background[0]) + Math.abs(data[k + 1] - background[1]) + Math.abs(data[k + 2] - background[2]) > 30) differ++;
    }
    return { colours: colours.size, share: differ / (data.length / 4), width: canvas.width };
  });
  assert.ok(stats.width > 100, `${what}: screenshot ${stats.width} px wide`);
  assert.ok(stats.colours > 20, `${what}: ${stats.colours} colours`);
  assert.ok(stats.share > 0.02, `${what}: only ${(100 * stats.share).toFixed(2)} % of the pixels are not background`);
}

// Screenshots for docs/SERVE.md, when the test is run with FOLDKIT_SCREENSHOTS=DIR.
async function keepScreenshot(page, name) {
  const dir = process.env.FOLDKIT_SCREENSHOTS;
  if (!dir) return;
  mkdirSync(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`) });
}

// The CLI's numbers for a pattern and sequence under `root`.
function cliNumbers(root, pattern, sequence) {
  const info = foldkit(['info', join(root, pattern), '--json']).json;
  const sim = foldkit(['simulate', join(root, pattern), join(root, sequence), '--json'], { expect: [0, 3] }).json;
  const dof = foldkit(['dof', join(root, pattern), '--state', join(root, sequence), '--json']).json;
  return { info, sim, dof };
}

// The page shows numbers with 3 significant digits.
function close(shownValue, exact) {
  return exact === 0 ? shownValue === 0 : Math.abs(shownValue - exact) <= 0.006 * Math.abs(exact);
}

test('the files named on the command line open, simulate, and show the CLI\'s numbers', async () => {
  const { root } = await serve('demo', ['miura.pmml', 'miura-folded.cmml'], (dir) => {
    foldkit(['generate', 'miura', '--rows', '4', '--cols', '4', '-o', join(dir, 'miura.pmml')]);
    foldkit(['fold', join(dir, 'miura.pmml'), '--fraction', '0.9', '-o', join(dir, 'miura-folded.cmml')]);
  });
  const page = await openApp(browser, servers[servers.length - 1].url);
  await page.waitForFunction(() => window.foldkit.simulation !== null);
  await idle(page);
  const cli = cliNumbers(root, 'miura.pmml', 'miura-folded.cmml');
  assert.equal(await shown(page, 'n-joints'), cli.info.joints);
  assert.equal(await shown(page, 'n-actors'), cli.info.actors);
  assert.equal(await shown(page, 'n-collisions'), cli.sim.collision_count);
  assert.ok(close(await shown(page, 'closure-max'), cli.sim.max_closure_error), 'closure error of the sequence');
  // The scrubber rests on the end state: its DOF is the CLI's at the sequence's end state.
  assert.equal(await shown(page, 'n-dof'), cli.dof.dof);
  assert.equal(await page.$eval('#verdict', (e) => e.textContent), 'valid');
  await assertNotBlank(page, 'folded Miura-ori');
  await keepScreenshot(page, 'serve-miura');
  assert.deepEqual(page.errors, []);
});
