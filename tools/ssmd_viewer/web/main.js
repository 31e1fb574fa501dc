// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The page of ssmd_viewer: shows the mesh, selects the region of interest,
// fixed vertices and handle, and sends the gizmo's motion to the server,
// which answers with the positions of the region (see doc/viewer.md).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { TransformControls } from 'three/addons/controls/TransformControls.js';

const $ = (id) => document.getElementById(id);
const COLORS = { none: [0.75, 0.75, 0.72], roi: [0.94, 0.82, 0.25], fixed: [0.31, 0.63, 1.0], handle: [1.0, 0.31, 0.31] };

// --- scene ---------------------------------------------------------------
// A software rasterizer (SwiftShader, llvmpipe: a browser without a GPU)
// draws on the CPU cores the server deforms on; multisampling there doubles
// the cost of a frame, so it is kept for hardware renderers.
function softwareRenderer() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}
const antialias = !softwareRenderer();
const renderer = new THREE.WebGLRenderer({ antialias, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
$('view').appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242a);
const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
scene.add(new THREE.HemisphereLight(0xffffff, 0x404040, 1.5));
const light = new THREE.DirectionalLight(0xffffff, 1.5);
camera.add(light);
light.position.set(0.5, 1, 0.2);
scene.add(camera);
const orbit = new OrbitControls(camera, renderer.domElement);
const gizmo = new TransformControls(camera, renderer.domElement);
const handleObject = new THREE.Object3D(); // the gizmo moves this; its motion is the drag
scene.add(handleObject);
scene.add(gizmo.getHelper());

function resize() {
  renderer.setSize(window.innerWidth, window.innerHeight);
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

// --- state ---------------------------------------------------------------
const geometry = new THREE.BufferGeometry();
const mesh = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.7 }));
let n = 0;
let rest = null;                        // Float32Array of the rest positions
const selection = {};                   // mode -> Uint8Array of flags
let region = null;                      // Uint32Array: the vertices a reply carries, in its order
let center = new THREE.Vector3();       // the handle's rest centroid
let announced = null;                   // the JSON message announcing the next binary one
let inFlight = false, dirty = false;    // at most one drag waits for its reply
let sentAt = 0;
let dragged = false;                    // the shape is a drag's result: Refine may start
let refinement = null;                  // the running refinement: { stopped }; null when none runs
let refined = false;                    // the status line shows a refinement
let preparedStatus = '';                // the status line after Prepare, shown again by a drag after a refinement
const undoStack = [];
const replyTimes = [];                  // arrival times of recent replies, for updates per second
const waiters = [];                     // test hook: resolved by the next message of a type
const stats = { deformMs: 0, serverMs: 0, roundTripMs: 0, updatesPerSecond: 0, replies: 0, refinedChunks: 0 };

// Normals are recomputed once per frame, not once per reply: replies may
// come faster than frames.
let normalsStale = false;
// While the server prepares a selection the picture changes only when the
// view moves: frames are drawn then only, so that a browser that renders in
// software (no GPU) leaves the cores to the server (a 3,627-vertex region
// was prepared in 0.32-0.55 s beside a page redrawing 12 times a second in
// headless Chromium, in 0.19-0.20 s without a browser).
let preparing = false, framesOwed = 0, viewChanged = false;
orbit.addEventListener('change', () => { viewChanged = true; });
renderer.setAnimationLoop(() => {
  if (normalsStale) { geometry.computeVertexNormals(); normalsStale = false; }
  orbit.update();
  if (preparing && !viewChanged && framesOwed === 0) return;
  viewChanged = false;
  framesOwed = Math.max(0, framesOwed - 1);
  renderer.render(scene, camera);
});

const ws = new WebSocket(`ws://${location.host}/ws`);
ws.binaryType = 'arraybuffer';
ws.onclose = () => { preparing = false; message('connection closed: reload the page'); };
ws.onmessage = (event) => {
  if (typeof event.data === 'string') onJson(JSON.parse(event.data));
  else onBinary(event.data);
};

function send(command) { ws.send(JSON.stringify(command)); }
function message(text) { $('message').textContent = text; }
function currentMode() { return document.querySelector('input[name=mode]:checked').value; }
function notify(type, data) {
  for (let i = waiters.length - 1; i >= 0; --i)
    if (waiters[i].types.includes(data.type)) { waiters[i].resolve(data); waiters.splice(i, 1); }
}
function next(...types) { return new Promise((resolve) => waiters.push({ types, resolve })); }

// --- messages from the server -----------------------------------------------
function onJson(data) {
  if (data.type === 'progress') {
    $('progress').value = data.fraction;
    $('stage').textContent = data.stage === 'approximation'
      ? `basis: approximation of ${data.wanted} frequencies in a space of sampled functions`
      : `basis: ${data.stage}, ${data.converged}/${data.wanted} frequencies, ${data.solves} solves`;
  } else if (data.type === 'ready') {
    preparing = false;
    region = Uint32Array.from(data.region);
    center.fromArray(data.center);
    $('progress').value = 1;
    preparedStatus = `${region.length} region vertices, prepared in ${(1000 * data.preprocess_seconds).toFixed(0)} ms` +
      (data.basis_computed ? ` (basis ${(1000 * data.basis_seconds).toFixed(0)} ms)` : '');
    $('stage').textContent = preparedStatus;
    placeGizmo(new THREE.Vector3(), new THREE.Quaternion());
    gizmo.attach(handleObject);
    undoStack.length = 0;
    inFlight = dirty = false;
    cancelRefinement(false);
    message('');
  } else if (data.type === 'error') {
    message(`server: ${data.message}`);
    if (data.request === 'drag') inFlight = false;
    if (data.request === 'refine' && refinement) finishRefinement(null);
    if (data.request === 'select') { $('progress').value = 0; preparing = false; }
  } else {
    announced = data; // mesh, deformed, refined, off: the data follow in a binary message
    return;
  }
  notify(data.type, data);
}

function onBinary(buffer) {
  const header = announced;
  announced = null;
  if (header.type === 'mesh') setMesh(header, buffer);
  else if (header.type === 'deformed') applyDeformed(header, buffer);
  else if (header.type === 'refined') applyRefined(header, buffer);
  else if (header.type === 'off') download(header.name, buffer);
  notify(header.type, header);
}

function setMesh(header, buffer) {
  n = header.vertices;
  rest = new Float32Array(buffer, 0, 3 * n).slice();
  const faces = new Uint32Array(buffer, 12 * n, 3 * header.faces);
  geometry.setAttribute('position', new THREE.BufferAttribute(rest.slice(), 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(3 * n), 3));
  geometry.setIndex(new THREE.BufferAttribute(faces.slice(), 1));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
  scene.add(mesh);
  for (const mode of ['roi', 'fixed', 'handle']) selection[mode] = new Uint8Array(n);
  updateColors();
  const { center: c, radius } = geometry.boundingSphere;
  orbit.target.copy(c);
  // Looking along +z: CGAL's sample meshes (the armadillo) face -z.
  camera.position.set(c.x, c.y, c.z - 2.8 * radius);
  camera.near = radius / 100; camera.far = radius * 100;
  camera.updateProjectionMatrix();
  gizmo.size = 0.8;
  $('title').textContent = `${header.name}: ${n.toLocaleString('en')} vertices`;
}

// The positions of the region vertices, in the order of `region`.
function applyPositions(buffer) {
  const values = new Float32Array(buffer);
  const position = geometry.attributes.position;
  for (let j = 0; j < region.length; ++j) {
    const i = 3 * region[j];
    position.array[i] = values[3 * j];
    position.array[i + 1] = values[3 * j + 1];
    position.array[i + 2] = values[3 * j + 2];
  }
  position.needsUpdate = true;
  normalsStale = true;
}

function applyDeformed(header, buffer) {
  applyPositions(buffer);
  $('refine').disabled = !dragged;
  const now = performance.now();
  replyTimes.push(now);
  while (replyTimes.length > 0 && replyTimes[0] < now - 1000) replyTimes.shift();
  stats.replies += 1;
  stats.deformMs = 1000 * header.deform_seconds;
  stats.serverMs = 1000 * header.server_seconds;
  stats.roundTripMs = now - sentAt;
  stats.updatesPerSecond = replyTimes.length;
  $('stats').textContent = `deform   ${stats.deformMs.toFixed(1)} ms (${header.iterations} solves)\n` +
    `server   ${stats.serverMs.toFixed(1)} ms\nround    ${stats.roundTripMs.toFixed(1)} ms\n` +
    `updates  ${stats.updatesPerSecond} /s`;
  inFlight = false;
  if (dirty) sendDrag();
}

// --- refinement ----------------------------------------------------------------
// Refine asks the server for a few as-rigid-as-possible iterations at a
// time, shows each result, and asks again until the server says the
// refinement is done (converged, or at its cap of iterations). A drag, a
// reset or a new selection cancels it: the answer in flight is dropped,
// the drag's answer follows. The button stops it too, after the chunk in
// flight, whose result is shown.
function startRefinement() {
  if (!region || !dragged || refinement) return;
  refinement = { stopped: false };
  refined = true;
  $('refine').textContent = 'Stop';
  $('stage').textContent = 'refining…';
  send({ type: 'refine' });
}

function stopRefinement() {
  if (!refinement) return;
  refinement.stopped = true;
  $('refine').disabled = true; // until the chunk in flight is back
}

// Forgets the running refinement (its answer in flight is dropped).
function cancelRefinement(enable) {
  refinement = null;
  $('refine').textContent = 'Refine';
  $('refine').disabled = !enable;
}

function finishRefinement(header) {
  cancelRefinement(dragged && region !== null);
  notify('refinement', { ...(header || { failed: true }), type: 'refinement' });
}

const energyText = (e) => e.toExponential(3);

function applyRefined(header, buffer) {
  if (!refinement) return; // cancelled by a drag, a reset or a selection
  applyPositions(buffer);
  stats.refinedChunks += 1;
  const state = header.done ? (header.converged ? ', converged' : `, stopped at ${header.max_iterations}`)
    : refinement.stopped ? ', stopped' : '…';
  $('stage').textContent = `ARAP energy ${energyText(header.energy_start)} → ${energyText(header.energy_after)}, ` +
    `${header.total_iterations} iterations${state}`;
  $('stats').textContent = `refine   ${(1000 * header.refine_seconds).toFixed(1)} ms (${header.iterations} iterations)\n` +
    `server   ${(1000 * header.server_seconds).toFixed(1)} ms`;
  if (header.done || refinement.stopped) finishRefinement(header);
  else send({ type: 'refine' });
}

function download(name, buffer) {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(new Blob([buffer], { type: 'model/off' }));
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

// --- selection ---------------------------------------------------------------
function updateColors() {
  const color = geometry.attributes.color;
  for (let i = 0; i < n; ++i) {
    const c = selection.handle[i] ? COLORS.handle : selection.fixed[i] ? COLORS.fixed
      : selection.roi[i] ? COLORS.roi : COLORS.none;
    color.array.set(c, 3 * i);
  }
  color.needsUpdate = true;
}

// --- selection undo ------------------------------------------------------------
// Each change of the selection (a box, a brush stroke, a clear) keeps the
// flags it replaced. Drag and selection steps carry a common clock so that
// Ctrl+Z undoes whichever came last; the buttons undo one kind each.
const MAX_SELECTION_UNDO = 50;          // snapshots are 3n bytes each
const selectionUndo = [];
let historyClock = 0;

function snapshotSelection() {
  return { roi: selection.roi.slice(), fixed: selection.fixed.slice(), handle: selection.handle.slice() };
}

function sameFlags(a, b) {
  for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) return false;
  return true;
}

// Records `before` as an undo step unless the flags are still the same: an
// empty box or a stroke over the background is no step.
function commitSelectionChange(before) {
  if (['roi', 'fixed', 'handle'].every((mode) => sameFlags(before[mode], selection[mode]))) return false;
  selectionUndo.push({ flags: before, time: ++historyClock });
  if (selectionUndo.length > MAX_SELECTION_UNDO) selectionUndo.shift();
  $('undo-selection').disabled = false;
  return true;
}

function undoSelection() {
  const step = selectionUndo.pop();
  $('undo-selection').disabled = selectionUndo.length === 0;
  if (!step) return false;
  for (const mode in selection) selection[mode].set(step.flags[mode]);
  updateColors();
  return true;
}

// --- what the camera sees -------------------------------------------------------
// The selection tools can take only the vertices the camera sees. The mesh's
// depth is rendered off screen once per box or brush stroke (the camera does
// not move meanwhile) and read back, so that visibility is one lookup per
// vertex and the surface under the pointer one per move, instead of rays
// through all the triangles.
const VISIBILITY_TOLERANCE = 0.01;      // relative to the bounding radius: how far behind the surface seen a vertex still counts as seen
const depthMaterial = new THREE.MeshDepthMaterial({ depthPacking: THREE.RGBADepthPacking });
const depthScene = new THREE.Scene();
depthScene.overrideMaterial = depthMaterial;
const depthTarget = new THREE.WebGLRenderTarget(1, 1); // no multisampling: depths are not blended
let depthPixels = new Uint8Array(4);

// Renders the mesh alone (not the gizmo) with its window depth packed into
// RGBA, 1 (white) where there is no surface, and reads it back.
function renderDepth() {
  const size = renderer.getDrawingBufferSize(new THREE.Vector2());
  if (depthTarget.width !== size.x || depthTarget.height !== size.y) depthTarget.setSize(size.x, size.y);
  if (depthPixels.length !== 4 * size.x * size.y) depthPixels = new Uint8Array(4 * size.x * size.y);
  camera.updateMatrixWorld(); // the camera may have moved since the last frame
  const clearColor = renderer.getClearColor(new THREE.Color()), clearAlpha = renderer.getClearAlpha();
  depthScene.add(mesh); // borrowed from the scene, which takes it back below
  renderer.setClearColor(0xffffff, 1);
  renderer.setRenderTarget(depthTarget);
  renderer.render(depthScene, camera);
  renderer.setRenderTarget(null);
  renderer.setClearColor(clearColor, clearAlpha);
  scene.add(mesh);
  renderer.readRenderTargetPixels(depthTarget, 0, 0, size.x, size.y, depthPixels);
  return { width: size.x, height: size.y, pixels: depthPixels };
}

// The window depth in [0, 1] at a pixel (x to the right, y up), as
// three.js's packDepthToRGBA stores it.
function depthAt(depth, x, y) {
  const p = depth.pixels, i = 4 * (y * depth.width + x);
  return p[i] / 256 + p[i + 1] / 65536 + p[i + 2] / 16777216 + p[i + 3] / (255 * 16777216);
}

// The distance along the view direction of a window depth: comparisons are
// made there because window depth is far from linear.
function viewDepth(d) { return camera.near * camera.far / (camera.far - d * (camera.far - camera.near)); }

// Flags the vertices in the view that lie at most the tolerance behind the
// surface seen at their pixel. The tolerance lets through the vertices on
// surfaces up to about 80 degrees from facing the camera (the pixel's center
// is half a pixel off the vertex); it also hides no vertex behind a farther
// neighbor pixel, as a margin of pixels around silhouettes would.
function visibleVertices(depth) {
  const visible = new Uint8Array(n);
  const p = new THREE.Vector3(), position = geometry.attributes.position;
  const tolerance = VISIBILITY_TOLERANCE * geometry.boundingSphere.radius;
  const { width, height } = depth;
  for (let i = 0; i < n; ++i) {
    p.fromBufferAttribute(position, i).applyMatrix4(camera.matrixWorldInverse);
    const distance = -p.z;
    p.applyMatrix4(camera.projectionMatrix);
    if (Math.abs(p.x) > 1 || Math.abs(p.y) > 1 || Math.abs(p.z) > 1) continue;
    const x = Math.min(width - 1, Math.floor((p.x + 1) / 2 * width));
    const y = Math.min(height - 1, Math.floor((p.y + 1) / 2 * height));
    if (distance <= viewDepth(depthAt(depth, x, y)) + tolerance) visible[i] = 1;
  }
  return visible;
}

// The point of the surface seen at a client pixel, or null over the background.
function surfacePoint(depth, clientX, clientY) {
  const r = renderer.domElement.getBoundingClientRect();
  const x = Math.floor((clientX - r.left) / r.width * depth.width);
  const y = Math.floor((r.bottom - clientY) / r.height * depth.height);
  if (x < 0 || y < 0 || x >= depth.width || y >= depth.height) return null;
  const d = depthAt(depth, x, y);
  if (d >= 1) return null;
  return new THREE.Vector3((x + 0.5) / depth.width * 2 - 1, (y + 0.5) / depth.height * 2 - 1, 2 * d - 1).unproject(camera);
}

// --- box -------------------------------------------------------------------------
// Flags the vertices whose projection lies in the box (normalized device
// coordinates): only those the camera sees with visibleOnly, else hidden ones
// too, so that a box through the mesh takes both sides.
function selectBox(mode, x0, y0, x1, y1, { remove = false, visibleOnly = false } = {}) {
  const [xmin, xmax, ymin, ymax] = [Math.min(x0, x1), Math.max(x0, x1), Math.min(y0, y1), Math.max(y0, y1)];
  const visible = visibleOnly ? visibleVertices(renderDepth()) : null;
  const before = snapshotSelection();
  const p = new THREE.Vector3();
  const position = geometry.attributes.position;
  camera.updateMatrixWorld(); // the camera may have moved since the last frame
  let count = 0;
  for (let i = 0; i < n; ++i) {
    if (visible && !visible[i]) continue;
    p.fromBufferAttribute(position, i).project(camera);
    if (p.z < 1 && p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax) {
      selection[mode][i] = remove ? 0 : 1;
      ++count;
    }
  }
  commitSelectionChange(before);
  updateColors();
  return count;
}

// --- brush -----------------------------------------------------------------------
// A stroke paints, at each pointer position, the vertices within the radius of
// the surface point under the pointer. The depth is rendered when the stroke
// starts, and the vertices that may be painted are listed then.
const BRUSH_STEP_PIXELS = 4;            // a fast pointer move is painted at least every 4 pixels
let stroke = null;

function brushFraction() { return Number($('brush-radius').value); }
function setBrushFraction(fraction) {
  const slider = $('brush-radius');
  slider.value = Math.min(Number(slider.max), Math.max(Number(slider.min), fraction));
  $('brush-radius-value').textContent = brushFraction().toFixed(3);
}

function beginStroke(mode, { remove = false, visibleOnly = true, fraction = brushFraction() } = {}) {
  const depth = renderDepth();
  const candidates = visibleOnly ? indicesOf(visibleVertices(depth)) : indicesOf(new Uint8Array(n).fill(1));
  stroke = { depth, candidates, mode, value: remove ? 0 : 1, radius: fraction * geometry.boundingSphere.radius,
             before: snapshotSelection(), last: null };
}

// Paints at one client pixel; returns the surface point and how many vertices it reached.
function paintAt(clientX, clientY) {
  const hit = surfacePoint(stroke.depth, clientX, clientY);
  if (!hit) return { hit: null, count: 0 };
  const flags = selection[stroke.mode], position = geometry.attributes.position, p = new THREE.Vector3();
  const r2 = stroke.radius * stroke.radius;
  let count = 0;
  for (const i of stroke.candidates)
    if (p.fromBufferAttribute(position, i).distanceToSquared(hit) <= r2) { flags[i] = stroke.value; ++count; }
  return { hit, count };
}

// Paints from the previous pointer position to this one.
function paintTo(clientX, clientY) {
  const [x0, y0] = stroke.last || [clientX, clientY];
  const steps = Math.max(1, Math.ceil(Math.hypot(clientX - x0, clientY - y0) / BRUSH_STEP_PIXELS));
  let result = null;
  for (let k = 1; k <= steps; ++k) result = paintAt(x0 + (clientX - x0) * k / steps, y0 + (clientY - y0) * k / steps);
  stroke.last = [clientX, clientY];
  updateColors();
  return result;
}

function endStroke() {
  commitSelectionChange(stroke.before);
  stroke = null;
}

// The brush's outline at the pointer, sized at the distance of the orbit's
// center: only a guide, the painted sphere is centered on the surface.
const brushCursor = $('brush-cursor');
function showBrushCursor(event) {
  if (currentTool() !== 'brush' || n === 0 || event.target !== renderer.domElement) {
    brushCursor.style.display = 'none';
    return;
  }
  const distance = camera.position.distanceTo(orbit.target);
  const pixels = brushFraction() * geometry.boundingSphere.radius / (distance * Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)))
    * renderer.domElement.clientHeight / 2;
  Object.assign(brushCursor.style, { display: 'block', left: `${event.clientX}px`, top: `${event.clientY}px`,
                                     width: `${2 * pixels}px`, height: `${2 * pixels}px` });
}

function selectIndices(mode, indices) {
  const before = snapshotSelection();
  for (const i of indices) selection[mode][i] = 1;
  commitSelectionChange(before);
  updateColors();
}

// Also forgets the prepared region and its drags: they belong to the old selection.
function clearSelection() {
  const before = snapshotSelection();
  for (const mode in selection) selection[mode].fill(0);
  gizmo.detach();
  region = null;
  dragged = false;
  cancelRefinement(false);
  undoStack.length = 0;
  commitSelectionChange(before);
  updateColors();
}

function indicesOf(flags) {
  const result = [];
  for (let i = 0; i < n; ++i) if (flags[i]) result.push(i);
  return result;
}

function prepare() {
  gizmo.detach();
  region = null;
  dragged = false;
  cancelRefinement(false);
  geometry.attributes.position.array.set(rest);
  geometry.attributes.position.needsUpdate = true;
  geometry.computeVertexNormals();
  $('progress').value = 0;
  $('stage').textContent = 'preparing…';
  preparing = true;
  framesOwed = 2; // the mesh at rest, without the gizmo
  send({ type: 'select', roi: indicesOf(selection.roi), fixed: indicesOf(selection.fixed), handle: indicesOf(selection.handle) });
}

// Shift-drag runs the chosen tool; Ctrl, or the erase box, removes.
const box = $('box');
let boxStart = null;
function currentTool() { return document.querySelector('input[name=tool]:checked').value; }
function erasing(event) { return event.ctrlKey || $('erase').checked; }
function toNdc(event) {
  const r = renderer.domElement.getBoundingClientRect();
  return [((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1];
}
renderer.domElement.addEventListener('pointerdown', (event) => {
  if (!event.shiftKey || n === 0 || event.button !== 0) return;
  orbit.enabled = false;
  if (currentTool() === 'brush') {
    beginStroke(currentMode(), { remove: erasing(event), visibleOnly: $('visible-only').checked });
    paintTo(event.clientX, event.clientY);
  } else boxStart = event;
}, true);
window.addEventListener('pointermove', (event) => {
  showBrushCursor(event);
  if (stroke) paintTo(event.clientX, event.clientY);
  if (!boxStart) return;
  Object.assign(box.style, {
    display: 'block', left: `${Math.min(boxStart.clientX, event.clientX)}px`, top: `${Math.min(boxStart.clientY, event.clientY)}px`,
    width: `${Math.abs(event.clientX - boxStart.clientX)}px`, height: `${Math.abs(event.clientY - boxStart.clientY)}px`,
  });
});
window.addEventListener('pointerup', (event) => {
  if (stroke) {
    endStroke();
    orbit.enabled = true;
  }
  if (!boxStart) return;
  const [x0, y0] = toNdc(boxStart), [x1, y1] = toNdc(event);
  selectBox(currentMode(), x0, y0, x1, y1, { remove: erasing(event), visibleOnly: $('visible-only').checked });
  boxStart = null;
  box.style.display = 'none';
  orbit.enabled = true;
});

// --- dragging ------------------------------------------------------------------
function placeGizmo(translation, quaternion) {
  handleObject.position.copy(center).add(translation);
  handleObject.quaternion.copy(quaternion);
}

// While the handle moves, each drag runs the server's few solves and
// continues the iteration of the previous one; when it stops, one more drag
// with more solves lets the shape settle.
const SETTLE_ITERATIONS = 10;
let settlePending = false;
function sendDrag(settle = false) {
  if (!region) return;
  // A drag stops the refinement; Refine is enabled again by the drag's answer.
  if (refinement) cancelRefinement(false);
  if (refined) { $('stage').textContent = preparedStatus; refined = false; }
  dragged = true;
  if (settle) settlePending = true;
  if (inFlight) { dirty = true; return; }
  const t = handleObject.position.clone().sub(center);
  const q = handleObject.quaternion;
  const command = { type: 'drag', translation: t.toArray(), rotation: [q.w, q.x, q.y, q.z], center: center.toArray() };
  if (settlePending) command.iterations = SETTLE_ITERATIONS;
  inFlight = true;
  dirty = settlePending = false;
  sentAt = performance.now();
  send(command);
}

function snapshot() {
  return { translation: handleObject.position.clone().sub(center), quaternion: handleObject.quaternion.clone(), time: ++historyClock };
}

gizmo.addEventListener('dragging-changed', (event) => {
  orbit.enabled = !event.value;
  if (event.value) undoStack.push(snapshot());
  else sendDrag(true);
});
gizmo.addEventListener('objectChange', () => sendDrag());

function undo() {
  const state = undoStack.pop();
  if (!state) return;
  placeGizmo(state.translation, state.quaternion);
  sendDrag(true);
}

// Ctrl+Z: the latest of the gizmo drags (which exist only while a region is
// prepared) and the selection changes.
function undoLatest() {
  const drag = undoStack.at(-1), step = selectionUndo.at(-1);
  if (step && (!drag || step.time > drag.time)) undoSelection();
  else undo();
}

function reset() {
  if (!region) return;
  dragged = false;
  cancelRefinement(false);
  undoStack.length = 0;
  placeGizmo(new THREE.Vector3(), new THREE.Quaternion());
  send({ type: 'reset' });
}

$('clear').onclick = clearSelection;
$('prepare').onclick = prepare;
$('undo').onclick = undo;
$('undo-selection').onclick = undoSelection;
$('reset').onclick = reset;
$('refine').onclick = () => (refinement ? stopRefinement() : startRefinement());
$('save').onclick = () => send({ type: 'save' });
for (const input of document.querySelectorAll('input[name=gizmo]'))
  input.onchange = () => gizmo.setMode(input.value);
$('brush-radius').oninput = () => setBrushFraction(brushFraction());
setBrushFraction(brushFraction());
const BRUSH_KEY_FACTOR = 1.25;          // [ and ] scale the brush by this
window.addEventListener('keydown', (event) => {
  if (event.key === 't' || event.key === 'r') {
    const mode = event.key === 't' ? 'translate' : 'rotate';
    gizmo.setMode(mode);
    document.querySelector(`input[name=gizmo][value=${mode}]`).checked = true;
  } else if (event.key === 'b') {
    const tool = currentTool() === 'brush' ? 'box' : 'brush';
    document.querySelector(`input[name=tool][value=${tool}]`).checked = true;
  } else if (event.key === '[' || event.key === ']') {
    setBrushFraction(brushFraction() * (event.key === ']' ? BRUSH_KEY_FACTOR : 1 / BRUSH_KEY_FACTOR));
  } else if ((event.key === 'z' || event.key === 'Z') && event.ctrlKey) {
    event.preventDefault();
    undoLatest();
  }
});

// --- hook for scripts (the browser test) ---------------------------------------------
// Moves the handle as a pointer would, 120 moves a second, through the same
// path as the gizmo: one drag in flight, the latest position sent when the
// reply arrives. Frames are counted apart: without a GPU they are the slow part.
async function animateHandle(seconds, amplitude) {
  const start = performance.now(), replies = stats.replies;
  let frames = 0;
  const countFrame = () => { ++frames; if (performance.now() - start < 1000 * seconds) requestAnimationFrame(countFrame); };
  requestAnimationFrame(countFrame);
  await new Promise((resolve) => {
    const step = () => {
      const time = (performance.now() - start) / 1000;
      if (time >= seconds) { resolve(); return; }
      handleObject.position.copy(center).add(new THREE.Vector3(amplitude * Math.sin(3 * time), amplitude * (1 - Math.cos(3 * time)), 0));
      sendDrag();
      setTimeout(step, 1000 / 120);
    };
    step();
  });
  const elapsed = (performance.now() - start) / 1000;
  while (inFlight) await next('deformed', 'error');
  return { updatesPerSecond: (stats.replies - replies) / elapsed, framesPerSecond: frames / elapsed,
           lastDeformMs: stats.deformMs, lastServerMs: stats.serverMs, lastRoundTripMs: stats.roundTripMs };
}

// One brush stroke of a single dab at a client pixel, as a Shift-press there
// would paint (radiusFraction relative to the bounding radius).
function brushAt(clientX, clientY, mode, radiusFraction = brushFraction(), { remove = false, visibleOnly = true } = {}) {
  beginStroke(mode, { remove, visibleOnly, fraction: radiusFraction });
  const { hit, count } = paintAt(clientX, clientY);
  updateColors();
  const radius = stroke.radius;
  endStroke();
  return { hit: hit ? hit.toArray() : null, count, radius };
}

function clientPixel(point) {
  camera.updateMatrixWorld();
  const p = point.clone().project(camera), r = renderer.domElement.getBoundingClientRect();
  return [r.left + (p.x + 1) / 2 * r.width, r.top + (1 - p.y) / 2 * r.height];
}

window.ssmdViewer = {
  meshLoaded: n > 0 ? Promise.resolve() : next('mesh'),
  // The box in normalized device coordinates; options { remove, visibleOnly }
  // (a boolean: remove, as before), both false by default: the box as it was
  // before the visible-side option, whatever the page's check box says.
  selectBox(mode, x0, y0, x1, y1, options = {}) {
    return selectBox(mode, x0, y0, x1, y1, typeof options === 'boolean' ? { remove: options } : options);
  },
  selectIndices, clearSelection, brushAt, undoSelection,
  selectionUndoSteps: () => selectionUndo.length,
  brushRadius: brushFraction,
  visible: () => indicesOf(visibleVertices(renderDepth())),
  prepare() { const reply = next('ready', 'error'); prepare(); return reply; },
  drag(translation, quaternion = [0, 0, 0, 1]) {
    placeGizmo(new THREE.Vector3(...translation), new THREE.Quaternion(...quaternion));
    const reply = next('deformed', 'error');
    sendDrag(true);
    return reply;
  },
  reset() { const reply = next('deformed', 'error'); reset(); return reply; },
  // Runs Refine to its end; resolves with the last answer's header (type
  // 'refinement'), or { type: 'refinement', failed: true } after an error.
  refine() { const end = next('refinement'); $('refine').click(); return end; },
  refineEnabled: () => !$('refine').disabled,
  status: () => $('stage').textContent,
  animateHandle,
  positions: () => Array.from(geometry.attributes.position.array),
  restPositions: () => Array.from(rest),
  selected: (mode) => indicesOf(selection[mode]),
  region: () => Array.from(region || []),
  radius: () => geometry.boundingSphere.radius,
  gizmoPixel: () => clientPixel(handleObject.position),
  vertexPixel: (i) => clientPixel(new THREE.Vector3().fromBufferAttribute(geometry.attributes.position, i)),
  camera: () => { camera.updateMatrixWorld(); return { position: camera.position.toArray(), near: camera.near, far: camera.far }; },
  faces: () => Array.from(geometry.index.array),
  normals: () => Array.from(geometry.attributes.normal.array),
  idle: () => !inFlight && !dirty,
  stats: () => ({ ...stats }),
  antialias: () => antialias,
};
