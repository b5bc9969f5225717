// The 3D view (three.js): the toolpath coloured by kind of move, the part done so far
// brighter than what is to come, the tool at the current step, orbit/pan/zoom and standard
// views. A lathe is drawn as a half-section in the XZ plane: Z to the right, the radius (X/2)
// up, the spindle axis as a line.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { drawStock } from './stock.js';
import { makeAxes } from './axes.js';
import { PathLayer } from './path_layer.js';

const BG = 0x15181d;
// The full path again this long after the camera stopped: after the end of a drag or a wheel
// turn, and while a drag holds still.
const REFINE_AFTER_END_MS = 150;
const REFINE_WHILE_STILL_MS = 500;

// True when WebGL is drawn by the CPU (SwiftShader, llvmpipe): multisampling there cost a
// third of every frame (bench/viewer: scrub 151 -> 94 ms, orbit 107 -> 78 ms at 43,000
// lines), while the path layer is not multisampled anyway.
function softwareGL() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(String(name));
}

export class View3D {
  constructor(host) {
    this.host = host;
    this.renderer = new THREE.WebGLRenderer({ antialias: !softwareGL(), preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(BG);
    host.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.1, 1e6);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    // An orbit, pan or zoom by the user draws the path's coarse copy (path_layer.js), and the
    // full path once the camera has stopped: at the end of the drag or wheel turn, or when a
    // drag holds still. A camera set by the program (setView) is drawn in full at once.
    this.interacting = false;
    this.refineTimer = null;
    this.controls.addEventListener('start', () => (this.interacting = true));
    this.controls.addEventListener('change', () => (this.interacting ? this.cameraMoved() : this.draw()));
    this.controls.addEventListener('end', () => {
      this.interacting = false;
      this.refineAfter(REFINE_AFTER_END_MS);
    });
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.7));
    const sun = new THREE.DirectionalLight(0xffffff, 0.8);
    sun.position.set(1, -2, 3);
    this.scene.add(sun);
    this.group = new THREE.Group();
    this.scene.add(this.group);
    this.tool = this.makeTool(5);
    this.scene.add(this.tool);
    this.lathe = false;
    this.bounds = new THREE.Box3(new THREE.Vector3(-50, -50, -50), new THREE.Vector3(50, 50, 50));
    new ResizeObserver(() => this.resize()).observe(host);
    this.resize();
  }

  // Work coordinates -> scene: a lathe's (X diameter, Z) become (Z, 0, X/2).
  toScene(p) {
    return this.lathe ? new THREE.Vector3(p[2], 0, p[0] / 2) : new THREE.Vector3(p[0], p[1], p[2]);
  }

  makeTool(size) {
    const g = new THREE.Group();
    const mat = new THREE.MeshPhongMaterial({ color: 0xd0d4da, transparent: true, opacity: 0.85 });
    const tip = new THREE.Mesh(new THREE.CylinderGeometry(size / 2, size / 2, size * 3, 24), mat);
    tip.rotation.x = Math.PI / 2;
    tip.position.z = size * 1.5;
    const holder = new THREE.Mesh(
      new THREE.CylinderGeometry(size * 1.4, size * 1.4, size * 2, 24),
      new THREE.MeshPhongMaterial({ color: 0x667080, transparent: true, opacity: 0.6 }),
    );
    holder.rotation.x = Math.PI / 2;
    holder.position.z = size * 4;
    g.add(tip, holder);
    return g;
  }

  // Frees the GPU buffers of everything in the group (the last run's path, grid, stock, the
  // axes and their label textures) and of the path layer.
  disposeGroup() {
    this.group.traverse((o) => {
      o.geometry?.dispose();
      for (const mat of [].concat(o.material || [])) {
        for (const v of Object.values(mat)) if (v?.isTexture) v.dispose();
        mat.dispose();
      }
    });
    this.group.clear();
    this.layer?.dispose();
    this.layer = null;
    this.pathGeometry?.dispose();
    this.pathGeometry = null;
  }

  setModel(model) {
    this.model = model;
    this.lathe = model.lathe;
    this.disposeGroup();
    const box = new THREE.Box3();
    box.expandByPoint(this.toScene(new Array(model.axes).fill(0)));
    if (model.bounds) {
      box.expandByPoint(new THREE.Vector3(...model.bounds.min));
      box.expandByPoint(new THREE.Vector3(...model.bounds.max));
    }
    if (box.isEmpty()) box.set(new THREE.Vector3(-50, -50, -50), new THREE.Vector3(50, 50, 50));
    const size = box.getSize(new THREE.Vector3()).length() || 100;
    box.expandByScalar(size * 0.05);
    this.bounds = box;
    // The whole path is one vertex buffer with a colour and an event index per vertex,
    // uploaded once, drawn as a layer (path_layer.js); else what is done is drawn bright, what
    // is to come dim: two draw ranges of the same attributes.
    const position = new THREE.BufferAttribute(model.vertices, 3);
    const color = new THREE.BufferAttribute(model.colors, 4, true); // RGBA (model.js)
    this.paths = {};
    if (PathLayer.supported(this.renderer)) {
      this.pathGeometry = new THREE.BufferGeometry();
      this.pathGeometry.setAttribute('position', position);
      this.pathGeometry.setAttribute('color', color);
      this.pathGeometry.setAttribute('eventIndex', new THREE.BufferAttribute(model.vertexEvent, 1));
      // Given, not computed: three.js sorts what it draws by distance and would otherwise go
      // through every vertex for it (0.2 s at a million moves).
      this.pathGeometry.boundingSphere = box.getBoundingSphere(new THREE.Sphere());
      this.layer = new PathLayer(this.pathGeometry);
      // The coarse copy is asked for after the first frame with the whole path, which it
      // would otherwise slow down.
      const sphere = this.pathGeometry.boundingSphere;
      requestAnimationFrame(() => setTimeout(() => this.model === model && model.coarse?.().then((path) => this.setCoarse(model, path, sphere))));
      delete this.host.dataset.coarse;
    }
    for (const done of this.layer ? [] : [true, false]) {
      const geo = new THREE.BufferGeometry();
      geo.setAttribute('position', position);
      geo.setAttribute('color', color);
      geo.boundingSphere = box.getBoundingSphere(new THREE.Sphere());
      const mat = new THREE.LineBasicMaterial({ vertexColors: true, transparent: !done, opacity: done ? 1 : 0.28 });
      const line = new THREE.LineSegments(geo, mat);
      line.frustumCulled = false;
      this.paths[done] = line;
      this.group.add(line);
    }
    this.vertexCount = model.vertices.length / 3;
    const grid = new THREE.GridHelper(Math.ceil(size / 10) * 20, 20, 0x3a4048, 0x262b31);
    if (!this.lathe) grid.rotation.x = Math.PI / 2;
    else grid.rotation.x = 0;
    grid.position.copy(this.lathe ? new THREE.Vector3(box.getCenter(new THREE.Vector3()).x, 0, 0) : new THREE.Vector3(0, 0, box.min.z));
    this.group.add(grid);
    this.group.add(makeAxes(size * 0.15, this.lathe));
    if (this.lathe) {
      // The spindle axis (X = 0).
      const axis = new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(box.min.x - size * 0.1, 0, 0),
        new THREE.Vector3(box.max.x + size * 0.1, 0, 0),
      ]);
      this.group.add(new THREE.Line(axis, new THREE.LineDashedMaterial({ color: 0x99a0aa, dashSize: 3, gapSize: 2 })).computeLineDistances());
    }
    // The final stock of the stock simulation, when the run answer has one; data-stock on
    // the view says which form was drawn (the browser test reads it).
    const stock = model.answer.stock ? drawStock(model.answer.stock, this.lathe) : null;
    if (stock) {
      this.group.add(stock);
      this.bounds.union(new THREE.Box3().setFromObject(stock)); // Fit frames the part too
    }
    this.host.dataset.stock = stock ? model.answer.stock.type : 'none';
    this.scene.remove(this.tool);
    this.tool.traverse((o) => {
      o.geometry?.dispose();
      o.material?.dispose();
    });
    // Sized to the part (mm or inch); on a lathe it stands along X, as a turret tool would.
    this.tool = this.makeTool(Math.min(10, size / 40));
    this.scene.add(this.tool);
    this.setView(this.lathe ? 'front' : 'iso');
  }

  // verticesDone: the vertices of the moves done so far (model.js verticesDone); only the
  // two draw ranges change.
  // eventsDone: the events done (the layer's threshold).
  setProgress(verticesDone, toolWork, eventsDone) {
    if (!this.model) return;
    if (this.layer) this.layer.setDone(eventsDone);
    else {
      const k = Math.max(0, Math.min(verticesDone, this.vertexCount));
      this.paths[true].geometry.setDrawRange(0, k);
      this.paths[false].geometry.setDrawRange(k, this.vertexCount - k);
    }
    if (toolWork) this.tool.position.copy(this.toScene(toolWork));
    this.draw();
  }

  // The path's one colour attribute: the layer's geometry's, or shared by both draw ranges.
  pathColourAttribute() {
    return (this.layer ? this.pathGeometry : this.paths[true].geometry).getAttribute('color');
  }

  // A new colour for every vertex of the path (colour_by.js): one upload, the draw ranges kept.
  setPathColours(rgb) {
    if (!this.model) return;
    const color = this.pathColourAttribute();
    color.array.set(rgb);
    color.needsUpdate = true;
    if (this.layer) this.layer.setColours(rgb); // the layer keeps the path drawn for the camera
    this.draw();
  }

  setView(name) {
    const b = this.bounds, c = b.getCenter(new THREE.Vector3());
    // Far enough for the bounding sphere to fit the narrower of the two fields of view: a
    // view taller than wide is limited by its horizontal one.
    const radius = b.getSize(new THREE.Vector3()).length() / 2 || 50;
    const vfov = THREE.MathUtils.degToRad(this.camera.fov);
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * this.camera.aspect);
    const d = (radius / Math.sin(Math.min(vfov, hfov) / 2)) * 1.05 + 1;
    const dirs = {
      iso: new THREE.Vector3(1, -1.2, 0.9),
      top: new THREE.Vector3(0, -0.0001, 1),
      front: new THREE.Vector3(0, -1, 0.0001),
      side: new THREE.Vector3(1, 0, 0.0001),
      fit: this.camera.position.clone().sub(this.controls.target),
    };
    const dir = (dirs[name] || dirs.iso).clone().normalize();
    this.camera.position.copy(c).addScaledVector(dir, d);
    this.controls.target.copy(c);
    this.camera.near = d / 1000;
    this.camera.far = d * 100;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.draw();
  }

  cameraMoved() {
    this.draw(true);
    this.refineAfter(REFINE_WHILE_STILL_MS);
  }

  refineAfter(ms) {
    clearTimeout(this.refineTimer);
    this.refineTimer = setTimeout(() => {
      this.refineTimer = null;
      if (!this.layer?.coarseShown) return;
      this.layer.dirty = true;
      this.draw();
    }, ms);
  }

  // The path's coarse copy (run.worker.js), when it comes for the model still shown.
  setCoarse(model, path, sphere) {
    if (this.model !== model || !this.layer) return;
    this.layer.setCoarse(path, sphere);
    this.host.dataset.coarse = String(path.vertices.length / 6);
  }

  resize() {
    const w = this.host.clientWidth || 300, h = this.host.clientHeight || 200;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  // moving: the camera is being moved by the user (the layer may draw the coarse copy).
  draw(moving = false) {
    if (!this.layer) return this.renderer.render(this.scene, this.camera);
    // The path layer first, then the grid, stock and tool over it.
    const r = this.renderer;
    r.clear();
    this.layer.render(r, this.camera, moving);
    this.host.dataset.detail = this.layer.coarseShown ? 'coarse' : 'full';
    r.autoClear = false;
    r.render(this.scene, this.camera);
    r.autoClear = true;
  }
}
