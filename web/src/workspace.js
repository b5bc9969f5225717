// The page's files: a local program opened with the Open button or dropped on the page, the
// text being edited kept in IndexedDB so that a reload brings it back, and the recent files
// (server examples and local files, the local ones' text kept too).
const DB = 'ncvm', STORE = 'kv', RECENT = 'ncvm.recent', MAX_RECENT = 8;
const SAVE_DELAY_MS = 600;
// A local file is read into the editor up to this size; the server's own limit for a run is
// its --max-request option (docs/web-viewer.md).
export const MAX_LOCAL_BYTES = 256 * 1024 * 1024;

let dbPromise = null;
function db() {
  if (!dbPromise)
    dbPromise = new Promise((resolve, reject) => {
      const req = indexedDB.open(DB, 1);
      req.onupgradeneeded = () => req.result.createObjectStore(STORE);
      req.onsuccess = () => resolve(req.result);
      req.onerror = () => reject(req.error);
    });
  return dbPromise;
}

async function idb(mode, fn) {
  const d = await db();
  return new Promise((resolve, reject) => {
    const tx = d.transaction(STORE, mode);
    const req = fn(tx.objectStore(STORE));
    tx.oncomplete = () => resolve(req?.result);
    tx.onerror = () => reject(tx.error);
  });
}
export const kvGet = (key) => idb('readonly', (s) => s.get(key));
export const kvPut = (key, value) => idb('readwrite', (s) => s.put(value, key));
const kvDelete = (key) => idb('readwrite', (s) => s.delete(key));

// A source: {kind: 'server', root, path, name} or {kind: 'local', name} or {kind: 'new', name}.
const sameSource = (a, b) => a && b && a.kind === b.kind && a.name === b.name && a.root === b.root && a.path === b.path;
const label = (s) => (s.kind === 'server' ? `${s.root}: ${s.path}` : `${s.name} (local)`);

export class Workspace {
  // hooks: {editor, setupText (textarea), openServer(root, path), openLocal(name, text), source()}
  constructor(hooks) {
    this.h = hooks;
    this.timer = 0;
    this.edited = false;
    this.recentSelect = document.getElementById('recent');
    this.renderRecent();
    const input = document.getElementById('file-input');
    document.getElementById('open-file').addEventListener('click', () => input.click());
    input.addEventListener('change', () => {
      if (input.files[0]) this.openLocalFile(input.files[0]);
      input.value = '';
    });
    document.addEventListener('dragover', (e) => {
      if (![...(e.dataTransfer?.types || [])].includes('Files')) return;
      e.preventDefault();
      document.body.classList.add('dropping');
    });
    document.addEventListener('dragleave', (e) => {
      if (!e.relatedTarget) document.body.classList.remove('dropping');
    });
    document.addEventListener('drop', (e) => {
      document.body.classList.remove('dropping');
      const f = e.dataTransfer?.files?.[0];
      if (!f) return;
      e.preventDefault();
      this.openLocalFile(f);
    });
    this.recentSelect.addEventListener('change', () => {
      const k = Number(this.recentSelect.value);
      this.recentSelect.value = '';
      const s = this.recent()[k];
      if (s) this.openRecent(s);
    });
    document.getElementById('setup-text').addEventListener('input', () => this.changed());
    // Leaving the page within the save delay: keep the edits now.
    addEventListener('pagehide', () => this.edited && this.save());
  }

  async openLocalFile(file) {
    if (file.size > MAX_LOCAL_BYTES)
      return this.h.status(`${file.name} is ${(file.size / 1048576).toFixed(0)} MB: the page opens files up to ${MAX_LOCAL_BYTES / 1048576} MB`, 'bad');
    const text = await file.text();
    await kvPut(`local:${file.name}`, text).catch(() => {});
    this.h.openLocal(file.name, text);
  }

  async openRecent(s) {
    if (s.kind === 'server') return this.h.openServer(s.root, s.path);
    const text = await kvGet(`local:${s.name}`).catch(() => undefined);
    if (typeof text !== 'string') return this.h.status(`${s.name} is no longer stored in this browser: open it again`, 'bad');
    this.h.openLocal(s.name, text);
  }

  // A program was opened (not yet edited): the draft is that source, the recent list gets it.
  opened(source) {
    this.edited = false;
    clearTimeout(this.timer);
    kvPut('draft', { source, text: null, setup: null, time: Date.now() }).catch(() => {});
    if (source.kind === 'new') return;
    const list = [source, ...this.recent().filter((s) => !sameSource(s, source))];
    for (const dropped of list.splice(MAX_RECENT)) if (dropped.kind === 'local') kvDelete(`local:${dropped.name}`).catch(() => {});
    localStorage.setItem(RECENT, JSON.stringify(list));
    this.renderRecent();
  }

  recent() {
    try {
      return JSON.parse(localStorage.getItem(RECENT) || '[]');
    } catch {
      return [];
    }
  }

  renderRecent() {
    const list = this.recent();
    this.recentSelect.innerHTML = '<option value="">Recent…</option>' +
      list.map((s, k) => `<option value="${k}">${label(s).replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`)}</option>`).join('');
    this.recentSelect.disabled = !list.length;
  }

  // The text or the setup changed: saved a moment after the last change (a million-line
  // text is not copied on every keystroke).
  changed() {
    this.edited = true;
    clearTimeout(this.timer);
    // A longer pause before copying a long text (a million lines: about 2.5 s), and then only
    // when the page is idle, so that a save does not land on a keystroke.
    const delay = SAVE_DELAY_MS + this.h.editor.lineCount / 500;
    this.timer = setTimeout(() => {
      this.timer = 0;
      if (window.requestIdleCallback) requestIdleCallback(() => this.save(), { timeout: 2000 });
      else this.save();
    }, delay);
  }

  save() {
    clearTimeout(this.timer);
    this.timer = 0;
    const draft = { source: this.h.source(), text: this.h.editor.text, setup: this.h.setupText.value, time: Date.now() };
    return kvPut('draft', draft).catch((e) => this.h.status(`the edits could not be kept in this browser: ${e}`, 'warn'));
  }

  // The draft of the last visit: {source, text (null when unedited), setup, time} or null.
  async draft() {
    return (await kvGet('draft').catch(() => null)) || null;
  }
}
