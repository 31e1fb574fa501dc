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
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
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
const undoStack = [];
const replyTimes = [];                  // arrival times of recent replies, for updates per second
const waiters = [];                     // test hook: resolved by the next message of a type
const stats = { deformMs: 0, serverMs: 0, roundTripMs: 0, updatesPerSecond: 0, replies: 0 };

// Normals are recomputed once per frame, not once per reply: replies may
// come faster than frames.
let normalsStale = false;
renderer.setAnimationLoop(() => {
  if (normalsStale) { geometry.computeVertexNormals(); normalsStale = false; }
  orbit.update();
  renderer.render(scene, camera);
});

const ws = new WebSocket(`ws://${location.host}/ws`);
ws.binaryType = 'arraybuffer';
ws.onclose = () => { message('connection closed: reload the page'); };
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
    $('stage').textContent = `basis: ${data.stage}, ${data.converged}/${data.wanted} frequencies, ${data.solves} solves`;
  } else if (data.type === 'ready') {
    region = Uint32Array.from(data.region);
    center.fromArray(data.center);
    $('progress').value = 1;
    $('stage').textContent = `${region.length} region vertices, prepared in ${(1000 * data.preprocess_seconds).toFixed(0)} ms` +
      (data.basis_computed ? ` (basis ${(1000 * data.basis_seconds).toFixed(0)} ms)` : '');
    placeGizmo(new THREE.Vector3(), new THREE.Quaternion());
    gizmo.attach(handleObject);
    undoStack.length = 0;
    inFlight = dirty = false;
    message('');
  } else if (data.type === 'error') {
    message(`server: ${data.message}`);
    if (data.request === 'drag') inFlight = false;
    if (data.request === 'select') $('progress').value = 0;
  } else {
    announced = data; // mesh, deformed, off: the data follow in a binary message
    return;
  }
  notify(data.type, data);
}

function onBinary(buffer) {
  const header = announced;
  announced = null;
  if (header.type === 'mesh') setMesh(header, buffer);
  else if (header.type === 'deformed') applyDeformed(header, buffer);
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

function applyDeformed(header, buffer) {
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

// Flags the vertices whose projection lies in the box (normalized device
// coordinates), hidden ones included: a box through the mesh takes both sides.
function selectBox(mode, x0, y0, x1, y1, remove = false) {
  const [xmin, xmax, ymin, ymax] = [Math.min(x0, x1), Math.max(x0, x1), Math.min(y0, y1), Math.max(y0, y1)];
  const p = new THREE.Vector3();
  const position = geometry.attributes.position;
  camera.updateMatrixWorld(); // the camera may have moved since the last frame
  let count = 0;
  for (let i = 0; i < n; ++i) {
    p.fromBufferAttribute(position, i).project(camera);
    if (p.z < 1 && p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax) {
      selection[mode][i] = remove ? 0 : 1;
      ++count;
    }
  }
  updateColors();
  return count;
}

function selectIndices(mode, indices) {
  for (const i of indices) selection[mode][i] = 1;
  updateColors();
}

function clearSelection() {
  for (const mode in selection) selection[mode].fill(0);
  gizmo.detach();
  region = null;
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
  geometry.attributes.position.array.set(rest);
  geometry.attributes.position.needsUpdate = true;
  geometry.computeVertexNormals();
  $('progress').value = 0;
  $('stage').textContent = 'preparing…';
  send({ type: 'select', roi: indicesOf(selection.roi), fixed: indicesOf(selection.fixed), handle: indicesOf(selection.handle) });
}

const box = $('box');
let boxStart = null;
function toNdc(event) {
  const r = renderer.domElement.getBoundingClientRect();
  return [((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1];
}
renderer.domElement.addEventListener('pointerdown', (event) => {
  if (!event.shiftKey || n === 0) return;
  orbit.enabled = false;
  boxStart = event;
}, true);
window.addEventListener('pointermove', (event) => {
  if (!boxStart) return;
  Object.assign(box.style, {
    display: 'block', left: `${Math.min(boxStart.clientX, event.clientX)}px`, top: `${Math.min(boxStart.clientY, event.clientY)}px`,
    width: `${Math.abs(event.clientX - boxStart.clientX)}px`, height: `${Math.abs(event.clientY - boxStart.clientY)}px`,
  });
});
window.addEventListener('pointerup', (event) => {
  if (!boxStart) return;
  const [x0, y0] = toNdc(boxStart), [x1, y1] = toNdc(event);
  selectBox(currentMode(), x0, y0, x1, y1, event.ctrlKey);
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

function snapshot() { return { translation: handleObject.position.clone().sub(center), quaternion: handleObject.quaternion.clone() }; }

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

function reset() {
  if (!region) return;
  undoStack.length = 0;
  placeGizmo(new THREE.Vector3(), new THREE.Quaternion());
  send({ type: 'reset' });
}

$('clear').onclick = clearSelection;
$('prepare').onclick = prepare;
$('undo').onclick = undo;
$('reset').onclick = reset;
$('save').onclick = () => send({ type: 'save' });
for (const input of document.querySelectorAll('input[name=gizmo]'))
  input.onchange = () => gizmo.setMode(input.value);
window.addEventListener('keydown', (event) => {
  if (event.key === 't' || event.key === 'r') {
    const mode = event.key === 't' ? 'translate' : 'rotate';
    gizmo.setMode(mode);
    document.querySelector(`input[name=gizmo][value=${mode}]`).checked = true;
  } else if (event.key === 'z' && event.ctrlKey) undo();
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

window.ssmdViewer = {
  meshLoaded: n > 0 ? Promise.resolve() : next('mesh'),
  selectBox, selectIndices, clearSelection,
  prepare() { const reply = next('ready', 'error'); prepare(); return reply; },
  drag(translation, quaternion = [0, 0, 0, 1]) {
    placeGizmo(new THREE.Vector3(...translation), new THREE.Quaternion(...quaternion));
    const reply = next('deformed', 'error');
    sendDrag(true);
    return reply;
  },
  reset() { const reply = next('deformed', 'error'); reset(); return reply; },
  animateHandle,
  positions: () => Array.from(geometry.attributes.position.array),
  restPositions: () => Array.from(rest),
  selected: (mode) => indicesOf(selection[mode]),
  region: () => Array.from(region || []),
  radius: () => geometry.boundingSphere.radius,
  gizmoPixel() {
    const p = handleObject.position.clone().project(camera), r = renderer.domElement.getBoundingClientRect();
    return [r.left + (p.x + 1) / 2 * r.width, r.top + (1 - p.y) / 2 * r.height];
  },
  idle: () => !inFlight && !dirty,
  stats: () => ({ ...stats }),
};
