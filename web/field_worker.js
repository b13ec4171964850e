// The page's worker: asks for the whole field over one open WebSocket (/api/field-socket, the
// same bytes as /api/field: src/server/field_socket.h), which saves Chromium's cost of a fetch
// on every change (6-10 ms of a 1024 x 1024 redraw on two cores), and fetches /api/field when
// no socket opens. It splits the binary answer ("CRD1", the head's length, the head as JSON,
// then the values: src/server/api.h) into the head and the values, which it hands over
// without a copy. Only the latest request is answered: an older one's answer is dropped.
import { errorText, fetchLatest } from "./worker_fetch.js";

function readField(id, buffer) {
  try {
    const bytes = new Uint8Array(buffer);
    if (buffer.byteLength < 8 || String.fromCharCode(...bytes.subarray(0, 4)) !== "CRD1")
      throw new Error("the server's answer to /api/field is not a CRD1 field");
    const n = new DataView(buffer).getUint32(4, true);
    const head = JSON.parse(new TextDecoder().decode(bytes.subarray(8, 8 + n)));
    self.postMessage({ id, head, buffer, offset: 8 + n }, [buffer]);
  } catch (err) {
    self.postMessage({ id, error: String(err.message || err) });
  }
}

let latest = null;        // the request to answer: {id, url}
let socket = null;        // open or opening
let socketRefused = false;  // a socket never opened: fetch from now on
let waiting = null;       // asked while the socket was opening
const onTheWay = [];      // ids sent on the socket, in order: its answers come in that order

function sendOnSocket(request) {
  socket.send(request.url.slice(request.url.indexOf("?") + 1));
  onTheWay.push(request.id);
}

function openSocket() {
  const scheme = location.protocol === "https:" ? "wss:" : "ws:";
  const s = new WebSocket(`${scheme}//${location.host}/api/field-socket`);
  s.binaryType = "arraybuffer";
  let opened = false;
  s.onopen = () => {
    opened = true;
    if (waiting) sendOnSocket(waiting);
    waiting = null;
  };
  s.onmessage = ({ data }) => {
    const id = onTheWay.shift();
    if (!latest || id !== latest.id) return;  // a newer change has asked since
    if (typeof data === "string") self.postMessage({ id, error: errorText(new TextEncoder().encode(data), "an error") });
    else readField(id, data);
  };
  s.onclose = () => {
    // Closed by the server (idle, stopping) or never opened: the latest request, if the socket
    // took it along, is fetched; the next opens a socket again unless this one never opened.
    if (socket === s) socket = null;
    if (!opened) socketRefused = true;
    const lost = waiting || (latest && onTheWay.includes(latest.id) ? latest : null);
    waiting = null;
    onTheWay.length = 0;
    if (lost) fetchLatest(lost, readField);
  };
  return s;
}

self.onmessage = ({ data }) => {
  latest = data;
  // A query longer than a socket's message (64 KiB: a long outline) is fetched, by POST.
  if (socketRefused || data.url.length > 60000) {
    fetchLatest(data, readField);
    return;
  }
  if (!socket) socket = openSocket();
  if (socket.readyState === WebSocket.OPEN) sendOnSocket(data);
  else waiting = data;
};
