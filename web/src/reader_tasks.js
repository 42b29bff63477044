// What reader_worker.js does, as functions that answer through `post(answer, transfer)`: in the
// worker that is its postMessage; where there are no module workers, boot.js calls them on the
// page's thread. Answers are {what, value} or, for a failure, {what, error, status, exit}.
import { index, readFile, readFilePieces } from './api.js';
import { CmmlReader } from './cmml.js';
import { opensPattern, opensSequence, formatOf, stem } from './formats.js';

function fail(post, what, e) {
  post({ what, error: e.message, status: e.status, exit: e.exit });
}

/** Reads the CMML file `path` as it downloads; answers what 'sequence': CmmlReader.packed()'s
 * arrays (their buffers listed for moving, not copying). */
export async function sendSequence(path, post) {
  try {
    const reader = new CmmlReader();
    await readFilePieces(path, (text) => reader.push(text));
    const packed = reader.packed();
    post({ what: 'sequence', value: packed }, [packed.numbers.buffer, packed.counts.buffer, packed.joints.buffer, packed.angles.buffer, packed.speeds.buffer]);
  } catch (e) {
    fail(post, 'sequence', e);
  }
}

/** The command line's files: answers what 'server': {server: GET /api's answer, pattern,
 * sequence, readsPattern, name}, the first pattern and first sequence (paths, or null), whether
 * the pattern's text follows (a PMML, which the page reads; any other format it converts) and
 * the session's name; then what 'pattern': that text, and what 'sequence' (sendSequence). */
export async function sendCommandLine(post) {
  let server;
  try {
    server = await index();
  } catch (e) {
    return fail(post, 'server', e);
  }
  const pattern = server.files.find((f) => opensPattern(server.formats, f)) ?? null;
  const sequence = (pattern && server.files.find((f) => opensSequence(server.formats, f))) ?? null;
  const readsPattern = Boolean(pattern && formatOf(server.formats, pattern)?.name === 'PMML');
  post({ what: 'server', value: { server, pattern, sequence, readsPattern, name: pattern ? `${stem(server.formats, pattern)}-edit` : null } });
  // The pattern (1 MB) first, for the page to read while the sequence downloads and is read
  // here: read side by side, its answer waited behind the sequence's pieces.
  if (readsPattern) {
    try {
      post({ what: 'pattern', value: await readFile(pattern) });
    } catch (e) {
      fail(post, 'pattern', e);
    }
  }
  if (sequence) await sendSequence(sequence, post);
}
