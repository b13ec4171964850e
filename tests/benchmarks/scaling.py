"""How each output grows with the layout: the two-curd tile pattern (paper fig. 3) laid at
10^4, 10^5 and 10^6 tiles, each output written alone by `curdle generate --outputs NAME`. A
writer's time and memory (shown) are the run's less those of a run that lays the same tiles and
writes only quantities.csv (a few lines). Checks, from 10^5 to 10^6 tiles, that the run's whole
time grows at most 11 times, and at 10^6 that the writer's peak memory is under three times the
file it writes (files over 8 MiB), for every output a default run writes at that size (the others are skipped by their
caps unless named, and are shown but not judged). Prints a table; exits 1 when a check fails.

Usage: scaling.py [BUILD_DIR] [--sizes 100,316,1000]
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OUTPUTS = ["cells.csv", "preview.png", "layout.svg", "layout.png", "layout.pdf", "layout.glb",
           "layout.dxf", "schedule.csv", "install.svg", "layout.ifc", "layout.gpkg", "lots.csv"]
BASE = "quantities.csv"


def measured(curdle, side, outputs, work):
    """Runs one generate in a child process of its own, so that its peak memory is its own."""
    out = tempfile.mkdtemp(dir=work)
    code = (
        "import resource, subprocess, sys, time\n"
        "t = time.perf_counter()\n"
        "r = subprocess.run(sys.argv[1:], capture_output=True)\n"
        "s = time.perf_counter() - t\n"
        "print(r.returncode, s, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024)\n")
    args = [curdle, "generate", str(ROOT / "patterns/paper/fig3-two-curds.toml"), "--set",
            f"field.cells=[{side},{side}]", "--outputs", outputs, "--out", out]
    best = None
    for _ in range(2):
        rc, seconds, rss = subprocess.run([sys.executable, "-c", code, *args], capture_output=True,
                                          text=True, check=True).stdout.split()
        if rc != "0":
            return None
        if best is None or float(seconds) < best[0]:
            best = (float(seconds), int(rss))
    written = sum(f.stat().st_size for f in Path(out).rglob("*") if f.is_file() and f.name != BASE)
    return best[0], best[1], written


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build", nargs="?", default=str(ROOT / "build/release"))
    ap.add_argument("--sizes", default="100,316,1000")
    a = ap.parse_args()
    curdle = str(Path(a.build, "curdle"))
    sides = [int(s) for s in a.sizes.split(",")]
    print(f"load: {' '.join(Path('/proc/loadavg').read_text().split()[:3])} on {os.cpu_count()} cores")
    failures = []
    with tempfile.TemporaryDirectory() as work:
        base = {side: measured(curdle, side, BASE, work) for side in sides}
        # What a default run writes at the largest size: the rest are skipped by their caps
        # (written only when named), and the checks leave their largest step out.
        default = Path(work, "default")
        subprocess.run([curdle, "generate", str(ROOT / "patterns/paper/fig3-two-curds.toml"),
                        "--set", f"field.cells=[{sides[-1]},{sides[-1]}]", "--out", str(default)],
                       capture_output=True, check=True)
        written = {f.name for f in default.iterdir()}
        print(f"{'output':14}" + "".join(f"{s * s:>26,}" for s in sides) + "   run x10   memory/file")
        for name in OUTPUTS:
            cols, rows = [], {}
            capped = name not in written
            for side in sides:
                if capped and side == sides[-1]:
                    cols.append(f"{'(capped: not by default)':>26}")
                    continue
                m = measured(curdle, side, f"{name},{BASE}", work)
                if m is None:
                    cols.append(f"{'refused':>26}")
                    continue
                t = max(m[0] - base[side][0], 0.0)
                extra = max(m[1] - base[side][1], 0)
                rows[side] = (m[0], extra, m[2])
                cols.append(f"{t:8.2f} s {extra / 2**20:6.0f} MiB {m[2] / 2**20:5.0f} MiB")
            growth = memory = ""
            if not capped and len(sides) >= 2 and sides[-1] in rows and sides[-2] in rows:
                # The run's whole time, laying out included: what the user waits for. (The
                # writer's own share, shown, is a difference of two noisy runs.)
                g = rows[sides[-1]][0] / rows[sides[-2]][0]
                growth = f"{g:6.1f}x"
                if g > 11:
                    failures.append(f"{name}: {g:.1f} times the time for 10 times the tiles")
            if sides[-1] in rows and not capped:
                t, extra, size = rows[sides[-1]]
                memory = f"{extra / max(size, 1):6.2f}x"
                if size > 8 * 2**20 and extra > 3 * size:
                    failures.append(f"{name}: {extra / 2**20:.0f} MiB at its peak for a "
                                    f"{size / 2**20:.0f} MiB file")
            print(f"{name:14}" + "".join(cols) + f"   {growth:>9}   {memory:>11}")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
