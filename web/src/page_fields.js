// What the page reads from its text fields and hands to the browser: NAME=VALUE parameters and
// downloads.

/** The NAME=VALUE pairs of a text field (generator parameters, lattice), numbers as numbers. */
export function parameters(text) {
  const out = {};
  for (const pair of text.split(/\s+/).filter(Boolean)) {
    const [key, value] = pair.split('=');
    if (value === undefined) continue;
    out[key] = /^[-+]?[0-9.]+(e[-+]?[0-9]+)?$/i.test(value) ? Number(value) : value;
  }
  return out;
}

// A path's last component: the file name a download takes.
export const baseName = (path) => path.split('/').pop();

/** Saves `text` (or a data: URL) as the browser's download `name`, of MIME `type`. */
export function download(name, text, type) {
  const link = document.createElement('a');
  link.href = typeof text === 'string' && text.startsWith('data:') ? text : URL.createObjectURL(new Blob([text], { type }));
  link.download = name;
  link.click();
}
