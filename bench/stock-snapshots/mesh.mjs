// The page's cost of crossing into another stock snapshot (web/src/stock.js): a 256 x 256 grid
// built as a mesh once, then given new heights in place (regrid) as the timeline moves on.
// Node, no GPU: the JavaScript only (the upload of 66,000 positions and normals comes on top).
import { drawStock, regrid } from '../../web/src/stock.js';

const nx = 256, ny = 256;
const grid = (d) => ({
  type: 'grid', nx, ny, x0: 0, y0: 0, x1: 100, y1: 100, cell: 100 / 256, step: 4, top: 0, bottom: -20,
  z: Float32Array.from({ length: nx * ny }, (_, k) => -((k * d) % 7) / 7),
});
const shots = Array.from({ length: 16 }, (_, d) => grid(d + 1));
const median = (a) => a.sort((x, y) => x - y)[a.length >> 1];
const build = [], update = [];
let mesh = null;
for (const s of shots) {
  const t = performance.now();
  mesh = drawStock(s, false);
  build.push(performance.now() - t);
}
for (let r = 0; r < 4; r++)
  for (const s of shots) {
    const t = performance.now();
    if (!regrid(mesh, s)) throw new Error('regrid refused a grid of the same cells');
    update.push(performance.now() - t);
  }
console.log(`mesh of a 256 x 256 snapshot: built ${median(build).toFixed(1)} ms, heights replaced in place ${median(update).toFixed(1)} ms (medians)`);
