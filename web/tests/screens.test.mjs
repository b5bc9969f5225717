// The control-like screens and the playback in the browser: the position page (units, actual
// feed and speed), the offset pages with the control's names, the variable search, the alarm
// history, run time and parts count; play/pause with a speed, steps by move and tool change.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/screens.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, tab, typeProgram } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

const scrubTo = (p) =>
  page.evaluate((v) => {
    const s = document.getElementById('scrub');
    s.value = v;
    s.dispatchEvent(new Event('input'));
  }, p);
const text = (sel) => page.textContent(sel);

test('the position page: units, actual feed (moving only) and spindle speed', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  await tab(page, 'p-position');
  assert.equal(await text('#pos-units'), 'mm');
  // Half-way through the first G01 (F#9 = 100) of the holes: the axes move at 100 mm/min,
  // the spindle turns at S1200 (M03 before it).
  // Found by stepping by move (no reach into the page's model): the end of the first G01.
  await scrubTo(0);
  await page.selectOption('#step-by', 'move');
  for (let k = 0; k < 30 && !/ move linear /.test(await text('#stepinfo')); k++) await page.click('#fwd');
  await page.selectOption('#step-by', 'block');
  assert.match(await text('#stepinfo'), / move linear /);
  const end = Number(await page.inputValue('#scrub'));
  await scrubTo(end - 5);
  assert.equal(await text('#act-feed'), '100.0');
  assert.equal(await text('#act-speed'), '1200');
  assert.equal(await text('#move-mode'), 'linear');
  await h.shot('screen-position');
  // At the end of that block the axes stand still.
  await scrubTo(end);
  assert.equal(await text('#act-feed'), '0.0');
  // An inch program: the page says so and shows four decimals.
  await typeProgram(page, 'O0001\nG20 G90 G00 X1. Y1.\nG01 X2. F10.\nM30\n');
  await runAndWait(page);
  assert.equal(await text('#pos-units'), 'inch');
  assert.equal(await text('#p-position td[data-axis="X"]'), '2.0000');
});

test('the offset pages use the control names: a lathe has X, Z, R and T, and no Y without a Y axis', async () => {
  await openExample(page, 'convex-arc-turning/arc-tnrc-g42.nc');
  await runAndWait(page);
  await tab(page, 'p-offsets');
  const head = await page.locator('#p-offsets table.tool-geometry th').allTextContents();
  assert.deepEqual(head.slice(0, 5), ['No.', 'X', 'Z', 'R', 'T']);
  const row = await page.locator('#p-offsets table.tool-geometry tbody tr').first().locator('td').allTextContents();
  assert.deepEqual(row, ['0.000', '0.000', '0.800', '3']);
  assert.ok(await page.locator('#p-offsets table.tool-wear').count());
  assert.match(await text('#p-offsets table.work-offsets'), /00 \(EXT\)/);
  await h.shot('screen-offsets-lathe');
});

test('the variables can be searched', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  await tab(page, 'p-vars');
  await page.fill('#var-search', '#4119');
  assert.deepEqual(await page.locator('#vars-system tr[data-var]').evaluateAll((r) => r.map((x) => x.dataset.var)), ['#4119']);
  await page.fill('#var-search', '#5001-#5003');
  assert.deepEqual(await page.locator('#vars-system tr[data-var]').evaluateAll((r) => r.map((x) => x.dataset.var)), ['#5001', '#5002', '#5003']);
  // The search stays while the timeline moves.
  await page.click('#back');
  assert.equal(await page.inputValue('#var-search'), '#5001-#5003');
  assert.equal(await page.locator('#vars-system tr[data-var]').count(), 3);
  await h.shot('screen-variables');
  await page.fill('#var-search', '');
});

test('alarm history, run time and the parts count over several runs', async () => {
  await typeProgram(page, 'O0001\nG00 X1.\n#1=0\n#2=1/#1\nM30\n');
  await runAndWait(page);
  await runAndWait(page);
  await tab(page, 'p-messages');
  const alarms = await page.locator('#p-messages table.alarm-history tbody tr').allTextContents();
  assert.equal(alarms.length, 2);
  for (const a of alarms) assert.match(a, /PS0112[\s\S]*ZERO DIVIDE[\s\S]*:4/);
  await h.shot('screen-alarm-history');
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  await tab(page, 'p-time');
  assert.equal(await text('#parts-run'), '1'); // M30 counts a part (#3901)
  const total = Number(await text('#parts-total'));
  assert.ok(total >= 2, `${total} parts`); // the two bolt circles run before
  await runAndWait(page);
  assert.equal(Number(await text('#parts-total')), total + 1);
  assert.match(await text('#run-counters'), /Run time, all \d+ runs/);
  await h.shot('screen-time');
});

test('playback: play and pause at a speed, and steps by move and by tool change', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc'); // 25.8 s of modelled time
  await runAndWait(page);
  await scrubTo(0);
  await page.selectOption('#speed', '5');
  await page.click('#play');
  assert.equal(await page.getAttribute('#timeline', 'data-playing'), 'true');
  await page.waitForFunction(() => Number(document.getElementById('scrub').value) > 0);
  await page.click('#play');
  assert.equal(await page.getAttribute('#timeline', 'data-playing'), 'false');
  const paused = await page.inputValue('#scrub');
  await page.waitForTimeout(300);
  assert.equal(await page.inputValue('#scrub'), paused);
  // At 100x it plays to its end in a quarter of a second, and stops there.
  await page.selectOption('#speed', '100');
  await page.click('#play');
  await page.waitForFunction(() => document.getElementById('timeline').dataset.playing === 'false');
  assert.equal(await page.inputValue('#scrub'), await page.getAttribute('#scrub', 'max'));
  await openExample(page, 'face-milling-g42/face-milling-g42-x150.nc');
  await runAndWait(page);
  // Steps by move land on moves; by tool on the tool change (T1 M6, line 8).
  await scrubTo(0);
  await page.selectOption('#step-by', 'move');
  assert.match(await text('#fwd'), /Move/);
  for (let k = 0; k < 3; k++) {
    await page.click('#fwd');
    assert.match(await text('#stepinfo'), / move /);
  }
  await scrubTo(0);
  await page.selectOption('#step-by', 'tool');
  await page.click('#fwd');
  assert.match(await text('#stepinfo'), /x150\.nc:8 .* tool/);
  await page.click('#back');
  assert.match(await text('#stepinfo'), /^start/);
  await page.selectOption('#step-by', 'block');
  await h.shot('screen-playback');
});
