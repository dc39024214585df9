// The karkas viewer page script (an ES module; the Rust side inlines it into the page).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const scene_data = JSON.parse(document.getElementById('karkas-scene').textContent);

function bytes(b64) {
  const text = atob(b64);
  const out = new Uint8Array(text.length);
  for (let k = 0; k < text.length; k++) out[k] = text.charCodeAt(k);
  return out.buffer;
}
const floats = (b64) => new Float32Array(bytes(b64));
const uints = (b64) => new Uint32Array(bytes(b64));

const container = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(container.clientWidth, container.clientHeight);
renderer.setClearColor(0xffffff, 1);
container.appendChild(renderer.domElement);

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(35, container.clientWidth / container.clientHeight, 1e-3, 1e7);
camera.up.set(0, 0, 1);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.2));
const headlight = new THREE.DirectionalLight(0xffffff, 1.8);
camera.add(headlight);
headlight.position.set(-0.4, 0.6, 1.0);
scene.add(camera);

// The groups the checkboxes switch.
const groups = {};
function group(key) {
  if (!groups[key]) {
    groups[key] = new THREE.Group();
    scene.add(groups[key]);
  }
  return groups[key];
}

function polyline(array, colour) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(array, 3));
  return new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: colour }));
}

const palette = [0xd62728, 0x1f77b4, 0x2ca02c, 0x9467bd, 0xff7f0e, 0x8c564b];
const names = [];

scene_data.surfaces.forEach((s, k) => {
  const positions = floats(s.mesh.positions);
  if (positions.length > 0) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(floats(s.mesh.normals), 3));
    geometry.setIndex(new THREE.BufferAttribute(uints(s.mesh.indices), 1));
    const material = new THREE.MeshStandardMaterial({
      color: 0xb8c8e0, roughness: 0.55, metalness: 0.05, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    });
    group('surfaces').add(new THREE.Mesh(geometry, material));
    const wire = new THREE.LineSegments(
      new THREE.WireframeGeometry(geometry),
      new THREE.LineBasicMaterial({ color: 0x51627a, transparent: true, opacity: 0.35 }));
    group('wireframe').add(wire);
  }
  s.net.forEach((line) => group('control net').add(polyline(floats(line), 0x333333)));
  s.isolines.forEach((line) => group('isolines').add(polyline(floats(line), 0x1f5fbf)));
  names.push(s.name);
});

scene_data.curves.forEach((c, k) => {
  group('curves').add(polyline(floats(c.points), palette[k % palette.length]));
  names.push(c.name);
});

const points = floats(scene_data.points);
if (points.length > 0) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(points, 3));
  group('input points').add(new THREE.Points(geometry,
    new THREE.PointsMaterial({ color: 0x111111, size: 6, sizeAttenuation: false })));
}

// Checkboxes, one per group present; the wireframe starts hidden.
const toggles = document.getElementById('toggles');
for (const key of ['surfaces', 'wireframe', 'control net', 'isolines', 'curves', 'input points']) {
  if (!groups[key]) continue;
  const label = document.createElement('label');
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.id = 'toggle-' + key.replace(' ', '-');
  box.checked = key !== 'wireframe';
  groups[key].visible = box.checked;
  box.addEventListener('change', () => { groups[key].visible = box.checked; render(); });
  label.appendChild(box);
  label.appendChild(document.createTextNode(' ' + key));
  toggles.appendChild(label);
}
document.getElementById('names').textContent =
  names.filter((n) => n && n !== scene_data.title).join(', ');
const c = scene_data.centre;
if (c[0] !== 0 || c[1] !== 0 || c[2] !== 0) {
  document.getElementById('shift').textContent =
    'coordinates shown relative to (' + c.map((v) => v.toPrecision(6)).join(', ') + ')';
}

// Frame everything: look from the azimuth 45 deg, elevation 30 deg direction.
const box = new THREE.Box3();
for (const g of Object.values(groups)) box.expandByObject(g);
if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
const sphere = box.getBoundingSphere(new THREE.Sphere());
const radius = Math.max(sphere.radius, 1e-9);
const distance = radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2)) * 1.05;
let direction = new THREE.Vector3(Math.cos(Math.PI / 6) * Math.cos(Math.PI / 4),
  Math.cos(Math.PI / 6) * Math.sin(Math.PI / 4), Math.sin(Math.PI / 6));
// A flat scene (a planar curve, say) in the x-y plane: look straight down, y up.
const size = box.getSize(new THREE.Vector3());
if (size.z <= 1e-9 * Math.max(size.x, size.y)) {
  direction = new THREE.Vector3(0, 0, 1);
  camera.up.set(0, 1, 0);
}
camera.position.copy(sphere.center).addScaledVector(direction, distance);
camera.near = distance / 1000;
camera.far = distance * 100;
camera.lookAt(sphere.center);
camera.updateProjectionMatrix();
// Move in until the box's corners fill 80% of the view (perspective: repeat to settle).
for (let pass = 0; pass < 3; pass++) {
  camera.updateMatrixWorld();
  let reach = 0;
  for (let k = 0; k < 8; k++) {
    const corner = new THREE.Vector3(k & 1 ? box.max.x : box.min.x,
      k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z).project(camera);
    reach = Math.max(reach, Math.abs(corner.x), Math.abs(corner.y));
  }
  if (!(reach > 0) || !isFinite(reach)) break;
  const d = camera.position.distanceTo(sphere.center) * Math.min(Math.max(reach / 0.8, 0.2), 5);
  camera.position.copy(sphere.center).addScaledVector(direction, d);
}

const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(sphere.center);
controls.update();
controls.addEventListener('change', render);

function render() { renderer.render(scene, camera); }
window.addEventListener('resize', () => {
  camera.aspect = container.clientWidth / container.clientHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(container.clientWidth, container.clientHeight);
  render();
});
render();
document.body.dataset.rendered = 'true';
