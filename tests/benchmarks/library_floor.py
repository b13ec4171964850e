"""How low a whole run can go while its outputs keep their bytes: the CPU a run spends in the
libraries that write those bytes (SQLite and GDAL for layout.gpkg, cairo, pixman and zlib for
layout.pdf and layout.png, ...), spread over every core, in yardsticks (table.py's).

Each recipe is run with every default output: best of five as a whole process (wall and CPU,
beside the best of five yardsticks), then under `perf record` (Debian's linux-perf), whose
samples split its CPU by shared object. Whatever curdle's own code is made to cost, a run's
libraries take at least their CPU over the cores, and the bytes fix what they do; so where that
floor is over a goal, the goal cannot be met with the same bytes. The process's own costs
(loading libraries, the kernel's pages, libc's allocation and copying) are counted apart: curdle
shares them with the libraries.

One file is one stream: layout.gpkg is one SQLite database written by one writer, after GDAL is
loaded. So the run is also measured with layout.gpkg alone, and SQLite's, GDAL's and the
loader's CPU there (loading GDAL is most of the loader's work) is a floor on one core that no
spreading over cores lowers.

Usage: library_floor.py [--build DIR] [recipe ...]   (default: the pavilion, the curved
screen and every brief)
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from table import ROOT, load, machine, yardstick_ms  # noqa: E402

RUNS = 5
PERF_HZ = 4000
DEFAULT = ["patterns/pavilion-l-shaped.toml", "patterns/perforated-screen-curved.toml",
           *sorted(p.relative_to(ROOT).as_posix() for p in ROOT.glob("examples/briefs/*.toml"))]
GOALS = {"patterns/pavilion-l-shaped.toml": 2.5}  # every other shipped recipe: 2 (issue 70)

# Shared objects as curdle's own (its code, its modules, the C++ runtime and the libraries it
# calls for its own work), the process's (shared by everyone) or a writer's library (the rest).
OWN = re.compile(r"^(curdle|curdle-serve|libcurdle_.*|libstdc\+\+.*|libfmt.*|libm\.so.*|"
                 r"libtbb.*|libgcc_s.*)$")
GPKG = re.compile(r"^(libsqlite3.*|libgdal.*|ld-linux.*)$")
PROCESS = re.compile(r"^(\[kernel\.kallsyms\]|ld-linux.*|libc\.so.*|\[vdso\].*|\[unknown\])$")


def best_of(args, runs=RUNS):
    """The fastest of `runs` whole runs: (wall s, CPU s of that run)."""
    best = None
    for _ in range(runs):
        start, t = os.times(), time.perf_counter()
        subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        wall, end = time.perf_counter() - t, os.times()
        cpu = (end.children_user - start.children_user) + (end.children_system - start.children_system)
        if best is None or wall < best[0]:
            best = (wall, cpu)
    return best


def shares_by_object(args, work):
    """The run's samples under perf, as each shared object's share of them."""
    data = Path(work, "perf.data")
    subprocess.run(["perf", "record", "-q", "-F", str(PERF_HZ), "-o", str(data), "--", *args],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    report = subprocess.run(["perf", "report", "-i", str(data), "--no-children", "--sort", "dso",
                             "-g", "none", "-n", "--stdio"],
                            capture_output=True, text=True, check=True).stdout
    return shares_in_report(report)


def shares_in_report(report):
    """`perf report --sort dso -n --stdio`'s lines as each shared object's share of the
    samples."""
    samples = {}
    for line in report.splitlines():
        fields = line.split()
        if len(fields) >= 3 and not line.startswith("#") and fields[1].isdigit():
            name = " ".join(fields[2:])
            samples[name] = samples.get(name, 0) + int(fields[1])
    total = sum(samples.values()) or 1
    return {name: n / total for name, n in samples.items()}


def group_of(name):
    """"own", "process" or "libraries": whose a shared object's samples are."""
    return "own" if OWN.match(name) else "process" if PROCESS.match(name) else "libraries"


def grouped(shares):
    """{"own", "process", "libraries"}: the shares of curdle's own code, the process's and the
    writers' libraries."""
    groups = {"own": 0, "process": 0, "libraries": 0}
    for name, share in shares.items():
        groups[group_of(name)] += share
    return groups


def gpkg_share(shares):
    """The share of a run with layout.gpkg alone that SQLite, GDAL and the loader take, all on
    one thread."""
    return sum(share for name, share in shares.items() if GPKG.match(name))


def gpkg_floor(args, work):
    """layout.gpkg alone: the CPU (s) of SQLite, GDAL and the loader."""
    alone = [*args, "--outputs", "layout.gpkg"]
    return best_of(alone, runs=3)[1] * gpkg_share(shares_by_object(alone, work))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build" / "release"))
    parser.add_argument("recipes", nargs="*", default=DEFAULT)
    opts = parser.parse_args()
    curdle = Path(opts.build, "curdle")
    if not curdle.is_file():
        sys.exit(f"build first: {curdle} is missing (cmake --build --preset release)")
    if not shutil.which("perf"):
        sys.exit("perf is missing: apt-get install linux-perf (it splits a run's CPU by library)")
    cores = os.cpu_count()
    print(f"{machine()}; load {load()}")
    with tempfile.TemporaryDirectory() as work:
        for recipe in opts.recipes:
            args = [str(curdle), "generate", str(ROOT / recipe), "--out", str(Path(work, "out"))]
            before = yardstick_ms()
            wall, cpu = best_of(args)
            stick = min(before, yardstick_ms()) / 1e3  # table.py's yardstick, in seconds
            shares = shares_by_object(args, work)
            groups = grouped(shares)
            gpkg = gpkg_floor(args, work) / stick
            goal = GOALS.get(recipe, 2)
            floor = groups["libraries"] * cpu / cores / stick
            with_process = (groups["libraries"] + groups["process"]) * cpu / cores / stick
            libraries = {n: v for n, v in shares.items() if group_of(n) == "libraries"}
            top = ", ".join(f"{name} {share:.0%}" for name, share in
                            sorted(libraries.items(), key=lambda kv: -kv[1])[:5])
            print(f"\n{recipe}: {wall * 1e3:.0f} ms whole = {wall / stick:.1f} yardsticks "
                  f"(yardstick {stick * 1e3:.0f} ms, goal {goal}); CPU {cpu * 1e3:.0f} ms")
            print(f"  CPU: curdle's own {groups['own']:.0%}, the process's {groups['process']:.0%}"
                  f" (loading, the kernel, libc), the writers' libraries {groups['libraries']:.0%}"
                  f" ({top})")
            print(f"  floor over {cores} cores: the libraries alone {floor:.1f} yardsticks, with the "
                  f"process's costs {with_process:.1f}; "
                  + ("below the goal" if floor < goal else "over the goal before curdle's own code"))
            print(f"  layout.gpkg's one stream: SQLite, GDAL and loading them {gpkg:.1f} yardsticks "
                  "on one core; " + ("below the goal" if gpkg < goal else "over the goal by itself"))


if __name__ == "__main__":
    main()
