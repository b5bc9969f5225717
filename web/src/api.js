// The server's API (src/server/web_server.cpp): JSON for the lists and files, and the run as
// a binary stream read and turned into a timeline by a Web Worker (run.worker.js).
import { withViews } from './model.js';

async function call(url, options) {
  const res = await fetch(url, options);
  let body;
  try {
    body = await res.json();
  } catch {
    body = { ok: false, error: `${res.status} ${res.statusText}` };
  }
  if (!res.ok && body.ok === undefined) body.ok = false;
  return body;
}

export const info = () => call('api/info');
export const files = () => call('api/files');
export const setups = () => call('api/setups');
export const file = (root, path) => call(`api/file?root=${encodeURIComponent(root)}&path=${encodeURIComponent(path)}`);

// Runs `req` ({program, name, setup, root, dir} or, for a file of the server's folders
// unchanged, {root, path, setup}); onProgress({events, bytes, line}) while it streams;
// expect: the events to make room for at once (the program's line count).
// Resolves to {ok: true, model} or {ok: false, error}. One worker per run: a new run
// cancels the last one.
let current = null;
export function run(req, onProgress = () => {}, expect = 0) {
  current?.terminate();
  const worker = new Worker(new URL('./run.worker.js', import.meta.url), { type: 'module' });
  current = worker;
  return new Promise((resolve) => {
    const stop = () => {
      worker.terminate();
      if (current === worker) current = null;
    };
    const end = (v) => {
      stop();
      resolve(v);
    };
    // After the model, the worker makes the path's coarse copy when asked (run.worker.js):
    // model.coarse() asks and resolves to it (never when a new run stops the worker first).
    let coarse = null;
    worker.onmessage = (e) => {
      const d = e.data;
      if (d.type === 'progress') onProgress(d);
      else if (d.type === 'error') end({ ok: false, error: d.error, status: d.status });
      else if (d.type === 'done' && !d.model.answer.ok) end({ ok: false, error: d.model.answer.error });
      else if (d.type === 'done') {
        const model = withViews(d.model);
        const made = new Promise((r) => (coarse = r));
        model.coarse = () => {
          worker.postMessage({ coarse: true });
          return made;
        };
        resolve({ ok: true, model });
      } else if (d.type === 'coarse') {
        stop();
        coarse(d.path);
      }
    };
    worker.onerror = (e) => end({ ok: false, error: `the run worker failed: ${e.message}` });
    worker.postMessage({ url: new URL('api/run.bin', location.href).href, request: req, expect });
  });
}
