// An example runs with the setup its folder pairs with it, by the rule of `ncvm list` (and
// `make demo`): face-milling-g42-x150.nc with face-milling-g42.toml (calculator-type input,
// D52): 35.79 s, not the 0.04 s of the default machine. Also with the setup tab emptied or
// the program edited; a setup the user wrote wins.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/setups.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { start, openExample, runAndWait, tab, typeProgram, editorText, repo } from './harness.mjs';

const bin = process.env.NCVM_BIN || path.join(repo, 'build/release/bin/ncvm');
const X150 = 'face-milling-g42/face-milling-g42-x150.nc';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

const status = () => page.textContent('#status');
async function setSetup(text) {
  await tab(page, 'setup');
  await page.fill('#setup-text', text);
  await tab(page, 'editor');
}

test('the page pairs every example with the setup `ncvm list` gives it', async () => {
  const cli = {};
  for (const line of execFileSync(bin, ['list', 'examples'], { cwd: repo, encoding: 'utf8' }).trim().split('\n')) {
    const [program, setup] = line.split('\t');
    cli[program.replace(/^examples\//, '')] = setup === '-' ? null : setup.replace(/^examples\//, '');
  }
  const files = await page.evaluate(async () => (await (await fetch('/api/files')).json()).roots.find((r) => r.name === 'examples').files);
  assert.ok(files.length >= 20, `${files.length} examples`);
  for (const f of files) assert.equal(f.setup ?? null, cli[f.path], f.path);
  assert.equal(cli[X150], 'face-milling-g42/face-milling-g42.toml');
});

test('face-milling-g42-x150 runs with face-milling-g42.toml: as opened, with the tab emptied, edited', async () => {
  await openExample(page, X150);
  assert.match(await status(), /\(setup face-milling-g42\/face-milling-g42\.toml\)/);
  await runAndWait(page);
  assert.match(await status(), /cycle time 35\.79 s/);
  // The setup tab emptied: still the program's own setup (the server's --setup is for
  // programs that have none).
  await setSetup('');
  await runAndWait(page);
  assert.match(await status(), /cycle time 35\.79 s/);
  // The program edited (its text is sent, not its path): the same setup.
  const text = await editorText(page);
  await typeProgram(page, text.replace('(FACE MILL)', '(FACE MILL, EDITED)'));
  await runAndWait(page);
  assert.match(await status(), /cycle time 35\.79 s/);
  await h.shot('setup-rule-x150');
});

test('a setup the user wrote wins: without calculator-type input X-50 is 0.05 mm', async () => {
  await openExample(page, X150);
  await setSetup('[machine]\nkind = "mill"\n');
  await runAndWait(page);
  assert.match(await status(), /cycle time 0\.04 s/);
});
