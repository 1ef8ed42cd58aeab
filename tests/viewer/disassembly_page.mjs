// Browser test of a page written by `swept disassemble --view`: headless Chromium (software
// WebGL) opens it, shows the end of the sequence, and reports the blocking graph the page drew
// (window.sweptView.blocking), whether its arrows are shown, the panel's text and how many
// pixels are the arrows' red; then the start, where the arrows must be hidden when something
// comes out first. Prints one JSON line; exit 0 when the checks pass, 1 when one fails (the
// reason on stderr), 2 on usage or setup errors.
//
//   node tests/viewer/disassembly_page.mjs VIEW.html OUT_DIR [--chromium /usr/bin/chromium]
import { createRequire } from 'node:module';
import { mkdirSync, mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const require = createRequire(new URL('../../viewer/package.json', import.meta.url));
const args = process.argv.slice(2);
let chromiumPath = '/usr/bin/chromium';
const positional = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--chromium' && i + 1 < args.length) chromiumPath = args[++i];
  else positional.push(args[i]);
}
if (positional.length !== 2) {
  console.error('disassembly_page: expected VIEW.html OUT_DIR');
  process.exit(2);
}
const [htmlFile, outDir] = positional.map((p) => resolve(p));
let chromium;
try {
  ({ chromium } = require('playwright-core'));
  statSync(chromiumPath);
} catch (e) {
  console.error(`disassembly_page: ${e.message}`);
  process.exit(2);
}
mkdirSync(outDir, { recursive: true });
const profile = mkdtempSync(join(tmpdir(), 'swept-disassembly-chromium-'));
const failures = [];
const figures = {};
let context;
try {
  context = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath, headless: true, viewport: { width: 1000, height: 700 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = context.pages()[0] ?? await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(pathToFileURL(htmlFile).href);
  await page.waitForFunction(() => document.documentElement.dataset.sweptReady === '1' ||
    document.documentElement.dataset.sweptError !== undefined, null, { timeout: 120000 });
  const error = await page.evaluate(() => document.documentElement.dataset.sweptError);
  if (error !== undefined) throw new Error(`the page reported: ${error}`);

  // The arrows' red (0xff3030, lit only by itself: a basic material) against everything else.
  const redPixels = async (file) => {
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const data = await page.evaluate(() => {
      const c = document.getElementById('swept-canvas');
      const gl = c.getContext('webgl2') ?? c.getContext('webgl');
      const px = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
      gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, px);
      let red = 0;
      for (let i = 0; i < px.length; i += 4) if (px[i] > 200 && px[i + 1] < 90 && px[i + 2] < 90) red++;
      return red;
    });
    await page.screenshot({ path: file });
    return data;
  };
  const steps = await page.evaluate(() => window.sweptView.steps);
  await page.evaluate((s) => window.sweptView.show(s), steps);
  figures.steps = steps;
  figures.blocking = await page.evaluate(() => window.sweptView.blocking);
  figures.arrows_visible_at_end = await page.evaluate(() => window.sweptView.arrowsVisible);
  figures.info_at_end = await page.evaluate(() => window.sweptView.info);
  figures.red_pixels_at_end = await redPixels(join(outDir, 'disassembly-end.png'));
  if (figures.blocking.length > 0) {
    if (!figures.arrows_visible_at_end) failures.push('the blocking arrows are hidden at the end');
    if (!(figures.red_pixels_at_end > 50)) failures.push(`no arrows drawn at the end (${figures.red_pixels_at_end} red pixels)`);
    for (const b of figures.blocking)
      if (!figures.info_at_end.includes(`${b.parts.join(' + ')} blocked:`)) failures.push(`the panel does not name ${b.parts}`);
  }
  if (steps > 0) {
    await page.evaluate(() => window.sweptView.show(0));
    figures.arrows_visible_at_start = await page.evaluate(() => window.sweptView.arrowsVisible);
    figures.red_pixels_at_start = await redPixels(join(outDir, 'disassembly-start.png'));
    if (figures.arrows_visible_at_start) failures.push('the blocking arrows show before the removals are done');
  }
  if (errors.length) failures.push(`page errors: ${errors.join(' | ')}`);
} catch (e) {
  failures.push(String(e?.message ?? e));
} finally {
  await context?.close();
  rmSync(profile, { recursive: true, force: true });
}
console.log(JSON.stringify(figures));
for (const f of failures) console.error(`disassembly_page: ${f}`);
process.exit(failures.length ? 1 : 0);
