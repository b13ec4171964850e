// The page's site from a drawing: a DXF or SVG dropped or chosen is sent to /api/site, its
// layers are listed and each given a role (the outline, openings, zones kept free, or none),
// and the surface read from them becomes the page's overrides (the outline with its arcs as
// bulges, a façade's windows) and zones, as [layout.site] reads it (loaded before app.js).
"use strict";

const siteDrawing = { file: null, layers: [] };

function siteRoleGuess(name, first) {
  if (/otln|outline|boundary|wall|site/i.test(name)) return "outline";
  if (/glaz|window|door|opening/i.test(name)) return "opening";
  if (/pit|drain|zone|planter/i.test(name)) return "zone";
  return first ? "outline" : "none";
}

function renderSiteLayers() {
  const rows = siteDrawing.layers.map((l, i) => {
    const guess = siteRoleGuess(l.name, i === 0);
    const options = ["none", "outline", "opening", "zone"].map((r) =>
      `<option value="${r}"${r === guess ? " selected" : ""}>${
        { none: "not used", outline: "the outline", opening: "openings", zone: "zones kept free" }[r]}</option>`);
    return `<tr><td>${escapeHtml(l.name)}</td><td>${l.shapes} shapes, ${l.closed} closed</td>` +
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
  try {
    state.siteSets = [];  // the drawing is read against the recipe, not a drawing read before
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
    showError(err.message);
  }
}

function wireSite() {
  wireDrop("site-drop", "site-file", readSite);
  $("site-apply").addEventListener("click", applySite);
}
