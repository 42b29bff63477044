// What the page asks the server for before the editor and three.js have loaded: GET /api, and
// the files named on the command line (the first pattern and the first sequence), read as they
// download on a thread of their own (reader_worker.js). index.html loads this module, which
// imports next to nothing, ahead of app.js, which imports it for the answers: a 40 × 40
// Miura-ori's 49 MB fold then arrives while three.js is still being read (issue 35).
import { readerWorker, answerError } from './reader.js';

// A promise whose failure app.js reports when it waits on it, never as an unhandled rejection.
function settled() {
  let resolve, reject;
  const promise = new Promise((yes, no) => { resolve = yes; reject = no; });
  promise.catch(() => {});
  return { promise, resolve, reject };
}

const answers = { server: settled(), pattern: settled(), sequence: settled() };
function take(data) {
  const answer = answers[data.what];
  if (data.error === undefined) answer.resolve(data.value);
  else answer.reject(answerError(data));
}
const worker = readerWorker();
if (worker) {
  worker.onmessage = ({ data }) => take(data);
  worker.onerror = (e) => {
    for (const a of Object.values(answers)) a.reject(new Error(`reading the command line's files: ${e.message || 'the reader failed'}`));
  };
  worker.postMessage({ boot: true });
} else {
  // No module workers (Firefox before 114): the same, on this thread.
  import('./reader_tasks.js').then((tasks) => tasks.sendCommandLine(take), (e) => answers.server.reject(e));
}

/** {server: GET /api's answer, name: the session's name for the pattern, pattern: its path or
 * null, sequence: the sequence's path or null, patternText: a promise of the pattern's text
 * (PMML; null for another format, which the page converts), packedSequence: a promise of the
 * sequence as CmmlReader.packed() packs it (null without one)}; rejects when GET /api fails. The
 * worker ends when everything has come. */
export const opening = answers.server.promise.then(({ server, name, pattern, sequence, readsPattern }) => {
  if (!readsPattern) answers.pattern.resolve(null);
  if (!sequence) answers.sequence.resolve(null);
  Promise.allSettled([answers.pattern.promise, answers.sequence.promise]).then(() => worker?.terminate());
  return { server, name, pattern, sequence, patternText: readsPattern ? answers.pattern.promise : null,
    packedSequence: sequence ? answers.sequence.promise : null };
});
opening.catch(() => worker && worker.terminate());
