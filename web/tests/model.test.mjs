// The front end's pure parts, without a browser: Fanuc highlighting, and the timeline model
// built from the binary answer of a real run (`ncvm serve-worker`, the process the server
// starts): arcs drawn round, the tool part-way through a move, the state folded from the
// sparse deltas, blocks, and the draw range of each event.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/model.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { tokenize } from '../src/highlight.js';
import { coarsePath } from '../src/path_lod.js';
import { FrameReader } from '../src/wire.js';
import { ModelBuilder, toolAt, stateAt, eventAt, notesOf, verticesDone, nextBlockEnd, prevBlockEnd, timeBreakdown, timeByTool } from '../src/model.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const bin = process.env.NCVM_BIN || path.join(here, '../../build/release/bin/ncvm');

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

// The binary answer of one run, fed to the model in chunks of `chunk` bytes (as a stream).
function modelOf(program, setup, chunk = 777) {
  const req = { program, name: 'p.nc', format: 'binary' };
  if (setup) req.setup = setup;
  const r = spawnSync(bin, ['serve-worker'], { input: JSON.stringify(req), maxBuffer: 1 << 28 });
  assert.equal(r.status, 0, String(r.stderr));
  const frames = new FrameReader(), b = new ModelBuilder();
  const bytes = new Uint8Array(r.stdout.buffer, r.stdout.byteOffset, r.stdout.length);
  for (let at = 0; at < bytes.length; at += chunk) for (const f of frames.push(bytes.subarray(at, at + chunk))) b.add(f);
  assert.equal(frames.pending, 0);
  return b.model();
}

const MILL = `O0001
G21 G90 G17 G54
#1 = 5
G00 X0 Y0 Z0
G01 X10. F600.
G03 X10. Y10. I0 J5.
G04 P2000
#1 = 6
#100 = 1
T5 M06
G00 Z5.
M30
`;

test('timeline model of a run', () => {
  const m = modelOf(MILL);
  assert.equal(m.answer.ok, true, JSON.stringify(m.answer));
  assert.equal(m.answer.state.end, 'M30');
  assert.equal(m.moves, 4);
  const types = Array.from({ length: m.n }, (_, i) => eventAt(m, i).type);
  assert.deepEqual(types.filter((t) => t !== 'aux'), ['move', 'move', 'move', 'dwell', 'tool', 'tool', 'move']);
  // The arc (CCW about X10 Y5 from X10 Y0) bulges to X15, not to X5.
  const arc = types.indexOf('move') + 2;
  assert.equal(eventAt(m, arc).mode, 'ccw');
  const v0 = verticesDone(m, arc), v1 = verticesDone(m, arc + 1);
  const xs = [];
  for (let v = v0; v < v1; v++) xs.push(m.vertices[v * 3]);
  assert.ok(xs.length >= 8, `${xs.length} vertices for a half circle`);
  assert.ok(Math.abs(Math.max(...xs) - 15) < 1e-3 && Math.min(...xs) > 10 - 1e-3, `${Math.min(...xs)}..${Math.max(...xs)}`);
  // Half-way through the G01 (event arc - 1): X5, 5 to go.
  const t = toolAt(m, arc - 1 + 0.5);
  assert.deepEqual(t.work.map((v) => +v.toFixed(6)), [5, 0, 0]);
  assert.deepEqual(t.togo.map((v) => +v.toFixed(6)), [5, 0, 0]);
  // Half-way through the arc: at its far point (15, 5).
  const a = toolAt(m, arc + 0.5);
  assert.ok(Math.abs(a.work[0] - 15) < 0.01 && Math.abs(a.work[1] - 5) < 0.01, `${a.work}`);
  // Variables: #1 = 5 before the moves, 6 after the dwell; #100 set; #5041- the work position.
  const s = stateAt(m, arc);
  assert.equal(s.locals['#1'], 5);
  assert.equal(s.system['#5041'], 10);
  assert.equal(s.system['#5042'], 10);
  const dwell = types.indexOf('dwell');
  const later = stateAt(m, m.n - 1);
  assert.equal(later.locals['#1'], 6);
  assert.equal(later.common['#100'], 1);
  assert.equal(later.modal.T, 5);
  assert.equal(later.modal['1'], 0); // G00 last
  assert.equal(stateAt(m, dwell).locals['#1'], 5);
  // Blocks: stepping visits each event's block and comes back.
  let p = 0, visited = 0;
  for (let e; (e = nextBlockEnd(m, p)) !== null; p = e) visited++;
  assert.equal(p, m.n);
  assert.ok(visited >= 6);
  assert.equal(prevBlockEnd(m, p, false), m.blockLast[m.blockLast.length - 2] + 1);
  const tb = timeBreakdown(m);
  assert.ok(Math.abs(tb.dwell - 2) < 1e-9, JSON.stringify(tb));
  assert.ok(Math.abs(tb.rapid + tb.feed + tb.dwell - m.answer.state.cycle_time) < 1e-6, `${JSON.stringify(tb)} vs ${m.answer.state.cycle_time}`);
  const byTool = timeByTool(m);
  assert.ok(byTool.T5 > 0 && byTool.T0 > 2, JSON.stringify(byTool));
  assert.deepEqual(notesOf(m).map((e) => e.type).filter((t) => t !== 'aux'), ['dwell', 'tool', 'tool']);
});

test('a lathe arc is round in radius, X given as a diameter', () => {
  // X100 Z0 to X200 Z-50 about X100 Z-50 (radius 50, a quarter circle): drawn as Z right,
  // radius up.
  const m = modelOf('O0001\nG18 G21 G90 G99\nG00 X100. Z0.\nG03 X200. Z-50. K-50. F0.2 S500 M03\nM30\n', '[machine]\nkind = "lathe"\n');
  assert.equal(m.answer.ok, true, JSON.stringify(m.answer));
  assert.equal(m.lathe, true);
  const arc = Array.from({ length: m.n }, (_, i) => eventAt(m, i)).find((e) => e.mode === 'ccw').index;
  for (let v = verticesDone(m, arc); v < verticesDone(m, arc + 1); v++) {
    const z = m.vertices[v * 3], r = m.vertices[v * 3 + 2];
    assert.ok(Math.abs(Math.hypot(r - 50, z + 50) - 50) < 1e-3, `radius at z ${z} r ${r}`);
  }
});

test('a failed run ends with an end frame that says why', () => {
  const m = modelOf('O0001\nG00 X1.\nM30\n', '[machine\n');
  assert.equal(m.answer.ok, false);
  assert.match(m.answer.error, /setup error/);
});

// Segments as path_layer.js draws them: [x, y, z] pairs, a colour and an event each.
function segments(list) {
  const vertices = [], colors = [], vertexEvent = [];
  list.forEach(([a, b, col, ev]) => {
    vertices.push(...a, ...b);
    colors.push(...col, 255, ...col, 255);
    vertexEvent.push(ev, ev);
  });
  return { vertices: Float32Array.from(vertices), colors: Uint8Array.from(colors), vertexEvent: Float32Array.from(vertexEvent) };
}

test('the coarse path merges joined segments of one colour within the tolerance, no more', () => {
  const blue = [0x33, 0xcc, 0xff], red = [0xff, 0x55, 0x33];
  // 100 steps of 0.1 along X, wobbling 0.01 in Y: within 0.02 they merge, 32 steps at most.
  const wobble = Array.from({ length: 100 }, (_, i) => [[i / 10, (i % 2) / 100, 0], [(i + 1) / 10, ((i + 1) % 2) / 100, 0], blue, i]);
  const c = coarsePath(segments(wobble), 0.02);
  assert.equal(c.vertices.length / 6, 4); // 32 + 32 + 32 + 4
  assert.deepEqual(Array.from(c.vertexEvent), [0, 31, 32, 63, 64, 95, 96, 99]);
  assert.deepEqual(Array.from(c.source.subarray(0, 2)), [0, 63]); // the first start, the 32nd end
  assert.deepEqual(Array.from(c.vertices.subarray(-3)), [10, 0, 0]);
  // Within 0.005 nothing merges: the wobble is drawn as it is.
  assert.equal(coarsePath(segments(wobble), 0.005).vertices.length / 6, 100);
  // A change of colour, a gap and a corner each end a run.
  const broken = [
    [[0, 0, 0], [1, 0, 0], blue, 0],
    [[1, 0, 0], [2, 0, 0], red, 1], // another colour
    [[2.5, 0, 0], [3, 0, 0], red, 2], // not joined
    [[3, 0, 0], [4, 0, 0], red, 3],
    [[4, 0, 0], [4, 1, 0], red, 4], // a corner
  ];
  const b = coarsePath(segments(broken), 0.01);
  assert.deepEqual(Array.from(b.vertexEvent), [0, 0, 1, 1, 2, 3, 4, 4]);
  assert.deepEqual(Array.from(b.colors.subarray(0, 8)), [...blue, 255, ...blue, 255]);
  assert.equal(coarsePath(segments([]), 0.01).vertices.length, 0);
});
