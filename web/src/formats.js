// The file formats foldkit reads and writes, as `GET /api` lists them (io's one table,
// io/src/formats.cpp): the page opens what the CLI opens, and a format added there is offered
// here without an edit.

// `path` in lower case without a trailing `.gz`: foldkit reads and writes `X.cmml.gz` as CMML,
// gzip-compressed (io::format_of), and the server sends such a file with gzip content coding,
// which the browser undoes.
function plainName(path) {
  const lower = String(path).toLowerCase();
  return lower.endsWith('.gz') ? lower.slice(0, -3) : lower;
}

/** The format of `path` among `formats` by its extension, ignoring case and a trailing `.gz`;
 * null when none. */
export function formatOf(formats, path) {
  const lower = plainName(path);
  return formats.find((f) => lower.length > f.extension.length && lower.endsWith(f.extension)) || null;
}

/** Whether `path` opens as a crease pattern. */
export function opensPattern(formats, path) {
  const f = formatOf(formats, path);
  return Boolean(f && f.reads_patterns);
}

/** Whether `path` opens as a fold sequence. */
export function opensSequence(formats, path) {
  const f = formatOf(formats, path);
  return Boolean(f && f.sequence);
}

/** The extensions of the formats `which` accepts, as a message lists them: ".pmml, .cmml or .fold". */
export function extensions(formats, which) {
  const listed = formats.filter(which).map((f) => f.extension);
  return listed.length < 2 ? listed.join('') : `${listed.slice(0, -1).join(', ')} or ${listed[listed.length - 1]}`;
}

/** `path` without its folder and its format's extension (and a `.gz` after it). */
export function stem(formats, path) {
  const name = String(path).replace(/^.*\//, '');
  const f = formatOf(formats, name);
  return f ? name.slice(0, name.length - f.extension.length - (name.length - plainName(name).length)) : name;
}
