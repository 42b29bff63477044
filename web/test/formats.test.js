// formats.js against foldkit itself: the table `foldkit serve` lists (GET /api) says of each
// format what the CLI does with a file of it, and the page picks formats as the CLI does.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { rmSync } from 'node:fs';
import { join } from 'node:path';
import { spawnSync } from 'node:child_process';
import { cli, tempRoot, startServer } from './harness.js';
import { formatOf, opensPattern, opensSequence, extensions, stem } from '../src/formats.js';

const root = tempRoot('formats');
let server = null;
after(async () => {
  if (server) await server.stop();
  rmSync(root, { recursive: true, force: true });
});
const run = (...args) => spawnSync(cli, args, { encoding: 'utf8', timeout: 60000 });

test('each served format does what the CLI does with its files', { timeout: 60000 }, async () => {
  server = await startServer(root);
  const index = await (await fetch(`${server.url}api`)).json();
  const formats = index.formats;
  assert.deepEqual(formats.map((f) => f.extension), ['.pmml', '.cmml', '.fold', '.svg', '.cp', '.opx']);
  assert.equal(run('generate', 'miura', '--rows', '2', '--cols', '2', '-o', join(root, 'm.pmml')).status, 0);
  assert.equal(run('fold', join(root, 'm.pmml'), '--fraction', '0.5', '-o', join(root, 'm-folded.cmml')).status, 0);
  for (const f of formats) {
    const file = join(root, `copy${f.extension}`);
    // Written from a pattern (a CMML needs a state: from the folded sequence) exactly when served so.
    const written = f.sequence
      ? run('convert', join(root, 'm-folded.cmml'), file, '--pattern', join(root, 'm.pmml'))
      : run('convert', join(root, 'm.pmml'), file);
    assert.equal(written.status === 0, f.writes_patterns, `${f.name}: convert exit ${written.status} ${written.stderr}`);
    // Read as a pattern by any verb exactly when served so (a sequence is no pattern: usage error);
    // a format foldkit only reads (.cp) has no file written here to read.
    const info = run('info', file);
    if (f.writes_patterns || f.sequence) assert.equal(info.status === 0, f.reads_patterns, `${f.name}: info exit ${info.status} ${info.stderr}`);
    if (!f.reads_patterns) assert.equal(info.status, 2, `${f.name}: ${info.stderr}`);
    // A sequence validates against its pattern.
    if (f.sequence) assert.equal(run('validate', file, '--pattern', join(root, 'm.pmml')).status, 0);
    assert.equal(opensPattern(formats, file), f.reads_patterns);
    assert.equal(opensSequence(formats, file), f.sequence);
  }
  // The page's message lists what it opens, as the CLI's validate does.
  assert.equal(extensions(formats, (f) => f.reads_patterns || f.sequence), '.pmml, .cmml, .fold, .svg, .cp or .opx');
  const unknown = run('validate', join(root, 'notes.txt'));
  assert.match(unknown.stderr, /expected \.pmml, \.cmml, \.fold, \.svg, \.cp or \.opx/);
  assert.equal(formatOf(formats, 'a/B.FOLD').name, 'FOLD');
  assert.equal(formatOf(formats, 'notes.txt'), null);
  assert.equal(formatOf(formats, '.pmml'), null);
  assert.equal(stem(formats, 'dir/bird.Fold'), 'bird');
  assert.equal(stem(formats, 'dir/notes.txt'), 'notes.txt');
  // A gzip-compressed file is of its format, as foldkit reads and writes it (X.cmml.gz).
  assert.equal(run('fold', join(root, 'm.pmml'), '--fraction', '0.5', '-o', join(root, 'm-folded.cmml.gz')).status, 0);
  assert.equal(run('validate', join(root, 'm-folded.cmml.gz'), '--pattern', join(root, 'm.pmml')).status, 0);
  assert.ok(opensSequence(formats, 'm-folded.cmml.gz'));
  assert.equal(formatOf(formats, 'a/B.PMML.GZ').name, 'PMML');
  assert.equal(formatOf(formats, 'x.gz'), null);
  assert.equal(stem(formats, 'dir/m-folded.cmml.gz'), 'm-folded');
  // … and the server sends its text, which the browser's fetch inflates.
  const sent = await fetch(`${server.url}api/file?path=m-folded.cmml.gz`);
  assert.equal(sent.headers.get('content-encoding'), 'gzip');
  assert.match(await sent.text(), /^<\?xml[\s\S]*<CMML>/);
});
