// The segment's layout in 3-D: the same layout.glb the page downloads, in three.js (served from
// the page's own vendor/three, nothing from the network), orbit and zoom, a façade seen from the
// street and a floor from eye height, and a click on an element shows its ID, value and
// material. report.js announces each new layout.glb with showLayout3d(src).
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const EYE = 1.6;  // m: where a person's eyes are
const ELEMENTS = 1;  // the layer of the model's elements, which the camera does not draw
const box = document.getElementById("view3d");
const info = document.getElementById("view3d-info");
const caption = document.getElementById("view3d-caption");
// Multisampled only on a GPU. Software WebGL (a machine without one: SwiftShader, llvmpipe)
// took 40-60 ms more of the GPU process for each multisampled picture of a 67 x 67 floor,
// and the page's thread waits for that picture when it next shows the page, the curd's
// redraw included.
function softwareWebGl() {
  const gl = document.createElement("canvas").getContext("webgl2");
  if (!gl) return true;
  const about = gl.getExtension("WEBGL_debug_renderer_info");
  const name = about ? String(gl.getParameter(about.UNMASKED_RENDERER_WEBGL)) : "";
  const lose = gl.getExtension("WEBGL_lose_context");
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}
const SOFTWARE = softwareWebGl();
const renderer = new THREE.WebGLRenderer({ antialias: !SOFTWARE, preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
renderer.setClearColor(0xf4f6f8, 1);
box.append(renderer.domElement);
const scene = new THREE.Scene();
const sky = new THREE.HemisphereLight(0xffffff, 0x808080, 2.2);
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(-3, 8, 5);
// Lit on both layers: the drawing the camera sees, and the elements drawn one by one when the
// page's tests compare the two (mergedAgrees).
for (const light of [sky, sun]) {
  light.layers.enable(ELEMENTS);
  scene.add(light);
}
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
let model = null;  // the model's elements, made when first asked for (elements())
let elementsToMake = null;  // what they are made of until then: the worker's arrays
let picking = null;  // the worker's scene, where a click on the merged drawing finds its element
let drawing = null;  // what the camera draws of the model, merged a material at a time
let extras = {};  // the scene's extras: a whole building says so
let loading = 0;  // the latest model asked for
// What the page's tests read: the model shown, how much of the picture it covers, the eye's
// height over the model's lowest point.
window.view3d = { src: null, loads: 0, error: null, readIn: null, pointOnElement, model: () => elements(),
                  eyeAboveGround: () => camera.position.y - ground, mergedAgrees, picksAgree: (n) => picksAgree(n) };
// For the page's tests, read when asked: reading the picture back waits for the whole drawing,
// which on a machine without a GPU held the page's thread for 15-30 ms on every new model.
Object.defineProperty(window.view3d, "drawn", { get: () => { render(); return drawnShare(); } });

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

// The picture's pixels as RGBA, bottom row first.
function pixelsOf() {
  const gl = renderer.getContext();
  const pixels = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
  gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

// Whether pixel i (RGBA, at byte i) is the clear colour, within a few levels.
const isBackground = (p, i) =>
  Math.abs(p[i] - 0xf4) + Math.abs(p[i + 1] - 0xf6) + Math.abs(p[i + 2] - 0xf8) <= 12;

// For the page's tests: the share of pixels that differ by more than a few levels between the
// merged drawing and the elements drawn one by one, and the share each covers.
function mergedAgrees() {
  elements();
  const picture = (layer) => {
    camera.layers.set(layer);
    render();
    return pixelsOf();
  };
  const one = picture(ELEMENTS), merged = picture(0);
  render();
  let differ = 0, covered = [0, 0];
  for (let i = 0; i < one.length; i += 4) {
    if (Math.abs(one[i] - merged[i]) + Math.abs(one[i + 1] - merged[i + 1]) + Math.abs(one[i + 2] - merged[i + 2]) > 12) differ++;
    if (!isBackground(one, i)) covered[0]++;
    if (!isBackground(merged, i)) covered[1]++;
  }
  const n = one.length / 4;
  return { differ: differ / n, elements: covered[0] / n, merged: covered[1] / n };
}

// The share of the picture that is not background.
function drawnShare() {
  const pixels = pixelsOf();
  let drawn = 0;
  for (let i = 0; i < pixels.length; i += 16)
    if (!isBackground(pixels, i)) drawn++;
  return drawn / (pixels.length / 16);
}

// A façade (standing up) from the street, a floor from eye height at its near edge, a whole
// building (its scene says so) from above its south-west corner. The bounds are the merged
// drawing's: the worker's drawing comes with them (glb_merge.js).
function frame() {
  const bounds = new THREE.Box3().setFromObject(drawing);
  const s = bounds.getSize(new THREE.Vector3());
  const c = bounds.getCenter(new THREE.Vector3());
  const reach = Math.max(s.x, s.y, s.z, 0.1);
  const upright = s.y > 0.5 * Math.max(s.x, s.z);
  camera.near = reach / 500;
  camera.far = reach * 20;
  if (extras.building) {
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
  if (!drawing) return;
  frame();
  render();
});

// The element under a point of the canvas: the nearest named node holding its value. Found in
// the merged drawing the camera shows, whose triangles know their node (glb_merge.js), so that
// a click never waits for the elements' three.js objects (a building's 23,000 bricks took
// 0.4 s to make); from those objects when `fromElements`, or when the model was read by
// three.js's loader.
function elementAt(clientX, clientY, fromElements = false) {
  const r = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
  const ray = new THREE.Raycaster();
  if (!fromElements && picking && drawing) {
    ray.setFromCamera(ndc, camera);
    for (const hit of ray.intersectObject(drawing, true)) {
      const e = pickedElement(hit);
      if (e) return e;
    }
    return null;
  }
  if (!elements()) return null;
  ray.layers.set(ELEMENTS);
  ray.setFromCamera(ndc, camera);
  for (const hit of ray.intersectObject(model, true)) {
    let o = hit.object;
    while (o && !(o.userData && o.userData.value !== undefined)) o = o.parent;
    if (!o) continue;
    return { id: o.name, value: o.userData.value, material: materialName(hit.object), curds: o.userData.curds || [] };
  }
  return null;
}

// The model names each value's material "value N label" (a park's element: its type).
const materialName = (mesh) => ((mesh.material && mesh.material.name) || "").replace(/^value \d+ /, "");

// The element a ray's hit on the merged drawing belongs to: the node its triangle came from, or
// the nearest of that node's parents holding a value, named as three.js's loader names it.
function pickedElement(hit) {
  const runs = hit.object.userData.runs;
  if (!runs || hit.faceIndex === undefined) return null;
  let lo = 0, hi = runs.firstTriangle.length - 1;  // the last run starting at or before the face
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (runs.firstTriangle[mid] <= hit.faceIndex) lo = mid;
    else hi = mid - 1;
  }
  const { scene } = picking;
  for (let node = runs.node[lo]; node >= 0; node = scene.parent[node]) {
    const data = scene.extras[node] ? JSON.parse(scene.extras[node]) : {};
    if (data.value === undefined) continue;
    return { id: THREE.PropertyBinding.sanitizeNodeName(scene.names[node]), value: data.value,
             material: materialName(hit.object), curds: data.curds || [] };
  }
  return null;
}

// For the page's tests: the middle of an element's top face as the canvas shows it (page
// coordinates), where a click finds that element again, and its ID.
function pointOnElement() {
  if (!elements()) return null;
  const r = renderer.domElement.getBoundingClientRect();
  for (let k = 0; k < 400; ++k) {
    const x = r.left + r.width * (0.2 + 0.6 * ((k % 20) / 19));
    const y = r.top + r.height * (0.9 - 0.6 * (Math.floor(k / 20) / 19));  // nearest first
    const e = elementAt(x, y, true);
    if (!e) continue;
    const bounds = new THREE.Box3().setFromObject(model.getObjectByName(e.id));
    const top = bounds.getCenter(new THREE.Vector3());
    top.y = bounds.max.y;
    top.project(camera);
    // Whole pixels, as a click reports them.
    const px = Math.round(r.left + (top.x + 1) / 2 * r.width), py = Math.round(r.top + (1 - top.y) / 2 * r.height);
    const again = elementAt(px, py, true);
    if (again && again.id === e.id) return { x: px, y: py, id: e.id };
  }
  return null;
}

// A click answers wherever it lands, a click on none too; from the click's event to the answer
// is measured.
renderer.domElement.addEventListener("click", (event) => {
  if (!drawing) return;
  const e = elementAt(event.clientX, event.clientY);
  info.textContent = e
    ? `${e.id}: value ${e.value}${e.curds.length ? " (" + e.curds.join(" + ") + ")" : ""}, ${e.material || "no material"}`
    : "No element there (sky, ground or an opening): click a brick, tile or piece to see its ID, value and material.";
  info.dataset.id = e ? e.id : "";
  performance.measure("view3d-click", { start: event.timeStamp, end: performance.now() });
});

// For the page's tests: the element found at each of n x n points over the canvas from the
// merged drawing and from the elements' own objects, where they differ, and a point on none.
function picksAgree(n) {
  const r = renderer.domElement.getBoundingClientRect();
  let points = 0, hits = 0, empty = null;
  const differ = [];
  for (let i = 0; i < n; ++i)
    for (let j = 0; j < n; ++j) {
      const x = r.left + r.width * (i + 0.5) / n, y = r.top + r.height * (j + 0.5) / n;
      const a = elementAt(x, y), b = elementAt(x, y, true);
      ++points;
      if (b) ++hits;
      else empty ||= { x: Math.round(x), y: Math.round(y) };
      if (JSON.stringify(a) !== JSON.stringify(b)) differ.push([x, y, a && a.id, b && b.id]);
    }
  return { points, hits, differ: differ.length, first: differ[0] || null, empty };
}

// layout.glb is fetched and read in a worker (glb_worker.js), which also merges what the camera
// draws (glb_merge.js); here the drawing is handed to WebGL as it comes, and the three.js
// objects of the elements are made only when a click or a check asks for them, so that a 2-D
// redraw that arrives meanwhile is drawn at once.
const glbWorker = new Worker("glb_worker.js", { type: "module" });
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

const SLICE_MS = 4;
const yieldToPage = () =>
  globalThis.scheduler && scheduler.yield ? scheduler.yield() : new Promise((r) => setTimeout(r, 0));

// The glb's PBR material; without a GPU a matte one of the same colour: software WebGL shaded
// a 67 x 67 floor's picture in half the time, time the curd's redraw waited for.
function material(m) {
  const seen = { opacity: m.colour[3], transparent: m.blend, depthWrite: !m.blend,
                 side: m.doubleSided ? THREE.DoubleSide : THREE.FrontSide };
  const made = SOFTWARE ? new THREE.MeshLambertMaterial(seen)
    : new THREE.MeshStandardMaterial({ ...seen, metalness: m.metallic, roughness: m.roughness });
  made.color.setRGB(m.colour[0], m.colour[1], m.colour[2], THREE.LinearSRGBColorSpace);
  made.name = m.name;
  return made;
}

// The scene's materials by their index, and the one for a primitive without (at -1); flat
// shaded where a primitive has no normals, as three.js's loader makes them.
function materialsOf(scene) {
  const made = scene.materials.map(material);
  made.none = material({ name: "", colour: [1, 1, 1, 1], metallic: 1, roughness: 1, blend: false, doubleSided: false });
  const rows = scene.primitives;
  for (let r = 0; r < rows.length; r += 9)
    if (rows[r + 3] < 0) (rows[r + 7] >= 0 ? made[rows[r + 7]] : made.none).flatShading = true;
  return made;
}
const materialAt = (materials, i) => (i >= 0 ? materials[i] : materials.none);

// Each mesh's primitives as [geometry, material] pairs, sharing the worker's buffer.
function meshParts(scene, buffer, materials) {
  const parts = [];
  const rows = scene.primitives;
  const INDEX = { 5121: Uint8Array, 5123: Uint16Array, 5125: Uint32Array };
  for (let r = 0; r < rows.length; r += 9) {
    const [m, po, pc, no, io, ic, it, mat] = rows.subarray(r, r + 8);
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(buffer, po, pc * 3), 3));
    if (no >= 0) g.setAttribute("normal", new THREE.BufferAttribute(new Float32Array(buffer, no, pc * 3), 3));
    if (io >= 0) g.setIndex(new THREE.BufferAttribute(new INDEX[it](buffer, io, ic), 1));
    (parts[m] ||= []).push([g, materialAt(materials, mat)]);
  }
  return parts;
}

// The model's elements as three.js's loader would make them: a node with one primitive is that
// mesh, one with several a group of them; names and extras (userData) as the glb has them.
function buildModel({ scene, buffer, materials }) {
  const parts = meshParts(scene, buffer, materials);
  const root = new THREE.Group();
  root.userData = JSON.parse(scene.sceneExtras);
  const made = new Array(scene.mesh.length);
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
  }
  return root;
}

// The elements shown, made now if they were not yet: in the scene on a layer of their own,
// which the camera does not draw, for clicks to find them and for the page's checks.
function elements() {
  if (!model && elementsToMake) {
    model = buildModel(elementsToMake);
    elementsToMake = null;
    onElementsLayer(model);
    scene.add(model);
  }
  return model;
}

function onElementsLayer(root) {
  root.updateMatrixWorld(true);
  root.traverse((o) => { if (o.isMesh) o.layers.set(ELEMENTS); });
}

// The worker's merged drawing (glb_merge.js) as three.js meshes, one a material, with the
// bounds the worker measured.
function drawingFrom(groups, materials) {
  const made = new THREE.Group();
  for (const g of groups) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(g.position, 3));
    if (g.normal) geometry.setAttribute("normal", new THREE.BufferAttribute(g.normal, 3));
    geometry.setIndex(new THREE.BufferAttribute(g.index, 1));
    geometry.boundingBox = new THREE.Box3(new THREE.Vector3(...g.min), new THREE.Vector3(...g.max));
    geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(...g.centre), g.radius);
    const mesh = new THREE.Mesh(geometry, materialAt(materials, g.material));
    mesh.userData.runs = { node: g.node, firstTriangle: g.firstTriangle };
    made.add(mesh);
  }
  return made;
}

// What the camera draws of a model three.js's own loader read (a glb the worker does not
// read): its meshes merged into one a material on the page's thread, a slice at a time, as
// glb_merge.js does in the worker. Null when a newer model was asked for meanwhile.
async function mergedDrawing(root, stillWanted) {
  onElementsLayer(root);
  const byMaterial = new Map();
  const drawing = new THREE.Group();
  root.traverse((o) => {
    if (!o.isMesh) return;
    // As they are: an instanced mesh, or one of several materials (not made from our glb).
    if (o.isInstancedMesh || Array.isArray(o.material)) drawing.add(placedCopy(o));
    else (byMaterial.get(o.material) || byMaterial.set(o.material, []).get(o.material)).push(o);
  });
  let deadline = performance.now() + SLICE_MS;
  for (const [material, meshes] of byMaterial) {
    drawing.add(new THREE.Mesh(await mergedGeometry(meshes, !material.flatShading, async () => {
      if (performance.now() < deadline) return true;
      await yieldToPage();
      deadline = performance.now() + SLICE_MS;
      return stillWanted();
    }), material));
    if (!stillWanted()) return null;
  }
  return drawing;
}

function placedCopy(o) {
  const copy = o.clone();
  o.matrixWorld.decompose(copy.position, copy.quaternion, copy.scale);
  copy.layers.set(0);
  return copy;
}

// One geometry of `meshes` in world coordinates; a mirrored mesh's triangles turned back, as
// the renderer would face them. `goOn` is asked every 32 meshes.
async function mergedGeometry(meshes, withNormals, goOn) {
  let vertices = 0, indices = 0;
  for (const m of meshes) {
    const g = m.geometry, n = g.attributes.position.count;
    vertices += n;
    indices += g.index ? g.index.count : n;
    withNormals &&= !!g.attributes.normal;
  }
  const position = new Float32Array(vertices * 3);
  const normal = withNormals ? new Float32Array(vertices * 3) : null;
  const index = new Uint32Array(indices);
  const v = new THREE.Vector3(), turn = new THREE.Matrix3();
  let vo = 0, io = 0;
  for (let k = 0; k < meshes.length; ++k) {
    const m = meshes[k], g = m.geometry, p = g.attributes.position, n = g.attributes.normal;
    turn.getNormalMatrix(m.matrixWorld);
    for (let i = 0; i < p.count; ++i) {
      v.fromBufferAttribute(p, i).applyMatrix4(m.matrixWorld).toArray(position, (vo + i) * 3);
      if (normal) v.fromBufferAttribute(n, i).applyMatrix3(turn).normalize().toArray(normal, (vo + i) * 3);
    }
    const [second, third] = m.matrixWorld.determinant() < 0 ? [2, 1] : [1, 2];
    const own = g.index ? g.index.array : null, count = own ? g.index.count : p.count;
    for (let t = 0; t + 2 < count; t += 3) {
      index[io++] = vo + (own ? own[t] : t);
      index[io++] = vo + (own ? own[t + second] : t + second);
      index[io++] = vo + (own ? own[t + third] : t + third);
    }
    vo += p.count;
    if ((k & 31) === 31 && !(await goOn())) break;
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
  if (normal) geometry.setAttribute("normal", new THREE.BufferAttribute(normal, 3));
  geometry.setIndex(new THREE.BufferAttribute(index, 1));
  return geometry;
}

// The GPU's copies of a model no longer shown.
function dispose(root) {
  root.traverse((o) => {
    if (!o.isMesh) return;
    o.geometry.dispose();
    for (const m of [].concat(o.material)) m.dispose();
  });
}

// Drops the model on its way, if any: its fetch, and the building of one fetched.
function dropLoad() {
  ++loading;
  for (const [id, waiting] of glbWaiting) waiting({ id, aborted: true });
  glbWaiting.clear();
  glbWorker.postMessage({ drop: true });
}

const SHOWN = "The same layout.glb in 3-D: drag to turn (the eye stays above ground), scroll to " +
  "zoom, click an element; Reset view goes back to this view";

async function show(src) {
  if (!src) return;
  if (window.view3d.src === src) {  // a change came back to it, or its load was dropped
    dropLoad();  // another model on its way is no longer wanted
    box.classList.remove("stale");
    caption.textContent = SHOWN;
    return;
  }
  const wanted = ++loading;
  const stillWanted = () => wanted === loading;
  caption.textContent = "Loading the layout in 3-D…";
  box.classList.add("stale");
  try {
    const answer = await fetchGlb(src);
    if (answer.aborted || !stillWanted()) return;
    if (answer.error) throw new Error(answer.error);
    let root = null, made = null, merged, sceneExtras;
    if (answer.scene) {
      made = { scene: answer.scene, buffer: answer.buffer, materials: materialsOf(answer.scene) };
      merged = drawingFrom(answer.drawing, made.materials);
      sceneExtras = JSON.parse(answer.scene.sceneExtras);
      window.view3d.readIn = "worker";
    } else {
      root = (await new GLTFLoader().parseAsync(answer.buffer, "")).scene;
      window.view3d.readIn = "page: " + answer.unsupported;
      if (!stillWanted()) return;
      merged = await mergedDrawing(root, stillWanted);
      sceneExtras = root.userData || {};
    }
    if (!merged || !stillWanted()) return;
    await yieldToPage();  // a change that came meanwhile goes first, and drops this model
    if (!stillWanted()) return;
    const [oldModel, oldDrawing] = [model, drawing];
    if (model) scene.remove(model);
    if (drawing) scene.remove(drawing);
    model = root;
    elementsToMake = made;
    picking = made;
    drawing = merged;
    extras = sceneExtras;
    if (model) scene.add(model);
    scene.add(drawing);
    size();
    frame();
    const rendering = performance.now();
    render();
    performance.measure("view3d-render", { start: rendering, end: performance.now() });
    // The old model's GPU copies go once the new one is drawn: its shader programs, which the
    // new materials share, stay compiled (dropped first, each new model compiled them again).
    if (oldModel) dispose(oldModel);
    if (oldDrawing) dispose(oldDrawing);
    window.view3d.src = src;
    window.view3d.loads += 1;
    window.view3d.error = null;
    box.classList.remove("stale");
    caption.textContent = SHOWN;
  } catch (err) {
    window.view3d.error = String(err.message || err);
    caption.textContent = "The layout could not be shown in 3-D: " + window.view3d.error;
  }
}

window.addEventListener("resize", () => { size(); render(); });
window.addEventListener("layout3d", () => show(window.layout3dSrc));
// A change drops the model on its way (report.js dropSlowLoads).
window.addEventListener("layout3d-drop", dropLoad);
if (window.layout3dSrc) show(window.layout3dSrc);
