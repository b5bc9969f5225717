// Playback of the timeline: play and pause at a speed (simulated seconds per second of real
// time, from the modelled time of each event), and steps by move or by tool change (the step
// by block is main.js's single block). It moves the timeline only through goTo(position).
import { eventAt } from './model.js';
import { KIND } from './wire.js';

const SPEEDS = [1, 2, 5, 10, 50, 100, 1000];

export class Playback {
  // hooks: {model(), position(), goTo(position), sub (positions per event)}
  constructor(hooks) {
    this.h = hooks;
    this.playing = false;
    this.button = document.getElementById('play');
    this.speed = document.getElementById('speed');
    this.stepBy = document.getElementById('step-by');
    this.speed.innerHTML = SPEEDS.map((s) => `<option value="${s}"${s === 10 ? ' selected' : ''}>${s}×</option>`).join('');
    this.button.addEventListener('click', () => (this.playing ? this.pause() : this.play()));
    this.stepBy.addEventListener('change', () => this.labelSteps());
    this.labelSteps();
  }

  labelSteps() {
    const what = this.stepBy.selectedOptions[0].textContent;
    document.getElementById('back').textContent = `◀ ${what}`;
    document.getElementById('fwd').textContent = `${what} ▶`;
  }

  // The modelled time at a timeline position, and the position at a time.
  timeAt(p) {
    const s = this.h.model().time, sub = this.h.sub; // modelled end time of each event
    const done = Math.floor(p / sub), frac = p / sub - done;
    const t0 = done > 0 ? s[done - 1] : 0;
    return done < s.length ? t0 + frac * (s[done] - t0) : t0;
  }

  positionAt(t) {
    const s = this.h.model().time, sub = this.h.sub;
    let lo = 0, hi = s.length; // the first event that ends after t
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (s[mid] > t) hi = mid;
      else lo = mid + 1;
    }
    if (lo >= s.length) return s.length * sub;
    const t0 = lo > 0 ? s[lo - 1] : 0;
    return Math.floor((lo + (t - t0) / (s[lo] - t0)) * sub);
  }

  play() {
    const m = this.h.model();
    if (!m || !m.n) return;
    if (this.h.position() >= m.n * this.h.sub) this.h.goTo(0);
    this.playing = true;
    this.button.textContent = '❚❚ Pause';
    document.getElementById('timeline').dataset.playing = 'true';
    let t = this.timeAt(this.h.position()), last = performance.now();
    const end = m.time[m.n - 1];
    const frame = (now) => {
      if (!this.playing || this.h.model() !== m) return this.pause();
      t += ((now - last) / 1000) * Number(this.speed.value);
      last = now;
      if (t >= end) {
        this.h.goTo(m.n * this.h.sub);
        return this.pause();
      }
      const p = this.positionAt(t);
      if (p !== this.h.position()) this.h.goTo(p);
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  }

  pause() {
    this.playing = false;
    this.button.textContent = '▶ Play';
    document.getElementById('timeline').dataset.playing = 'false';
  }

  // A step by the mode chosen: true when done here, false for a step by block.
  step(dir) {
    const mode = this.stepBy.value;
    const m = this.h.model();
    if (mode === 'block' || !m) return false;
    this.pause();
    const sub = this.h.sub, p = this.h.position();
    // By kind from the typed column; only a tool event is made into an object (to read .change).
    const wanted = mode === 'move' ? (i) => m.kind[i] <= KIND.ccw : (i) => m.kind[i] === KIND.tool && (m.lathe || eventAt(m, i).change);
    const n = m.n;
    if (dir > 0) {
      for (let i = Math.floor(p / sub); i < n; i++) if (wanted(i) && (i + 1) * sub > p) return this.h.goTo((i + 1) * sub), true;
      this.h.goTo(n * sub);
    } else {
      for (let i = Math.min(n, Math.ceil(p / sub)) - 1; i >= 0; i--) if (wanted(i) && (i + 1) * sub < p) return this.h.goTo((i + 1) * sub), true;
      this.h.goTo(0);
    }
    return true;
  }
}
