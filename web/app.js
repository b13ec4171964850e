// The curdle page: edits a recipe as overrides (the same --set the command line takes), draws
// the curd from /api/field, selects segments snapped to cells, shows the segment's report
// beside the whole field's, and links the downloads /api/export makes. The page's files are ES
// modules, each importing what it uses. The parts call back into this one (a zone added
// schedules a new field): those imports run in a cycle, safe because no module calls
// another's functions while it loads.
import { $, escapeHtml, getJson, showError, state } from "./page_state.js";
import { fetchField } from "./field_fetch.js";
import { draw, fieldSize, fitSegmentToField, fixedCells, fixMode, placeSelection, recolour, setFix, wireCanvas } from "./canvas.js";
import { recipeZones, wireZones, zonesOverride } from "./surface.js";
import { dropSlowLoads, fmt, renderExports, renderReport } from "./report.js";
import { drawMeasurePlot, wireMeasure } from "./measure.js";
import { wireSite } from "./site.js";

// ---- overrides: what differs from the recipe, as KEY=VALUE in TOML ----

// A new curd's colour, by its place.
export const defaultCurdColours = ['#3b3b3b', '#c0392b', '#2471a3', '#229954'];

export const tomlString = (s) => JSON.stringify(String(s));
export const tomlArray = (items) => "[" + items.join(",") + "]";

function overrides() {
  const r = state.recipe;
  const sets = [];
  if (state.base !== r.lattice.base) sets.push(`lattice.base=${state.base}`);
  if (state.dimension !== r.lattice.dimension) sets.push(`lattice.dimension=${state.dimension}`);
  if (state.mode !== r.lattice.mode) sets.push(`lattice.mode=${tomlString(state.mode)}`);
  const reshaped = state.curds.length !== r.curds.length || state.stages !== r.lattice.stages ||
    state.curds.some((c, i) => c.name !== r.curds[i].name);
  if (reshaped) {
    if (state.stages !== r.lattice.stages && /\bstages\s*=/.test(r.recipe_toml))
      sets.push(`lattice.stages=${state.stages}`);
    const curds = state.curds.map((c) =>
      `{name=${tomlString(c.name)},colour=${tomlString(c.colour)},probabilities=` +
      tomlArray(c.probabilities.map(tomlString)) + "}");
    sets.push(`curds=${tomlArray(curds)}`);
  } else {
    state.curds.forEach((c, i) => {
      const was = r.curds[i];
      if (c.markov) return;  // its matrices live in the recipe
      if (c.probabilities.join() !== was.probabilities.join())
        sets.push(`curds.${i}.probabilities=${tomlArray(c.probabilities.map(tomlString))}`);
      if (c.colour !== was.colour) sets.push(`curds.${i}.colour=${tomlString(c.colour)}`);
    });
  }
  const fieldNow = state.field.slice(0, state.dimension);
  const fieldWas = r.field.slice(0, state.dimension);
  if (state.dimension !== r.lattice.dimension || fieldNow.join() !== fieldWas.join()) {
    if (state.dimension === r.lattice.dimension || state.fieldTouched)
      sets.push(`field.cells=${tomlArray(fieldNow)}`);
  }
  if (state.valueColours.length && state.valueColours.join() !== originalValueColours().join())
    sets.push(`layout.colours=${tomlArray(state.valueColours.map(tomlString))}`);
  for (const s of state.siteSets || []) sets.push(s);  // a site read from a drawing (site.js)
  const zones = zonesOverride();
  if (zones) sets.push(zones);
  return sets;
}

function originalValueColours() {
  return state.recipe.layout && state.recipe.layout.has_value_colours
    ? state.recipe.legend.map((e) => e.colour) : [];
}

export function query(extra) {
  const p = new URLSearchParams();
  for (const s of overrides()) p.append("set", s);
  p.append("seed", String(state.seed));
  for (const [k, v] of Object.entries(extra || {})) {
    if (Array.isArray(v)) v.forEach((x) => p.append(k, x)); else if (v !== undefined && v !== null) p.append(k, v);
  }
  return p.toString();
}

export function windowText() {
  if (!state.segment) return null;
  const [x, y, w, h] = state.segment;
  return state.dimension === 1 ? `${x},${w}` : `${x},${y},${w},${h}`;
}

// ---- requests ----

let generation = 0;



// One field at a time: a change while one is on its way asks for another once it is drawn,
// with the controls as they are then. A discrete change goes at once; a slider's stream of
// changes makes as many requests as the server can answer, never a queue of stale ones.
let fieldBusy = false, fieldAgain = false;
function fieldDone() {
  fieldBusy = false;
  if (fieldAgain) {
    fieldAgain = false;
    regenerate();
  }
}

// From each change to its pixels drawn, as performance measures "curd-redraw" (the benchmark
// tests/benchmarks/page_redraw.mjs reads them).
export async function regenerate() {
  dropSlowLoads();
  if (fieldBusy) { fieldAgain = true; return; }
  fieldBusy = true;
  const mine = ++generation;
  const started = performance.now();
  // Said only when it takes a while: the text would flicker on every fast change, and each
  // change of it lays out the page while the field is on its way.
  const slow = setTimeout(() => { if (mine === generation) $("status").textContent = "generating…"; }, 150);
  let whole;
  try {
    whole = await fetchField("/api/field?" + query());
    clearTimeout(slow);
    performance.measure("curd-fetch", { start: started, end: performance.now() });
    state.whole = whole;
    showError("");
    fitSegmentToField();
    draw();
    performance.measure("curd-redraw", { start: started, end: performance.now(),
                                         detail: { cells: whole.report.cells } });
  } catch (err) {
    clearTimeout(slow);
    if (err.name !== "AbortError") {
      showError(err.message);
      $("status").textContent = "";
    }
    fieldDone();
    return;
  }
  fieldDone();
  try {
    await refreshSegment();
    if (mine !== generation) return;
    const total = performance.now() - started;
    $("status").textContent =
      `${whole.report.cells.toLocaleString()} cells · server ${whole.server_ms.toFixed(1)} ms · page ${total.toFixed(0)} ms`;
  } catch (err) {
    if (err.name !== "AbortError") showError(err.message);
  }
}

let segmentController = null;
export async function refreshSegment() {
  if (segmentController) segmentController.abort();
  segmentController = new AbortController();
  state.segmentReport = null;
  if (state.segment) {
    try {
      state.segmentReport = await getJson("/api/generate?" + query({ cells: "0", window: windowText() }),
                                          segmentController.signal);
      showError("");
    } catch (err) {
      if (err.name === "AbortError") return;
      showError(err.message);
    }
  }
  renderReport();
  renderExports();
  drawMeasurePlot();
}

// ---- controls ----

function readRecipeIntoState(r) {
  state.seed = r.seed;
  state.base = r.lattice.base;
  state.dimension = r.lattice.dimension;
  state.stages = r.lattice.stages;
  state.mode = r.lattice.mode;
  state.field = r.field.slice();
  while (state.field.length < 3) state.field.push(1);
  state.fieldTouched = false;
  state.curds = r.curds.map((c) => ({ name: c.name, colour: c.colour, probabilities: c.probabilities.slice(),
    markov: Boolean(c.markov), states: c.states || [] }));
  state.valueColours = originalValueColours();
  state.zones = JSON.parse(JSON.stringify(recipeZones()));
  state.segment = r.default_window && r.lattice.dimension === 2 ? r.default_window.slice() : null;
  const floor = r.layout && r.layout.segment_cells;
  $("fix-floor-label").hidden = !floor;
  // A building's floor is its envelope unrolled: the strip.
  const building = Boolean(r.layout && r.layout.building);
  $("fix-floor-label").lastChild.textContent = building ? " the strip" : " the floor";
  // Its plan is read by [layout.building.site] in the recipe, not laid as a floor's site.
  $("site-box").hidden = building;
  setFix(floor ? "floor" : "free");
}

export function syncControls() {
  $("seed").value = String(state.seed);
  $("base").value = state.base;
  $("dimension").value = String(state.dimension);
  $("stages").value = state.stages;
  $("mode").value = state.mode;
  $("field-w").value = state.field[0];
  $("field-h").value = state.field[1];
  $("field-h").disabled = state.dimension === 1;
  $("curd-count").value = state.curds.length;
  // A Markov curd's table is the recipe's: the page does not rebuild the list of curds around it.
  const markov = state.curds.some((c) => c.markov);
  $("curd-count").disabled = markov;
  $("stages").disabled = markov;
  renderCurdControls();
  renderPalette();
}

function parseProbability(text) {
  const t = text.trim();
  const m = /^(\d+)\s*\/\s*(\d+)$/.exec(t);
  const v = m ? Number(m[1]) / Number(m[2]) : Number(t);
  return t !== "" && Number.isFinite(v) && v >= 0 && v <= 1 ? v : null;
}

function renderCurdControls() {
  const box = $("curds");
  box.textContent = "";
  state.curds.forEach((curd, c) => {
    const div = document.createElement("div");
    div.className = "curd";
    const head = document.createElement("div");
    head.className = "curd-head";
    const colour = document.createElement("input");
    colour.type = "color";
    colour.value = curd.colour;
    colour.title = "Curd colour";
    colour.setAttribute("aria-label", `Colour of curd ${c}`);
    colour.addEventListener("input", () => { curd.colour = colour.value; schedule(); });
    const name = document.createElement("input");
    name.type = "text";
    name.value = curd.name;
    name.setAttribute("aria-label", `Name of curd ${c}`);
    name.addEventListener("change", () => { curd.name = name.value.trim() || `curd${c}`; schedule(); });
    head.append(colour, name);
    div.append(head);
    if (curd.markov) {
      colour.disabled = true;
      name.disabled = true;
      const note = document.createElement("div");
      note.className = "note";
      note.textContent = "Markov curd: states " + curd.states.map((s) => s.name).join(", ") +
        " (and dead); its transition matrices are edited in the recipe.";
      for (const s of curd.states.slice().reverse()) {  // prepended: the first state first
        const swatch = document.createElement("span");
        swatch.className = "state-swatch";
        swatch.style.background = s.colour;
        swatch.title = s.name;
        note.prepend(swatch);
      }
      div.append(note);
    }
    curd.probabilities.forEach((p, k) => {
      const row = document.createElement("div");
      row.className = "stage";
      const label = document.createElement("span");
      label.textContent = `p${k + 1}`;
      const slider = document.createElement("input");
      slider.type = "range";
      slider.min = "0"; slider.max = "1"; slider.step = "0.001";
      slider.value = String(parseProbability(p) ?? 0.5);
      slider.setAttribute("aria-label", `Curd ${c} stage ${k + 1} probability slider`);
      slider.dataset.curd = c; slider.dataset.stage = k;
      const text = document.createElement("input");
      text.type = "text";
      text.value = p;
      text.setAttribute("aria-label", `Curd ${c} stage ${k + 1} probability`);
      text.dataset.curd = c; text.dataset.stage = k;
      slider.addEventListener("input", () => {
        curd.probabilities[k] = String(Number(slider.value));
        text.value = curd.probabilities[k];
        schedule();
      });
      text.addEventListener("change", () => {
        const v = parseProbability(text.value);
        if (v === null) {
          showError(`Curd ${curd.name}, stage ${k + 1}: '${text.value}' is not a probability; write a fraction such as 2/3 or a decimal from 0 to 1`);
          text.value = curd.probabilities[k];
          return;
        }
        curd.probabilities[k] = text.value.trim();
        slider.value = String(v);
        schedule();
      });
      row.append(label, slider, text);
      div.append(row);
    });
    box.append(div);
  });
}

function renderPalette() {
  const box = $("palette");
  box.textContent = "";
  const legend = (state.whole || state.recipe).legend;
  if (!state.valueColours.length) {
    const note = document.createElement("div");
    note.className = "note";
    note.textContent = "Values take the blend of their curds' colours; set the curd colours above.";
    box.append(note);
    return;
  }
  state.valueColours.forEach((colour, v) => {
    const row = document.createElement("label");
    row.className = "swatch-row";
    const input = document.createElement("input");
    input.type = "color";
    input.value = colour;
    input.addEventListener("input", () => {
      state.valueColours[v] = input.value;
      // Redrawn at once from the cells the page holds; the server's answer (legend, downloads)
      // follows when the picker rests.
      if (state.whole && state.whole.legend[v]) { state.whole.legend[v].colour = input.value; recolour(); }
      scheduleSoon();
    });
    row.append(input, document.createTextNode(legend[v] ? legend[v].label : `value ${v}`));
    box.append(row);
  });
}

function resizeCurds() {
  const count = Math.max(1, Math.min(4, Number($("curd-count").value) || 1));
  const stages = Math.max(1, Math.min(16, Number($("stages").value) || 1));
  state.stages = stages;
  while (state.curds.length < count) {
    const i = state.curds.length;
    state.curds.push({
      name: `curd${i}`,
      colour: defaultCurdColours[i % 4],
      probabilities: Array(stages).fill('1/2')
    });
  }
  state.curds.length = count;
  for (const c of state.curds) {
    while (c.probabilities.length < stages) c.probabilities.push(c.probabilities[c.probabilities.length - 1] || "1/2");
    c.probabilities.length = stages;
  }
  renderCurdControls();
  renderPalette();
}

// A recipe with a colour per value needs one for every value: new values take the blend of
// their curds' colours as the library makes it (/api/colours), so that the page and the
// previews agree to the last bit.
export async function fillValueColours() {
  const count = state.curds.length;
  if (!state.valueColours.length || state.valueColours.length === 1 << count) return;
  const p = new URLSearchParams();
  for (const c of state.curds) p.append("colour", c.colour);
  const response = await fetch("/api/colours?" + p.toString());
  const body = await response.json();
  if (!response.ok) throw new Error(body.error || `HTTP ${response.status}`);
  const old = state.valueColours;
  state.valueColours = body.values.map((blended, v) => (v < old.length ? old[v] : blended));
  renderPalette();
}

// A control's change regenerates at once (or as soon as the field on its way is drawn); a
// colour being dragged waits until the picker rests.
export function schedule() {
  clearTimeout(timer);
  regenerate();
}
let timer = null;
function scheduleSoon() {
  clearTimeout(timer);
  timer = setTimeout(regenerate, 150);
}

// ---- search ----

async function runSearch(event) {
  event.preventDefault();
  const targets = $("search-targets").value.split("\n").map((t) => t.trim()).filter(Boolean);
  const fixed = fixedCells();
  const size = fixed || (state.segment ? state.segment.slice(2) : null);
  const extra = { seeds: $("search-seeds").value.trim(), top: $("search-top").value, target: targets };
  if (size) extra.segment = state.dimension === 1 ? `${size[0]}` : `${size[0]},${size[1]}`;
  const params = new URLSearchParams(query(extra));
  params.delete("seed");
  $("search-run").disabled = true;
  $("search-results").innerHTML = "<tr><td>searching…</td></tr>";
  try {
    const result = await getJson("/api/search?" + params.toString());
    showError("");
    let html = "<tr><th>#</th><th>seed</th><th>segment</th><th>score</th>" +
      result.targets.map((t) => `<th title="${escapeHtml(t)}">${escapeHtml(t.split(/[<>=]/)[0])}</th>`).join("") + "</tr>";
    for (const hit of result.hits) {
      html += `<tr class="hit" data-seed="${hit.seed}" data-window="${hit.window}"><td>${hit.rank}</td><td>${hit.seed}</td>` +
        `<td>${hit.window}</td><td>${fmt(hit.score)}</td>` +
        Object.values(hit.measured).map((x) => `<td>${fmt(x, 3)}</td>`).join("") + "</tr>";
    }
    $("search-results").innerHTML = html;
    // Seeds come as strings: JavaScript numbers lose whole numbers above 2^53.
    const searched = BigInt(result.seeds[1]) - BigInt(result.seeds[0]) + 1n;
    $("status").textContent = `searched ${searched} seeds in ${result.server_ms.toFixed(0)} ms`;
  } catch (err) {
    showError(err.message);
    $("search-results").innerHTML = "";
  } finally {
    $("search-run").disabled = false;
  }
}

function pickHit(event) {
  const row = event.target.closest("tr.hit");
  if (!row) return;
  state.seed = row.dataset.seed;
  const w = row.dataset.window.split(",").map(Number);
  state.segment = state.dimension === 1 ? [w[0], 0, w[1], 1] : w;
  $("seed").value = state.seed;
  regenerate();
}

// ---- start ----

function wireControls() {
  $("seed").addEventListener("change", () => {
    const t = $("seed").value.trim();
    if (!/^\d+$/.test(t)) { showError(`'${t}' is not a seed; a seed is a whole number from 0 to 18446744073709551615`); return; }
    state.seed = t;
    schedule();
  });
  const step = (d) => {
    const next = BigInt(state.seed) + BigInt(d);
    if (next < 0n) return;
    state.seed = next.toString();
    $("seed").value = state.seed;
    schedule();
  };
  $("seed-prev").addEventListener("click", () => step(-1));
  $("seed-next").addEventListener("click", () => step(1));
  $("reroll").addEventListener("click", () => {
    const words = crypto.getRandomValues(new Uint32Array(2));
    state.seed = (BigInt(words[0]) << 32n | BigInt(words[1])).toString();
    $("seed").value = state.seed;
    schedule();
  });
  $("base").addEventListener("change", () => { state.base = Number($("base").value); schedule(); });
  $("dimension").addEventListener("change", () => {
    state.dimension = Number($("dimension").value);
    state.fieldTouched = true;
    state.segment = null;
    $("field-h").disabled = state.dimension === 1;
    schedule();
  });
  $("mode").addEventListener("change", () => { state.mode = $("mode").value; schedule(); });
  $("stages").addEventListener("change", () => { resizeCurds(); schedule(); });
  $("curd-count").addEventListener("change", async () => {
    resizeCurds();
    try {
      await fillValueColours();
    } catch (err) {
      showError(err.message);
      return;
    }
    schedule();
  });
  for (const id of ["field-w", "field-h"])
    $(id).addEventListener("change", () => {
      state.field[0] = Number($("field-w").value);
      state.field[1] = Number($("field-h").value);
      state.fieldTouched = true;
      schedule();
    });
  document.querySelectorAll("input[name=fix]").forEach((r) => r.addEventListener("change", () => {
    setFix(fixMode());
    applyFixedSize();
  }));
  for (const id of ["fix-w", "fix-h"]) $(id).addEventListener("change", applyFixedSize);
  $("window-text").addEventListener("change", typedWindow);
  $("clear-selection").addEventListener("click", () => {
    state.segment = null;
    setFix("free");
    placeSelection();
    $("segment-text").textContent = "";
    $("window-text").value = "";
    refreshSegment();
  });
  $("reset").addEventListener("click", () => { readRecipeIntoState(state.recipe); syncControls(); regenerate(); });
  $("copy-command").addEventListener("click", () => navigator.clipboard && navigator.clipboard.writeText($("command").textContent));
  $("search-form").addEventListener("submit", runSearch);
  $("search-results").addEventListener("click", pickHit);
  window.addEventListener("resize", () => state.whole && draw());
  wireCanvas();
  wireZones();
  wireMeasure();
  wireSite();
}

// A window typed as X,Y,W,H (X,W on a line): checked against the field here, so that the
// message names the field's size.
function typedWindow() {
  const text = $("window-text").value.trim();
  const numbers = text.split(",").map((t) => Number(t.trim()));
  const [w, h] = fieldSize();
  const oneD = state.dimension === 1;
  const box = oneD ? [numbers[0], 0, numbers[1], 1] : numbers;
  const whole = numbers.every((n) => Number.isInteger(n)) && numbers.length === (oneD ? 2 : 4);
  if (!whole || box[0] < 0 || box[1] < 0 || box[2] < 1 || box[3] < 1 || box[0] + box[2] > w || box[1] + box[3] > h) {
    // A segment still loading would clear the message when it arrives: it is stale now.
    if (segmentController) segmentController.abort();
    showError(`Window '${text}': write ${oneD ? "X,W" : "X,Y,W,H"} in whole cells, inside the field of ${w} × ${h} cells`);
    return;
  }
  showError("");
  state.segment = box;
  setFix("free");
  placeSelection();
  refreshSegment();
}

// A fixed size resizes the current selection in place (or places one at the origin).
export function applyFixedSize() {
  const fixed = fixedCells();
  if (!fixed || !state.whole) return;
  const [x, y] = state.segment || [0, 0];
  state.segment = [x, y, fixed[0], fixed[1]];
  fitSegmentToField();
  placeSelection();
  refreshSegment();
}

async function start() {
  wireControls();
  try {
    state.recipe = await getJson("/api/recipe");
  } catch (err) {
    showError(err.message);
    return;
  }
  $("recipe-name").textContent = state.recipe.name;
  $("recipe-description").textContent = state.recipe.description;
  document.title = `curdle · ${state.recipe.name}`;
  readRecipeIntoState(state.recipe);
  syncControls();
  await regenerate();
  document.body.dataset.ready = "1";
}

start();
