// The binary run answer of POST /api/run.bin (src/server/viewer_stream.hpp): a stream of
// frames, each `u32 kind, u32 length, payload, zero bytes to a multiple of 8`. FrameReader
// cuts the stream into frames as its chunks arrive; decodeBatch turns an events payload
// into typed arrays (views on a copy of the payload, aligned as the server wrote them).
export const FRAME = { hello: 0, events: 1, steps: 2, notes: 3, end: 4, origins: 5 };
export const KIND = { rapid: 0, linear: 1, cw: 2, ccw: 3, dwell: 8, message: 9, alarm: 10, tool: 11, spindle: 12, coolant: 13, aux: 14, offset: 15, skip: 16 };
export const FLAG = { thread: 1, compensated: 2, probe: 4, ownStart: 8, ownPositions: 16, arc: 32 };
export const KIND_NAMES = { 0: 'move', 1: 'move', 2: 'move', 3: 'move', 8: 'dwell', 9: 'message', 10: 'alarm', 11: 'tool', 12: 'spindle', 13: 'coolant', 14: 'aux', 15: 'offset', 16: 'skip' };
export const MODE_NAMES = ['rapid', 'linear', 'cw', 'ccw'];

const text = new TextDecoder();

export class FrameReader {
  constructor() {
    this.buf = new Uint8Array(1 << 16);
    this.len = 0;
  }

  // Appends a chunk; returns the frames it completed: [{kind, payload: Uint8Array}].
  push(chunk) {
    if (this.len + chunk.length > this.buf.length) {
      let cap = this.buf.length;
      while (cap < this.len + chunk.length) cap *= 2;
      const b = new Uint8Array(cap);
      b.set(this.buf.subarray(0, this.len));
      this.buf = b;
    }
    this.buf.set(chunk, this.len);
    this.len += chunk.length;
    const frames = [];
    let at = 0;
    const dv = new DataView(this.buf.buffer);
    while (this.len - at >= 8) {
      const kind = dv.getUint32(at, true), length = dv.getUint32(at + 4, true);
      const whole = 8 + length + ((8 - (length % 8)) % 8);
      if (this.len - at < whole) break;
      frames.push({ kind, payload: this.buf.slice(at + 8, at + 8 + length) });
      at += whole;
    }
    if (at) {
      this.buf.copyWithin(0, at, this.len);
      this.len -= at;
    }
    return frames;
  }

  // Bytes of a frame not yet complete.
  get pending() {
    return this.len;
  }
}

export const json = (payload) => JSON.parse(text.decode(payload));
export const lines = (payload) => text.decode(payload).split('\n').filter((l) => l);

// An events payload as columns (see viewer_stream.hpp for the order).
export function decodeBatch(payload) {
  const b = payload.buffer, base = payload.byteOffset;
  const head = new Uint32Array(b, base, 8);
  const [n, m, nStart, nPos, nArc, nPath, axes] = head;
  let at = base + 32;
  const take = (Type, count) => {
    const a = new Type(b, at, count);
    at += count * Type.BYTES_PER_ELEMENT;
    return a;
  };
  return {
    n, m, axes,
    time: take(Float64Array, n),
    pos: take(Float64Array, nPos * 3 * axes),
    start: take(Float64Array, nStart * axes),
    end: take(Float64Array, m * axes),
    mend: take(Float64Array, m * axes),
    center: take(Float64Array, nArc * 3),
    path: take(Float64Array, nPath * axes),
    dt: take(Float64Array, n),
    feed: take(Float32Array, m),
    line: take(Uint32Array, n),
    block: take(Uint32Array, n),
    nnum: take(Int32Array, n),
    file: take(Uint16Array, n),
    pathCount: take(Uint16Array, m),
    kind: take(Uint8Array, n),
    flags: take(Uint8Array, n),
    plane: take(Uint8Array, nArc),
  };
}
