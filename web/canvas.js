// The page: drawing the curd on the canvas, and selecting a segment on it.
import { $, showError, state } from "./page_state.js";
import { fieldGl } from "./field_gl.js";
import { drawSurface, zoneDrag, zoneFrom } from "./surface.js";
import { refreshSegment, windowText } from "./app.js";

// ---- drawing ----

export function hexToRgb(h) {
  const n = parseInt(h.slice(1), 16);
  return [n >> 16 & 255, n >> 8 & 255, n & 255];
}

export function fieldSize() {
  const v = state.whole.view;
  return state.whole.lattice.dimension === 1 ? [v[1], 1] : [v[2], v[3]];
}

function legendColours() {
  return state.whole.legend.map((e) => hexToRgb(e.colour));
}

// Draws the curd (fieldGl, field_gl.js) at the size it is shown: the canvas's pixels are the
// screen's, not the field's cells, so a 2048 x 2048 field costs no more to draw than a small one.
export function draw() {
  const canvas = $("curd");
  const whole = state.whole;
  if (!whole.values) {
    canvas.width = canvas.height = 1;
    showError("The page draws 1-D and 2-D lattices; for 3-D, use the report here and curdle generate.");
    return;
  }
  const [w, h] = fieldSize();
  const room = Math.min($("view").clientWidth - 4, window.innerHeight - 220);
  const scale = Math.max(1, Math.floor(Math.max(room, 200) / Math.max(w, h))) || 1;
  const cssScale = Math.max(w, h) * scale > room ? room / Math.max(w, h) : scale;
  const cssW = w * cssScale, cssH = Math.max(h * cssScale, h === 1 ? 40 : 0);
  canvas.style.width = `${cssW}px`;
  canvas.style.height = `${cssH}px`;
  const ratio = window.devicePixelRatio || 1;
  const pw = Math.max(1, Math.round(cssW * ratio)), ph = Math.max(1, Math.round(cssH * ratio));
  // Set only when it changes: setting a canvas's size, even to the same, makes a new buffer.
  if (canvas.width !== pw) canvas.width = pw;
  if (canvas.height !== ph) canvas.height = ph;
  if (!fieldGl.draw(canvas, whole.values, whole.value_bits, w, h, legendColours()))
    showError("This browser has no WebGL 2, which the page draws the curd with.");
  placeSelection();
}

// The palette changed on the page: the same cells in new colours.
export function recolour() {
  if (state.whole && state.whole.values) fieldGl.recolour(legendColours());
}

export function placeSelection() {
  const box = $("selection");
  if (!state.segment || !state.whole) {
    box.hidden = true;
    if (state.whole) drawSurface();
    return;
  }
  const [w, h] = fieldSize();
  const canvas = $("curd");
  const sx = canvas.clientWidth / w, sy = canvas.clientHeight / h;
  const [x, y, sw, sh] = state.segment;
  box.hidden = false;
  box.style.left = `${x * sx}px`;
  box.style.width = `${sw * sx}px`;
  box.style.top = `${(h - y - sh) * sy}px`;
  box.style.height = `${sh * sy}px`;
  const layout = state.whole.layout;
  let size = "";
  if (layout && layout.size_mm && layout.segment_cells[0] === sw && layout.segment_cells[1] === sh)
    size = ` · the floor, ${layout.size_mm[0] / 1000} × ${layout.size_mm[1] / 1000} m`;
  else if (layout)
    size = ` · ${(sw * layout.cell_mm[0] / 1000).toFixed(2)} × ${(sh * layout.cell_mm[1] / 1000).toFixed(2)} m`;
  $("segment-text").textContent = `Segment ${windowText()} (x, y, width, height in cells)${size}`;
  if (document.activeElement !== $("window-text")) $("window-text").value = windowText();
  drawSurface();
}

// ---- selection ----

export function fixMode() { return document.querySelector("input[name=fix]:checked").value; }
export function setFix(mode) {
  document.querySelector(`input[name=fix][value=${mode}]`).checked = true;
  const floor = state.recipe.layout && state.recipe.layout.segment_cells;
  if (mode === "floor" && floor) { $("fix-w").value = floor[0]; $("fix-h").value = floor[1]; }
  $("fix-w").disabled = $("fix-h").disabled = mode === "free" || mode === "floor";
}

// The fixed size in cells, or null when the selection is free.
export function fixedCells() {
  const mode = fixMode();
  const layout = state.whole && state.whole.layout;
  if (mode === "free") return null;
  if (mode === "floor" && layout && layout.segment_cells) return layout.segment_cells.slice();
  const w = Number($("fix-w").value), h = Number($("fix-h").value);
  if (!(w > 0) || !(h > 0)) return null;
  if (mode === "metres") {
    if (!layout) { showError("This recipe has no layout, so sizes in metres have no meaning; give cells."); return null; }
    return [Math.max(1, Math.round(w * 1000 / layout.cell_mm[0])), Math.max(1, Math.round(h * 1000 / layout.cell_mm[1]))];
  }
  return [Math.max(1, Math.round(w)), Math.max(1, Math.round(h))];
}

function cellAt(event) {
  const canvas = $("curd");
  const rect = canvas.getBoundingClientRect();
  const [w, h] = fieldSize();
  const x = Math.floor((event.clientX - rect.left) / rect.width * w);
  const y = h - 1 - Math.floor((event.clientY - rect.top) / rect.height * h);
  return [Math.max(0, Math.min(w - 1, x)), Math.max(0, Math.min(h - 1, y))];
}

function segmentFrom(a, b) {
  const [w, h] = fieldSize();
  const fixed = fixedCells();
  if (fixed) {
    const sw = Math.min(fixed[0], w), sh = Math.min(fixed[1], h);
    // The fixed segment is centred on the pointer, kept inside the field.
    const x = Math.max(0, Math.min(w - sw, b[0] - Math.floor(sw / 2)));
    const y = Math.max(0, Math.min(h - sh, b[1] - Math.floor(sh / 2)));
    return [x, y, sw, sh];
  }
  const x0 = Math.min(a[0], b[0]), x1 = Math.max(a[0], b[0]);
  const y0 = Math.min(a[1], b[1]), y1 = Math.max(a[1], b[1]);
  return [x0, y0, x1 - x0 + 1, y1 - y0 + 1];
}

export function fitSegmentToField() {
  if (!state.segment || !state.whole || !state.whole.values) return;
  const [w, h] = fieldSize();
  let [x, y, sw, sh] = state.segment;
  sw = Math.min(sw, w); sh = Math.min(sh, h);
  x = Math.max(0, Math.min(w - sw, x)); y = Math.max(0, Math.min(h - sh, y));
  state.segment = [x, y, sw, sh];
}

let dragFrom = null;
export function wireCanvas() {
  const canvas = $("curd");
  canvas.addEventListener("pointerdown", (e) => {
    if (!state.whole || !state.whole.values) return;
    canvas.setPointerCapture(e.pointerId);
    if ($('zone-draw').checked) {
      zoneDrag(e, 'start');
      return;
    }  // a zone, not a segment
    dragFrom = cellAt(e);
    state.segment = segmentFrom(dragFrom, dragFrom);
    placeSelection();
  });
  canvas.addEventListener("pointermove", (e) => {
    if (!state.whole || !state.whole.values) return;
    const cell = cellAt(e);
    const v = decodeValueAt(cell);
    $("hover").textContent = `cell ${cell[0]}, ${cell[1]}: ${v === null ? "" : state.whole.legend[v].label}`;
    if (zoneFrom) {
      zoneDrag(e, 'move');
      return;
    }
    if (!dragFrom) return;
    state.segment = segmentFrom(dragFrom, cell);
    placeSelection();
  });
  const end = (e) => {
    if (zoneFrom) {
      zoneDrag(e, 'end');
      return;
    }
    if (!dragFrom) return;
    state.segment = segmentFrom(dragFrom, cellAt(e));
    dragFrom = null;
    placeSelection();
    refreshSegment();
  };
  canvas.addEventListener("pointerup", end);
  canvas.addEventListener("pointercancel", () => { dragFrom = null; });
}

// The value of cell i of the packed values (value_bits a cell, lowest bits first).
function valueAt(i) {
  const bits = state.whole.value_bits, bytes = state.whole.values;
  const at = i * bits;
  if (at >= bytes.length * 8) return null;
  if (bits === 16) return bytes[at >> 3] | bytes[(at >> 3) + 1] << 8;
  return bytes[at >> 3] >> (at & 7) & ((1 << bits) - 1);
}

function decodeValueAt([x, y]) {
  const [w] = fieldSize();
  return valueAt(y * w + x);
}
