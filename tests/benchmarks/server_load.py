#!/usr/bin/env python3
"""Load on `curdle serve`, as the issue measured it: 14 clients export layout.png and layout.pdf
of the L-shaped courtyard back to back while 2 clients act as the page (/api/recipe and the
page's own generate); then 40 clients that trickle their headers beside a maximal search.
Prints p50, p99 and max per request kind and the server's resident memory. Times on a shared
machine are noise; the page's p99 beside the exports' is the result.
Usage: server_load.py [BUILD_DIR] [SECONDS]"""
import os, socket, subprocess, sys, threading, time, urllib.request

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build/release")
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 30.0
port = 18000 + os.getpid() % 1000
server = subprocess.Popen([os.path.join(build, "curdle"), "serve",
                           os.path.join(root, "patterns/courtyard-l-shaped.toml"),
                           "--port", str(port)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
base = "http://127.0.0.1:%d" % port


def fetch(path, timeout=120):
    start = time.perf_counter()
    try:
        with urllib.request.urlopen(base + path, timeout=timeout) as r:
            r.read()
            status = r.status
    except urllib.error.HTTPError as e:
        status = e.code
    return status, time.perf_counter() - start


def rss_mb(field="VmRSS:"):
    for line in open("/proc/%d/status" % server.pid):
        if line.startswith(field):
            return int(line.split()[1]) / 1024
    return -1


def quantiles(xs):
    xs = sorted(xs)
    if not xs:
        return "none"
    pick = lambda q: xs[min(len(xs) - 1, int(q * len(xs)))] * 1e3
    return "n %5d  p50 %8.1f ms  p99 %8.1f ms  max %8.1f ms" % (len(xs), pick(0.5), pick(0.99), xs[-1] * 1e3)


for _ in range(100):
    try:
        fetch("/api/recipe", 1)
        break
    except Exception:
        time.sleep(0.1)
idle = rss_mb()
times = {k: [] for k in ("recipe", "generate", "layout.png", "layout.pdf")}
statuses = {}
end = time.time() + seconds


def client(kinds):
    i = 0
    while time.time() < end:
        kind = kinds[i % len(kinds)]
        i += 1
        path = "/api/recipe" if kind == "recipe" else \
            "/api/generate?seed=%d" % i if kind == "generate" else \
            "/api/export?seed=%d&file=%s" % (i, kind)
        status, t = fetch(path)
        statuses[status] = statuses.get(status, 0) + 1
        times[kind].append(t)


threads = [threading.Thread(target=client, args=(["layout.png", "layout.pdf"],)) for _ in range(14)]
threads += [threading.Thread(target=client, args=(["recipe", "generate"],)) for _ in range(2)]
for t in threads:
    t.start()
peak = idle
while any(t.is_alive() for t in threads):
    peak = max(peak, rss_mb())
    time.sleep(0.5)
print("16 clients for %.0f s (statuses %s):" % (seconds, statuses))
for kind, xs in times.items():
    print("  %-11s %s" % (kind, quantiles(xs)))
fetch("/api/export?file=report.json")  # one heavy request more, alone: its end trims the heap
time.sleep(1)
print("  resident: idle %.0f MB, peak %.0f MB, after %.0f MB (%.0f MB of it the heap)" %
      (idle, peak, rss_mb(), rss_mb("RssAnon:")))

# 40 clients trickling their headers, a maximal search, and the page's requests.
slow = []
for _ in range(40):
    s = socket.create_connection(("127.0.0.1", port))
    s.send(b"GET /api/recipe HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Pad: " % port)
    slow.append(s)
search = threading.Thread(target=lambda: fetch("/api/search?seeds=1..5000"))
search.start()
page = []
stop = time.time() + 5
while time.time() < stop:
    for s in slow:
        try:
            s.send(b"a")
        except OSError:
            pass
    page.append(fetch("/api/recipe", 5)[1])
    time.sleep(0.05)
search.join()
print("40 slow clients and a search: /api/recipe %s" % quantiles(page))
server.terminate()
server.wait()
