// A request to the API with the page's overrides, shared by the page and its workers
// (imported by both): by GET while its address stays short, else by POST with the same query as a
// form body, since an outline of thousands of vertices (a spline read from a drawing) makes an
// address no server takes (414). The body is the query's text, as text/plain.

export const kLongestAddress = 4000;

// [url, init] for fetch: the query moved into the body when the address is too long.
function apiRequest(url, init = {}) {
  const q = url.indexOf("?");
  if (url.length <= kLongestAddress || q < 0 || (init.method && init.method !== "GET")) return [url, init];
  return [url.slice(0, q), {
    ...init,
    method: "POST",
    body: url.slice(q + 1),
    headers: { ...(init.headers || {}), "Content-Type": "text/plain;charset=UTF-8" },
  }];
}

export function apiFetch(url, init) {
  const [address, options] = apiRequest(url, init);
  return fetch(address, options);
}
