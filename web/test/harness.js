// What the browser tests and the browser benchmark share: a `foldkit serve` on a free port and a
// headless Debian chromium driven by puppeteer-core, both with bounded waits, and the CLI itself
// as the oracle.
import { spawn, spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { before, after } from 'node:test';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';

/** The web app's folder (this file's parent's parent). */
export const webDir = join(dirname(fileURLToPath(import.meta.url)), '..');

/** The foldkit CLI (FOLDKIT_CLI, as ctest sets it) and the browser (FOLDKIT_CHROMIUM, else Debian's). */
export const cli = process.env.FOLDKIT_CLI || join(webDir, '..', 'build', 'apps', 'foldkit');
export const chromium = process.env.FOLDKIT_CHROMIUM || '/usr/bin/chromium';

/** Runs the CLI; `--json` output parsed. Throws with its stderr on an unexpected exit code. */
export function foldkit(args, { expect = [0] } = {}) {
  const run = spawnSync(cli, args, { encoding: 'utf8', timeout: 120000 });
  if (!expect.includes(run.status)) throw new Error(`foldkit ${args.join(' ')}: exit ${run.status}\n${run.stderr}`);
  return { exit: run.status, json: args.includes('--json') ? JSON.parse(run.stdout) : null, err: run.stderr };
}

/** A fresh folder for a server's root. */
export function tempRoot(name) {
  return mkdtempSync(join(tmpdir(), `foldkit-web-${name}-`));
}

/** Starts `foldkit serve --port 0` on `root` with `files`; resolves {url, pid, stop()} once its
 * first line names the port (at most 20 s). `web`: the app's folder (a copy of another version,
 * to measure side by side). */
export function startServer(root, files = [], extra = [], web = webDir) {
  const child = spawn(cli, ['serve', '--port', '0', '--root', root, '--web', web, ...extra, ...files], { stdio: ['ignore', 'ignore', 'pipe'] });
  let err = '';
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => { child.kill('SIGKILL'); reject(new Error(`foldkit serve did not start in 20 s:\n${err}`)); }, 20000);
    child.on('exit', (code) => { clearTimeout(timer); reject(new Error(`foldkit serve exited (${code}):\n${err}`)); });
    child.stderr.on('data', (chunk) => {
      err += chunk;
      const match = err.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (!match) return;
      clearTimeout(timer);
      child.removeAllListeners('exit');
      const stop = () => new Promise((done) => {
        if (child.exitCode !== null || child.signalCode !== null) return done();
        const kill = setTimeout(() => process.kill(child.pid, 'SIGKILL'), 5000);
        child.on('exit', () => { clearTimeout(kill); done(); });
        process.kill(child.pid, 'SIGTERM');
      });
      resolve({ url: `http://127.0.0.1:${match[1]}/`, pid: child.pid, stop, log: () => err });
    });
  });
}

/** Headless chromium with WebGL on the CPU (SwiftShader); --no-sandbox because tests run as root. */
export async function launchBrowser() {
  return puppeteer.launch({
    executablePath: chromium,
    headless: true,
    protocolTimeout: 120000,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1400,900'],
    defaultViewport: { width: 1400, height: 900 },
  });
}

/** Opens the app and waits until it has loaded the server's files (at most 30 s). Page errors
 * are collected in `page.errors`. */
export async function openApp(browser, url) {
  const page = await browser.newPage();
  page.setDefaultTimeout(30000);
  page.errors = [];
  page.on('pageerror', (e) => page.errors.push(String(e)));
  // Script errors count; the browser's own note of an HTTP 4xx answer (a refusal the page shows) does not.
  page.on('console', (m) => { if (m.type() === 'error' && !/^Failed to load resource: the server responded with a status of 4/.test(m.text())) page.errors.push(m.text()); });
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
  await idle(page);
  return page;
}

/** Waits until the page has no request to foldkit in flight (at most 60 s). */
export async function idle(page) {
  await page.waitForFunction(() => window.foldkit && window.foldkit.busy === 0, { timeout: 60000, polling: 50 });
}

/** The text of the page's number `id`, as a number (NaN for '–'). */
export async function shown(page, id) {
  return Number(await page.$eval(`#${id}`, (e) => e.textContent));
}

/** A browser for a test file and the servers it starts, each on a fresh root: registers node's
 * `before` (launch) and `after` (close the browser, stop the servers, remove the roots), and
 * kills the servers even when the runner is stopped. Returns {browser(), serve(name, files,
 * prepare)}, where serve makes a root, calls prepare(root), starts `foldkit serve` on it and
 * resolves {root, server}; root(name) is a fresh folder removed after the tests. */
export function browserSuite() {
  let browser = null;
  const servers = [];
  const roots = [];
  process.on('exit', () => {
    for (const s of servers) try { process.kill(s.pid, 'SIGKILL'); } catch (_) { /* already gone */ }
  });
  before(async () => { browser = await launchBrowser(); });
  after(async () => {
    try {
      if (browser) await browser.close();
    } finally {
      await Promise.all(servers.map((s) => s.stop()));
      for (const root of roots) rmSync(root, { recursive: true, force: true });
    }
  });
  const root = (name) => {
    const dir = tempRoot(name);
    roots.push(dir);
    return dir;
  };
  return {
    browser: () => browser,
    root,
    async serve(name, files = [], prepare = () => {}) {
      const dir = root(name);
      prepare(dir);
      const server = await startServer(dir, files);
      servers.push(server);
      return { root: dir, server };
    },
  };
}
