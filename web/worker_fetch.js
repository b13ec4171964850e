// What the page's workers share (importScripts): one request at a time, a newer one aborting
// the one before it, and a failed answer's JSON "error" as its message.
"use strict";

let currentRequest = null;

function errorText(buffer, status) {
  try {
    return JSON.parse(new TextDecoder().decode(buffer)).error || `request failed (${status})`;
  } catch (err) {
    return `the server answered ${status} with no JSON`;
  }
}

// Answers each message {id, url} with what `read(id, buffer)` posts of the fetched bytes, or
// with {id, error}; an aborted request posts nothing. {drop: true} aborts the one on its way.
function answerLatest(read) {
  self.onmessage = async ({ data }) => {
    if (currentRequest) currentRequest.abort();
    if (data.drop) return;  // {drop: true}: only the request on its way dropped
    const controller = new AbortController();
    currentRequest = controller;
    const { id, url } = data;
    try {
      const response = await fetch(url, { signal: controller.signal });
      const buffer = await response.arrayBuffer();
      if (!response.ok) self.postMessage({ id, error: errorText(buffer, response.status) });
      else read(id, buffer);
    } catch (err) {
      if (err.name !== "AbortError") self.postMessage({ id, error: String(err.message || err) });
    } finally {
      if (currentRequest === controller) currentRequest = null;
    }
  };
}
