// The path drawn fixed on the machine when a program moves work zero: probe-milled-bore's
// O5001 writes the measured bore centre into G54, and the moves after it must be drawn where
// the tool went, not 14.6 mm off (the position page keeps the control's work coordinates).
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/machine_frame.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, typeProgram, tab } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

// Each move's drawn end (link.points: the highlight and the picking), its last vertex in the
// path's buffer (scene coordinates), its work end and its machine end; the tool as drawn.
const moves = () =>
  page.evaluate(() => {
    const link = document.getElementById('view').link, m = link.model, A = m.axes;
    const out = [];
    for (let i = 0; i < m.moves; i++) {
      const last = (i + 1 < m.moves ? m.vFirst[i + 1] : m.vertices.length / 3) - 1;
      out.push({
        drawn: link.points(i).at(-1),
        vertex: Array.from(m.vertices.subarray(last * 3, last * 3 + 3)),
        end: Array.from(m.end.subarray(i * A, i * A + A)),
        mend: Array.from(m.mend.subarray(i * A, i * A + A)),
        line: m.line[m.mEvent[i]],
      });
    }
    const t = link.view.tool.position;
    return { moves: out, tool: [t.x, t.y, t.z] };
  });
const near = (a, b, what) => a.forEach((v, k) => assert.ok(Math.abs(v - b[k]) < 1e-3, `${what}: ${a} is not ${b}`));

test('probe-milled-bore: the moves after O5001 rewrites G54 are drawn where the tool went', async () => {
  await openExample(page, 'probe-milled-bore/bore-o5001.nc');
  await runAndWait(page);
  const { moves: mv, tool } = await moves();
  // Fixed on the machine: drawn X and Y are the machine's, less the first G54 (X100 Y50), for
  // every move; the tool lengths (H1, H20) are only in Z.
  for (const m of mv) {
    near([m.drawn[0] - m.mend[0], m.drawn[1] - m.mend[1]], [-100, -50], `move of line ${m.line}`);
    near(m.vertex, m.drawn, 'the buffer');
  }
  // The last move ends at X0 Y0 Z50 of the new G54, the bore centre X12.35 Y-7.9 of the old.
  const last = mv.at(-1);
  near(last.end, [0, 0, 50], 'work end');
  near(last.drawn, [12.35, -7.9, 50], 'drawn end');
  near(tool, [12.35, -7.9, 50], 'the tool');
  // The position page still shows the control's work coordinates.
  await tab(page, 'p-position');
  const absolute = await page.$$eval('#p-position tr', (rows) => rows.find((r) => /Absolute/.test(r.textContent)).textContent);
  assert.match(absolute, /Absolute\s*0\.000\s*0\.000\s*50\.000/);
  await page.click('.views button[data-view="top"]');
  await h.shot('machine-frame-probe');
});

test('a G10 between cuts: later moves shifted by the change, on a mill and on a lathe', async () => {
  // A new program (not an edit of the example, which would run with the example's setup).
  await page.selectOption('#files', '');
  await tab(page, 'setup');
  await page.fill('#setup-text', '');
  await tab(page, 'editor');
  await typeProgram(page, 'O0001\nG21 G90 G17 G54\nG00 X0 Y0 Z5.\nG01 Z-1. F100.\nX10.\nG10 L2 P1 X20.\nG01 X10. Y5.\nM30\n');
  await runAndWait(page);
  let mv = (await moves()).moves;
  near(mv[2].drawn, [10, 0, -1], 'before G10');
  // G54 X0 -> X20: X10 of the new G54 is X30 of the old.
  near(mv[3].drawn, [30, 5, -1], 'after G10');
  near(mv[3].end, [10, 5, -1], 'work end');

  await tab(page, 'setup');
  await page.fill('#setup-text', '[machine]\nkind = "lathe"\n');
  await tab(page, 'editor');
  await typeProgram(page, 'O0002\nG21 G18 G99\nG00 X40. Z2.\nG01 Z-10. F0.2\nG10 L2 P1 X4. Z-5.\nG01 X40. Z-10.\nX50.\nM30\n');
  await runAndWait(page);
  mv = (await moves()).moves;
  // X4. (a diameter) and Z-5.: X40. Z-10. of the new system is X44. Z-15. of the old; in the
  // half-section that is Z-15 to the right, the radius 22 up.
  near(mv[2].drawn, [44, 0, -15], 'lathe after G10');
  near(mv[2].vertex, [-15, 0, 22], 'lathe buffer');
  near(mv[3].drawn, [54, 0, -15], 'lathe X50.');
});
