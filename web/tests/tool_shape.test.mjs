// The tool drawn from the setup's tool description: the face mill of face-milling-g42 at its
// Ø50, the Ø16 end mill and then the probe's Ø4 ball of probe-milled-bore as the timeline
// passes the M06, a lathe insert in the half-section on the side its tip direction gives;
// without a description, the generic tool.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/tool_shape.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, typeProgram, tab } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

// The tool's size in the scene (its bounding box less its position) and what it is.
const tool = () =>
  page.evaluate(() => {
    const host = document.getElementById('view');
    const t = host.link.view.tool;
    t.updateMatrixWorld(true);
    const THREE = t.position.constructor; // Vector3
    const box = { min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity] };
    t.traverse((o) => {
      if (!o.isMesh) return;
      o.geometry.computeBoundingBox();
      const b = o.geometry.boundingBox;
      for (const x of [b.min.x, b.max.x]) for (const y of [b.min.y, b.max.y]) for (const z of [b.min.z, b.max.z]) {
        const v = new THREE(x, y, z).applyMatrix4(o.matrixWorld).sub(t.position);
        ['x', 'y', 'z'].forEach((k, a) => {
          box.min[a] = Math.min(box.min[a], v[k]);
          box.max[a] = Math.max(box.max[a], v[k]);
        });
      }
    });
    return { shape: host.dataset.toolShape, min: box.min, max: box.max, size: box.max.map((v, a) => v - box.min[a]) };
  });
const scrubTo = (fraction) =>
  page.$eval('#scrub', (el, f) => {
    el.value = String(Math.round(Number(el.max) * f));
    el.dispatchEvent(new Event('input'));
  }, fraction);
const close = (a, b, what) => assert.ok(Math.abs(a - b) < 0.05, `${what}: ${a} is not ${b}`);

test('face-milling-g42: the face mill at its diameter, 50 mm wide and short', async () => {
  await openExample(page, 'face-milling-g42/face-milling-g42.nc');
  await runAndWait(page);
  const t = await tool();
  assert.equal(t.shape, 'T1 face');
  close(t.size[0], 50, 'width');
  close(t.size[1], 50, 'depth');
  close(t.min[2], 0, 'the tip at the programmed point');
  assert.ok(t.size[2] < 25, `a face mill is short: ${t.size[2]}`);
  await page.click('.views button[data-view="front"]');
  await h.shot('tool-face-mill');
});

test('probe-milled-bore: the end mill, then the probe after its M06', async () => {
  await openExample(page, 'probe-milled-bore/bore-o5001.nc');
  await runAndWait(page);
  await scrubTo(0.1);
  let t = await tool();
  assert.equal(t.shape, 'T1 flat');
  close(t.size[0], 16, 'end mill');
  await scrubTo(1);
  t = await tool();
  assert.equal(t.shape, 'T20 probe');
  close(t.size[0], 4, 'probe ball');
  close(t.min[2], 0, 'the ball on the programmed point');
  await scrubTo(0);
  assert.equal((await tool()).shape, 'generic', 'before the first M06');
});

test('a lathe insert: its outline in the half-section, on the side of its tip direction', async () => {
  await openExample(page, 'convex-arc-turning/arc-tnrc-g42.nc');
  await runAndWait(page);
  const t = await tool();
  assert.match(t.shape, /^T\d+ insert$/);
  close(t.size[1], 0, 'flat in the XZ plane');
  // Tip 3: the imaginary tip at the lower left of the nose (-X, -Z), the insert above and to
  // the right of the programmed point, its edges about 10 mm long.
  assert.ok(t.min[0] > -0.05 && t.min[2] > -0.05, `${t.min}`);
  assert.ok(t.max[0] > 5 && t.max[2] > 5, `${t.max}`);
  await h.shot('tool-lathe-insert');
});

test('a program without tool descriptions keeps the generic tool', async () => {
  // A new program on the default mill (an edit of the lathe example would run with its setup).
  await page.selectOption('#files', '');
  await tab(page, 'setup');
  await page.fill('#setup-text', '');
  await tab(page, 'editor');
  await typeProgram(page, 'O0001\nT1 M06\nG00 X0 Y0 Z5.\nG01 Z-1. F100.\nM30\n');
  await runAndWait(page);
  assert.match(await page.textContent('#status'), /^ended M30/);
  assert.equal((await tool()).shape, 'generic');
});
