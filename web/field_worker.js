// The page's worker: fetches /api/field off the main thread and splits its binary answer
// ("CRD1", the head's length, the head as JSON, then the values: src/server/api.h) into the
// head and the values, which it hands over without a copy. One field at a time: a newer
// request aborts the one before it.
"use strict";
importScripts("worker_fetch.js");

answerLatest((id, buffer) => {
  const bytes = new Uint8Array(buffer);
  if (buffer.byteLength < 8 || String.fromCharCode(...bytes.subarray(0, 4)) !== "CRD1")
    throw new Error("the server's answer to /api/field is not a CRD1 field");
  const n = new DataView(buffer).getUint32(4, true);
  const head = JSON.parse(new TextDecoder().decode(bytes.subarray(8, 8 + n)));
  self.postMessage({ id, head, buffer, offset: 8 + n }, [buffer]);
});
