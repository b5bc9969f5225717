// The front end's pure parts, without a browser: Fanuc highlighting, and the timeline model
// (arcs drawn round, the tool part-way through a move, state folded from the steps).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { tokenize } from '../src/highlight.js';
import { buildModel, toolAt, timeBreakdown, timeByTool } from '../src/model.js';

const kinds = (line) => tokenize(line).filter((t) => t.cls !== 'ws').map((t) => `${t.cls}:${t.text}`);

test('Fanuc tokens', () => {
  assert.deepEqual(kinds('N10 G01 X-1.5 F100. (CUT)'), ['seq:N10', 'g:G01', 'addr:X-1.5', 'addr:F100.', 'comment:(CUT)']);
  assert.deepEqual(kinds('IF[#1GT0]GOTO20'), ['kw:IF', 'op:[', 'var:#1', 'kw:GT', 'num:0', 'op:]', 'kw:GOTO', 'num:20']);
  assert.deepEqual(kinds('/2 M98 P1000'), ['skip:/2', 'm:M98', 'addr:P1000']);
  assert.deepEqual(kinds('O0100'), ['prog:O0100']);
  assert.deepEqual(kinds('#[#1+1]=SIN[30]'), ['var:#', 'op:[', 'var:#1', 'op:+', 'num:1', 'op:]', 'op:=', 'kw:SIN', 'op:[', 'num:30', 'op:]']);
  // Every character is covered, so the overlay lines up with the textarea.
  const line = 'G02X10.Y10.R5.;rest';
  assert.equal(tokenize(line).map((t) => t.text).join(''), line);
});

const move = (o) => JSON.stringify({ type: 'move', file: 'p.nc', prog: 'O1', n: null, feed: 100, length: 1, time: 1, ...o });

test('timeline model', () => {
  const answer = {
    machine: { kind: 'mill', axes: 3 },
    trace: [
      move({ line: 2, mode: 'linear', start: [0, 0, 0], end: [10, 0, 0], mstart: [5, 0, 0], mend: [15, 0, 0] }),
      // Half a circle CCW about (10, 5): through (15, 5).
      move({ line: 3, mode: 'ccw', start: [10, 0, 0], end: [10, 10, 0], mstart: [15, 0, 0], mend: [15, 10, 0], center: [10, 5, 0], plane: 17 }),
      JSON.stringify({ type: 'dwell', file: 'p.nc', line: 4, n: null, prog: 'O1', time: 2 }),
    ].join('\n') + '\n',
    steps: [{ b: 2, t: 1, l: { '#1': 5 } }, { b: 3, t: 2, l: { '#1': 6 }, c: { '#100': 1 } }, { b: 4, t: 4, l: { '#1': null } }],
    state: {},
  };
  const m = buildModel(answer);
  assert.equal(m.events.length, 3);
  assert.equal(m.blocks.length, 3);
  assert.deepEqual(m.states[1].locals, { '#1': 6 });
  assert.deepEqual(m.states[1].common, { '#100': 1 });
  assert.deepEqual(m.states[2].locals, {});
  assert.ok(m.states[1].changed.has('#1'));
  // The arc bulges to X15 (CCW from the bottom), not to X5.
  const xs = m.moves[1].pts.map((p) => p[0]);
  assert.ok(Math.abs(Math.max(...xs) - 15) < 1e-9 && Math.min(...xs) > 10 - 1e-9);
  // Half-way through the first move: X5, 5 to go, machine = work + the move's offset (5).
  const t = toolAt(m, 0.5);
  assert.deepEqual(t.work.map((v) => +v.toFixed(6)), [5, 0, 0]);
  assert.deepEqual(t.togo.map((v) => +v.toFixed(6)), [5, 0, 0]);
  assert.deepEqual(t.machine.map((v) => +v.toFixed(6)), [10, 0, 0]);
  // Half-way through the arc: at its far point (15, 5).
  const a = toolAt(m, 1.5);
  assert.ok(Math.abs(a.work[0] - 15) < 0.01 && Math.abs(a.work[1] - 5) < 0.01, `${a.work}`);
  assert.deepEqual(timeBreakdown(m), { rapid: 0, feed: 2, thread: 0, dwell: 2 });
  assert.deepEqual(timeByTool(m), { T0: 4 });
  const withTool = buildModel({
    ...answer,
    trace: JSON.stringify({ type: 'tool', file: 'p.nc', line: 1, n: null, prog: 'O1', tool: 5, change: true }) + '\n' + answer.trace,
    steps: [{}, ...answer.steps],
  });
  assert.deepEqual(timeByTool(withTool), { T5: 4 });
});

test('a lathe arc is round in radius, X given as a diameter', () => {
  const answer = {
    machine: { kind: 'lathe', axes: 3 },
    // X100 Z0 to X200 Z-50 with the centre at X100 Z-50 (radius 50): a quarter circle, G18.
    trace: move({ line: 2, mode: 'ccw', start: [100, 0, 0], end: [200, 0, -50], mstart: [100, 0, 0], mend: [200, 0, -50], center: [100, 0, -50], plane: 18 }) + '\n',
    steps: [{}],
    state: {},
  };
  const m = buildModel(answer);
  for (const p of m.moves[0].pts) {
    const r = Math.hypot(p[0] / 2 - 50, p[2] + 50);
    assert.ok(Math.abs(r - 50) < 1e-6, `radius ${r} at ${p}`);
  }
});
