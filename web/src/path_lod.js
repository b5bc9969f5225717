// A coarse copy of the toolpath for the frames drawn while the camera moves (path_layer.js):
// software WebGL draws about a microsecond a segment, so a million-move path cost a second an
// orbit frame. Runs of segments that join end to start in one colour are merged into one
// segment while every point they drop stays within `tol` of it (scene units; the run worker
// takes a thousandth of the path's diagonal, about a pixel when the whole part is in view).
// A run is at most MAX_RUN segments long, which bounds the work to a few tests a segment.
// When the camera stops, the full path is drawn again.
import { RGBA } from './model.js'; // bytes of a vertex colour

const MAX_RUN = 32;

// Squared distance from point (px, py, pz) to the segment a-b.
function dist2(px, py, pz, ax, ay, az, bx, by, bz) {
  const ux = bx - ax, uy = by - ay, uz = bz - az;
  const wx = px - ax, wy = py - ay, wz = pz - az;
  const uu = ux * ux + uy * uy + uz * uz;
  let t = uu > 0 ? (wx * ux + wy * uy + wz * uz) / uu : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const dx = wx - t * ux, dy = wy - t * uy, dz = wz - t * uz;
  return dx * dx + dy * dy + dz * dz;
}

// path: {vertices (Float32Array, x y z a vertex, two a segment), colors (Uint8Array, RGBA a
// vertex), vertexEvent (Float32Array, a vertex)}. Returns the same three arrays for the merged
// segments and `source`: for each of their vertices, the vertex of the full path it stands for
// (a new colouring of the full path is copied over through it).
export function coarsePath(path, tol) {
  const V = path.vertices, C = path.colors, E = path.vertexEvent;
  const segs = V.length / 6, tol2 = tol * tol;
  const out = { vertices: new Float32Array(V.length), colors: new Uint8Array(C.length), vertexEvent: new Float32Array(E.length), source: new Uint32Array(E.length) };
  let n = 0; // vertices written
  const emit = (a, b) => {
    // From the start of segment a to the end of segment b.
    for (const v of [2 * a, 2 * b + 1]) {
      out.vertices[3 * n] = V[3 * v], out.vertices[3 * n + 1] = V[3 * v + 1], out.vertices[3 * n + 2] = V[3 * v + 2];
      out.colors.set(C.subarray(RGBA * v, RGBA * v + RGBA), RGBA * n);
      out.vertexEvent[n] = E[v];
      out.source[n++] = v;
    }
  };
  // Does segment s join the one before it (same point, same colour)?
  const joins = (s) => {
    const p = 6 * s - 3, q = 6 * s; // the end of s-1, the start of s
    const c = 2 * RGBA * s - RGBA, d = 2 * RGBA * s;
    return V[p] === V[q] && V[p + 1] === V[q + 1] && V[p + 2] === V[q + 2] && C[c] === C[d] && C[c + 1] === C[d + 1] && C[c + 2] === C[d + 2];
  };
  let first = 0; // the run's first segment
  for (let s = 1; s <= segs; s++) {
    let keep = s < segs && s - first < MAX_RUN && joins(s);
    if (keep) {
      // The run first..s as one segment: every inner point (the end of first..s-1) near it.
      const a = 6 * first, b = 6 * s + 3;
      for (let k = first; keep && k < s; k++) {
        const p = 6 * k + 3;
        keep = dist2(V[p], V[p + 1], V[p + 2], V[a], V[a + 1], V[a + 2], V[b], V[b + 1], V[b + 2]) <= tol2;
      }
    }
    if (!keep) {
      emit(first, s - 1);
      first = s;
    }
  }
  return { vertices: out.vertices.slice(0, 3 * n), colors: out.colors.slice(0, RGBA * n), vertexEvent: out.vertexEvent.slice(0, n), source: out.source.slice(0, n) };
}
