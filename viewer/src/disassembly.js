// The disassembly page (`swept disassemble --view`, scene data format 2): every part at its
// mounted pose, the removals played one after the other along their paths; a part that has left
// fades. The parameter runs over [0, steps]: step k plays while it is in [k, k + 1]. At the end
// (u = steps), the parts that stay show their blocking graph: one red arrow per direction tried,
// from the part's centre, and the panel names the parts that block each direction.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { PathMotion } from './path.js';

const PALETTE = [0xf08a24, 0x4ab3f0, 0x7bd15a, 0xe0508a, 0xb58cf0, 0xf0d24a, 0x4ae0c4, 0xf06a4a];

export async function startDisassembly(data, { element, buildMesh }) {
  document.title = `swept disassemble: ${data.title}`;
  const canvas = element('canvas', { id: 'swept-canvas' }, document.body);
  const panel = element('div', { id: 'swept-panel' }, document.body);
  element('h1', { text: data.title }, panel);
  const row1 = element('div', { class: 'row' }, panel);
  const playButton = element('button', { id: 'swept-play', text: 'Play' }, row1);
  const row2 = element('div', { class: 'row' }, panel);
  const steps = data.steps.length;
  const scrub = element('input', { id: 'swept-scrub', type: 'range', min: '0', max: String(Math.max(steps, 1)),
    step: '0.001', value: '0' }, row2);
  const info = element('div', { id: 'swept-info' }, panel);

  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x1b1d22);

  const materials = [], groups = [];
  const meshes = await Promise.all(data.parts.map((p, i) => {
    const m = new THREE.MeshLambertMaterial({ color: p.fixed ? 0x8f9bb3 : PALETTE[i % PALETTE.length],
      flatShading: true, side: THREE.DoubleSide, transparent: true, opacity: 1 });
    materials.push(m);
    return buildMesh(p.mesh, p.name, m);
  }));
  const box = new THREE.Box3();
  meshes.forEach((mesh, i) => {
    const g = new THREE.Group();  // the part's frame: the world at its mounted pose
    g.add(mesh);
    scene.add(g);
    groups.push(g);
    box.expandByPoint(new THREE.Vector3(...data.parts[i].mesh.min));
    box.expandByPoint(new THREE.Vector3(...data.parts[i].mesh.max));
  });
  const motions = data.steps.map((s) => new PathMotion(s.waypoints, s.reference));
  // Frame the assembly and where the parts go.
  const q = new THREE.Quaternion(), t = new THREE.Vector3();
  data.steps.forEach((s, k) => {
    motions[k].poseAt(1, q, t);
    for (const i of s.parts) {
      const m = data.parts[i].mesh;
      box.union(new THREE.Box3(new THREE.Vector3(...m.min), new THREE.Vector3(...m.max))
        .applyMatrix4(new THREE.Matrix4().compose(t, q, new THREE.Vector3(1, 1, 1))));
    }
  });
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-9);
  const camera = new THREE.PerspectiveCamera(40, 1, radius / 1000, radius * 100);
  camera.up.set(0, 0, 1);
  camera.position.copy(center).addScaledVector(new THREE.Vector3(1.0, -1.5, 0.9).normalize(), radius * 2.8);
  camera.lookAt(center);
  scene.add(camera);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x303040, 1.2));
  const headlight = new THREE.DirectionalLight(0xffffff, 1.6);
  headlight.position.set(0.3, 0.6, 1);
  camera.add(headlight);
  camera.add(headlight.target);
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(center);
  controls.update();

  // The blocking graph of the parts that stay (data.blocking; pages written before it had none).
  const blocking = [];
  const arrows = new THREE.Group();
  for (const b of data.blocking ?? []) {
    const partBox = new THREE.Box3();
    for (const i of b.parts) {
      partBox.expandByPoint(new THREE.Vector3(...data.parts[i].mesh.min));
      partBox.expandByPoint(new THREE.Vector3(...data.parts[i].mesh.max));
    }
    const from = partBox.getCenter(new THREE.Vector3());
    const length = Math.max(partBox.getSize(new THREE.Vector3()).length() * 0.6, radius * 0.15);
    for (const d of b.directions) {
      const dir = new THREE.Vector3(...d.direction).normalize();
      const arrow = new THREE.ArrowHelper(dir, from, length, 0xff3030, length * 0.25, length * 0.12);
      arrow.line.material.depthTest = false;
      arrow.cone.material.depthTest = false;
      arrow.renderOrder = 10;
      arrows.add(arrow);
      blocking.push({ parts: b.parts.map((i) => data.parts[i].name), direction: d.direction,
        blockers: d.blockers.map((i) => data.parts[i].name) });
    }
  }
  scene.add(arrows);
  const blockingText = (() => {
    const fmt = (d) => {
      const axes = ['x', 'y', 'z'];
      const k = d.findIndex((c) => Math.abs(Math.abs(c) - 1) < 1e-9);
      return k >= 0 && d.filter((c) => c === 0).length === 2 ? `${d[k] > 0 ? '+' : '−'}${axes[k]}` :
        `(${d.map((c) => c.toFixed(2)).join(', ')})`;
    };
    const lines = [];
    for (const b of data.blocking ?? []) {
      const name = b.parts.map((i) => data.parts[i].name).join(' + ');
      const per = b.directions.map((d) => `  ${fmt(d.direction)} by ${d.blockers.length ?
        d.blockers.map((i) => data.parts[i].name).join(', ') : 'none alone'}`);
      const shown = 10;  // one line per direction, the panel stays readable
      lines.push(`${name} blocked:`, ...per.slice(0, shown));
      if (per.length > shown) lines.push(`  … ${per.length - shown} more directions`);
    }
    return lines.join('\n');
  })();

  const state = { u: 0, playing: false, needsRender: true, frames: 0 };
  const secondsPerStep = 2;

  function setParameter(u) {
    state.u = Math.min(steps, Math.max(0, u));
    const current = Math.min(Math.floor(state.u), steps - 1);
    data.steps.forEach((s, k) => {
      const local = k < current ? 1 : k > current ? 0 : state.u - k;
      motions[k].poseAt(local, q, t);
      // Fades over the last fifth of its own step, then stays faint.
      const opacity = local < 0.8 ? 1 : 1 - 0.85 * Math.min(1, (local - 0.8) / 0.2);
      for (const i of s.parts) {
        groups[i].quaternion.copy(q);
        groups[i].position.copy(t);
        materials[i].opacity = opacity;
        materials[i].depthWrite = opacity >= 1;
      }
    });
    scrub.value = String(state.u);
    const s = data.steps[current];
    // The blocking graph holds once every removal is done.
    arrows.visible = state.u >= steps;
    info.textContent = (steps === 0 ? 'nothing comes out' :
      `step ${current + 1} of ${steps}: ${s.parts.map((i) => data.parts[i].name).join(' + ')} (${s.method})`) +
      `\n${data.complete ? 'complete' : `not complete: ${data.blocked.join(', ')} stay`}` +
      (arrows.visible && blockingText ? `\n${blockingText}` : '');
    state.needsRender = true;
  }
  function setPlaying(playing) {
    state.playing = playing;
    if (playing && state.u >= steps) setParameter(0);
    playButton.textContent = playing ? 'Pause' : 'Play';
    state.last = undefined;
  }
  playButton.addEventListener('click', () => setPlaying(!state.playing));
  scrub.addEventListener('input', () => { setPlaying(false); setParameter(Number(scrub.value)); });
  controls.addEventListener('change', () => { state.needsRender = true; });
  function resize() {
    const w = window.innerWidth, h = window.innerHeight;
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    state.needsRender = true;
  }
  window.addEventListener('resize', resize);
  setParameter(0);
  resize();
  if (location.hash.includes('play')) setPlaying(true);
  function frame(now) {
    if (state.playing) {
      if (state.last !== undefined) {
        const u = state.u + (now - state.last) / 1000 / secondsPerStep;
        setParameter(u);
        if (u >= steps) setPlaying(false);
      }
      state.last = now;
    }
    controls.update();
    if (state.needsRender || state.playing) {
      renderer.render(scene, camera);
      state.frames++;
      state.needsRender = false;
      if (state.frames === 1) document.documentElement.dataset.sweptReady = '1';
    }
    requestAnimationFrame(frame);
  }
  requestAnimationFrame(frame);
  window.sweptView = {
    get parameter() { return state.u; },
    get frames() { return state.frames; },
    get steps() { return steps; },
    /** The blocking graph drawn at the end: [{parts, direction, blockers}] (names). */
    get blocking() { return blocking; },
    get arrowsVisible() { return arrows.visible; },
    get info() { return info.textContent; },
    show(u) { setPlaying(false); setParameter(u); renderer.render(scene, camera); },
    play() { setPlaying(true); },
  };
}
