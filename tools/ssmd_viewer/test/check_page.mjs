// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Browser test of ssmd_viewer: loads the page in headless Chromium, selects
// a region, a handle and fixed vertices with the page's own box selection,
// drags the handle, checks the mesh the page shows, measures the updates per
// second while the handle moves, and saves a screenshot.
//
//   node check_page.mjs URL NODE_PACKAGES_DIR SCREENSHOT.png
import { createRequire } from 'node:module';
import path from 'node:path';

const [url, packages, screenshot] = process.argv.slice(2);
const require = createRequire(path.resolve(packages, 'package.json'));
const puppeteer = require('puppeteer-core');

const failures = [];
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures.push(what);
}

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  // WebGL without a GPU: SwiftShader, which Chromium only enables when asked.
  args: ['--no-sandbox', '--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
         '--window-size=1200,800'],
  defaultViewport: { width: 1200, height: 800 },
});
try {
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.ssmdViewer !== undefined, { timeout: 30000 });
  await page.evaluate(() => window.ssmdViewer.meshLoaded);

  // In the default view the armadillo faces the camera: its raised right arm
  // (on the left of the picture) is selected by boxes in normalized device
  // coordinates.
  // The region first with the mouse, as a user would: shift-drag a box (from
  // its lower right corner: the panel covers the upper left one).
  const toPixels = (x, y) => [(x + 1) / 2 * 1200, (1 - y) / 2 * 800];
  await page.keyboard.down('Shift');
  await page.mouse.move(...toPixels(-0.12, 0.0));
  await page.mouse.down();
  await page.mouse.move(...toPixels(-0.4, 0.3), { steps: 5 });
  await page.mouse.move(...toPixels(-0.7, 0.65), { steps: 5 });
  await page.mouse.up();
  await page.keyboard.up('Shift');
  const mouseRegion = await page.evaluate(() => window.ssmdViewer.selected('roi').length);
  const counts = await page.evaluate(() => ({
    roi: window.ssmdViewer.selectBox('roi', -0.7, 0.0, -0.12, 0.65),
    fixed: window.ssmdViewer.selectBox('fixed', -0.2, 0.0, -0.12, 0.65),
    handle: window.ssmdViewer.selectBox('handle', -0.7, 0.25, -0.38, 0.65),
  }));
  check(mouseRegion > 0 && Math.abs(mouseRegion - counts.roi) <= counts.roi / 100,
        `a shift-drag box selects the region (${mouseRegion} vertices)`);
  check(counts.roi > 0 && counts.fixed > 0 && counts.handle > 0,
        `box selection: ${counts.roi} region, ${counts.fixed} fixed, ${counts.handle} handle vertices`);
  const ready = await page.evaluate(() => window.ssmdViewer.prepare());
  check(ready.type === 'ready', `the selection is prepared (${ready.message || ready.region.length + ' region vertices'})`);
  if (ready.type !== 'ready') throw new Error('cannot go on without a region');

  const radius = await page.evaluate(() => window.ssmdViewer.radius());
  const t = [-0.12 * radius, -0.06 * radius, -0.15 * radius];
  const reply = await page.evaluate((t) => window.ssmdViewer.drag(t), t);
  check(reply.type === 'deformed', `the drag is answered (${reply.message || reply.count + ' positions'})`);
  const result = await page.evaluate(() => {
    const v = window.ssmdViewer;
    return { positions: v.positions(), rest: v.restPositions(), handle: v.selected('handle'),
             fixed: v.selected('fixed'), region: v.region() };
  });
  const moved = (i, k) => result.positions[3 * i + k] - result.rest[3 * i + k];
  let handleError = 0, fixedError = 0, outsideMoved = 0;
  for (const i of result.handle) for (let k = 0; k < 3; ++k) handleError = Math.max(handleError, Math.abs(moved(i, k) - t[k]));
  for (const i of result.fixed) for (let k = 0; k < 3; ++k) fixedError = Math.max(fixedError, Math.abs(moved(i, k)));
  const inRegion = new Set(result.region);
  for (let i = 0; i < result.rest.length / 3; ++i)
    if (!inRegion.has(i)) for (let k = 0; k < 3; ++k) if (moved(i, k) !== 0) ++outsideMoved;
  check(handleError < 1e-3 * radius, `the handle vertices moved with the handle (error ${handleError.toExponential(2)})`);
  check(fixedError < 1e-5 * radius, `the fixed vertices stayed (error ${fixedError.toExponential(2)})`);
  check(outsideMoved === 0, 'the vertices outside the region stayed');

  const speed = await page.evaluate((a) => window.ssmdViewer.animateHandle(4, a), 0.2 * radius);
  check(speed.updatesPerSecond > 0, `updates per second while the handle moves: ${speed.updatesPerSecond.toFixed(1)} ` +
        `at ${speed.framesPerSecond.toFixed(1)} frames per second (last drag: deform ${speed.lastDeformMs.toFixed(1)} ms, ` +
        `server ${speed.lastServerMs.toFixed(1)} ms, round trip ${speed.lastRoundTripMs.toFixed(1)} ms)`);
  // The gizmo dragged with the mouse from its center (which moves the handle
  // in the view plane), then the Undo button.
  const handleDistance = () => page.evaluate(() => {
    const v = window.ssmdViewer, p = v.positions(), r = v.restPositions();
    return Math.max(...v.selected('handle').map((i) => Math.hypot(p[3 * i] - r[3 * i], p[3 * i + 1] - r[3 * i + 1], p[3 * i + 2] - r[3 * i + 2])));
  });
  const waitIdle = async () => {
    await new Promise((resolve) => setTimeout(resolve, 200));
    await page.waitForFunction(() => window.ssmdViewer.idle(), { timeout: 60000 });
  };
  await page.evaluate(() => window.ssmdViewer.drag([0, 0, 0]));
  const [gx, gy] = await page.evaluate(() => window.ssmdViewer.gizmoPixel());
  await page.mouse.move(gx, gy);
  await page.mouse.down();
  await page.mouse.move(gx + 40, gy - 60, { steps: 10 });
  await page.mouse.up();
  await waitIdle();
  const dragged = await handleDistance();
  check(dragged > 0.02 * radius, `a mouse drag of the gizmo moves the handle (by ${(dragged / radius).toFixed(3)} radius)`);
  await page.click('#undo');
  await waitIdle();
  const undone = await handleDistance();
  check(undone < 1e-3 * radius, `Undo puts the handle back (${(undone / radius).toExponential(2)} radius from rest)`);

  const replies = await page.evaluate(() => window.ssmdViewer.stats().replies);
  await page.click('#reset');
  await page.waitForFunction((r) => window.ssmdViewer.stats().replies > r, { timeout: 60000 }, replies);
  const resetMoved = await page.evaluate(() => {
    const v = window.ssmdViewer, p = v.positions(), r = v.restPositions();
    return p.filter((x, i) => x !== r[i]).length;
  });
  check(resetMoved === 0, 'the Reset button puts the mesh back at rest');

  await page.evaluate((t) => window.ssmdViewer.drag(t), t);
  await new Promise((resolve) => setTimeout(resolve, 300));
  await page.screenshot({ path: screenshot });
  console.log(`screenshot: ${screenshot}`);
  check(errors.length === 0, `no error in the page${errors.length ? ': ' + errors.join('; ') : ''}`);
} finally {
  await browser.close();
}
console.log(`${failures.length} failure(s)`);
process.exit(failures.length ? 1 : 0);
