// A small program editor: a textarea over a highlighted copy of its text, with a gutter of
// line numbers and alarm/warning markers and a highlighted current block. Lines are 1-based,
// as in the trace.
import { highlightLine, escapeHtml } from './highlight.js';

export class Editor {
  constructor(host) {
    this.host = host;
    host.classList.add('editor');
    host.innerHTML = `<div class="scroll"><div class="gutter"></div><div class="code">
      <pre class="hl" aria-hidden="true"></pre><textarea spellcheck="false" wrap="off"
      aria-label="program text"></textarea></div></div>`;
    this.scroll = host.querySelector('.scroll');
    this.gutter = host.querySelector('.gutter');
    this.pre = host.querySelector('.hl');
    this.area = host.querySelector('textarea');
    this.marks = new Map(); // line -> {kind: 'alarm'|'warning', text}
    this.current = 0;
    this.onChange = () => {};
    this.area.addEventListener('input', () => {
      this.render();
      this.onChange();
    });
    this.area.addEventListener('keydown', (e) => {
      if (e.key === 'Tab') {
        e.preventDefault();
        document.execCommand('insertText', false, '  ');
      }
    });
  }

  get text() {
    return this.area.value;
  }

  set text(t) {
    this.area.value = t;
    this.marks.clear();
    this.current = 0;
    this.render();
  }

  // marks: [{line, kind, text}]
  setMarks(marks) {
    this.marks.clear();
    for (const m of marks) {
      const had = this.marks.get(m.line);
      // An alarm outranks a warning on the same line.
      if (!had || (had.kind === 'warning' && m.kind === 'alarm')) this.marks.set(m.line, { ...m });
      else had.text += '\n' + m.text;
    }
    this.render();
  }

  setCurrent(line, reveal = true) {
    if (line === this.current) return;
    this.current = line;
    for (const el of this.host.querySelectorAll('.current')) el.classList.remove('current');
    if (!line) return;
    const l = this.pre.querySelector(`.line[data-line="${line}"]`);
    const g = this.gutter.querySelector(`.ln[data-line="${line}"]`);
    l?.classList.add('current');
    g?.classList.add('current');
    if (reveal && l) {
      const top = l.offsetTop, h = this.scroll.clientHeight;
      if (top < this.scroll.scrollTop || top > this.scroll.scrollTop + h - 40) this.scroll.scrollTop = top - h / 3;
    }
  }

  render() {
    const lines = this.area.value.split('\n');
    let gutter = '', code = '';
    lines.forEach((text, k) => {
      const n = k + 1;
      const mark = this.marks.get(n);
      const cls = [mark ? mark.kind : '', n === this.current ? 'current' : ''].join(' ').trim();
      const title = mark ? ` title="${escapeHtml(mark.text)}"` : '';
      gutter += `<div class="ln ${cls}" data-line="${n}"${title}>${mark ? '<b class="marker"></b>' : ''}${n}</div>`;
      code += `<div class="line ${cls}" data-line="${n}">${highlightLine(text) || ' '}</div>`;
    });
    this.gutter.innerHTML = gutter;
    this.pre.innerHTML = code;
    // The textarea grows with its text so that the outer box scrolls both layers together.
    this.area.style.height = `${this.pre.scrollHeight}px`;
    this.area.style.width = `${Math.max(this.pre.scrollWidth, this.scroll.clientWidth - this.gutter.offsetWidth)}px`;
  }
}
