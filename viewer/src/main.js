// swept's path viewer: the page `swept view` writes embeds this bundle and the scene data
// (<script id="swept-data" type="application/json">). Everything is local: no network.
//
// URL hash parameters: #t=0.5 shows path parameter 0.5 (paused); #play starts playing;
// #speed=2 sets the speed; #obstacles=transparent|hidden|opaque.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { base64ToBytes, decodeIndices, decodePositions, inflate } from './decode.js';
import { PathMotion } from './path.js';
import { startDisassembly } from './disassembly.js';
import { ClearancePlot } from './plot.js';

const CSS = `
html, body { margin: 0; height: 100%; background: #1b1d22; color: #ddd; font: 13px system-ui, sans-serif; overflow: hidden; }
#swept-canvas { position: absolute; inset: 0; width: 100%; height: 100%; display: block; touch-action: none; }
#swept-panel { position: absolute; left: 10px; top: 10px; background: rgba(20,22,27,0.85); padding: 8px 10px;
  border-radius: 6px; max-width: 360px; user-select: none; }
#swept-panel h1 { font-size: 14px; margin: 0 0 6px; font-weight: 600; }
#swept-panel .row { display: flex; align-items: center; gap: 6px; margin: 4px 0; }
#swept-panel button { min-width: 64px; }
#swept-panel input[type=range] { flex: 1; }
#swept-info { white-space: pre; font-family: ui-monospace, monospace; font-size: 11px; color: #aaa; }
#swept-plot { position: absolute; left: 10px; right: 10px; bottom: 10px; height: 130px; width: calc(100% - 20px);
  background: rgba(20,22,27,0.85); border-radius: 6px; cursor: crosshair; }
#swept-error { position: absolute; inset: 40% 10% auto 10%; color: #f88; font-size: 15px; text-align: center; }
`;

function element(tag, attributes = {}, parent = null) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes)) {
    if (k === 'text') e.textContent = v; else e.setAttribute(k, v);
  }
  if (parent) parent.appendChild(e);
  return e;
}

function hashParameters() {
  const out = new Map();
  for (const part of location.hash.replace(/^#/, '').split('&')) {
    if (!part) continue;
    const [k, v] = part.split('=');
    out.set(decodeURIComponent(k), v === undefined ? '' : decodeURIComponent(v));
  }
  return out;
}

/** Builds a mesh from the embedded, quantised data: positions stay uint16 (normalised) on the
 *  GPU; the mesh's scale and position map [0, 1]³ back to the bounding box. */
async function buildMesh(data, what, material) {
  const [positionBytes, indexBytes] = await Promise.all([
    inflate(base64ToBytes(data.positions)),
    inflate(base64ToBytes(data.indices)),
  ]);
  const positions = decodePositions(positionBytes, data.vertices, `${what} positions`);
  const indices = decodeIndices(indexBytes, data.triangles, data.vertices, `${what} indices`);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3, true));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  geometry.boundingBox = new THREE.Box3(new THREE.Vector3(0, 0, 0), new THREE.Vector3(1, 1, 1));
  geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(0.5, 0.5, 0.5), Math.sqrt(3) / 2);
  const mesh = new THREE.Mesh(geometry, material);
  const min = new THREE.Vector3(...data.min), max = new THREE.Vector3(...data.max);
  const size = max.clone().sub(min);
  // A flat box keeps a non-zero scale so the matrix stays invertible.
  for (const axis of ['x', 'y', 'z']) if (!(size[axis] > 0)) size[axis] = 1;
  mesh.position.copy(min);
  mesh.scale.copy(size);
  mesh.name = data.name;
  return mesh;
}

async function start() {
  element('style', { text: CSS }, document.head);
  const dataElement = document.getElementById('swept-data');
  if (!dataElement) throw new Error('no scene data in this page');
  const data = JSON.parse(dataElement.textContent);
  if (data.format === 2) return startDisassembly(data, { element, buildMesh });  // swept disassemble --view
  if (data.format !== 1) throw new Error(`unknown scene data format ${data.format}`);
  document.title = `swept view: ${data.title}`;

  const canvas = element('canvas', { id: 'swept-canvas' }, document.body);
  const panel = element('div', { id: 'swept-panel' }, document.body);
  element('h1', { text: data.title }, panel);
  const row1 = element('div', { class: 'row' }, panel);
  const playButton = element('button', { id: 'swept-play', text: 'Play' }, row1);
  element('label', { for: 'swept-speed', text: 'speed' }, row1);
  const speedSelect = element('select', { id: 'swept-speed' }, row1);
  for (const v of [0.1, 0.25, 0.5, 1, 2, 4]) element('option', { value: String(v), text: `${v}×` }, speedSelect);
  speedSelect.value = '1';
  const row2 = element('div', { class: 'row' }, panel);
  const scrub = element('input', { id: 'swept-scrub', type: 'range', min: '0', max: '1', step: '0.0001', value: '0' }, row2);
  const row3 = element('div', { class: 'row' }, panel);
  element('label', { for: 'swept-obstacles', text: 'obstacles' }, row3);
  const obstacleSelect = element('select', { id: 'swept-obstacles' }, row3);
  for (const v of ['opaque', 'transparent', 'hidden']) element('option', { value: v, text: v }, obstacleSelect);
  obstacleSelect.value = 'transparent';
  const pairLabel = element('label', {}, row3);
  const pairBox = element('input', { id: 'swept-pair', type: 'checkbox' }, pairLabel);
  pairBox.checked = true;
  pairLabel.append(' closest pair');
  const info = element('div', { id: 'swept-info' }, panel);
  const plotCanvas = element('canvas', { id: 'swept-plot' }, document.body);

  // Multisampling doubles the cost of a frame where WebGL is software-rendered; large scenes
  // go without it so that they stay interactive there.
  const large = data.meshes.obstacles.triangles + data.meshes.body.triangles > 500000;
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: !large, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x1b1d22);

  const obstacleMaterial = new THREE.MeshLambertMaterial({ color: 0x8f9bb3, flatShading: true, side: THREE.DoubleSide });
  const bodyMaterial = new THREE.MeshLambertMaterial({ color: 0xf08a24, flatShading: true, side: THREE.DoubleSide });
  const [obstacleMesh, bodyMesh] = await Promise.all([
    buildMesh(data.meshes.obstacles, 'obstacles', obstacleMaterial),
    buildMesh(data.meshes.body, 'body', bodyMaterial),
  ]);
  scene.add(obstacleMesh);
  const body = new THREE.Group();  // the body frame; its pose is the path's pose
  body.add(bodyMesh);
  scene.add(body);

  const motion = new PathMotion(data.waypoints, data.reference);
  const clearance = data.clearance;

  // Frame everything the body visits and the obstacles.
  const box = new THREE.Box3();
  box.expandByPoint(new THREE.Vector3(...data.meshes.obstacles.min));
  box.expandByPoint(new THREE.Vector3(...data.meshes.obstacles.max));
  const q = new THREE.Quaternion(), t = new THREE.Vector3();
  const bodyBox = new THREE.Box3(new THREE.Vector3(...data.meshes.body.min), new THREE.Vector3(...data.meshes.body.max));
  for (let i = 0; i <= 32; i++) {
    motion.poseAt(i / 32, q, t);
    box.union(bodyBox.clone().applyMatrix4(new THREE.Matrix4().compose(t, q, new THREE.Vector3(1, 1, 1))));
  }
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-9);

  const camera = new THREE.PerspectiveCamera(40, 1, radius / 1000, radius * 100);
  camera.up.set(0, 0, 1);  // CAD convention: z up
  const direction = new THREE.Vector3(1.0, -1.5, 0.9).normalize();
  camera.position.copy(center).addScaledVector(direction, radius / Math.sin(THREE.MathUtils.degToRad(20)) * 0.95);
  camera.lookAt(center);
  scene.add(camera);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x303040, 1.2));
  const headlight = new THREE.DirectionalLight(0xffffff, 1.6);
  headlight.position.set(0.3, 0.6, 1);
  camera.add(headlight);
  camera.add(headlight.target);

  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(center);
  controls.screenSpacePanning = true;
  controls.update();

  // Closest-point pair at the current sample.
  const pairGeometry = new THREE.BufferGeometry();
  pairGeometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
  const pairLine = new THREE.Line(pairGeometry, new THREE.LineBasicMaterial({ color: 0xffe04a, depthTest: false }));
  pairLine.renderOrder = 10;
  const dotGeometry = new THREE.SphereGeometry(radius * 0.008, 12, 8);
  const dotA = new THREE.Mesh(dotGeometry, new THREE.MeshBasicMaterial({ color: 0x4ad7ff, depthTest: false }));
  const dotB = new THREE.Mesh(dotGeometry, new THREE.MeshBasicMaterial({ color: 0xffe04a, depthTest: false }));
  dotA.renderOrder = dotB.renderOrder = 11;
  const pair = new THREE.Group();
  pair.add(pairLine, dotA, dotB);
  scene.add(pair);

  const state = { s: 0, playing: false, speed: 1, needsRender: true, frames: 0, fps: 0 };
  const secondsAtOneX = 10;  // the whole path takes this long at speed 1×
  const plot = new ClearancePlot(plotCanvas, clearance, data.unit, (s) => { setPlaying(false); setParameter(s); });

  function applyObstacleMode(mode) {
    obstacleMesh.visible = mode !== 'hidden';
    const transparent = mode === 'transparent';
    obstacleMaterial.transparent = transparent;
    obstacleMaterial.opacity = transparent ? 0.28 : 1;
    obstacleMaterial.depthWrite = !transparent;
    obstacleMaterial.needsUpdate = true;
    obstacleSelect.value = mode;
    state.needsRender = true;
  }

  function setParameter(s) {
    state.s = Math.min(1, Math.max(0, s));
    motion.poseAt(state.s, body.quaternion, body.position);
    body.updateMatrixWorld(true);
    scrub.value = String(state.s);
    const k = plot.sampleIndex(state.s);
    let text = `s = ${state.s.toFixed(4)}`;
    if (k >= 0) {
      const a = clearance.point_a.slice(3 * k, 3 * k + 3), b = clearance.point_b.slice(3 * k, 3 * k + 3);
      const attribute = pairGeometry.getAttribute('position');
      attribute.setXYZ(0, a[0], a[1], a[2]);
      attribute.setXYZ(1, b[0], b[1], b[2]);
      attribute.needsUpdate = true;
      pairGeometry.computeBoundingSphere();
      dotA.position.set(a[0], a[1], a[2]);
      dotB.position.set(b[0], b[1], b[2]);
      text += `   clearance ${clearance.distance[k].toPrecision(4)} ${data.unit}`;
    }
    pair.visible = pairBox.checked && k >= 0;
    info.textContent = `${text}\nobstacles ${data.meshes.obstacles.triangles} triangles, body ${data.meshes.body.triangles}` +
      `\nmin clearance ${clearance.min.toPrecision(4)} ${data.unit} (${clearance.s.length} samples)` +
      `\n${state.fps ? `${state.fps.toFixed(1)} frames/s` : ''}`;
    plot.draw(state.s);
    state.needsRender = true;
  }

  function setPlaying(playing) {
    state.playing = playing;
    if (playing && state.s >= 1) setParameter(0);
    playButton.textContent = playing ? 'Pause' : 'Play';
    state.last = undefined;
  }

  function applyHash() {
    const p = hashParameters();
    if (p.has('speed')) { state.speed = Number(p.get('speed')) || 1; speedSelect.value = String(state.speed); }
    if (p.has('obstacles')) applyObstacleMode(p.get('obstacles'));
    if (p.has('t')) { setPlaying(false); setParameter(Number(p.get('t')) || 0); }
    if (p.has('play')) setPlaying(true);
  }

  playButton.addEventListener('click', () => setPlaying(!state.playing));
  speedSelect.addEventListener('change', () => { state.speed = Number(speedSelect.value); });
  scrub.addEventListener('input', () => { setPlaying(false); setParameter(Number(scrub.value)); });
  obstacleSelect.addEventListener('change', () => applyObstacleMode(obstacleSelect.value));
  pairBox.addEventListener('change', () => setParameter(state.s));
  controls.addEventListener('change', () => { state.needsRender = true; });
  window.addEventListener('hashchange', applyHash);
  window.addEventListener('keydown', (e) => {
    if (e.key === ' ' && e.target === document.body) { e.preventDefault(); setPlaying(!state.playing); }
  });

  function resize() {
    const w = window.innerWidth, h = window.innerHeight;
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    plot.draw(state.s);
    state.needsRender = true;
  }
  window.addEventListener('resize', resize);

  applyObstacleMode('transparent');
  setParameter(0);
  applyHash();
  resize();

  let fpsWindowStart = performance.now(), fpsFrames = 0;
  let resolveFirstFrame;
  const firstFrame = new Promise((resolve) => { resolveFirstFrame = resolve; });

  function renderNow() {
    renderer.render(scene, camera);
    state.frames++;
    state.needsRender = false;
  }

  function frame(now) {
    if (state.playing) {
      if (state.last !== undefined) {
        const s = state.s + ((now - state.last) / 1000) * state.speed / secondsAtOneX;
        setParameter(Math.min(1, s));
        if (s >= 1) setPlaying(false);
      }
      state.last = now;
    }
    controls.update();
    if (state.needsRender || state.playing) {
      renderNow();
      fpsFrames++;
    }
    if (now - fpsWindowStart >= 1000) {
      state.fps = fpsFrames > 1 ? (fpsFrames * 1000) / (now - fpsWindowStart) : state.fps;
      fpsWindowStart = now;
      fpsFrames = 0;
    }
    if (state.frames === 1) {
      document.documentElement.dataset.sweptReady = '1';
      resolveFirstFrame();
    }
    requestAnimationFrame(frame);
  }
  requestAnimationFrame(frame);

  // For tests and scripting.
  window.sweptView = {
    firstFrame,
    get parameter() { return state.s; },
    get frames() { return state.frames; },
    get fps() { return state.fps; },
    /** Moves the body to parameter s and renders that frame at once. */
    show(s) { setPlaying(false); setParameter(s); renderNow(); },
    play(speed = 1) { state.speed = speed; setPlaying(true); },
    pause() { setPlaying(false); },
    /** The camera's position in the world (for checking the orbit controls). */
    cameraPosition() { return camera.position.toArray(); },
    /** The body's screen-space box in CSS pixels of the canvas: {left, top, right, bottom}. */
    bodyScreenBox() {
      const b = bodyBox.clone().applyMatrix4(body.matrixWorld);
      const r = canvas.getBoundingClientRect();
      let left = Infinity, top = Infinity, right = -Infinity, bottom = -Infinity;
      for (let i = 0; i < 8; i++) {
        const p = new THREE.Vector3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z).project(camera);
        const x = (p.x + 1) / 2 * r.width, y = (1 - p.y) / 2 * r.height;
        left = Math.min(left, x); right = Math.max(right, x); top = Math.min(top, y); bottom = Math.max(bottom, y);
      }
      return { left, top, right, bottom };
    },
  };
}

start().catch((error) => {
  const e = document.createElement('div');
  e.id = 'swept-error';
  e.textContent = `swept view: ${error.message}`;
  document.body.appendChild(e);
  document.documentElement.dataset.sweptError = error.message;
  console.error(error);
});
