// The measuring tool: Measure on, two clicks near the path pick two segment end points
// (snapped), and the view shows the distance and dX/dY/dZ; on a lathe dX is on the diameter.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/measure.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, runAndWait, typeProgram, cursorLine, tab } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

// The screen position of a program point (work coordinates).
const screenOf = (p) => page.evaluate((q) => document.getElementById('view').link.project()(q), p);

// Clicks `dx`, `dy` pixels off the screen position of program point p.
async function clickNear(p, dx, dy) {
  const [x, y] = await screenOf(p);
  await page.mouse.click(x + dx, y + dy);
}

const panel = () => page.textContent('#measure-panel');

test('two points on a mill path: snapped to the segment ends, distance and dX dY dZ', async () => {
  await typeProgram(page, 'O0001\nG21 G90 G17\nG00 X0 Y0 Z5.\nG01 Z-1. F100.\nX50.\nY30.\nG00 Z20.\nM30\n');
  await runAndWait(page);
  const line = await cursorLine(page);
  await page.click('#measure');
  assert.equal(await page.getAttribute('#view', 'data-measuring'), 'true');
  assert.match(await panel(), /pick a point/);
  // Off the path: nothing picked.
  const box = await page.locator('#view canvas').boundingBox();
  await page.mouse.click(box.x + box.width - 30, box.y + box.height - 30);
  assert.equal(await page.getAttribute('#view', 'data-measure-snap'), '-1');
  // A few pixels beside the end points of G01 Z-1. and Y30.
  await clickNear([0, 0, -1], 4, -3);
  assert.match(await panel(), /pick the second point/);
  await clickNear([50, 30, -1], -3, 4);
  const text = await panel();
  assert.match(text, /58\.310 mm/);
  assert.match(text, /dX 50\.000 dY 30\.000 dZ 0\.000/);
  assert.match(text, /A X0\.000 Y0\.000 Z-1\.000 · B X50\.000 Y30\.000 Z-1\.000/);
  // While measuring a click does not select a program line.
  assert.equal(await cursorLine(page), line);
  await h.shot('measure-mill');
  // A third click starts again; the end of the rapid up, then the start of the path.
  await clickNear([50, 30, 20], 2, 2);
  assert.match(await panel(), /pick the second point/);
  await clickNear([50, 30, -1], 0, 0);
  assert.match(await panel(), /^21\.000 mm.*dX 0\.000 dY 0\.000 dZ -21\.000/);
  await page.keyboard.press('Escape');
  assert.equal(await page.isHidden('#measure-panel'), true);
  assert.equal(await page.getAttribute('#view', 'data-measuring'), 'false');
});

test('on a lathe: dX on the diameter, the distance in the half-section', async () => {
  await tab(page, 'setup');
  await page.fill('#setup-text', '[machine]\nkind = "lathe"\n');
  await tab(page, 'editor');
  await typeProgram(page, 'O0002\nG21 G18 G99\nG00 X40. Z2.\nG01 Z-20. F0.2\nX60.\nG00 Z2.\nM30\n');
  await runAndWait(page);
  await page.click('#measure');
  await clickNear([40, 0, 2], 3, 0);
  await clickNear([60, 0, -20], 0, -3);
  const text = await panel();
  // Radius 20 -> 30 (10) and Z 2 -> -20 (22): sqrt(10^2 + 22^2).
  assert.match(text, /^24\.166 mm \(dX on the diameter\)/);
  assert.match(text, /dX 20\.000 dZ -22\.000/);
  await h.shot('measure-lathe');
  await page.click('#measure');
  assert.equal(await page.isHidden('#measure-panel'), true);
});
