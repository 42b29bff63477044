// The JSON API of `foldkit serve` (docs/SERVE.md): the browser asks, foldkit computes.

/** An answer the server refused (HTTP 4xx/5xx): `status`, the CLI's `exit` code and, for
 * validate, its `result` listing every problem with its line. */
export class ApiError extends Error {
  constructor(status, body) {
    super(body && body.error ? body.error : `HTTP ${status}`);
    this.status = status;
    this.exit = body ? body.exit : undefined;
    this.result = body ? body.result : undefined;
  }
}

async function answer(response) {
  const text = await response.text();
  let body = null;
  try {
    body = JSON.parse(text);
  } catch (_) {
    if (!response.ok) throw new ApiError(response.status, { error: text.trim() || `HTTP ${response.status}` });
    return text;
  }
  if (!response.ok) throw new ApiError(response.status, body);
  return body;
}

// The server runs a few verbs at once (foldkit serve --workers), queues more (--queue) and answers
// 503 only past its queue: the page sends its own verbs one after another, and waits out a busy
// server (up to a minute).
let queue = Promise.resolve();

async function post(name, args) {
  for (let tries = 0, wait = 100; ; tries++, wait = Math.min(2 * wait, 2000)) {
    const response = await fetch(`/api/${name}`, {
      method: 'POST',
      headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify(args),
    });
    if (response.status !== 503 || tries >= 35) return answer(response);
    await new Promise((resolve) => setTimeout(resolve, wait));
  }
}

/** Runs a verb: `{verb, exit, log, result}`; throws ApiError when the server refuses. */
export function verb(name, args) {
  const run = queue.then(() => post(name, args));
  queue = run.catch(() => {});
  return run;
}

/** `GET /api`: the server's verbs, the files it was started on and its limits. */
export async function index() {
  return answer(await fetch('/api'));
}

/** The entries of a folder under the server's root ('' = the root). */
export async function listFiles(folder = '') {
  return answer(await fetch(`/api/files?folder=${encodeURIComponent(folder)}`));
}

/** A file's text. */
export async function readFile(path) {
  const response = await fetch(`/api/file?path=${encodeURIComponent(path)}`);
  if (!response.ok) await answer(response);
  return response.text();
}

/** A file's text as it arrives: `piece(text)` for each piece, in order; resolves once the last
 * has been given. A large file (a 40 × 40 Miura-ori's fold is 49 MB) is then read while it
 * downloads rather than after. */
export async function readFilePieces(path, piece) {
  const response = await fetch(`/api/file?path=${encodeURIComponent(path)}`);
  if (!response.ok) await answer(response);
  const decoder = new TextDecoder();
  const reader = response.body.getReader();
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    piece(decoder.decode(value, { stream: true }));
  }
  piece(decoder.decode());
}

/** Writes a file under the root (atomically, on the server). */
export async function writeFile(path, text) {
  const response = await fetch(`/api/file?path=${encodeURIComponent(path)}`, {
    method: 'PUT',
    headers: { 'Content-Type': 'application/octet-stream' },
    body: text,
  });
  return answer(response);
}
