// The page: the values, box-dimension and per-stage tables, the reproducing command, the
// downloads and the layout drawing.
import { apiFetch, kLongestAddress } from "./api_request.js";
import { $, escapeHtml, showError, state } from "./page_state.js";
import { query, windowText } from "./app.js";

// ---- report ----

export const fmt = (x, digits = 4) => (x === null || x === undefined || Number.isNaN(x)) ? "–" : Number(x).toFixed(digits);

export function renderReport() {
  const whole = state.whole;
  if (!whole) return;
  const seg = state.segmentReport;
  const legend = whole.legend;
  const cells = whole.report.cells, segCells = seg ? seg.report.cells : 0;
  const head = ["Value", "Whole", "ratio", "expected"].concat(seg ? ["Segment", "ratio", "÷ exp."] : []);
  let html = "<tr>" + head.map((h, i) => `<th class="${i >= 4 ? "seg" : ""}">${h}</th>`).join("") + "</tr>";
  const markov = whole.report.markov_curds || [];
  whole.report.values.forEach((v, i) => {
    // A code a Markov curd's bits can hold but no state has: never there, not listed.
    if (markov.length && v.count === 0 && v.expected === 0 && i > 0) return;
    const expectedRatio = v.expected / cells;
    html += `<tr><td><span class="chip" style="background:${legend[i] ? legend[i].colour : "#fff"}"></span>${escapeHtml(v.label)}</td>` +
      `<td>${v.count}</td><td>${fmt(v.count / cells)}</td><td>${fmt(expectedRatio)}</td>`;
    if (seg) {
      const s = seg.report.values[i];
      const ratio = s.count / segCells;
      html += `<td class="seg">${s.count}</td><td class="seg">${fmt(ratio)}</td>` +
        `<td class="seg">${expectedRatio > 0 ? fmt(ratio / expectedRatio, 2) : "–"}</td>`;
    }
    html += "</tr>";
  });
  $("values-table").innerHTML = html;

  // The limit of many stages, what the fit should give at these stages, and the fits; a
  // segment's fit also with the boxes it cuts weighted by the share it shows.
  let dims =
      '<tr><th>Curd</th><th title="K → ∞">limit</th><th title="expected fit at these stages">at K</th><th>whole</th><th>R²</th>' +
      (seg ?
           '<th class="seg">segment</th><th class="seg" title="boxes the segment cuts weighted by the share it shows">cut boxes weighted</th><th class="seg" title="expected, weighted the same way">expected</th>' :
           '') +
      '</tr>';
  whole.report.curds.forEach((c, i) => {
    const s = seg ? seg.report.curds[i] : null;
    const w = s && s.box_dimension.share_weighted;
    dims += `<tr><td>${escapeHtml(c.name)}</td><td>${fmt(c.box_dimension.theory, 3)}</td><td>${
                fmt(c.box_dimension.expected_at_these_stages, 3)}</td><td>${
                fmt(c.box_dimension.fit, 3)}</td><td>${fmt(c.box_dimension.r2, 3)}</td>` +
        (s ? `<td class="seg">${fmt(s.box_dimension.fit, 3)}</td><td class="seg">${
                 w ? fmt(w.fit, 3) : '–'}</td><td class="seg">${
                 w ? fmt(w.expected_at_these_stages, 3) : '–'}</td>` :
             '') +
        '</tr>';
  });
  // A Markov curd: each state's set and the living set, beside their theory (no segment
  // columns: the segment's sets are in its report.json).
  markov.forEach((m) => {
    m.sets.forEach((set) => {
      const fit = set.box_dimension, expected = set.expected_box_dimension;
      dims += `<tr><td>${escapeHtml(m.name + ": " + set.name)}</td><td>${fmt(set.theory_dimension, 3)}</td><td>${
                  fmt(expected && expected.slope, 3)}</td><td>${fmt(fit && fit.slope, 3)}</td><td>${
                  fmt(fit && fit.r2, 3)}</td>` + (seg ? '<td class="seg" colspan="3"></td>' : '') + '</tr>';
    });
  });
  $("dimension-table").innerHTML = dims;

  const stages = $("stages-tables");
  stages.textContent = "";
  whole.report.curds.forEach((c, i) => {
    const t = document.createElement("table");
    const s = seg ? seg.report.curds[i] : null;
    let rows = `<caption>${escapeHtml(c.name)}</caption><tr><th title="stage">k</th><th>p</th><th>N</th>` +
      `<th title="expected survivors ± standard deviation">expected</th><th title="boxes with a survivor">boxes</th>` +
      `<th title="local box dimension">D</th>` +
      (s ? '<th class="seg" title="survivors in the segment">seg. N</th><th class="seg" title="expected in the segment">expected</th>' : "") + "</tr>";
    c.stages.forEach((k, j) => {
      rows += `<tr><td>${k.stage}</td><td>${escapeHtml(k.probability_text)}</td><td>${k.survivors}</td>` +
        `<td>${fmt(k.expected, 1)} ± ${fmt(k.expected_sd, 1)}</td><td>${k.box_count}</td><td>${fmt(k.local_dimension, 3)}</td>` +
        (s ? `<td class="seg">${s.stages[j].survivors}</td><td class="seg">${fmt(s.stages[j].expected, 1)}</td>` : "") + "</tr>";
    });
    t.innerHTML = rows;
    stages.append(t);
  });
  // A Markov curd's stages: each state's count beside its expectation and z.
  markov.forEach((m) => {
    const t = document.createElement("table");
    let rows = `<caption>${escapeHtml(m.name)} (Markov)</caption><tr><th title="stage">k</th><th>state</th>` +
      `<th title="expected share">share</th><th>N</th><th title="expected ± standard deviation">expected</th><th>z</th></tr>`;
    m.stages.forEach((k) => {
      if (k.stage === 0) return;
      rows += `<tr><td>${k.stage}</td><td>${escapeHtml(k.state)}</td><td>${fmt(k.expected_share, 4)}</td><td>${k.count}</td>` +
        `<td>${fmt(k.expected, 1)} ± ${fmt(k.expected_sd, 1)}</td><td>${fmt(k.z, 2)}</td></tr>`;
    });
    t.innerHTML = rows;
    stages.append(t);
  });
  const shown = seg || whole;
  $("command").textContent = shown.command;
}


export function renderExports() {
  const box = $("exports");
  box.textContent = "";
  const hasLayout = !!(state.whole && state.whole.layout);
  const win = windowText();
  const own = state.whole && state.whole.default_window;
  $("export-what").textContent = win ? `segment ${win}`
    : own ? `the recipe's segment ${own.join(",")}` : "whole field";
  // The server lists what this recipe can download (its registry of outputs).
  for (const name of (state.whole || state.recipe).downloads) {
    const a = document.createElement("a");
    a.href = "/api/export?" + query({ file: name, window: win || undefined });
    a.download = name;
    a.addEventListener("click", downloadByPost);
    a.textContent = name;
    const about = ((state.whole || state.recipe).download_descriptions || {})[name];
    if (about) a.title = about;
    box.append(a);
  }
  // The recipe text and the drawn layout cost more than a regenerate: they wait until the
  // controls rest, so that a moving slider never queues them ahead of the curd.
  clearTimeout(slowTimer);
  slowTimer = setTimeout(() => {
    updateRecipeText();
    updateLayoutPreview(hasLayout, win);
  }, 300);
}
let slowTimer = null;

// A download whose address is too long to follow (a long outline in the query) is asked for by
// POST and saved from the answer.
async function downloadByPost(event) {
  const link = event.currentTarget;
  if (link.href.length <= kLongestAddress) return;
  event.preventDefault();
  try {
    const response = await apiFetch(link.href);
    if (!response.ok) throw new Error((await response.json()).error || `HTTP ${response.status}`);
    const url = URL.createObjectURL(await response.blob());
    const save = document.createElement("a");
    save.href = url;
    save.download = link.download;
    save.click();
    setTimeout(() => URL.revokeObjectURL(url), 60000);
  } catch (err) {
    showError(`${link.download}: ${err.message}`);
  }
}

let recipeController = null;
async function updateRecipeText() {
  if (recipeController) recipeController.abort();
  recipeController = new AbortController();
  try {
    const response = await apiFetch("/api/export?" + query({ file: "recipe.toml", window: windowText() || undefined }),
                                 { signal: recipeController.signal });
    if (response.ok) $("recipe-toml").textContent = await response.text();
  } catch (err) { /* a newer request took over */ }
}

function updateLayoutPreview(hasLayout, win) {
  const figure = $("layout-figure");
  const cells = state.segment ? state.segment[2] * state.segment[3] : (state.whole ? state.whole.report.cells : 0);
  if (!hasLayout || cells > 40000) { figure.hidden = true; $("view3d-figure").hidden = true; return; }
  figure.hidden = false;
  // The 3-D view (view3d.js) loads the same layout.glb as the download.
  $("view3d-figure").hidden = false;
  window.layout3dSrc = "/api/export?" + query({ file: "layout.glb", window: win || undefined });
  window.dispatchEvent(new Event("layout3d"));
  if (!window.view3d)
    $("view3d-caption").textContent = "The 3-D view needs three.js beside the page: run setup.sh and build again.";
  showPreview(win, "/api/export?" + query({ file: "layout.png", window: win || undefined, set: PREVIEW_DPI }));
}
// The preview's resolution: the pixels it is shown at. It is at most 420 px high (style.css),
// an A3 sheet's height at 36 dpi, times the screen's pixels a point (up to two). The server drew
// the download's 150 dpi in 100 ms and 36 dpi in 10 ms, and the page decodes a seventeenth of
// the pixels: work that on two cores shared the CPU with the next redraw (a 1024 x 1024 change
// 5 ms slower at the median with the preview at 150 dpi on its way, under 2 ms at 36 dpi).
const PREVIEW_DPI = `layout.dpi=${Math.round(36 * Math.min(2, Math.max(1, window.devicePixelRatio || 1)))}`;

// layout.png, fetched so that a change can drop it on its way (dropSlowLoads); until it
// arrives the old drawing stays, dimmed, and the caption says so. data-src is the drawing
// asked for, data-shown the one shown.
let previewController = null;
async function showPreview(win, src) {
  const img = $("layout-preview");
  const caption = () => `The layout of ${win ? "segment " + win : "the field"}, as layout.png (here at the screen's resolution)`;
  if (img.dataset.shown === src) {  // a change came back to it, or its load was dropped
    img.classList.remove("stale");
    $("layout-caption").textContent = caption();
    return;
  }
  if (previewController) previewController.abort();
  const controller = previewController = new AbortController();
  img.dataset.src = src;
  img.classList.add("stale");
  $("layout-caption").textContent = "Drawing the layout…";
  try {
    const response = await apiFetch(src, { signal: controller.signal });
    if (!response.ok) throw new Error(`the server answered ${response.status}`);
    const blob = await response.blob();
    if (controller !== previewController) return;
    const old = img.getAttribute("src");
    img.onload = () => {
      if (old && old.startsWith("blob:")) URL.revokeObjectURL(old);
      img.classList.remove("stale");
      $("layout-caption").textContent = caption();
      img.dataset.shown = src;
    };
    img.onerror = () => { $("layout-caption").textContent = "The layout could not be drawn."; };
    img.src = URL.createObjectURL(blob);
  } catch (err) {
    if (err.name !== "AbortError") $("layout-caption").textContent = "The layout could not be drawn.";
  }
}

// A change makes the layout's drawing, the recipe text and the 3-D view stale: what is on its
// way for them is dropped at once (the server stops a request whose client has gone), so that
// it does not hold the two cores while the curd is redrawn. They are asked for again when the
// controls rest (renderExports).
export function dropSlowLoads() {
  clearTimeout(slowTimer);
  if (recipeController) recipeController.abort();
  if (previewController) previewController.abort();
  window.dispatchEvent(new Event("layout3d-drop"));
}
