// The 3-D view's worker: fetches layout.glb and reads its JSON off the page's thread, so that
// a big model (a building's 23,000 bricks) never holds up a redraw of the 2-D field. It hands
// over the binary chunk without a copy, the scene as flat arrays (view3d.js builds the
// three.js objects of its elements from them when a click or a check asks) and the drawing the
// camera shows, merged a material at a time (glb_merge.js). It reads what curdle's own writer
// puts in a glb (export/gltf/gltf_json.cpp): float positions and normals, integer indices, PBR
// colours, node trees with matrices or TRS and extras. Anything else is answered with
// `unsupported`, and the page falls back to three.js's own loader.
import { answerLatest } from "./worker_fetch.js";
import { mergedDrawing } from "./glb_merge.js";

class Unsupported extends Error {}

const COMPONENTS = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };
const BYTES = { 5121: 1, 5123: 2, 5125: 4, 5126: 4 };

function chunks(buffer) {
  const view = new DataView(buffer);
  if (buffer.byteLength < 20 || view.getUint32(0, true) !== 0x46546c67)
    throw new Error("the answer is not a binary glTF (no 'glTF' magic)");
  const jsonLength = view.getUint32(12, true);
  if (view.getUint32(16, true) !== 0x4e4f534a) throw new Unsupported("the first chunk is not JSON");
  const json = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 20, jsonLength)));
  const binHead = 20 + jsonLength;
  const binStart = binHead + 8 <= buffer.byteLength ? binHead + 8 : buffer.byteLength;
  return { json, binStart };
}

// An accessor as [byte offset in the glb, element count, component type], checked to be one
// tightly packed run inside the file.
function accessorRun(json, binStart, buffer, index, type) {
  const a = json.accessors[index];
  if (!a || a.type !== type || a.sparse || !BYTES[a.componentType]) throw new Unsupported(`accessor ${index}`);
  const bv = json.bufferViews[a.bufferView];
  const size = BYTES[a.componentType] * COMPONENTS[type];
  if (!bv || bv.buffer !== 0 || (bv.byteStride && bv.byteStride !== size)) throw new Unsupported(`view of ${index}`);
  const offset = binStart + (bv.byteOffset || 0) + (a.byteOffset || 0);
  if (offset % BYTES[a.componentType] || offset + a.count * size > buffer.byteLength)
    throw new Error(`accessor ${index} lies outside the file`);
  return [offset, a.count, a.componentType];
}

// Each primitive as one row of 9 numbers: mesh, position offset and count, normal offset (-1:
// none), index offset (-1: none), index count and type, material (-1: none), mode.
function primitiveRows(json, binStart, buffer) {
  const rows = [];
  (json.meshes || []).forEach((mesh, m) => {
    for (const p of mesh.primitives) {
      const mode = p.mode ?? 4;
      if (mode !== 4 || p.targets || p.extensions) throw new Unsupported(`primitive of mesh ${m}`);
      const [po, pc, pt] = accessorRun(json, binStart, buffer, p.attributes.POSITION, "VEC3");
      if (pt !== 5126) throw new Unsupported("positions that are not floats");
      let no = -1;
      if (p.attributes.NORMAL !== undefined) {
        const n = accessorRun(json, binStart, buffer, p.attributes.NORMAL, "VEC3");
        if (n[2] !== 5126 || n[1] !== pc) throw new Unsupported("normals");
        no = n[0];
      }
      let io = -1, ic = 0, it = 0;
      if (p.indices !== undefined) [io, ic, it] = accessorRun(json, binStart, buffer, p.indices, "SCALAR");
      rows.push(m, po, pc, no, io, ic, it, p.material ?? -1, mode);
    }
  });
  return new Float64Array(rows);
}

function materials(json) {
  return (json.materials || []).map((m) => {
    const pbr = m.pbrMetallicRoughness || {};
    if (pbr.baseColorTexture || m.normalTexture || m.extensions) throw new Unsupported("textured materials");
    return { name: m.name || "", colour: pbr.baseColorFactor || [1, 1, 1, 1],
             metallic: pbr.metallicFactor ?? 1, roughness: pbr.roughnessFactor ?? 1,
             blend: m.alphaMode === "BLEND", doubleSided: !!m.doubleSided };
  });
}

// The scene's nodes, parents before children: for each its parent's place in that order (-1 at
// the root), mesh, 16-number local matrix (column-major), name and extras as JSON text.
function nodes(json) {
  const scene = json.scenes[json.scene ?? 0];
  const all = json.nodes || [];
  const order = [], parent = [];
  const seen = new Uint8Array(all.length);
  const queue = scene.nodes.map((n) => [n, -1]);
  for (let q = 0; q < queue.length; ++q) {
    const [n, up] = queue[q];
    if (!all[n] || seen[n]) throw new Error(`node ${n} is missing or used twice`);
    seen[n] = 1;
    const place = order.length;
    order.push(n);
    parent.push(up);
    for (const c of all[n].children || []) queue.push([c, place]);
  }
  const mesh = new Int32Array(order.length), matrix = new Float32Array(order.length * 16);
  const names = [], extras = [];
  order.forEach((n, i) => {
    const node = all[n];
    if (node.extensions || node.skin !== undefined) throw new Unsupported(`node ${n}`);
    mesh[i] = node.mesh ?? -1;
    matrix.set(node.matrix || trs(node), i * 16);
    names.push(node.name || "");
    extras.push(node.extras === undefined ? "" : JSON.stringify(node.extras));
  });
  return { parent: new Int32Array(parent), mesh, matrix, names, extras,
           sceneExtras: JSON.stringify(scene.extras || {}) };
}

// A column-major matrix from translation, rotation (a unit quaternion) and scale.
function trs(node) {
  const [x, y, z, w] = node.rotation || [0, 0, 0, 1];
  const [sx, sy, sz] = node.scale || [1, 1, 1];
  const [tx, ty, tz] = node.translation || [0, 0, 0];
  return [
    (1 - 2 * (y * y + z * z)) * sx, 2 * (x * y + z * w) * sx, 2 * (x * z - y * w) * sx, 0,
    2 * (x * y - z * w) * sy, (1 - 2 * (x * x + z * z)) * sy, 2 * (y * z + x * w) * sy, 0,
    2 * (x * z + y * w) * sz, 2 * (y * z - x * w) * sz, (1 - 2 * (x * x + y * y)) * sz, 0,
    tx, ty, tz, 1,
  ];
}

answerLatest(async (id, buffer, stillWanted) => {
  try {
    const { json, binStart } = chunks(buffer);
    const scene = { materials: materials(json), primitives: primitiveRows(json, binStart, buffer), ...nodes(json) };
    const merged = await mergedDrawing(scene, buffer, stillWanted);
    if (!merged) return;  // dropped by a change on the page
    const { drawing, buffers } = merged;
    self.postMessage({ id, scene, buffer, drawing }, [buffer, scene.parent.buffer, scene.mesh.buffer,
                                                      scene.matrix.buffer, scene.primitives.buffer, ...buffers]);
  } catch (err) {
    if (!(err instanceof Unsupported)) throw err;
    self.postMessage({ id, unsupported: err.message, buffer }, [buffer]);
  }
});
