// What the 3-D view's camera draws of a glb read by glb_worker.js: the meshes of each material
// merged into one geometry in world coordinates, a few draw calls for thousands of elements
// (a mesh an element took software WebGL 40-85 ms for each picture). Made in the worker, so
// that the page's thread only hands the arrays to WebGL: merged there, a floor of 4,500 tiles
// held it for 50-80 ms in slices, and the garbage of its objects for a collection of up to
// 18 ms when the curd's redraw came. The worker merges a slice at a time, reading its messages
// between slices, so that a change on the page, which drops the model, frees the CPU at once
// for the curd's redraw. A mirrored node's triangles are turned back, as a renderer would face
// them.
const MERGE_SLICE_MS = 3;
// Back after the messages already waiting: a plain task, queued behind them (scheduler.yield
// would come back first).
const afterWaitingMessages = () => new Promise((resolve) => {
  const channel = new MessageChannel();
  channel.port1.onmessage = () => resolve();
  channel.port2.postMessage(0);
});

// out[o..] = a[ao..] * b[bo..], 4 x 4 column-major matrices; out may be a.
function multiply(a, ao, b, bo, out, o) {
  const product = new Float64Array(16);
  for (let c = 0; c < 4; ++c)
    for (let r = 0; r < 4; ++r) {
      let sum = 0;
      for (let k = 0; k < 4; ++k) sum += a[ao + k * 4 + r] * b[bo + c * 4 + k];
      product[c * 4 + r] = sum;
    }
  out.set(product, o);
}

// Each node's world matrix; nodes come parents first (glb_worker.js nodes()).
function worldMatrices(scene) {
  const world = new Float64Array(scene.parent.length * 16);
  for (let i = 0; i < scene.parent.length; ++i) {
    const up = scene.parent[i];
    if (up < 0) world.set(scene.matrix.subarray(i * 16, i * 16 + 16), i * 16);
    else multiply(world, up * 16, scene.matrix, i * 16, world, i * 16);
  }
  return world;
}

// The cofactors of a world matrix's 3 x 3 part, signed by its determinant: the inverse
// transpose up to a positive scale, which normalising the normals takes out.
function normalTurn(w, o) {
  const [a, b, c, d, e, f, g, h, i] = [w[o], w[o + 1], w[o + 2], w[o + 4], w[o + 5], w[o + 6],
                                       w[o + 8], w[o + 9], w[o + 10]];
  // Row by row; the matrix's columns are (a, b, c), (d, e, f), (g, h, i).
  const cofactors = [e * i - h * f, h * c - b * i, b * f - e * c,
                     g * f - d * i, a * i - g * c, d * c - a * f,
                     d * h - g * e, g * b - a * h, a * e - d * b];
  const det = a * cofactors[0] + d * cofactors[1] + g * cofactors[2];
  return { turn: cofactors.map((x) => (det < 0 ? -x : x)), mirrored: det < 0 };
}

const INDEX = { 5121: Uint8Array, 5123: Uint16Array, 5125: Uint32Array };

// The primitives of each material as [node, row] pairs, with their sizes.
function groupsByMaterial(scene) {
  const rows = scene.primitives, ofMesh = [];
  for (let r = 0; r < rows.length; r += 9) (ofMesh[rows[r]] ||= []).push(r);
  const groups = new Map();
  for (let node = 0; node < scene.mesh.length; ++node) {
    for (const r of (scene.mesh[node] >= 0 && ofMesh[scene.mesh[node]]) || []) {
      const material = rows[r + 7];
      if (!groups.has(material)) groups.set(material, { material, vertices: 0, indices: 0, normals: true, parts: [] });
      const g = groups.get(material);
      g.vertices += rows[r + 2];
      g.indices += rows[r + 4] >= 0 ? rows[r + 5] : rows[r + 2];
      g.normals &&= rows[r + 3] >= 0;
      g.parts.push(node, r);
    }
  }
  return [...groups.values()];
}

// One group's geometry: positions, normals (when every part has them), indices, bounds; null
// when `goOn` says to stop.
async function mergedGroup(group, rows, world, buffer, goOn) {
  const position = new Float32Array(group.vertices * 3);
  const normal = group.normals ? new Float32Array(group.vertices * 3) : null;
  const index = new Uint32Array(group.indices);
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  // Which node each run of triangles came from, for a click to find its element (view3d.js).
  const node = new Int32Array(group.parts.length / 2), firstTriangle = new Uint32Array(group.parts.length / 2);
  let vo = 0, io = 0;
  for (let p = 0; p < group.parts.length; p += 2) {
    const o = group.parts[p] * 16, r = group.parts[p + 1];
    node[p / 2] = group.parts[p];
    firstTriangle[p / 2] = io / 3;
    const [, po, pc, no, ixo, ic, it] = rows.subarray(r, r + 7);
    const from = new Float32Array(buffer, po, pc * 3);
    for (let v = 0; v < pc; ++v) {
      const x = from[v * 3], y = from[v * 3 + 1], z = from[v * 3 + 2];
      for (let k = 0; k < 3; ++k) {
        const value = world[o + k] * x + world[o + 4 + k] * y + world[o + 8 + k] * z + world[o + 12 + k];
        position[(vo + v) * 3 + k] = value;
        if (value < min[k]) min[k] = value;
        if (value > max[k]) max[k] = value;
      }
    }
    const { turn, mirrored } = normalTurn(world, o);
    if (normal) {
      const n = new Float32Array(buffer, no, pc * 3);
      for (let v = 0; v < pc; ++v) {
        const x = n[v * 3], y = n[v * 3 + 1], z = n[v * 3 + 2];
        const tx = turn[0] * x + turn[1] * y + turn[2] * z;
        const ty = turn[3] * x + turn[4] * y + turn[5] * z;
        const tz = turn[6] * x + turn[7] * y + turn[8] * z;
        const length = Math.hypot(tx, ty, tz) || 1;
        normal[(vo + v) * 3] = tx / length;
        normal[(vo + v) * 3 + 1] = ty / length;
        normal[(vo + v) * 3 + 2] = tz / length;
      }
    }
    const own = ixo >= 0 ? new INDEX[it](buffer, ixo, ic) : null, count = own ? ic : pc;
    const [second, third] = mirrored ? [2, 1] : [1, 2];
    for (let t = 0; t + 2 < count; t += 3) {
      index[io++] = vo + (own ? own[t] : t);
      index[io++] = vo + (own ? own[t + second] : t + second);
      index[io++] = vo + (own ? own[t + third] : t + third);
    }
    vo += pc;
    if ((p & 63) === 62 && !(await goOn())) return null;
  }
  // The bounding sphere as three.js makes it: about the box's centre, out to the farthest point.
  const centre = [0, 1, 2].map((k) => (min[k] + max[k]) / 2);
  let reach = 0;
  for (let v = 0; v < group.vertices; ++v)
    reach = Math.max(reach, (position[v * 3] - centre[0]) ** 2 + (position[v * 3 + 1] - centre[1]) ** 2 +
                     (position[v * 3 + 2] - centre[2]) ** 2);
  return { material: group.material, position, normal, index, min, max, centre, radius: Math.sqrt(reach),
           node, firstTriangle };
}

// The merged drawing of `scene` (glb_worker.js's arrays) and the buffers it holds, to transfer;
// null once stillWanted() says it is no longer wanted.
export async function mergedDrawing(scene, buffer, stillWanted = () => true) {
  const world = worldMatrices(scene);
  let deadline = performance.now() + MERGE_SLICE_MS;
  const goOn = async () => {
    if (performance.now() < deadline) return true;
    await afterWaitingMessages();
    deadline = performance.now() + MERGE_SLICE_MS;
    return stillWanted();
  };
  const drawing = [];
  for (const g of groupsByMaterial(scene)) {
    const made = await mergedGroup(g, scene.primitives, world, buffer, goOn);
    if (!made) return null;
    drawing.push(made);
  }
  const buffers = drawing.flatMap((g) => [g.position.buffer, g.index.buffer, g.node.buffer, g.firstTriangle.buffer]
    .concat(g.normal ? [g.normal.buffer] : []));
  return { drawing, buffers };
}
