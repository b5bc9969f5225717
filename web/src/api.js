// The server's JSON API (src/server/web_server.cpp).
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
export const file = (root, path) => call(`api/file?root=${encodeURIComponent(root)}&path=${encodeURIComponent(path)}`);
export const run = (req) =>
  call('api/run', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(req) });
