// The karkas workbench page script (an ES module; web/build.py inlines it into the page).
// Curves: the points on a 2-D canvas with each method's curve and curvature comb, and the
// curvature against arc length below; drag a point or move a slider and everything is
// rebuilt by the library (WebAssembly). Grids and networks: the surface in 3-D with a
// section by a movable plane. Lofts: a sections table and its profiles lofted into a wing in
// 3-D; a section's chord, twist and leading edge move with sliders and the loft is rebuilt.
// Exports go through the command line's writers.
import init, * as K from 'karkas-wasm';
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const $ = (id) => document.querySelector(`[data-testid="${id}"]`);
const METHODS = [
  ['ll', 'LL', '#1f77b4', true],
  ['ll-interpolate', 'interpolating LL', '#9467bd', false],
  ['spline', 'cubic spline', '#2ca02c', true],
  ['fit', 'defect-2 fit', '#d62728', true],
];
const SAMPLES = 400;
const CURVE_EXPORTS = ['step', 'iges', 'dxf', 'csv', 'svg', 'points'];
const SURFACE_EXPORTS = ['step', 'iges', 'obj', 'stl'];

const LOFT_TOLERANCE = 1e-5;
const LOFT_FIELDS = ['x', 'y', 'z', 'chord', 'twist'];

const state = {
  kind: null, name: '', text: '', dim: 2, coords: [], box: null,
  network: null, grid: null, surface: null, mesh: null, loft: null,
  options: {
    order: 3, closed: false, ends: 'not-a-knot', param: 'chord', tolerance: 1e-3, eps: 0,
    corners: '', comb: true, methods: Object.fromEntries(METHODS.map((m) => [m[0], m[3]])),
    'surface-method': 'll', 'network-kind': 'gordon', 'section-axis': 'x', section: 0.5,
    'loft-rule': 'monotone',
  },
  curves: {}, errors: [], lastUpdateMs: 0, dragging: -1,
};

// ---- inputs ----------------------------------------------------------------------------

function stem(name) {
  const base = name.split(/[\\/]/).pop();
  const dot = base.lastIndexOf('.');
  return dot > 0 ? base.slice(0, dot) : base;
}

function showError(message, text) {
  state.errors = message ? [message] : [];
  $('errors').textContent = message || '';
  const lines = $('input-lines');
  lines.textContent = '';
  if (!message || !text) return;
  // "karkas: NAME:LINE: ..." names the offending line, as the command line does.
  const at = message.match(/:(\d+)(?::\d+)?:/);
  const bad = at ? Number(at[1]) : 0;
  const all = text.split(/\r?\n/);
  const from = Math.max(0, bad - 4), to = Math.min(all.length, Math.max(bad + 3, 8));
  for (let k = from; k < to; k++) {
    const div = document.createElement('div');
    div.textContent = `${String(k + 1).padStart(5)}  ${all[k]}`;
    if (k + 1 === bad) {
      div.className = 'bad';
      const why = document.createElement('div');
      why.className = 'why';
      why.textContent = `      ^ ${message}`;
      lines.append(div, why);
    } else {
      lines.append(div);
    }
  }
}

function kindOf(text, name) {
  if (/\.dat$/i.test(name)) return 'curve';
  const first = text.split(/\r?\n/).find((l) => l.trim() && !l.trim().startsWith('#')) || '';
  const head = first.trim().toLowerCase();
  if (/^(i|row)\s*,\s*(j|col)\b/.test(head)) return 'grid';
  if (/^curve\s*,/.test(head)) return 'network';
  if (/^file\s*,/.test(head)) return 'loft';
  return 'curve';
}

const isSurface = (kind) => kind === 'grid' || kind === 'network' || kind === 'loft';

/** Loads the sections table `text` (file `name`) and the profiles it names, looked up by
 * their names in `profiles` (name: text; a name may carry a folder, matched by its last part). */
function loadLoft(text, name, profiles) {
  try {
    const table = K.readSectionsTable(text, name);
    const files = table.files(), lines = Array.from(table.lines());
    const placements = Array.from(table.placements());
    table.free();
    const byName = {};
    for (const [n, t] of Object.entries(profiles)) byName[n.split(/[\\/]/).pop()] = t;
    const coords = [], counts = [];
    files.forEach((file, k) => {
      const at = `${name}: row ${lines[k]} (${file})`;
      const profile = byName[file.split(/[\\/]/).pop()];
      if (profile === undefined) throw new Error(`karkas: error: ${at}: the profile file is missing: drop it with the table`);
      let input;
      try {
        input = K.readCurve(profile, file);
      } catch (e) {
        throw new Error(`karkas: error: ${at}: ${String(e.message || e).replace(/^karkas: error: /, '')}`);
      }
      const dim = input.dim(), c = input.coords();
      input.free();
      if (dim !== 2) throw new Error(`karkas: error: ${at}: a profile has two coordinates (x, y in unit chord), not three`);
      coords.push(...c);
      counts.push(c.length / 2);
    });
    state.loft = {
      files, lines, base: placements, placements: [...placements], selected: 0,
      coords: new Float64Array(coords), counts: new Uint32Array(counts),
      labels: files.map((f, k) => `${name}: row ${lines[k]} (${f})`).join('\n'),
      buildMs: 0, controls: [], deviation: NaN, toleranceMet: false, stations: [], curves: [],
    };
  } catch (e) {
    showError(String(e.message || e), text);
    return false;
  }
  state.kind = 'loft';
  state.name = name;
  state.text = text;
  if (three) three.framed = false;
  showError('');
  setMode();
  fillLoftControls();
  update();
  return state.errors.length === 0;
}

function load(text, name) {
  const kind = kindOf(text, name);
  if (kind === 'loft') return loadLoft(text, name, demoProfiles(name));
  try {
    if (kind === 'grid') {
      state.grid = K.readGrid(text, name);
      state.kind = 'grid';
    } else if (kind === 'network') {
      throw new Error(`karkas: error: ${name}: a curve network needs two files, the u-curves and the v-curves: drop or pick both`);
    } else {
      const input = K.readCurve(text, name);
      state.coords = Array.from(input.coords());
      state.dim = input.dim();
      input.free();
      state.kind = 'curve';
      state.box = null;
      state.fitKnots = null;
    }
  } catch (e) {
    showError(String(e.message || e), text);
    return false;
  }
  state.name = name;
  state.text = text;
  showError('');
  setMode();
  update();
  return true;
}

function loadNetwork(uText, uName, vText, vName) {
  state.network = { uText, uName, vText, vName };
  state.kind = 'network';
  state.name = uName;
  state.text = uText;
  showError('');
  setMode();
  update();
  return state.errors.length === 0;
}

async function loadFiles(files) {
  const list = Array.from(files).sort((a, b) => a.name.localeCompare(b.name));
  const texts = await Promise.all(list.map((f) => f.text()));
  const table = list.findIndex((f, k) => kindOf(texts[k], f.name) === 'loft');
  if (table >= 0) {
    const profiles = Object.fromEntries(list.map((f, k) => [f.name, texts[k]]));
    return loadLoft(texts[table], list[table].name, profiles);
  }
  if (list.length >= 2) {
    // The file whose name says "v" holds the v-curves.
    const v = list.findIndex((f) => /(^|[^a-z])v([^a-z]|$)|v[-_]?curves/i.test(f.name));
    const vi = v >= 0 ? v : 1, ui = vi === 0 ? 1 : 0;
    return loadNetwork(texts[ui], list[ui].name, texts[vi], list[vi].name);
  }
  if (list.length === 1) return load(texts[0], list[0].name);
  return false;
}

// ---- building ----------------------------------------------------------------------------

function freeAll() {
  for (const c of Object.values(state.curves)) c.view?.free();
  state.curves = {};
  state.surface?.free();
  state.surface = null;
}

function corners() {
  return new Float64Array(state.options.corners.split(/[\s,]+/).filter(Boolean).map(Number));
}

function update() {
  const started = performance.now();
  freeAll();
  const errors = [];
  if (state.kind === 'curve') {
    const o = state.options;
    const coords = new Float64Array(state.coords);
    for (const [id, label] of METHODS) {
      if (!o.methods[id]) continue;
      try {
        // While a point is dragged the fit keeps the knots it found for the tolerance (one
        // least-squares fit instead of the knot search); the search runs again when the drag
        // ends, so what is exported is the command line's fit.
        const live = id === 'fit' && state.dragging >= 0 && state.fitKnots;
        const none = new Float64Array(0);
        const view = K.buildCurve(id, coords, state.dim, o.order, o.closed, o.ends, o.param,
          o.tolerance, o.eps, corners(), live ? state.fitKnots : none,
          live ? state.fitStart : none, state.name);
        const breaks = view.knots();
        if (id === 'fit') {
          if (!live) state.fitKnots = breaks;
          state.fitStart = view.parameters();
        }
        // About 1200 samples of the curvature in all, 2 to 12 a piece.
        const perPiece = Math.max(2, Math.min(12, Math.ceil(1200 / Math.max(1, breaks.length - 1))));
        state.curves[id] = { view, samples: view.samples(SAMPLES), profile: view.profile(perPiece) };
      } catch (e) {
        errors.push(`${label}: ${e.message || e}`);
      }
    }
  } else if (state.kind === 'loft') {
    const L = state.loft;
    try {
      const begun = performance.now();
      state.surface = K.buildLoft(L.coords, L.counts, new Float64Array(L.placements),
        state.options['loft-rule'], LOFT_TOLERANCE, L.labels, state.name);
      L.buildMs = performance.now() - begun;
      L.controls = Array.from(state.surface.loftControls());
      L.deviation = state.surface.loftDeviation();
      L.toleranceMet = state.surface.loftToleranceMet();
      L.stations = Array.from(state.surface.loftStations());
      L.curves = Array.from(state.surface.loftSectionCurves());
      state.mesh = { nu: 80, nv: 121, positions: state.surface.samples(80, 121) };
    } catch (e) {
      state.mesh = null;
      L.controls = [];
      errors.push(String(e.message || e));
    }
  } else if (state.kind === 'grid' || state.kind === 'network') {
    try {
      state.surface = state.kind === 'grid'
        ? K.buildGridSurface(state.grid, state.options['surface-method'], state.options.order, state.name)
        : K.buildNetworkSurface(state.network.uText, state.network.uName, state.network.vText,
          state.network.vName, state.options['network-kind']);
      state.mesh = meshOf(state.surface);
    } catch (e) {
      errors.push(String(e.message || e));
    }
  }
  if (errors.length) showError(errors.join('\n'), state.kind === 'curve' || state.kind === 'loft' ? '' : state.text);
  else if (state.errors.length) showError('');
  draw();
  state.lastUpdateMs = performance.now() - started;
  const sizes = Object.entries(state.curves)
    .map(([id, c]) => `${id}: degree ${c.view.degree()}, ${c.view.poles()} poles`).join('; ');
  $('status').textContent = `${state.name}: ${state.kind === 'curve' ? `${state.coords.length / state.dim} points; ${sizes}` : ''} update ${state.lastUpdateMs.toFixed(1)} ms`;
  if (state.kind === 'loft') {
    const L = state.loft;
    $('loft-summary').textContent = L.controls.length
      ? `${L.counts.length} sections; ${L.controls[0]} x ${L.controls[1]} control points; largest section deviation ` +
        `${L.deviation.toExponential(2)} of the chord (tolerance ${LOFT_TOLERANCE}${L.toleranceMet ? ', met' : ', NOT met'}); ` +
        `loft ${L.buildMs.toFixed(1)} ms`
      : 'no loft';
  }
}

// ---- the 2-D view ----------------------------------------------------------------------------

function canvasOf(id) {
  const canvas = $(id).querySelector('canvas');
  const ratio = window.devicePixelRatio || 1;
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width !== Math.round(w * ratio) || canvas.height !== Math.round(h * ratio)) {
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
  }
  const ctx = canvas.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, w, h);
  return { canvas, ctx, w, h };
}

/** Model to screen: the points' box (fixed while dragging), equal scales, 6% margins. */
function viewTransform(w, h) {
  if (!state.box) {
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (let k = 0; k < state.coords.length; k += state.dim) {
      x0 = Math.min(x0, state.coords[k]); x1 = Math.max(x1, state.coords[k]);
      y0 = Math.min(y0, state.coords[k + 1]); y1 = Math.max(y1, state.coords[k + 1]);
    }
    state.box = [x0, y0, x1, y1];
  }
  const [x0, y0, x1, y1] = state.box;
  const size = Math.max(x1 - x0, y1 - y0) || 1;
  const scale = Math.min((w * 0.88) / Math.max(x1 - x0, size * 1e-3), (h * 0.88) / Math.max(y1 - y0, size * 1e-3));
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  return {
    scale, size,
    x: (x) => w / 2 + (x - cx) * scale,
    y: (y) => h / 2 - (y - cy) * scale,
    back: (px, py) => [cx + (px - w / 2) / scale, cy - (py - h / 2) / scale],
  };
}

function percentile(values, p) {
  const v = values.filter(Number.isFinite).sort((a, b) => a - b);
  return v.length ? v[Math.min(v.length - 1, Math.floor(p * v.length))] : 0;
}

function draw() {
  const is3d = isSurface(state.kind);
  $('view').style.display = is3d ? 'none' : 'block';
  $('view3d').style.display = is3d ? 'block' : 'none';
  $('curvature-plot').style.display = is3d ? 'none' : 'block';
  document.getElementById('main').style.gridTemplateRows = is3d ? '1fr' : '1fr 220px';
  if (is3d) {
    drawSurface();
    drawPlot([]);
    return;
  }
  const { ctx, w, h } = canvasOf('view');
  if (state.kind !== 'curve') return;
  const T = viewTransform(w, h);
  const shown = METHODS.filter(([id]) => state.curves[id]);
  // One comb scale for all curves: the 90th percentile of |κ| is 8% of the view.
  const all = shown.flatMap(([id]) => {
    const s = state.curves[id].samples, out = [];
    for (let k = 7; k < s.length; k += 9) out.push(Math.abs(s[k]));
    return out;
  });
  const p90 = percentile(all, 0.9);
  const comb = p90 > 0 ? (0.08 * T.size) / p90 : 0;
  for (const [id, , color] of shown) {
    const s = state.curves[id].samples;
    if (state.options.comb && comb > 0) {
      ctx.strokeStyle = color + '55';
      ctx.lineWidth = 1;
      ctx.beginPath();
      const tips = [];
      for (let k = 0; k < s.length; k += 9) {
        const [x, y, dx, dy, kappa] = [s[k + 1], s[k + 2], s[k + 4], s[k + 5], s[k + 7]];
        const n = Math.hypot(dx, dy) || 1;
        // Teeth longer than a quarter of the view (a kink, a dragged point) are cut there.
        const length = Math.max(-0.25 * T.size, Math.min(0.25 * T.size, kappa * comb));
        const tx = x + (dy / n) * length, ty = y - (dx / n) * length;
        if (k % 36 === 0) { ctx.moveTo(T.x(x), T.y(y)); ctx.lineTo(T.x(tx), T.y(ty)); }
        tips.push([tx, ty]);
      }
      ctx.stroke();
      ctx.beginPath();
      tips.forEach(([x, y], i) => (i ? ctx.lineTo(T.x(x), T.y(y)) : ctx.moveTo(T.x(x), T.y(y))));
      ctx.stroke();
    }
    ctx.strokeStyle = color;
    ctx.lineWidth = 1.6;
    ctx.beginPath();
    for (let k = 0; k < s.length; k += 9) {
      const [x, y] = [T.x(s[k + 1]), T.y(s[k + 2])];
      k ? ctx.lineTo(x, y) : ctx.moveTo(x, y);
    }
    ctx.stroke();
  }
  ctx.fillStyle = '#222';
  for (let k = 0; k < state.coords.length; k += state.dim) {
    const r = k / state.dim === state.dragging ? 4.5 : 2.5;
    ctx.beginPath();
    ctx.arc(T.x(state.coords[k]), T.y(state.coords[k + 1]), r, 0, 2 * Math.PI);
    ctx.fill();
  }
  // The legend: methods and the comb's scale.
  ctx.font = '12px system-ui, sans-serif';
  shown.forEach(([, label, color], i) => {
    ctx.fillStyle = color;
    ctx.fillRect(10, 10 + 16 * i, 10, 10);
    ctx.fillStyle = '#222';
    ctx.fillText(label, 26, 19 + 16 * i);
  });
  if (comb > 0 && state.options.comb) {
    ctx.fillText(`comb: curvature ${p90.toPrecision(3)} drawn as ${(0.08 * T.size).toPrecision(3)} (model units)`, 10, h - 10);
  }
  drawPlot(shown);
}

function drawPlot(shown) {
  const { ctx, w, h } = canvasOf('curvature-plot');
  if (!shown.length) return;
  const pad = { l: 56, r: 10, t: 10, b: 26 };
  const values = shown.flatMap(([id]) => {
    const p = state.curves[id].profile, out = [];
    for (let k = 2; k < p.length; k += 3) out.push(Math.abs(p[k]));
    return out;
  });
  const top = 1.3 * percentile(values, 0.95) || 1;
  const px = (f) => pad.l + f * (w - pad.l - pad.r);
  const py = (k) => pad.t + (1 - (Math.max(-top, Math.min(top, k)) + top) / (2 * top)) * (h - pad.t - pad.b);
  ctx.strokeStyle = '#bbb';
  ctx.beginPath(); ctx.moveTo(px(0), py(0)); ctx.lineTo(px(1), py(0)); ctx.stroke();
  ctx.fillStyle = '#444';
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillText(top.toPrecision(3), 4, py(top) + 8);
  ctx.fillText('0', 4, py(0) + 4);
  ctx.fillText((-top).toPrecision(3), 4, py(-top));
  ctx.fillText('curvature against arc length (share of the length)', px(0.3), h - 8);
  for (const [id, , color] of shown) {
    const p = state.curves[id].profile;
    const length = p[p.length - 2] || 1;
    ctx.strokeStyle = color;
    ctx.lineWidth = 1.3;
    ctx.beginPath();
    for (let k = 0; k < p.length; k += 3) {
      const [x, y] = [px(p[k + 1] / length), py(p[k + 2])];
      k ? ctx.lineTo(x, y) : ctx.moveTo(x, y);
    }
    ctx.stroke();
  }
}

// ---- the 3-D view ----------------------------------------------------------------------------

let three = null;

function meshOf(surface) {
  const nu = 60, nv = 60;
  return { nu, nv, positions: surface.samples(nu, nv) };
}

function setupThree() {
  const container = $('view3d');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xffffff, 1);
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e7);
  camera.up.set(0, 0, 1);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.2));
  const light = new THREE.DirectionalLight(0xffffff, 1.6);
  light.position.set(-0.4, 0.6, 1.0);
  camera.add(light);
  scene.add(camera);
  const controls = new OrbitControls(camera, renderer.domElement);
  const group = new THREE.Group();
  scene.add(group);
  three = { renderer, scene, camera, controls, group, framed: false };
  controls.addEventListener('change', () => renderer.render(scene, camera));
}

function drawSurface() {
  if (!three) setupThree();
  const { renderer, scene, camera, controls, group } = three;
  const container = $('view3d');
  renderer.setSize(container.clientWidth, container.clientHeight);
  camera.aspect = container.clientWidth / Math.max(1, container.clientHeight);
  camera.updateProjectionMatrix();
  for (const child of [...group.children]) { group.remove(child); child.geometry?.dispose(); }
  if (!state.mesh) { renderer.render(scene, camera); return; }
  const { nu, nv, positions } = state.mesh;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  const index = [];
  for (let i = 0; i + 1 < nu; i++) {
    for (let j = 0; j + 1 < nv; j++) {
      const a = i * nv + j, b = a + nv;
      index.push(a, b, a + 1, a + 1, b, b + 1);
    }
  }
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  geometry.computeBoundingBox();
  group.add(new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color: 0x8fb3d9, side: THREE.DoubleSide, roughness: 0.6 })));
  const box = geometry.boundingBox;
  if (state.kind === 'loft') drawLoftSections();
  else drawSectionPlane(box);
  if (!three.framed) {
    const size = new THREE.Vector3(); box.getSize(size);
    const centre = new THREE.Vector3(); box.getCenter(centre);
    const r = 0.5 * size.length() || 1;
    camera.position.set(centre.x + 1.6 * r, centre.y - 2.2 * r, centre.z + 1.4 * r);
    controls.target.copy(centre);
    camera.near = r * 1e-3; camera.far = r * 100;
    camera.updateProjectionMatrix();
    controls.update();
    three.framed = true;
  }
  renderer.render(scene, camera);
}

/** A loft's sections: the surface at every station, the chosen one in red. */
function drawLoftSections() {
  const L = state.loft, n = 121;
  if (L.curves.length !== 3 * n * L.counts.length) return;
  L.files.forEach((_, k) => {
    const points = [];
    for (let j = 0; j + 1 < n; j++) {
      const a = 3 * (k * n + j);
      points.push(...L.curves.slice(a, a + 6));
    }
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
    const color = k === L.selected ? 0xd62728 : 0x333333;
    three.group.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial({ color })));
  });
}

/** The section plane and the surface's section by it. */
function drawSectionPlane(box) {
  const { group } = three;
  const axis = { x: 0, y: 1, z: 2 }[state.options['section-axis']];
  const lo = box.min.getComponent(axis), hi = box.max.getComponent(axis);
  const offset = lo + state.options.section * (hi - lo);
  const normal = [0, 0, 0]; normal[axis] = 1;
  try {
    const cut = state.surface.section(normal[0], normal[1], normal[2], offset);
    const points = [];
    let run = [];
    for (let k = 0; k < cut.length; k += 3) {
      if (Number.isNaN(cut[k])) {
        for (let i = 0; i + 1 < run.length; i++) points.push(...run[i], ...run[i + 1]);
        run = [];
      } else run.push([cut[k], cut[k + 1], cut[k + 2]]);
    }
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
    group.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial({ color: 0xd62728 })));
    state.sectionPoints = points.length / 6;
  } catch (e) {
    showError(String(e.message || e), '');
  }
  const size = new THREE.Vector3(); box.getSize(size);
  const centre = new THREE.Vector3(); box.getCenter(centre);
  const plane = new THREE.Mesh(new THREE.PlaneGeometry(1, 1),
    new THREE.MeshBasicMaterial({ color: 0xd62728, transparent: true, opacity: 0.12, side: THREE.DoubleSide, depthWrite: false }));
  const extent = 1.2 * Math.max(size.x, size.y, size.z);
  plane.scale.set(extent, extent, 1);
  plane.position.copy(centre);
  plane.position.setComponent(axis, offset);
  if (axis === 0) plane.rotation.y = Math.PI / 2;
  if (axis === 1) plane.rotation.x = Math.PI / 2;
  group.add(plane);
}

// ---- exports ----------------------------------------------------------------------------

function firstCurve() {
  const id = METHODS.map((m) => m[0]).find((m) => state.curves[m]);
  return id ? [id, state.curves[id]] : [null, null];
}

function exportText(format) {
  const name = stem(state.name || 'karkas');
  if (isSurface(state.kind)) {
    if (!state.surface) throw new Error('karkas: error: no surface to export');
    if (SURFACE_EXPORTS.includes(format)) return state.surface.export(format, name, state.name);
    throw new Error(`karkas: error: a surface exports as ${SURFACE_EXPORTS.join(', ')}`);
  }
  if (format === 'points') {
    const head = state.dim === 3 ? 'x,y,z' : 'x,y';
    const rows = [];
    for (let k = 0; k < state.coords.length; k += state.dim) rows.push(state.coords.slice(k, k + state.dim).join(','));
    return [head, ...rows].join('\n') + '\n';
  }
  const [id, curve] = firstCurve();
  if (!curve) throw new Error('karkas: error: no curve to export');
  if (format === 'svg') {
    const label = METHODS.find((m) => m[0] === id)[1];
    return curve.view.export('svg', `${label}, ${state.coords.length / state.dim} points`, state.name);
  }
  if (CURVE_EXPORTS.includes(format)) return curve.view.export(format, name, state.name);
  throw new Error(`karkas: error: a curve exports as ${CURVE_EXPORTS.join(', ')} (${id})`);
}

function download(format) {
  try {
    const text = exportText(format);
    const ext = format === 'points' ? 'points.csv' : format;
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
    a.download = `${stem(state.name || 'karkas')}.${ext}`;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  } catch (e) {
    showError(String(e.message || e), '');
  }
}

// ---- controls ----------------------------------------------------------------------------

function setMode() {
  const surface = isSurface(state.kind);
  document.getElementById('curve-controls').classList.toggle('hidden', surface);
  document.getElementById('surface-controls').classList.toggle('hidden', !surface || state.kind === 'loft');
  document.getElementById('loft-controls').classList.toggle('hidden', state.kind !== 'loft');
  const select = $('export-format');
  select.textContent = '';
  for (const f of surface ? SURFACE_EXPORTS : CURVE_EXPORTS) select.append(new Option(f === 'points' ? 'points (CSV)' : f.toUpperCase(), f));
}

function setOption(name, value) {
  const o = state.options;
  if (name.startsWith('method-')) o.methods[name.slice(7)] = Boolean(value);
  else if (name in o) o[name] = typeof o[name] === 'number' ? Number(value) : typeof o[name] === 'boolean' ? Boolean(value) : String(value);
  else throw new Error(`unknown option ${name}`);
  state.dragging = -1;
  syncControls();
  update();
}

function syncControls() {
  const o = state.options;
  $('order').value = o.order;
  document.getElementById('order-value').textContent = o.order;
  $('closed').checked = o.closed;
  $('ends').value = o.ends;
  $('param').value = o.param;
  $('tolerance').value = Math.log10(o.tolerance);
  document.getElementById('tolerance-value').textContent = o.tolerance.toPrecision(2);
  $('eps').value = o.eps > 0 ? Math.log10(o.eps) : -8;
  document.getElementById('eps-value').textContent = o.eps > 0 ? o.eps.toPrecision(2) : 'none';
  $('corners').value = o.corners;
  $('comb').checked = o.comb;
  for (const [id] of METHODS) $(`method-${id}`).checked = o.methods[id];
  $('surface-method').value = o['surface-method'];
  $('network-kind').value = o['network-kind'];
  $('section-axis').value = o['section-axis'];
  $('section').value = o.section;
  $('loft-rule').value = o['loft-rule'];
}

// ---- the loft's sections ----------------------------------------------------------------------------

/** The profiles of the demo data beside the sections table `name` (same folder). */
function demoProfiles(name) {
  const folder = name.includes('/') ? name.slice(0, name.lastIndexOf('/') + 1) : '';
  return Object.fromEntries(Object.entries(demos).filter(([n]) => n.startsWith(folder) && n !== name));
}

/** The sliders' ranges around the chosen section's table values, and its values. */
function fillLoftControls() {
  const L = state.loft;
  const select = $('loft-section');
  select.textContent = '';
  L.files.forEach((f, k) => select.append(new Option(`${k + 1}: ${f} (row ${L.lines[k]})`, String(k))));
  select.value = String(L.selected);
  const k = L.selected, base = L.base.slice(6 * k, 6 * k + 6);
  // The wing's size: the largest chord or leading-edge distance from the first section.
  let size = 0;
  for (let i = 0; i < L.files.length; i++) {
    size = Math.max(size, L.base[6 * i + 3]);
    for (let d = 0; d < 3; d++) size = Math.max(size, Math.abs(L.base[6 * i + d] - L.base[d]));
  }
  const range = (id, lo, hi, step) => Object.assign($(id), { min: lo, max: hi, step });
  range('loft-chord', 0.25 * base[3], 2 * base[3], base[3] / 400);
  for (const [d, axis] of ['x', 'y', 'z'].entries()) range(`loft-${axis}`, base[d] - 0.25 * size, base[d] + 0.25 * size, size / 2000);
  syncLoftControls();
}

function syncLoftControls() {
  const L = state.loft, k = L.selected;
  LOFT_FIELDS.forEach((field) => {
    const value = L.placements[6 * k + LOFT_FIELDS.indexOf(field)];
    $(`loft-${field}`).value = value;
    document.getElementById(`loft-${field}-value`).textContent = Number(value).toPrecision(4);
  });
}

/** Sets `field` (`x`, `y`, `z`, `chord`, `twist`) of section `k` and rebuilds the loft. */
function setLoftSection(k, field, value) {
  const L = state.loft;
  if (state.kind !== 'loft' || !(k >= 0 && k < L.files.length) || !LOFT_FIELDS.includes(field)) return false;
  L.placements[6 * k + LOFT_FIELDS.indexOf(field)] = Number(value);
  if (L.selected !== k) { L.selected = k; fillLoftControls(); } else syncLoftControls();
  update();
  return state.errors.length === 0;
}

/** What the page shows of the loft (for tests): the summary and the section curves. */
function loftState() {
  const L = state.loft;
  if (state.kind !== 'loft' || !L) return null;
  const n = 121, sections = [];
  for (let k = 0; 3 * n * (k + 1) <= L.curves.length; k++) {
    const points = [];
    for (let j = 0; j < n; j++) points.push(L.curves.slice(3 * (k * n + j), 3 * (k * n + j) + 3));
    sections.push(points);
  }
  return { sections: L.counts.length, controls: L.controls, deviation: L.deviation,
    toleranceMet: L.toleranceMet, stations: L.stations, placements: [...L.placements],
    selected: L.selected, buildMs: L.buildMs, curves: sections,
    mesh: state.mesh ? { nu: state.mesh.nu, nv: state.mesh.nv, positions: Array.from(state.mesh.positions) } : null };
}

/** Rebuilds the loft `rounds` times, turning the chosen section's twist by 0.1 degrees back
 * and forth as a slider does; the loft's times (ms: median, 95th percentile). */
function benchLoft(rounds = 40) {
  const L = state.loft;
  if (state.kind !== 'loft') throw new Error('load a sections table first');
  const k = L.selected, twist = L.placements[6 * k + 4], times = [];
  for (let r = 0; r < rounds; r++) {
    setLoftSection(k, 'twist', twist + (r % 2 ? 0.1 : -0.1));
    times.push(L.buildMs);
  }
  setLoftSection(k, 'twist', twist);
  const at = (v, p) => [...v].sort((a, b) => a - b)[Math.floor(p * (v.length - 1) + 0.5)];
  return { rounds, sections: L.counts.length, controls: L.controls, median: at(times, 0.5), p95: at(times, 0.95) };
}

function wire() {
  const methods = document.getElementById('methods');
  for (const [id, label, color] of METHODS) {
    const l = document.createElement('label');
    l.innerHTML = `<input type="checkbox" data-testid="method-${id}"> <span class="swatch" style="background:${color}"></span>${label}`;
    methods.append(l);
    l.querySelector('input').addEventListener('change', (e) => setOption(`method-${id}`, e.target.checked));
  }
  $('order').addEventListener('input', (e) => setOption('order', Number(e.target.value)));
  $('closed').addEventListener('change', (e) => setOption('closed', e.target.checked));
  $('ends').addEventListener('change', (e) => setOption('ends', e.target.value));
  $('param').addEventListener('change', (e) => setOption('param', e.target.value));
  $('tolerance').addEventListener('input', (e) => setOption('tolerance', 10 ** Number(e.target.value)));
  $('eps').addEventListener('input', (e) => setOption('eps', Number(e.target.value) <= -8 ? 0 : 10 ** Number(e.target.value)));
  $('corners').addEventListener('change', (e) => setOption('corners', e.target.value));
  $('comb').addEventListener('change', (e) => setOption('comb', e.target.checked));
  $('surface-method').addEventListener('change', (e) => setOption('surface-method', e.target.value));
  $('network-kind').addEventListener('change', (e) => setOption('network-kind', e.target.value));
  $('section-axis').addEventListener('change', (e) => setOption('section-axis', e.target.value));
  $('section').addEventListener('input', (e) => setOption('section', Number(e.target.value)));
  $('loft-rule').addEventListener('change', (e) => setOption('loft-rule', e.target.value));
  $('loft-section').addEventListener('change', (e) => {
    state.loft.selected = Number(e.target.value);
    fillLoftControls();
    draw();
  });
  for (const field of LOFT_FIELDS) {
    $(`loft-${field}`).addEventListener('input', (e) => setLoftSection(state.loft.selected, field, e.target.value));
  }
  $('loft-reset').addEventListener('click', () => {
    state.loft.placements = [...state.loft.base];
    fillLoftControls();
    update();
  });
  $('export').addEventListener('click', () => download($('export-format').value));
  $('file').addEventListener('change', (e) => loadFiles(e.target.files));
  const drop = $('drop');
  for (const type of ['dragenter', 'dragover']) document.body.addEventListener(type, (e) => { e.preventDefault(); drop.classList.add('over'); });
  document.body.addEventListener('dragleave', () => drop.classList.remove('over'));
  document.body.addEventListener('drop', (e) => { e.preventDefault(); drop.classList.remove('over'); loadFiles(e.dataTransfer.files); });
  const select = $('demo');
  for (const name of Object.keys(demos)) select.append(new Option(name, name));
  select.addEventListener('change', () => load(demos[select.value], select.value));
  // Dragging points.
  const canvas = $('view').querySelector('canvas');
  const at = (e) => {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  canvas.addEventListener('pointerdown', (e) => {
    if (state.kind !== 'curve') return;
    const [px, py] = at(e);
    const T = viewTransform(canvas.clientWidth, canvas.clientHeight);
    let best = -1, bestD = 10;
    for (let k = 0; k < state.coords.length; k += state.dim) {
      const d = Math.hypot(T.x(state.coords[k]) - px, T.y(state.coords[k + 1]) - py);
      if (d < bestD) { bestD = d; best = k / state.dim; }
    }
    if (best >= 0) { state.dragging = best; canvas.setPointerCapture(e.pointerId); draw(); }
  });
  canvas.addEventListener('pointermove', (e) => {
    if (state.dragging < 0) return;
    const [px, py] = at(e);
    const T = viewTransform(canvas.clientWidth, canvas.clientHeight);
    const [x, y] = T.back(px, py);
    movePoint(state.dragging, x, y);
  });
  const end = () => { if (state.dragging >= 0) { state.dragging = -1; update(); } };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  window.addEventListener('resize', () => draw());
}

function movePoint(index, x, y) {
  if (state.kind !== 'curve' || index < 0 || index >= state.coords.length / state.dim) return false;
  state.coords[index * state.dim] = x;
  state.coords[index * state.dim + 1] = y;
  update();
  return true;
}

/** Where point `index` is drawn, in the page's CSS pixels (for tests that drag it). */
function pointOnScreen(index) {
  const canvas = $('view').querySelector('canvas');
  const r = canvas.getBoundingClientRect();
  const T = viewTransform(canvas.clientWidth, canvas.clientHeight);
  const k = index * state.dim;
  return [r.left + T.x(state.coords[k]), r.top + T.y(state.coords[k + 1])];
}

function curves() {
  return Object.fromEntries(Object.entries(state.curves).map(([id, c]) => {
    const xy = [];
    for (let k = 0; k < c.samples.length; k += 9) xy.push([c.samples[k + 1], c.samples[k + 2], c.samples[k + 3]]);
    const profile = [];
    for (let k = 0; k < c.profile.length; k += 3) profile.push([c.profile[k + 1], c.profile[k + 2]]);
    return [id, { points: xy, curvature: profile, degree: c.view.degree(), poles: c.view.poles() }];
  }));
}

// ---- the benchmark ----------------------------------------------------------------------------

/** NACA 0012 through `n` points (cosine spacing, from the trailing edge over the top). */
function naca0012(n) {
  const half = Math.floor(n / 2), lines = ['x,y'];
  const y = (x) => 0.6 * (0.2969 * Math.sqrt(x) - 0.126 * x - 0.3516 * x * x + 0.2843 * x ** 3 - 0.1036 * x ** 4);
  for (let k = 0; k < n; k++) {
    const upper = k < half, j = upper ? k : k - half;
    const m = upper ? half : n - half;
    const x = upper ? 0.5 * (1 + Math.cos(Math.PI * j / (m - 1))) : 0.5 * (1 - Math.cos(Math.PI * (j + 1) / m));
    lines.push(`${x},${upper ? y(x) : -y(x)}`);
  }
  return lines.join('\n');
}

/** Drags `drags` points of a `points`-point airfoil, each by `moves` steps as a mouse drag
 * delivers them, with LL, the spline and the fit on; returns the times of the updates during
 * the drags (ms: median, 95th percentile) and of the full rebuild when a drag ends. */
function bench(points = 200, drags = 20, moves = 10) {
  if (!load(naca0012(points), `naca0012-${points}.csv`)) throw new Error(state.errors.join('; '));
  const o = state.options;
  Object.assign(o.methods, { ll: true, 'll-interpolate': false, spline: true, fit: true });
  o.tolerance = 1e-4;
  update();
  const during = [], after = [];
  for (let k = 0; k < drags; k++) {
    const i = 5 + ((k * 37) % (points - 10));
    const [x, y] = [state.coords[i * state.dim], state.coords[i * state.dim + 1]];
    state.dragging = i;
    for (let m = 1; m <= moves; m++) {
      movePoint(i, x, y + (k % 2 ? 1 : -1) * 2e-4 * m);
      during.push(state.lastUpdateMs);
    }
    state.dragging = -1;
    update();
    after.push(state.lastUpdateMs);
  }
  const at = (v, p) => [...v].sort((a, b) => a - b)[Math.floor(p * (v.length - 1) + 0.5)];
  const result = { points: state.coords.length / state.dim, updates: during.length,
    methods: Object.keys(state.curves), median: at(during, 0.5), p95: at(during, 0.95),
    dragEndMedian: at(after, 0.5), wasmBytes: wasm.length,
    pageBytes: document.documentElement.outerHTML.length };
  $('status').textContent = `benchmark: ${result.points} points, ${drags} drags of ${moves} moves, ` +
    `${result.methods.join(', ')}: median ${result.median.toFixed(1)} ms, 95th percentile ` +
    `${result.p95.toFixed(1)} ms per update while dragging, ${result.dragEndMedian.toFixed(1)} ms ` +
    `when a drag ends; WebAssembly ${(wasm.length / 1e6).toFixed(2)} MB`;
  return result;
}

// ---- start ----------------------------------------------------------------------------

const demos = JSON.parse(document.getElementById('karkas-demo').textContent);
const wasm = Uint8Array.from(atob(document.getElementById('karkas-wasm').textContent.trim()), (c) => c.charCodeAt(0));
const ready = init({ module_or_path: wasm }).then(() => {
  wire();
  setMode();
  syncControls();
  const first = Object.keys(demos)[0];
  if (first) load(demos[first], first);
  if (window.location.hash === '#bench') bench();
  return true;
});

window.karkasWorkbench = {
  ready,
  load,
  loadNetwork,
  loadLoft,
  movePoint,
  setLoftSection,
  loft: loftState,
  benchLoft,
  setOption,
  curves,
  pointOnScreen,
  bench,
  export: exportText,
  state: () => ({ kind: state.kind, name: state.name, points: state.coords.length / (state.dim || 1),
    errors: [...state.errors], lastUpdateMs: state.lastUpdateMs, sectionSegments: state.sectionPoints || 0 }),
  wasmBytes: wasm.length,
};
