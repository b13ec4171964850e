// Reads every layout.ifc back with IFClite (@ifc-lite/parser and its WASM geometry, a second
// IFC reader independent of web-ifc) beside the schedule.csv written with it, and checks:
// one element per schedule row, named and tagged by its ID, with its value, lot and material;
// its common property set's Reference and its base quantities' area as the schedule's (a
// sheet's opening: curdle's quantities' area); its
// mesh's extent equal to the row's box within 0.01 mm (a sheet's openings are annotations drawn
// by their outlines, each assigned to its sheet, and the sheets' meshes carry their holes: no
// IfcOpeningElement voids a sheet); a building's windows and doors each in the storey its base
// stands in, as IFClite's spatial hierarchy has it. And a schema check of every entity in the file against
// IFC4's EXPRESS schema as IFClite's registry holds it: a known, instantiable entity, with as
// many attributes as the schema gives it, none left out that is not optional, an aggregate
// where the schema has one, an enumeration's value where it has one, a reference where it
// names an entity, a string or a number where the defined type is one.
// Usage: node ifc_lite_check.mjs DIR... (each with layout.ifc and schedule.csv).
import fs from 'fs';
import path from 'path';
import * as Lite from '@ifc-lite/parser';
import init, { IfcAPI } from '@ifc-lite/wasm';
import { boxMiss, buildingMiss, csvRows, expectedBox, isBuilding, isFramedScreen } from './schedule_rows.mjs';

await init({ module_or_path: fs.readFileSync(new URL('./node_modules/@ifc-lite/wasm/pkg/ifc-lite_bg.wasm', import.meta.url)) });
const geometry = new IfcAPI();
const kTolerance = 1e-5;  // 0.01 mm, in metres
const kClasses = ['IFCCOVERING', 'IFCANNOTATION', 'IFCGEOGRAPHICELEMENT', 'IFCFURNITURE', 'IFCBUILDINGELEMENTPROXY', 'IFCBUILDINGELEMENTPART'];
const kStandardSets = new Map([
  ['IFCCOVERING', ['Pset_CoveringCommon', 'Qto_CoveringBaseQuantities', 'NetArea']],
  ['IFCBUILDINGELEMENTPROXY', ['Pset_BuildingElementProxyCommon', 'Qto_BuildingElementProxyQuantities', 'NetSurfaceArea']],
  ['IFCANNOTATION', [null, 'Curdle_Quantities', 'NetArea']],  // IFC4 has no set for an annotation
]);

// The parser reports its phases on the console (and that a site's ground works have no
// storey): keep the check's own output readable.
async function parse(bytes) {
  const { log, warn } = console;
  console.log = console.warn = () => {};
  try {
    return await new Lite.IfcParser().parseColumnar(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
  } finally {
    Object.assign(console, { log, warn });
  }
}

// Every mesh's world extent, by element.
function extents(bytes) {
  const pre = geometry.buildPrePassOnce(bytes);
  const out = new Map();
  for (let start = 0; start < pre.totalJobs; start += 500) {
    const end = Math.min(start + 500, pre.totalJobs);
    const batch = geometry.processGeometryBatch(bytes, pre.jobs.slice(start * 3, end * 3), pre.unitScale,
      pre.rtcOffset?.[0] ?? 0, pre.rtcOffset?.[1] ?? 0, pre.rtcOffset?.[2] ?? 0, pre.needsShift,
      pre.voidKeys, pre.voidCounts, pre.voidValues, pre.styleIds, pre.styleColors);
    for (let i = 0; i < batch.length; i++) {
      const mesh = batch.get(i);
      const p = mesh.positions, o = mesh.origin;
      const e = out.get(mesh.expressId) ?? [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
      for (let k = 0; k < p.length; k += 3)
        for (let a = 0; a < 3; ++a) e[a] = Math.min(e[a], o[a] + p[k + a]), e[3 + a] = Math.max(e[3 + a], o[a] + p[k + a]);
      out.set(mesh.expressId, e);
      mesh.free();
    }
    batch.free();
  }
  geometry.clearPrePassCache();
  return out;
}

// A STEP entity's attributes, split at the top level: "#1,'a,b',(#2,#3),.T." -> 4 texts.
function attributes(text) {
  const out = [];
  let depth = 0, quoted = false, start = 0;
  for (let i = 0; i < text.length; ++i) {
    const c = text[i];
    if (quoted) { if (c === "'") { if (text[i + 1] === "'") ++i; else quoted = false; } continue; }
    if (c === "'") quoted = true;
    else if (c === '(') ++depth;
    else if (c === ')') --depth;
    else if (c === ',' && depth === 0) out.push(text.slice(start, i)), start = i + 1;
  }
  out.push(text.slice(start));
  return out;
}

// The registry's lookups normalise names each call: remember each answer (a model has millions
// of entities but a few dozen types).
function memo(f) {
  const seen = new Map();
  return (key) => { if (!seen.has(key)) seen.set(key, f(key)); return seen.get(key); };
}
const metadata = memo((type) => (Lite.isInstantiable(type) ? Lite.getEntityMetadata(type) : null));
const isEntity = memo((type) => Lite.isKnownEntity(type));

const kStrings = new Set(['IfcLabel', 'IfcText', 'IfcIdentifier', 'IfcGloballyUniqueId']);
const isNumberType = (t) => /Measure$/.test(t) || ['IfcReal', 'IfcInteger', 'IfcTimeStamp', 'IfcDimensionCount', 'IfcPositiveInteger'].includes(t);
const isEnumType = (t) => Lite[t] !== undefined && typeof Lite[t] === 'object';

// What is wrong with one attribute's value, or null.
function attributeProblem(attribute, value) {
  if (value === '*') return null;  // derived in this subtype
  if (value === '$') return attribute.optional ? null : 'left out, not optional';
  if (attribute.isList || attribute.isSet || attribute.isArray) return value.startsWith('(') ? null : 'not an aggregate';
  const t = attribute.type;
  if (isEnumType(t)) return /^\.[A-Z_0-9]+\.$/.test(value) ? null : 'not an enumeration value';
  if (isEntity(t)) return /^#\d+$/.test(value) ? null : 'not a reference';
  if (kStrings.has(t)) return value.startsWith("'") ? null : 'not a string';
  if (isNumberType(t)) return /^-?\d/.test(value) ? null : 'not a number';
  if (t === 'IfcBoolean' || t === 'IfcLogical') return /^\.[TFU]\.$/.test(value) ? null : 'not a boolean';
  return null;  // a select: a reference or a typed value, as the entity's reader decides
}

// Every entity of the file against the schema: the problems, and how many entities were read.
function schemaProblems(text) {
  const problems = [];
  let count = 0;
  const data = text.slice(text.indexOf('DATA;'));
  for (const m of data.matchAll(/^#(\d+)=([A-Z0-9]+)\((.*)\);$/gm)) {
    ++count;
    const [, id, type, body] = m;
    const meta = metadata(type);
    if (!meta) { problems.push(`#${id}: ${type} is not an instantiable IFC4 entity`); continue; }
    const values = attributes(body), wanted = meta.allAttributes;
    if (values.length !== wanted.length) { problems.push(`#${id}: ${type} with ${values.length} attributes, the schema has ${wanted.length}`); continue; }
    wanted.forEach((attribute, i) => {
      const problem = attributeProblem(attribute, values[i]);
      if (problem) problems.push(`#${id}: ${type}.${attribute.name} ${problem}: ${values[i].slice(0, 40)}`);
    });
  }
  return { problems, count };
}

// Each window and door in the storey its base stands in, as IFClite's spatial hierarchy has it:
// the highest storey whose elevation (metres) is at or below the bottom of its mesh (Y up).
// Returns how many stand in each storey, by name.
function storeyProblems(store, meshes, problems) {
  const h = store.spatialHierarchy;
  const storeys = [...h.storeyElevations].map(([id, elevation]) => ({ id, elevation, held: 0,
    name: Lite.extractEntityAttributesOnDemand(store, id).name })).sort((a, b) => a.elevation - b.elevation);
  for (const type of ['IFCWINDOW', 'IFCDOOR'])
    for (const id of store.entityIndex.byType.get(type) ?? []) {
      const base = meshes.get(id)?.[1];
      const want = storeys.filter((s) => s.elevation <= base + 1e-6).pop();
      const got = storeys.find((s) => s.id === h.elementToStorey.get(id));
      if (!want || got !== want)
        problems.push(`${Lite.extractEntityAttributesOnDemand(store, id).name}: base at ${base} m in ${got?.name ?? 'no storey'}, not ${want?.name}`);
      else ++got.held;
    }
  return storeys.map((s) => `${s.name} ${s.held}`).join(', ');
}

async function check(dir) {
  const rows = csvRows(fs.readFileSync(path.join(dir, 'schedule.csv'), 'utf8'));
  const bytes = new Uint8Array(fs.readFileSync(path.join(dir, 'layout.ifc')));
  const { problems, count } = schemaProblems(new TextDecoder().decode(bytes));
  const store = await parse(bytes);
  if (store.schemaVersion !== 'IFC4') problems.push(`schema ${store.schemaVersion}`);
  const byTag = new Map();
  for (const type of kClasses)
    for (const id of store.entityIndex.byType.get(type) ?? []) {
      const a = Lite.extractEntityAttributesOnDemand(store, id);
      if (type === 'IFCANNOTATION') {  // a sheet's opening, by its name (IFC4 gives no tag)
        if (a.objectType === 'opening') byTag.set(a.name, { id, type });
        continue;
      }
      if (a.name !== a.tag) problems.push(`#${id}: Name and Tag differ`);
      byTag.set(a.tag, { id, type });
    }
  const building = isBuilding(rows);
  let curved = false;
  if (building) {  // its openings are its walls', not schedule rows: one wall per façade
    const facades = JSON.parse(fs.readFileSync(path.join(dir, 'report.json'), 'utf8')).layout.facades;
    curved = facades.some((f) => f.curved);
    const walls = store.entityIndex.byType.get('IFCWALL')?.length ?? 0;
    if (walls !== facades.length) problems.push(`${walls} walls for ${facades.length} façades`);
  }
  if (byTag.size !== rows.length) problems.push(`${byTag.size} elements for ${rows.length} schedule rows`);
  const meshes = extents(bytes);
  const bodies = rows.filter((r) => byTag.get(r.element_id)?.type !== 'IFCANNOTATION');
  const first = bodies.find((r) => meshes.has(byTag.get(r.element_id)?.id));
  const upright = first && boxMiss(meshes.get(byTag.get(first.element_id).id), expectedBox(first, true)) <
                  boxMiss(meshes.get(byTag.get(first.element_id).id), expectedBox(first, false));
  let worst = 0;
  for (const row of rows) {
    const e = byTag.get(row.element_id);
    if (!e) { problems.push(`no element ${row.element_id}`); continue; }
    const sets = Object.fromEntries(Lite.extractPropertiesOnDemand(store, e.id).map((s) => [s.name, Object.fromEntries(s.properties.map((p) => [p.name, p.value]))]));
    const own = sets.Curdle_Element ?? {};
    if (String(own.Value) !== row.value) problems.push(`${row.element_id}: value ${own.Value}, schedule ${row.value}`);
    if (own.Lot !== row.lot) problems.push(`${row.element_id}: lot ${own.Lot}, schedule ${row.lot}`);
    const material = Lite.extractMaterialsOnDemand(store, e.id)?.name;
    if (material !== row.material) problems.push(`${row.element_id}: material ${material}, schedule ${row.material}`);
    const standard = kStandardSets.get(e.type);
    if (standard) {
      const [pset, qto, area] = standard;
      if (pset && sets[pset]?.Reference !== row.element_id) problems.push(`${row.element_id}: no ${pset} with its reference`);
      const quantities = Lite.extractQuantitiesOnDemand(store, e.id).find((q) => q.name === qto);
      const net = quantities?.quantities.find((q) => q.name === area)?.value;
      if (!(Math.abs(net - Number(row.area_m2)) <= 1e-6 + 1e-6 * net)) problems.push(`${row.element_id}: ${qto}.${area} ${net}, schedule ${row.area_m2}`);
    }
    if (e.type === 'IFCANNOTATION') continue;
    const extent = meshes.get(e.id);
    if (!extent) { problems.push(`${row.element_id}: no mesh`); continue; }
    const miss = building ? buildingMiss(extent, row, curved) : boxMiss(extent, expectedBox(row, upright));
    worst = Math.max(worst, miss);
    if (miss > kTolerance) problems.push(`${row.element_id}: extent off by ${(miss * 1000).toFixed(4)} mm`);
  }
  const storeys = building ? storeyProblems(store, meshes, problems) : '';
  // No sheet voided by what its body has cut already: no Boolean operation for a reader to run.
  if (!building && store.entityIndex.byType.get('IFCRELVOIDSELEMENT')?.length)
    problems.push(`${store.entityIndex.byType.get('IFCRELVOIDSELEMENT').length} voids: a reader would subtract what the sheets' bodies have cut`);
  for (const plate of store.entityIndex.byType.get('IFCPLATE') ?? [])
    if (!meshes.has(plate)) problems.push(`sheet #${plate}: no mesh`);
  if (isFramedScreen(rows)) {  // a screen on a building: each opening's middle in a sheet's mesh
    const sheets = (store.entityIndex.byType.get('IFCPLATE') ?? []).map((p) => meshes.get(p)).filter(Boolean);
    for (const row of rows) {
      const p = [Number(row.x_mm) / 1000, Number(row.z_mm) / 1000, -Number(row.y_mm) / 1000];
      const inside = (e) => [0, 1, 2].every((a) => p[a] >= e[a] - 1e-6 && p[a] <= e[3 + a] + 1e-6);
      if (!sheets.some(inside)) problems.push(`${row.element_id}: in no sheet's mesh`);
    }
  }
  const name = path.basename(dir);
  if (problems.length) {
    console.log(`${name}: ${problems.length} problems`);
    for (const p of problems.slice(0, 10)) console.log('  ' + p);
  } else {
    console.log(`${name}: ${count} entities as the schema has them; ${rows.length} elements agree (extents within ${(worst * 1000).toFixed(4)} mm)${storeys ? `; windows and doors by storey: ${storeys}` : ''}`);
  }
  return problems.length === 0;
}

let ok = true;
for (const dir of process.argv.slice(2)) ok = (await check(dir)) && ok;
process.exit(ok ? 0 : 1);
