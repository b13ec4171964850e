// What the page's workers share: one request at a time, a newer one aborting
// the one before it, and a failed answer's JSON "error" as its message.
import { apiFetch } from "./api_request.js";

let currentRequest = null;

export function errorText(buffer, status) {
  try {
    return JSON.parse(new TextDecoder().decode(buffer)).error || `request failed (${status})`;
  } catch (err) {
    return `the server answered ${status} with no JSON`;
  }
}

// Fetches {id, url}, aborting the fetch before it, and answers with what `read(id, buffer,
// stillWanted)` posts of the bytes, or with {id, error}; an aborted request posts nothing. A
// read that takes a while asks stillWanted() between slices of its work, and stops when a
// newer request or a drop has come.
export async function fetchLatest({ id, url }, read) {
  if (currentRequest) currentRequest.abort();
  const controller = new AbortController();
  currentRequest = controller;
  try {
    const response = await apiFetch(url, { signal: controller.signal });
    const buffer = await response.arrayBuffer();
    if (!response.ok) self.postMessage({ id, error: errorText(buffer, response.status) });
    else await read(id, buffer, () => !controller.signal.aborted);
  } catch (err) {
    if (err.name !== "AbortError") self.postMessage({ id, error: String(err.message || err) });
  } finally {
    if (currentRequest === controller) currentRequest = null;
  }
}

// Answers each message {id, url} by fetchLatest. {drop: true} aborts the one on its way.
export function answerLatest(read) {
  self.onmessage = ({ data }) => {
    if (data.drop) {
      if (currentRequest) currentRequest.abort();
      return;
    }
    fetchLatest(data, read);
  };
}
