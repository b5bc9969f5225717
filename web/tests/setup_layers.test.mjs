// Setups in layers in the Setup tab, as `--setup` given more than once: a preset under the
// program's own setup gives the command line's cycle time; a job file after the folder's setup
// adds its [stock]; the order decides; the layers are kept over a reload.
//   NCVM_BIN=build/release/bin/ncvm node --test web/tests/setup_layers.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { start, openExample, runAndWait, tab, repo } from './harness.mjs';

const bin = process.env.NCVM_BIN || path.join(repo, 'build/release/bin/ncvm');
const FACE = 'face-milling-g42/face-milling-g42.nc';

let h, page;
before(async () => {
  h = await start();
  page = h.page;
});
after(() => h?.close());

// The command line's cycle time with these --setup files, to two decimals as the page shows it.
const cliTime = (program, setups) => {
  const args = ['run', `examples/${program}`, ...setups.flatMap((s) => ['--setup', s]), '--state', '-'];
  return JSON.parse(execFileSync(bin, args, { cwd: repo, encoding: 'utf8' })).cycle_time.toFixed(2);
};
const cycleTime = async () => /cycle time ([\d.]+) s/.exec(await page.textContent('#status'))?.[1];
const layers = () => page.getAttribute('#setup-layers', 'data-layers');
async function addLayer(value) {
  await tab(page, 'setup');
  await page.waitForSelector(`#setup-layers option[value="${value}"]`, { state: 'attached' });
  await page.selectOption('#setup-layers .layer-add', value);
}
const rowButton = (index, act) => page.click(`#setup-layers li[data-index="${index}"] button[data-act="${act}"]`);

test('a preset under the program\'s own setup runs as --setup preset --setup job', async () => {
  await openExample(page, FACE);
  await runAndWait(page);
  const own = await cycleTime();
  assert.equal(own, cliTime(FACE, ['examples/face-milling-g42/face-milling-g42.toml']));
  await addLayer('presets|fanuc-0i-mf.toml');
  assert.equal(await layers(), 'presets/fanuc-0i-mf.toml,tab');
  await h.shot('setup-layers');
  await tab(page, 'editor');
  await runAndWait(page);
  const layered = await cycleTime();
  assert.equal(layered, cliTime(FACE, ['presets/fanuc-0i-mf.toml', 'examples/face-milling-g42/face-milling-g42.toml']));
  assert.notEqual(layered, own);
  // Kept over a reload.
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await layers(), 'presets/fanuc-0i-mf.toml,tab');
  // Removed: the program's own setup alone again.
  await tab(page, 'setup');
  await rowButton(0, 'remove');
  assert.equal(await layers(), 'tab');
  await openExample(page, FACE);
  await runAndWait(page);
  assert.equal(await cycleTime(), own);
});

test('a job file after the folder\'s setup adds its stock; before the tab\'s row as well, moved down', async () => {
  const prog = 'lathe-cycles/g71-g70-rough-turning.nc';
  await openExample(page, prog);
  await runAndWait(page);
  assert.equal(await page.getAttribute('#view', 'data-stock'), 'none');
  await addLayer('examples|lathe-cycles/stock-o0402.toml');
  assert.equal(await layers(), 'examples/lathe-cycles/stock-o0402.toml,tab');
  await rowButton(0, 'down'); // --setup setup.toml --setup stock-o0402.toml, as its comment says
  assert.equal(await layers(), 'tab,examples/lathe-cycles/stock-o0402.toml');
  await tab(page, 'editor');
  await runAndWait(page);
  assert.equal(await page.getAttribute('#view', 'data-stock'), 'profile');
  assert.equal(await cycleTime(), cliTime(prog, ['examples/lathe-cycles/setup.toml', 'examples/lathe-cycles/stock-o0402.toml']));
  await tab(page, 'p-messages');
  assert.ok(await page.isVisible('#stock-summary'), 'the stock analysis is shown');
  await h.shot('setup-layers-stock');
  await tab(page, 'setup');
  await rowButton(1, 'remove');
});
