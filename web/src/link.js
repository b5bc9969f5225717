// Path and program linked both ways: a click on a segment of the 3D path selects its program
// line, and the moves of the editor cursor's line are drawn over the path in the highlight
// colour. The link knows the model only through moveLine() and movePoints() below, so that a
// change of how moves are stored touches these two functions only.
import * as THREE from 'three';
import { movePointsAt, moveOfVertex } from './model.js';
import { drawnPoint } from './machine_frame.js';

// The program line of move i when it is in `file` (the editor's program), else 0.
export function moveLine(model, i, file) {
  const e = model.mEvent[i];
  return !file || model.answer.files?.[model.file[e]] === file ? model.line[e] : 0;
}

// The points of move i as drawn (work coordinates fixed on the machine, machine_frame.js).
export function movePoints(model, i) {
  return movePointsAt(model, i).map((p) => drawnPoint(model, i, p));
}

// line -> moves: the moves of each line of `file`, as index ranges into one Int32Array
// (a line in a loop has many moves; a line of a subprogram in another file has none).
export function lineIndex(model, file) {
  const n = model.moves;
  const lineOf = new Int32Array(n);
  let maxLine = 0;
  // moveLine() for every move, the file compared by its number (a million moves).
  const id = file ? (model.answer.files || []).indexOf(file) : -1;
  for (let i = 0; i < n; i++) {
    const e = model.mEvent[i];
    const line = !file || model.file[e] === id ? model.line[e] : 0;
    lineOf[i] = line;
    if (line > maxLine) maxLine = line;
  }
  const start = new Int32Array(maxLine + 2);
  for (let i = 0; i < n; i++) if (lineOf[i]) start[lineOf[i] + 1]++;
  for (let l = 1; l < start.length; l++) start[l] += start[l - 1];
  const moves = new Int32Array(start[maxLine + 1]);
  const fill = start.slice();
  for (let i = 0; i < n; i++) if (lineOf[i]) moves[fill[lineOf[i]]++] = i;
  return {
    lineOf,
    movesOf: (line) => (line >= 1 && line <= maxLine ? moves.subarray(start[line], start[line + 1]) : moves.subarray(0, 0)),
  };
}

const MAX_HIGHLIGHT_SEGMENTS = 200000;
const PICK_RADIUS_PX = 8;

export class PathLink {
  // view: the View3D (its scene, camera, canvas and toScene); onPick(line, move).
  constructor(view, onPick) {
    this.view = view;
    this.onPick = onPick;
    this.model = null;
    this.overlay = new THREE.LineSegments(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0xffffff, depthTest: false, transparent: true }),
    );
    this.overlay.renderOrder = 10;
    window.addEventListener('themechange', () => {
      this.overlay.material.color.set(this.colour());
      this.view.draw();
    });
    view.host.link = this; // the browser tests reach the link through the view's element
    const canvas = view.renderer.domElement;
    let down = null;
    canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
    canvas.addEventListener('pointerup', (e) => {
      // A click, not the end of an orbit or a pan; while measuring, the clicks are the measure's.
      if (down && !view.measuring && Math.hypot(e.clientX - down.x, e.clientY - down.y) < 4) this.pickAt(e.clientX, e.clientY);
      down = null;
    });
  }

  setModel(model, file) {
    this.model = model;
    this.index = lineIndex(model, file);
    this.line = 0;
    this.setHighlight([]);
  }

  get moveCount() {
    return this.model ? this.model.moves : 0;
  }

  points(i) {
    return movePoints(this.model, i);
  }

  // The screen position (client pixels) of a work point, for the tests and the picking.
  project() {
    const cam = this.view.camera;
    cam.updateMatrixWorld();
    const m = new THREE.Matrix4().multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse).elements;
    const rect = this.view.renderer.domElement.getBoundingClientRect();
    const lathe = this.view.lathe;
    return (p) => {
      const x = lathe ? p[2] : p[0], y = lathe ? 0 : p[1], z = lathe ? p[0] / 2 : p[2];
      const w = m[3] * x + m[7] * y + m[11] * z + m[15];
      if (w <= 0) return null;
      return [
        rect.left + ((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) * 0.5 * rect.width,
        rect.top + (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) * 0.5 * rect.height,
      ];
    };
  }

  // The move nearest to a client point, within PICK_RADIUS_PX, or -1: the segments of the
  // path's vertex buffer (scene coordinates), each pair one segment of one move.
  moveAt(cx, cy) {
    const model = this.model;
    if (!model) return -1;
    const cam = this.view.camera;
    cam.updateMatrixWorld();
    const m = new THREE.Matrix4().multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse).elements;
    const rect = this.view.renderer.domElement.getBoundingClientRect();
    const v = model.vertices;
    const px = new Float64Array(2);
    const proj = (k) => {
      const x = v[k * 3], y = v[k * 3 + 1], z = v[k * 3 + 2];
      const w = m[3] * x + m[7] * y + m[11] * z + m[15];
      if (w <= 0) return false;
      px[0] = rect.left + ((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) * 0.5 * rect.width;
      px[1] = rect.top + (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) * 0.5 * rect.height;
      return true;
    };
    let best = -1, bestD = PICK_RADIUS_PX * PICK_RADIUS_PX;
    for (let k = 0; k + 1 < v.length / 3; k += 2) {
      if (!proj(k)) continue;
      const ax = px[0], ay = px[1];
      if (!proj(k + 1)) continue;
      const dx = px[0] - ax, dy = px[1] - ay, len = dx * dx + dy * dy;
      const t = len > 0 ? Math.max(0, Math.min(1, ((cx - ax) * dx + (cy - ay) * dy) / len)) : 0;
      const ex = ax + t * dx - cx, ey = ay + t * dy - cy, d = ex * ex + ey * ey;
      if (d < bestD) (bestD = d), (best = k);
    }
    if (best < 0) return -1;
    return moveOfVertex(model, best); // the move whose vertices hold segment `best`
  }

  pickAt(cx, cy) {
    const i = this.moveAt(cx, cy);
    this.view.host.dataset.pickedMove = String(i);
    if (i < 0) return;
    const line = this.index.lineOf[i];
    if (line) this.onPick(line, i);
  }

  // The editor's cursor is on `line`: its moves drawn over the path.
  highlightLine(line) {
    if (!this.model || line === this.line) return;
    this.line = line;
    this.setHighlight(this.index.movesOf(line));
  }

  colour() {
    return getComputedStyle(document.documentElement).getPropertyValue('--path-highlight').trim() || '#ffffff';
  }

  setHighlight(moves) {
    const pos = [];
    let segments = 0;
    for (const i of moves) {
      const pts = movePoints(this.model, i).map((p) => this.view.toScene(p));
      for (let j = 1; j < pts.length && segments < MAX_HIGHLIGHT_SEGMENTS; j++, segments++)
        pos.push(pts[j - 1].x, pts[j - 1].y, pts[j - 1].z, pts[j].x, pts[j].y, pts[j].z);
    }
    const geo = this.overlay.geometry;
    geo.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    geo.computeBoundingSphere();
    this.overlay.material.color.set(this.colour());
    if (!this.overlay.parent) this.view.scene.add(this.overlay);
    this.view.host.dataset.highlightMoves = String(moves.length);
    this.view.draw();
  }
}
