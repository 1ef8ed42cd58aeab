// Browser test of a page written by `swept view`: headless Chromium (software WebGL) opens it,
// waits for the first frame, takes screenshots at the start and at the end of the path, and
// checks that the canvas is not blank and that the body moved (the images differ where the
// body is). Also plays the path for a few seconds and reports the frame rate.
//
//   node tests/viewer/view_screenshots.mjs VIEW.html OUT_DIR [--chromium /usr/bin/chromium]
//        [--size 1200x800] [--play-seconds 3] [--hash obstacles=opaque]
// Writes OUT_DIR/<name>-start.png and OUT_DIR/<name>-end.png; prints one JSON line of figures.
// Exit status 0: all checks passed; 1: a check failed (the reason on stderr); 2: usage/setup.
import { createRequire } from 'node:module';
import { mkdtempSync, mkdirSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { basename, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { inflateSync } from 'node:zlib';

const require = createRequire(new URL('../../viewer/package.json', import.meta.url));

function usage(message) {
  console.error(`view_screenshots: ${message}`);
  process.exit(2);
}

const args = process.argv.slice(2);
const positional = [];
const options = { chromium: '/usr/bin/chromium', size: '1200x800', 'play-seconds': '3', hash: '' };
for (let i = 0; i < args.length; i++) {
  if (args[i].startsWith('--')) {
    const key = args[i].slice(2);
    if (!(key in options) || i + 1 >= args.length) usage(`unknown or incomplete option ${args[i]}`);
    options[key] = args[++i];
  } else positional.push(args[i]);
}
if (positional.length !== 2) usage('expected VIEW.html OUT_DIR');
const [htmlFile, outDir] = positional.map((p) => resolve(p));
const [width, height] = options.size.split('x').map(Number);
if (!(width > 0 && height > 0)) usage(`bad --size ${options.size}`);

/** Decodes an 8-bit, non-interlaced RGB or RGBA PNG (what Chromium writes) to RGBA. */
function decodePng(buffer) {
  if (buffer.readUInt32BE(0) !== 0x89504e47) throw new Error('not a PNG');
  let offset = 8, w = 0, h = 0, channels = 0;
  const idat = [];
  while (offset < buffer.length) {
    const length = buffer.readUInt32BE(offset);
    const type = buffer.toString('latin1', offset + 4, offset + 8);
    const data = buffer.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      w = data.readUInt32BE(0);
      h = data.readUInt32BE(4);
      const depth = data[8], colour = data[9], interlace = data[12];
      if (depth !== 8 || interlace !== 0 || (colour !== 2 && colour !== 6)) throw new Error(`unsupported PNG (depth ${depth}, colour ${colour})`);
      channels = colour === 6 ? 4 : 3;
    } else if (type === 'IDAT') idat.push(data);
    else if (type === 'IEND') break;
    offset += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = w * channels;
  const pixels = Buffer.alloc(w * h * channels);
  for (let y = 0; y < h; y++) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? pixels[y * stride + x - channels] : 0;
      const b = y > 0 ? pixels[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? pixels[(y - 1) * stride + x - channels] : 0;
      let v = line[x];
      if (filter === 1) v += a;
      else if (filter === 2) v += b;
      else if (filter === 3) v += (a + b) >> 1;
      else if (filter === 4) {
        const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        v += pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      } else if (filter !== 0) throw new Error(`bad PNG filter ${filter}`);
      pixels[y * stride + x] = v & 0xff;
    }
  }
  const rgba = Buffer.alloc(w * h * 4);
  for (let i = 0; i < w * h; i++) {
    for (let k = 0; k < 3; k++) rgba[4 * i + k] = pixels[channels * i + k];
    rgba[4 * i + 3] = channels === 4 ? pixels[channels * i + 3] : 255;
  }
  return { width: w, height: h, rgba };
}

function clampBox(box, image) {
  return {
    left: Math.max(0, Math.floor(box.left)), top: Math.max(0, Math.floor(box.top)),
    right: Math.min(image.width, Math.ceil(box.right)), bottom: Math.min(image.height, Math.ceil(box.bottom)),
  };
}

function differs(a, b, i) {
  return Math.abs(a.rgba[i] - b.rgba[i]) + Math.abs(a.rgba[i + 1] - b.rgba[i + 1]) + Math.abs(a.rgba[i + 2] - b.rgba[i + 2]) > 24;
}

/** Fraction of the box's pixels that differ between two images. */
function changedFraction(a, b, box) {
  const r = clampBox(box, a);
  let changed = 0, total = 0;
  for (let y = r.top; y < r.bottom; y++)
    for (let x = r.left; x < r.right; x++, total++) if (differs(a, b, 4 * (y * a.width + x))) changed++;
  return total ? changed / total : 0;
}

/** Fraction of the box's pixels that are not the background colour. */
function coveredFraction(image, box, background) {
  const r = clampBox(box, image);
  let covered = 0, total = 0;
  for (let y = r.top; y < r.bottom; y++)
    for (let x = r.left; x < r.right; x++, total++) {
      const i = 4 * (y * image.width + x);
      if (Math.abs(image.rgba[i] - background[0]) + Math.abs(image.rgba[i + 1] - background[1]) +
          Math.abs(image.rgba[i + 2] - background[2]) > 24) covered++;
    }
  return total ? covered / total : 0;
}

let chromium;
try {
  ({ chromium } = require('playwright-core'));
} catch {
  usage('playwright-core is not installed: run `npm ci` in viewer/');
}
try {
  statSync(options.chromium);
} catch {
  usage(`no Chromium at ${options.chromium}`);
}
mkdirSync(outDir, { recursive: true });
const profile = mkdtempSync(join(tmpdir(), 'swept-view-chromium-'));
const failures = [];
const figures = { file: htmlFile, bytes: statSync(htmlFile).size };
let context;
try {
  // launchPersistentContext is how Playwright takes --user-data-dir (a new, empty profile).
  context = await chromium.launchPersistentContext(profile, {
    executablePath: options.chromium,
    headless: true,
    viewport: { width, height },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = context.pages()[0] ?? await context.newPage();
  const requests = [];
  page.on('request', (r) => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) requests.push(r.url()); });
  const consoleErrors = [];
  page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
  page.on('pageerror', (e) => consoleErrors.push(String(e)));

  const t0 = Date.now();
  await page.goto(`${pathToFileURL(htmlFile).href}#t=0${options.hash ? `&${options.hash}` : ''}`);
  await page.waitForFunction(() => document.documentElement.dataset.sweptReady === '1' ||
    document.documentElement.dataset.sweptError !== undefined, null, { timeout: 120000 });
  figures.first_frame_ms = Date.now() - t0;
  const error = await page.evaluate(() => document.documentElement.dataset.sweptError);
  if (error !== undefined) throw new Error(`the page reported: ${error}`);

  const name = basename(htmlFile).replace(/\.html?$/i, '');
  const shot = async (s, label) => {
    const box = await page.evaluate((t) => { window.sweptView.show(t); return window.sweptView.bodyScreenBox(); }, s);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const file = join(outDir, `${name}-${label}.png`);
    const png = await page.screenshot({ path: file });
    return { box, image: decodePng(png), file };
  };
  const start = await shot(0, 'start');
  const end = await shot(1, 'end');
  figures.screenshots = [start.file, end.file];
  figures.body_box_start = start.box;
  figures.body_box_end = end.box;

  // Not blank: where the body is, most pixels are not the background (#1b1d22).
  const background = [0x1b, 0x1d, 0x22];
  figures.body_covered_start = coveredFraction(start.image, start.box, background);
  figures.body_covered_end = coveredFraction(end.image, end.box, background);
  if (!(figures.body_covered_start > 0.1)) failures.push(`blank canvas where the body is at the start (${figures.body_covered_start})`);
  if (!(figures.body_covered_end > 0.1)) failures.push(`blank canvas where the body is at the end (${figures.body_covered_end})`);
  const whole = { left: 0, top: 0, right: start.image.width, bottom: start.image.height };
  figures.canvas_covered = coveredFraction(start.image, whole, background);
  if (!(figures.canvas_covered > 0.02)) failures.push(`blank canvas (${figures.canvas_covered} of the pixels drawn)`);

  // Moved: the images differ where the body was and where it went.
  const cx = (b) => (b.left + b.right) / 2, cy = (b) => (b.top + b.bottom) / 2;
  figures.body_moved_px = Math.hypot(cx(end.box) - cx(start.box), cy(end.box) - cy(start.box));
  figures.changed_at_start_box = changedFraction(start.image, end.image, start.box);
  figures.changed_at_end_box = changedFraction(start.image, end.image, end.box);
  if (!(figures.body_moved_px > 10)) failures.push(`the body's screen box moved only ${figures.body_moved_px} px`);
  if (!(figures.changed_at_start_box > 0.05)) failures.push(`start and end images barely differ where the body started (${figures.changed_at_start_box})`);
  if (!(figures.changed_at_end_box > 0.05)) failures.push(`start and end images barely differ where the body ended (${figures.changed_at_end_box})`);

  // Frame rate while playing (software WebGL here: a floor, not what a GPU gives).
  const seconds = Number(options['play-seconds']);
  if (seconds > 0) {
    const frames0 = await page.evaluate(() => { window.sweptView.play(0.5); return window.sweptView.frames; });
    const p0 = await page.evaluate(() => window.sweptView.parameter);
    await page.waitForTimeout(seconds * 1000);
    const [frames1, p1] = await page.evaluate(() => [window.sweptView.frames, window.sweptView.parameter]);
    figures.play_fps = (frames1 - frames0) / seconds;
    if (!(p1 > p0)) failures.push(`playing did not advance the parameter (${p0} -> ${p1})`);
  }
  // Orbit: a left drag over the canvas turns the camera about the target.
  await page.evaluate(() => window.sweptView.pause());
  const camera0 = await page.evaluate(() => window.sweptView.cameraPosition());
  await page.mouse.move(width * 0.5, height * 0.4);
  await page.mouse.down();
  await page.mouse.move(width * 0.6, height * 0.45, { steps: 5 });
  await page.mouse.up();
  const camera1 = await page.evaluate(() => window.sweptView.cameraPosition());
  figures.orbit_moved_camera = Math.hypot(...camera1.map((v, i) => v - camera0[i]));
  if (!(figures.orbit_moved_camera > 0)) failures.push('dragging over the canvas did not move the camera');

  if (requests.length) failures.push(`the page made network requests: ${requests.join(', ')}`);
  if (consoleErrors.length) failures.push(`console errors: ${consoleErrors.join(' | ')}`);
} catch (e) {
  failures.push(String(e && e.message ? e.message : e));
} finally {
  if (context) await context.close();
  rmSync(profile, { recursive: true, force: true });
}
console.log(JSON.stringify(figures));
for (const f of failures) console.error(`view_screenshots: FAIL: ${f}`);
process.exit(failures.length ? 1 : 0);
