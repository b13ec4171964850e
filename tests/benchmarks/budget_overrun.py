#!/usr/bin/env python3
"""How far past its budget each heavy hostile request runs on `curdle serve --request-seconds B`:
the cases of the fourth hostile round (a progressive JPEG of 400,000 scans and a PNG of 1,000
zTXt chunks sent to /api/measure, layout.glb of a 1024 x 1024-tile floor, cells.csv of a
2048 x 2048 field of 16 curds, and the same cells.csv from a client that leaves after a second)
plus a page-sized generate beside them. Prints each answer's status, time, time over budget and
the server's peak memory; the worst ratio of time to budget is the result (goal: none over 2).
Then twelve page-sized generates at once on a recipe whose density is a 4096^2 RGBA16 picture:
the server's peak memory, which stays near one decode's since pictures are read in a slot.
Usage: budget_overrun.py [BUILD_DIR] [BUDGET_SECONDS]"""
import http.client, os, socket, struct, subprocess, sys, threading, time, zlib

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build/release")
budget = float(sys.argv[2]) if len(sys.argv) > 2 else 4.0
port = 19000 + os.getpid() % 1000


def request(method, path, body=None, leave_after=None):
    start = time.perf_counter()
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=600)
    headers = {"Content-Type": "application/octet-stream"} if body is not None else {}
    try:
        c.request(method, path, body=body, headers=headers)
    except (BrokenPipeError, ConnectionResetError):
        pass  # answered (and closed) before the whole body was sent: the answer is read below
    if leave_after is not None:  # a client that goes away: the work must stop soon after
        time.sleep(leave_after)
        c.sock.close()
        return "left", time.perf_counter() - start
    r = c.getresponse()
    r.read()
    return r.status, time.perf_counter() - start


def serve(recipe, *options):
    """`curdle serve RECIPE OPTIONS` on the next port, once it answers."""
    global port
    port += 1
    process = subprocess.Popen([os.path.join(build, "curdle"), "serve", recipe, "--port", str(port),
                                *options], stdout=subprocess.DEVNULL)
    for _ in range(100):
        try:
            request("GET", "/api/colours?colour=%23000000")
            break
        except OSError:
            time.sleep(0.1)
    return process


def peak_mb():
    for line in open("/proc/%d/status" % server.pid):
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    return -1


def cpu_seconds():
    fields = open("/proc/%d/stat" % server.pid).read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


chunk = lambda t, b: struct.pack(">I", len(b)) + t + b + struct.pack(">I", zlib.crc32(t + b))
raw = zlib.compress(b"".join(b"\0" + bytes(64) for _ in range(64)))
ztxt = chunk(b"zTXt", b"Comment\0\0" + zlib.compress(b" " * 8_000_000, 9))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 64, 64, 8, 0, 0, 0, 0))
       + ztxt * 1000 + chunk(b"IDAT", raw) + chunk(b"IEND", b""))
sof2 = b"\xff\xc2" + struct.pack(">HBHHB", 11, 8, 1024, 1024, 1) + b"\x01\x11\x00"
sos = b"\xff\xda" + struct.pack(">HB", 8, 1) + b"\x01\x00\x00\x3f\x00" + b"\x00" * 32
jpeg = b"\xff\xd8" + sof2 + sos * 360_000 + b"\xff\xd9"  # 15.5 MB, under the upload limit
quote = lambda text: "".join(c if c.isalnum() else "%%%02X" % ord(c) for c in text)
sixteen = "set=" + quote("curds=[" + ",".join('{name="c%d",probabilities=["1/2","1/2","1/2"]}' % i
                                          for i in range(16)) + "]")
floor = "set=" + quote('layout={kind="paving",tile=[300,300],joint=0,floor=[307200,307200]}')
cases = [
    ("measure: JPEG of 360,000 scans", "POST", "/api/measure?name=scans.jpg", jpeg, None),
    ("measure: PNG of 1,000 zTXt", "POST", "/api/measure?name=text.png", png, None),
    ("export: layout.glb of 1024^2 tiles", "GET",
     "/api/export?file=layout.glb&" + floor, None, None),
    ("export: cells.csv of 2048^2 x 16", "GET",
     "/api/export?file=cells.csv&field.cells=%5B2048,2048%5D&" + sixteen, None, None),
    ("export: cells.csv, client gone at 0.2 s", "GET",
     "/api/export?file=cells.csv&field.cells=%5B2048,2048%5D&" + sixteen, None, 0.2),
]

server = serve(os.path.join(root, "patterns/paper/fig7-three-stages.toml"),
               "--request-seconds", "%g" % budget)
with open("/proc/loadavg") as f:
    load = f.read().split()[0]
print("budget %.1f s, load %s" % (budget, load))
worst = 0.0
try:
    for name, method, path, body, leave in cases:
        before = cpu_seconds()
        status, seconds = request(method, path, body, leave)
        if leave is not None:  # the work's time: the server's CPU (one thread) until it stopped
            time.sleep(budget * 2)
            seconds = cpu_seconds() - before
        ratio = seconds / budget
        worst = max(worst, ratio)
        print("%-40s %5s %7.2f s  %5.2fx budget  peak %6.0f MB" % (name, status, seconds, ratio, peak_mb()))
finally:
    server.terminate()
    server.wait()
print("worst: %.2fx the budget (goal: at most 2x)" % worst)

# Twelve page-sized generates at once, each reading a 4096^2 RGBA16 density picture of 138 KB.
import re, shutil, tempfile
folder = tempfile.mkdtemp()
rows = zlib.compress(b"".join(b"\0" + bytes(4096 * 8) for _ in range(4096)), 9)
with open(os.path.join(folder, "density.png"), "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 4096, 4096, 16, 6, 0, 0, 0))
            + chunk(b"IDAT", rows) + chunk(b"IEND", b""))
plaza = open(os.path.join(root, "patterns/plaza-radial-density.toml")).read()
plaza = re.sub(r"\[curds\.density\]\n(?:[^\[\n].*\n)*", '[curds.density]\nkind = "image"\n'
               'path = "density.png"\nvalues = [0, 2]\n\n', plaza, count=1)
with open(os.path.join(folder, "plaza.toml"), "w") as f:
    f.write(plaza)
server = serve(os.path.join(folder, "plaza.toml"))
try:
    idle = peak_mb()
    results = []
    start = time.perf_counter()
    threads = [threading.Thread(target=lambda s=s: results.append(request("GET", "/api/generate?seed=%d" % s)))
               for s in range(12)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    statuses = sorted({r[0] for r in results})
    print("12 generates with a 4096^2 density picture: statuses %s, %.2f s, peak %.0f MB (idle %.0f MB)"
          % (statuses, time.perf_counter() - start, peak_mb(), idle))
finally:
    server.terminate()
    server.wait()
    shutil.rmtree(folder)
