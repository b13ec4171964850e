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
let loading = null;
// What the page's tests read: the model shown, how much of the picture it covers, the eye's
// height over the model's lowest point.
window.view3d = { src: null, loads: 0, drawn: 0, error: null, pointOnElement,
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

async function show(src) {
  if (!src || window.view3d.src === src) return;
  if (loading) loading.abort();
  loading = new AbortController();
  caption.textContent = "Loading the layout in 3-D…";
  box.classList.add("stale");
  try {
    const response = await fetch(src, { signal: loading.signal });
    if (!response.ok) throw new Error((await response.json()).error || response.statusText);
    const bytes = await response.arrayBuffer();
    const gltf = await new GLTFLoader().parseAsync(bytes, "");
    if (model) scene.remove(model);
    model = gltf.scene;
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
    if (err.name === "AbortError") return;
    window.view3d.error = String(err.message || err);
    caption.textContent = "The layout could not be shown in 3-D: " + window.view3d.error;
  }
}

window.addEventListener("resize", () => { size(); render(); });
window.addEventListener("layout3d", () => show(window.layout3dSrc));
if (window.layout3dSrc) show(window.layout3dSrc);
