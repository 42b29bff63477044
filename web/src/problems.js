// The pattern's problems as foldkit validate reports them (line: message), shown in the page's
// list and on the 2D editor: the actor or joint a line names, the point a message names.

// A problem's line in the PMML the page wrote names the actor or joint it concerns.
export function elementAtLine(pmml, line) {
  const lines = pmml.split('\n').slice(0, line);
  for (let k = lines.length - 1; k >= 0; k--) {
    const open = lines[k].match(/<(Actor|Joint)>/);
    if (open) {
      const id = pmml.split('\n').slice(k).join('\n').match(/<ID>\s*([-+0-9]+)\s*<\/ID>/);
      return id ? { kind: open[1], id: Number(id[1]) } : null;
    }
  }
  return null;
}

/** Lists `problems` ({line, message}) in the <ul> `list`, marks where each is on `editor`, and selects its actor or joint on a click. */
export function showProblemList(list, editor, model, problems) {
  list.replaceChildren();
  editor.clearProblems();
  const pmml = model.toPMML();
  for (const p of problems) {
    const item = document.createElement('li');
    item.textContent = p.line ? `line ${p.line}: ${p.message}` : p.message;
    const element = p.line ? elementAtLine(pmml, p.line) : null;
    const where = problemLocation(model, p.message, element);
    if (where) editor.markProblem(where);
    item.addEventListener('click', () => {
      if (element && element.kind === 'Joint') editor.select({ joints: [element.id] });
      if (element && element.kind === 'Actor') editor.select({ actors: [element.id] });
    });
    list.append(item);
  }
}

// foldkit's messages name points as (x, y); else the element's own place.
export function problemLocation(model, message, element) {
  const point = message.match(/\(\s*([-+0-9.e]+)\s*,\s*([-+0-9.e]+)/i);
  if (point) return { x: Number(point[1]), y: Number(point[2]) };
  if (element && element.kind === 'Joint') {
    const j = model.joints().find((x) => x.id === element.id);
    if (j) return { x: (j.a.x + j.b.x) / 2, y: (j.a.y + j.b.y) / 2 };
  }
  return null;
}
