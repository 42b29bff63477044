// The editor's undo history: snapshots of the model (PatternModel.snapshot()).

/** Bounded undo/redo stack of snapshots: push the state after every edit, the initial one too. */
export class History {
  /** An empty history keeping at most `limit` states. */
  constructor(limit = 200) {
    this.limit = limit;
    this._states = [];
    this._index = -1;
  }

  /** Record a state; drops any redo states and the oldest state past the limit. */
  push(snapshot) {
    this._states.length = this._index + 1;
    this._states.push(snapshot);
    if (this._states.length > this.limit) this._states.splice(0, this._states.length - this.limit);
    this._index = this._states.length - 1;
  }

  /** The state before the current one (now current), or null. */
  undo() {
    if (!this.canUndo) return null;
    return this._states[--this._index];
  }

  /** The state after the current one (now current), or null. */
  redo() {
    if (!this.canRedo) return null;
    return this._states[++this._index];
  }

  /** The current state, or null. */
  get current() {
    return this._states[this._index] ?? null;
  }

  /** Whether undo() has a state to return. */
  get canUndo() {
    return this._index > 0;
  }

  /** Whether redo() has a state to return. */
  get canRedo() {
    return this._index < this._states.length - 1;
  }

  /** Forget every state. */
  clear() {
    this._states = [];
    this._index = -1;
  }
}
