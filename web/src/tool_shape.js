// The tool in the 3D view drawn from the setup's tool description ([tools.T], the shapes the
// stock simulation cuts with, sent by the server as answer.tools: server/viewer_tools.hpp):
// a mill's cutter as a solid of revolution from its profile (flat, face, bull, ball, drill),
// a probe's ball on its stem, the holder when given; a lathe's insert (or drill) outline and
// shank in the half-section, with its tip direction. The tool in the spindle changes with
// the timeline (M06 on a mill, T on a lathe). A tool without a description keeps the view's
// generic tool.
import * as THREE from 'three';
import { eventAt } from './model.js';
import { KIND } from './wire.js';

const STEEL = 0xc8ced6, HOLDER = 0x6a7482;
const material = (color, opacity = 0.9) => new THREE.MeshPhongMaterial({ color, transparent: true, opacity, side: THREE.DoubleSide });

// The tool in the spindle after each event (0 before the first).
function toolsOfEvents(m) {
  const out = new Int32Array(m.n);
  let tool = 0;
  for (let i = 0; i < m.n; i++) {
    if (m.kind[i] === KIND.tool) {
      const e = eventAt(m, i);
      if (e.change || m.lathe) tool = e.tool;
    }
    out[i] = tool;
  }
  return out;
}

// A mill tool standing on its tip at the origin, along +Z.
function millShape(t) {
  const g = new THREE.Group();
  const R = t.diameter / 2;
  if (t.type === 'probe') {
    const ball = new THREE.Mesh(new THREE.SphereGeometry(R, 24, 16), material(0xd94f4f));
    ball.position.z = R;
    const stem = new THREE.Mesh(new THREE.CylinderGeometry(R * 0.35, R * 0.35, R * 8, 16), material(STEEL));
    stem.rotation.x = Math.PI / 2;
    stem.position.z = R + R * 4;
    g.add(ball, stem);
    return g;
  }
  const pts = t.profile.map(([r, h]) => new THREE.Vector2(r, h));
  pts.push(new THREE.Vector2(R, t.length), new THREE.Vector2(0, t.length));
  const body = new THREE.Mesh(new THREE.LatheGeometry(pts, 48), material(STEEL));
  body.rotation.x = Math.PI / 2; // the lathe geometry's axis (Y) along the spindle (Z)
  g.add(body);
  if (t.holder && t.holder.radius > 0 && t.holder.length > 0) {
    const h = t.holder;
    const holder = new THREE.Mesh(new THREE.CylinderGeometry(h.radius, h.radius, h.length, 32), material(HOLDER, 0.7));
    holder.rotation.x = Math.PI / 2;
    holder.position.z = h.z + h.length / 2;
    g.add(holder);
    if (h.z > t.length) {
      const r = Math.min(R, h.radius) * 0.8;
      const shank = new THREE.Mesh(new THREE.CylinderGeometry(r, r, h.z - t.length, 24), material(STEEL));
      shank.rotation.x = Math.PI / 2;
      shank.position.z = (t.length + h.z) / 2;
      g.add(shank);
    }
  }
  return g;
}

// A lathe tool in the half-section: outline points (r, z) relative to the programmed point;
// the scene's x is Z and its z the radius, so the shape (z, r) is turned into the XZ plane.
function latheShape(t) {
  const g = new THREE.Group();
  const flat = (points, color, opacity) => {
    if (!points || points.length < 3) return;
    const shape = new THREE.Shape(points.map(([r, z]) => new THREE.Vector2(z, r)));
    const mesh = new THREE.Mesh(new THREE.ShapeGeometry(shape), material(color, opacity));
    mesh.rotation.x = Math.PI / 2; // (x, y) -> (x, 0, y)
    g.add(mesh);
  };
  flat(t.holder, HOLDER, 0.7);
  flat(t.outline, STEEL, 0.95);
  return g;
}

export class ToolShapes {
  constructor(view) {
    this.view = view;
    this.model = null;
  }

  setModel(model) {
    this.model = model;
    this.tools = model.answer.tools || {};
    this.toolOf = toolsOfEvents(model);
    this.generic = [...this.view.tool.children]; // the view's tool, made for this run
    this.shaped = null;
    this.current = undefined;
  }

  // The description of tool T: [tools.T], on a lathe also the turret number (T0101 -> 1).
  specOf(T) {
    return this.tools[T] || (this.model.lathe ? this.tools[Math.floor(T / 100)] : undefined);
  }

  // The tool in the spindle at event index (the event in progress, else the last one done).
  update(index) {
    if (!this.model) return;
    const T = index >= 0 && this.model.n ? this.toolOf[Math.min(index, this.model.n - 1)] : 0;
    if (T === this.current) return;
    this.current = T;
    const tool = this.view.tool;
    if (this.shaped) {
      tool.remove(this.shaped);
      this.shaped.traverse((o) => {
        o.geometry?.dispose();
        o.material?.dispose();
      });
      this.shaped = null;
    }
    const spec = T > 0 ? this.specOf(T) : undefined;
    if (!spec || (spec.type === 'insert' && !this.model.lathe) || (!this.model.lathe && spec.type !== 'probe' && !spec.profile)) {
      for (const c of this.generic) if (!c.parent) tool.add(c);
      this.view.host.dataset.toolShape = 'generic';
      return;
    }
    for (const c of this.generic) tool.remove(c);
    this.shaped = this.model.lathe ? latheShape(spec) : millShape(spec);
    tool.add(this.shaped);
    this.view.host.dataset.toolShape = `T${T} ${spec.type}`;
  }
}
