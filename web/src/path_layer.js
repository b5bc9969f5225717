// The toolpath as a layer drawn once per camera position, so that moving along the timeline
// costs one full-screen pass, not a million segments (software WebGL draws about a
// microsecond a segment). The path is rendered into a float render target: each pixel keeps
// the colour of the nearest segment and, in alpha, 1 + the index of its event (exact up to
// 2^24 events), and its depth in a depth texture. A scrub or a step only changes the `done`
// uniform of the pass that puts the layer on the screen: events before it bright, the others
// dim. That pass writes the layer's depth too, so the grid, the stock and the tool drawn after
// it are hidden where the path is in front of them. Without float render targets (no
// EXT_color_buffer_float) the view falls back to drawing the path itself, the timeline as
// two draw ranges. While the camera moves (an orbit, a pan, a zoom) the layer is drawn from
// the path's coarse copy when it has one (path_lod.js: about 30 times fewer segments at a
// million moves); the view draws the full path again when the camera stops (view3d.js).
import * as THREE from 'three';

const PATH_VERTEX = /* glsl */ `
attribute float eventIndex;
varying vec3 vColor;
varying float vIndex;
void main() {
  vColor = color.rgb;
  vIndex = eventIndex;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;
const PATH_FRAGMENT = /* glsl */ `
varying vec3 vColor;
varying float vIndex;
void main() { gl_FragColor = vec4(vColor, vIndex + 1.0); }`;
const SHOW_VERTEX = /* glsl */ `
varying vec2 vUv;
void main() { vUv = uv; gl_Position = vec4(position.xy, 0.0, 1.0); }`;
const SHOW_FRAGMENT = /* glsl */ `
uniform sampler2D layer;
uniform sampler2D depth;
uniform float done;
uniform float dim;
varying vec2 vUv;
void main() {
  vec4 t = texture2D(layer, vUv);
  if (t.a < 0.5) discard;
  gl_FragDepth = texture2D(depth, vUv).r;
  gl_FragColor = vec4(t.rgb, t.a - 1.0 < done - 0.5 ? 1.0 : dim);
}`;

export class PathLayer {
  static supported(renderer) {
    return renderer.capabilities.isWebGL2 && renderer.extensions.has('EXT_color_buffer_float');
  }

  // geometry: position, color (normalized) and eventIndex attributes.
  constructor(geometry) {
    this.scene = new THREE.Scene();
    this.material = new THREE.ShaderMaterial({ vertexShader: PATH_VERTEX, fragmentShader: PATH_FRAGMENT, vertexColors: true });
    this.lines = new THREE.LineSegments(geometry, this.material);
    this.lines.frustumCulled = false;
    this.scene.add(this.lines);
    this.target = new THREE.WebGLRenderTarget(1, 1, {
      type: THREE.FloatType, format: THREE.RGBAFormat, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter,
      depthBuffer: true, generateMipmaps: false, depthTexture: new THREE.DepthTexture(1, 1),
    });
    this.show = new THREE.ShaderMaterial({
      vertexShader: SHOW_VERTEX, fragmentShader: SHOW_FRAGMENT, transparent: true, depthTest: true, depthFunc: THREE.AlwaysDepth, depthWrite: true,
      uniforms: { layer: { value: this.target.texture }, depth: { value: this.target.depthTexture }, done: { value: 0 }, dim: { value: 0.28 } },
    });
    this.quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), this.show);
    this.quad.frustumCulled = false;
    this.quadScene = new THREE.Scene();
    this.quadScene.add(this.quad);
    this.quadCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
    this.dirty = true;
    this.lastCamera = new THREE.Matrix4();
    this.coarse = null; // LineSegments of the coarse copy, once it came
    this.coarseShown = false; // the layer holds the coarse copy's drawing
  }

  // path: coarsePath()'s arrays; sphere: the full path's bounding sphere. Its colours follow
  // the full path's (setColours).
  setCoarse(path, sphere) {
    const g = new THREE.BufferGeometry();
    g.boundingSphere = sphere;
    g.setAttribute('position', new THREE.BufferAttribute(path.vertices, 3));
    g.setAttribute('color', new THREE.BufferAttribute(path.colors, 4, true));
    g.setAttribute('eventIndex', new THREE.BufferAttribute(path.vertexEvent, 1));
    this.coarse = new THREE.LineSegments(g, this.material);
    this.coarse.frustumCulled = false;
    this.coarse.visible = false;
    this.scene.add(this.coarse);
    this.coarseSource = path.source;
    this.coarseColours(this.lines.geometry.getAttribute('color').array); // the layer stays as drawn
  }

  // rgb: the full path's new vertex colours (RGBA, already in its attribute): the layer is
  // drawn again.
  setColours(rgb) {
    this.dirty = true;
    this.coarseColours(rgb);
  }

  // The coarse copy takes the colours of the vertices it stands for.
  coarseColours(rgb) {
    if (!this.coarse) return;
    const attr = this.coarse.geometry.getAttribute('color'), c = attr.array, src = this.coarseSource;
    for (let k = 0; k < src.length; k++) c.set(rgb.subarray(4 * src[k], 4 * src[k] + 4), 4 * k);
    attr.needsUpdate = true;
  }

  setDone(events) {
    this.show.uniforms.done.value = events;
  }

  // Draws the layer (again when the camera or the size changed), then puts it on the screen;
  // moving: from the coarse copy, when there is one.
  render(renderer, camera, moving = false) {
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    if (this.target.width !== size.x || this.target.height !== size.y) {
      this.target.setSize(size.x, size.y);
      this.dirty = true;
    }
    camera.updateMatrixWorld();
    const pose = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    if (!pose.equals(this.lastCamera)) this.dirty = true;
    if (this.dirty) {
      this.lastCamera.copy(pose);
      const clear = renderer.getClearColor(new THREE.Color()), alpha = renderer.getClearAlpha();
      renderer.setRenderTarget(this.target);
      renderer.setClearColor(0x000000, 0);
      renderer.clear();
      this.coarseShown = moving && this.coarse !== null;
      this.lines.visible = !this.coarseShown;
      if (this.coarse) this.coarse.visible = this.coarseShown;
      renderer.render(this.scene, camera);
      renderer.setRenderTarget(null);
      renderer.setClearColor(clear, alpha);
      this.dirty = false;
    }
    renderer.render(this.quadScene, this.quadCamera);
  }

  dispose() {
    this.target.depthTexture.dispose();
    this.target.dispose();
    this.material.dispose();
    this.show.dispose();
    this.quad.geometry.dispose();
    this.coarse?.geometry.dispose();
  }
}
