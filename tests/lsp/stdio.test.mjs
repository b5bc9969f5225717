// Drives `ncvm lsp` over stdio with the LSP client library VS Code's client is built on
// (vscode-languageserver-protocol, tests/lsp/package-lock.json): the life cycle, diagnostics
// after open and after a change, hover, go to definition into a --lib folder, document
// symbols and completion. NCVM_BIN names the binary (ctest sets it).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import lsp from 'vscode-languageserver-protocol/node.js';

const bin = process.env.NCVM_BIN;
assert.ok(bin, 'NCVM_BIN must name the ncvm binary');

test('ncvm lsp answers a real LSP client over stdio', { timeout: 60000 }, async (t) => {
  const dir = mkdtempSync(join(tmpdir(), 'ncvm-lsp-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  mkdirSync(join(dir, 'lib'));
  writeFileSync(join(dir, 'lib', 'O9010.nc'), '%\nO9010 (DRILL MACRO)\nG91 G01 Z-#26 F#9\nM99\n%\n');
  const mainPath = join(dir, 'main.nc');
  const uri = pathToFileURL(mainPath).href;
  const text = [
    '%',
    'O0100 (MAIN)',
    'N10 G90 G54 G00 X10 Y0.',
    'G65 P9010 Z5. F100.',
    '#1 = #5021',
    'IF [#1 GT 5.] GOTO 20',
    'G01 X5. F0',
    'N20 M30',
    '%',
    '',
  ].join('\n');

  const server = spawn(bin, ['lsp', '--no-macros', '--lib', join(dir, 'lib')], {
    stdio: ['pipe', 'pipe', 'inherit'],
  });
  const exited = new Promise((resolve) => server.on('exit', (code) => resolve(code)));
  const connection = lsp.createProtocolConnection(
    new lsp.StreamMessageReader(server.stdout),
    new lsp.StreamMessageWriter(server.stdin),
  );
  const published = [];
  let wake = () => {};
  connection.onNotification(lsp.PublishDiagnosticsNotification.type, (params) => {
    published.push(params);
    wake();
  });
  const nextDiagnostics = async (version) => {
    const deadline = Date.now() + 20000;
    for (;;) {
      const found = published.find((p) => p.uri === uri && p.version === version);
      if (found) return found.diagnostics;
      assert.ok(Date.now() < deadline, `no diagnostics for version ${version}`);
      await new Promise((resolve) => {
        wake = resolve;
        setTimeout(resolve, 500);
      });
    }
  };
  connection.listen();

  const init = await connection.sendRequest(lsp.InitializeRequest.type, {
    processId: process.pid,
    rootUri: pathToFileURL(dir).href,
    capabilities: {},
  });
  assert.equal(init.serverInfo.name, 'ncvm');
  assert.equal(init.capabilities.textDocumentSync.change, lsp.TextDocumentSyncKind.Full);
  await connection.sendNotification(lsp.InitializedNotification.type, {});
  await connection.sendNotification(lsp.DidOpenTextDocumentNotification.type, {
    textDocument: { uri, languageId: 'fanuc', version: 1, text },
  });

  // check's W001 on X10 (line 2) and the dry run's PS0011 (feed zero) on line 6.
  const first = await nextDiagnostics(1);
  const byCode = Object.fromEntries(first.map((d) => [d.code, d]));
  assert.deepEqual(Object.keys(byCode).sort(), ['PS0011', 'W001'], JSON.stringify(first));
  assert.equal(byCode.W001.severity, lsp.DiagnosticSeverity.Warning);
  assert.deepEqual(byCode.W001.range, {
    start: { line: 2, character: 16 },
    end: { line: 2, character: 19 },
  });
  assert.equal(byCode.PS0011.severity, lsp.DiagnosticSeverity.Error);
  assert.equal(byCode.PS0011.range.start.line, 6);

  const hover = await connection.sendRequest(lsp.HoverRequest.type, {
    textDocument: { uri },
    position: { line: 4, character: 7 },
  });
  assert.match(hover.contents.value, /^#5021: current position \(machine coordinates\) of axis 1 \(X\)/);
  const gHover = await connection.sendRequest(lsp.HoverRequest.type, {
    textDocument: { uri },
    position: { line: 3, character: 1 },
  });
  assert.match(gHover.contents.value, /^G65: /);
  const callHover = await connection.sendRequest(lsp.HoverRequest.type, {
    textDocument: { uri },
    position: { line: 3, character: 6 },
  });
  assert.match(callHover.contents.value, /^P9010: program number to call/);
  assert.ok(
    callHover.contents.value.endsWith(`→ ${join(dir, 'lib', 'O9010.nc')}:2`),
    callHover.contents.value,
  );

  const def = await connection.sendRequest(lsp.DefinitionRequest.type, {
    textDocument: { uri },
    position: { line: 3, character: 6 },
  });
  assert.equal(def.uri, pathToFileURL(join(dir, 'lib', 'O9010.nc')).href);
  assert.equal(def.range.start.line, 1);
  const label = await connection.sendRequest(lsp.DefinitionRequest.type, {
    textDocument: { uri },
    position: { line: 5, character: 20 },
  });
  assert.equal(label.uri, uri);
  assert.deepEqual(label.range.start, { line: 7, character: 0 });

  const symbols = await connection.sendRequest(lsp.DocumentSymbolRequest.type, {
    textDocument: { uri },
  });
  assert.equal(symbols.length, 1);
  assert.equal(symbols[0].name, 'O0100');
  assert.deepEqual(symbols[0].children.map((s) => s.name), ['N10', 'N20']);

  const completion = await connection.sendRequest(lsp.CompletionRequest.type, {
    textDocument: { uri },
    position: { line: 4, character: 8 },
  });
  const labels = completion.items.map((i) => i.label);
  assert.ok(labels.includes('#5021') && labels.includes('#3001'), labels.join(' '));

  // A change (debounced): the fixed program has only the decimal-point warning left.
  await connection.sendNotification(lsp.DidChangeTextDocumentNotification.type, {
    textDocument: { uri, version: 2 },
    contentChanges: [{ text: text.replace('F0', 'F200.') }],
  });
  const second = await nextDiagnostics(2);
  assert.deepEqual(second.map((d) => d.code), ['W001']);

  await connection.sendRequest(lsp.ShutdownRequest.type);
  await connection.sendNotification(lsp.ExitNotification.type);
  assert.equal(await exited, 0);
  connection.dispose();
});

test('ncvm lsp with a setup it cannot read stops before the editor connects', async () => {
  const server = spawn(bin, ['lsp', '--setup', '/nonexistent/ncvm-setup.toml'], {
    stdio: ['pipe', 'pipe', 'pipe'],
  });
  let stderr = '';
  server.stderr.on('data', (d) => (stderr += d));
  const code = await new Promise((resolve) => server.on('exit', resolve));
  assert.equal(code, 2);
  assert.match(stderr, /ncvm-setup\.toml/);
});

test('ncvm lsp refuses a --lib folder that is not there', async () => {
  const server = spawn(bin, ['lsp', '--lib', '/nonexistent/ncvm-lib'], {
    stdio: ['pipe', 'pipe', 'pipe'],
  });
  let stderr = '';
  server.stderr.on('data', (d) => (stderr += d));
  const code = await new Promise((resolve) => server.on('exit', resolve));
  assert.equal(code, 2);
  assert.match(stderr, /--lib \/nonexistent\/ncvm-lib: not a folder/);
});

test('ncvm lsp ends when its input closes, and answers a frame that is not JSON', async () => {
  const server = spawn(bin, ['lsp', '--no-macros'], { stdio: ['pipe', 'pipe', 'inherit'] });
  let out = '';
  server.stdout.on('data', (d) => (out += d));
  const body = '{not json';
  server.stdin.end(`Content-Length: ${body.length}\r\n\r\n${body}`);
  const code = await new Promise((resolve) => server.on('exit', resolve));
  assert.equal(code, 1); // no shutdown before the end: 1, as LSP says for exit
  assert.match(out, /"code":-32700/);
});
