// The whole field for the canvas, fetched off the page's thread: fetchField.

// The whole field comes through a worker (field_worker.js) as bytes: nothing decodes the
// cells on this thread. A newer request makes the worker drop the older, whose promise is
// rejected here as aborted.
const fieldWorker = new Worker("field_worker.js", { type: "module" });
const fieldWaiting = new Map();
export let fieldIds = 0;  // the fields asked for (the browser check counts them)
fieldWorker.onmessage = ({ data }) => {
  const waiting = fieldWaiting.get(data.id);
  if (!waiting) return;
  fieldWaiting.delete(data.id);
  if (data.error) { waiting.reject(new Error(data.error)); return; }
  const head = data.head;
  // The values packed value_bits to a cell (src/server/api.h); unpacked on the GPU
  // (field_gl.js) and one at a time under the pointer (valueAt).
  head.values = head.value_bits ? new Uint8Array(data.buffer, data.offset) : null;
  waiting.resolve(head);
};
export function fetchField(url) {
  for (const [id, waiting] of fieldWaiting) {
    const abort = new Error("a newer field was asked for");
    abort.name = "AbortError";
    waiting.reject(abort);
    fieldWaiting.delete(id);
  }
  const id = ++fieldIds;
  return new Promise((resolve, reject) => {
    fieldWaiting.set(id, { resolve, reject });
    fieldWorker.postMessage({ id, url });
  });
}
