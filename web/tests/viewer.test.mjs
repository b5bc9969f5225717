// Browser tests of `ncvm serve`: Playwright (playwright-core) driving Debian's Chromium,
// headless. Each main screen is saved as a PNG under $NCVM_ARTIFACTS (build/web-artifacts).
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start } from './harness.mjs';

// The server and a fresh browser profile, as every browser test starts them (harness.mjs).
let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

const shot = (name) => h.shot(name);
const tab = (name) => page.click(`.tabs button[data-tab="${name}"]`);

async function openExample(file) {
  await page.selectOption('#files', `examples|${file}`);
  await page.waitForFunction((f) => document.getElementById('status').textContent.startsWith(f), file);
}

async function runAndWait() {
  await page.click('#run');
  await page.waitForFunction(() => /ended|alarm|error/.test(document.getElementById('status').textContent));
}

// Pixels of the 3D canvas that differ from its background colour.
const litPixels = () =>
  page.evaluate(() => {
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    const bg = [0x15, 0x18, 0x1d];
    let n = 0;
    for (let i = 0; i < d.length; i += 4)
      if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 60) n++;
    return { n, total: d.length / 4 };
  });

test('an example loads, runs, and the 3D view draws its toolpath', async () => {
  await openExample('macro-basics/bolt-circle.nc');
  assert.match(await page.textContent('#editor .cm-content'), /O0100/);
  // Fanuc highlighting: G codes and macro keywords are tokens of their own.
  assert.ok((await page.locator('#editor .t-g').count()) > 5);
  assert.ok((await page.locator('#editor .t-kw').count()) > 5);
  await runAndWait();
  assert.match(await page.textContent('#status'), /ended M30/);
  const px = await litPixels();
  assert.ok(px.n > 500, `the 3D view is blank (${px.n} lit pixels of ${px.total})`);
  assert.match(await page.textContent('#p-position'), /Distance to go/);
  await tab('p-time');
  assert.match(await page.textContent('#cycle-time'), /^\d+\.\d\d s$/);
  await shot('time');
  await tab('p-position');
  await shot('run');
});

test('single-block stepping highlights the block and updates the variables', async () => {
  await tab('p-vars');
  await page.fill('#scrub', '0');
  await page.dispatchEvent('#scrub', 'input');
  const seen = [];
  let previous = null, changes = 0;
  for (let k = 0; k < 12; k++) {
    await page.click('#fwd');
    const info = await page.textContent('#stepinfo');
    const line = Number(/:(\d+)/.exec(info)[1]);
    const current = await page.getAttribute('#editor .cm-current-block', 'data-line');
    assert.equal(Number(current), line, `the highlighted line is not the block of "${info}"`);
    const vars = await page.textContent('#vars-local');
    if (previous !== null && vars !== previous) changes++;
    previous = vars;
    seen.push(line);
  }
  assert.ok(new Set(seen).size > 3, `stepping stayed on lines ${seen}`);
  assert.ok(changes >= 2, 'the local variables never changed while stepping through the holes');
  // Step to the rapid of the next hole (line 42, G00 X#15 Y#16): #14-#16 are new there
  // and shown as changed.
  for (let k = 0; k < 12 && !/:42 /.test(await page.textContent('#stepinfo')); k++) await page.click('#fwd');
  assert.match(await page.textContent('#stepinfo'), /:42 /);
  for (const v of ['#14', '#15', '#16'])
    assert.equal(await page.getAttribute(`#vars-local tr[data-var="${v}"]`, 'class'), 'changed', v);
  await shot('step');
  const before = await page.textContent('#stepinfo');
  await page.click('#back');
  assert.notEqual(await page.textContent('#stepinfo'), before);
});

test('an alarm is marked on its line', async () => {
  await page.selectOption('#files', '');
  await tab('editor');
  await page.click('#editor .cm-content');
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText('O0001 (ALARM TEST)\nG90 G00 X10. Y10.\n#1=0\nG01 X[20/#1] F100.\nM30\n');
  await runAndWait();
  assert.match(await page.textContent('#status'), /PS0112/);
  const marked = await page.evaluate(() => document.getElementById('editor').editor.marks().map((m) => `${m.line} ${m.kind}`));
  assert.deepEqual(marked, ['4 alarm']);
  assert.ok(await page.locator('#editor .cm-lintRange-error').count());
  await tab('p-messages');
  assert.match(await page.textContent('#p-messages'), /PS0112/);
  await shot('alarm');
});

test('a lathe program is shown as a half-section', async () => {
  await openExample('convex-arc-turning/arc-no-tnrc.nc');
  await runAndWait();
  assert.match(await page.textContent('#status'), /ended M30/);
  assert.ok((await litPixels()).n > 200);
  await tab('p-modal');
  assert.match(await page.textContent('#p-modal'), /G18/);
  await shot('lathe');
});

// The stock of the simulation: the examples' setups have a [stock], so the run answer
// carries the final stock and the view draws it.
async function stockPixels(file, form) {
  await openExample(file);
  await runAndWait();
  assert.match(await page.textContent('#status'), /ended M30/);
  assert.equal(await page.getAttribute('#view', 'data-stock'), form);
  // The stock is drawn in its own pale grey-blue (not the grid's dark grey nor the path's
  // saturated colours): count the pixels of that hue.
  return page.evaluate(() => {
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
      const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
      if (r > 60 && g > r && b > g && b - r >= 12 && b - r <= 80) n++;
    }
    return { n, total: d.length / 4 };
  });
}

test('a lathe stock is drawn as a half-section with the revolved part', async () => {
  const px = await stockPixels('convex-arc-turning/arc-tnrc-g42.nc', 'profile');
  assert.ok(px.n > 5000, `no stock on the canvas (${px.n} stock pixels of ${px.total})`);
  await tab('p-messages');
  assert.match(await page.textContent('#stock-summary'), /deviation max/);
  await shot('stock-lathe');
});

test('a mill stock is drawn from its height grid', async () => {
  const px = await stockPixels('face-milling-g42/face-milling-g42.nc', 'grid');
  assert.ok(px.n > 5000, `no stock on the canvas (${px.n} stock pixels of ${px.total})`);
  await tab('p-messages');
  assert.match(await page.textContent('#stock-summary'), /uncut area/);
  await shot('stock-mill');
});
