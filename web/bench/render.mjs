// The browser figures of issue 17, in headless Debian chromium with WebGL on the CPU (SwiftShader):
// how soon the page answers input, the simulate round trip on the demo's pattern, and the frame
// rate of the 3D view animating a folded Miura-ori 40 × 40 (3,120 creases).
//   node web/bench/render.mjs [--size 40] [--seconds 5]    (FOLDKIT_CLI: the foldkit to serve)
import { join } from 'node:path';
import { foldkit, tempRoot, startServer, launchBrowser, openApp, idle } from '../test/harness.js';

const arg = (name, fallback) => {
  const at = process.argv.indexOf(`--${name}`);
  return at > 0 ? Number(process.argv[at + 1]) : fallback;
};
const size = arg('size', 40);
const seconds = arg('seconds', 5);

function median(values) {
  const s = [...values].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

const browser = await launchBrowser();
const servers = [];
try {
  // 1. The demo's Miura-ori 4 × 4 folded to 0.9: page load and the simulate round trip.
  const demo = tempRoot('bench-demo');
  foldkit(['generate', 'miura', '--rows', '4', '--cols', '4', '-o', join(demo, 'miura.pmml')]);
  foldkit(['fold', join(demo, 'miura.pmml'), '--fraction', '0.9', '-o', join(demo, 'folded.cmml')]);
  const server = await startServer(demo, ['miura.pmml', 'folded.cmml']);
  servers.push(server);
  const loads = [];
  for (let k = 0; k < 5; k++) {
    const page = await openApp(browser, server.url);
    loads.push(await page.evaluate(() => ({ interactive: window.foldkit.interactiveAt, ready: performance.now() })));
    if (k < 4) await page.close();
    else {
      const trips = await page.evaluate(async () => {
        const api = await import('/src/api.js');
        const out = [];
        for (let i = 0; i < 10; i++) {
          const t = performance.now();
          await api.verb('simulate', { pattern: 'miura.pmml', sequence: 'folded.cmml', frames: 'trip.fold' });
          const fold = await api.readFile('trip.fold');
          out.push({ simulate: performance.now() - t, bytes: fold.length });
        }
        return out;
      });
      console.log(`simulate round trip, Miura-ori 4x4 folded to 0.9 (POST /api/simulate + GET its frames): median ${median(trips.map((t) => t.simulate)).toFixed(1)} ms over ${trips.length}`);
    }
  }
  console.log(`page interactive (input handled) after: median ${median(loads.map((l) => l.interactive)).toFixed(0)} ms; files opened and simulated after ${median(loads.map((l) => l.ready)).toFixed(0)} ms (5 loads)`);

  // 2. A Miura-ori SIZE × SIZE folded to 0.9 and simulated by the page, then animated.
  const big = tempRoot('bench-big');
  foldkit(['generate', 'miura', '--rows', String(size), '--cols', String(size), '-o', join(big, 'miura.pmml')]);
  foldkit(['fold', join(big, 'miura.pmml'), '--fraction', '0.9', '--no-collision', '-o', join(big, 'folded.cmml')]);
  const bigServer = await startServer(big, ['miura.pmml', 'folded.cmml']);
  servers.push(bigServer);
  const page = await openApp(browser, bigServer.url);
  await page.waitForFunction(() => window.foldkit.simulation !== null, { timeout: 300000 });
  await idle(page);
  const fps = await page.evaluate(async (s) => {
    const { view, simulation } = window.foldkit;
    const frames = simulation.frames;
    const result = await view.measureFps(s, (t) => frames[Math.floor((t / s) * (frames.length - 1)) % frames.length]);
    return { ...result, stats: view.stats(), frames: frames.length, width: view.renderer.domElement.width, height: view.renderer.domElement.height };
  }, seconds);
  console.log(`Miura-ori ${size}x${size} (${fps.stats.creases} creases, ${fps.stats.triangles} triangles), ${fps.width}x${fps.height} px: ${fps.fps.toFixed(1)} frames/s over ${seconds} s (setAngles ${fps.stats.lastSetAnglesMs.toFixed(2)} ms, render ${fps.stats.lastRenderMs.toFixed(2)} ms per frame)`);
  console.log(`chromium ${await browser.version()}`);
} finally {
  await browser.close();
  await Promise.all(servers.map((s) => s.stop()));
}
