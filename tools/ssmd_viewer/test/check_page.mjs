// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Browser test of ssmd_viewer: loads the page in headless Chromium, checks
// the selection tools (the box on the visible side or through the mesh, the
// brush, the selection's undo) against visibility computed here by ray
// casting, selects a region, a handle and fixed vertices with the page's own
// box selection, drags the handle, checks the mesh the page shows, refines
// it with the Refine button (and stops a refinement with a drag), measures
// the updates per second while the handle moves, and saves a screenshot.
//
//   node check_page.mjs URL NODE_PACKAGES_DIR SCREENSHOT.png
import { launchChromium, VIEWPORT } from './headless_chromium.mjs';

const [url, packages, screenshot] = process.argv.slice(2);

const failures = [];
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures.push(what);
}

const browser = await launchChromium(packages);
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
  const toPixels = (x, y) => [(x + 1) / 2 * VIEWPORT.width, (1 - y) / 2 * VIEWPORT.height];
  const flags = () => page.evaluate(() => ['roi', 'fixed', 'handle'].map((m) => window.ssmdViewer.selected(m)));
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  const undoSteps = () => page.evaluate(() => window.ssmdViewer.selectionUndoSteps());
  const radius = await page.evaluate(() => window.ssmdViewer.radius());
  const defaults = await page.evaluate(() => ({ visibleOnly: document.querySelector('#visible-only').checked,
                                                 tool: document.querySelector('input[name=tool]:checked').value }));
  check(defaults.visibleOnly && defaults.tool === 'box', 'by default the box is chosen and takes the visible side only');

  // Visibility computed here, independently of the page's depth buffer: a
  // vertex is hidden when the segment from the camera to it crosses a
  // triangle more than `margin` before it (Moeller-Trumbore on every face).
  const model = await page.evaluate(() => {
    const v = window.ssmdViewer;
    return { positions: v.positions(), faces: v.faces(), normals: v.normals(), camera: v.camera() };
  });
  const P = Float64Array.from(model.positions), F = Uint32Array.from(model.faces), C = model.camera.position;
  const occluded = (i, margin) => {
    const d = [P[3 * i] - C[0], P[3 * i + 1] - C[1], P[3 * i + 2] - C[2]];
    const length = Math.hypot(...d);
    d[0] /= length; d[1] /= length; d[2] /= length;
    for (let f = 0; f < F.length; f += 3) {
      const a = 3 * F[f], b = 3 * F[f + 1], c = 3 * F[f + 2];
      const e1x = P[b] - P[a], e1y = P[b + 1] - P[a + 1], e1z = P[b + 2] - P[a + 2];
      const e2x = P[c] - P[a], e2y = P[c + 1] - P[a + 1], e2z = P[c + 2] - P[a + 2];
      const px = d[1] * e2z - d[2] * e2y, py = d[2] * e2x - d[0] * e2z, pz = d[0] * e2y - d[1] * e2x;
      const det = e1x * px + e1y * py + e1z * pz;
      if (Math.abs(det) < 1e-12) continue;
      const sx = C[0] - P[a], sy = C[1] - P[a + 1], sz = C[2] - P[a + 2];
      const u = (sx * px + sy * py + sz * pz) / det;
      if (u < 0 || u > 1) continue;
      const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
      const w = (d[0] * qx + d[1] * qy + d[2] * qz) / det;
      if (w < 0 || u + w > 1) continue;
      const t = (e2x * qx + e2y * qy + e2z * qz) / det;
      if (t > 0 && t < length - margin) return true;
    }
    return false;
  };
  const facing = (i) => {
    const N = model.normals;
    return N[3 * i] * (C[0] - P[3 * i]) + N[3 * i + 1] * (C[1] - P[3 * i + 1]) + N[3 * i + 2] * (C[2] - P[3 * i + 2]) > 0;
  };
  const sample = (list, count) => list.filter((_, k) => k % Math.max(1, Math.floor(list.length / count)) === 0);
  const distance = (i, q) => Math.hypot(P[3 * i] - q[0], P[3 * i + 1] - q[1], P[3 * i + 2] - q[2]);

  // A box over the whole view: through the mesh, then on the visible side only.
  const whole = await page.evaluate(() => {
    const v = window.ssmdViewer, all = v.selectBox('roi', -1, -1, 1, 1);
    const allIndices = v.selected('roi');
    v.undoSelection();
    const empty = v.selected('roi').length === 0;
    const visible = v.selectBox('roi', -1, -1, 1, 1, { visibleOnly: true });
    return { all, allIndices, empty, visible, visibleIndices: v.selected('roi') };
  });
  check(whole.all === model.positions.length / 3 && whole.empty,
        `a see-through box over the whole view takes all ${whole.all} vertices, and undo empties the selection again`);
  check(whole.visible > 0.25 * whole.all && whole.visible < 0.75 * whole.all,
        `the visible-only box takes strictly fewer: ${whole.visible} of ${whole.all} vertices`);
  // A depth buffer resolves visibility to the pixel: about 1 % of the
  // vertices lie within a pixel of a silhouette, where the ray cast and the
  // pixel's center may disagree. Vertex normals of this bumpy surface may face
  // away near silhouettes, so only their share is compared.
  const visibleSet = new Set(whole.visibleIndices);
  const hiddenIndices = whole.allIndices.filter((i) => !visibleSet.has(i));
  const seen = sample(whole.visibleIndices, 500), hidden = sample(hiddenIndices, 500);
  const seenBlocked = seen.filter((i) => occluded(i, 0.02 * radius)).length;
  const hiddenBlocked = hidden.filter((i) => occluded(i, 0.005 * radius)).length;
  const seenFacing = whole.visibleIndices.filter(facing).length / whole.visible;
  const hiddenFacing = hiddenIndices.filter(facing).length / hiddenIndices.length;
  check(seenBlocked <= 0.02 * seen.length,
        `the vertices it takes are seen: ${seen.length - seenBlocked} of ${seen.length} sampled have a clear line to the camera`);
  check(hiddenBlocked >= 0.97 * hidden.length,
        `the vertices it leaves are hidden: ${hiddenBlocked} of ${hidden.length} sampled lie behind the surface`);
  check(seenFacing > 0.9 && hiddenFacing < 0.25, `${(100 * seenFacing).toFixed(1)} % of the vertices it takes face the camera, ` +
        `${(100 * hiddenFacing).toFixed(1)} % of those it leaves`);

  // The brush at the pixel of a vertex of the belly that faces the camera.
  const [before] = [await flags()];
  const center = whole.visibleIndices.filter((i) => facing(i) && !occluded(i, 0.02 * radius));
  const pixels = await page.evaluate((list) => list.map((i) => window.ssmdViewer.vertexPixel(i)), center);
  const byPixel = (x, y) => center[pixels.reduce((best, p, k) => (Math.hypot(p[0] - x, p[1] - y) < Math.hypot(pixels[best][0] - x, pixels[best][1] - y) ? k : best), 0)];
  const target = byPixel(600, 420);
  const [tx, ty] = await page.evaluate((i) => window.ssmdViewer.vertexPixel(i), target);
  await page.evaluate(() => window.ssmdViewer.clearSelection());
  const dab = await page.evaluate((x, y) => window.ssmdViewer.brushAt(x, y, 'fixed', 0.05), tx, ty);
  const dabbed = (await flags())[1];
  const within = whole.visibleIndices.filter((i) => distance(i, dab.hit) <= dab.radius);
  check(dab.hit !== null && distance(target, dab.hit) < 0.01 * radius,
        `the brush finds the surface under the pointer (${dab.hit ? (distance(target, dab.hit) / radius).toExponential(2) : '-'} radius from the vertex there)`);
  check(dabbed.includes(target) && dabbed.length === dab.count && dabbed.length > 1 &&
        dabbed.every((i) => distance(i, dab.hit) <= dab.radius * (1 + 1e-6)) && same(dabbed, within),
        `a brush dab takes the vertex under it and exactly the visible vertices within its radius (${dabbed.length})`);
  const through = await page.evaluate((x, y) => {
    const v = window.ssmdViewer, result = v.brushAt(x, y, 'roi', 0.3, { visibleOnly: false }), count = v.selected('roi').length;
    v.undoSelection();
    return { ...result, selected: count };
  }, tx, ty);
  const visibleThrough = await page.evaluate((x, y) => {
    const v = window.ssmdViewer, count = v.brushAt(x, y, 'roi', 0.3).count;
    v.undoSelection();
    return count;
  }, tx, ty);
  check(through.selected === through.count && visibleThrough < through.count,
        `a large brush takes the back too without the visible-side option (${through.count} vertices, ${visibleThrough} with it)`);
  const afterDab = await flags();
  const erase = await page.evaluate((x, y) => window.ssmdViewer.brushAt(x, y, 'fixed', 0.02, { remove: true }), tx, ty);
  const erased = (await flags())[1];
  check(!erased.includes(target) && erased.length === dabbed.length - erase.count && erased.every((i) => distance(i, erase.hit) > erase.radius),
        `a brush dab with remove erases within its radius (${erase.count} vertices)`);
  const restored = [];
  for (const expected of [afterDab, [[], [], []], before]) {
    await page.evaluate(() => window.ssmdViewer.undoSelection());
    restored.push(same(await flags(), expected));
  }
  check(restored.every((x) => x), 'undoing the selection restores the flags of each step exactly (erase, dab, clear)');

  // The brush with the mouse: the tool and the mode chosen with the mouse,
  // the size with the keys, a Shift-stroke from the belly to the chest, a
  // Ctrl+Shift dab, Ctrl+Z and the Undo selection button.
  await page.click('input[name=tool][value=brush]');
  await page.click('input[name=mode][value=handle]');
  const size0 = await page.evaluate(() => window.ssmdViewer.brushRadius());
  await page.keyboard.press(']');
  const size1 = await page.evaluate(() => window.ssmdViewer.brushRadius());
  await page.keyboard.press('[');
  const size2 = await page.evaluate(() => window.ssmdViewer.brushRadius());
  check(size1 > size0 && Math.abs(size2 - size0) < 1e-9, `] grows the brush (${size0.toFixed(3)} to ${size1.toFixed(3)}) and [ shrinks it back`);
  const end = byPixel(tx, ty - 120);
  const [ex, ey] = await page.evaluate((i) => window.ssmdViewer.vertexPixel(i), end);
  const beforeStroke = await flags(), stepsBefore = await undoSteps();
  await page.keyboard.down('Shift');
  await page.mouse.move(tx, ty);
  await page.mouse.down();
  await page.mouse.move(ex, ey, { steps: 8 });
  await page.mouse.up();
  await page.keyboard.up('Shift');
  const stroked = (await flags())[2];
  const strokeSpan = distance(target, [P[3 * end], P[3 * end + 1], P[3 * end + 2]]);
  check(stroked.includes(target) && stroked.includes(end) && stroked.every((i) => visibleSet.has(i)) &&
        same((await flags()).slice(0, 2), beforeStroke.slice(0, 2)) && (await undoSteps()) === stepsBefore + 1,
        `a Shift-stroke of the mouse paints the handle from start to end (${stroked.length} vertices over ` +
        `${(strokeSpan / radius).toFixed(2)} radius, visible ones only) as one undo step`);
  const afterStroke = await flags();
  await page.keyboard.down('Control');
  await page.keyboard.down('Shift');
  await page.mouse.move(ex, ey);
  await page.mouse.down();
  await page.mouse.up();
  await page.keyboard.up('Shift');
  await page.keyboard.up('Control');
  const ctrlErased = (await flags())[2];
  check(!ctrlErased.includes(end) && ctrlErased.includes(target) && ctrlErased.length < stroked.length,
        `a Ctrl+Shift press of the brush erases around it (${stroked.length - ctrlErased.length} vertices)`);
  await page.keyboard.down('Control');
  await page.keyboard.press('z');
  await page.keyboard.up('Control');
  const ctrlZ = same(await flags(), afterStroke);
  await page.click('#undo-selection');
  check(ctrlZ && same(await flags(), beforeStroke),
        'Ctrl+Z (no region prepared) undoes the erasing, the Undo selection button the stroke');
  await page.click('input[name=tool][value=box]');
  await page.click('input[name=mode][value=roi]');

  // The box with the mouse, as a user would: shift-drag (from its lower right
  // corner: the panel covers the upper left one), on the visible side, then
  // with the option off, through the mesh.
  const mouseBox = async () => {
    await page.evaluate(() => window.ssmdViewer.clearSelection());
    await page.keyboard.down('Shift');
    await page.mouse.move(...toPixels(-0.12, 0.0));
    await page.mouse.down();
    await page.mouse.move(...toPixels(-0.4, 0.3), { steps: 5 });
    await page.mouse.move(...toPixels(-0.7, 0.65), { steps: 5 });
    await page.mouse.up();
    await page.keyboard.up('Shift');
    return page.evaluate(() => window.ssmdViewer.selected('roi').length);
  };
  const hookBox = (visibleOnly) => page.evaluate((visibleOnly) => {
    const v = window.ssmdViewer;
    v.clearSelection();
    return v.selectBox('roi', -0.7, 0.0, -0.12, 0.65, { visibleOnly });
  }, visibleOnly);
  const mouseVisible = await mouseBox(), hookVisible = await hookBox(true);
  await page.click('#visible-only');
  const mouseRegion = await mouseBox();
  await page.click('#visible-only');
  await page.evaluate(() => window.ssmdViewer.clearSelection());
  const counts = await page.evaluate(() => ({
    roi: window.ssmdViewer.selectBox('roi', -0.7, 0.0, -0.12, 0.65),
    fixed: window.ssmdViewer.selectBox('fixed', -0.2, 0.0, -0.12, 0.65),
    handle: window.ssmdViewer.selectBox('handle', -0.7, 0.25, -0.38, 0.65),
  }));
  check(mouseVisible > 0 && Math.abs(mouseVisible - hookVisible) <= hookVisible / 100 && mouseVisible < counts.roi,
        `a shift-drag box selects the visible side of the arm (${mouseVisible} vertices)`);
  check(mouseRegion > 0 && Math.abs(mouseRegion - counts.roi) <= counts.roi / 100,
        `a shift-drag box without the visible-side option selects the whole arm (${mouseRegion} vertices)`);
  check(counts.roi > 0 && counts.fixed > 0 && counts.handle > 0,
        `box selection: ${counts.roi} region, ${counts.fixed} fixed, ${counts.handle} handle vertices`);
  const ready = await page.evaluate(() => window.ssmdViewer.prepare());
  check(ready.type === 'ready', `the selection is prepared (${ready.message || ready.region.length + ' region vertices'})`);
  if (ready.type !== 'ready') throw new Error('cannot go on without a region');
  check(!(await page.evaluate(() => window.ssmdViewer.refineEnabled())), 'Refine is disabled before a drag');

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

  // Refine: chunks of iterations until done, the mesh updated after each.
  check(await page.evaluate(() => window.ssmdViewer.refineEnabled()), 'Refine is enabled after a drag');
  const chunksBefore = await page.evaluate(() => window.ssmdViewer.stats().refinedChunks);
  const refinement = await page.evaluate(() => window.ssmdViewer.refine());
  const chunks = (await page.evaluate(() => window.ssmdViewer.stats().refinedChunks)) - chunksBefore;
  const refined = await page.evaluate(() => {
    const v = window.ssmdViewer;
    return { positions: v.positions(), status: v.status(), enabled: v.refineEnabled(),
             label: document.querySelector('#refine').textContent };
  });
  let refinedHandleError = 0, refinedFixedError = 0, refinedOutsideMoved = 0, refinedMoved = 0;
  const refinedMove = (i, k) => refined.positions[3 * i + k] - result.rest[3 * i + k];
  for (const i of result.handle) for (let k = 0; k < 3; ++k) refinedHandleError = Math.max(refinedHandleError, Math.abs(refinedMove(i, k) - t[k]));
  for (const i of result.fixed) for (let k = 0; k < 3; ++k) refinedFixedError = Math.max(refinedFixedError, Math.abs(refinedMove(i, k)));
  for (let i = 0; i < result.rest.length / 3; ++i)
    for (let k = 0; k < 3; ++k) {
      if (!inRegion.has(i) && refinedMove(i, k) !== 0) ++refinedOutsideMoved;
      refinedMoved = Math.max(refinedMoved, Math.abs(refined.positions[3 * i + k] - result.positions[3 * i + k]));
    }
  check(!refinement.failed && refinement.done && refinement.energy_after < refinement.energy_start &&
        chunks >= 2 && refinement.total_iterations <= 5 * chunks && refinement.total_iterations > 5 * (chunks - 1),
        `Refine runs in chunks of 5 iterations until done (${chunks} chunks, ${refinement.total_iterations} iterations, ` +
        `energy ${refinement.energy_start?.toExponential(3)} -> ${refinement.energy_after?.toExponential(3)})`);
  check(refinedMoved > 1e-5 * radius && refinedHandleError < 1e-3 * radius && refinedFixedError < 1e-5 * radius &&
        refinedOutsideMoved === 0,
        `the refined mesh is shown: the region moved by up to ${(refinedMoved / radius).toExponential(2)} radius, the handle ` +
        `on its targets (error ${refinedHandleError.toExponential(2)}), the fixed vertices and the outside in place`);
  check(/ARAP energy .* → .*, \d+ iterations, (converged|stopped at \d+)/.test(refined.status) &&
        refined.enabled && refined.label === 'Refine',
        `the status line shows the refinement ("${refined.status}"), the button is back`);
  // A drag stops a refinement: its answer replaces the refined shape, and no
  // chunk follows.
  const stopped = await page.evaluate(async (t) => {
    const v = window.ssmdViewer;
    document.querySelector('#refine').click();
    const label = document.querySelector('#refine').textContent;
    const reply = await v.drag(t);
    const positions = v.positions();
    await new Promise((resolve) => setTimeout(resolve, 500));
    return { label, type: reply.type, still: JSON.stringify(positions) === JSON.stringify(v.positions()),
             status: v.status(), enabled: v.refineEnabled(), after: document.querySelector('#refine').textContent };
  }, t);
  check(stopped.label === 'Stop' && stopped.type === 'deformed' && stopped.still && stopped.enabled &&
        stopped.after === 'Refine' && !stopped.status.startsWith('ARAP'),
        'a drag stops the refinement: the mesh keeps the drag\'s answer, Refine is enabled again');

  check(!(await page.evaluate(() => window.ssmdViewer.antialias())),
        'under the software renderer (SwiftShader) the page draws without multisampling');
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
  // Ctrl+Z undoes the latest change: a gizmo drag made after the selection,
  // then, with no drag left, the last selection change (the handle's box).
  const selectedBefore = await flags();
  await page.mouse.move(gx, gy);
  await page.mouse.down();
  await page.mouse.move(gx - 50, gy + 30, { steps: 10 });
  await page.mouse.up();
  await waitIdle();
  const draggedAgain = await handleDistance();
  await page.keyboard.down('Control');
  await page.keyboard.press('z');
  await page.keyboard.up('Control');
  await waitIdle();
  const ctrlZHandle = await handleDistance();
  check(draggedAgain > 0.02 * radius && ctrlZHandle < 1e-3 * radius && same(await flags(), selectedBefore),
        `after Prepare, Ctrl+Z undoes the gizmo drag (${(ctrlZHandle / radius).toExponential(2)} radius from rest) and not the selection`);
  await page.keyboard.down('Control');
  await page.keyboard.press('z');
  await page.keyboard.up('Control');
  const handleUndone = await flags();
  check(handleUndone[2].length === 0 && same(handleUndone.slice(0, 2), selectedBefore.slice(0, 2)),
        'with no drag left, Ctrl+Z undoes the last selection change (the handle box)');
  await page.evaluate(() => window.ssmdViewer.selectBox('handle', -0.7, 0.25, -0.38, 0.65));

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
