// The run, off the page's thread: POST /api/run.bin, read the binary frames as they stream
// in (wire.js), build the timeline (model.js), and hand it over with its typed arrays
// transferred, not copied. Messages to the page:
//   {type: 'progress', events, bytes, line}   after each batch of events
//   {type: 'done', model}                     model.answer.ok false: the run failed
//   {type: 'error', status, error}            the request was refused (HTTP error)
import { FrameReader } from './wire.js';
import { ModelBuilder, transferables } from './model.js';

self.onmessage = async (e) => {
  const { url, request, expect } = e.data;
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
    self.postMessage({ type: 'done', model }, transferables(model));
  } catch (err) {
    self.postMessage({ type: 'error', status: 0, error: String(err?.message || err) });
  }
};
