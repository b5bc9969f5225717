#!/usr/bin/env node
// The pictures of README.md and docs/web-viewer.md, taken from a running `ncvm serve` in
// headless Chromium (web/tests/harness.mjs, as the browser tests), at 1400x820:
//   docs/images/viewer.png               the bolt-hole circle macro part way through its holes
//   docs/images/viewer-stock.png         face-milling-g42 part way: the face mill has cut the
//                                        first strips, the label names the snapshot's move
//   docs/images/viewer-stock-lathe.png   convex-arc-turning part way, the profile as cut so far
//   docs/images/viewer-setup-layers.png  the Setup tab: a preset under the program's own setup
// and at 1280x720, the smallest layout:
//   docs/images/viewer-light.png         the light theme, the bolt-hole circle run
// Run after a build (make screenshots, or NCVM_BIN=build/release/bin/ncvm node scripts/...).
import path from 'node:path';
import { start, openExample, runAndWait, tab, repo } from '../web/tests/harness.mjs';

const out = (name) => path.join(repo, 'docs/images', name);
const h = await start({ width: 1400, height: 820 });
const page = h.page;
const scrubTo = (fraction) =>
  page.$eval('#scrub', (el, f) => {
    el.value = String(Math.round(Number(el.max) * f));
    el.dispatchEvent(new Event('input'));
  }, fraction);
try {
  await openExample(page, 'macro-basics/bolt-circle.nc');
  await runAndWait(page);
  await scrubTo(0.5);
  await page.screenshot({ path: out('viewer.png') });

  await openExample(page, 'face-milling-g42/face-milling-g42.nc');
  await runAndWait(page);
  await scrubTo(0.6); // move 8 of 16: two strips faced, two to go
  await page.click('.views button[data-view="iso"]');
  await page.screenshot({ path: out('viewer-stock.png') });

  await openExample(page, 'convex-arc-turning/arc-tnrc-g42.nc');
  await runAndWait(page);
  await scrubTo(0.6);
  await page.screenshot({ path: out('viewer-stock-lathe.png') });

  await openExample(page, 'face-milling-g42/face-milling-g42.nc');
  await tab(page, 'setup');
  await page.waitForSelector('#setup-layers option[value="presets|fanuc-0i-mf.toml"]', { state: 'attached' });
  await page.selectOption('#setup-layers .layer-add', 'presets|fanuc-0i-mf.toml');
  await runAndWait(page);
  await page.screenshot({ path: out('viewer-setup-layers.png') });
} finally {
  await h.close();
}
const small = await start({ width: 1280, height: 720 });
try {
  await openExample(small.page, 'macro-basics/bolt-circle.nc');
  await runAndWait(small.page);
  await small.page.click('#theme');
  await small.page.screenshot({ path: out('viewer-light.png') });
} finally {
  await small.close();
}
console.log('wrote docs/images/viewer.png, viewer-stock.png, viewer-stock-lathe.png, ' +
            'viewer-setup-layers.png, viewer-light.png');
