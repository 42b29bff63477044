// The 2D editor's input: pointer, wheel and keyboard events of its canvas (and the window's keys)
// turned into the editor's actions and its tools' handlers (`_down_TOOL`, `_move_TOOL`, `_up_TOOL`
// in editor_tools.js). Functions of the editor; listen() is called once by its constructor, and
// destroy() removes what it added (editor._listeners).

// Whether a key goes to a form field rather than to the editor.
function isEditable(target) {
  if (!target || !target.tagName) return false;
  const tag = target.tagName.toLowerCase();
  return tag === 'input' || tag === 'textarea' || tag === 'select' || target.isContentEditable;
}

/** Listens to `editor`'s canvas, the window's keys and the canvas's size, for as long as the editor lives. */
export function listen(editor) {
  editor._listeners = [];
  const on = (target, type, fn, opts) => {
    target.addEventListener(type, fn, opts);
    editor._listeners.push([target, type, fn, opts]);
  };
  const c = editor.canvas;
  on(c, 'pointerdown', (e) => onDown(editor, e));
  on(c, 'pointermove', (e) => onMove(editor, e));
  on(c, 'pointerup', (e) => onUp(editor, e));
  on(c, 'pointercancel', () => editor._cancel());
  on(c, 'pointerleave', () => {
    if (!editor._action && editor._hover) {
      editor._hover = null;
      editor._requestDraw();
    }
  });
  on(c, 'wheel', (e) => onWheel(editor, e), { passive: false });
  on(c, 'dblclick', (e) => onDoubleClick(editor, e));
  on(c, 'contextmenu', (e) => e.preventDefault());
  if (typeof window !== 'undefined') {
    on(window, 'keydown', (e) => onKey(editor, e));
    on(window, 'keyup', (e) => {
      if (e.key === ' ') editor._space = false;
    });
    on(window, 'resize', () => editor.resize());
    on(window, 'blur', () => (editor._space = false));
  }
  if (typeof ResizeObserver !== 'undefined') {
    editor._resizeObserver = new ResizeObserver(() => editor.resize());
    editor._resizeObserver.observe(c);
  }
}

function local(editor, e) {
  const r = editor.canvas.getBoundingClientRect();
  return { x: e.clientX - r.left - editor.canvas.clientLeft, y: e.clientY - r.top - editor.canvas.clientTop };
}

function onDown(editor, e) {
  if (editor.canvas.focus) editor.canvas.focus({ preventScroll: true });
  const s = local(editor, e);
  try {
    editor.canvas.setPointerCapture(e.pointerId);
  } catch {
    // Synthetic events have no active pointer to capture.
  }
  if (e.button === 1 || e.button === 2 || (e.button === 0 && editor._space)) {
    e.preventDefault();
    editor._action = { kind: 'pan', sx: s.x, sy: s.y, ox: editor.view.ox, oy: editor.view.oy };
    return;
  }
  if (e.button !== 0) return;
  e.preventDefault();
  const handler = editor[`_down_${editor.tool}`];
  if (handler) handler.call(editor, s, e);
}

function onMove(editor, e) {
  const s = local(editor, e);
  const a = editor._action;
  if (a && a.kind === 'pan') {
    editor.view.ox = a.ox + s.x - a.sx;
    editor.view.oy = a.oy + s.y - a.sy;
    editor._requestDraw();
    return;
  }
  const handler = editor[`_move_${editor.tool}`];
  if (a && handler) handler.call(editor, s, e);
  else editor._hoverAt(s, e);
}

function onUp(editor, e) {
  const s = local(editor, e);
  const a = editor._action;
  try {
    editor.canvas.releasePointerCapture(e.pointerId);
  } catch {
    // Nothing was captured.
  }
  if (!a) return;
  if (a.kind === 'pan') {
    editor._action = null;
    return;
  }
  const handler = editor[`_up_${editor.tool}`];
  if (handler) handler.call(editor, s, e);
}

function onWheel(editor, e) {
  e.preventDefault();
  const s = local(editor, e);
  const unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? editor._size.h : 1;
  editor._zoomAt(s.x, s.y, Math.exp(-e.deltaY * unit * 0.0015));
}

function onDoubleClick(editor, e) {
  const s = local(editor, e);
  if (editor.tool === 'polygon') editor._closePolygon();
  else if (editor.tool === 'select') {
    const t = editor._model.triangleAt(editor._toModel(s.x, s.y));
    if (t >= 0) editor.select({ actors: [editor._model.triangles[t].actor] });
  }
}

function onKey(editor, e) {
  if (isEditable(e.target)) return;
  const ctrl = e.ctrlKey || e.metaKey;
  const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
  const overCanvas = e.target === editor.canvas || e.target === document.body || e.target === document.documentElement;
  if (key === ' ' && overCanvas) {
    editor._space = true;
    e.preventDefault();
    return;
  }
  let handled = true;
  if (ctrl && key === 'z') e.shiftKey ? editor.redo() : editor.undo();
  else if (ctrl && key === 'y') editor.redo();
  else if (ctrl && key === 'c' && overCanvas) editor.copySelection();
  else if (ctrl && key === 'v' && overCanvas) editor.paste();
  else if (ctrl && key === 'a' && overCanvas) editor.selectAll();
  else if (key === 'Escape') {
    if (editor._action || editor._points.length || editor._picked.length) editor._cancel();
    else editor._setSelection({});
  } else if (key === 'Enter' && editor.tool === 'polygon') editor._closePolygon();
  else if (key === 'Backspace' && editor.tool === 'polygon' && editor._points.length) {
    editor._points.pop();
    editor._requestDraw();
  } else if ((key === 'Delete' || key === 'Backspace') && overCanvas && !editor._action) editor.deleteSelection();
  else handled = false;
  if (handled) e.preventDefault();
}
