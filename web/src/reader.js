// The page's side of reader_worker.js: files of the server's root read on a thread of their own.
import { ApiError } from './api.js';
import { unpackSequence } from './cmml.js';

/** A worker of reader_worker.js, or null where there are no module workers. */
export function readerWorker() {
  try {
    return new Worker(new URL('./reader_worker.js', import.meta.url), { type: 'module' });
  } catch (_) {
    return null;
  }
}

/** The worker's failure ({error, status, exit}) as the page's API reports it. */
export function answerError(data) {
  return data.status ? new ApiError(data.status, { error: data.error, exit: data.exit }) : new Error(data.error);
}

/** A CMML file of the root, read as it downloads by a worker of its own: the sequence, or null
 * where there are no module workers (the caller reads it itself). */
export function readSequenceAside(path) {
  const worker = readerWorker();
  if (!worker) return null;
  return new Promise((resolve, reject) => {
    worker.onmessage = ({ data }) => {
      worker.terminate();
      if (data.error === undefined) resolve(unpackSequence(data.value));
      else reject(answerError(data));
    };
    worker.onerror = (e) => {
      worker.terminate();
      reject(new Error(`reading ${path}: ${e.message || 'the reader failed'}`));
    };
    worker.postMessage({ read: path });
  });
}
