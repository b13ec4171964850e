// The floor over the curd: the layout's outline and zones drawn on the segment the floor is laid
// from, and zones drawn or typed in metres, added to the layout or kept empty by a search.
import { $, showError, state } from "./page_state.js";
import { draw, fieldSize } from "./canvas.js";
import { schedule, tomlArray, tomlString } from "./app.js";

// The surface the server describes (outline, zones, where the segment's cells lie), or null.
export function surface() {
  const layout = state.whole && state.whole.layout;
  return layout && layout.surface ? layout : null;
}

// The segment the floor is laid on: the selection when it has the floor's size.
function floorSegment() {
  const layout = surface();
  if (!layout) return null;
  const [fw, fh] = layout.segment_cells;
  if (state.segment && state.segment[2] === fw && state.segment[3] === fh) return state.segment;
  const [w, h] = fieldSize();
  return !state.segment && w === fw && h === fh ? [0, 0, fw, fh] : null;
}

// mm on the floor to cells of the field (continuous), and back.
function mmToCell([x, y], segment) {
  const s = surface().surface;
  return [
    segment[0] + (x - s.origin_mm[0]) / s.cell_mm[0],
    segment[1] + (y - s.origin_mm[1]) / s.cell_mm[1]
  ];
}
function cellToMm([u, v], segment) {
  const s = surface().surface;
  return [
    s.origin_mm[0] + s.cell_mm[0] * (u - segment[0]),
    s.origin_mm[1] + s.cell_mm[1] * (v - segment[1])
  ];
}

const svgNS = 'http://www.w3.org/2000/svg';
function svgPolygon(points, segment, h, cls) {
  const el = document.createElementNS(svgNS, 'polygon');
  el.setAttribute(
      'points',
      points
          .map((p) => {
            const [u, v] = mmToCell(p, segment);
            return `${u.toFixed(3)},${(h - v).toFixed(3)}`;
          })
          .join(' '));
  el.setAttribute('class', cls);
  return el;
}

// A building's façades on its unrolled strip: a dashed line at each corner and each face's
// name along the top, so that a segment is chosen knowing where the corners fall.
function drawFacades(overlay, building, segment, h) {
  // Round a ring (the field wrapped round the building, turned by its phase) a place on the
  // strip is taken round to the field's cells.
  const s = surface().surface;
  const round = (x) => {
    const [u] = mmToCell([x, 0], segment);
    if (!(s.period_mm > 0)) return u;
    const cells = s.period_mm / s.cell_mm[0];
    return segment[0] + ((((u - segment[0]) % cells) + cells) % cells);
  };
  for (const f of building.facades) {
    const u1 = round(f.start_mm + f.length_mm), middle = round(f.start_mm + f.length_mm / 2);
    if (f.corner !== 'end' && f.corner !== 'bend') {
      const line = document.createElementNS(svgNS, 'line');
      line.setAttribute('x1', u1), line.setAttribute('x2', u1);
      line.setAttribute('y1', 0), line.setAttribute('y2', h);
      line.setAttribute('class', `corner ${f.corner}`);
      overlay.append(line);
    }
    const name = document.createElementNS(svgNS, 'text');
    name.setAttribute('x', middle);
    name.setAttribute('y', 0);
    name.setAttribute('class', 'facade-name');
    name.setAttribute('font-size', (h / 9).toFixed(2));  // in cells, as the strip is drawn
    name.textContent = f.name;
    overlay.append(name);
  }
}

// Redraws the outline, the zones and the zone being drawn over the canvas.
export function drawSurface() {
  const overlay = $('surface-overlay');
  overlay.textContent = '';
  const building = surface() && surface().building;
  // A building's strip takes no zones: its openings come from the recipe.
  $('zone-box').hidden = !surface() || Boolean(building);
  const segment = floorSegment();
  if (!segment) {
    overlay.setAttribute('hidden', '');
    return;
  }
  overlay.removeAttribute('hidden');
  const [w, h] = fieldSize();
  overlay.setAttribute('viewBox', `0 0 ${w} ${h}`);
  const s = surface().surface;
  overlay.append(svgPolygon(s.outline_mm, segment, h, 'outline'));
  if (building) drawFacades(overlay, building, segment, h);
  for (const z of s.zones) {
    const el = svgPolygon(z.polygon, segment, h, `zone ${z.rule}`);
    const title = document.createElementNS(svgNS, 'title');
    title.textContent = z.rule === 'value' ? `${z.name}: value ${z.value}` : `${z.name}: kept free`;
    el.append(title);
    overlay.append(el);
  }
  const drawn = typedZone(false);
  if (drawn) overlay.append(svgPolygon(rectCorners(drawn), segment, h, 'zone drawn'));
  renderZoneList();
}

function rectCorners([x, y, w, h]) {
  return [[x, y], [x + w, y], [x + w, y + h], [x, y + h]];
}

// The zone in the X, Y, W, H fields, in mm from the floor's bottom-left corner; null (and, when
// `complain`, a message saying what is allowed) when it is not a rectangle on the floor.
function typedZone(complain) {
  const metres = ['zone-x', 'zone-y', 'zone-w', 'zone-h'].map((id) => $(id).value.trim());
  if (metres.some((t) => t === '')) {
    if (complain)
      showError('Zone: give X, Y, W and H in metres, or drag on the floor with \'draw\' ticked');
    return null;
  }
  const mm = metres.map((t) => Math.round(Number(t) * 1000));
  const size = surface().size_mm;
  const ok = mm.every(Number.isFinite) && mm[0] >= 0 && mm[1] >= 0 && mm[2] > 0 && mm[3] > 0 &&
      mm[0] + mm[2] <= size[0] && mm[1] + mm[3] <= size[1];
  if (!ok) {
    if (complain)
      showError(`Zone ${
          metres.join(
              ', ')} m: X, Y from the floor's bottom-left corner and W, H above 0, inside the floor of ${
          size[0] / 1000} × ${size[1] / 1000} m`);
    return null;
  }
  return mm;
}

function showZone(mm) {
  ['zone-x', 'zone-y', 'zone-w', 'zone-h'].forEach((id, i) => {
    $(id).value = String(mm[i] / 1000);
  });
  $('zone-text').textContent =
      `${mm[2] / 1000} × ${mm[3] / 1000} m at ${mm[0] / 1000}, ${mm[1] / 1000} m`;
}

// ---- drawing with the pointer (a rectangle snapped to 10 mm, clamped to the floor) ----

function continuousCellAt(event) {
  const rect = $('curd').getBoundingClientRect();
  const [w, h] = fieldSize();
  return [
    (event.clientX - rect.left) / rect.width * w, h - (event.clientY - rect.top) / rect.height * h
  ];
}

export let zoneFrom = null;
export function zoneDrag(event, phase) {
  const segment = floorSegment();
  if (!segment) {
    showError('Select the floor (Segment: the floor) to draw a zone on it');
    return;
  }
  const size = surface().size_mm;
  const snap = (v, most) => Math.max(0, Math.min(most, Math.round(v / 10) * 10));
  const at = cellToMm(continuousCellAt(event), segment).map((v, i) => snap(v, size[i]));
  if (phase === 'start') zoneFrom = at;
  if (!zoneFrom) return;
  const x = Math.min(zoneFrom[0], at[0]), y = Math.min(zoneFrom[1], at[1]);
  const w = Math.abs(at[0] - zoneFrom[0]), h = Math.abs(at[1] - zoneFrom[1]);
  if (w > 0 && h > 0) showZone([x, y, w, h]);
  if (phase === 'end') zoneFrom = null;
  drawSurface();
}

function drawingZone() {
  return $('zone-draw').checked && floorSegment() !== null;
}

// ---- the layout's zones, as the override layout.zones ----

export function recipeZones() {
  const layout = state.recipe.layout;
  return layout && layout.surface ? layout.surface.zones : [];
}

export function zonesOverride() {
  if (!state.zones || JSON.stringify(state.zones) === JSON.stringify(recipeZones())) return null;
  const tables = state.zones.map(
      (z) => `{name=${tomlString(z.name)},polygon=${
                 tomlArray(z.polygon.map((p) => tomlArray(p)))},rule=${tomlString(z.rule)}` +
          (z.rule === 'value' ? `,value=${z.value}` : '') + '}');
  return `layout.zones=${tomlArray(tables)}`;
}

function addZone() {
  const mm = typedZone(true);
  if (!mm) return;
  const rule = $('zone-rule').value;
  const zone = {
    name: $('zone-name').value.trim() || `zone ${state.zones.length + 1}`,
    rule,
    polygon: rectCorners(mm)
  };
  if (rule === 'value') {
    const v = Number($('zone-value').value);
    const values = state.whole.legend.length;
    if (!Number.isInteger(v) || v < 0 || v >= values) {
      showError(`Zone value '${$('zone-value').value}': a whole number from 0 to ${
          values - 1}, one of the legend's values`);
      return;
    }
    zone.value = v;
  }
  showError('');
  state.zones.push(zone);
  schedule();
}

function keepZoneEmpty() {
  const mm = typedZone(true);
  if (!mm) return;
  showError('');
  const box = $('search-targets');
  box.value = (box.value.trim() ? box.value.trim() + '\n' : '') + `empty=${mm.join(',')} mm`;
}

// A zone's size as a site team reads it, to the millimetre: a round one by its diameter, else
// the extent of its edges, arcs included (a vertex [x, y, bulge] starts an arc).
function zoneSize(polygon) {
  const m = (mm) => `${Number((mm / 1000).toFixed(3))}`;
  if (polygon.length === 2 && polygon.every((p) => Math.abs(p[2] || 0) === 1))
    return `round, ⌀ ${m(Math.hypot(polygon[1][0] - polygon[0][0], polygon[1][1] - polygon[0][1]))} m`;
  const xs = [], ys = [];
  polygon.forEach((p, i) => {
    const q = polygon[(i + 1) % polygon.length], bulge = p[2] || 0;
    xs.push(p[0]), ys.push(p[1]);
    if (!bulge) return;
    // Points along the arc: the chord's middle pushed out by the sagitta, at 32 steps.
    const sweep = 4 * Math.atan(bulge), dx = q[0] - p[0], dy = q[1] - p[1];
    const chord = Math.hypot(dx, dy), r = chord / (2 * Math.sin(Math.abs(sweep) / 2));
    const offset = (chord * (1 - bulge * bulge)) / (4 * bulge);
    const cx = (p[0] + q[0]) / 2 - (dy / chord) * offset, cy = (p[1] + q[1]) / 2 + (dx / chord) * offset;
    const start = Math.atan2(p[1] - cy, p[0] - cx);
    for (let k = 1; k < 32; ++k) {
      xs.push(cx + r * Math.cos(start + (sweep * k) / 32));
      ys.push(cy + r * Math.sin(start + (sweep * k) / 32));
    }
  });
  return `${m(Math.max(...xs) - Math.min(...xs))} × ${m(Math.max(...ys) - Math.min(...ys))} m`;
}

export function renderZoneList() {
  const list = $('zone-list');
  list.textContent = '';
  (state.zones || []).forEach((z, i) => {
    const row = document.createElement('div');
    row.className = 'row';
    const text = document.createElement('span');
    text.textContent =
        `${z.name}: ${z.rule === 'value' ? 'value ' + z.value : 'kept free'}, ${zoneSize(z.polygon)}`;
    const remove = document.createElement('button');
    remove.textContent = 'remove';
    remove.setAttribute('aria-label', `Remove zone ${z.name}`);
    remove.addEventListener('click', () => {
      state.zones.splice(i, 1);
      schedule();
    });
    row.append(text, remove);
    list.append(row);
  });
}

export function wireZones() {
  for (const id of ['zone-x', 'zone-y', 'zone-w', 'zone-h'])
    $(id).addEventListener('change', () => {
      const mm = typedZone(true);
      if (mm) {
        showError('');
        showZone(mm);
      }
      drawSurface();
    });
  $('zone-rule').addEventListener('change', () => {
    $('zone-value').disabled = $('zone-rule').value !== 'value';
  });
  $('zone-add').addEventListener('click', addZone);
  $('zone-target').addEventListener('click', keepZoneEmpty);
}
