// The segment's layout in 3-D: the same layout.glb the page downloads, in three.js (served from
// the page's own vendor/three, nothing from the network), orbit and zoom, a façade seen from the
// street and a floor from eye height, and a click on an element shows its ID, value and
// material. report.js announces each new layout.glb with showLayout3d(src).
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const EYE = 1.6;  // m: where a person's eyes are
const box = document.getElementById("view3d");
const info = document.getElementById("view3d-info");
const caption = document.getElementById("view3d-caption");
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
renderer.setClearColor(0xf4f6f8, 1);
box.append(renderer.domElement);
const scene = new THREE.Scene();
scene.add(new THREE.HemisphereLight(0xffffff, 0x808080, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(-3, 8, 5);
scene.add(sun);
const camera = new THREE.PerspectiveCamera(50, 4 / 3, 0.05, 2000);
const controls = new OrbitControls(camera, renderer.domElement);
// The camera stays above the ground: however far it is dragged or zoomed, its eye is at least
// ABOVE over the model's lowest point (a drag that went under the paving showed it from below).
const ABOVE = 0.3;  // m
let ground = 0;
function keepAboveGround() {
  const distance = camera.position.distanceTo(controls.target);
  if (!(distance > 0)) return;
  // The polar angle (from straight up) at which the eye would sink below ground + ABOVE.
  const lowest = (ground + ABOVE - controls.target.y) / distance;
  controls.maxPolarAngle = lowest <= -1 ? Math.PI : lowest >= 1 ? 0 : Math.acos(lowest);
}
controls.addEventListener("start", keepAboveGround);
controls.addEventListener("change", () => {
  keepAboveGround();
  render();
});
controls.minDistance = 0.2;
let model = null;
let loading = 0;  // the latest model asked for
// What the page's tests read: the model shown, how much of the picture it covers, the eye's
// height over the model's lowest point.
window.view3d = { src: null, loads: 0, drawn: 0, error: null, readIn: null, pointOnElement, model: () => model,
                  eyeAboveGround: () => camera.position.y - ground };

function size() {
  const w = box.clientWidth || 600;
  const h = Math.round(w * 0.62);
  renderer.setSize(w, h, false);
  renderer.domElement.style.width = "100%";
  renderer.domElement.style.height = "auto";
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}

function render() {
  renderer.render(scene, camera);
}

// The share of the picture that is not background.
function drawnShare() {
  const gl = renderer.getContext();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const pixels = new Uint8Array(w * h * 4);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let drawn = 0;
  for (let i = 0; i < pixels.length; i += 16)
    if (Math.abs(pixels[i] - 0xf4) + Math.abs(pixels[i + 1] - 0xf6) + Math.abs(pixels[i + 2] - 0xf8) > 12) drawn++;
  return drawn / (pixels.length / 16);
}

// A façade (standing up) from the street, a floor from eye height at its near edge, a whole
// building (its scene says so) from above its south-west corner.
function frame(root) {
  const bounds = new THREE.Box3().setFromObject(root);
  const s = bounds.getSize(new THREE.Vector3());
  const c = bounds.getCenter(new THREE.Vector3());
  const reach = Math.max(s.x, s.y, s.z, 0.1);
  const upright = s.y > 0.5 * Math.max(s.x, s.z);
  camera.near = reach / 500;
  camera.far = reach * 20;
  if (root.userData && root.userData.building) {
    const away = reach / (2 * Math.tan(THREE.MathUtils.degToRad(25))) * 1.1;
    camera.position.set(c.x - away * 0.55, c.y + away * 0.5, c.z + away * 0.75);
    controls.target.set(c.x, c.y, c.z);
  } else if (upright) {
    const away = Math.max(s.x / camera.aspect, s.y) / (2 * Math.tan(THREE.MathUtils.degToRad(25))) * 1.15;
    camera.position.set(c.x + s.x * 0.15, Math.min(EYE, bounds.max.y), bounds.max.z + away);
    controls.target.set(c.x, c.y, c.z);
  } else {
    // Standing a step back from the near edge, looking a third of the way across.
    camera.position.set(c.x - s.x * 0.1, bounds.max.y + EYE, bounds.max.z + Math.max(1.5, s.z * 0.08));
    controls.target.set(c.x, bounds.max.y, bounds.max.z - s.z * 0.3);
  }
  ground = bounds.min.y;
  camera.far = Math.max(camera.far, reach * 40);  // zoomed out, the model stays in view
  controls.maxDistance = reach * 10;
  camera.updateProjectionMatrix();
  keepAboveGround();
  controls.update();
}

// Back to the first view of the model.
document.getElementById("view3d-reset").addEventListener("click", () => {
  if (!model) return;
  frame(model);
  render();
});

// The element under a point of the canvas: the nearest named node holding its value.
function elementAt(clientX, clientY) {
  if (!model) return null;
  const r = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
  const ray = new THREE.Raycaster();
  ray.setFromCamera(ndc, camera);
  for (const hit of ray.intersectObject(model, true)) {
    let o = hit.object;
    while (o && !(o.userData && o.userData.value !== undefined)) o = o.parent;
    if (!o) continue;
    // The model names each value's material "value N label" (a park's element: its type).
    const name = (hit.object.material && hit.object.material.name) || "";
    const material = name.replace(/^value \d+ /, "");
    return { id: o.name, value: o.userData.value, material, curds: o.userData.curds || [] };
  }
  return null;
}

// For the page's tests: the middle of an element's top face as the canvas shows it (page
// coordinates), where a click finds that element again, and its ID.
function pointOnElement() {
  if (!model) return null;
  const r = renderer.domElement.getBoundingClientRect();
  for (let k = 0; k < 400; ++k) {
    const x = r.left + r.width * (0.2 + 0.6 * ((k % 20) / 19));
    const y = r.top + r.height * (0.9 - 0.6 * (Math.floor(k / 20) / 19));  // nearest first
    const e = elementAt(x, y);
    if (!e) continue;
    const bounds = new THREE.Box3().setFromObject(model.getObjectByName(e.id));
    const top = bounds.getCenter(new THREE.Vector3());
    top.y = bounds.max.y;
    top.project(camera);
    // Whole pixels, as a click reports them.
    const px = Math.round(r.left + (top.x + 1) / 2 * r.width), py = Math.round(r.top + (1 - top.y) / 2 * r.height);
    const again = elementAt(px, py);
    if (again && again.id === e.id) return { x: px, y: py, id: e.id };
  }
  return null;
}

renderer.domElement.addEventListener("click", (event) => {
  const e = elementAt(event.clientX, event.clientY);
  info.textContent = e
    ? `${e.id}: value ${e.value}${e.curds.length ? " (" + e.curds.join(" + ") + ")" : ""}, ${e.material || "no material"}`
    : "Click an element to see its ID, value and material.";
  info.dataset.id = e ? e.id : "";
});

// layout.glb is fetched and read in a worker (glb_worker.js); here the three.js objects are
// made from its arrays a slice at a time, yielding to the page between slices, so that a 2-D
// redraw that arrives meanwhile is drawn at once.
const glbWorker = new Worker("glb_worker.js");
const glbWaiting = new Map();
let glbIds = 0;
glbWorker.onmessage = ({ data }) => {
  const waiting = glbWaiting.get(data.id);
  glbWaiting.delete(data.id);
  if (waiting) waiting(data);
};
function fetchGlb(src) {
  for (const [id, waiting] of glbWaiting) waiting({ id, aborted: true });
  glbWaiting.clear();
  const id = ++glbIds;
  return new Promise((resolve) => {
    glbWaiting.set(id, resolve);
    glbWorker.postMessage({ id, url: new URL(src, location.href).href });
  });
}

const SLICE_MS = 6;
const yieldToPage = () =>
  globalThis.scheduler && scheduler.yield ? scheduler.yield() : new Promise((r) => setTimeout(r, 0));

function material(m) {
  const made = new THREE.MeshStandardMaterial({
    metalness: m.metallic, roughness: m.roughness, opacity: m.colour[3],
    transparent: m.blend, depthWrite: !m.blend, side: m.doubleSided ? THREE.DoubleSide : THREE.FrontSide });
  made.color.setRGB(m.colour[0], m.colour[1], m.colour[2], THREE.LinearSRGBColorSpace);
  made.name = m.name;
  return made;
}

// Each mesh's primitives as [geometry, material] pairs, sharing the worker's buffer.
function meshParts(scene, buffer) {
  const materials = scene.materials.map(material);
  const fallback = new THREE.MeshStandardMaterial({ metalness: 1, roughness: 1 });
  const parts = [];
  const rows = scene.primitives;
  const INDEX = { 5121: Uint8Array, 5123: Uint16Array, 5125: Uint32Array };
  for (let r = 0; r < rows.length; r += 9) {
    const [m, po, pc, no, io, ic, it, mat] = rows.subarray(r, r + 8);
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(buffer, po, pc * 3), 3));
    if (no >= 0) g.setAttribute("normal", new THREE.BufferAttribute(new Float32Array(buffer, no, pc * 3), 3));
    if (io >= 0) g.setIndex(new THREE.BufferAttribute(new INDEX[it](buffer, io, ic), 1));
    const used = mat >= 0 ? materials[mat] : fallback;
    if (no < 0) used.flatShading = true;
    (parts[m] ||= []).push([g, used]);
  }
  return parts;
}

// The model as three.js's loader would make it: a node with one primitive is that mesh, one
// with several a group of them; names and extras (userData) as the glb has them. Null when a
// newer model was asked for meanwhile.
async function buildModel(scene, buffer, stillWanted) {
  const parts = meshParts(scene, buffer);
  const root = new THREE.Group();
  root.userData = JSON.parse(scene.sceneExtras);
  const made = new Array(scene.mesh.length);
  let deadline = performance.now() + SLICE_MS;
  for (let i = 0; i < made.length; ++i) {
    const own = scene.mesh[i] >= 0 ? parts[scene.mesh[i]] || [] : [];
    let o;
    if (own.length === 1) o = new THREE.Mesh(own[0][0], own[0][1]);
    else {
      o = new THREE.Group();
      for (const [g, m] of own) o.add(new THREE.Mesh(g, m));
    }
    if (scene.names[i]) {
      o.name = THREE.PropertyBinding.sanitizeNodeName(scene.names[i]);
      o.userData.name = scene.names[i];
    }
    if (scene.extras[i]) Object.assign(o.userData, JSON.parse(scene.extras[i]));
    o.matrix.fromArray(scene.matrix, i * 16);
    o.matrix.decompose(o.position, o.quaternion, o.scale);
    (scene.parent[i] < 0 ? root : made[scene.parent[i]]).add(o);
    made[i] = o;
    if ((i & 127) === 127 && performance.now() > deadline) {
      await yieldToPage();
      if (!stillWanted()) return null;
      deadline = performance.now() + SLICE_MS;
    }
  }
  return root;
}

// The GPU's copies of a model no longer shown.
function dispose(root) {
  root.traverse((o) => {
    if (!o.isMesh) return;
    o.geometry.dispose();
    for (const m of [].concat(o.material)) m.dispose();
  });
}

async function show(src) {
  if (!src || window.view3d.src === src) return;
  const wanted = ++loading;
  const stillWanted = () => wanted === loading;
  caption.textContent = "Loading the layout in 3-D…";
  box.classList.add("stale");
  try {
    const answer = await fetchGlb(src);
    if (answer.aborted || !stillWanted()) return;
    if (answer.error) throw new Error(answer.error);
    let root;
    if (answer.scene) {
      root = await buildModel(answer.scene, answer.buffer, stillWanted);
      window.view3d.readIn = "worker";
    } else {
      root = (await new GLTFLoader().parseAsync(answer.buffer, "")).scene;
      window.view3d.readIn = "page: " + answer.unsupported;
    }
    if (!root || !stillWanted()) return;
    if (model) {
      scene.remove(model);
      dispose(model);
    }
    model = root;
    scene.add(model);
    size();
    frame(model);
    render();
    window.view3d.src = src;
    window.view3d.loads += 1;
    window.view3d.drawn = drawnShare();
    window.view3d.error = null;
    box.classList.remove("stale");
    caption.textContent =
      "The same layout.glb in 3-D: drag to turn (the eye stays above ground), scroll to zoom, " +
      "click an element; Reset view goes back to this view";
  } catch (err) {
    window.view3d.error = String(err.message || err);
    caption.textContent = "The layout could not be shown in 3-D: " + window.view3d.error;
  }
}

window.addEventListener("resize", () => { size(); render(); });
window.addEventListener("layout3d", () => show(window.layout3dSrc));
if (window.layout3dSrc) show(window.layout3dSrc);
