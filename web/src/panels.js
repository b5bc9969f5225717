// The side panels: position page, macro variables, offsets, modal state, messages and
// alarms, cycle time. Each render function fills one element from the model and the step.
import { escapeHtml } from './highlight.js';
import { timeBreakdown, timeByTool, notesOf, eventAt } from './model.js';
import { KIND } from './wire.js';
import { counters, partsOfRun } from './counters.js';

const fmt = (v, d = 3) => (typeof v === 'number' ? v.toFixed(d) : v ?? '');

function table(head, rows, cls = '') {
  return `<table class="${cls}"><thead><tr>${head.map((h) => `<th>${escapeHtml(String(h))}</th>`).join('')}</tr></thead><tbody>${rows.join('')}</tbody></table>`;
}

const MM_PER_INCH = 25.4;
const unitsOf = (state) => (state?.modal?.units === 'inch' ? 'inch' : 'mm');
const feedUnit = (u) => (u === 'inch' ? 'in/min' : 'mm/min');

// The spindle after each event: the last spindle event at or before it (one pass, kept).
const spindleCache = new WeakMap();
function spindleAt(model, index) {
  let last = spindleCache.get(model);
  if (!last) {
    last = new Int32Array(model.n);
    let k = -1;
    for (let i = 0; i < model.n; i++) {
      if (model.kind[i] === KIND.spindle) k = i;
      last[i] = k;
    }
    spindleCache.set(model, last);
  }
  const k = index >= 0 && index < last.length ? last[index] : -1;
  return k < 0 ? null : eventAt(model, k);
}

// As the control's position page: absolute (work), relative, machine, distance to go, in the
// program's units; the actual feed (of the move in progress: 0 at a block end, where a
// single-block stop holds the axes) and spindle speed, the commanded F and S, and the tool.
export function renderPosition(el, model, tool, state) {
  const names = model.axisNames;
  const u = unitsOf(state);
  const row = (label, vals) =>
    `<tr><th>${label}</th>${names.map((n, a) => `<td data-axis="${n}">${fmt(vals?.[a] ?? 0, u === 'inch' ? 4 : 3)}</td>`).join('')}</tr>`;
  const ev = tool.index >= 0 ? eventAt(model, tool.index) : null; // the move in progress, else the last event done
  const moving = ev && ev.type === 'move' && tool.togo.some((v) => Math.abs(v) > 1e-9);
  const sp = spindleAt(model, tool.index);
  const rpm = sp && sp.dir !== 'stop' ? sp.rpm : 0;
  const m = state?.modal || {};
  const cell = (k, v, unit, id) => `<div class="pos-cell"><small>${k}</small><b id="${id}">${v}</b><small>${unit}</small></div>`;
  el.innerHTML =
    `<p class="units">Units <b id="pos-units">${u}</b>${model.lathe ? ' · X is a diameter' : ''}</p>` +
    table(['', ...names], [
      row('Absolute', tool.work),
      row('Relative', tool.work),
      row('Machine', tool.machine),
      row('Distance to go', tool.togo),
    ], 'position') +
    `<div class="pos-grid">${[
      cell('Act. F', fmt(moving ? ev.feed : 0, 1), feedUnit(u), 'act-feed'),
      cell('Act. S', fmt(rpm, 0), 'rpm', 'act-speed'),
      cell('F', fmt(m.F ?? 0, 1), feedUnit(u), 'cmd-feed'),
      cell('S', fmt(m.S ?? 0, 0), 'rpm', 'cmd-speed'),
      cell('T', escapeHtml(String(m.T ?? 0)), '', 'cmd-tool'),
      cell('Mode', ev?.type === 'move' ? escapeHtml(ev.mode) : '-', '', 'move-mode'),
    ].join('')}</div>` +
    '<p class="note">Relative equals absolute: ncvm has no operator to reset the relative counters.</p>';
}

function varTable(title, vars, changed, id, match) {
  const keys = Object.keys(vars).filter(match).sort((a, b) => Number(a.slice(1)) - Number(b.slice(1)));
  const rows = keys.map(
    (k) => `<tr class="${changed?.has(k) ? 'changed' : ''}" data-var="${k}"><th>${k}</th><td>${fmt(vars[k], 4)}</td></tr>`,
  );
  if (!rows.length) rows.push(`<tr><td colspan="2" class="empty">${Object.keys(vars).length ? 'none matches' : 'all vacant'}</td></tr>`);
  return `<h3>${title}</h3><div id="${id}">${table(['#', 'value'], rows, 'vars')}</div>`;
}

// A variable search: "#5001", "5001", "500" (every number with it), or "#100-#110".
function varMatcher(query) {
  const q = query.trim().replace(/#/g, '');
  if (!q) return () => true;
  const range = /^(\d+)\s*-\s*(\d+)$/.exec(q);
  if (range) {
    const lo = Number(range[1]), hi = Number(range[2]);
    return (k) => Number(k.slice(1)) >= lo && Number(k.slice(1)) <= hi;
  }
  return (k) => k.slice(1).includes(q);
}

// Highlighted: what differs from `before`, the state shown last (a step may span several
// events), else what the current event changed. The search box above the tables stays.
export function renderVariables(el, state, before) {
  if (!el.querySelector('#var-search')) {
    el.innerHTML = '<input id="var-search" type="search" placeholder="search: #5001, 100, #100-#199" aria-label="search variables"><div class="var-body"></div>';
    el.querySelector('#var-search').addEventListener('input', () => renderVariables(el, el.shown, el.before));
  }
  el.shown = state;
  el.before = before;
  const body = el.querySelector('.var-body');
  if (!state) return (body.innerHTML = '<p class="empty">Run the program to see its variables.</p>');
  let changed = state.changed;
  if (before && before !== state) {
    changed = new Set();
    for (const part of ['locals', 'common', 'system'])
      for (const k of new Set([...Object.keys(state[part]), ...Object.keys(before[part])]))
        if (state[part][k] !== before[part][k]) changed.add(k);
  }
  const match = varMatcher(el.querySelector('#var-search').value);
  body.innerHTML =
    varTable('Local (current level)', state.locals, changed, 'vars-local', match) +
    varTable('Common', state.common, changed, 'vars-common', match) +
    varTable('System', state.system, changed, 'vars-system', match);
}

// The offset pages with the control's names, in the program's units (the state has mm):
// work offsets 00 (EXT) and G54-G59; tool offsets as geometry and wear, a mill's H (length)
// and D (radius), a lathe's X, Z, R and T (tip), Y only on a lathe with a Y axis.
export function renderOffsets(el, state) {
  if (!state) return (el.innerHTML = '');
  const u = unitsOf(state);
  const k = u === 'inch' ? 1 / MM_PER_INCH : 1;
  const d = u === 'inch' ? 4 : 3;
  const v = (x) => (typeof x === 'number' ? (x * k).toFixed(d) : '');
  const work = state.offsets?.work || {};
  const axes = Object.keys(Object.values(work)[0] || {});
  const workName = (n) => (n === 'EXT' ? '00 (EXT)' : n);
  let html = `<h3>Work offsets (${u})</h3>` + table(['', ...axes], Object.entries(work).map(
    ([name, o]) => `<tr><th>${escapeHtml(workName(name))}</th>${axes.map((a) => `<td>${v(o[a])}</td>`).join('')}</tr>`,
  ), 'work-offsets');
  const tool = state.offsets?.tool || {};
  const rows = Object.entries(tool);
  const lathe = rows.some(([, r]) => 'tip' in r);
  if (!rows.length) return (el.innerHTML = html + `<h3>Tool offsets (${u})</h3><p class="empty">all zero</p>`);
  if (lathe) {
    const fields = ['x', ...(axes.includes('Y') ? ['y'] : []), 'z', 'r'];
    for (const kind of ['geometry', 'wear'])
      html += `<h3>Tool offsets: ${kind} (${u})</h3>` + table(['No.', ...fields.map((f) => f.toUpperCase()), 'T'], rows.map(
        ([n, r]) => `<tr><th>${n}</th>${fields.map((f) => `<td>${v(r[`${f}_${kind}`])}</td>`).join('')}<td>${r.tip ?? 0}</td></tr>`,
      ), `tool-${kind}`);
  } else {
    html += `<h3>Tool offsets (${u})</h3>` + table(['No.', 'H geometry', 'H wear', 'D geometry', 'D wear'], rows.map(
      ([n, r]) => `<tr><th>${n}</th>${['h_geometry', 'h_wear', 'd_geometry', 'd_wear'].map((f) => `<td>${v(r[f])}</td>`).join('')}</tr>`,
    ), 'tool-offsets');
  }
  el.innerHTML = html;
}

export function renderModal(el, state) {
  const m = state?.modal;
  if (!m || !Object.keys(m).length) return (el.innerHTML = '<p class="empty">-</p>');
  const groups = Object.keys(m).filter((k) => /^\d+$/.test(k)).sort((a, b) => a - b);
  const g = (v) => `G${String(Math.trunc(v)).padStart(2, '0')}${v % 1 ? '.' + Math.round((v % 1) * 10) : ''}`;
  const cells = groups.map((k) => `<div class="modal-g" title="group ${k}"><small>${k}</small>${g(m[k])}</div>`);
  el.innerHTML = `<div class="modal-grid">${cells.join('')}</div>` + table(['F', 'S', 'T', 'D', 'H', 'units'],
    [`<tr>${['F', 'S', 'T', 'D', 'H', 'units'].map((k) => `<td>${escapeHtml(String(m[k] ?? ''))}</td>`).join('')}</tr>`]);
}

// Alarms, warnings, messages and DPRNT output; clicking one jumps there.
export function renderMessages(el, model, onPick) {
  const a = model.answer;
  const items = [];
  const alarm = a.state?.alarm;
  if (alarm) items.push({ kind: 'alarm', line: alarm.line, file: alarm.file, text: `${alarm.code} ${alarm.text}`, col: alarm.col });
  for (const c of a.check?.alarms || []) if (!alarm || c.line !== alarm.line || c.code !== alarm.code) items.push({ kind: 'alarm', ...c, text: `${c.code} ${c.text}` });
  for (const w of [...(a.check?.warnings || []), ...(a.state?.warnings || [])]) items.push({ kind: 'warning', ...w, text: `${w.code} ${w.text}` });
  for (const e of notesOf(model))
    if (e.type === 'message') items.push({ kind: 'message', line: e.line, file: e.file, text: `${e.source}: ${e.text}`, event: e.index });
  for (const w of a.load_warnings || []) items.push({ kind: 'warning', text: w });
  const stock = a.state?.stock;
  for (const c of stock?.collisions || [])
    items.push({ kind: 'alarm', line: c.line, file: c.program, text: `stock collision: ${c.kind} (${fmt(c.amount, 3)})` });
  let html = `<ul class="messages">${items.map((it, k) => `<li class="${it.kind}" data-k="${k}">
    <b>${it.kind}</b> ${it.file ? `${escapeHtml(it.file)}:${it.line}${it.col ? ':' + it.col : ''}` : ''} ${escapeHtml(it.text)}</li>`).join('')}</ul>`;
  if (!items.length) html = '<p class="empty">No alarms, warnings or messages.</p>';
  if (stock) html += stockSummary(stock);
  if (a.printed) html += `<h3>DPRNT output</h3><pre class="printed">${escapeHtml(a.printed)}</pre>`;
  html += alarmHistory();
  el.innerHTML = html;
  el.querySelectorAll('li').forEach((li) => li.addEventListener('click', () => onPick(items[Number(li.dataset.k)])));
  return items;
}

// The stock analysis in a few lines (docs/stock-analysis.md has every field).
function stockSummary(st) {
  const u = st.units || '';
  const rows = [['model', `${st.kind}, ${st.cutting_moves ?? '?'} of ${st.moves ?? '?'} moves cut`]];
  const d = st.deviation;
  if (d && d.measured === false) rows.push(['deviation', `not measured (${d.not_measured || 'no sample'})`]);
  else if (d) {
    rows.push(['deviation max', `${fmt(d.max, 4)} ${u} (excess ${fmt(d.max_excess, 4)}, gouge ${fmt(d.max_gouge, 4)})`]);
    rows.push(['in tolerance', `${fmt(100 * (d.in_tolerance ?? 0), 1)} % of ±${fmt(d.tolerance, 4)} ${u}`]);
  } else rows.push(['deviation', 'no [target]']);
  if (st.uncut) rows.push(['uncut area', `${fmt(st.uncut.area, 2)} ${u}² (${fmt(100 * (st.uncut.share ?? 0), 1)} %)`]);
  rows.push(['collisions', String((st.collisions || []).length)]);
  return `<h3>Stock</h3><table id="stock-summary"><tbody>${rows
    .map(([k, v]) => `<tr><th>${escapeHtml(k)}</th><td>${escapeHtml(v)}</td></tr>`)
    .join('')}</tbody></table>`;
}

function bars(entries, total) {
  const max = Math.max(...entries.map(([, v]) => v), 1e-12);
  return `<div class="bars">${entries.map(([k, v]) => `<div class="bar"><span class="k">${escapeHtml(k)}</span>
    <span class="b"><i style="width:${(100 * v) / max}%"></i></span><span class="v">${fmt(v, 2)} s${total ? ` (${((100 * v) / total).toFixed(0)}%)` : ''}</span></div>`).join('')}</div>`;
}

// Cycle time: the state's cycle_time, the split by kind of motion from the trace, and any
// modelled breakdown the state carries (an object of numbers under a key with "time").
export function renderTime(el, model) {
  const s = model.answer.state || {};
  const total = s.cycle_time || 0;
  const t = timeBreakdown(model);
  const c = counters();
  let html = `<p class="cycle">Cycle time <b id="cycle-time">${fmt(total, 2)} s</b> (${hms(total)})</p>`;
  html += `<table id="run-counters"><tbody>
    <tr><th>Parts counted this run (M30, #3901)</th><td id="parts-run">${partsOfRun(model)}</td></tr>
    <tr><th>Parts counted, all runs</th><td id="parts-total">${c.parts}</td></tr>
    <tr><th>Run time, all ${c.runs} runs</th><td id="run-time">${hms(c.runTime)}</td></tr>
  </tbody></table><p class="note">All runs: the runs in this browser (kept in its storage); times are modelled, not measured on a machine.</p>`;
  html += '<h3>By motion (trace)</h3>' + bars(Object.entries(t), total);
  const byTool = Object.entries(timeByTool(model));
  if (byTool.length > 1 || (byTool.length === 1 && byTool[0][0] !== 'T0')) html += '<h3>By tool (trace)</h3>' + bars(byTool, total);
  for (const [key, v] of Object.entries(s))
    if (key !== 'cycle_time' && /time/i.test(key) && v && typeof v === 'object') {
      const nums = Object.entries(v).filter(([, x]) => typeof x === 'number');
      if (nums.length) html += `<h3>${escapeHtml(key)}</h3>` + bars(nums, total);
    }
  el.innerHTML = html;
}

function hms(s) {
  const h = Math.floor(s / 3600), m = Math.floor(s / 60) % 60, sec = s - Math.floor(s / 60) * 60;
  return `${h}:${String(m).padStart(2, '0')}:${sec.toFixed(2).padStart(5, '0')}`;
}

// The control's alarm history: the alarms of the runs in this browser, newest first.
function alarmHistory() {
  const list = counters().alarms;
  const rows = list.map((a) => `<tr><td>${escapeHtml(new Date(a.time).toLocaleString())}</td><td>${escapeHtml(a.code)}</td>
    <td class="text">${escapeHtml(a.text)}</td><td>${escapeHtml(`${a.program}${a.line ? ':' + a.line : ''}${a.n !== null && a.n !== undefined ? ' N' + a.n : ''}`)}</td></tr>`);
  return '<h3>Alarm history</h3>' + (rows.length ? table(['time', 'alarm', 'message', 'where'], rows, 'alarm-history') : '<p class="empty" id="alarm-history">no alarms yet</p>');
}
