// The colours of the toolpath's vertices by what the user wants to see: the kind of move (the
// default: rapid, feed, compensated, threading), the feed rate, the depth or the tool. Each
// mode gives one Uint8Array of RGBA per vertex of the model's vertex buffer (model.js), made
// once when the mode changes, and a legend that says what the colours mean.
import { COLORS, RGBA, eventAt } from './model.js';
import { FLAG, KIND } from './wire.js';

export const MODES = { kind: 'Move kind', feed: 'Feed rate', depth: 'Depth', tool: 'Tool' };

// Rapids under "feed rate": they move at the traverse rate, not at a programmed F.
export const RAPID_GREY = [0x8a, 0x90, 0x99];

// Blue (low) through cyan, green and yellow to red (high): t in 0..1.
const RAMP = [
  [0x30, 0x50, 0xff],
  [0x22, 0xcc, 0xee],
  [0x33, 0xdd, 0x55],
  [0xff, 0xdd, 0x22],
  [0xff, 0x33, 0x22],
];
export function ramp(t) {
  const x = Math.max(0, Math.min(1, Number.isFinite(t) ? t : 0)) * (RAMP.length - 1);
  const i = Math.min(Math.floor(x), RAMP.length - 2), f = x - i;
  return RAMP[i].map((c, k) => Math.round(c + (RAMP[i + 1][k] - c) * f));
}

// Distinct hues for tools, in the order the run uses them.
const TOOL_COLOURS = [
  [0x33, 0xcc, 0xff], [0xff, 0x99, 0x33], [0x66, 0xdd, 0x55], [0xee, 0x55, 0xcc],
  [0xff, 0xee, 0x44], [0x99, 0x77, 0xff], [0x33, 0xee, 0xbb], [0xff, 0x55, 0x55],
];

const hex = (c) => `#${c.map((v) => v.toString(16).padStart(2, '0')).join('')}`;

// The vertices of move mv: [first, end).
const vertexEnd = (m, mv) => (mv + 1 < m.moves ? m.vFirst[mv + 1] : m.vertices.length / 3);

const kindColour = (m, mv) => {
  const ev = m.mEvent[mv], f = m.flags[ev];
  return m.kind[ev] === KIND.rapid ? COLORS.rapid : f & FLAG.thread ? COLORS.thread : f & FLAG.compensated ? COLORS.comp : COLORS.feed;
};

// The tool in the spindle during each move: the last M06 on a mill, the last T on a lathe
// (its turret indexes with T), as timeByTool counts them; 0 before the first.
export function toolsOfMoves(m) {
  const tools = new Int32Array(m.moves);
  let tool = 0, mv = 0;
  for (let i = 0; i < m.n; i++) {
    const k = m.kind[i];
    if (k === KIND.tool) {
      const e = eventAt(m, i);
      if (e.change || m.lathe) tool = e.tool;
    } else if (k <= 3) tools[mv++] = tool;
  }
  return tools;
}

// An RGBA buffer for n vertices, opaque.
function opaque(n) {
  const out = new Uint8Array(n * RGBA);
  for (let k = 3; k < out.length; k += RGBA) out[k] = 255;
  return out;
}

// Fills the vertices of each move with colourOf(mv) (an [r, g, b]).
function perMove(m, colourOf) {
  const out = opaque(m.vertices.length / 3);
  for (let mv = 0; mv < m.moves; mv++) {
    const c = colourOf(mv);
    for (let v = m.vFirst[mv], e = vertexEnd(m, mv); v < e; v++) out.set(c, v * RGBA);
  }
  return out;
}

function range(values) {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) {
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  return lo <= hi ? [lo, hi] : null;
}

const scaled = (v, [lo, hi]) => (hi > lo ? (v - lo) / (hi - lo) : 0.5);
const fmt = (v) => (Math.abs(v) >= 100 ? v.toFixed(0) : Number(v.toFixed(3)).toString());

// {colours: Uint8Array (RGBA per vertex), legend: [{colour: '#rrggbb' or a CSS gradient, text}]}
export function pathColours(m, mode) {
  if (mode === 'feed') {
    const feeds = [];
    for (let mv = 0; mv < m.moves; mv++) if (m.kind[m.mEvent[mv]] !== KIND.rapid) feeds.push(m.feed[mv]);
    const r = range(feeds);
    const colours = perMove(m, (mv) => (m.kind[m.mEvent[mv]] === KIND.rapid ? RAPID_GREY : ramp(scaled(m.feed[mv], r))));
    const legend = r ? [{ gradient: true, text: `F ${fmt(r[0])} … ${fmt(r[1])}` }, { colour: hex(RAPID_GREY), text: 'rapid' }] : [{ colour: hex(RAPID_GREY), text: 'rapid' }];
    return { colours, legend, range: r };
  }
  if (mode === 'depth') {
    // Each vertex by its own height: a ramp down is a gradient. On a lathe the height of the
    // half-section is the radius (X/2), the depth of cut into the part.
    const v = m.vertices, n = v.length / 3;
    const zs = new Float32Array(n);
    for (let k = 0; k < n; k++) zs[k] = v[k * 3 + 2];
    const r = range(zs);
    const colours = opaque(n);
    for (let k = 0; k < n; k++) colours.set(ramp(scaled(zs[k], r)), k * RGBA);
    const axis = m.lathe ? 'X' : 'Z';
    const show = (z) => fmt(m.lathe ? z * 2 : z);
    const legend = r ? [{ gradient: true, text: `${axis} ${show(r[0])} … ${show(r[1])}` }] : [];
    return { colours, legend, range: r };
  }
  if (mode === 'tool') {
    const tools = toolsOfMoves(m);
    const order = [];
    for (const t of tools) if (!order.includes(t)) order.push(t);
    const colourOf = (t) => TOOL_COLOURS[order.indexOf(t) % TOOL_COLOURS.length];
    const colours = perMove(m, (mv) => colourOf(tools[mv]));
    return { colours, legend: order.map((t) => ({ colour: hex(colourOf(t)), text: `T${t}` })), tools: order };
  }
  const colours = perMove(m, (mv) => kindColour(m, mv));
  const legend = [
    { colour: hex(COLORS.rapid), text: 'rapid' },
    { colour: hex(COLORS.feed), text: 'feed' },
    { colour: hex(COLORS.comp), text: 'compensated' },
    { colour: hex(COLORS.thread), text: 'thread' },
  ];
  return { colours, legend };
}

export const RAMP_CSS = `linear-gradient(to right, ${RAMP.map(hex).join(', ')})`;
