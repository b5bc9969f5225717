// The side panels: position page, macro variables, offsets, modal state, messages and
// alarms, cycle time. Each render function fills one element from the model and the step.
import { escapeHtml } from './highlight.js';
import { timeBreakdown, timeByTool, notesOf } from './model.js';

const fmt = (v, d = 3) => (typeof v === 'number' ? v.toFixed(d) : v ?? '');

function table(head, rows, cls = '') {
  return `<table class="${cls}"><thead><tr>${head.map((h) => `<th>${escapeHtml(String(h))}</th>`).join('')}</tr></thead><tbody>${rows.join('')}</tbody></table>`;
}

// As the control's position page: absolute (work), relative, machine, distance to go.
export function renderPosition(el, model, tool) {
  const names = model.axisNames;
  const row = (label, vals) =>
    `<tr><th>${label}</th>${names.map((n, a) => `<td data-axis="${n}">${fmt(vals?.[a] ?? 0)}</td>`).join('')}</tr>`;
  el.innerHTML =
    table(['', ...names], [
      row('Absolute', tool.work),
      row('Relative', tool.work),
      row('Machine', tool.machine),
      row('Distance to go', tool.togo),
    ], 'position') +
    `<p class="note">Relative equals absolute: ncvm has no operator to reset the relative counters.${model.lathe ? ' X is a diameter.' : ''}</p>`;
}

function varTable(title, vars, changed, id) {
  const keys = Object.keys(vars).sort((a, b) => Number(a.slice(1)) - Number(b.slice(1)));
  const rows = keys.map(
    (k) => `<tr class="${changed?.has(k) ? 'changed' : ''}" data-var="${k}"><th>${k}</th><td>${fmt(vars[k], 4)}</td></tr>`,
  );
  if (!rows.length) rows.push('<tr><td colspan="2" class="empty">all vacant</td></tr>');
  return `<h3>${title}</h3><div id="${id}">${table(['#', 'value'], rows, 'vars')}</div>`;
}

// Highlighted: what differs from `before`, the state shown last (a step may span several
// events), else what the current event changed.
export function renderVariables(el, state, before) {
  if (!state) return (el.innerHTML = '<p class="empty">Run the program to see its variables.</p>');
  let changed = state.changed;
  if (before && before !== state) {
    changed = new Set();
    for (const part of ['locals', 'common', 'system'])
      for (const k of new Set([...Object.keys(state[part]), ...Object.keys(before[part])]))
        if (state[part][k] !== before[part][k]) changed.add(k);
  }
  el.innerHTML =
    varTable('Local (current level)', state.locals, changed, 'vars-local') +
    varTable('Common', state.common, changed, 'vars-common') +
    varTable('System', state.system, changed, 'vars-system');
}

export function renderOffsets(el, state) {
  if (!state) return (el.innerHTML = '');
  const work = state.offsets?.work || {};
  const axes = Object.keys(Object.values(work)[0] || {});
  let html = '<h3>Work offsets (mm)</h3>' + table(['', ...axes], Object.entries(work).map(
    ([name, v]) => `<tr><th>${escapeHtml(name)}</th>${axes.map((a) => `<td>${fmt(v[a])}</td>`).join('')}</tr>`,
  ));
  const tool = state.offsets?.tool || {};
  const cols = [...new Set(Object.values(tool).flatMap((r) => Object.keys(r)))];
  html += '<h3>Tool offsets (mm)</h3>' + (Object.keys(tool).length
    ? table(['No.', ...cols], Object.entries(tool).map(
      ([n, r]) => `<tr><th>${n}</th>${cols.map((c) => `<td>${fmt(r[c])}</td>`).join('')}</tr>`))
    : '<p class="empty">all zero</p>');
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
  let html = `<p class="cycle">Cycle time <b id="cycle-time">${fmt(total, 2)} s</b> (${hms(total)})</p>`;
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
