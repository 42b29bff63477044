// The fold sequence's events as blocks in a row, and the simulated trajectory's scrubber with
// the collisions (and a physical run's stalls) marked where they happened.

/** Draws into `container`; calls `onEvent(number)` when an event is picked, `onScrub(frame)`
 * while the scrubber moves, `onScrubEnd(frame)` when it rests. */
export class Timeline {
  constructor(container, { onEvent, onScrub, onScrubEnd }) {
    this.onEvent = onEvent;
    this.onScrub = onScrub;
    this.onScrubEnd = onScrubEnd;
    this.events = container.querySelector('.events');
    this.slider = container.querySelector('input[type=range]');
    this.marks = container.querySelector('.marks');
    this.clock = container.querySelector('.clock');
    this.play = container.querySelector('.play');
    this.current = null;
    this.duration = 0;
    this.frameCount = 0;
    this.timer = null;
    this.slider.addEventListener('input', () => this.onScrub(this.frame));
    this.slider.addEventListener('change', () => this.onScrubEnd(this.frame));
    this.play.addEventListener('click', () => (this.timer ? this.stop() : this.start()));
  }

  /** The frame the scrubber is on. */
  get frame() {
    return Number(this.slider.value);
  }

  /** Shows the sequence's events; `current` is the number new folds go into. */
  setEvents(sequence, current) {
    this.current = current;
    this.events.replaceChildren();
    for (const event of sequence.events) {
      const block = document.createElement('button');
      block.className = 'event' + (event.number === current ? ' current' : '');
      block.textContent = `${event.number}: ${event.folds.length} fold${event.folds.length === 1 ? '' : 's'}`;
      // The list of folds as a tooltip, written when first pointed at: a 40 × 40 Miura-ori's fold
      // has 99 events of 3,120 folds, whose text took 0.37 s to write on opening.
      const tip = () => { block.title = event.folds.map((f) => `joint ${f.joint} → ${f.angle}° at ${f.speed}°/s`).join('\n'); };
      block.addEventListener('pointerenter', tip, { once: true });
      block.addEventListener('focus', tip, { once: true });
      block.dataset.number = event.number;
      block.addEventListener('click', () => this.onEvent(event.number));
      this.events.append(block);
    }
  }

  /** A new trajectory of `frameCount` frames over `duration` seconds, collisions at their times;
   * `times`: each frame's time (else the frames are taken as evenly spaced). */
  setTrajectory(frameCount, duration, collisions, times = null) {
    this.stop();
    this.frameCount = frameCount;
    this.duration = duration;
    this.times = times && times.length === frameCount ? times : null;
    this.slider.max = Math.max(0, frameCount - 1);
    this.slider.value = Math.max(0, frameCount - 1);
    this.slider.disabled = frameCount < 2;
    this.marks.replaceChildren();
    for (const c of collisions) {
      const mark = document.createElement('span');
      mark.className = 'collision-mark';
      mark.style.left = `${duration > 0 ? (100 * c.time) / duration : 0}%`;
      mark.title = `collision of actors ${c.actors.join(' and ')} at ${c.time.toFixed(3)} s`;
      this.marks.append(mark);
    }
    this.showClock();
  }

  /** Marks the physical run's stalls ({joint, time, …}) on the scrubber, each labelled with its
   * joint and time (`label(stall)`); none: the marks go. */
  markStalls(stalls, label) {
    for (const old of this.marks.querySelectorAll('.stall-mark')) old.remove();
    for (const s of stalls) {
      const mark = document.createElement('span');
      mark.className = 'stall-mark';
      const at = this.duration > 0 ? Math.min(100, (100 * s.time) / this.duration) : 0;
      mark.style.left = `${at}%`;
      mark.dataset.joint = s.joint;
      mark.dataset.time = s.time;
      const text = document.createElement('span');
      text.className = at > 50 ? 'stall-label before' : 'stall-label';  // on the side with room
      text.textContent = label(s);
      mark.append(text);
      this.marks.append(mark);
    }
  }

  /** Seconds into the trajectory at `frame`. */
  timeAt(frame) {
    if (this.times) return this.times[Math.max(0, Math.min(this.frameCount - 1, frame))];
    return this.frameCount > 1 ? (this.duration * frame) / (this.frameCount - 1) : this.duration;
  }

  showClock() {
    this.clock.textContent = `${this.timeAt(this.frame).toFixed(2)} / ${this.duration.toFixed(2)} s`;
  }

  /** Moves the scrubber (and tells onScrub). */
  seek(frame) {
    this.slider.value = Math.max(0, Math.min(this.frameCount - 1, frame));
    this.showClock();
    this.onScrub(this.frame);
  }

  /** Plays the trajectory in about four seconds (or its real time when shorter). */
  start() {
    if (this.frameCount < 2) return;
    if (this.frame >= this.frameCount - 1) this.seek(0);
    const seconds = Math.min(4, Math.max(this.duration, 1));
    const began = performance.now() - (this.frame / (this.frameCount - 1)) * seconds * 1000;
    this.play.textContent = '❚❚';
    const tick = (now) => {
      const f = Math.round(((now - began) / 1000 / seconds) * (this.frameCount - 1));
      this.seek(Math.min(f, this.frameCount - 1));
      if (f >= this.frameCount - 1) return this.stop(true);
      this.timer = requestAnimationFrame(tick);
    };
    this.timer = requestAnimationFrame(tick);
  }

  /** Stops playing; `ended` also reports the frame it rests on. */
  stop(ended = false) {
    if (this.timer) cancelAnimationFrame(this.timer);
    this.timer = null;
    this.play.textContent = '▶';
    if (ended) this.onScrubEnd(this.frame);
  }
}
