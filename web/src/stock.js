// The stock, when the run answer carries one (`answer.stock`, from the stock simulation of
// issue 8; ncvm does not compute it yet). Two forms are drawn:
//   {"type": "mesh", "vertices": [x, y, z, ...], "triangles": [i, j, k, ...]}
//       a mill's stock, work coordinates;
//   {"type": "profile", "points": [[z, x], ...]}
//       a lathe's stock as its outline (X a diameter), revolved over half a turn so that the
//       half-section shows the cut.
import * as THREE from 'three';

export function drawStock(stock, lathe) {
  const mat = new THREE.MeshPhongMaterial({ color: 0x8a9bb0, transparent: true, opacity: 0.45, side: THREE.DoubleSide });
  if (stock.type === 'mesh' && Array.isArray(stock.vertices) && Array.isArray(stock.triangles)) {
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', new THREE.Float32BufferAttribute(stock.vertices, 3));
    geo.setIndex(stock.triangles);
    geo.computeVertexNormals();
    return new THREE.Mesh(geo, mat);
  }
  if (stock.type === 'profile' && Array.isArray(stock.points) && lathe) {
    // LatheGeometry revolves (x, y) about y: x = radius, y = Z; then Z goes to scene x.
    const pts = stock.points.map(([z, x]) => new THREE.Vector2(Math.abs(x) / 2, z));
    const geo = new THREE.LatheGeometry(pts, 48, Math.PI, Math.PI);
    const mesh = new THREE.Mesh(geo, mat);
    mesh.rotation.z = -Math.PI / 2;
    return mesh;
  }
  return null;
}
