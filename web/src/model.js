// The run answer as a timeline, built once (in the run worker, run.worker.js) from the binary
// frames of wire.js into typed arrays: the events' columns, each move's end points, the
// toolpath as one vertex buffer with a colour per vertex (RGBA, see RGBA below), and for each event the number of
// vertices drawn once it is done (the view shows the timeline as a draw range of that
// buffer). The control's state at an event is folded from sparse deltas on demand, from
// checkpoints, so that nothing is rebuilt per scrub or step.
import { KIND, FLAG, KIND_NAMES, MODE_NAMES, decodeBatch, json, lines } from './wire.js';
import { fixOnMachine } from './machine_frame.js';

const AXES = ['X', 'Y', 'Z', 'A', 'B', 'C'];
export const COLORS = { rapid: [0xff, 0x55, 0x33], feed: [0x33, 0xcc, 0xff], comp: [0xdd, 0x55, 0xff], thread: [0xff, 0xdd, 0x33] };
const CHECKPOINT = 64; // steps between full states
// Bytes of a vertex colour: R, G, B and an opaque alpha. Three bytes a vertex made ANGLE
// convert the whole buffer to four on the CPU before SwiftShader drew it (bench/viewer: the
// GPU process's CPU time to the first frame of a million moves 1.6 s -> 0.75 s).
export const RGBA = 4;

// A typed array that grows by doubling. done() hands out a view of its buffer, not a copy:
// a copy of a million-move timeline took a second, while the unused tail of a buffer was
// never written and so takes no memory.
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
    return this.a.subarray(0, this.n);
  }
}

// Chord points of an arc, work coordinates: within `tol` of the circle (program units), at
// least 4 and at most 96 a full turn. Lathe X is a diameter: the arc is round in radius.
// The start, end and centre are read at offsets si, ti, ci of s, t and c (A axes); each point
// j = 0..n goes to emit(p, j), p one of two scratch arrays that take turns (copy it to keep
// it): the run worker writes them straight into its buffers, as an array a point made the
// 100,000 arcs of a million-line CAM program cost the collector half a second.
const scratch = [new Float64Array(6), new Float64Array(6)];
function arcChords(s, si, t, ti, c, ci, A, plane, cw, lathe, emit, tol = 0.001) {
  const [ui, vi] = plane === 18 ? [2, 0] : plane === 19 ? [1, 2] : [0, 1];
  const k = (i) => (lathe && i === 0 ? 0.5 : 1);
  const su = s[si + ui] * k(ui), sv = s[si + vi] * k(vi), tu = t[ti + ui] * k(ui), tv = t[ti + vi] * k(vi);
  const cu = c[ci + ui] * k(ui), cv = c[ci + vi] * k(vi);
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
  for (let j = 0; j <= n; j++) {
    const f = j / n, a = a0 + sweep * f, rr = r0 + (r1 - r0) * f;
    const p = scratch[j & 1];
    for (let i = 0; i < A; i++) p[i] = s[si + i] + (t[ti + i] - s[si + i]) * f; // helix and other axes: linear
    p[ui] = (cu + rr * Math.cos(a)) / k(ui);
    p[vi] = (cv + rr * Math.sin(a)) / k(vi);
    emit(p, j);
  }
}

// arcChords as arrays of points.
function arcPoints(s, t, c, plane, cw, lathe) {
  const pts = [];
  arcChords(s, 0, t, 0, c, 0, s.length, plane, cw, lathe, (p) => pts.push(Array.from(p.subarray(0, s.length))));
  return pts;
}

// A move's points, work coordinates: an arc's chords, a dog-leg rapid's corners, else its ends.
function pointsOf(mv, lathe) {
  if (mv.center) return arcPoints(mv.start, mv.end, mv.center, mv.plane, mv.kind === KIND.cw, lathe);
  return [mv.start, ...mv.path, mv.end];
}

const colorOf = (kind, flags) =>
  kind === KIND.rapid ? COLORS.rapid : flags & FLAG.thread ? COLORS.thread : flags & FLAG.compensated ? COLORS.comp : COLORS.feed;

// Takes the frames of one run in order; model() returns the timeline. `expect`: the number
// of events to make room for at once (the program's line count: CAM code is a move a line),
// as growing a buffer of hundreds of MB by doubling cost seconds in copies and fresh pages.
export class ModelBuilder {
  constructor(expect = 0) {
    this.axes = 3;
    this.lathe = false;
    this.n = 0;
    this.m = 0;
    const cap = Math.max(1024, Math.min(expect + 64, 1 << 26));
    const G = (T, k = 1) => new Grow(T, cap * k);
    Object.assign(this, {
      kind: G(Uint8Array), flags: G(Uint8Array), line: G(Uint32Array), block: G(Uint32Array), nnum: G(Int32Array),
      file: G(Uint16Array), time: G(Float64Array), dt: G(Float64Array), lastMove: G(Int32Array), vEnd: G(Uint32Array),
      start: G(Float64Array, 3), end: G(Float64Array, 3), mend: G(Float64Array, 3), feed: G(Float32Array), mEvent: G(Uint32Array),
      vFirst: G(Uint32Array), arcOf: G(Int32Array), center: new Grow(Float64Array), plane: new Grow(Uint8Array),
      pathFirst: G(Uint32Array), path: new Grow(Float64Array), posEvent: new Grow(Int32Array), pos: new Grow(Float64Array),
      vertices: G(Float32Array, 6), colors: G(Uint8Array, 2 * RGBA), vertexEvent: G(Float32Array, 2),
    });
    this.pathFirst.push(0);
    this.min = [Infinity, Infinity, Infinity];
    this.max = [-Infinity, -Infinity, -Infinity];
    this.steps = []; // [event, delta]
    this.noteEvents = [];
    this.noteLines = [];
    this.maxLine = 0;
    this.tail = null;
    this.origins = []; // [event, x, y, z]: where work zero is on the machine (machine_frame.js)
    this.frame = 'work';
    this.stockShots = []; // kind 6 payloads: the stock along the timeline (stock.js)
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
    else if (frame.kind === 6) this.stockShots.push(frame.payload);
  }

  // Appends the segment from point p (at offset i) to point q (at offset j) to the vertex,
  // colour and event buffers, work coordinates -> scene: a lathe's (X diameter, Z) become
  // (Z, 0, X/2). The buffers have room (batch() makes it); each store site sees one array type.
  segment(p, i, q, j, col, ev) {
    const V = this.vertices, C = this.colors, E = this.vertexEvent;
    const va = V.a, ca = C.a, ea = E.a, lo = this.min, hi = this.max;
    let vn = V.n, cn = C.n;
    for (let k = 0; k < 2; k++) {
      const a = k ? q : p, o = k ? j : i;
      const x = this.lathe ? a[o + 2] : a[o], y = this.lathe ? 0 : a[o + 1], z = this.lathe ? a[o] / 2 : a[o + 2];
      va[vn] = x, va[vn + 1] = y, va[vn + 2] = z;
      ca[cn] = col[0], ca[cn + 1] = col[1], ca[cn + 2] = col[2], ca[cn + 3] = 255;
      vn += 3, cn += RGBA;
      if (x < lo[0]) lo[0] = x;
      if (y < lo[1]) lo[1] = y;
      if (z < lo[2]) lo[2] = z;
      if (x > hi[0]) hi[0] = x;
      if (y > hi[1]) hi[1] = y;
      if (z > hi[2]) hi[2] = z;
    }
    ea[E.n] = ev, ea[E.n + 1] = ev;
    V.n = vn, C.n = cn, E.n += 2;
  }

  // One events frame. The columns the server sends are appended whole; the per-move columns
  // and the vertices are written by index into typed arrays made big enough first, as a
  // push per value (a store site seeing seven kinds of typed array) cost seconds a million
  // moves.
  batch(b) {
    const A = b.axes, n = b.n, m = b.m;
    this.axes = A;
    const e0 = this.n, m0 = this.m;
    for (const k of ['kind', 'flags', 'line', 'block', 'nnum', 'file', 'time', 'dt']) this[k].append(b[k]);
    for (const k of ['end', 'mend', 'feed', 'center', 'plane', 'path']) this[k].append(b[k]);
    for (let i = 0; i < n; i++) if (b.line[i] > this.maxLine) this.maxLine = b.line[i];
    for (const k of ['mEvent', 'vFirst', 'arcOf', 'pathFirst']) this[k].room(m);
    this.start.room(m * A), this.lastMove.room(n), this.vEnd.room(n);
    const start = this.start.a, end = this.end.a, mEvent = this.mEvent.a, vFirst = this.vFirst.a, arcOf = this.arcOf.a;
    const pathFirst = this.pathFirst.a, lastMove = this.lastMove.a, vEnd = this.vEnd.a;
    const V = this.vertices, C = this.colors, E = this.vertexEvent;
    V.room(m * 6), C.room(m * 2 * RGBA), E.room(m * 2); // a segment a move; arcs and dog-legs ask for more
    let mi = 0, si = 0, pi = 0, arcs = this.plane.n - b.plane.length, paths = this.path.n / A - b.path.length / A;
    for (let i = 0; i < n; i++) {
      const k = b.kind[i], f = b.flags[i], ev = e0 + i;
      if (k <= 3) {
        const mv = m0 + mi;
        // The start: its own (after a jump of the position) or the last move's end.
        if (f & FLAG.ownStart) start.set(b.start.subarray(si * A, ++si * A), mv * A);
        else if (mv > 0) start.set(end.subarray((mv - 1) * A, mv * A), mv * A);
        else start.set(b.end.subarray(mi * A, mi * A + A), 0);
        const corners = b.pathCount[mi];
        paths += corners;
        pathFirst[mv + 1] = paths; // the first corner of the next move
        mEvent[mv] = ev, vFirst[mv] = V.n / 3;
        const col = colorOf(k, f);
        if (f & FLAG.arc) {
          arcOf[mv] = arcs++;
        } else arcOf[mv] = -1;
        if (!(f & FLAG.arc) && corners === 0) {
          this.segment(start, mv * A, end, mv * A, col, ev);
        } else if (corners === 0) {
          // An arc: its chords into the buffers, room made for them and the moves after.
          const a = arcOf[mv], rest = m - mi;
          arcChords(start, mv * A, end, mv * A, this.center.a, a * 3, A, this.plane.a[a], k === KIND.cw, this.lathe, (p, j) => {
            if (j === 0) return;
            V.room((rest + 1) * 6), C.room((rest + 1) * 2 * RGBA), E.room((rest + 1) * 2);
            this.segment(scratch[(j - 1) & 1], 0, p, 0, col, ev);
          });
        } else {
          const pts = pointsOf(this.moveRecord(mv), this.lathe);
          const more = m - mi + pts.length;
          V.room(more * 6), C.room(more * 2 * RGBA), E.room(more * 2);
          for (let j = 1; j < pts.length; j++) this.segment(pts[j - 1], 0, pts[j], 0, col, ev);
        }
        lastMove[ev] = mv;
        mi++;
      } else lastMove[ev] = m0 + mi - 1;
      if (f & FLAG.ownPositions) {
        this.posEvent.push(ev);
        this.pos.append(b.pos.subarray(pi * 3 * A, ++pi * 3 * A));
      }
      vEnd[ev] = V.n / 3;
    }
    for (const k of ['start', 'mEvent', 'vFirst', 'arcOf']) this[k].n += k === 'start' ? m * A : m;
    this.pathFirst.n += m, this.lastMove.n += n, this.vEnd.n += n;
    this.n += n;
    this.m += m;
  }

  // Move mv (of those built so far) as pointsOf takes it.
  moveRecord(mv) {
    const A = this.axes;
    const sl = (g, j) => Array.from(g.a.subarray(j * A, j * A + A));
    const rec = { kind: this.kind.a[this.mEvent.a[mv]], start: sl(this.start, mv), end: sl(this.end, mv), path: [], center: null, plane: 17 };
    for (let j = this.pathFirst.a[mv]; j < this.pathFirst.a[mv + 1]; j++) rec.path.push(sl(this.path, j));
    const a = this.arcOf.a[mv];
    if (a >= 0) (rec.center = Array.from(this.center.a.subarray(a * 3, a * 3 + 3))), (rec.plane = this.plane.a[a]);
    return rec;
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
      vertices: g(this.vertices), colors: g(this.colors), vertexEvent: g(this.vertexEvent), bounds: box, shiftFrom: fixed.shiftFrom, shiftBy: fixed.shiftBy,
      stepEvent: Int32Array.from(steps.map((s) => s[0])), ...packDeltas(steps), checkpoints,
      notes, blockLast: blockEnds(this), stockShots: this.stockShots,
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

// The deltas as one block of JSON text, a delta a line, and where each starts (bytes): two
// typed arrays handed over to the page without a copy. As 200,000 objects (a million-line
// program changes the modal state every fifth move) they took a second to clone into the
// page; a state is folded from at most CHECKPOINT of them, parsed when asked for.
function packDeltas(steps) {
  const text = steps.map((s) => JSON.stringify(s[1])).join('\n');
  const stepText = new TextEncoder().encode(text);
  const stepAt = new Uint32Array(steps.length + 1);
  let k = 0;
  for (let b = 0; b < stepText.length; b++) if (stepText[b] === 10) stepAt[++k] = b + 1;
  stepAt[steps.length] = stepText.length + 1; // as if the last line ended with a newline too
  return { stepText, stepAt };
}

const utf8 = new TextDecoder();
// Delta k of the timeline (state_diff.hpp: {l, c, s, m, o}).
export const stepDelta = (m, k) => JSON.parse(utf8.decode(m.stepText.subarray(m.stepAt[k], m.stepAt[k + 1] - 1)));

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
    for (let j = c * CHECKPOINT; j <= k; j++) applyStep(st, stepDelta(m, j));
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
    const d = stepDelta(m, k);
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

// The move that vertex k belongs to (the last with vFirst <= k).
export function moveOfVertex(model, k) {
  const f = model.vFirst;
  let lo = 0, hi = f.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (f[mid] <= k) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}
