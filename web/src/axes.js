// The work-coordinate axes of the 3D view: neutral grey lines with X, Y and Z written at
// their ends, so that no axis shares a colour with a kind of move (rapid red, feed cyan,
// ...). A lathe's half-section shows Z to the right and X (the radius) up.
import * as THREE from 'three';

export const AXIS_COLOUR = 0x9aa3ad;

function label(text, size) {
  const c = document.createElement('canvas');
  c.width = c.height = 64;
  const ctx = c.getContext('2d');
  ctx.fillStyle = '#9aa3ad';
  ctx.font = 'bold 48px sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText(text, 32, 34);
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(c), depthTest: false }));
  sprite.scale.set(size, size, 1);
  return sprite;
}

// Axes of `length` scene units from the origin.
export function makeAxes(length, lathe) {
  const g = new THREE.Group();
  g.name = 'axes';
  const dirs = lathe
    ? [['Z', new THREE.Vector3(1, 0, 0)], ['X', new THREE.Vector3(0, 0, 1)]]
    : [['X', new THREE.Vector3(1, 0, 0)], ['Y', new THREE.Vector3(0, 1, 0)], ['Z', new THREE.Vector3(0, 0, 1)]];
  const pts = [];
  for (const [, d] of dirs) pts.push(new THREE.Vector3(), d.clone().multiplyScalar(length));
  g.add(new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(pts), new THREE.LineBasicMaterial({ color: AXIS_COLOUR })));
  for (const [name, d] of dirs) {
    const s = label(name, length * 0.35);
    s.position.copy(d).multiplyScalar(length * 1.15);
    g.add(s);
  }
  return g;
}
