// schedule.csv's rows, and the box each row says its piece fills, as the IFC checks compare them.

// The rows as objects keyed by the header (RFC 4180 quoting, a leading BOM skipped).
export function csvRows(text) {
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

// The row's box in the readers' frame (metres, Y up, Z towards the viewer): a plan (x right,
// y away: -Z), an upright wall (y up: Y), or a block (plan, and z up).
export function expectedBox(row, upright) {
  const mm = (k) => Number(row[k]) / 1000;
  const x = mm('x_mm'), y = mm('y_mm'), w = mm('width_mm'), h = mm('height_mm');
  if (row.depth_mm) return { X: [x, x + w], Y: [mm('z_mm'), mm('z_mm') + h], Z: [-(y + mm('depth_mm')), -y] };
  return upright ? { X: [x, x + w], Y: [y, y + h] } : { X: [x, x + w], Z: [-(y + h), -y] };
}

// How far an extent [min x, y, z, max x, y, z] lies from the box, on the axes the box gives.
export function boxMiss(e, box) {
  let worst = 0;
  for (const [a, i] of [['X', 0], ['Y', 1], ['Z', 2]])
    if (box[a]) worst = Math.max(worst, Math.abs(e[i] - box[a][0]), Math.abs(e[3 + i] - box[a][1]));
  return worst;
}

// A building's schedule (layout.building): each row's x, y, z is the middle of the unit's outer
// face in the building (mm, x east, y north, z up), and its façade is named. A building's walls
// have units; a perforated screen on a building (or along a path) has only openings.
const framed = (rows) => rows.length > 0 && 'facade' in rows[0];
export function isBuilding(rows) { return framed(rows) && rows.some((r) => r.element_type !== 'opening'); }
export function isFramedScreen(rows) { return framed(rows) && !isBuilding(rows); }

// How far a building unit's mesh extent [min x, y, z, max x, y, z] (metres, Y up, Z towards the
// viewer, south) lies from what its row says: its course's height about z, and the middle of
// its face on the extent's outside (its faces stand along x and y on a square plan; on a curve
// the face's middle lies inside the extent, behind no face).
export function buildingMiss(e, row, curved = false) {
  const p = [Number(row.x_mm) / 1000, Number(row.z_mm) / 1000, -Number(row.y_mm) / 1000];
  const h = Number(row.height_mm) / 1000;
  let worst = Math.max(Math.abs(e[1] - (p[1] - h / 2)), Math.abs(e[4] - (p[1] + h / 2)));
  for (const a of [0, 2]) worst = Math.max(worst, e[a] - p[a], p[a] - e[3 + a]);
  if (!curved) {
    const onFace = Math.min(...[0, 2].flatMap((a) => [Math.abs(p[a] - e[a]), Math.abs(p[a] - e[3 + a])]));
    worst = Math.max(worst, onFace);
  }
  return worst;
}
