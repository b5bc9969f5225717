// The stock, when the run answer carries one (`answer.stock`: the final stock of the stock
// simulation, made when the setup has a [stock]; docs/web-viewer.md). Three forms are drawn:
//   {"type": "grid", "nx", "ny", "x0", "y0", "x1", "y1", "cell", "top", "bottom", "z": [...]}
//       a mill's stock as heights, row by row from y0, each row from x0 (work coordinates);
//   {"type": "profile", "rings": [{"hole": bool, "points": [[z, x], ...]}]}
//       a lathe's stock as its half-profile (X a diameter): the section through the axis,
//       filled, and the part revolved over the half turn behind it;
//   {"type": "mesh", "vertices": [x, y, z, ...], "triangles": [i, j, k, ...]}
//       any stock as triangles, work coordinates.
// Along the timeline (StockTimeline) the view shows the stock as cut up to the current move:
// the snapshots the server took during the run (model.stockShots, the kind 6 frames of
// src/server/stock_snapshots.hpp), each the exact stock after its first k moves, and the
// final stock once every move is done.
import * as THREE from 'three';

const shellMat = () => new THREE.MeshPhongMaterial({ color: 0x8a9bb0, transparent: true, opacity: 0.45, side: THREE.DoubleSide });

function meshOf(vertices, triangles, mat) {
  const geo = new THREE.BufferGeometry();
  geo.setAttribute('position', new THREE.Float32BufferAttribute(vertices, 3));
  geo.setIndex(triangles);
  geo.computeVertexNormals();
  return new THREE.Mesh(geo, mat);
}

// The top surface through the cell centres, and walls down to the bottom around it.
function gridMesh(s) {
  const { nx, ny } = s;
  if (!(nx > 0 && ny > 0) || !(Array.isArray(s.z) || ArrayBuffer.isView(s.z)) || s.z.length !== nx * ny) return null;
  const x = (i) => Math.min(s.x0 + (i + 0.5) * s.cell, s.x1 ?? Infinity);
  const y = (j) => Math.min(s.y0 + (j + 0.5) * s.cell, s.y1 ?? Infinity);
  const v = [];
  const t = [];
  for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) v.push(x(i), y(j), s.z[j * nx + i]);
  for (let j = 0; j + 1 < ny; j++)
    for (let i = 0; i + 1 < nx; i++) {
      const a = j * nx + i;
      t.push(a, a + 1, a + nx + 1, a, a + nx + 1, a + nx);
    }
  // The border, top then bottom, as a wall strip.
  const ring = [];
  for (let i = 0; i < nx; i++) ring.push(i);
  for (let j = 1; j < ny; j++) ring.push(j * nx + nx - 1);
  for (let i = nx - 2; i >= 0; i--) ring.push((ny - 1) * nx + i);
  for (let j = ny - 2; j > 0; j--) ring.push(j * nx);
  const base = v.length / 3;
  for (const k of ring) v.push(v[3 * k], v[3 * k + 1], s.bottom);
  for (let k = 0; k < ring.length; k++) {
    const n = (k + 1) % ring.length;
    t.push(ring[k], ring[n], base + n, ring[k], base + n, base + k);
  }
  // Pushed back in depth: the path of a face cut runs on its top.
  const mat = new THREE.MeshPhongMaterial({ color: 0x8a9bb0, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  return meshOf(v, t, mat);
}

function inside(p, ring) {
  let c = false;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const [zi, xi] = ring[i];
    const [zj, xj] = ring[j];
    if (xi > p[1] !== xj > p[1] && p[0] < ((zj - zi) * (p[1] - xi)) / (xj - xi) + zi) c = !c;
  }
  return c;
}

// Lathe scene: (Z, 0, X/2), the section in the plane y = 0 (see view3d.js toScene).
function profileGroup(s) {
  const rings = Array.isArray(s.rings) ? s.rings : Array.isArray(s.points) ? [{ hole: false, points: s.points }] : [];
  const g = new THREE.Group();
  const outers = rings.filter((r) => !r.hole && r.points.length > 2);
  const holes = rings.filter((r) => r.hole && r.points.length > 2);
  // Pushed back in depth so the toolpath, in the same plane, stays visible over it.
  const faceMat = new THREE.MeshBasicMaterial({ color: 0xb8c4d2, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  for (const o of outers) {
    // The section: the ring above the axis and its mirror below, holes cut out.
    for (const sign of [1, -1]) {
      const shape = new THREE.Shape(o.points.map(([z, x]) => new THREE.Vector2(z, (sign * x) / 2)));
      for (const h of holes)
        if (inside(h.points[0], o.points)) shape.holes.push(new THREE.Path(h.points.map(([z, x]) => new THREE.Vector2(z, (sign * x) / 2))));
      const face = new THREE.Mesh(new THREE.ShapeGeometry(shape), faceMat);
      face.rotation.x = Math.PI / 2; // shape y -> scene z
      g.add(face);
    }
  }
  // The revolved surface: every ring over the half turn on the +y side (behind the section
  // in the front view). LatheGeometry revolves (radius, y) about y; y then goes to scene x.
  for (const r of [...outers, ...holes]) {
    const pts = r.points.map(([z, x]) => new THREE.Vector2(Math.abs(x) / 2, z));
    pts.push(pts[0].clone());
    const mesh = new THREE.Mesh(new THREE.LatheGeometry(pts, 48, Math.PI, Math.PI), shellMat());
    mesh.rotation.z = -Math.PI / 2;
    g.add(mesh);
  }
  g.name = 'stock';
  return g;
}

export function drawStock(stock, lathe) {
  let obj = null;
  if (stock.type === 'mesh' && Array.isArray(stock.vertices) && Array.isArray(stock.triangles))
    obj = meshOf(stock.vertices, stock.triangles, shellMat());
  else if (stock.type === 'grid' && !lathe) obj = gridMesh(stock);
  else if (stock.type === 'profile' && lathe) obj = profileGroup(stock);
  if (obj) obj.name = 'stock';
  return obj;
}

// A kind 6 payload (server/stock_snapshots.hpp) as {moves, stock}, stock in the form of
// answer.stock (a grid's z a Float32Array).
export function decodeSnapshot(payload) {
  const b = payload.buffer, base = payload.byteOffset;
  const head = new Uint32Array(b, base, 8);
  const moves = head[0] + head[1] * 2 ** 32;
  if (head[2] === 0) {
    const [x0, y0, x1, y1, cell, top, bottom] = new Float64Array(b, base + 32, 7);
    const nx = head[3], ny = head[4];
    const z = new Float32Array(b, base + 88, nx * ny);
    return { moves, stock: { type: 'grid', nx, ny, step: head[5], x0, y0, x1, y1, cell, top, bottom, z } };
  }
  const rings = head[3];
  const counts = new Uint32Array(b, base + 32, rings), holes = new Uint32Array(b, base + 32 + 4 * rings, rings);
  let at = base + Math.ceil((32 + 8 * rings) / 8) * 8;
  const out = [];
  for (let r = 0; r < rings; r++) {
    const zx = new Float64Array(b, at, 2 * counts[r]);
    at += zx.byteLength;
    const points = [];
    for (let k = 0; k < zx.length; k += 2) points.push([zx[k], zx[k + 1]]);
    out.push({ hole: holes[r] === 1, points });
  }
  return { moves, stock: { type: 'profile', rings: out } };
}

const dispose = (o) =>
  o.traverse((x) => {
    x.geometry?.dispose();
    x.material?.dispose();
  });

// The stock the view shows at the timeline's position: the last snapshot at or before the
// moves done, or the final stock when all are done. `label` says which (a snapshot names its
// move: "stock after move 12,288 of 100,000"); the view's data-stock-move holds the move of
// the snapshot shown, or "final". Only a change of snapshot rebuilds the mesh.
export class StockTimeline {
  constructor(view, label) {
    this.view = view;
    this.label = label;
    this.model = null;
  }

  setModel(model) {
    this.model = model;
    this.shots = (model.stockShots || []).map(decodeSnapshot).sort((a, b) => a.moves - b.moves);
    this.shown = 'final'; // view3d.js drew the final stock
    this.every = model.answer.stock_snapshots?.every || 0;
    this.update(model.n);
  }

  // done: the events done (the timeline's position, rounded down).
  update(done) {
    const m = this.model;
    if (!m || !m.answer.stock) {
      this.label.hidden = true;
      delete this.view.host.dataset.stockMove;
      return;
    }
    const moves = done > 0 ? m.lastMove[Math.min(done, m.n) - 1] + 1 : 0;
    let pick = 'final';
    if (moves < m.moves && this.shots.length) {
      let lo = 0, hi = this.shots.length - 1;
      while (lo < hi) {
        const mid = (lo + hi + 1) >> 1;
        if (this.shots[mid].moves <= moves) lo = mid;
        else hi = mid - 1;
      }
      if (this.shots[lo].moves <= moves) pick = lo;
    }
    const n = (x) => x.toLocaleString('en-US');
    this.label.hidden = false;
    this.label.textContent =
      pick === 'final'
        ? `stock: final, after all ${n(m.moves)} moves`
        : `stock after move ${n(this.shots[pick].moves)} of ${n(m.moves)}${this.every > 1 ? ` (a snapshot every ${n(this.every)} moves)` : ''}`;
    this.view.host.dataset.stockMove = pick === 'final' ? 'final' : String(this.shots[pick].moves);
    if (pick === this.shown) return;
    const group = this.view.group;
    const old = group.getObjectByName('stock');
    if (old) {
      group.remove(old);
      dispose(old);
    }
    const obj = drawStock(pick === 'final' ? m.answer.stock : this.shots[pick].stock, m.lathe);
    if (obj) group.add(obj);
    this.shown = pick;
  }
}
