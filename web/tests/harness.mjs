// Shared set-up of the browser tests: `ncvm serve` on a free port, Debian's Chromium headless
// through playwright-core with a fresh profile, and the helpers the tests share. Screenshots
// go to $NCVM_ARTIFACTS (build/web-artifacts).
import { spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const repo = path.resolve(here, '../..');
const bin = process.env.NCVM_BIN || path.join(repo, 'build/release/bin/ncvm');
const artifacts = process.env.NCVM_ARTIFACTS || path.join(repo, 'build/web-artifacts');
const chromiumPath = process.env.NCVM_CHROMIUM || '/usr/bin/chromium';
mkdirSync(artifacts, { recursive: true });

// Starts the server and the browser; returns {page, url, shot, close}.
export async function start({ width = 1400, height = 820, serveArgs = [] } = {}) {
  const server = spawn(bin, ['serve', '--port', '0', ...serveArgs], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
      out += d;
      const m = /http:\/\/\S+\//.exec(out);
      if (m) resolve(m[0]);
    });
    server.on('exit', (code) => reject(new Error(`ncvm serve exited (${code})`)));
    setTimeout(() => reject(new Error('ncvm serve did not start')), 15000);
  });
  const profile = mkdtempSync(path.join(tmpdir(), 'ncvm-chromium-'));
  const browser = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath,
    viewport: { width, height },
    headless: true,
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    ],
  });
  const page = browser.pages()[0] || (await browser.newPage());
  page.on('pageerror', (e) => console.error('page error:', e.message));
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]');
  return {
    page,
    url,
    shot: (name) => page.screenshot({ path: path.join(artifacts, `${name}.png`) }),
    async close() {
      await browser.close();
      server.kill('SIGTERM');
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

export const tab = (page, name) => page.click(`.tabs button[data-tab="${name}"]`);

export async function openExample(page, file) {
  await page.selectOption('#files', `examples|${file}`);
  await page.waitForFunction((f) => document.getElementById('status').textContent.startsWith(f), file);
}

export async function runAndWait(page) {
  await page.click('#run');
  await page.waitForFunction(() => /ended|alarm|error/.test(document.getElementById('status').textContent));
}

// Replaces the editor's text as a user would: select all, then type (insert) the new text.
export async function typeProgram(page, text) {
  await page.click('#editor .cm-content');
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(text);
}

// The editor's state through its element (web/src/editor.js sets host.editor).
export const editorText = (page) => page.evaluate(() => document.getElementById('editor').editor.text);
export const cursorLine = (page) => page.evaluate(() => document.getElementById('editor').editor.cursorLine);

// Pixels of the 3D canvas for which `test(r, g, b)` holds.
export const countPixels = (page, test) =>
  page.evaluate((src) => {
    const f = new Function('r', 'g', 'b', `return ${src};`);
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (f(d[i], d[i + 1], d[i + 2])) n++;
    return n;
  }, test);
