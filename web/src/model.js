// The run answer of /api/run turned into a timeline: events (the trace lines), the control's
// state after each event (folded from the per-event deltas in `steps`), the blocks to step
// through, and each move as a polyline for drawing and for the tool position mid-move.

const AXES = ['X', 'Y', 'Z', 'A', 'B', 'C'];

function applyDelta(obj, delta) {
  if (!delta) return obj;
  const out = { ...obj };
  for (const [k, v] of Object.entries(delta)) {
    if (v === null) delete out[k];
    else out[k] = v;
  }
  return out;
}

// Points of an arc move (work coordinates), `segs` chords per full turn.
function arcPoints(e, segs = 96) {
  const [ui, vi, wi] = e.plane === 18 ? [2, 0, 1] : e.plane === 19 ? [1, 2, 0] : [0, 1, 2];
  const s = e.start, t = e.end, c = e.center;
  // Lathe X is a diameter in the trace: the arc is round in radius space.
  const k = (i) => (e.lathe && i === 0 ? 0.5 : 1);
  const su = s[ui] * k(ui), sv = s[vi] * k(vi), tu = t[ui] * k(ui), tv = t[vi] * k(vi);
  const cu = c[ui] * k(ui), cv = c[vi] * k(vi);
  const a0 = Math.atan2(sv - cv, su - cu);
  let a1 = Math.atan2(tv - cv, tu - cu);
  const cw = e.mode === 'cw';
  let sweep = a1 - a0;
  if (cw) {
    while (sweep >= -1e-9) sweep -= 2 * Math.PI;
  } else {
    while (sweep <= 1e-9) sweep += 2 * Math.PI;
  }
  // Start = end gives a whole turn (sweep 2 pi), as G02/G03 with I/J/K only.
  const r0 = Math.hypot(su - cu, sv - cv), r1 = Math.hypot(tu - cu, tv - cv);
  const n = Math.max(4, Math.ceil((Math.abs(sweep) / (2 * Math.PI)) * segs));
  const pts = [];
  for (let j = 0; j <= n; j++) {
    const f = j / n, a = a0 + sweep * f, r = r0 + (r1 - r0) * f;
    const p = s.slice();
    for (let i = 0; i < p.length; i++) p[i] = s[i] + (t[i] - s[i]) * f; // helix and other axes: linear
    p[ui] = (cu + r * Math.cos(a)) / k(ui);
    p[vi] = (cv + r * Math.sin(a)) / k(vi);
    pts.push(p);
  }
  return pts;
}

function movePoints(e) {
  if (e.center && (e.mode === 'cw' || e.mode === 'ccw')) return arcPoints(e);
  const pts = [e.start];
  for (const p of e.path || []) pts.push([...p, ...e.start.slice(3)]);
  pts.push(e.end);
  return pts;
}

function cumulative(pts) {
  const d = [0];
  for (let i = 1; i < pts.length; i++) {
    let s = 0;
    for (let a = 0; a < 3; a++) s += (pts[i][a] - pts[i - 1][a]) ** 2;
    d.push(d[i - 1] + Math.sqrt(s));
  }
  return d;
}

export function buildModel(answer) {
  const lathe = answer.machine?.kind === 'lathe';
  const axes = answer.machine?.axes || 3;
  const lines = (answer.trace || '').split('\n').filter((l) => l.trim());
  const events = lines.map((l) => JSON.parse(l));
  const steps = answer.steps || [];
  const states = [];
  let st = { block: 0, time: 0, locals: {}, common: {}, system: {}, modal: {}, offsets: { work: {}, tool: {} } };
  let pos = null, mpos = null;
  const moves = [];
  events.forEach((e, i) => {
    const d = steps[i] || {};
    const changed = new Set([...Object.keys(d.l || {}), ...Object.keys(d.c || {}), ...Object.keys(d.s || {})]);
    st = {
      block: d.b ?? st.block,
      time: d.t ?? st.time,
      locals: applyDelta(st.locals, d.l),
      common: applyDelta(st.common, d.c),
      system: applyDelta(st.system, d.s),
      modal: d.m || st.modal,
      offsets: d.o || st.offsets,
      changed,
    };
    states.push(st);
    if (e.type === 'move') {
      e.lathe = lathe;
      const pts = movePoints(e);
      moves.push({ index: i, event: e, pts, dist: cumulative(pts) });
      e.moveIndex = moves.length - 1;
      pos = e.end;
      mpos = e.mend;
    }
    e.pos = pos;
    e.mpos = mpos;
  });
  // Blocks to step through: consecutive events of one block (same block count and line).
  const blocks = [];
  events.forEach((e, i) => {
    const key = `${states[i].block}:${e.file}:${e.line}`;
    const last = blocks[blocks.length - 1];
    if (last && last.key === key) last.last = i;
    else blocks.push({ key, first: i, last: i, line: e.line, file: e.file });
  });
  const start = new Array(axes).fill(0);
  return { answer, lathe, axes, axisNames: AXES.slice(0, axes), events, states, moves, blocks, start };
}

// The tool at progress p (events fully done: floor(p); the next one at the fraction).
// Returns {work, machine, togo, event}.
export function toolAt(model, p) {
  const n = model.events.length;
  const done = Math.min(Math.floor(p), n);
  const frac = p - done;
  const next = done < n ? model.events[done] : null;
  const prev = done > 0 ? model.events[done - 1] : null;
  const base = prev?.pos || model.start;
  const mbase = prev?.mpos || model.start;
  if (next && next.type === 'move' && frac > 0) {
    const m = model.moves[next.moveIndex];
    const total = m.dist[m.dist.length - 1];
    const want = total * frac;
    let j = 1;
    while (j < m.dist.length - 1 && m.dist[j] < want) j++;
    const seg = m.dist[j] - m.dist[j - 1];
    const f = seg > 0 ? (want - m.dist[j - 1]) / seg : 1;
    const work = m.pts[j - 1].map((v, a) => v + (m.pts[j][a] - v) * f);
    const off = next.mend.map((v, a) => v - next.end[a]);
    return {
      work,
      machine: work.map((v, a) => v + (off[a] || 0)),
      togo: next.end.map((v, a) => v - work[a]),
      event: next,
      index: done,
    };
  }
  return { work: base, machine: mbase, togo: base.map(() => 0), event: prev, index: done - 1 };
}

// Time per kind of motion, from the trace: what the state's cycle_time is made of.
export function timeBreakdown(model) {
  const t = { rapid: 0, feed: 0, thread: 0, dwell: 0 };
  for (const e of model.events) {
    if (e.type === 'dwell') t.dwell += e.time;
    else if (e.type === 'move') t[e.mode === 'rapid' ? 'rapid' : e.thread ? 'thread' : 'feed'] += e.time;
  }
  return t;
}

// Time per tool: moves and dwells counted against the tool in the spindle (the last M06 on a
// mill, the last T on a lathe, whose turret indexes with T); "T0" before the first.
export function timeByTool(model) {
  const t = {};
  let tool = 'T0';
  for (const e of model.events) {
    if (e.type === 'tool' && (e.change || model.lathe)) tool = `T${e.tool}`;
    if (e.type === 'move' || e.type === 'dwell') t[tool] = (t[tool] || 0) + e.time;
  }
  return t;
}
