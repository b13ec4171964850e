// How long each layout.ifc takes a reader to open and mesh whole, as a web viewer or a
// coordinator's tool does: web-ifc (open, then every product's mesh, voids cut) and IFClite
// (parse, then every product's mesh). Prints a row per model and the slowest of each; exits 1
// when any model takes web-ifc more than `--limit` seconds (default 30).
// Usage: node ifc_timing.mjs [--limit S] DIR... (each with layout.ifc)
import fs from 'fs';
import path from 'path';
import * as W from 'web-ifc';
import * as Lite from '@ifc-lite/parser';
import init, { IfcAPI } from '@ifc-lite/wasm';

const args = process.argv.slice(2);
const limit = args[0] === '--limit' ? Number(args.splice(0, 2)[1]) : 30;
const webIfc = new W.IfcAPI();
await webIfc.Init();
webIfc.SetLogLevel(W.LogLevel.LOG_LEVEL_OFF);
await init({ module_or_path: fs.readFileSync(new URL('./node_modules/@ifc-lite/wasm/pkg/ifc-lite_bg.wasm', import.meta.url)) });
const lite = new IfcAPI();

function timeWebIfc(bytes) {
  const started = performance.now();
  const model = webIfc.OpenModel(bytes);
  let meshes = 0;
  webIfc.StreamAllMeshes(model, () => { ++meshes; });
  webIfc.CloseModel(model);
  return [(performance.now() - started) / 1000, meshes];
}

async function timeLite(bytes) {
  const started = performance.now();
  const { log, warn } = console;
  console.log = console.warn = () => {};
  try {
    await new Lite.IfcParser().parseColumnar(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
  } finally {
    Object.assign(console, { log, warn });
  }
  const pre = lite.buildPrePassOnce(bytes);
  let meshes = 0;
  for (let start = 0; start < pre.totalJobs; start += 500) {
    const end = Math.min(start + 500, pre.totalJobs);
    const batch = lite.processGeometryBatch(bytes, pre.jobs.slice(start * 3, end * 3), pre.unitScale,
      pre.rtcOffset?.[0] ?? 0, pre.rtcOffset?.[1] ?? 0, pre.rtcOffset?.[2] ?? 0, pre.needsShift,
      pre.voidKeys, pre.voidCounts, pre.voidValues, pre.styleIds, pre.styleColors);
    meshes += batch.length;
    batch.free();
  }
  lite.clearPrePassCache();
  return [(performance.now() - started) / 1000, meshes];
}

let slowest = { web: [0, ''], lite: [0, ''] };
console.log('model                              MB   web-ifc s  meshes   IFClite s  meshes');
for (const dir of args) {
  const bytes = new Uint8Array(fs.readFileSync(path.join(dir, 'layout.ifc')));
  const name = path.basename(dir);
  const [w, wm] = timeWebIfc(bytes);
  const [l, lm] = await timeLite(bytes);
  console.log(`${name.padEnd(32)} ${(bytes.length / 1e6).toFixed(1).padStart(5)} ${w.toFixed(2).padStart(10)} ${String(wm).padStart(7)} ${l.toFixed(2).padStart(11)} ${String(lm).padStart(7)}`);
  if (w > slowest.web[0]) slowest.web = [w, name];
  if (l > slowest.lite[0]) slowest.lite = [l, name];
}
console.log(`slowest: web-ifc ${slowest.web[0].toFixed(2)} s (${slowest.web[1]}), IFClite ${slowest.lite[0].toFixed(2)} s (${slowest.lite[1]}); limit ${limit} s`);
process.exit(slowest.web[0] <= limit ? 0 : 1);
