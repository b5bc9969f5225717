// The measuring tool of the 3D view: with *Measure* on, two clicks on the path pick two points,
// each snapped to the nearest end point of a segment of the drawn path, and the view shows the
// distance between them and dX, dY, dZ (a lathe: dX on the diameter, the distance in the
// half-section). A third click starts a new measurement; Escape or the button ends it.
import * as THREE from 'three';
import { stateAt, moveOfVertex } from './model.js';

const SNAP_PX = 14;

// Vertex k of the path buffer (scene coordinates) as program coordinates: a lathe's scene
// (Z, 0, radius) is X (diameter), Z.
export function vertexPoint(model, k) {
  const v = model.vertices, x = v[k * 3], y = v[k * 3 + 1], z = v[k * 3 + 2];
  return model.lathe ? { X: 2 * z, Z: x } : { X: x, Y: y, Z: z };
}

// The distance between two vertices and the differences per axis (B - A).
export function measure(model, a, b) {
  const pa = vertexPoint(model, a), pb = vertexPoint(model, b);
  const d = {};
  for (const k of Object.keys(pa)) d[k] = pb[k] - pa[k];
  const v = model.vertices;
  const dist = Math.hypot(v[b * 3] - v[a * 3], v[b * 3 + 1] - v[a * 3 + 1], v[b * 3 + 2] - v[a * 3 + 2]);
  return { a: pa, b: pb, d, distance: dist };
}


export class Measure {
  // view: the View3D; button: the toggle; panel: where the result is written.
  constructor(view, button, panel) {
    this.view = view;
    this.button = button;
    this.panel = panel;
    this.model = null;
    this.picked = [];
    this.marks = new THREE.Group();
    this.marks.renderOrder = 11;
    view.scene.add(this.marks);
    view.host.measure = this; // the browser tests reach it through the view's element
    button.addEventListener('click', () => this.toggle());
    document.addEventListener('keydown', (e) => {
      if (e.key === 'Escape' && this.on) this.toggle(false);
    });
    const canvas = view.renderer.domElement;
    let down = null;
    canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
    canvas.addEventListener('pointerup', (e) => {
      // A click, not the end of an orbit or a pan.
      if (this.on && down && Math.hypot(e.clientX - down.x, e.clientY - down.y) < 4) this.pickAt(e.clientX, e.clientY);
      down = null;
    });
    this.show();
  }

  get on() {
    return !!this.view.measuring;
  }

  toggle(on = !this.on) {
    this.view.measuring = on; // the path link leaves clicks to the measure while it is on
    this.button.classList.toggle('active', on);
    this.view.host.dataset.measuring = String(on);
    this.clear();
  }

  setModel(model) {
    this.model = model;
    this.clear();
  }

  clear() {
    this.picked = [];
    this.drawMarks();
    this.show();
  }

  // The path vertex nearest to a client point on the screen, within SNAP_PX, or -1.
  vertexAt(cx, cy) {
    const model = this.model;
    if (!model) return -1;
    const cam = this.view.camera;
    cam.updateMatrixWorld();
    const m = new THREE.Matrix4().multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse).elements;
    const rect = this.view.renderer.domElement.getBoundingClientRect();
    const v = model.vertices;
    let best = -1, bestD = SNAP_PX * SNAP_PX;
    for (let k = 0; k < v.length / 3; k++) {
      const x = v[k * 3], y = v[k * 3 + 1], z = v[k * 3 + 2];
      const w = m[3] * x + m[7] * y + m[11] * z + m[15];
      if (w <= 0) continue;
      const px = rect.left + ((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) * 0.5 * rect.width;
      const py = rect.top + (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) * 0.5 * rect.height;
      const d = (px - cx) ** 2 + (py - cy) ** 2;
      if (d < bestD) (bestD = d), (best = k);
    }
    return best;
  }

  pickAt(cx, cy) {
    const k = this.vertexAt(cx, cy);
    this.view.host.dataset.measureSnap = String(k);
    if (k < 0) return;
    if (this.picked.length === 2) this.picked = [];
    this.picked.push(k);
    this.drawMarks();
    this.show();
  }

  drawMarks() {
    for (const o of this.marks.children) {
      o.geometry.dispose();
      o.material.dispose();
    }
    this.marks.clear();
    if (this.model && this.picked.length) {
      const v = this.model.vertices;
      const pts = this.picked.map((k) => new THREE.Vector3(v[k * 3], v[k * 3 + 1], v[k * 3 + 2]));
      const colour = getComputedStyle(document.documentElement).getPropertyValue('--path-highlight').trim() || '#ffffff';
      const geo = new THREE.BufferGeometry().setFromPoints(pts);
      this.marks.add(new THREE.Points(geo, new THREE.PointsMaterial({ color: colour, size: 9, sizeAttenuation: false, depthTest: false })));
      if (pts.length === 2)
        this.marks.add(new THREE.Line(geo.clone(), new THREE.LineBasicMaterial({ color: colour, depthTest: false })));
    }
    this.view.draw();
  }

  // The result: the points and the distance in the program's units at the second point.
  show() {
    const p = this.panel;
    p.hidden = !this.on;
    if (!this.on) return;
    if (!this.model) return (p.textContent = 'Measure: run a program first');
    if (this.picked.length < 2)
      return (p.textContent = this.picked.length ? 'Measure: pick the second point' : 'Measure: pick a point on the path (snaps to segment ends)');
    const [a, b] = this.picked;
    const r = measure(this.model, a, b);
    const units = stateAt(this.model, this.model.mEvent[moveOfVertex(this.model, b)])?.modal?.units === 'inch' ? 'in' : 'mm';
    const dec = units === 'in' ? 4 : 3;
    const f = (x) => (Math.abs(x) < 0.5 * 10 ** -dec ? 0 : x).toFixed(dec);
    const pt = (q) => Object.entries(q).map(([k, x]) => `${k}${f(x)}`).join(' ');
    const deltas = Object.entries(r.d).map(([k, x]) => `<span data-axis="${k}">d${k} ${f(x)}</span>`).join(' ');
    p.innerHTML =
      `<b data-measure="distance">${f(r.distance)}</b> ${units}${this.model.lathe ? ' (dX on the diameter)' : ''}<br>` +
      `${deltas}<br><small>A ${pt(r.a)} · B ${pt(r.b)}</small>`;
  }
}
