// Path and program linked both ways in the browser: a click on a segment of the 3D path
// selects its program line; the editor cursor's line has its moves drawn in the highlight
// colour over the path.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/link.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, cursorLine, countPixels } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  assert.match(await page.textContent('#status'), /ended M30/);
});
after(() => h?.close());

const white = 'r > 245 && g > 245 && b > 245';

test("the cursor's line has its moves highlighted in the 3D view", async () => {
  // The rapid to each hole (G00 X#15 Y#16, line 42) runs once per hole: six moves.
  const line = await page.evaluate(() => {
    const ed = document.getElementById('editor').editor;
    const doc = ed.view.state.doc;
    for (let n = 1; n <= doc.lines; n++) if (/^\s*G00 X#15 Y#16/.test(doc.line(n).text)) return n;
    return 0;
  });
  assert.equal(line, 42);
  const before = await countPixels(page, white);
  await page.evaluate(() => document.getElementById('editor').editor.selectLine(1));
  await page.click('#editor .cm-content');
  await page.evaluate((n) => document.getElementById('editor').editor.selectLine(n), line);
  assert.equal(await page.getAttribute('#view', 'data-highlight-moves'), '6');
  const after = await countPixels(page, white);
  assert.ok(after > before + 100, `highlighted pixels ${before} -> ${after}`);
  await h.shot('link-line-to-moves');
  // A line without moves: nothing highlighted.
  await page.keyboard.press('Control+Home');
  assert.equal(await page.getAttribute('#view', 'data-highlight-moves'), '0');
});

test('a click on a path segment selects its program line', async () => {
  // The midpoint of each feed move's first segment on screen; click one far from the others.
  const target = await page.evaluate(() => {
    const link = document.getElementById('view').link;
    const proj = link.project();
    for (let i = link.moveCount - 1; i >= 0; i--) {
      const p = link.points(i);
      const a = proj(p[0]), b = proj(p[p.length - 1]);
      if (!a || !b || Math.hypot(b[0] - a[0], b[1] - a[1]) < 40) continue;
      const x = (a[0] + b[0]) / 2, y = (a[1] + b[1]) / 2;
      if (link.moveAt(x, y) === i) return { i, x, y, line: link.index.lineOf[i] };
    }
    return null;
  });
  assert.ok(target, 'no move of the path is alone under a point of the screen');
  await page.mouse.click(target.x, target.y);
  assert.equal(await page.getAttribute('#view', 'data-picked-move'), String(target.i));
  assert.equal(await cursorLine(page), target.line);
  const selected = await page.evaluate(() => {
    const v = document.getElementById('editor').editor.view;
    return v.state.sliceDoc(v.state.selection.main.from, v.state.selection.main.to);
  });
  assert.ok(selected.length > 0, 'the picked line is selected');
  // And the picked line's moves are the highlighted ones.
  assert.ok(Number(await page.getAttribute('#view', 'data-highlight-moves')) >= 1);
  await h.shot('link-pick');
  // A click on empty space picks nothing.
  await page.mouse.click(5 + (await page.locator('#view').boundingBox()).x, 60 + (await page.locator('#view').boundingBox()).y);
  assert.equal(await page.getAttribute('#view', 'data-picked-move'), '-1');
});
