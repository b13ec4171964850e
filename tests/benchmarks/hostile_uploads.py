#!/usr/bin/env python3
"""The page's light requests while hostile drawings are uploaded, as issue 66 asks: two clients
upload, back to back, the heaviest drawings the server still reads (190,000 SVG paths; 190,000
DXF lines through one point), while a third acts as the page (/api/recipe and its small
/api/generate). Prints the page's p50 and p99 and the uploads' statuses; then one upload whose
client leaves 0.1 s after sending it, and the server's CPU in the 1.5 s after it left against
one whole read's CPU. Times on a shared machine are noise; the page's p99 is the result.
Usage: hostile_uploads.py [BUILD_DIR] [SECONDS]"""
import os, socket, subprocess, sys, tempfile, threading, time, urllib.request

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build/release")
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 20.0
port = 18000 + os.getpid() % 1000
work = tempfile.mkdtemp(prefix="hostile-uploads-")
outline = ('0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA\n90\n4\n70\n1\n10\n0\n20\n0\n10\n10000\n20\n0\n'
           '10\n10000\n20\n10000\n10\n0\n20\n10000\n')
drawings = {
    "paths.svg": ('<svg xmlns="http://www.w3.org/2000/svg"><g id="A"><rect width="10000" height="10000"/></g>'
                  '<g id="B">' + '<path d="M0 0L1 1L2 0L3 1L4 0Z"/>' * 190000 + '</g></svg>').encode(),
    "star.dxf": (outline + '0\nLINE\n8\nI\n10\n0\n20\n0\n11\n1\n21\n1\n' * 190000 + '0\nENDSEC\n0\nEOF\n').encode(),
}
server = subprocess.Popen([os.path.join(build, "curdle"), "serve",
                           os.path.join(root, "patterns/courtyard-l-shaped.toml"), "--port", str(port)],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
base = "http://127.0.0.1:%d" % port


def fetch(path, body=None, timeout=120):
    start = time.perf_counter()
    request = urllib.request.Request(base + path, data=body,
                                     headers={"Content-Type": "application/octet-stream"} if body else {})
    try:
        with urllib.request.urlopen(request, timeout=timeout) as r:
            r.read()
            status = r.status
    except urllib.error.HTTPError as e:
        status = e.code
    return status, time.perf_counter() - start


def cpu_seconds():
    fields = open("/proc/%d/stat" % server.pid).read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def quantiles(xs):
    xs = sorted(xs)
    pick = lambda q: xs[min(len(xs) - 1, int(q * len(xs)))] * 1e3
    return "n %4d  p50 %7.1f ms  p99 %7.1f ms  max %7.1f ms" % (len(xs), pick(0.5), pick(0.99), xs[-1] * 1e3)


for _ in range(100):
    try:
        fetch("/api/recipe", timeout=1)
        break
    except Exception:
        time.sleep(0.1)
end = time.time() + seconds
uploads = {}


def uploader(name):
    while time.time() < end:
        status, t = fetch("/api/site?name=" + name, drawings[name])
        uploads.setdefault((name, status), []).append(t)


threads = [threading.Thread(target=uploader, args=(n,)) for n in drawings]
for t in threads:
    t.start()
page = []
i = 0
while time.time() < end:
    i += 1
    page.append(fetch("/api/recipe" if i % 2 else "/api/generate?seed=%d" % i)[1])
    time.sleep(0.05)
for t in threads:
    t.join()
print("two hostile uploads in flight for %.0f s:" % seconds)
print("  the page's light requests  %s" % quantiles(page))
for (name, status), xs in sorted(uploads.items()):
    print("  upload %-10s %d       %s" % (name, status, quantiles(xs)))

# A whole read's CPU, then one whose client leaves 0.1 s after sending it.
before = cpu_seconds()
fetch("/api/site?name=paths.svg", drawings["paths.svg"])
whole = cpu_seconds() - before
body = drawings["paths.svg"]
s = socket.create_connection(("127.0.0.1", port))
s.sendall(b"POST /api/site?name=paths.svg HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nContent-Type: "
          b"application/octet-stream\r\nContent-Length: %d\r\n\r\n" % (port, len(body)) + body)
time.sleep(0.1)
s.close()
left = cpu_seconds()
time.sleep(1.5)
print("one read's CPU %.2f s; after its client left at 0.1 s, the server used %.2f s more" %
      (whole, cpu_seconds() - left))
server.terminate()
server.wait()
