// The stock follows the timeline: scrubbing shows the stock as cut up to the current move (the
// server's snapshots, src/server/stock_snapshots.hpp), the final stock at the end, on a mill
// (face-milling-g42: the height field) and on a lathe (convex-arc-turning: the profile).
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/stock.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

const scrubTo = (fraction) =>
  page.$eval('#scrub', (el, f) => {
    el.value = String(Math.round(Number(el.max) * f));
    el.dispatchEvent(new Event('input'));
  }, fraction);

// The stock drawn in the scene: the move of its snapshot ("final" at the end), the label, and
// sums over the vertices of its meshes (the drawn geometry itself, not the data it came from).
const drawn = () =>
  page.evaluate(() => {
    const host = document.getElementById('view');
    const stock = host.link.view.group.getObjectByName('stock');
    let vertices = 0, sumZ = 0, sumAll = 0, meshes = 0;
    stock?.traverse((o) => {
      const p = o.geometry?.getAttribute('position');
      if (!p) return;
      meshes++;
      for (let i = 0; i < p.count; i++) {
        vertices++;
        sumZ += p.getZ(i);
        sumAll += p.getX(i) + 2 * p.getY(i) + 3 * p.getZ(i);
      }
    });
    const label = document.getElementById('stock-label');
    return { move: host.dataset.stockMove, label: label.hidden ? null : label.textContent, vertices, sumZ, sumAll, meshes, objects: host.link.view.group.children.filter((c) => c.name === 'stock').length };
  });

test('mill: scrubbing changes the height field drawn, snapshot by snapshot', async () => {
  await openExample(page, 'face-milling-g42/face-milling-g42.nc');
  await runAndWait(page);
  const end = await drawn();
  assert.equal(end.move, 'final');
  assert.match(end.label, /^stock: final, after all \d+ moves$/);
  await scrubTo(0);
  const first = await drawn();
  assert.equal(first.move, '0');
  assert.match(first.label, /^stock after move 0 of \d+/);
  // Along the timeline the face is cut down: the heights drawn go down, never up, and part
  // way they are neither the bar's nor the final ones.
  let last = first, mid = null;
  for (let k = 1; k <= 20; k++) {
    await scrubTo(k / 20);
    const d = await drawn();
    assert.ok(d.sumZ <= last.sumZ, `at ${k / 20}: ${d.sumZ} after ${last.sumZ}`);
    if (!mid && d.sumZ < first.sumZ && d.sumZ > end.sumZ) (mid = d), await h.shot('stock-mill-mid');
    last = d;
  }
  assert.ok(mid, 'a position part way with the stock part cut');
  const moves = Number(/of (\d+)/.exec(mid.label)[1]);
  assert.ok(Number(mid.move) > 0 && Number(mid.move) < moves, `mid-timeline: ${mid.label}`);
  assert.equal(last.move, 'final');
  assert.equal(last.sumAll, end.sumAll);
  // One stock in the scene whatever the scrubbing; scrubbing back shows the start again.
  for (const f of [0.2, 0.9, 0.4, 1, 0]) await scrubTo(f);
  const again = await drawn();
  assert.equal(again.objects, 1);
  assert.equal(again.move, '0');
  assert.equal(again.sumAll, first.sumAll);
});

test('lathe: the profile drawn follows the timeline', async () => {
  await openExample(page, 'convex-arc-turning/arc-tnrc-g42.nc');
  await runAndWait(page);
  const end = await drawn();
  assert.equal(end.move, 'final');
  await scrubTo(0);
  const first = await drawn();
  assert.equal(first.move, '0');
  await scrubTo(0.6);
  const mid = await drawn();
  assert.ok(Number(mid.move) > 0, mid.label);
  await h.shot('stock-lathe-mid');
  assert.notEqual(mid.sumAll, first.sumAll, 'the profile changed from the bar');
  assert.notEqual(end.sumAll, mid.sumAll, 'the final profile is not the mid one');
});

test('without a [stock], no stock and no label', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  const d = await drawn();
  assert.equal(d.move, undefined);
  assert.equal(d.label, null);
  assert.equal(d.meshes, 0);
});
