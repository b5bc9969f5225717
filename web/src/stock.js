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

// The top surface through the cell centres, and walls down to the bottom around it. Typed
// arrays throughout: a 256 x 256 grid is 66,000 vertices and 130,000 triangles.
function gridMesh(s) {
  const { nx, ny } = s;
  if (!(nx > 0 && ny > 0) || !(Array.isArray(s.z) || ArrayBuffer.isView(s.z)) || s.z.length !== nx * ny) return null;
  const x = (i) => Math.min(s.x0 + (i + 0.5) * s.cell, s.x1 ?? Infinity);
  const y = (j) => Math.min(s.y0 + (j + 0.5) * s.cell, s.y1 ?? Infinity);
  // The border, as indices of the top: a wall strip from it down to the bottom.
  const ring = [];
  for (let i = 0; i < nx; i++) ring.push(i);
  for (let j = 1; j < ny; j++) ring.push(j * nx + nx - 1);
  for (let i = nx - 2; i >= 0; i--) ring.push((ny - 1) * nx + i);
  for (let j = ny - 2; j > 0; j--) ring.push(j * nx);
  const n = nx * ny, base = n;
  const v = new Float32Array((n + ring.length) * 3);
  for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) (v[3 * (j * nx + i)] = x(i)), (v[3 * (j * nx + i) + 1] = y(j));
  ring.forEach((k, r) => ((v[3 * (base + r)] = v[3 * k]), (v[3 * (base + r) + 1] = v[3 * k + 1])));
  const t = new Uint32Array(6 * ((nx - 1) * (ny - 1) + ring.length));
  let q = 0;
  for (let j = 0; j + 1 < ny; j++)
    for (let i = 0; i + 1 < nx; i++) {
      const a = j * nx + i;
      (t[q] = a), (t[q + 1] = a + 1), (t[q + 2] = a + nx + 1), (t[q + 3] = a), (t[q + 4] = a + nx + 1), (t[q + 5] = a + nx);
      q += 6;
    }
  for (let k = 0; k < ring.length; k++) {
    const m = (k + 1) % ring.length;
    t.set([ring[k], ring[m], base + m, ring[k], base + m, base + k], q);
    q += 6;
  }
  const geo = new THREE.BufferGeometry();
  geo.setAttribute('position', new THREE.BufferAttribute(v, 3));
  geo.setIndex(new THREE.BufferAttribute(t.subarray(0, q), 1));
  setHeights(geo, s, ring);
  // Pushed back in depth: the path of a face cut runs on its top.
  const mat = new THREE.MeshPhongMaterial({ color: 0x8a9bb0, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  const mesh = new THREE.Mesh(geo, mat);
  mesh.userData.grid = { key: gridKey(s), ring };
  return mesh;
}

const gridKey = (s) => [s.nx, s.ny, s.x0, s.y0, s.x1, s.y1, s.cell, s.bottom].join(' ');

// The heights of grid s into the mesh's positions (the top, then the walls' top edge; their
// foot stays at the bottom), and the normals again.
function setHeights(geo, s, ring) {
  const pos = geo.getAttribute('position'), v = pos.array, n = s.nx * s.ny;
  for (let k = 0; k < n; k++) v[3 * k + 2] = s.z[k];
  for (let r = 0; r < ring.length; r++) v[3 * (n + r) + 2] = s.bottom;
  pos.needsUpdate = true;
  // Normals straight from the heights (central differences; computeVertexNormals walks the
  // 130,000 triangles with vector objects, several times slower), the walls' foot outwards.
  let nrm = geo.getAttribute('normal');
  if (!nrm) geo.setAttribute('normal', (nrm = new THREE.BufferAttribute(new Float32Array(v.length), 3)));
  const a = nrm.array, { nx, ny } = s, c = s.cell || 1;
  for (let j = 0; j < ny; j++)
    for (let i = 0; i < nx; i++) {
      const k = j * nx + i;
      const dx = (v[3 * (k + (i + 1 < nx ? 1 : 0)) + 2] - v[3 * (k - (i > 0 ? 1 : 0)) + 2]) / c;
      const dy = (v[3 * (k + (j + 1 < ny ? nx : 0)) + 2] - v[3 * (k - (j > 0 ? nx : 0)) + 2]) / c;
      const l = Math.hypot(dx, dy, 2);
      (a[3 * k] = -dx / l), (a[3 * k + 1] = -dy / l), (a[3 * k + 2] = 2 / l);
    }
  const cx = (s.x0 + s.x1) / 2, cy = (s.y0 + s.y1) / 2;
  for (let r = 0; r < ring.length; r++) {
    const k = n + r, ox = v[3 * k] - cx, oy = v[3 * k + 1] - cy, l = Math.hypot(ox, oy) || 1;
    (a[3 * k] = ox / l), (a[3 * k + 1] = oy / l), (a[3 * k + 2] = 0);
  }
  nrm.needsUpdate = true;
  geo.computeBoundingSphere();
}

// Another stock on the same grid drawn by changing the heights of `mesh` in place (no new
// buffers, no new index): false when the mesh is not a grid of the same cells.
export function regrid(mesh, s) {
  const g = mesh?.userData?.grid;
  if (!g || s.type !== 'grid' || g.key !== gridKey(s) || s.z?.length !== s.nx * s.ny) return false;
  setHeights(mesh.geometry, s, g.ring);
  return true;
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
    const stock = pick === 'final' ? m.answer.stock : this.shots[pick].stock;
    this.shown = pick;
    if (regrid(old, stock)) return; // a mill: the same grid, new heights
    if (old) {
      group.remove(old);
      dispose(old);
    }
    const obj = drawStock(stock, m.lathe);
    if (obj) group.add(obj);
  }
}
