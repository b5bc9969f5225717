// The 3D view: Fit frames the whole path in a view taller than wide, and a run frees the
// GPU buffers and memory of the runs before it (issue 25: about 2.4 MB were lost a run, the
// geometries never disposed).
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/view.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait } from './harness.mjs';

let h, page;
before(async () => {
  h = await start({ width: 1400, height: 820 });
  page = h.page;
});
after(() => h?.close());

// The box (canvas pixels) of the toolpath's bright colours (feed blue, rapid orange: the
// whole path is done after a run), and the canvas size.
const pathBox = () =>
  page.evaluate(() => {
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    const box = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity, n: 0, w: c.width, h: c.height };
    for (let y = 0; y < c.height; y++)
      for (let x = 0; x < c.width; x++) {
        const i = (y * c.width + x) * 4, r = d[i], g = d[i + 1], b = d[i + 2];
        const feed = r < 0x80 && g > 0xa0 && b > 0xd0, rapid = r > 0xd0 && g > 0x30 && g < 0x90 && b < 0x60;
        if (!feed && !rapid) continue;
        box.n++;
        box.x0 = Math.min(box.x0, x), box.x1 = Math.max(box.x1, x);
        box.y0 = Math.min(box.y0, y), box.y1 = Math.max(box.y1, y);
      }
    return box;
  });

test('Fit frames the whole path when the view is taller than wide', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  // A view three times as tall as wide (a narrow window, a phone held upright).
  await page.addStyleTag({ content: '#view { flex: none !important; width: 260px !important; height: 760px !important; }' });
  await page.waitForFunction(() => document.querySelector('#view canvas').clientWidth === 260);
  for (const view of ['top', 'iso']) {
    await page.click(`.views button[data-view="${view}"]`);
    await page.click('.views button[data-view="fit"]');
    const b = await pathBox();
    assert.ok(b.n > 200, `${view}: ${b.n} path pixels`);
    // Inside the canvas with a margin on every side (a clipped path touches the edges)...
    const margin = 3;
    assert.ok(b.x0 >= margin && b.x1 <= b.w - 1 - margin && b.y0 >= margin && b.y1 <= b.h - 1 - margin, `${view}: path at x ${b.x0}..${b.x1}, y ${b.y0}..${b.y1} of ${b.w}x${b.h}`);
    // ...and not a speck: it spans a good part of the narrow side.
    assert.ok(b.x1 - b.x0 > b.w * 0.4, `${view}: the path is ${b.x1 - b.x0} px wide of ${b.w}`);
  }
  await h.shot('view-fit-tall');
});

test('an orbit draws the coarse copy of the path, and the full path when it stops', async () => {
  await page.setViewportSize({ width: 1400, height: 820 });
  // 4,000 steps of 0.05 mm wobbling 0.02 mm: about a thousandth of the part's size, merged.
  await page.evaluate(() => {
    const lines = ['O0003 (COARSE)', 'G21 G90 G17 G54 G00 X0 Y0 Z5.', 'G01 Z-1. F1000.'];
    for (let i = 1; i <= 4000; i++) lines.push(`G01 X${((i % 2000) / 20).toFixed(2)} Y${(Math.floor(i / 2000) * 20 + (i % 2) * 0.02).toFixed(2)}`);
    lines.push('G00 Z5.', 'M30');
    document.getElementById('editor').editor.text = lines.join('\n');
  });
  await runAndWait(page);
  await page.waitForSelector('#view[data-coarse]');
  const coarse = Number(await page.getAttribute('#view', 'data-coarse'));
  const full = await page.evaluate(() => document.getElementById('view').link.view.vertexCount / 2);
  assert.ok(coarse > 0 && coarse < full / 10, `${coarse} coarse segments of ${full}`);
  assert.equal(await page.getAttribute('#view', 'data-detail'), 'full');
  const box = await page.locator('#view canvas').boundingBox();
  const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  await page.mouse.move(cx + 30, cy + 10);
  await page.mouse.move(cx + 60, cy + 20);
  assert.equal(await page.getAttribute('#view', 'data-detail'), 'coarse');
  assert.ok((await pathBox()).n > 500, 'the coarse path is drawn');
  await h.shot('view-orbit-coarse');
  await page.mouse.up();
  await page.waitForSelector('#view[data-detail="full"]');
  assert.ok((await pathBox()).n > 500, 'the full path is drawn');
});

test('ten runs do not keep the geometries and memory of the runs before', async () => {
  // A program of some size (20,000 moves), so that what a run leaves behind shows.
  await page.evaluate(() => {
    const lines = ['O0002 (MEMORY)', 'G21 G90 G17 G54 G00 X0 Y0 Z5.', 'G01 Z-1. F1000.'];
    for (let i = 0; i < 20000; i++) lines.push(i % 10 === 9 ? `G02 X${(i % 500) / 5} Y${(i % 7) * 3} R20.` : `G01 X${(i % 500) / 5} Y${(i % 7) * 3}`);
    lines.push('M30');
    document.getElementById('editor').editor.text = lines.join('\n');
  });
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  const measure = async () => {
    await cdp.send('HeapProfiler.collectGarbage');
    const metrics = Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((x) => [x.name, x.value]));
    const gpu = await page.evaluate(() => {
      const info = document.getElementById('view').link.view.renderer.info.memory;
      return { geometries: info.geometries, textures: info.textures };
    });
    return { heap: metrics.JSHeapUsedSize, ...gpu };
  };
  const runs = [];
  for (let k = 0; k < 10; k++) {
    await runAndWait(page);
    assert.match(await page.textContent('#status'), /ended M30/);
    runs.push(await measure());
  }
  console.log(`after runs 1, 2 and 10: ${runs.filter((_, k) => k === 0 || k === 1 || k === 9).map((r) => `heap ${(r.heap / 1048576).toFixed(1)} MB, ${r.geometries} geometries, ${r.textures} textures`).join('; ')}`);
  // The GPU objects of a run replace those of the run before: as many after the tenth run
  // as after the second (the first run also makes what the page keeps, such as the tool).
  assert.equal(runs[9].geometries, runs[1].geometries, 'geometries kept from the runs before');
  assert.equal(runs[9].textures, runs[1].textures, 'textures kept from the runs before');
  // The JS heap: a run's leftovers would add up over eight runs; a few hundred kB of noise
  // (caches, the alarm history) are allowed.
  const growth = runs[9].heap - runs[1].heap;
  assert.ok(growth < 2 * 1048576, `the JS heap grew by ${(growth / 1048576).toFixed(1)} MB over 8 runs`);
});
