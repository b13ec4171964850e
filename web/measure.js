// The page's measuring: a picture dropped or chosen is sent to /api/measure with the lattice on
// the page (base, stages, curds); its box counts are plotted beside the curd's, and the recipe
// fitted to it can be loaded as overrides or downloaded.
import { $, escapeHtml, getJson, showError, state, wireDrop } from "./page_state.js";
import { setFix } from "./canvas.js";
import { fmt } from "./report.js";
import { defaultCurdColours, fillValueColours, schedule, syncControls } from "./app.js";

export const measured = { result: null, url: null };

// log N against log s: a curd's boxes with a survivor at each stage's cell side.
function plotSeries() {
  const series = [];
  const fit = measured.result && measured.result.fit;
  if (fit && fit.recipe_is_chain) {
    // Each state's boxes at each stage beside the fitted chain's expectation.
    const b = fit.lattice.base, K = fit.lattice.stages, chain = fit.chain;
    const colours = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"];
    chain.states.forEach((name, i) => series.push({
      label: `picture · ${name}`, colour: chain.colours[i] || colours[i % colours.length], filled: true,
      points: chain.levels.map((l) => [Math.pow(b, K - l.level), l.boxes[i + 1]]),
      line: chain.levels.map((l) => [Math.pow(b, K - l.level), l.expected_boxes[i + 1]]),
    }));
  } else if (fit) {
    const b = fit.lattice.base, K = fit.lattice.stages;
    fit.curds.forEach((c) => series.push({
      label: `picture · ${c.name}`, colour: "#d62728", filled: true,
      points: c.stages.map((s) => [Math.pow(b, K - s.stage), s.measured]),
      line: c.stages.map((s) => [Math.pow(b, K - s.stage), s.expected]),
    }));
  }
  if (state.whole) {
    const b = state.base, K = state.stages;
    state.whole.report.curds.forEach((c, i) => series.push({
      label: `curd · ${c.name}`, colour: state.curds[i] ? state.curds[i].colour : "#c0392b", filled: false,
      points: c.stages.map((s) => [Math.pow(b, K - s.stage), s.box_count]),
    }));
  }
  return series;
}

export function drawMeasurePlot() {
  const canvas = $("measure-plot");
  const series = plotSeries();
  canvas.hidden = !measured.result;
  if (!measured.result) return;
  const ratio = window.devicePixelRatio || 1;
  const W = canvas.clientWidth || 360, H = canvas.clientHeight || 240;
  canvas.width = Math.round(W * ratio);
  canvas.height = Math.round(H * ratio);
  const g = canvas.getContext("2d");
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  g.fillStyle = "#fff";
  g.fillRect(0, 0, W, H);
  const all = series.flatMap((s) => s.points.concat(s.line || [])).filter(([x, y]) => x > 0 && y > 0);
  if (!all.length) return;
  const lx = all.map(([x]) => Math.log10(x)), ly = all.map(([, y]) => Math.log10(y));
  const x0 = Math.floor(Math.min(...lx)), x1 = Math.max(x0 + 1, Math.ceil(Math.max(...lx)));
  const y0 = Math.floor(Math.min(...ly)), y1 = Math.max(y0 + 1, Math.ceil(Math.max(...ly)));
  const left = 44, right = 18, top = 8, bottom = 34;
  const px = (x) => left + (Math.log10(x) - x0) / (x1 - x0) * (W - left - right);
  const py = (y) => H - bottom - (Math.log10(y) - y0) / (y1 - y0) * (H - top - bottom);
  g.strokeStyle = "#ddd";
  g.fillStyle = "#555";
  g.font = "11px sans-serif";
  g.lineWidth = 1;
  for (let e = x0; e <= x1; ++e) {
    const x = px(Math.pow(10, e));
    g.beginPath(); g.moveTo(x, top); g.lineTo(x, H - bottom); g.stroke();
    g.textAlign = "center";
    g.fillText(String(Math.pow(10, e)), x, H - bottom + 13);
  }
  for (let e = y0; e <= y1; ++e) {
    const y = py(Math.pow(10, e));
    g.beginPath(); g.moveTo(left, y); g.lineTo(W - right, y); g.stroke();
    g.textAlign = "right";
    g.fillText(e <= 4 ? String(Math.pow(10, e)) : `1e${e}`, left - 4, y + 4);
  }
  g.textAlign = "center";
  g.fillText("box side, cells (a cell a pixel)", left + (W - left - right) / 2, H - 4);
  g.textAlign = "left";
  g.fillText("boxes", left + 4, top + 10);
  // The key, top right: one row a series.
  g.textAlign = "left";
  series.forEach((s, i) => {
    const y = top + 10 + 14 * i, x = W - right - 150;
    g.fillStyle = s.colour;
    g.strokeStyle = s.colour;
    if (s.filled) { g.beginPath(); g.arc(x + 4, y - 4, 3.5, 0, 2 * Math.PI); g.fill(); } else g.strokeRect(x, y - 8, 7, 7);
    g.fillStyle = "#333";
    g.fillText(s.label, x + 12, y);
  });
  for (const s of series) {
    if (s.line) {
      g.strokeStyle = "#888";
      g.setLineDash([4, 3]);
      g.beginPath();
      s.line.filter(([x, y]) => x > 0 && y > 0).forEach(([x, y], i) => (i ? g.lineTo(px(x), py(y)) : g.moveTo(px(x), py(y))));
      g.stroke();
      g.setLineDash([]);
    }
    g.strokeStyle = s.colour;
    g.fillStyle = s.colour;
    for (const [x, y] of s.points) {
      if (!(x > 0 && y > 0)) continue;
      g.beginPath();
      if (s.filled) { g.arc(px(x), py(y), 3.5, 0, 2 * Math.PI); g.fill(); } else { g.lineWidth = 1.5; g.strokeRect(px(x) - 3.5, py(y) - 3.5, 7, 7); }
    }
  }
}

function renderMeasure() {
  const r = measured.result;
  $("measure-result").hidden = !r;
  if (!r) return;
  const m = r.measure, fit = r.fit;
  let html = "<tr><th>Value</th><th>share</th><th>lacunarity</th><th>D</th><th>R²</th></tr>";
  for (const v of m.values) {
    const d = v.box_dimension;
    html += `<tr><td><span class="chip" style="background:${v.colour}"></span>${v.value}${v.ground ? " (ground)" : ""}</td>` +
      `<td>${fmt(v.share, 3)}</td><td>${fmt(v.lacunarity, 3)}</td><td>${d ? fmt(d.fit, 3) : "–"}</td><td>${d ? fmt(d.r2, 3) : "–"}</td></tr>`;
  }
  $("measure-values").innerHTML = html;
  const chain = fit.chain;
  $("measure-readings").textContent = chain && chain.readings.length > 1
    ? "Which reading the picture supports (BIC, lower is better): " +
      chain.readings.map((g) => `${g.what}: ${fmt(g.bic, 1)}${g.name === chain.supported ? " (supported)" : ""}`).join("; ") +
      `; by ${fmt(chain.margin, 1)}.`
    : "";
  $("measure-recipe").hidden = !fit.recipe_is_chain;
  $("measure-recipe").textContent = fit.recipe_is_chain ? fit.recipe_toml : "";
  // The page's controls edit plain curds: a chain's recipe is downloaded and served, not loaded.
  $("measure-load").hidden = fit.recipe_is_chain;
  if (fit.recipe_is_chain) {
    renderChainFit(m, fit);
    return;
  }
  $("measure-caption").textContent =
    `${m.source}: ${m.size[0]} × ${m.size[1]} pixels, boxes of side ${m.base}^j; fitted as base ${fit.lattice.base}, ` +
    `${fit.lattice.stages} stages, ${fit.curds.length} curd${fit.curds.length > 1 ? "s" : ""} (the picture's boxes: dots, ` +
    "their expectation with the fitted probabilities: dashed; the curd on the page: squares)";
  let fits = "<tr><th>Curd</th><th>k</th><th>measured</th><th>expected</th><th>p</th><th>95 % of p</th></tr>";
  for (const c of fit.curds)
    for (const s of c.stages)
      fits += `<tr><td>${escapeHtml(c.name)}</td><td>${s.stage}</td><td>${s.measured}</td><td>${fmt(s.expected, 1)}</td>` +
        `<td>${fmt(s.probability, 4)}</td><td>${fmt(s.low, 3)} to ${fmt(s.high, 3)}</td></tr>`;
  $("measure-fit").innerHTML = fits;
  offerRecipe(fit);
}

// A Markov curd fitted to the picture's tones: each entry with its 95 % interval.
function renderChainFit(m, fit) {
  const chain = fit.chain, names = ["dead"].concat(chain.states);
  $("measure-caption").textContent =
    `${m.source}: ${m.size[0]} × ${m.size[1]} pixels, read as one Markov curd of ${chain.states.length} states ` +
    `(${chain.stage_wise ? "a matrix per stage" : "one matrix"}), base ${fit.lattice.base}, ${fit.lattice.stages} stages ` +
    "(each state's boxes: dots, the fitted chain's expectation: dashed)";
  const cell = (e) => e.fixed ? `${fmt(e.value, 4)}` : `${fmt(e.value, 4)} <small>(${fmt(e.low, 3)}–${fmt(e.high, 3)})</small>`;
  let rows = "<tr><th>from \\ to</th>" + names.map((n) => `<th>${escapeHtml(n)}</th>`).join("") + "</tr>";
  rows += "<tr><td>start</td>" + chain.start.map((e) => `<td>${cell(e)}</td>`).join("") + "</tr>";
  chain.transitions.forEach((matrix, k) => {
    if (chain.transitions.length > 1) rows += `<tr><th colspan="${names.length + 1}">stage ${k + 1}</th></tr>`;
    matrix.forEach((row, i) => {
      rows += `<tr><td>${escapeHtml(names[i])}</td>` + row.map((e) => `<td>${cell(e)}</td>`).join("") + "</tr>";
    });
  });
  $("measure-fit").innerHTML = rows;
  offerRecipe(fit);
}

function offerRecipe(fit) {
  if (measured.url) URL.revokeObjectURL(measured.url);
  measured.url = URL.createObjectURL(new Blob([fit.recipe_toml], { type: "application/toml" }));
  const link = $("measure-download");
  link.href = measured.url;
  link.download = `${fit.name}.toml`;
  drawMeasurePlot();
}

async function measurePicture(file) {
  if (!file) return;
  const limit = state.recipe.max_upload_bytes;
  if (file.size > limit) {
    showError(`${file.name} is ${(file.size / 1048576).toFixed(1)} MiB; the server takes pictures up to ${(limit / 1048576).toFixed(0)} MiB`);
    return;
  }
  const states = Math.max(0, Math.min(15, Number($("measure-states").value) || 0));
  const p = new URLSearchParams({ name: file.name, base: state.base, stages: state.stages, curds: state.curds.length, states });
  $("measure-status").textContent = `measuring ${file.name}…`;
  try {
    measured.result = await getJson("/api/measure?" + p.toString(), undefined,
      { method: "POST", body: file, headers: { "Content-Type": file.type || "application/octet-stream" } });
    showError("");
    $("measure-status").textContent = "";
    renderMeasure();
  } catch (err) {
    showError(err.message);
    $("measure-status").textContent = "";
  }
}

// The fitted recipe as overrides of the served one: its lattice, field and curds.
function loadFittedRecipe() {
  const fit = measured.result && measured.result.fit;
  if (!fit) return;
  state.base = fit.lattice.base;
  state.dimension = fit.lattice.dimension;
  state.stages = fit.lattice.stages;
  state.mode = fit.lattice.mode;
  state.field = [fit.field[0], fit.field[1], 1];
  state.fieldTouched = true;
  state.curds = fit.curds.map((c, i) => ({
                                name: c.name,
                                colour: c.colour || defaultCurdColours[i % 4],
                                probabilities: c.probabilities.slice()
                              }));
  state.segment = null;
  setFix("free");
  syncControls();
  fillValueColours().catch((err) => showError(err.message)).then(schedule);
}

export function wireMeasure() {
  wireDrop("measure-drop", "measure-file", measurePicture);
  $("measure-load").addEventListener("click", loadFittedRecipe);
  // A picture dropped beside the zone would replace the page: ignored instead.
  window.addEventListener("dragover", (e) => e.preventDefault());
  window.addEventListener("drop", (e) => e.preventDefault());
}
