// The path drawn fixed on the machine. Moves come in the work coordinates of the system in
// use, so a program that moves work zero (a probing macro writing #5221, G10, G52, G92,
// another of G54-G59) would draw its later moves shifted by as much, while the tool on the
// machine did not jump. The server sends where work zero is on the machine (the origins
// frame, viewer_stream.hpp); each move is drawn shifted by how far work zero has moved
// since the anchor, the same rule as the stock (stock.frame, docs/stock-analysis.md):
//   "work"    (default) anchor: work zero at the first feed move, so the drawing is in the
//             work coordinates the program cuts in, and the stock lines up with it;
//   "machine" anchor: machine zero (machine coordinates of the tool tip);
//   "program" nothing shifted (the path follows every change of work zero).
// The positions on the control's screens stay the control's (work, machine); only the drawing
// moves.

// Last index k with a[k][0] <= v (a sorted by its first column), or -1.
function lastAt(a, v) {
  let lo = 0, hi = a.length - 1, r = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (a[mid][0] <= v) (r = mid), (lo = mid + 1);
    else hi = mid - 1;
  }
  return r;
}

// Shifts the vertices of the moves (in place) and returns the shifts as runs of moves:
// {shiftFrom: Uint32Array (first move of each run), shiftBy: Float64Array (3 per run, the
// amount to add to a point in work coordinates: lathe X on the diameter), bounds (scene
// min/max again when anything moved, else null)}.
// b: {origins: [[event, x, y, z]] (x a radius), frame, lathe, moves, mEvent, kind, vFirst,
// vertices (Float32Array, scene x y z), vertexCount}.
export function fixOnMachine(b) {
  const none = { shiftFrom: new Uint32Array(0), shiftBy: new Float64Array(0), bounds: null };
  if (b.frame === 'program' || !b.origins.length || !b.moves) return none;
  const originOf = (mv) => {
    const k = lastAt(b.origins, b.mEvent[mv]);
    return k < 0 ? [0, 0, 0] : b.origins[k].slice(1);
  };
  let anchor = [0, 0, 0];
  if (b.frame !== 'machine') {
    let first = b.moves - 1;
    for (let mv = 0; mv < b.moves; mv++)
      if (b.kind[b.mEvent[mv]] !== 0) {
        first = mv;
        break;
      }
    anchor = originOf(first);
  }
  const from = [], by = [];
  let last = null, moved = false;
  const end = (mv) => (mv + 1 < b.moves ? b.vFirst[mv + 1] : b.vertexCount);
  for (let mv = 0; mv < b.moves; mv++) {
    const o = originOf(mv);
    const d = [o[0] - anchor[0], o[1] - anchor[1], o[2] - anchor[2]];
    if (!last || d.some((v, k) => v !== last[k])) {
      from.push(mv);
      by.push(b.lathe ? 2 * d[0] : d[0], d[1], d[2]);
      last = d;
    }
    if (!d[0] && !d[1] && !d[2]) continue;
    moved = true;
    // Scene: a mill's X Y Z; a lathe's (Z, 0, radius).
    const s = b.lathe ? [d[2], 0, d[0]] : d;
    const v = b.vertices;
    for (let k = b.vFirst[mv], e = end(mv); k < e; k++) (v[k * 3] += s[0]), (v[k * 3 + 1] += s[1]), (v[k * 3 + 2] += s[2]);
  }
  if (!moved) return none;
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  const v = b.vertices;
  for (let k = 0; k < b.vertexCount * 3; k++) {
    const a = k % 3;
    if (v[k] < min[a]) min[a] = v[k];
    if (v[k] > max[a]) max[a] = v[k];
  }
  return { shiftFrom: Uint32Array.from(from), shiftBy: Float64Array.from(by), bounds: b.vertexCount ? { min, max } : null };
}

// What to add to a work point of move mv to draw it (a zero array without shifts).
export function shiftOfMove(m, mv, axes = m.axes) {
  const out = new Array(axes).fill(0);
  const f = m.shiftFrom;
  if (!f || !f.length || mv < 0) return out;
  let lo = 0, hi = f.length - 1, r = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (f[mid] <= mv) (r = mid), (lo = mid + 1);
    else hi = mid - 1;
  }
  if (r < 0) return out;
  for (let a = 0; a < Math.min(3, axes); a++) out[a] = m.shiftBy[r * 3 + a];
  return out;
}

// A work point of move mv as drawn.
export function drawnPoint(m, mv, p) {
  const s = shiftOfMove(m, mv, p.length);
  return p.map((v, a) => v + s[a]);
}

// The tool of toolAt() (model.js) as drawn: the move in progress, else the last one done.
export function drawnTool(m, tool) {
  const mv = tool.index >= 0 ? m.lastMove[tool.index] : -1;
  return drawnPoint(m, mv, tool.work);
}
