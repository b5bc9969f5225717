// Setups in layers, as `--setup` given more than once (docs/setup-format.md): a preset from
// presets/, then the job's file, later layers overriding earlier ones. The Setup tab lists the
// layers in the order they apply. One row is the tab's own text (or, when it is the program's
// own setup as opened, that setup, by the rule of `ncvm list`); the others are .toml files of
// the server (GET /api/setups), added from the list under the rows, moved up and down, and
// removed. A run sends them as `setups` (src/server/setup_layers.hpp); with no row but the
// tab's, nothing is sent and the run is as before. The list is kept in the browser.
const KEY = 'ncvm.setupLayers';
const TAB = { tab: true };

const same = (a, b) => (a.tab && b.tab) || (a.root === b.root && a.path === b.path);

export class SetupLayers {
  // host: the element the rows and the picker go in; onChange(): after any change.
  constructor(host, onChange = () => {}) {
    this.host = host;
    this.onChange = onChange;
    this.layers = this.load();
    host.innerHTML =
      '<div class="layers-head">Layers, in the order they apply (a later one overrides an earlier one, as <code>--setup</code> given more than once):</div>' +
      '<ol class="layer-list"></ol>' +
      '<select class="layer-add" aria-label="add a setup layer"><option value="">Add a layer…</option></select>';
    this.list = host.querySelector('.layer-list');
    this.picker = host.querySelector('.layer-add');
    this.picker.addEventListener('change', () => {
      const [root, ...rest] = this.picker.value.split('|');
      this.picker.value = '';
      if (!root) return;
      const layer = { root, path: rest.join('|') };
      if (this.layers.some((l) => same(l, layer))) return;
      // Added before the tab's row: a preset under the job's own setup.
      this.layers.splice(this.layers.findIndex((l) => l.tab), 0, layer);
      this.changed();
    });
    this.list.addEventListener('click', (e) => {
      const b = e.target.closest('button[data-act]');
      if (!b) return;
      const k = Number(b.closest('li').dataset.index), L = this.layers;
      if (b.dataset.act === 'remove') L.splice(k, 1);
      else {
        const j = k + (b.dataset.act === 'up' ? -1 : 1);
        if (j < 0 || j >= L.length) return;
        [L[k], L[j]] = [L[j], L[k]];
      }
      this.changed();
    });
    this.tabName = "this tab's setup (empty or as opened: the program's own)";
    this.render();
  }

  load() {
    try {
      const v = JSON.parse(localStorage.getItem(KEY));
      if (Array.isArray(v) && v.filter((l) => l.tab).length === 1) return v;
    } catch {
      // none kept, or not ours
    }
    return [TAB];
  }

  // The files a layer may be: {presets: [...], roots: [{name, files}]} (GET /api/setups).
  setFiles(list) {
    const groups = [['presets', list.presets || []], ...(list.roots || []).map((r) => [r.name, r.files])];
    for (const [root, files] of groups) {
      if (!files.length) continue;
      const g = document.createElement('optgroup');
      g.label = root;
      for (const f of files) g.appendChild(new Option(f, `${root}|${f}`));
      this.picker.appendChild(g);
    }
  }

  changed() {
    localStorage.setItem(KEY, JSON.stringify(this.layers));
    this.render();
    this.onChange();
  }

  render() {
    this.list.innerHTML = '';
    this.layers.forEach((l, k) => {
      const li = document.createElement('li');
      li.dataset.index = k;
      li.className = l.tab ? 'tab-layer' : 'file-layer';
      const name = document.createElement('span');
      name.textContent = l.tab ? this.tabName : `${l.root}/${l.path}`;
      li.appendChild(name);
      for (const [act, text, title] of [['up', '↑', 'apply earlier'], ['down', '↓', 'apply later'], ...(l.tab ? [] : [['remove', '×', 'remove this layer']])]) {
        const b = document.createElement('button');
        Object.assign(b.dataset, { act });
        b.textContent = text;
        b.title = title;
        li.appendChild(b);
      }
      this.list.appendChild(li);
    });
    this.host.dataset.layers = this.layers.map((l) => (l.tab ? 'tab' : `${l.root}/${l.path}`)).join(',');
  }

  // The run request's `setups`, or undefined when only the tab's row is there.
  request() {
    return this.layers.length > 1 ? this.layers.map((l) => (l.tab ? { tab: true } : { root: l.root, path: l.path })) : undefined;
  }
}
