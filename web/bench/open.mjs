// Issue 35 item 6: how long the browser app takes to open a Miura-ori SIZE × SIZE with its fold
// from the command line (`foldkit serve miura.pmml folded.cmml`), and where the time goes.
//   node web/bench/open.mjs [--size 40] [--runs 3] [--collisions] [--gzip] [--web DIR]
// FOLDKIT_CLI: the foldkit to serve; --web: the app's folder (default this one), e.g. an earlier
// version's web/ (with its node_modules/three) to compare side by side.
// Headless Debian chromium (WebGL on the CPU, SwiftShader), as web/bench/render.mjs. Per run, from
// navigation: the page answers input; the folded sheet is on screen (the first animation frame
// whose sheet is not flat); foldkit's numbers are in (the page is idle: simulate's verdict and the
// DOF of the state shown). Then every request the page made (server time = request sent → first
// byte; transfer = first → last byte) and the page's script time by function (V8's sampling
// profiler, inclusive, each sample counted once per function name).
// The fold is `foldkit fold --fraction 0.9` (--no-collision unless --collisions: only the file is
// wanted, and the simulation the page asks for checks collisions anyway).
import { join } from 'node:path';
import { foldkit, tempRoot, startServer, launchBrowser, idle } from '../test/harness.js';

const arg = (name, fallback) => {
  const at = process.argv.indexOf(`--${name}`);
  return at > 0 ? Number(process.argv[at + 1]) : fallback;
};
const size = arg('size', 40);
const runs = arg('runs', 3);
const foldCollisions = process.argv.includes('--collisions');
// --gzip: the fold written gzip-compressed (`foldkit fold -o folded.cmml.gz`), which the server
// sends as stored, with gzip content coding: 3.6 MB in place of 49 MB at 40 × 40.
const sequence = process.argv.includes('--gzip') ? 'folded.cmml.gz' : 'folded.cmml';
const web = process.argv.includes('--web') ? process.argv[process.argv.indexOf('--web') + 1] : undefined;

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const ms = (x) => `${Math.round(x)} ms`;

// Inclusive time per function name from a CPU profile (Profiler.stop's), a stack's functions
// counted once each; `(program)`, `(idle)` and `(garbage collector)` as V8 names them.
function profileByFunction(profile) {
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  const parent = new Map();
  for (const n of profile.nodes) for (const c of n.children || []) parent.set(c, n.id);
  const name = (n) => {
    const f = n.callFrame;
    const file = f.url ? f.url.replace(/^.*\//, '') : '';
    return f.functionName ? `${f.functionName}${file ? ` (${file})` : ''}` : (file ? `(anonymous ${file}:${f.lineNumber + 1})` : '(root)');
  };
  const total = new Map();
  profile.samples.forEach((id, k) => {
    const dt = (profile.timeDeltas[k + 1] ?? 0) / 1000;
    const seen = new Set();
    for (let n = id; n !== undefined; n = parent.get(n)) seen.add(name(byId.get(n)));
    for (const s of seen) total.set(s, (total.get(s) || 0) + dt);
  });
  return total;
}

async function openOnce(browser, url) {
  const page = await browser.newPage();
  page.errors = [];
  page.on('pageerror', (e) => page.errors.push(String(e)));
  const cdp = await page.target().createCDPSession();
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
  await cdp.send('Profiler.start');
  await page.goto(url, { waitUntil: 'load' });
  // The first frame on screen with the sheet folded: polled in the page at every animation frame.
  const folded = await page.waitForFunction(() => {
    const v = window.foldkit && window.foldkit.view;
    const s = v && v._sheet ? v.stats() : null;
    return s && s.maxZ - s.minZ > 1e-6 ? performance.now() : false;
  }, { timeout: 300000, polling: 'raf' });
  const foldedAt = await folded.jsonValue();
  await page.waitForSelector('body[data-ready="true"]', { timeout: 300000 });
  await idle(page);
  const doneAt = await page.evaluate(() => performance.now());
  const { profile } = await cdp.send('Profiler.stop');
  const out = await page.evaluate(() => ({
    interactive: window.foldkit.interactiveAt,
    marks: performance.getEntriesByType('mark').filter((m) => m.name.startsWith('foldkit:')).map((m) => [m.name.slice(8), m.startTime]),
    verdict: document.getElementById('verdict').textContent,
    dof: document.getElementById('n-dof').textContent,
    requests: performance.getEntriesByType('resource').filter((r) => r.name.includes('/api')).map((r) => ({
      name: r.name.replace(/^https?:\/\/[^/]+/, ''), start: r.startTime, server: r.responseStart - r.requestStart,
      transfer: r.responseEnd - r.responseStart, end: r.responseEnd, bytes: r.encodedBodySize })),
    errors: window.foldkit.errors,
  }));
  await page.close();
  return { ...out, foldedAt, doneAt, profile: profileByFunction(profile), pageErrors: page.errors };
}

const browser = await launchBrowser();
let server = null;
try {
  const root = tempRoot('bench-open');
  foldkit(['generate', 'miura', '--rows', String(size), '--cols', String(size), '-o', join(root, 'miura.pmml')]);
  foldkit(['fold', join(root, 'miura.pmml'), '--fraction', '0.9', ...(foldCollisions ? [] : ['--no-collision']), '-o', join(root, sequence)]);
  server = await startServer(root, ['miura.pmml', sequence], [], web);
  const results = [];
  for (let k = 0; k < runs; k++) results.push(await openOnce(browser, server.url));
  console.log(`Miura-ori ${size}x${size} with its fold (foldkit serve miura.pmml ${sequence}), chromium ${await browser.version()}, ${runs} runs`);
  console.log(`  page answers input:        ${results.map((r) => ms(r.interactive)).join(', ')}`);
  console.log(`  folded sheet on screen:    ${results.map((r) => ms(r.foldedAt)).join(', ')} (median ${ms(median(results.map((r) => r.foldedAt)))})`);
  console.log(`  foldkit's numbers all in:  ${results.map((r) => ms(r.doneAt)).join(', ')} (median ${ms(median(results.map((r) => r.doneAt)))})`);
  const last = results[results.length - 1];
  console.log(`  verdict "${last.verdict}", DOF (this state) ${last.dof}${last.errors.length || last.pageErrors.length ? `; errors: ${[...last.errors, ...last.pageErrors].join('; ')}` : ''}`);
  console.log(`  the page's marks (median): ${last.marks.map(([name]) => `${name} ${ms(median(results.map((r) => (r.marks.find((m) => m[0] === name) || [0, NaN])[1])))}`).join(', ')}`);
  console.log('  requests of the last run (start, server, transfer, bytes):');
  for (const r of last.requests)
    console.log(`    ${ms(r.start).padStart(8)} ${ms(r.server).padStart(8)} ${ms(r.transfer).padStart(8)} ${String(r.bytes).padStart(10)}  ${decodeURIComponent(r.name)}`);
  console.log('  script time by function, inclusive, median over the runs (the 25 largest):');
  const names = new Set(results.flatMap((r) => [...r.profile.keys()]));
  const rows = [...names].map((n) => [n, median(results.map((r) => r.profile.get(n) || 0))]).sort((a, b) => b[1] - a[1]);
  for (const [n, t] of rows.slice(0, 25)) console.log(`    ${ms(t).padStart(8)}  ${n}`);
} finally {
  await browser.close();
  if (server) await server.stop();
}
