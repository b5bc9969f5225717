// The "Colour by" selector of the 3D view and its legend: the toolpath coloured by move kind
// (the default), feed rate, depth or tool (path_colours.js). The colours are the path's
// vertex colour attribute, rewritten once per change of mode or of run, never per frame.
import { MODES, RAMP_CSS, pathColours } from './path_colours.js';

const KEY = 'ncvm.colourBy';

export class ColourBy {
  // view: the View3D; host: the legend's element.
  constructor(view, host) {
    this.view = view;
    this.host = host;
    this.model = null;
    this.select = document.createElement('select');
    this.select.id = 'colour-by';
    this.select.title = 'Colour the path by';
    this.select.setAttribute('aria-label', 'colour the path by');
    this.select.innerHTML = Object.entries(MODES).map(([k, t]) => `<option value="${k}">${t}</option>`).join('');
    const saved = localStorage.getItem(KEY);
    this.select.value = saved && MODES[saved] ? saved : 'kind';
    this.items = document.createElement('span');
    this.items.className = 'legend-items';
    host.replaceChildren(this.select, this.items);
    this.select.addEventListener('change', () => {
      localStorage.setItem(KEY, this.select.value);
      this.apply();
    });
    view.host.colourBy = this; // the browser tests reach it through the view's element
    this.showLegend(pathLegendOf(this.select.value));
  }

  get mode() {
    return this.select.value;
  }

  setModel(model) {
    this.model = model;
    // A new path's colour attribute is already by kind (model.js): no second upload.
    if (this.select.value === 'kind') {
      this.view.host.dataset.colourBy = 'kind';
      this.showLegend(pathColours({ moves: 0, vertices: new Float32Array(0) }, 'kind').legend);
    } else this.apply();
  }

  apply() {
    const mode = this.select.value;
    this.view.host.dataset.colourBy = mode;
    if (!this.model) return this.showLegend(pathLegendOf(mode));
    const { colours, legend } = pathColours(this.model, mode);
    this.view.setPathColours(colours);
    this.showLegend(legend);
  }

  showLegend(legend) {
    this.items.replaceChildren(
      ...legend.map((l) => {
        const s = document.createElement('span');
        const i = document.createElement('i');
        if (l.gradient) {
          i.className = 'ramp';
          i.style.background = RAMP_CSS;
        } else i.style.background = l.colour;
        s.append(i, l.text);
        return s;
      }),
    );
  }
}

// The legend before a run: the mode's meaning without numbers.
function pathLegendOf(mode) {
  if (mode === 'kind') return pathColours({ moves: 0, vertices: new Float32Array(0) }, 'kind').legend;
  if (mode === 'tool') return [];
  return [{ gradient: true, text: mode === 'feed' ? 'F low … high' : 'low … high' }];
}
