// The page's site from a drawing: a DXF or SVG dropped or chosen is sent to /api/site, its
// layers are listed and each given a role (the outline, openings, zones kept free, or none),
// and the surface read from them becomes the page's overrides (the outline with its arcs as
// bulges, a façade's windows) and zones, as [layout.site] reads it.
import { $, escapeHtml, getJson, showError, state, wireDrop } from "./page_state.js";
import { renderZoneList, surface } from "./surface.js";
import { applyFixedSize, query, regenerate } from "./app.js";

// regions: each layer's closed regions in drawing coordinates (the server's listing); around: the
// point clicked inside the outline where its layer holds several.
const siteDrawing = { file: null, layers: [], hidden: [], regions: [], around: null };

// A layer's role guessed from its name, as offices name them (the US National CAD Standard's
// and the AIA's -OTLN, -BNDY, -PITS, -DRAN, ...): a frozen or hidden layer never.
function siteRoleGuess(name, hidden) {
  if (hidden) return "none";
  if (/(^|[-_ ])(OTLN|BNDY)([-_ ]|$)|outline|boundary|wall|site/i.test(name)) return "outline";
  if (/glaz|window|door|opening|(^|[-_ ])(WIND|DOOR)([-_ ]|$)/i.test(name)) return "opening";
  if (/(^|[-_ ])(PITS?|DRAN|POND|PLAY|PLNT)([-_ ]|$)|pit|drain|zone|planter|pond|play/i.test(name)) return "zone";
  return "none";
}

function renderSiteLayers() {
  const guesses = siteDrawing.layers.map((l) => siteRoleGuess(l.name, siteDrawing.hidden.includes(l.name)));
  // One outline: the first layer guessed so, else the first layer that is not hidden.
  const outlines = guesses.map((g, i) => (g === "outline" ? i : -1)).filter((i) => i >= 0);
  guesses.forEach((g, i) => { if (g === "outline" && i !== outlines[0]) guesses[i] = "none"; });
  if (!outlines.length) {
    const first = siteDrawing.layers.findIndex((l) => !siteDrawing.hidden.includes(l.name));
    if (first >= 0 && guesses[first] === "none") guesses[first] = "outline";
  }
  const rows = siteDrawing.layers.map((l, i) => {
    const guess = guesses[i];
    const hidden = siteDrawing.hidden.includes(l.name) ? " (frozen or off in the drawing)" : "";
    const options = ["none", "outline", "opening", "zone"].map((r) =>
      `<option value="${r}"${r === guess ? " selected" : ""}>${
        { none: "not used", outline: "the outline", opening: "openings", zone: "zones kept free" }[r]}</option>`);
    return `<tr><td>${escapeHtml(l.name)}${hidden}</td><td>${l.shapes} shapes, ${l.closed} closed</td>` +
      `<td><select data-layer="${i}" aria-label="Role of layer ${escapeHtml(l.name)}">${options.join("")}</select></td></tr>`;
  });
  $("site-layers").innerHTML = rows.length
    ? "<tr><th>layer</th><th>holds</th><th>is</th></tr>" + rows.join("") : "";
  $("site-apply").hidden = !rows.length;
  document.querySelectorAll("#site-layers select").forEach((s) => s.addEventListener("change", renderSitePick));
  renderSitePick();
}

// The layer chosen as the outline, or null.
function siteOutlineLayer() {
  const chosen = [...document.querySelectorAll("#site-layers select")].filter((s) => s.value === "outline");
  return chosen.length === 1 ? siteDrawing.layers[Number(chosen[0].dataset.layer)].name : null;
}

function siteRingsOf(layer) {
  const entry = siteDrawing.regions.find((r) => r.layer === layer);
  return entry ? entry.rings : [];
}

function ringArea(ring) {
  let a = 0;
  ring.forEach((p, i) => { const q = ring[(i + 1) % ring.length]; a += p[0] * q[1] - q[0] * p[1]; });
  return Math.abs(a / 2);
}

function ringHolds(ring, [x, y]) {
  let inside = false;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const [xi, yi] = ring[i], [xj, yj] = ring[j];
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

// The canvas's frame: every region of the drawing, fitted with a margin, y up as drawn.
function sitePickFrame() {
  const canvas = $("site-pick");
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  siteDrawing.regions.forEach((r) => r.rings.forEach((ring) => ring.forEach(([x, y]) => {
    x0 = Math.min(x0, x), y0 = Math.min(y0, y), x1 = Math.max(x1, x), y1 = Math.max(y1, y);
  })));
  const margin = 12;
  const k = Math.min((canvas.width - 2 * margin) / Math.max(x1 - x0, 1e-9),
                     (canvas.height - 2 * margin) / Math.max(y1 - y0, 1e-9));
  return {
    toCanvas: ([x, y]) => [margin + (x - x0) * k, canvas.height - margin - (y - y0) * k],
    toDrawing: (cx, cy) => [x0 + (cx - margin) / k, y0 + (canvas.height - margin - cy) / k],
  };
}

// Where a drawing point lies on the pick canvas, in CSS pixels from its corner (for a click).
export function sitePickPosition(x, y) {
  const canvas = $("site-pick");
  const [cx, cy] = sitePickFrame().toCanvas([x, y]);
  const box = canvas.getBoundingClientRect();
  return { x: (cx * box.width) / canvas.width, y: (cy * box.height) / canvas.height };
}

// Where the outline's layer holds more than one region, the drawing's regions are drawn and the
// designer clicks inside the one meant, as CAD's BOUNDARY takes a pick point.
function renderSitePick() {
  const canvas = $("site-pick");
  const layer = siteOutlineLayer();
  const rings = layer ? siteRingsOf(layer) : [];
  const several = rings.length > 1;
  canvas.hidden = !several;
  $("site-pick-note").hidden = !several;
  if (!several) { siteDrawing.around = null; return; }
  const held = siteDrawing.around
    ? rings.filter((r) => ringHolds(r, siteDrawing.around)).sort((a, b) => ringArea(a) - ringArea(b))[0] : null;
  $("site-pick-note").textContent = held
    ? `outline: the region of ${layer} around the point clicked (${siteDrawing.around.map((v) => +v.toFixed(3)).join(", ")}); click another to change it`
    : `${layer} holds ${rings.length} closed regions: click inside the one that is the outline`;
  const frame = sitePickFrame();
  const g = canvas.getContext("2d");
  g.clearRect(0, 0, canvas.width, canvas.height);
  const trace = (ring) => {
    g.beginPath();
    ring.forEach((p, i) => { const [x, y] = frame.toCanvas(p); i ? g.lineTo(x, y) : g.moveTo(x, y); });
    g.closePath();
  };
  g.lineWidth = 1;
  g.strokeStyle = "#bbb";
  siteDrawing.regions.filter((r) => r.layer !== layer).forEach((r) => r.rings.forEach((ring) => { trace(ring); g.stroke(); }));
  g.strokeStyle = "#222";
  rings.forEach((ring) => { trace(ring); g.stroke(); });
  if (held) {
    trace(held);
    g.fillStyle = "rgba(40, 110, 200, 0.35)";
    g.fill();
    const [x, y] = frame.toCanvas(siteDrawing.around);
    g.fillStyle = "#c00";
    g.fillRect(x - 3, y - 3, 6, 6);
  }
}

function pickSiteRegion(event) {
  const canvas = $("site-pick");
  const box = canvas.getBoundingClientRect();
  const cx = ((event.clientX - box.left) * canvas.width) / box.width;
  const cy = ((event.clientY - box.top) * canvas.height) / box.height;
  siteDrawing.around = sitePickFrame().toDrawing(cx, cy);
  showError("");
  renderSitePick();
}


// The drawing sent with the page's run and `extra` parameters; the server's answer.
async function postSite(extra) {
  const file = siteDrawing.file;
  return getJson(`/api/site?${query({ name: file.name, ...extra })}`, undefined,
    { method: "POST", body: file, headers: { "Content-Type": "application/octet-stream" } });
}

async function readSite(file) {
  if (!file) return;
  const limit = state.recipe.max_upload_bytes;
  if (file.size > limit) {
    showError(`${file.name} is ${(file.size / 1048576).toFixed(1)} MiB; the server takes drawings up to ${(limit / 1048576).toFixed(0)} MiB`);
    return;
  }
  siteDrawing.file = file;
  $("site-summary").textContent = `reading ${file.name}…`;
  try {
    const answer = await postSite({});
    siteDrawing.layers = answer.layers;
    siteDrawing.hidden = answer.hidden || [];
    siteDrawing.regions = answer.regions || [];
    siteDrawing.around = null;
    showError("");
    $("site-summary").textContent = `${answer.file}: ${answer.format}, units ${answer.units || "not said"}` +
      (answer.notes.length ? `; ${answer.notes.join("; ")}` : "");
    renderSiteLayers();
  } catch (err) {
    showError(err.message);
    $("site-summary").textContent = "";
  }
}

// The chosen layers read as the surface: its keys become the page's, its zones the page's zones.
async function applySite() {
  const roles = { outline: [], opening: [], zone: [] };
  document.querySelectorAll("#site-layers select").forEach((s) => {
    const role = s.value;
    if (roles[role]) roles[role].push(siteDrawing.layers[Number(s.dataset.layer)].name);
  });
  if (roles.outline.length !== 1) {
    showError("Give exactly one layer as the outline: the one that holds the surface's outline");
    return;
  }
  const several = siteRingsOf(roles.outline[0]).length > 1;
  if (several && !siteDrawing.around) {
    showError(`${roles.outline[0]} holds several closed regions: click inside the one that is the outline`);
    return;
  }
  // The drawing is read against the recipe, not against a drawing read before (its outline and
  // zones would lie off the recipe's floor); both come back if this one is refused.
  const before = { sets: state.siteSets, zones: state.zones };
  try {
    state.siteSets = [];
    state.zones = [];
    const around = several ? { around: siteDrawing.around.map((v) => v.toPrecision(15)).join(",") } : {};
    const answer = await postSite({ outline: roles.outline[0], ...around, openings: roles.opening, zones: roles.zone });
    state.siteSets = answer.site.sets;
    state.zones = answer.site.zones;
    showError("");
    $("site-summary").textContent = `site: ${answer.site.summary}` +
      (answer.site.notes.length ? `; ${answer.site.notes.join("; ")}` : "");
    renderZoneList();
    // The floor may have another size now: no segment is asked for until it is known, then the
    // segment follows it where it is fixed to the floor.
    state.segment = null;
    await regenerate();
    applyFixedSize();
  } catch (err) {
    if (!state.siteSets.length) state.siteSets = before.sets, state.zones = before.zones;
    showError(err.message);
  }
}

export function wireSite() {
  wireDrop("site-drop", "site-file", readSite);
  $("site-apply").addEventListener("click", applySite);
  $("site-pick").addEventListener("click", pickSiteRegion);
}
