// The run's progress on the page: document.body.dataset.run is loading, running, ready or
// alarm (the browser tests and bench/viewer wait on it), dataset.moves the number of moves
// drawn once ready, and a bar over the 3D view while a run streams in.
export class RunProgress {
  constructor(host) {
    this.el = document.createElement('div');
    this.el.id = 'run-progress';
    this.el.setAttribute('role', 'progressbar');
    Object.assign(this.el.style, {
      position: 'absolute', left: '0', right: '0', top: '0', height: '22px', display: 'none',
      background: 'rgba(20,24,29,0.85)', color: '#cfd6de', font: '12px sans-serif', zIndex: 5,
    });
    this.bar = document.createElement('i');
    Object.assign(this.bar.style, { position: 'absolute', left: '0', top: '0', bottom: '0', width: '0%', background: '#2c6e9a' });
    this.label = document.createElement('span');
    Object.assign(this.label.style, { position: 'relative', padding: '0 8px', lineHeight: '22px' });
    this.el.append(this.bar, this.label);
    if (getComputedStyle(host).position === 'static') host.style.position = 'relative';
    host.appendChild(this.el);
    this.set('loading');
  }

  set(state, moves) {
    document.body.dataset.run = state;
    if (moves === undefined) delete document.body.dataset.moves;
    else document.body.dataset.moves = String(moves);
    if (state !== 'running') this.el.style.display = 'none';
  }

  // A run streaming in: `lines` is the program's line count (0: unknown), p the worker's
  // {events, bytes, line}.
  update(p, lines) {
    this.el.style.display = 'block';
    const f = lines > 0 ? Math.min(1, p.line / lines) : 0;
    this.bar.style.width = `${(100 * f).toFixed(1)}%`;
    this.el.setAttribute('aria-valuenow', String(Math.round(100 * f)));
    this.label.textContent = `running: ${p.events.toLocaleString('en')} events, ${(p.bytes / 1048576).toFixed(1)} MB${lines > 0 ? `, line ${p.line.toLocaleString('en')} of ${lines.toLocaleString('en')}` : ''}`;
  }
}
