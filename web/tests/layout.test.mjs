// The page at 1280x720 (a laptop): tabs on one row, a usable slider, the whole status line;
// the axes in colours of their own; the light theme; and no false "O... is also in ..."
// warning for an example (the editor text and its file are one program).
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/layout.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, tab, countPixels } from './harness.mjs';

let h, page;
before(async () => {
  h = await start({ width: 1280, height: 720 });
  page = h.page;
});
after(() => h?.close());

test('at 1280x720 the tabs are one row each, the slider is wide and the status line whole', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  const bars = await page.evaluate(() =>
    [...document.querySelectorAll('.tabs')].map((bar) => {
      const b = [...bar.querySelectorAll('button')].filter((x) => x.offsetParent);
      const r = bar.getBoundingClientRect();
      return {
        rows: new Set(b.map((x) => x.offsetTop)).size,
        inside: b.every((x) => x.getBoundingClientRect().right <= r.right + 0.5),
      };
    }),
  );
  for (const bar of bars) assert.deepEqual(bar, { rows: 1, inside: true });
  const slider = (await page.locator('#scrub').boundingBox()).width;
  assert.ok(slider >= 300, `the slider is ${slider} px wide`);
  // A long status (an alarm in a program with a CAM system's long name): all of it on the screen.
  const name = 'op20-finish-contour-of-the-left-hand-bracket-from-the-cam-system-revision-c.nc';
  await page.setInputFiles('#file-input', { name, mimeType: 'text/plain', buffer: Buffer.from('O0001\nG90 G00 X10. Y10.\n#1=0\n#2=1\n#3=2\nG01 X[#2/#1] F100.\nM30\n') });
  await page.waitForFunction((n) => document.getElementById('status').textContent.startsWith(n), name);
  await runAndWait(page);
  const status = await page.evaluate(() => {
    const s = document.getElementById('status');
    const r = s.getBoundingClientRect();
    return { text: s.textContent, cut: s.scrollWidth > s.clientWidth + 1 || r.right > innerWidth || r.bottom > innerHeight };
  });
  assert.match(status.text, /PS0112 .*revision-c\.nc:6\)$/);
  assert.equal(status.cut, false, status.text);
  assert.ok((await page.locator('#stepinfo').boundingBox()).width > 400);
  await h.shot('layout-1280x720');
});

// Hue in degrees and saturation of a three.js colour (r, g, b in 0..1).
function hueSat({ r, g, b }) {
  const max = Math.max(r, g, b), min = Math.min(r, g, b), d = max - min;
  if (d === 0) return { h: 0, s: 0 };
  const h = max === r ? ((g - b) / d) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
  return { h: (h * 60 + 360) % 360, s: max === 0 ? 0 : d / max };
}

test('the axes do not share a colour with any kind of move', async () => {
  const colours = await page.evaluate(() => {
    const view = document.getElementById('view').link.view;
    const axes = [], paths = [];
    // The toolpath is in the view's scene, or in the scene of its path layer (path_layer.js).
    for (const scene of [view.scene, view.layer?.scene].filter(Boolean)) scene.traverse((o) => {
      if (!o.isLine || o.type === 'GridHelper') return;
      let inAxes = false;
      for (let p = o; p; p = p.parent) inAxes ||= p.name === 'axes' || p.isAxesHelper;
      const c = o.material.color;
      const list = inAxes ? axes : paths;
      if (o.geometry.getAttribute('color') && o.material.vertexColors) {
        const a = o.geometry.getAttribute('color');
        for (let i = 0; i < a.count; i++) list.push({ r: a.getX(i), g: a.getY(i), b: a.getZ(i) });
      } else {
        const hex = c.getHex(); // sRGB, as on the screen
        list.push({ r: (hex >> 16) / 255, g: ((hex >> 8) & 255) / 255, b: (hex & 255) / 255 });
      }
    });
    return { axes, paths };
  });
  assert.ok(colours.axes.length > 0, 'no axes in the scene');
  const kinds = colours.paths.map(hueSat).filter((c) => c.s > 0.4);
  assert.ok(kinds.length > 0, 'the path colours were not found');
  for (const a of colours.axes.map(hueSat)) {
    if (a.s < 0.15) continue; // a neutral grey is no kind of move
    for (const k of kinds) {
      const dh = Math.min(Math.abs(a.h - k.h), 360 - Math.abs(a.h - k.h));
      assert.ok(dh > 40, `an axis of hue ${a.h.toFixed(0)} looks like a move of hue ${k.h.toFixed(0)}`);
    }
  }
});

test('the light theme: page, editor and 3D view light, kept over a reload', async () => {
  const lum = (sel) =>
    page.evaluate((s) => {
      const m = /(\d+), (\d+), (\d+)/.exec(getComputedStyle(document.querySelector(s)).backgroundColor);
      return 0.2126 * m[1] + 0.7152 * m[2] + 0.0722 * m[3];
    }, sel);
  assert.ok((await lum('body')) < 60);
  await page.click('#theme');
  assert.equal(await page.getAttribute('html', 'data-theme'), 'light');
  assert.ok((await lum('body')) > 200);
  assert.ok((await lum('#editor .cm-editor')) > 200);
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  const light = await countPixels(page, 'r > 230 && g > 230 && b > 230');
  const total = await page.evaluate(() => document.querySelector('#view canvas').width * document.querySelector('#view canvas').height);
  assert.ok(light > total / 2, `${light} of ${total} pixels of the 3D view are light`);
  await h.shot('theme-light');
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.getAttribute('html', 'data-theme'), 'light');
  await page.click('#theme');
  assert.equal(await page.getAttribute('html', 'data-theme'), 'dark');
});

test('an example has no "is also in" warning: the editor text is its file', async () => {
  for (const file of ['face-milling-g42/face-milling-g42-x150.nc', 'convex-arc-turning/arc-no-tnrc.nc']) {
    await openExample(page, file);
    await runAndWait(page);
    await tab(page, 'p-messages');
    assert.doesNotMatch(await page.textContent('#p-messages'), /is also in/, file);
  }
});
