// What every part of the page shares: its element lookup, its state, its error line, its
// requests for JSON, and its file drops.
import { apiFetch } from "./api_request.js";

export const $ = (id) => document.getElementById(id);

export const state = {
  recipe: null,  // /api/recipe, as loaded: the base every override is measured against
  seed: 1,
  base: 2,
  dimension: 2,
  stages: 1,
  mode: 'canonical',
  field: [1, 1],
  curds: [],         // {name, colour, probabilities: [text]}
  valueColours: [],  // layout.colours, when the recipe has them
  whole: null,       // the last /api/field of the whole field (values: its cells, typed)
  segment: null,     // [x, y, w, h] in cells, or null for the whole field
  segmentReport: null,
  zones: [],  // the layout's zones: the recipe's, then those added on the page
};

export function showError(message) {
  const e = $("error");
  e.textContent = message;
  e.hidden = !message;
}

// A request's JSON; its message thrown when it failed. `init` as fetch takes it (a POST's body).
export async function getJson(url, signal, init) {
  const response = await apiFetch(url, { ...init, signal });
  let body;
  try {
    body = await response.json();
  } catch (err) {
    if (err.name === "AbortError") throw err;  // a newer request took over mid-body
    body = { error: `the server answered ${response.status} with no JSON` };
  }
  if (!response.ok) throw new Error(body.error || `request failed (${response.status})`);
  return body;
}

// A zone a file is dropped on, with its chooser: `use` takes the file either way.
export function wireDrop(zoneId, inputId, use) {
  const zone = $(zoneId);
  zone.addEventListener("dragover", (e) => { e.preventDefault(); zone.classList.add("over"); });
  zone.addEventListener("dragleave", () => zone.classList.remove("over"));
  zone.addEventListener("drop", (e) => {
    e.preventDefault();
    zone.classList.remove("over");
    use(e.dataTransfer.files[0]);
  });
  $(inputId).addEventListener("change", () => use($(inputId).files[0]));
}

// Text made safe to put in HTML.
export function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" }[c]));
}
