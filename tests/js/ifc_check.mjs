// Reads every layout.ifc back with web-ifc (an independent IFC reader, WASM) beside the
// schedule.csv written with it, and checks: one element per schedule row, named and tagged by
// its ID, with the model's owner history; its value, lot and material as the schedule gives
// them (the standard sets are ifc_lite_check.mjs's to read); its placement at its own corner;
// its body one solid (a tree: trunk and canopy) whose extent (from web-ifc's own meshes) is the
// row's box within 0.01 mm; each element in a space or a storey (a building's units in them
// through the wall that nests them, its walls, windows and doors in one); every
// opening of a sheet an annotation assigned to its plate, its outline (an 'Annotation' curve)
// the row's box, and each plate's mesh as open as its sheet (the holes are in its body, and no
// IfcOpeningElement voids it: nothing for a reader to subtract); every setting-out annotation's
// IfcIndexedPolyCurve with its arcs as IfcArcIndex through three distinct points on a circle;
// and that web-ifc logs nothing, not even a warning, on any model.
// Lines are read raw where only a few attributes are needed (and where web-ifc's typed reader
// has no select values).
// Prints the slowest model's time to open and mesh.
// Usage: node ifc_check.mjs DIR... (each with layout.ifc and schedule.csv).
import fs from 'fs';
import path from 'path';
import * as W from 'web-ifc';
import { boxMiss, buildingMiss, csvRows, expectedBox, isBuilding, isFramedScreen } from './schedule_rows.mjs';

// What web-ifc logs, caught: its module prints through console.log as bound when it starts.
const logged = [];
const print = console.log;
console.log = (...words) => {
  const line = words.join(' ');
  if (line.startsWith('[WEB-IFC]')) logged.push(line);
  else print(...words);
};
const api = new W.IfcAPI();
await api.Init();
api.SetLogLevel(W.LogLevel.LOG_LEVEL_WARN);
const kTolerance = 1e-5;  // 0.01 mm, in web-ifc's metres
const kClasses = [W.IFCCOVERING, W.IFCANNOTATION, W.IFCGEOGRAPHICELEMENT, W.IFCFURNITURE,
                  W.IFCBUILDINGELEMENTPROXY, W.IFCBUILDINGELEMENTPART];

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

// The arcs of the annotations' curves, and what is wrong with any of them.
function annotationArcs(model, problems) {
  let arcs = 0;
  const curves = api.GetLineIDsWithType(model, W.IFCINDEXEDPOLYCURVE);
  for (let i = 0; i < curves.size(); ++i) {
    const raw = api.GetRawLineData(model, curves.get(i));
    if (!raw.arguments[1]) continue;  // no segments: a polyline through its points (a sheet's hole)
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

// A local placement's frame in the model (millimetres, Z up) as [origin, x axis, y axis, z axis].
function placementFrame(model, id, cache) {
  if (cache.has(id)) return cache.get(id);
  const [relTo, relative] = api.GetRawLineData(model, id).arguments;
  const parent = relTo?.value ? placementFrame(model, relTo.value, cache)
                              : [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const [location, axis, refDirection] = api.GetRawLineData(model, relative.value).arguments;
  const numbers = (ref) => api.GetRawLineData(model, ref.value).arguments[0].map((c) => c.value);
  const vec = (d, fallback) => (d?.value ? numbers(d) : fallback);
  const z = vec(axis, [0, 0, 1]), x = vec(refDirection, [1, 0, 0]);
  const y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]];
  const at = (v) => [0, 1, 2].map((k) => parent[1][k] * v[0] + parent[2][k] * v[1] + parent[3][k] * v[2]);
  const o = location?.value ? numbers(location) : [0, 0, 0];
  const origin = at(o).map((v, k) => v + parent[0][k]);
  const frame = [origin, at(x), at(y), at(z)];
  cache.set(id, frame);
  return frame;
}

// A point of the surface's plane (layout mm) in the model: a wall's y is up (Z), a plan's is Y.
function modelPoint(x, y, upright) { return upright ? [x, 0, y] : [x, y, 0]; }

// The sets named `names` of each element: { setName: { property: value } }: every set's name
// and every relation's target first, then only the wanted sets' values.
function setsOf(model, names) {
  const wanted = new Map();  // set id -> its name and values
  for (const type of [W.IFCPROPERTYSET, W.IFCELEMENTQUANTITY]) {
    const ids = api.GetLineIDsWithType(model, type);
    for (let i = 0; i < ids.size(); ++i) {
      const name = api.GetRawLineData(model, ids.get(i)).arguments[2]?.value;
      if (names.includes(name)) wanted.set(ids.get(i), { name, values: null });
    }
  }
  const out = new Map();
  const rels = api.GetLineIDsWithType(model, W.IFCRELDEFINESBYPROPERTIES);
  for (let i = 0; i < rels.size(); ++i) {
    const raw = api.GetRawLineData(model, rels.get(i));
    const set = wanted.get(raw.arguments[5].value);
    if (!set) continue;
    if (!set.values) {
      // Raw: a property set's members are its 5th attribute, a quantity set's its 6th; a
      // property's name is its 1st and its value its 3rd, a quantity's value its 4th.
      const quantities = set.name.startsWith('Qto_');
      set.values = {};
      const members = api.GetRawLineData(model, raw.arguments[5].value).arguments[quantities ? 5 : 4];
      for (const member of members) {
        const a = api.GetRawLineData(model, member.value).arguments;
        set.values[a[0].value] = (quantities ? a[3] : a[2])?.value;
      }
    }
    for (const object of raw.arguments[4]) {
      if (!out.has(object.value)) out.set(object.value, {});
      out.get(object.value)[set.name] = set.values;
    }
  }
  return out;
}

// Which spatial element holds each element: id -> IFC type of its container.
function containers(model) {
  const out = new Map();
  for (const [id, holder] of holders(model)) out.set(id, api.GetLineType(model, holder));
  return out;
}

// Which spatial element holds each element: id -> the container's id.
function holders(model) {
  const out = new Map();
  const rels = api.GetLineIDsWithType(model, W.IFCRELCONTAINEDINSPATIALSTRUCTURE);
  for (let i = 0; i < rels.size(); ++i) {
    const rel = api.GetLine(model, rels.get(i));
    for (const object of rel.RelatedElements) out.set(object.value, rel.RelatingStructure.value);
  }
  return out;
}

// Each window and door in the storey its base stands in: the highest whose elevation (IFC z,
// mm) is at or below the bottom of its mesh (web-ifc's Y, metres). Returns how many stand in
// each storey, by name.
function storeyProblems(model, problems) {
  const storeys = [];
  const ids = api.GetLineIDsWithType(model, W.IFCBUILDINGSTOREY);
  for (let i = 0; i < ids.size(); ++i) {
    const s = api.GetLine(model, ids.get(i));
    storeys.push({ id: ids.get(i), name: s.Name?.value, elevation: Number(s.Elevation?.value) / 1000, held: 0 });
  }
  storeys.sort((a, b) => a.elevation - b.elevation);
  const held = holders(model);
  const openings = [];
  for (const type of [W.IFCWINDOW, W.IFCDOOR]) {
    const found = api.GetLineIDsWithType(model, type);
    for (let i = 0; i < found.size(); ++i) openings.push(found.get(i));
  }
  const meshes = extents(model, openings);
  for (const id of openings) {
    const base = meshes.get(id)?.[1];
    const want = storeys.filter((s) => s.elevation <= base + 1e-6).pop();
    const got = storeys.find((s) => s.id === held.get(id));
    if (!want || got !== want)
      problems.push(`${api.GetLine(model, id).Name?.value}: base at ${base} m in ${got?.name ?? 'no storey'}, not ${want?.name}`);
    else ++got.held;
  }
  return storeys.map((s) => `${s.name} ${s.held}`).join(', ');
}

// A building's parts: each unit's wall (by the wall's Tag, its façade's name), which nests it.
function wallsOfParts(model) {
  const out = new Map();
  const rels = api.GetLineIDsWithType(model, W.IFCRELNESTS);
  for (let i = 0; i < rels.size(); ++i) {
    const raw = api.GetRawLineData(model, rels.get(i)).arguments;
    const whole = raw[4].value;
    if (api.GetLineType(model, whole) !== W.IFCWALL) continue;
    const tag = api.GetRawLineData(model, whole).arguments[7]?.value;
    for (const part of raw[5]) out.set(part.value, tag);
  }
  return out;
}

// A building's walls, openings, windows and doors against its report: one wall per façade, one
// opening per window or door, each voiding its wall and filled.
function buildingProblems(model, dir, problems) {
  const report = JSON.parse(fs.readFileSync(path.join(dir, 'report.json'), 'utf8'));
  const facades = report.layout.facades;
  const count = (type) => api.GetLineIDsWithType(model, type).size();
  const openings = facades.reduce((n, f) => n + f.openings, 0);
  if (count(W.IFCWALL) !== facades.length) problems.push(`${count(W.IFCWALL)} walls for ${facades.length} façades`);
  for (const [what, n] of [['openings', count(W.IFCOPENINGELEMENT)], ['voids', count(W.IFCRELVOIDSELEMENT)],
                           ['fillings', count(W.IFCRELFILLSELEMENT)],
                           ['windows and doors', count(W.IFCWINDOW) + count(W.IFCDOOR)]])
    if (n !== openings) problems.push(`${n} ${what} for ${openings} openings in the report`);
  if (count(W.IFCBUILDINGSTOREY) < 1) problems.push('no storey');
  // The walls meshed, their openings cut where a wall has a body (a backing leaf), so that
  // whatever web-ifc logs doing it is caught.
  const walls = api.GetLineIDsWithType(model, W.IFCWALL);
  extents(model, Array.from({ length: walls.size() }, (_, i) => walls.get(i)));
  // Walls, windows and doors each in a storey (the one their base stands in).
  const heldBy = containers(model);
  for (const type of [W.IFCWALL, W.IFCWINDOW, W.IFCDOOR]) {
    const ids = api.GetLineIDsWithType(model, type);
    for (let i = 0; i < ids.size(); ++i)
      if (heldBy.get(ids.get(i)) !== W.IFCBUILDINGSTOREY) problems.push(`${api.GetLine(model, ids.get(i)).Name?.value}: in no storey`);
  }
  return { walls: facades.length, openings, storeys: storeyProblems(model, problems) };
}

// Each triangle of a product's meshes, placed (metres, web-ifc's frame): fn(a, b, c).
function eachTriangle(model, id, fn) {
  api.StreamMeshes(model, [id], (mesh) => {
    for (let g = 0; g < mesh.geometries.size(); ++g) {
      const placed = mesh.geometries.get(g);
      const geometry = api.GetGeometry(model, placed.geometryExpressID);
      const v = api.GetVertexArray(geometry.GetVertexData(), geometry.GetVertexDataSize());
      const ix = api.GetIndexArray(geometry.GetIndexData(), geometry.GetIndexDataSize());
      const T = placed.flatTransformation;
      const p = (k) => [0, 1, 2].map((a) => T[a] * v[6 * k] + T[4 + a] * v[6 * k + 1] + T[8 + a] * v[6 * k + 2] + T[12 + a]);
      for (let t = 0; t < ix.length; t += 3) fn(p(ix[t]), p(ix[t + 1]), p(ix[t + 2]));
      geometry.delete();
    }
  });
}

// The area of a plate's faces that look along `normal` (metres², web-ifc's frame): the sheet
// as punched, holes out.
function facingArea(model, id, normal) {
  let area = 0;
  eachTriangle(model, id, (a, b, c) => {
    const u = [0, 1, 2].map((k) => b[k] - a[k]), w = [0, 1, 2].map((k) => c[k] - a[k]);
    const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const along = n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2];
    if (along > 0) area += along / 2;
  });
  return area;
}

// The volume a plate's mesh encloses (metres³, by the divergence theorem over its triangles):
// a rolled sheet's metal, which no one direction shows.
function enclosedVolume(model, id) {
  let volume = 0;
  eachTriangle(model, id, (a, b, c) => {
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  });
  return volume;
}

// The openings each plate's IfcRelAssignsToProduct assigns to it (an opening of the schedule
// and to one plate only): how many.
function holesOfPlates(model, byId, problems) {
  const seen = new Set();
  const rels = api.GetLineIDsWithType(model, W.IFCRELASSIGNSTOPRODUCT);
  for (let i = 0; i < rels.size(); ++i) {
    const a = api.GetRawLineData(model, rels.get(i)).arguments;
    if (api.GetLineType(model, a[6].value) !== W.IFCPLATE) continue;
    for (const hole of a[4]) {
      if (byId.get(hole.value)?.type !== W.IFCANNOTATION) problems.push(`#${hole.value}: assigned to a sheet, not an opening`);
      if (seen.has(hole.value)) problems.push(`#${hole.value}: assigned to two sheets`);
      seen.add(hole.value);
    }
  }
  return seen.size;
}

function check(dir) {
  const problems = [];
  const rows = csvRows(fs.readFileSync(path.join(dir, 'schedule.csv'), 'utf8'));
  const bytes = fs.readFileSync(path.join(dir, 'layout.ifc'));
  const started = performance.now();
  const model = api.OpenModel(new Uint8Array(bytes));
  if (api.GetModelSchema(model) !== 'IFC4') problems.push(`schema ${api.GetModelSchema(model)}`);
  const owners = api.GetLineIDsWithType(model, W.IFCOWNERHISTORY);
  if (owners.size() !== 1) problems.push(`${owners.size()} owner histories`);
  const byTag = new Map();
  for (const type of kClasses) {
    const ids = api.GetLineIDsWithType(model, type);
    for (let i = 0; i < ids.size(); ++i) {
      // Raw: GlobalId, OwnerHistory, Name, Description, ObjectType, ObjectPlacement,
      // Representation, Tag.
      const a = api.GetRawLineData(model, ids.get(i)).arguments;
      const line = { ObjectPlacement: a[5], Representation: a[6] };
      // A sheet's opening is an annotation, known by its name (IFC4 gives an annotation no tag).
      if (type === W.IFCANNOTATION && a[4]?.value !== 'opening') continue;
      const tag = type === W.IFCANNOTATION ? a[2]?.value : a[7]?.value;
      if (a[2]?.value !== tag) problems.push(`#${ids.get(i)}: Name and Tag differ`);
      if (a[1]?.value !== owners.get(0)) problems.push(`${tag}: no owner history`);
      byTag.set(tag, { id: ids.get(i), type, line, material: null });
    }
  }
  const building = isBuilding(rows);
  const screen = isFramedScreen(rows);  // its openings are rows, placed on its façades
  const byId = new Map([...byTag.values()].map((e) => [e.id, e]));
  const wallOf = building ? wallsOfParts(model) : new Map();
  const sets = setsOf(model, ['Curdle_Element', 'Qto_PlateBaseQuantities']);
  const materials = api.GetLineIDsWithType(model, W.IFCRELASSOCIATESMATERIAL);
  for (let i = 0; i < materials.size(); ++i) {
    const rel = api.GetLine(model, materials.get(i));
    const name = api.GetLine(model, rel.RelatingMaterial.value).Name.value;
    for (const object of rel.RelatedObjects) if (byId.has(object.value)) byId.get(object.value).material = name;
  }
  const heldBy = containers(model);
  if (byTag.size !== rows.length) problems.push(`${byTag.size} elements for ${rows.length} schedule rows`);
  const wanted = [];
  for (const row of rows) {
    const e = byTag.get(row.element_id);
    if (!e) { problems.push(`no element ${row.element_id}`); continue; }
    const own = sets.get(e.id)?.Curdle_Element ?? {};
    if (String(own.Value) !== row.value) problems.push(`${row.element_id}: value ${own.Value}, schedule ${row.value}`);
    if (own.Lot !== row.lot) problems.push(`${row.element_id}: lot ${own.Lot}, schedule ${row.lot}`);
    if (e.material !== row.material) problems.push(`${row.element_id}: material ${e.material}, schedule ${row.material}`);
    const holder = heldBy.get(e.id);
    if (e.type === W.IFCANNOTATION) {
      if (holder !== W.IFCSPACE && holder !== W.IFCBUILDINGSTOREY) problems.push(`${row.element_id}: not in a space or a storey`);
    } else {
      if (building && wallOf.get(e.id) !== row.facade) problems.push(`${row.element_id}: a part of wall ${wallOf.get(e.id)}, not ${row.facade}`);
      // A building's unit is in the storeys through its wall, which nests it: not contained too.
      if (building && e.type === W.IFCBUILDINGELEMENTPART) {
        if (holder !== undefined) problems.push(`${row.element_id}: contained as well as nested in its wall`);
      } else if (holder !== W.IFCSPACE && holder !== W.IFCBUILDINGSTOREY) problems.push(`${row.element_id}: not in a space or a storey`);
      const shape = api.GetRawLineData(model, e.line.Representation.value).arguments[2][0].value;
      const items = api.GetRawLineData(model, shape).arguments[3];
      const solids = e.type === W.IFCGEOGRAPHICELEMENT ? 2 : 1;
      if (building ? items.length < 1 : items.length !== solids) problems.push(`${row.element_id}: ${items.length} solids`);
      wanted.push(e.id);
    }
  }
  const meshes = extents(model, wanted);
  const meshed = performance.now() - started;
  // Upright when the elements' frames stand in a wall: their z (the thickness) horizontal.
  const frames = new Map();
  const first = byTag.get(rows[0]?.element_id);
  const upright = first ? Math.abs(placementFrame(model, first.line.ObjectPlacement.value, frames)[3][2]) < 0.5 : false;
  let worst = 0;
  const built = building ? buildingProblems(model, dir, problems) : null;
  const curved = (building || screen) && JSON.parse(fs.readFileSync(path.join(dir, 'report.json'), 'utf8')).layout.facades.some((f) => f.curved);
  for (const row of rows) {
    const e = byTag.get(row.element_id);
    if (!e) continue;
    if (building || screen) {  // its face's middle on its mesh's outside, at its course's height
      const extent = e.type === W.IFCANNOTATION ? outlineExtent(model, e, frames) : meshes.get(e.id);
      if (!extent) { problems.push(`${row.element_id}: no mesh`); continue; }
      const miss = buildingMiss(extent, row, curved);
      worst = Math.max(worst, miss);
      if (miss > kTolerance) problems.push(`${row.element_id}: ${(miss * 1000).toFixed(4)} mm from its face's middle`);
      continue;
    }
    // Placed at its own corner.
    const at = placementFrame(model, e.line.ObjectPlacement.value, frames)[0];
    const corner = modelPoint(Number(row.x_mm), Number(row.y_mm), upright);
    const off = Math.max(Math.abs(at[0] - corner[0]), Math.abs(at[1] - corner[1]), Math.abs(at[2] - corner[2]));
    if (off > 0.01) problems.push(`${row.element_id}: placed ${off.toFixed(3)} mm from its corner`);
    const extent = e.type === W.IFCANNOTATION ? outlineExtent(model, e, frames) : meshes.get(e.id);
    if (!extent) { problems.push(`${row.element_id}: no mesh`); continue; }
    const miss = boxMiss(extent, expectedBox(row, upright));
    worst = Math.max(worst, miss);
    if (miss > kTolerance) problems.push(`${row.element_id}: extent off by ${(miss * 1000).toFixed(4)} mm`);
  }
  const arcs = annotationArcs(model, problems);
  const openings = rows.filter((r) => r.element_type === 'opening').length;
  const voids = api.GetLineIDsWithType(model, W.IFCRELVOIDSELEMENT).size();
  if (!building && voids) problems.push(`${voids} voids: a reader would subtract what the sheets' bodies have cut`);
  const plates = api.GetLineIDsWithType(model, W.IFCPLATE);
  const holes = holesOfPlates(model, byId, problems);
  if (plates.size() && holes !== openings) problems.push(`${holes} openings assigned to sheets, ${openings} in the schedule`);
  for (let i = 0; i < plates.size(); ++i) {
    const plate = plates.get(i);
    const { NetArea: net, GrossArea: gross } = sets.get(plate)?.Qto_PlateBaseQuantities ?? {};
    // Out of the sheet; a sheet rolled to an arc faces every way, and its metal is its volume.
    const width = sets.get(plate)?.Qto_PlateBaseQuantities?.Width;
    const area = screen ? enclosedVolume(model, plate) / (width / 1000)
                        : facingArea(model, plate, upright ? [0, 0, 1] : [0, 1, 0]);
    // Within 5 % of the open area: the holes' polygons lie within the chord tolerance of their
    // circles, and a sheet without its holes would miss by all of it.
    if (!(Math.abs(area - net) <= 0.05 * (gross - net))) problems.push(`sheet #${plate}: ${area.toFixed(5)} m² of metal, ${net} net of ${gross}`);
  }
  api.CloseModel(model);
  for (const line of logged.splice(0)) problems.push(`web-ifc logged: ${line}`);
  const name = path.basename(dir);
  if (problems.length) {
    console.log(`${name}: ${problems.length} problems`);
    for (const p of problems.slice(0, 10)) console.log('  ' + p);
  } else {
    console.log(`${name}: ${rows.length} elements agree (extents within ${(worst * 1000).toFixed(4)} mm)${built ? `, ${built.walls} walls with their ${built.openings} openings filled (windows and doors by storey: ${built.storeys})` : ''}${plates.size() ? `, ${plates.size()} sheets as punched with ${holes} openings assigned` : ''}${arcs ? `, ${arcs} arcs set out` : ''}; opened and meshed in ${(meshed / 1000).toFixed(2)} s`);
  }
  slowest = Math.max(slowest, meshed / 1000);
  return problems.length === 0;
}

// An opening's extent from its 'Annotation' outline, in web-ifc's frame (metres, Y up, Z towards
// the viewer), as the meshes give the others'.
function outlineExtent(model, e, frames) {
  const [o, x, y] = placementFrame(model, e.line.ObjectPlacement.value, frames);
  const rep = api.GetLine(model, api.GetLine(model, e.line.Representation.value).Representations[0].value);
  const out = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const item of rep.Items) {
    for (const p of api.GetLine(model, item.value).Points) {
      const [u, v] = api.GetLine(model, p.value).Coordinates.map((c) => c.value);
      const m = [0, 1, 2].map((k) => o[k] + x[k] * u + y[k] * v);
      const w = [m[0] / 1000, m[2] / 1000, -m[1] / 1000];  // Z up to Y up
      for (let a = 0; a < 3; ++a) out[a] = Math.min(out[a], w[a]), out[3 + a] = Math.max(out[3 + a], w[a]);
    }
  }
  return out;
}

let slowest = 0;
let ok = true;
for (const dir of process.argv.slice(2)) ok = check(dir) && ok;
console.log(`web-ifc: the slowest model opened and meshed in ${slowest.toFixed(2)} s`);
process.exit(ok ? 0 : 1);
