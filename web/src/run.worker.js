// The run, off the page's thread: POST /api/run.bin, read the binary frames as they stream
// in (wire.js), build the timeline (model.js), and hand it over with its typed arrays
// transferred, not copied. Messages to the page:
//   {type: 'progress', events, bytes, line}   after each batch of events
//   {type: 'done', model}                     model.answer.ok false: the run failed
//   {type: 'coarse', path}                    the path's coarse copy for the frames drawn
//                                             while the camera moves (path_lod.js), once the
//                                             page asks for it with {coarse: true}
//   {type: 'error', status, error}            the request was refused (HTTP error)
import { FrameReader } from './wire.js';
import { ModelBuilder, transferables } from './model.js';
import { coarsePath } from './path_lod.js';

// The copies of the arrays the coarse copy is made from, kept until the page asks for it.
let full = null;

self.onmessage = (e) => (e.data.coarse ? coarse() : run(e.data));

function coarse() {
  if (!full) return;
  const path = coarsePath(full, coarseTolerance(full.bounds));
  full = null;
  self.postMessage({ type: 'coarse', path }, transferables(path));
}

async function run({ url, request, expect }) {
  try {
    const res = await fetch(url, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(request) });
    if (!res.ok) {
      let error = `${res.status} ${res.statusText}`;
      try {
        error = (await res.json()).error || error;
      } catch {
        // not JSON: the status line says it
      }
      self.postMessage({ type: 'error', status: res.status, error });
      return;
    }
    const reader = res.body.getReader();
    const frames = new FrameReader();
    const builder = new ModelBuilder(expect);
    let bytes = 0, last = 0;
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      bytes += value.length;
      for (const f of frames.push(value)) builder.add(f);
      const now = performance.now();
      if (now - last > 100) {
        last = now;
        self.postMessage({ type: 'progress', events: builder.n, bytes, line: builder.maxLine });
      }
    }
    const model = builder.model();
    // The coarse copy is made when the page asks, after its first frame (from copies of the
    // three arrays it needs): made at once, it took a core from that frame on two.
    if (model.answer.ok) full = { vertices: model.vertices.slice(), colors: model.colors.slice(), vertexEvent: model.vertexEvent.slice(), bounds: model.bounds };
    self.postMessage({ type: 'done', model }, transferables(model));
  } catch (err) {
    self.postMessage({ type: 'error', status: 0, error: String(err?.message || err) });
  }
}

// The coarse copy stays within a thousandth of the path's diagonal of the full path: about a
// pixel when the whole part is in view (1600 x 1000).
function coarseTolerance(bounds) {
  if (!bounds) return 0;
  return Math.hypot(...bounds.max.map((v, k) => v - bounds.min[k])) / 1000;
}
