// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Measures, in the page of ssmd_viewer loaded in headless Chromium, how long
// the page waits for a prepared selection and how many deformed meshes a
// second it applies while the handle is dragged: selects the armadillo's
// right arm with the page's boxes (as the browser test does), prepares it
// (timed in the page), then moves the handle along a circle for
// `seconds`, `rounds` times in a row, as a pointer would (120 moves a second,
// one drag in flight, the latest position sent when a reply arrives).
// Prints one JSON object.
//
//   node viewer_page_rate.mjs URL NODE_PACKAGES_DIR ROUNDS SECONDS
import { launchChromium } from '../tools/ssmd_viewer/test/headless_chromium.mjs';

const [url, packages, rounds = '5', seconds = '4'] = process.argv.slice(2);
const browser = await launchChromium(packages);
try {
  const page = await browser.newPage();
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.ssmdViewer !== undefined, { timeout: 60000 });
  await page.evaluate(() => window.ssmdViewer.meshLoaded);
  const selection = await page.evaluate(() => {
    const v = window.ssmdViewer;
    return { roi: v.selectBox('roi', -0.7, 0.0, -0.12, 0.65), fixed: v.selectBox('fixed', -0.2, 0.0, -0.12, 0.65),
             handle: v.selectBox('handle', -0.7, 0.25, -0.38, 0.65) };
  });
  // The preparation as the user waits for it: from the page's request to
  // the reply it can drag with, a second after the selection (a user's
  // selection takes longer), when the page has drawn its first frames
  // (software rendering compiles its shaders then).
  await new Promise((resolve) => setTimeout(resolve, 1000));
  const { ready, pageSeconds } = await page.evaluate(async () => {
    const start = performance.now();
    const reply = await window.ssmdViewer.prepare();
    return { ready: reply, pageSeconds: (performance.now() - start) / 1000 };
  });
  if (ready.type !== 'ready') throw new Error(`the selection was not prepared: ${ready.message}`);
  const radius = await page.evaluate(() => window.ssmdViewer.radius());
  const measured = [];
  for (let r = 0; r < Number(rounds); ++r)
    measured.push(await page.evaluate((s, a) => window.ssmdViewer.animateHandle(s, a), Number(seconds), 0.2 * radius));
  const userAgent = await browser.version();
  const antialias = await page.evaluate(() => window.ssmdViewer.antialias());
  console.log(JSON.stringify({ browser: userAgent, antialias, vertices: await page.evaluate(() => window.ssmdViewer.restPositions().length / 3),
                               region: ready.region.length, selection, preprocessSeconds: ready.preprocess_seconds,
                               preparationPageSeconds: pageSeconds, rounds: measured }));
} finally {
  await browser.close();
}
