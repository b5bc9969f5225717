// Colour by move kind, feed rate, depth or tool: the selector over the 3D view rewrites the
// path's vertex colours once per change (not per frame or scrub), and the legend says what
// the colours mean.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/colour.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, countPixels } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
  // Feeds 300 to 1000, tools T1 (the end mill) and T20 (the probe), depths Z50 to Z-12.
  await openExample(page, 'probe-milled-bore/bore-o5001.nc');
  await runAndWait(page);
});
after(() => h?.close());

// The path's colour attribute: its version (bumped by each upload) and, for each move, the
// colour of its first vertex and the move's feed, kind, lowest and highest vertex.
const pathState = () =>
  page.evaluate(() => {
    const host = document.getElementById('view');
    const view = host.link.view, m = host.link.model;
    const attr = view.pathColourAttribute();
    const c = attr.array, v = m.vertices, w = attr.itemSize; // RGBA
    const moves = [];
    for (let mv = 0; mv < m.moves; mv++) {
      const k = m.vFirst[mv];
      moves.push({ rgb: [c[k * w], c[k * w + 1], c[k * w + 2]], feed: m.feed[mv], rapid: m.kind[m.mEvent[mv]] === 0, z: v[k * 3 + 2] });
    }
    let lo = 0, hi = 0;
    for (let k = 0; k < v.length / 3; k++) {
      if (v[k * 3 + 2] < v[lo * 3 + 2]) lo = k;
      if (v[k * 3 + 2] > v[hi * 3 + 2]) hi = k;
    }
    const at = (k) => [c[k * w], c[k * w + 1], c[k * w + 2]];
    return { version: attr.version, moves, lowest: at(lo), highest: at(hi), mode: host.dataset.colourBy };
  });
const legend = () => page.textContent('.legend .legend-items');
const BLUE = [0x30, 0x50, 0xff], RED = [0xff, 0x33, 0x22], GREY = [0x8a, 0x90, 0x99];

async function colourBy(mode) {
  await page.selectOption('#colour-by', mode);
  await page.waitForFunction((m) => document.getElementById('view').dataset.colourBy === m, mode);
}

test('by move kind (the default): rapids red, feeds blue, as the legend says', async () => {
  const s = await pathState();
  assert.equal(s.mode, 'kind');
  for (const mv of s.moves) assert.deepEqual(mv.rgb, mv.rapid ? [0xff, 0x55, 0x33] : [0x33, 0xcc, 0xff]);
  assert.match(await legend(), /rapid.*feed.*compensated.*thread/);
});

test('by feed rate: lowest F blue, highest red, rapids grey; one upload, none while scrubbing', async () => {
  const before = (await pathState()).version;
  await colourBy('feed');
  const s = await pathState();
  assert.equal(s.version, before + 1, 'the colours were uploaded once');
  const feeds = s.moves.filter((m) => !m.rapid).map((m) => m.feed);
  const lo = Math.min(...feeds), hi = Math.max(...feeds);
  assert.ok(hi > lo, 'the example has several feeds');
  for (const mv of s.moves) {
    if (mv.rapid) assert.deepEqual(mv.rgb, GREY);
    else if (mv.feed === lo) assert.deepEqual(mv.rgb, BLUE);
    else if (mv.feed === hi) assert.deepEqual(mv.rgb, RED);
    else assert.notDeepEqual(mv.rgb, BLUE);
  }
  assert.match(await legend(), new RegExp(`F ${lo} … ${hi}.*rapid`));
  // Scrubbing and stepping move the draw ranges only.
  for (const v of [0, 50, 200, 120]) {
    await page.$eval('#scrub', (el, x) => {
      el.value = String(Math.round((Number(el.max) * x) / 200));
      el.dispatchEvent(new Event('input'));
    }, v);
  }
  await page.click('#fwd');
  assert.equal((await pathState()).version, before + 1, 'no upload while scrubbing');
  await h.shot('colour-feed');
});

test('by depth: the lowest vertex blue, the highest red; by tool: one colour per tool', async () => {
  await colourBy('depth');
  let s = await pathState();
  assert.deepEqual(s.lowest, BLUE);
  assert.deepEqual(s.highest, RED);
  assert.match(await legend(), /Z -12 … 120/);
  await page.click('.views button[data-view="top"]');
  // The deepest part of the path (the bore's floor) in the ramp's blue on the screen.
  const blueish = await countPixels(page, 'b > 180 && r < 150 && g < 175');
  assert.ok(blueish > 20, `${blueish} deep-blue pixels on the screen`);
  await h.shot('colour-depth');

  await colourBy('tool');
  s = await pathState();
  assert.match(await legend(), /T1.*T20/);
  // The moves before the probe's M06 (line 17) are T1's, the others T20's: two colours.
  const colours = new Set(s.moves.map((m) => m.rgb.join(',')));
  assert.equal(colours.size, 2, [...colours].join(' '));
  assert.notDeepEqual(s.moves[0].rgb, s.moves.at(-1).rgb);
  await h.shot('colour-tool');
});

test('the mode is kept over a reload and applies to the next run', async () => {
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.inputValue('#colour-by'), 'tool');
  await openExample(page, 'probe-milled-bore/bore-o5001.nc');
  await runAndWait(page);
  const s = await pathState();
  assert.equal(new Set(s.moves.map((m) => m.rgb.join(','))).size, 2);
  await colourBy('kind');
  const k = await pathState();
  for (const mv of k.moves) assert.deepEqual(mv.rgb, mv.rapid ? [0xff, 0x55, 0x33] : [0x33, 0xcc, 0xff]);
});
