// The run answer as a timeline, built once (in the run worker, run.worker.js) from the binary
// frames of wire.js into typed arrays: the events' columns, each move's end points, the
// toolpath as one vertex buffer with a colour per vertex, and for each event the number of
// vertices drawn once it is done (the view shows the timeline as a draw range of that
// buffer). The control's state at an event is folded from sparse deltas on demand, from
// checkpoints, so that nothing is rebuilt per scrub or step.
import { KIND, FLAG, KIND_NAMES, MODE_NAMES, decodeBatch, json, lines } from './wire.js';
import { fixOnMachine } from './machine_frame.js';

const AXES = ['X', 'Y', 'Z', 'A', 'B', 'C'];
export const COLORS = { rapid: [0xff, 0x55, 0x33], feed: [0x33, 0xcc, 0xff], comp: [0xdd, 0x55, 0xff], thread: [0xff, 0xdd, 0x33] };
const CHECKPOINT = 64; // steps between full states

// A typed array that grows by doubling.
class Grow {
  constructor(Type, cap = 1024) {
    this.Type = Type;
    this.a = new Type(cap);
    this.n = 0;
  }
  room(k) {
    if (this.n + k <= this.a.length) return;
    let cap = this.a.length * 2;
    while (cap < this.n + k) cap *= 2;
    const b = new this.Type(cap);
    b.set(this.a.subarray(0, this.n));
    this.a = b;
  }
  push(v) {
    if (this.n === this.a.length) this.room(1);
    this.a[this.n++] = v;
  }
  append(arr) {
    this.room(arr.length);
    this.a.set(arr, this.n);
    this.n += arr.length;
  }
  done() {
    return this.a.slice(0, this.n);
  }
}

// Chord points of an arc, work coordinates: within `tol` of the circle (program units), at
// least 4 and at most 96 a full turn. Lathe X is a diameter: the arc is round in radius.
function arcPoints(s, t, c, plane, cw, lathe, tol = 0.001) {
  const [ui, vi] = plane === 18 ? [2, 0] : plane === 19 ? [1, 2] : [0, 1];
  const k = (i) => (lathe && i === 0 ? 0.5 : 1);
  const su = s[ui] * k(ui), sv = s[vi] * k(vi), tu = t[ui] * k(ui), tv = t[vi] * k(vi);
  const cu = c[ui] * k(ui), cv = c[vi] * k(vi);
  const a0 = Math.atan2(sv - cv, su - cu);
  const a1 = Math.atan2(tv - cv, tu - cu);
  let sweep = a1 - a0;
  if (cw) while (sweep >= -1e-9) sweep -= 2 * Math.PI;
  else while (sweep <= 1e-9) sweep += 2 * Math.PI;
  // Start = end gives a whole turn (sweep 2 pi), as G02/G03 with I/J/K only.
  const r0 = Math.hypot(su - cu, sv - cv), r1 = Math.hypot(tu - cu, tv - cv);
  const r = Math.max(r0, r1, 1e-12);
  const step = tol < r ? 2 * Math.acos(1 - tol / r) : Math.PI / 2;
  const turns = Math.abs(sweep) / (2 * Math.PI);
  const n = Math.max(4, Math.min(Math.ceil(Math.abs(sweep) / step), Math.ceil(turns * 96)));
  const pts = [];
  for (let j = 0; j <= n; j++) {
    const f = j / n, a = a0 + sweep * f, rr = r0 + (r1 - r0) * f;
    const p = s.slice();
    for (let i = 0; i < p.length; i++) p[i] = s[i] + (t[i] - s[i]) * f; // helix and other axes: linear
    p[ui] = (cu + rr * Math.cos(a)) / k(ui);
    p[vi] = (cv + rr * Math.sin(a)) / k(vi);
    pts.push(p);
  }
  return pts;
}

// A move's points, work coordinates: an arc's chords, a dog-leg rapid's corners, else its ends.
function pointsOf(mv, lathe) {
  if (mv.center) return arcPoints(mv.start, mv.end, mv.center, mv.plane, mv.kind === KIND.cw, lathe);
  return [mv.start, ...mv.path, mv.end];
}

const colorOf = (kind, flags) =>
  kind === KIND.rapid ? COLORS.rapid : flags & FLAG.thread ? COLORS.thread : flags & FLAG.compensated ? COLORS.comp : COLORS.feed;

// Takes the frames of one run in order; model() returns the timeline.
export class ModelBuilder {
  constructor() {
    this.axes = 3;
    this.lathe = false;
    this.n = 0;
    this.m = 0;
    const G = (T) => new Grow(T);
    Object.assign(this, {
      kind: G(Uint8Array), flags: G(Uint8Array), line: G(Uint32Array), block: G(Uint32Array), nnum: G(Int32Array),
      file: G(Uint16Array), time: G(Float64Array), dt: G(Float64Array), lastMove: G(Int32Array), vEnd: G(Uint32Array),
      start: G(Float64Array), end: G(Float64Array), mend: G(Float64Array), feed: G(Float32Array), mEvent: G(Uint32Array),
      vFirst: G(Uint32Array), arcOf: G(Int32Array), center: G(Float64Array), plane: G(Uint8Array),
      pathFirst: G(Uint32Array), path: G(Float64Array), posEvent: G(Int32Array), pos: G(Float64Array),
      vertices: new Grow(Float32Array, 1 << 16), colors: new Grow(Uint8Array, 1 << 16),
    });
    this.pathFirst.push(0);
    this.min = [Infinity, Infinity, Infinity];
    this.max = [-Infinity, -Infinity, -Infinity];
    this.steps = []; // [event, delta]
    this.noteEvents = [];
    this.noteLines = [];
    this.lastEnd = null;
    this.maxLine = 0;
    this.tail = null;
    this.origins = []; // [event, x, y, z]: where work zero is on the machine (machine_frame.js)
    this.frame = 'work';
  }

  // One frame of wire.js: {kind, payload}.
  add(frame) {
    if (frame.kind === 0) {
      const h = json(frame.payload);
      this.axes = h.axes;
      this.lathe = h.machine?.kind === 'lathe';
      this.frame = h.frame || 'work';
    } else if (frame.kind === 1) this.batch(decodeBatch(frame.payload));
    else if (frame.kind === 2) {
      const s = json(frame.payload);
      for (const st of s.steps) this.steps.push(st);
      for (const i of s.notes) this.noteEvents.push(i);
    } else if (frame.kind === 3) for (const l of lines(frame.payload)) this.noteLines.push(l);
    else if (frame.kind === 4) this.tail = json(frame.payload);
    else if (frame.kind === 5) for (const o of json(frame.payload).origins) this.origins.push(o);
  }

  scene(p, out) {
    // Work coordinates -> scene: a lathe's (X diameter, Z) become (Z, 0, X/2).
    const x = this.lathe ? p[2] : p[0], y = this.lathe ? 0 : p[1], z = this.lathe ? p[0] / 2 : p[2];
    out.push(x), out.push(y), out.push(z);
    if (x < this.min[0]) this.min[0] = x;
    if (y < this.min[1]) this.min[1] = y;
    if (z < this.min[2]) this.min[2] = z;
    if (x > this.max[0]) this.max[0] = x;
    if (y > this.max[1]) this.max[1] = y;
    if (z > this.max[2]) this.max[2] = z;
  }

  batch(b) {
    const A = b.axes;
    this.axes = A;
    let mi = 0, si = 0, pi = 0, ai = 0, qi = 0;
    const V = this.vertices, C = this.colors;
    for (let i = 0; i < b.n; i++) {
      const k = b.kind[i], f = b.flags[i], ev = this.n + i;
      this.kind.push(k), this.flags.push(f), this.line.push(b.line[i]), this.block.push(b.block[i]);
      this.nnum.push(b.nnum[i]), this.file.push(b.file[i]), this.time.push(b.time[i]), this.dt.push(b.dt[i]);
      if (b.line[i] > this.maxLine) this.maxLine = b.line[i];
      if (k <= 3) {
        const end = Array.from(b.end.subarray(mi * A, mi * A + A));
        const start = f & FLAG.ownStart ? Array.from(b.start.subarray(si * A, si++ * A + A)) : this.lastEnd || end;
        const mv = { kind: k, start, end, path: [], center: null, plane: 17 };
        for (let j = 0; j < b.pathCount[mi]; j++) mv.path.push(Array.from(b.path.subarray((qi + j) * A, (qi + j) * A + A)));
        qi += b.pathCount[mi];
        for (const p of mv.path) this.path.append(p);
        this.pathFirst.push(this.path.n / A);
        if (f & FLAG.arc) {
          mv.center = Array.from(b.center.subarray(ai * 3, ai * 3 + 3));
          mv.plane = b.plane[ai++];
          this.arcOf.push(this.plane.n);
          this.center.append(mv.center);
          this.plane.push(mv.plane);
        } else this.arcOf.push(-1);
        this.start.append(start), this.end.append(end), this.mend.append(b.mend.subarray(mi * A, mi * A + A));
        this.feed.push(b.feed[mi]), this.mEvent.push(ev), this.vFirst.push(V.n / 3);
        const pts = pointsOf(mv, this.lathe);
        const col = colorOf(k, f);
        V.room(pts.length * 6), C.room(pts.length * 6);
        for (let j = 1; j < pts.length; j++) {
          this.scene(pts[j - 1], V), this.scene(pts[j], V);
          C.push(col[0]), C.push(col[1]), C.push(col[2]), C.push(col[0]), C.push(col[1]), C.push(col[2]);
        }
        this.lastEnd = end;
        this.lastMove.push(this.m++);
        mi++;
      } else this.lastMove.push(this.m - 1);
      if (f & FLAG.ownPositions) {
        this.posEvent.push(ev);
        this.pos.append(b.pos.subarray(pi * 3 * A, ++pi * 3 * A));
      }
      this.vEnd.push(V.n / 3);
    }
    this.n += b.n;
  }

  // The timeline: plain data (typed arrays, transferable) and the end frame as `answer`.
  model() {
    const A = this.axes;
    const steps = this.steps;
    // Full states every CHECKPOINT steps: stateAt folds at most that many deltas.
    const checkpoints = [];
    let st = emptyState();
    steps.forEach(([, d], k) => {
      if (k % CHECKPOINT === 0) checkpoints.push(cloneState(st));
      st = applyStep(st, d);
    });
    const notes = {};
    this.noteEvents.forEach((i, k) => (notes[i] = this.noteLines[k]));
    const g = (x) => x.done();
    // The path drawn fixed on the machine when the program moved work zero.
    const V = this.vertices, ev = this.mEvent, kinds = this.kind;
    const fixed = fixOnMachine({
      origins: this.origins, frame: this.frame, lathe: this.lathe, moves: this.m, mEvent: ev.a, kind: kinds.a,
      vFirst: this.vFirst.a, vertices: V.a, vertexCount: V.n / 3,
    });
    const box = fixed.bounds || (this.min[0] <= this.max[0] ? { min: this.min, max: this.max } : null);
    return {
      answer: this.tail || { ok: false, error: 'the answer ended early (no end frame)' },
      lathe: this.lathe, axes: A, axisNames: AXES.slice(0, A), n: this.n, moves: this.m,
      kind: g(this.kind), flags: g(this.flags), line: g(this.line), block: g(this.block), nnum: g(this.nnum),
      file: g(this.file), time: g(this.time), dt: g(this.dt), lastMove: g(this.lastMove), vEnd: g(this.vEnd),
      start: g(this.start), end: g(this.end), mend: g(this.mend), feed: g(this.feed), mEvent: g(this.mEvent),
      vFirst: g(this.vFirst), arcOf: g(this.arcOf), center: g(this.center), plane: g(this.plane),
      pathFirst: g(this.pathFirst), path: g(this.path), posEvent: g(this.posEvent), pos: g(this.pos),
      vertices: g(this.vertices), colors: g(this.colors), bounds: box, shiftFrom: fixed.shiftFrom, shiftBy: fixed.shiftBy,
      stepEvent: Int32Array.from(steps.map((s) => s[0])), stepDelta: steps.map((s) => s[1]), checkpoints,
      notes, blockLast: blockEnds(this),
    };
  }
}

// Array-like views for code that reads the timeline event by event: model.events[i] is
// eventAt(i), model.states[i] stateAt(i), each made when asked for (a million events are
// never all made at once unless iterated).
export function withViews(m) {
  const view = (at) =>
    new Proxy([], {
      get(target, key, receiver) {
        if (key === 'length') return m.n;
        if (typeof key === 'string' && key !== '' && key >= '0' && key <= '9' && String(Number(key)) === key) return at(m, Number(key));
        return Reflect.get(target, key, receiver);
      },
      has: (target, key) => (typeof key === 'string' && String(Number(key)) === key ? Number(key) < m.n : Reflect.has(target, key)),
    });
  m.events = view(eventAt);
  m.states = view(stateAt);
  return m;
}

// The typed arrays of a model, for postMessage's transfer list.
export const transferables = (m) => Object.values(m).filter((v) => ArrayBuffer.isView(v)).map((v) => v.buffer);

// Blocks to step through: runs of consecutive events of one block (same block count, file
// and line); the index of each run's last event.
function blockEnds(b) {
  const out = new Grow(Uint32Array);
  const blk = b.block.a, file = b.file.a, line = b.line.a;
  for (let i = 0; i < b.n; i++)
    if (i === b.n - 1 || blk[i + 1] !== blk[i] || file[i + 1] !== file[i] || line[i + 1] !== line[i]) out.push(i);
  return out.done();
}

const emptyState = () => ({ locals: {}, common: {}, system: {}, modal: {}, offsets: { work: {}, tool: {} } });
const cloneState = (s) => ({ locals: { ...s.locals }, common: { ...s.common }, system: { ...s.system }, modal: { ...s.modal }, offsets: s.offsets });

function applyDelta(obj, delta) {
  for (const [k, v] of Object.entries(delta)) {
    if (v === null) delete obj[k];
    else obj[k] = v;
  }
}

// Folds one delta into st (in place); returns st.
function applyStep(st, d) {
  if (d.l) applyDelta(st.locals, d.l);
  if (d.c) applyDelta(st.common, d.c);
  if (d.s) applyDelta(st.system, d.s);
  if (d.m) Object.assign(st.modal, d.m);
  if (d.o) st.offsets = d.o;
  return st;
}

// Last index k with a[k] <= v, or -1.
function lastAtMost(a, v) {
  let lo = 0, hi = a.length - 1, r = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (a[mid] <= v) (r = mid), (lo = mid + 1);
    else hi = mid - 1;
  }
  return r;
}

// The control's state after event i (null before the first): {block, time, locals, common,
// system, modal, offsets, changed (the variables event i changed)}. #5001-, #5021- and
// #5041- come from the event's own positions when it has them, else from the last move.
export function stateAt(m, i) {
  if (i < 0 || i >= m.n) return null;
  const k = lastAtMost(m.stepEvent, i);
  let st;
  if (k < 0) st = emptyState();
  else {
    const c = Math.floor(k / CHECKPOINT);
    st = cloneState(m.checkpoints[c]);
    for (let j = c * CHECKPOINT; j <= k; j++) applyStep(st, m.stepDelta[j]);
  }
  const A = m.axes;
  const p = lastAtMost(m.posEvent, i);
  const lm = m.lastMove[i];
  const own = p >= 0 && m.posEvent[p] === i;
  for (let g = 0; g < 3; g++)
    for (let a = 0; a < A; a++) {
      let v;
      if (own) v = m.pos[p * 3 * A + g * A + a];
      else if (lm >= 0) v = (g === 1 ? m.mend : m.end)[lm * A + a];
      else continue;
      st.system[`#${5001 + 20 * g + a}`] = v;
    }
  const changed = new Set();
  if (k >= 0 && m.stepEvent[k] === i) {
    const d = m.stepDelta[k];
    for (const part of [d.l, d.c, d.s]) if (part) for (const key of Object.keys(part)) changed.add(key);
  }
  return { block: m.block[i], time: m.time[i], ...st, changed };
}

// Event i as the trace would give it: {type, file, line, n, mode, ...} (a note's trace line
// has every field of docs/trace-format.md; a move gets mode, start, end, mend, feed, time).
export function eventAt(m, i) {
  if (i < 0 || i >= m.n) return null;
  const k = m.kind[i];
  const base = { index: i, type: KIND_NAMES[k], file: m.answer.files?.[m.file[i]] ?? '', line: m.line[i], n: m.nnum[i] >= 0 ? m.nnum[i] : null, time: m.dt[i] };
  if (k <= 3) {
    const mv = m.lastMove[i], A = m.axes;
    return {
      ...base, mode: MODE_NAMES[k], thread: !!(m.flags[i] & FLAG.thread), compensated: !!(m.flags[i] & FLAG.compensated),
      start: Array.from(m.start.subarray(mv * A, mv * A + A)), end: Array.from(m.end.subarray(mv * A, mv * A + A)),
      mend: Array.from(m.mend.subarray(mv * A, mv * A + A)), feed: m.feed[mv],
    };
  }
  const line = m.notes[i];
  return line ? { ...JSON.parse(line), ...base, time: m.dt[i] } : base;
}

// The non-move events (messages, tool changes, ...) in order, each with its index.
export const notesOf = (m) => Object.keys(m.notes).map(Number).sort((a, b) => a - b).map((i) => eventAt(m, i));

// Move mv's points, work coordinates (an arc's chords as drawn).
export function movePointsAt(m, mv) {
  const A = m.axes;
  const sl = (a, j) => Array.from(a.subarray(j * A, j * A + A));
  const rec = { kind: m.kind[m.mEvent[mv]], start: sl(m.start, mv), end: sl(m.end, mv), path: [], center: null, plane: 17 };
  for (let j = m.pathFirst[mv]; j < m.pathFirst[mv + 1]; j++) rec.path.push(sl(m.path, j));
  const a = m.arcOf[mv];
  if (a >= 0) (rec.center = Array.from(m.center.subarray(a * 3, a * 3 + 3))), (rec.plane = m.plane[a]);
  return pointsOf(rec, m.lathe);
}

// The tool at progress p (events fully done: floor(p); the next one at the fraction).
// Returns {work, machine, togo, index}.
export function toolAt(m, p) {
  const A = m.axes;
  const done = Math.min(Math.floor(p), m.n);
  const frac = p - done;
  const zero = new Array(A).fill(0);
  const at = (arr, mv) => Array.from(arr.subarray(mv * A, mv * A + A));
  if (done < m.n && m.kind[done] <= 3 && frac > 0) {
    const mv = m.lastMove[done];
    const pts = movePointsAt(m, mv);
    const d = [0];
    for (let i = 1; i < pts.length; i++) {
      let s = 0;
      for (let a = 0; a < 3; a++) s += (pts[i][a] - pts[i - 1][a]) ** 2;
      d.push(d[i - 1] + Math.sqrt(s));
    }
    const want = d[d.length - 1] * frac;
    let j = 1;
    while (j < d.length - 1 && d[j] < want) j++;
    const seg = d[j] - d[j - 1];
    const f = seg > 0 ? (want - d[j - 1]) / seg : 1;
    const work = pts[j - 1].map((v, a) => v + (pts[j][a] - v) * f);
    const end = at(m.end, mv), mend = at(m.mend, mv);
    return { work, machine: work.map((v, a) => v + (mend[a] - end[a])), togo: end.map((v, a) => v - work[a]), index: done };
  }
  const lm = done > 0 ? m.lastMove[done - 1] : -1;
  const work = lm >= 0 ? at(m.end, lm) : zero;
  const machine = lm >= 0 ? at(m.mend, lm) : zero;
  return { work, machine, togo: zero, index: done - 1 };
}

// Vertices drawn once `done` events are done.
export const verticesDone = (m, done) => (done <= 0 ? 0 : m.vEnd[Math.min(done, m.n) - 1]);

// Single block: the progress (in events) at the end of the next block after `done`, or of
// the block before (`partial`: the current one is part-way).
export function nextBlockEnd(m, done) {
  const b = m.blockLast;
  let lo = 0, hi = b.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (b[mid] + 1 > done) hi = mid;
    else lo = mid + 1;
  }
  return lo < b.length ? b[lo] + 1 : null;
}
export function prevBlockEnd(m, done, partial) {
  const k = lastAtMost(m.blockLast, partial ? done - 1 : done - 2);
  return k >= 0 ? m.blockLast[k] + 1 : 0;
}

// Time per kind of motion: what the state's cycle_time is made of.
export function timeBreakdown(m) {
  const t = { rapid: 0, feed: 0, thread: 0, dwell: 0 };
  for (let i = 0; i < m.n; i++) {
    const k = m.kind[i];
    if (k === KIND.dwell) t.dwell += m.dt[i];
    else if (k <= 3) t[k === KIND.rapid ? 'rapid' : m.flags[i] & FLAG.thread ? 'thread' : 'feed'] += m.dt[i];
  }
  return t;
}

// Time per tool: moves and dwells counted against the tool in the spindle (the last M06 on a
// mill, the last T on a lathe, whose turret indexes with T); "T0" before the first.
export function timeByTool(m) {
  const t = {};
  let tool = 'T0';
  for (let i = 0; i < m.n; i++) {
    const k = m.kind[i];
    if (k === KIND.tool) {
      const e = eventAt(m, i);
      if (e.change || m.lathe) tool = `T${e.tool}`;
    }
    if (k <= 3 || k === KIND.dwell) t[tool] = (t[tool] || 0) + m.dt[i];
  }
  return t;
}
