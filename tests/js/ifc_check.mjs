// Reads every layout.ifc back with web-ifc (an independent IFC reader, WASM) beside the
// schedule.csv written with it, and checks: one element per schedule row, named and tagged by
// its ID; its value, lot and material as the schedule gives them; its geometry's extent (from
// web-ifc's own meshes) equal to the row's box within 0.01 mm; every opening a void of a
// plate; every setting-out annotation's IfcIndexedPolyCurve with its arcs as IfcArcIndex through
// three distinct points on a circle (read raw: web-ifc's typed reader has no select values).
// Usage: node ifc_check.mjs DIR... (each with layout.ifc and schedule.csv).
import fs from 'fs';
import path from 'path';
import * as W from 'web-ifc';

const api = new W.IfcAPI();
await api.Init();
const kTolerance = 1e-5;  // 0.01 mm, in web-ifc's metres
const kClasses = [W.IFCCOVERING, W.IFCOPENINGELEMENT, W.IFCGEOGRAPHICELEMENT, W.IFCFURNITURE,
                  W.IFCBUILDINGELEMENTPROXY];

function csvRows(text) {
  const rows = [];
  let row = [], field = '', quoted = false;
  for (let i = text.charCodeAt(0) === 0xfeff ? 1 : 0; i < text.length; ++i) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') field += '"', ++i;
      else if (c === '"') quoted = false;
      else field += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') row.push(field), field = '';
    else if (c === '\n') row.push(field.replace(/\r$/, '')), rows.push(row), row = [], field = '';
    else field += c;
  }
  const [head, ...body] = rows;
  return body.map((r) => Object.fromEntries(head.map((h, i) => [h, r[i]])));
}

// Each element's extent in web-ifc's frame (metres, Y up, Z towards the viewer).
function extents(model, ids) {
  const out = new Map();
  api.StreamMeshes(model, ids, (mesh) => {
    const e = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
    for (let g = 0; g < mesh.geometries.size(); ++g) {
      const placed = mesh.geometries.get(g);
      const geometry = api.GetGeometry(model, placed.geometryExpressID);
      const v = api.GetVertexArray(geometry.GetVertexData(), geometry.GetVertexDataSize());
      const T = placed.flatTransformation;
      for (let k = 0; k < v.length; k += 6) {
        const p = [0, 1, 2].map((a) => T[a] * v[k] + T[4 + a] * v[k + 1] + T[8 + a] * v[k + 2] + T[12 + a]);
        for (let a = 0; a < 3; ++a) e[a] = Math.min(e[a], p[a]), e[3 + a] = Math.max(e[3 + a], p[a]);
      }
      geometry.delete();
    }
    out.set(mesh.expressID, e);
  });
  return out;
}

// The row's box in web-ifc's frame: a plan (x right, y away: -Z), an upright wall (y up: Y),
// or a block (plan, and z up).
function expectedBox(row, upright) {
  const mm = (k) => Number(row[k]) / 1000;
  const x = mm('x_mm'), y = mm('y_mm'), w = mm('width_mm'), h = mm('height_mm');
  if (row.depth_mm) return { X: [x, x + w], Y: [mm('z_mm'), mm('z_mm') + h], Z: [-(y + mm('depth_mm')), -y] };
  return upright ? { X: [x, x + w], Y: [y, y + h] } : { X: [x, x + w], Z: [-(y + h), -y] };
}

function boxMiss(e, box) {
  let worst = 0;
  for (const [a, i] of [['X', 0], ['Y', 1], ['Z', 2]])
    if (box[a]) worst = Math.max(worst, Math.abs(e[i] - box[a][0]), Math.abs(e[3 + i] - box[a][1]));
  return worst;
}

// The arcs of the annotations' curves, and what is wrong with any of them.
function annotationArcs(model, problems) {
  let arcs = 0;
  const curves = api.GetLineIDsWithType(model, W.IFCINDEXEDPOLYCURVE);
  for (let i = 0; i < curves.size(); ++i) {
    const raw = api.GetRawLineData(model, curves.get(i));
    const points = api.GetLine(model, raw.arguments[0].value).CoordList
      .map((p) => p.map((c) => c.value));
    for (const segment of raw.arguments[1]) {
      const at = segment.value.map((v) => v.value);
      if (at.some((k) => k < 1 || k > points.length)) problems.push(`curve #${raw.ID}: index out of range`);
      if (segment.typecode !== W.IFCARCINDEX) continue;
      ++arcs;
      const [a, b, c] = at.map((k) => points[k - 1]);
      const turn = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if (at.length !== 3 || Math.abs(turn) < 1e-6) problems.push(`curve #${raw.ID}: an arc through collinear points`);
    }
  }
  return arcs;
}

function check(dir) {
  const problems = [];
  const rows = csvRows(fs.readFileSync(path.join(dir, 'schedule.csv'), 'utf8'));
  const bytes = fs.readFileSync(path.join(dir, 'layout.ifc'));
  const model = api.OpenModel(new Uint8Array(bytes));
  if (api.GetModelSchema(model) !== 'IFC4') problems.push(`schema ${api.GetModelSchema(model)}`);
  const byTag = new Map();
  for (const type of kClasses) {
    const ids = api.GetLineIDsWithType(model, type);
    for (let i = 0; i < ids.size(); ++i) {
      const line = api.GetLine(model, ids.get(i));
      if (line.Name?.value !== line.Tag?.value) problems.push(`#${line.expressID}: Name and Tag differ`);
      byTag.set(line.Tag?.value, { id: line.expressID, type, props: {}, material: null });
    }
  }
  const byId = new Map([...byTag.values()].map((e) => [e.id, e]));
  // Properties and materials, through their relations.
  const rels = api.GetLineIDsWithType(model, W.IFCRELDEFINESBYPROPERTIES);
  for (let i = 0; i < rels.size(); ++i) {
    const rel = api.GetLine(model, rels.get(i));
    const set = api.GetLine(model, rel.RelatingPropertyDefinition.value);
    if (set.Name?.value !== 'Curdle_Element') continue;
    for (const object of rel.RelatedObjects) {
      const e = byId.get(object.value);
      if (!e) continue;
      for (const p of set.HasProperties) {
        const prop = api.GetLine(model, p.value);
        e.props[prop.Name.value] = prop.NominalValue.value;
      }
    }
  }
  const materials = api.GetLineIDsWithType(model, W.IFCRELASSOCIATESMATERIAL);
  for (let i = 0; i < materials.size(); ++i) {
    const rel = api.GetLine(model, materials.get(i));
    const name = api.GetLine(model, rel.RelatingMaterial.value).Name.value;
    for (const object of rel.RelatedObjects) if (byId.has(object.value)) byId.get(object.value).material = name;
  }
  if (byTag.size !== rows.length) problems.push(`${byTag.size} elements for ${rows.length} schedule rows`);
  const wanted = [];
  for (const row of rows) {
    const e = byTag.get(row.element_id);
    if (!e) { problems.push(`no element ${row.element_id}`); continue; }
    if (String(e.props.Value) !== row.value) problems.push(`${row.element_id}: value ${e.props.Value}, schedule ${row.value}`);
    if (e.props.Lot !== row.lot) problems.push(`${row.element_id}: lot ${e.props.Lot}, schedule ${row.lot}`);
    if (e.material !== row.material) problems.push(`${row.element_id}: material ${e.material}, schedule ${row.material}`);
    wanted.push(e.id);
  }
  const meshes = extents(model, wanted);
  // Upright when the first element's box matches the wall's plane.
  const first = rows.find((r) => meshes.has(byTag.get(r.element_id)?.id));
  const upright = first && boxMiss(meshes.get(byTag.get(first.element_id).id), expectedBox(first, true)) <
                  boxMiss(meshes.get(byTag.get(first.element_id).id), expectedBox(first, false));
  let worst = 0;
  for (const row of rows) {
    const e = byTag.get(row.element_id);
    if (!e) continue;
    const extent = meshes.get(e.id);
    if (!extent) { problems.push(`${row.element_id}: no mesh`); continue; }
    const miss = boxMiss(extent, expectedBox(row, upright));
    worst = Math.max(worst, miss);
    if (miss > kTolerance) problems.push(`${row.element_id}: extent off by ${(miss * 1000).toFixed(4)} mm`);
  }
  const arcs = annotationArcs(model, problems);
  const openings = rows.filter((r) => r.element_type === 'opening').length;
  const voids = api.GetLineIDsWithType(model, W.IFCRELVOIDSELEMENT).size();
  if (voids !== openings) problems.push(`${voids} voids for ${openings} openings`);
  api.CloseModel(model);
  const name = path.basename(dir);
  if (problems.length) {
    console.log(`${name}: ${problems.length} problems`);
    for (const p of problems.slice(0, 10)) console.log('  ' + p);
  } else {
    console.log(`${name}: ${rows.length} elements agree (extents within ${(worst * 1000).toFixed(4)} mm)${voids ? `, ${voids} voids` : ''}${arcs ? `, ${arcs} arcs set out` : ''}`);
  }
  return problems.length === 0;
}

let ok = true;
for (const dir of process.argv.slice(2)) ok = check(dir) && ok;
process.exit(ok ? 0 : 1);
