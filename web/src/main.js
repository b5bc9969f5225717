// ncvm serve's page: program editor, 3D toolpath, timeline and panels, wired together.
import './style.css';
import * as api from './api.js';
import { Editor } from './editor.js';
import { View3D } from './view3d.js';
import { toolAt, stateAt, eventAt, notesOf, verticesDone, nextBlockEnd, prevBlockEnd } from './model.js';
import { RunProgress } from './progress.js';
import { Workspace } from './workspace.js';
import { PathLink } from './link.js';
import { initTheme, themeGrid } from './theme.js';
import { recordRun } from './counters.js';
import { Playback } from './playback.js';
import { ColourBy } from './colour_by.js';
import { Measure } from './measure.js';
import { drawnTool } from './machine_frame.js';
import { ToolShapes } from './tool_shape.js';
import { StockTimeline } from './stock.js';
import { SetupLayers } from './setup_layers.js';
import { renderPosition, renderVariables, renderOffsets, renderModal, renderMessages, renderTime } from './panels.js';

const $ = (id) => document.getElementById(id);
const SUB = 10; // slider positions per event: scrubbing shows a move part-way

const editor = new Editor($('editor'));
const view = new View3D($('view'));
const progress = new RunProgress($('view'));
const colourBy = new ColourBy(view, document.querySelector('.legend'));
const measure = new Measure(view, $('measure'), $('measure-panel'));
const toolShapes = new ToolShapes(view);
const stockTimeline = new StockTimeline(view, $('stock-label'));
const setupLayers = new SetupLayers($('setup-layers'));
initTheme(view, $('theme'));
const link = new PathLink(view, (line) => editor.selectLine(line));
editor.onCursorLine = (line) => link.highlightLine(line);
const ui = { model: null, p: 0, source: { kind: 'new', root: null, dir: '', name: 'program.nc' }, stale: false };

function setStatus(text, cls = '') {
  $('status').textContent = text;
  $('status').className = `status ${cls}`;
}

// Tabs: each .tabs bar switches the panes named by its buttons.
for (const bar of document.querySelectorAll('.tabs')) {
  bar.addEventListener('click', (e) => {
    const b = e.target.closest('button[data-tab]');
    if (!b) return;
    for (const x of bar.querySelectorAll('button[data-tab]')) {
      x.classList.toggle('active', x === b);
      $(x.dataset.tab).classList.toggle('active', x === b);
    }
    if (b.dataset.tab === 'editor') editor.render();
  });
}
document.querySelectorAll('.views button').forEach((b) => b.addEventListener('click', () => view.setView(b.dataset.view)));

async function loadFiles() {
  const list = await api.files();
  const sel = $('files');
  for (const r of list.roots || []) {
    const g = document.createElement('optgroup');
    g.label = r.name;
    for (const f of r.files) {
      const o = document.createElement('option');
      o.value = `${r.name}|${f.path}`;
      o.textContent = f.path;
      g.appendChild(o);
    }
    sel.appendChild(g);
  }
}

async function openFile(root, path) {
  progress.set('loading');
  const f = await api.file(root, path);
  progress.set('ready', 0);
  if (!f.ok) return setStatus(f.error, 'bad');
  editor.text = f.text;
  $('setup-text').value = f.setup || '';
  ui.source = { kind: 'server', root, path, dir: f.dir, name: path.split('/').pop(), text: f.text, doc: editor.doc, setup: f.setup || '' };
  $('files').value = `${root}|${path}`;
  workspace.opened(sourceKey());
  setStatus(`${path}${f.setup_path ? ` (setup ${f.setup_path})` : ''}`);
  clearRun();
}

function clearRun() {
  ui.model = null;
  $('scrub').max = 0;
  $('stepinfo').textContent = '-';
}

$('files').addEventListener('change', (e) => {
  const [root, path] = e.target.value.split('|');
  if (root && path) openFile(root, path);
  else {
    editor.text = 'O0001\n';
    ui.source = { kind: 'new', root: null, dir: '', name: 'program.nc' };
    workspace.opened(sourceKey());
    clearRun();
  }
});

// Where the editor's text came from, as the workspace keeps it (no server folder).
const sourceKey = () => ({ kind: ui.source.kind, name: ui.source.name, root: ui.source.root, path: ui.source.path });

function openLocal(name, text) {
  editor.text = text;
  ui.source = { kind: 'local', root: null, dir: '', name };
  $('files').value = '';
  workspace.opened(sourceKey());
  setStatus(`${name} (local file, ${editor.lineCount} lines)`);
  clearRun();
}

const workspace = new Workspace({
  editor,
  setupText: $('setup-text'),
  openServer: (root, path) => openFile(root, path),
  openLocal,
  source: sourceKey,
  status: setStatus,
});
$('find').addEventListener('click', () => editor.find());
$('goto-line').addEventListener('click', () => editor.goToLine());

editor.onChange = () => {
  workspace.changed();
  if (ui.model) {
    ui.stale = true;
    setStatus('edited: Run again to update', 'warn');
  }
};

async function run() {
  setStatus('running...', 'busy');
  $('run').disabled = true;
  const req = { name: ui.source.name };
  // A file of the server's folders, unchanged, runs by its path: its text is not sent back.
  // The editor's document still the one the file was loaded into is unchanged without a
  // look at its text.
  const same = ui.source.kind === 'server' && ui.source.doc === editor.doc;
  const text = same ? null : editor.text;
  const unchanged = ui.source.kind === 'server' && (same || ui.source.text === text);
  if (unchanged) Object.assign(req, { root: ui.source.root, path: ui.source.path });
  else req.program = text;
  // The setup tab's text when it is one of the user's; a program of the server's folders with
  // its own setup as it came (or none) runs with the setup the server pairs with it, by the rule
  // of `ncvm list` (docs/setup-format.md).
  const setup = $('setup-text').value;
  if (setup.trim() && !(ui.source.kind === 'server' && setup === ui.source.setup)) req.setup = setup;
  if (ui.source.root && !unchanged) Object.assign(req, { root: ui.source.root, dir: ui.source.dir });
  const layers = setupLayers.request(); // presets and job files around the tab's setup
  if (layers) req.setups = layers;
  progress.set('running');
  const lines = editor.lineCount || 0;
  // The stock along the timeline: a snapshot every N moves, N doubled by the server until
  // the run fits in 64 (CAM code is about a move a line, so N starts near lines / 64).
  req.stock_every = 2 ** Math.max(0, Math.floor(Math.log2(Math.max(1, lines / 64))));
  const result = await api.run(req, (p) => progress.update(p, lines), lines);
  $('run').disabled = false;
  if (!result.ok) {
    progress.set('alarm');
    setStatus(result.error || 'the run failed', 'bad');
    return;
  }
  ui.stale = false;
  const model = result.model;
  const answer = model.answer;
  ui.model = model;
  ui.shown = null;
  const s = answer.state;
  const marks = [];
  const mine = (f) => !f || f === ui.source.name;
  if (s.alarm && mine(s.alarm.file)) marks.push({ line: s.alarm.line, kind: 'alarm', text: `${s.alarm.code} ${s.alarm.text}` });
  for (const c of answer.check.alarms) if (mine(c.file)) marks.push({ line: c.line, kind: 'alarm', text: `${c.code} ${c.text}` });
  for (const w of [...answer.check.warnings, ...s.warnings]) if (mine(w.file)) marks.push({ line: w.line, kind: 'warning', text: `${w.code} ${w.text}` });
  editor.setMarks(marks);
  view.setModel(model);
  colourBy.setModel(model);
  measure.setModel(model);
  toolShapes.setModel(model);
  stockTimeline.setModel(model);
  themeGrid(view);
  link.setModel(model, ui.source.name);
  link.highlightLine(editor.cursorLine);
  $('scrub').max = model.n * SUB;
  recordRun(model, ui.source.name);
  renderMessages($('p-messages'), model, pick);
  renderTime($('p-time'), model);
  setStatus(
    s.alarm ? `${s.end}: ${s.alarm.code} ${s.alarm.text} (${s.alarm.file}:${s.alarm.line})` : `ended ${s.end}: ${s.blocks} blocks, ${s.moves} moves, cycle time ${s.cycle_time.toFixed(2)} s`,
    s.alarm ? 'bad' : 'good',
  );
  goTo(model.n * SUB);
  progress.set(s.alarm ? 'alarm' : 'ready', model.moves);
}

// Jump to a message: to its event when it has one, else just to its line.
function pick(item) {
  if (item.event !== undefined) goTo((item.event + 1) * SUB);
  else if (item.line && (!item.file || item.file === ui.source.name)) editor.setCurrent(item.line);
}

function goTo(pos) {
  const m = ui.model;
  if (!m) return;
  ui.p = Math.max(0, Math.min(pos, m.n * SUB));
  $('scrub').value = ui.p;
  const p = ui.p / SUB;
  const tool = toolAt(m, p);
  const done = Math.floor(p);
  toolShapes.update(tool.index);
  stockTimeline.update(done);
  view.setProgress(verticesDone(m, done), drawnTool(m, tool), done);
  const idx = p > done ? done : done - 1; // the event in progress, else the last one done
  const ev = eventAt(m, idx);
  const state = stateAt(m, idx);
  renderPosition($('p-position'), m, tool, state || stateAt(m, 0));
  renderVariables($('p-vars'), state, ui.shown);
  ui.shown = state;
  renderOffsets($('p-offsets'), state || stateAt(m, 0));
  renderModal($('p-modal'), state);
  if (ev) {
    const here = ev.file === ui.source.name;
    editor.setCurrent(here ? ev.line : 0);
    $('stepinfo').textContent = `event ${idx + 1}/${m.n} · block ${state.block} · ${ev.file}:${ev.line}${ev.n !== null ? ` N${ev.n}` : ''} · ${ev.type}${ev.mode ? ' ' + ev.mode : ''} · t ${state.time.toFixed(2)} s`;
  } else {
    editor.setCurrent(0);
    $('stepinfo').textContent = `start · ${m.n} events`;
  }
}

// Single block: to the end of the next (previous) block that made the machine do something.
function step(dir) {
  const m = ui.model;
  if (!m || playback.step(dir)) return;
  const done = Math.floor(ui.p / SUB);
  if (dir > 0) {
    const end = nextBlockEnd(m, done);
    if (end !== null) goTo(end * SUB);
  } else goTo(prevBlockEnd(m, done, ui.p % SUB !== 0) * SUB);
}

const playback = new Playback({ model: () => ui.model, position: () => ui.p, goTo, sub: SUB });
$('scrub').addEventListener('input', (e) => goTo(Number(e.target.value)));
$('fwd').addEventListener('click', () => step(1));
$('back').addEventListener('click', () => step(-1));
$('run').addEventListener('click', run);
document.addEventListener('keydown', (e) => {
  if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) run();
  // Keys typed in the editor (contenteditable) or a field are theirs, not the timeline's.
  if (['TEXTAREA', 'INPUT', 'SELECT'].includes(e.target.tagName) || e.target.closest?.('.cm-editor')) return;
  if (e.key === 'ArrowRight') step(1);
  if (e.key === 'ArrowLeft') step(-1);
  if (e.key === ' ' && e.target.tagName !== 'BUTTON') {
    e.preventDefault();
    $('play').click();
  }
});

(async () => {
  // The three answers at once: one after the other they were a third of opening the page.
  const [inf, , draft] = await Promise.all([api.info(), loadFiles(), workspace.draft()]);
  if (inf.setup) $('setup-text').placeholder = `# empty: the server's --setup ${inf.setup_name}`;
  api.setups().then((l) => setupLayers.setFiles(l));
  renderVariables($('p-vars'), null);
  const started = (s) => inf.start && s?.kind === 'server' && s.root === inf.start.root && s.path === inf.start.path;
  if (draft?.source && (draft.text !== null || draft.source.kind !== 'new') && (!inf.start || started(draft.source))) await restore(draft);
  else if (inf.start) await openFile(inf.start.root, inf.start.path);
  else {
    editor.text = 'O0001 (NEW PROGRAM)\nG21 G90 G17 G40 G80\nG00 X0 Y0 Z5.\nG01 Z-1. F100.\nX50.\nY30.\nM30\n';
    setStatus('pick an example or write a program, then Run');
  }
  document.body.dataset.ready = 'true';
  if (document.body.dataset.run === 'loading') progress.set('ready', 0);
})();

// The last visit's program: its edited text when it was edited, else the file again.
async function restore(d) {
  const s = d.source;
  if (s.kind === 'server') await openFile(s.root, s.path);
  else if (s.kind === 'local' && d.text === null) await workspace.openRecent(s);
  else ui.source = { kind: s.kind, root: null, dir: '', name: s.name };
  if (d.text !== null) {
    editor.text = d.text;
    if (d.setup !== null) $('setup-text').value = d.setup;
    workspace.save();
    setStatus(`${s.name}: your edits of ${new Date(d.time).toLocaleString()} (not yet run)`, 'warn');
  }
}
