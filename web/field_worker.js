// The page's worker: fetches /api/field off the main thread and splits its binary answer
// ("CRD1", the head's length, the head as JSON, then the values: src/server/api.h) into the
// head and the values, which it hands over without a copy. One field at a time: a newer
// request aborts the one before it.
"use strict";

let current = null;

function errorText(buffer, status) {
  try {
    return JSON.parse(new TextDecoder().decode(buffer)).error || `request failed (${status})`;
  } catch (err) {
    return `the server answered ${status} with no JSON`;
  }
}

self.onmessage = async ({ data }) => {
  if (current) current.abort();
  const controller = new AbortController();
  current = controller;
  const { id, url } = data;
  try {
    const response = await fetch(url, { signal: controller.signal });
    const buffer = await response.arrayBuffer();
    if (!response.ok) {
      self.postMessage({ id, error: errorText(buffer, response.status) });
      return;
    }
    const bytes = new Uint8Array(buffer);
    if (buffer.byteLength < 8 || String.fromCharCode(...bytes.subarray(0, 4)) !== "CRD1")
      throw new Error("the server's answer to /api/field is not a CRD1 field");
    const n = new DataView(buffer).getUint32(4, true);
    const head = JSON.parse(new TextDecoder().decode(bytes.subarray(8, 8 + n)));
    self.postMessage({ id, head, buffer, offset: 8 + n }, [buffer]);
  } catch (err) {
    if (err.name !== "AbortError") self.postMessage({ id, error: String(err.message || err) });
  } finally {
    if (current === controller) current = null;
  }
};
