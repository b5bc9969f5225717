// The stock, when the run answer carries one (`answer.stock`: the final stock of the stock
// simulation, made when the setup has a [stock]; docs/web-viewer.md). Three forms are drawn:
//   {"type": "grid", "nx", "ny", "x0", "y0", "x1", "y1", "cell", "top", "bottom", "z": [...]}
//       a mill's stock as heights, row by row from y0, each row from x0 (work coordinates);
//   {"type": "profile", "rings": [{"hole": bool, "points": [[z, x], ...]}]}
//       a lathe's stock as its half-profile (X a diameter): the section through the axis,
//       filled, and the part revolved over the half turn behind it;
//   {"type": "mesh", "vertices": [x, y, z, ...], "triangles": [i, j, k, ...]}
//       any stock as triangles, work coordinates.
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
  if (!(nx > 0 && ny > 0) || !Array.isArray(s.z) || s.z.length !== nx * ny) return null;
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
