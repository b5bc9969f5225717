// Local files in the browser: the Open button, drag-and-drop, the edits kept over a reload,
// and the recent files.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/files.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { start, openExample, runAndWait, editorText } from './harness.mjs';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

const LOCAL = 'O0042 (LOCAL FILE)\nG90 G00 X0 Y0 Z5.\nG01 Z-1. F200.\nX40.\nY20.\nM30\n';

test('the Open button reads a local file into the editor, and it runs under its own name', async () => {
  await page.setInputFiles('#file-input', { name: 'local-part.nc', mimeType: 'text/plain', buffer: Buffer.from(LOCAL) });
  await page.waitForFunction(() => document.getElementById('status').textContent.startsWith('local-part.nc'));
  assert.equal(await editorText(page), LOCAL);
  await runAndWait(page);
  assert.match(await page.textContent('#status'), /ended M30/);
  assert.match(await page.textContent('#stepinfo'), /local-part\.nc:5/);
  await h.shot('files-open');
});

test('a file dropped on the page is opened', async () => {
  await page.evaluate(() => {
    const dt = new DataTransfer();
    dt.items.add(new File(['O0077 (DROPPED)\nG00 X1.\nM30\n'], 'dropped.nc', { type: 'text/plain' }));
    const target = document.querySelector('#editor .cm-content');
    target.dispatchEvent(new DragEvent('dragover', { dataTransfer: dt, bubbles: true, cancelable: true }));
    target.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => document.getElementById('status').textContent.startsWith('dropped.nc'));
  assert.match(await editorText(page), /^O0077 \(DROPPED\)/);
});

test('edits survive a reload, and the recent files open again', async () => {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await page.click('#editor .cm-line >> nth=1');
  await page.keyboard.press('End');
  await page.keyboard.type(' (EDITED BEFORE RELOAD)');
  // The draft is written a moment after the last change; a reload also keeps it.
  await page.waitForTimeout(900);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  await page.waitForFunction(() => /EDITED BEFORE RELOAD/.test(document.getElementById('editor').editor.text));
  assert.match(await editorText(page), /^%\nO0100.*\(EDITED BEFORE RELOAD\)\n/);
  assert.match(await page.textContent('#status'), /your edits/);
  // Still the example's program: it runs in its folder, under its name.
  assert.equal(await page.inputValue('#files'), 'examples|macro-basics/bolt-circle.nc');
  await runAndWait(page);
  assert.match(await page.textContent('#status'), /ended M30/);

  const recent = await page.locator('#recent option').allTextContents();
  assert.deepEqual(recent.slice(1, 4), ['examples: macro-basics/bolt-circle.nc', 'dropped.nc (local)', 'local-part.nc (local)']);
  await page.selectOption('#recent', { label: 'local-part.nc (local)' });
  await page.waitForFunction(() => document.getElementById('status').textContent.startsWith('local-part.nc'));
  assert.equal(await editorText(page), LOCAL);
  await h.shot('files-recent');
});
