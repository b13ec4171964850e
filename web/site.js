// The page's site from a drawing: a DXF or SVG dropped or chosen is sent to /api/site, its
// layers are listed and each given a role (the outline, openings, zones kept free, or none),
// and the surface read from them becomes the page's overrides (the outline with its arcs as
// bulges, a façade's windows) and zones, as [layout.site] reads it (loaded before app.js).
"use strict";

const siteDrawing = { file: null, layers: [], hidden: [] };

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
}

function escapeHtml(text) {
  return String(text).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" }[c]));
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
  // The drawing is read against the recipe, not against a drawing read before (its outline and
  // zones would lie off the recipe's floor); both come back if this one is refused.
  const before = { sets: state.siteSets, zones: state.zones };
  try {
    state.siteSets = [];
    state.zones = [];
    const answer = await postSite({ outline: roles.outline[0], openings: roles.opening, zones: roles.zone });
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

function wireSite() {
  wireDrop("site-drop", "site-file", readSite);
  $("site-apply").addEventListener("click", applySite);
}
