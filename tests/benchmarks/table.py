"""The benchmark table: measures every row in one run on this machine, beside the numpy peer
(../shared/bench) where there is one, compares each row with the last committed results
(tests/benchmarks/results.json) and fails when one is more than 20 % worse, and with --readme
writes the table into README.md between its markers.

Rows: the engine alone (in process, curdle_bench), start-up alone (`curdle --help`,
`curdle --version`), and whole processes as a user runs them (start-up included, best of
five), each against the peer's whole process where it has one; the page from a change to its
pixels (headless Chromium, tests/js/page_redraw.mjs) and with the pavilion, a change to its
3-D model drawn and clicks on it answered (tests/js/page_building.mjs), and Blender's import of
its layout.glb (tests/benchmarks/blender_import.sh); every shipped pattern and brief whole with
every default output (the slowest of each); the screen's layout.glb. The load of the machine is
taken before and after, and kept with the results.

Every goal is a ratio, so that the table holds on any machine within its noise: to the numpy
peer where there is one, else to the yardstick (YARDSTICK below: a fixed single-core Python loop
of a few tenths of a second, no IO, as a whole process), measured in the same minute as the
row: the best of its runs there (best_beside), as each row is the best of its own (the fastest
of curdle_bench's runs, and of the peer's). The absolute times stand beside the
ratios for reading.

Usage: table.py [--build DIR] [--peer DIR] [--accept] [--readme] [--no-peer] [--no-page]
  --accept   keep this run as the new results (a regression is then reported, not failed)
  --readme   write the table into README.md (between the benchmark-table markers)
  --no-peer  leave out the peer (its cube takes half a minute and 6 GiB)
  --agree    on another machine: every row but the page's measured here and its ratio printed
             beside the committed run's (another machine's), with how far apart they are;
             keeps nothing and fails on nothing (.ci/run runs it on CI's machine)
"""
import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RESULTS = ROOT / "tests" / "benchmarks" / "results.json"
BEGIN, END = "<!-- benchmark table: begin -->", "<!-- benchmark table: end -->"
WORSE = 1.2  # a row more than 20 % worse than its committed result fails
AGREE = 0.25  # two machines' ratios are to agree within 25 %
BENCH_RUNS = 3  # curdle_bench's runs, of which each row takes the fastest
PEER_RUNS = 2  # the peer's runs, of which each row takes the fastest (its cube takes 25 s)


# The yardstick: one core's plain work, whole process, no IO (0.2-0.4 s on the machines here).
YARDSTICK = ["/usr/bin/python3", "-c", "sum(i * i for i in range(3_000_000))"]


def load():
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


def machine():
    """Which machine: its name, its processor and how many cores."""
    model = next((line.split(":", 1)[1].strip() for line in
                  Path("/proc/cpuinfo").read_text().splitlines() if line.startswith("model name")),
                 "an unnamed processor")
    return f"{platform.node()}, {model}, {os.cpu_count()} cores"


def best_ms(args, runs=5):
    best = 1e18
    for _ in range(runs):
        t = time.perf_counter()
        subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        best = min(best, time.perf_counter() - t)
    return best * 1e3


def once_ms(args):
    t = time.perf_counter()
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    return (time.perf_counter() - t) * 1e3, out


def yardstick_ms():
    return best_ms(YARDSTICK, runs=5)


# The rows are each the best of their runs, so the yardstick beside them is the best of its runs
# around them too: the best of the yardsticks taken before and after a row, or of the five taken
# nearest a pattern's (within half a minute), or between curdle_bench's runs. On the shared
# machine the yardstick's best of three moved between 125 and 250 ms from one minute to the next,
# and a ratio to one such measurement moved with it; it is the best of five.
def best_beside(*measured):
    return min(measured)


def best_repetitions(benchmarks):
    """Each benchmark's fastest run or repetition, as a row is the best of its runs (a
    benchmark's mean moved by a third from one run to the next on the shared machine)."""
    best = {}
    for b in benchmarks:
        if b.get("run_type", "iteration") != "iteration":
            continue  # the repetitions' mean, median and deviation
        kept = best.get(b["name"])
        if kept is None or bench_ms(b) < bench_ms(kept):
            best[b["name"]] = b
    return list(best.values())


def bench_ms(b):
    return b["real_time"] * {"ms": 1, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]


class Rows:
    def __init__(self):
        self.rows = []

    def add(self, key, what, value, unit, goal=None, better="lower", peer=None, source="",
            against_peer=False, yardstick=None):
        """A row; `goal` is (operator, number) on the value, or, `against_peer`, on the ratio to
        the peer (peer / value for times, value / peer for rates): not judged without the peer;
        or, given the `yardstick` measured beside it (ms), on the value in yardsticks."""
        ratio = None
        if peer is not None and value:
            ratio = value / peer if better == "higher" else peer / value
        yardsticks = value / yardstick if yardstick else None
        measured = ratio if against_peer else yardsticks if yardstick else value
        ok = None
        if goal and measured is not None:
            op, target = goal
            ok = measured >= target if op == ">=" else measured < target
        self.rows.append(dict(key=key, what=what, value=value, unit=unit, peer=peer, ratio=ratio,
                              goal=goal, ok=ok, better=better, source=source,
                              against_peer=against_peer, yardstick=yardstick,
                              yardsticks=yardsticks))


def engine_and_processes(build, peer_dir, rows, with_peer, work):
    py = "/usr/bin/python3"
    survey = Path(work, "survey")
    survey.mkdir()
    subprocess.run([py, str(ROOT / "patterns/sites/make_sites.py"), str(survey), "--survey"],
                   check=True, stdout=subprocess.DEVNULL)
    env = dict(os.environ, CURDLE_SURVEY_DIR=str(survey))
    # curdle_bench run BENCH_RUNS times between yardsticks: a yardstick taken only before and
    # after the benchmarks' minute found it 124 ms in one run and 206 ms in the next.
    sticks, runs = [yardstick_ms()], []
    for _ in range(BENCH_RUNS):
        runs += json.loads(subprocess.run([str(build / "tests/curdle_bench"), "--benchmark_format=json"],
                                          capture_output=True, text=True, check=True,
                                          env=env).stdout)["benchmarks"]
        sticks.append(yardstick_ms())
    in_process = best_beside(*sticks)
    ours = {}
    for b in best_repetitions(runs):
        ours.setdefault(b["name"].split("/")[0], b)
        ours["/".join(b["name"].split("/")[:2])] = b
    curdle = str(build / "curdle")
    p07 = ",".join(["0.7"] * 14)
    p08 = ",".join(["0.8"] * 5)
    cases = Path(work, "cases")
    cases.mkdir()
    Path(cases, "plane.toml").write_text(
        f'name = "plane"\n[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nname = "c"\nprobabilities = [{p07}]\n')
    Path(cases, "cube.toml").write_text(
        f'name = "cube"\n[lattice]\nbase = 4\ndimension = 3\n[[curds]]\nname = "c"\nprobabilities = [{p08}]\n')
    out = str(Path(work, "out"))
    # The plane's whole run, 20-30 ms, and start-up, 3 ms, the best of more runs than the cube's
    # quarter of a second: the shorter a run, the more of it one busy moment of the host takes.
    whole = {name: best_ms([curdle, "generate", str(cases / f"{name}.toml"), "--outputs",
                            "report.json", "--out", out], runs=tries)
             for name, tries in (("plane", 15), ("cube", 5))}
    before = yardstick_ms()
    help_ms = best_ms([curdle, "--help"], runs=15)
    version_ms = best_ms([curdle, "--version"], runs=15)
    startup = best_beside(before, yardstick_ms())
    peer = {}
    if with_peer:
        # The peer's best of its runs too, as ours are.
        for name, b, e, p in (("plane", 2, 2, p07), ("cube", 4, 3, p08)):
            for _ in range(PEER_RUNS):
                ms, text = once_ms([py, str(peer_dir / "peer_numpy.py"), str(b), str(e), p, "1", "1"])
                j = json.loads(text)
                engine = (j["generate_s"] + j["boxcount_s"]) * 1e3
                kept = peer.get(name, dict(whole=ms, engine=engine))
                peer[name] = dict(whole=min(ms, kept["whole"]), engine=min(engine, kept["engine"]))
        for _ in range(PEER_RUNS):
            search = json.loads(subprocess.run([py, str(peer_dir / "peer_numpy_search.py"), "4",
                                                "2/3,1/2,1/3", "3000", "0.111", "1.5"],
                                               capture_output=True, text=True, check=True).stdout)
            peer["search"] = max(search["seeds_per_s"], peer.get("search", 0))
    src = "tests/benchmarks/engine_bench.cpp"
    for name, bm, goal, cells in (("plane", "BM_Plane_b2_K14_p07", 300, "b = 2, E = 2, 14 stages, p = 0.7 (2^28 cells)"),
                                  ("cube", "BM_Cube_b4_K5_p08", 50, "b = 4, E = 3, 5 stages, p = 0.8 (2^30 cells)")):
        pe = peer.get(name, {})
        rows.add(f"{name}.engine", f"{cells}, generate + report, engine alone (in process)",
                 bench_ms(ours[bm]), "ms", (">=", goal), peer=pe.get("engine"), source=f"`{bm}`, {src}",
                 against_peer=True)
        rows.add(f"{name}.whole", f"the same, whole process: `curdle generate --outputs report.json`, start-up included",
                 whole[name], "ms", (">=", goal), peer=pe.get("whole"), source="tests/benchmarks/table.py",
                 against_peer=True)
    rows.add("startup.help", "start-up alone: `curdle --help`, whole process", help_ms, "ms", ("<", 0.07),
             source="tests/benchmarks/table.py", yardstick=startup)
    rows.add("startup.version", "start-up alone: `curdle --version`, whole process", version_ms, "ms",
             ("<", 0.07), source="tests/benchmarks/table.py", yardstick=startup)
    seeds = ours["BM_SeedSearch_64x64"]["seeds_per_s"]
    rows.add("search", "seed search: 64 × 64 curds (b = 4; 2/3, 1/2, 1/3) generated and scored, seeds/s",
             seeds, "seeds/s", (">=", 100), better="higher", peer=peer.get("search"),
             source=f"`BM_SeedSearch_64x64`, {src}", against_peer=True)
    rows.add("field.2048", "the page's field, `/api/field` of 2048 × 2048 cells, server alone",
             bench_ms(ours["BM_Serve_Field/2048"]), "ms", ("<", 0.07), source=f"`BM_Serve_Field`, {src}",
             yardstick=in_process)
    glb = ours["BM_Screen_LayoutGlb"]
    rows.add("screen.glb", f"the shipped screen's layout.glb ({glb['glb_bytes'] / 1e6:.1f} MB), recipe to bytes in process",
             bench_ms(glb), "ms", ("<", 1), source=f"`BM_Screen_LayoutGlb`, {src}", yardstick=in_process)
    rows.add("survey", "a surveyor's DXF of 10,003 entities read and laid, to schedule.csv, in process",
             bench_ms(ours["BM_Site_Survey_10000_entities"]), "ms", ("<", 3.3),
             source=f"`BM_Site_Survey_10000_entities`, {src}", yardstick=in_process)
    markov, overlay = bench_ms(ours["BM_Markov_Engine_4096/1"]), bench_ms(ours["BM_Markov_Engine_4096/0"])
    rows.add("markov", "a three-state Markov curd on 4096 × 4096 against two overlaid curds, engine (ratio)",
             markov / overlay, "×", ("<", 1.5), source=f"`BM_Markov_Engine_4096`, {src}")


def patterns_whole(build, rows, work):
    """Every shipped pattern and brief with every default output, best of three, each beside the
    best of the yardsticks measured just before it and its neighbours'; the slowest of each
    group, in yardsticks."""
    curdle = str(build / "curdle")
    times, sticks = {}, {}
    for recipe in sorted(ROOT.glob("patterns/**/*.toml")) + sorted(ROOT.glob("examples/briefs/*.toml")):
        name = recipe.relative_to(ROOT).as_posix()
        sticks[name] = yardstick_ms()
        times[name] = best_ms(
            [curdle, "generate", str(recipe), "--out", str(Path(work, "p", recipe.stem))], runs=3)
    # Each beside the best of the five yardsticks taken nearest it.
    order = list(sticks)
    taken = dict(sticks)
    for i, name in enumerate(order):
        sticks[name] = best_beside(*(taken[n] for n in order[max(0, i - 2):i + 3]))
    pattern_rows(rows, times, sticks)
    return times, sticks


def pattern_rows(rows, times, sticks):
    """The rows of the patterns' and briefs' whole runs (`times`, each beside `sticks`)."""
    # The pavilion's 23,000 bricks have a goal of their own (2.5 yardsticks); every other shipped
    # pattern, whole buildings among them, and every brief 2.
    pavilion = "patterns/pavilion-l-shaped.toml"
    shipped = {k: v for k, v in times.items() if k.startswith("patterns/") and k != pavilion}
    briefs = {k: v for k, v in times.items() if k.startswith("examples/")}
    rows.add("building.pavilion", "the L-shaped pavilion (23,180 bricks round six façades, two storeys "
             "of windows), `curdle generate` with every default output, whole", times[pavilion], "ms",
             ("<", 2.5), source="tests/benchmarks/table.py", yardstick=sticks[pavilion])
    for key, group, what in (("patterns.slowest", shipped, "the slowest shipped pattern but the pavilion"),
                             ("briefs.slowest", briefs, "the slowest brief")):
        name = max(group, key=lambda k: group[k] / sticks[k])
        rows.add(key, f"{what}, `curdle generate` with every default output, whole ({name})",
                 group[name], "ms", ("<", 2), source="tests/benchmarks/table.py", yardstick=sticks[name])


PAGE_ROUNDS = 20  # changes of each kind (at rest, reload under way) per size: a median of 10 moved by a fifth between runs minutes apart


def script_results(script, *args):
    """The JSON lines a benchmark script in tests/benchmarks prints, run between two
    yardsticks, and the yardstick beside it; says so when the script printed none."""
    before = yardstick_ms()
    out = subprocess.run(["bash", str(ROOT / "tests/benchmarks" / script), *map(str, args)],
                         capture_output=True, text=True).stdout
    beside = best_beside(before, yardstick_ms())
    results = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    if not results:
        print(f"{script} printed no result:", out, file=sys.stderr)
    return results, beside


def page(build, rows):
    results, beside = script_results("page_redraw.sh", build, PAGE_ROUNDS)
    # A frame's budget (16 ms at 60 Hz) as yardsticks of about 0.3 s: 0.05; 50 ms, 0.17.
    for r in results:
        goal = {"1024x1024": 0.05, "2048x2048": 0.17}.get(r["cells"])
        if goal:
            side = r["cells"].split("x")[0]
            rows.add(f"page.{side}", f"the page, a change to the curd's pixels drawn, {r['cells']} cells, the page "
                     f"at rest (headless Chromium over loopback, median of {PAGE_ROUNDS}; of it the server "
                     f"{r['server_ms_median']:.1f} ms; the same page asking for a 67 × 67 field "
                     f"alone on its socket, the floor of any change, {r['floor_ms_median']:.1f} ms)",
                     r["idle_ms_median"], "ms", ("<", goal), source="tests/benchmarks/page_redraw.sh",
                     yardstick=beside)
        if r["cells"] == "1024x1024":
            rows.add("page.reload", f"the same at 1024 × 1024 with the 3-D view's reload of the change before "
                     f"under way ({r['reload_in_flight']} of {PAGE_ROUNDS} changes found it on its way, at points "
                     f"spread over its {r['reload_ms_median']:.0f} ms course), median; p90 "
                     f"{r['redraw_ms_p90']:.0f} ms against {r['idle_ms_p90']:.0f} ms at rest",
                     r["redraw_ms_median"], "ms", ("<", 0.05), source="tests/benchmarks/page_redraw.sh",
                     yardstick=beside)


BUILDING_ROUNDS = 10  # changes of each kind on the pavilion's page


def building_page(build, rows):
    """The pavilion on the page (tests/benchmarks/page_building.sh): goals of 1 s, 100 ms and a
    frame (16 ms) as yardsticks of 0.3 s."""
    results, beside = script_results("page_building.sh", build, BUILDING_ROUNDS)
    if not results:
        return
    r = results[0]
    src = "tests/benchmarks/page_building.sh"
    rows.add("page.building", f"the page with the pavilion ({r['bricks']:,} elements), a change to its new model "
             f"drawn in the 3-D view, the page at rest (the 300 ms the page waits for the controls to rest "
             f"included; median of {BUILDING_ROUNDS}, slowest {r['change_ms_max']:.0f} ms)",
             r["change_ms_median"], "ms", ("<", 3.3), source=src, yardstick=beside)
    rows.add("page.building_click", f"the same, a click on the 3-D view answered, wherever it lands: the slowest of "
             f"{r['clicks']} over the view ({r['click_found']} on elements, {r['click_none']} on none, which the "
             f"page says; median {r['click_ms_median']:.1f} ms)",
             r["click_ms_max"], "ms", ("<", 0.33), source=src, yardstick=beside)
    rows.add("page.building_redraw", f"the same, a change's curd drawn while the 3-D view's reload is half its "
             f"{r['reload_course_ms']:.0f} ms course in, median ({r['rest_redraw_ms_median']:.1f} ms at rest)",
             r["redraw_ms_median"], "ms", ("<", 0.05), source=src, yardstick=beside)


def blender_import(build, rows):
    """Blender's own importer on the pavilion's layout.glb (tests/benchmarks/blender_import.sh):
    no goal, a reading of what a user of Blender waits."""
    results, beside = script_results("blender_import.sh", build)
    if not results:
        return
    r = results[0]
    rows.add("blender.pavilion", f"Blender 3.4's own glTF importer on the pavilion's layout.glb ({r['glb_mb']} MB, "
             f"{r['nodes']:,} nodes sharing {r['meshes']} meshes), the import alone ({r['process_s']:.1f} s and "
             f"{r['peak_mb']} MB the whole process; every element an object of its ID: {r['missing']} missing)",
             r["import_s"] * 1000, "ms", source="tests/benchmarks/blender_import.sh", yardstick=beside)


def judged(r, o):
    """What a row is judged by, here and in the committed row `o`: against the peer the ratio;
    else the yardsticks, where both have them; else the value. And whether higher is better."""
    if r.get("ratio") and o.get("ratio"):
        return r["ratio"], o["ratio"], True
    if r.get("yardsticks") and o.get("yardsticks"):
        return r["yardsticks"], o["yardsticks"], r["better"] == "higher"
    return r["value"], o["value"], r["better"] == "higher"


def compare(rows, previous):
    """Rows more than 20 % worse than the committed results."""
    old = {r["key"]: r for r in previous.get("rows", [])}
    worse = []
    for r in rows:
        o = old.get(r["key"])
        if not o:
            continue
        new_v, old_v, higher = judged(r, o)
        if (higher and new_v * WORSE < old_v) or (not higher and new_v > old_v * WORSE):
            worse.append(f"{r['key']}: {new_v:.4g} against {old_v:.4g} last committed")
    return worse


def agreement(rows, previous):
    """Each row judged by a ratio (to the peer, in yardsticks, or a ratio itself) beside the
    committed run's, and how far apart they are: the lines to print, and how many of how many
    agree within AGREE."""
    old = {r["key"]: r for r in previous.get("rows", [])}
    lines, agree, rated = [], 0, 0
    for r in rows:
        o = old.get(r["key"])
        if not o or not (r.get("ratio") or r.get("yardsticks") or r["unit"] == "×"):
            continue
        new_v, old_v, _ = judged(r, o)
        apart = new_v / old_v - 1
        rated += 1
        agree += abs(apart) <= AGREE
        lines.append(f"{r['key']:18} {new_v:10.4g} here {old_v:10.4g} committed {apart:+7.1%}"
                     f"{'' if abs(apart) <= AGREE else '  apart'}")
    return lines, agree, rated


def number(v, unit):
    if unit == "seeds/s":
        return f"{v / 1e6:.2f} M seeds/s" if v >= 1e5 else f"{v:,.0f} seeds/s"
    if unit == "ms" and v >= 1000:
        return f"{v / 1000:.2f} s"
    if unit == "×":
        return f"{v:.2f}×"
    if unit == "s":
        return f"{v:.0f} s"
    return f"{v:.1f} ms" if v < 100 else f"{v:.0f} ms"


def table(result):
    lines = [f"Measured {result['date']} on {result['machine']}, load {result['load_before']} before "
             f"and {result['load_after']} after (`tests/benchmarks/table.py`, which writes this table):", "",
             "Ratios are to the numpy peer (×) or, where there is none, to the yardstick measured "
             "beside the row (`tests/benchmarks/table.py`'s YARDSTICK: a single-core Python loop, "
             "whole process, the best of its runs around the row, as the row is the best of its "
             "own), in yardsticks (ys), with the yardstick's time.", "",
             "| case | peer (numpy) | curdle | ratio | goal | met |", "|---|---|---|---|---|---|"]
    for r in result["rows"]:
        peer = number(r["peer"], r["unit"]) if r.get("peer") else ""
        ratio = (f"{r['ratio']:.0f}×" if r.get("ratio") else
                 f"{r['yardsticks']:.3g} ys ({r['yardstick']:.0f} ms)" if r.get("yardsticks") else "")
        unit = ("×" if r.get("against_peer") or r["unit"] == "×" else " ys" if r.get("yardstick")
                else " " + r["unit"])
        goal = f"{r['goal'][0].replace('>=', '≥')} {r['goal'][1]:g}{unit}" if r.get("goal") else ""
        met = "" if r["ok"] is None else ("yes" if r["ok"] else "**no**")
        lines.append(f"| {r['what']} ({r['source']}) | {peer} | {number(r['value'], r['unit'])} | {ratio} | {goal} | {met} |")
    return "\n".join(lines)


def add_first_run(rows):
    """README command 1, measured apart: it builds a fresh clone (first_run.sh)."""
    first = ROOT / "tests/benchmarks/first_run.json"
    if first.exists():
        f = json.loads(first.read_text())
        rows.add("first_run", f"README command 1 in a fresh clone: set-up, build `curdle`, the first layout "
                 f"({f['date']}, load {f['load_before']}; packages already installed)",
                 f["seconds"], "s", ("<", 300), source="tests/benchmarks/first_run.sh")


def write_readme(result):
    text = (ROOT / "README.md").read_text()
    i, j = text.index(BEGIN) + len(BEGIN), text.index(END)
    (ROOT / "README.md").write_text(text[:i] + "\n" + table(result) + "\n" + text[j:])
    print("README.md: the benchmark table written")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=str(ROOT / "build/release"))
    ap.add_argument("--peer", default=str(ROOT.parent / "shared/bench"))
    ap.add_argument("--accept", action="store_true")
    ap.add_argument("--readme", action="store_true")
    ap.add_argument("--no-peer", action="store_true")
    ap.add_argument("--no-page", action="store_true")
    ap.add_argument("--agree", action="store_true")
    ap.add_argument("--from-results", action="store_true",
                    help="measure nothing: write the README's table from results.json (its "
                         "patterns' rows derived again from the times it keeps, and "
                         "first_run.json's row added or replaced)")
    a = ap.parse_args()
    if a.from_results:
        result = json.loads(RESULTS.read_text())
        rows = Rows()
        rows.rows = [r for r in result["rows"] if r["key"] != "first_run"]
        # The patterns' rows again from the times kept, under this file's grouping, in place.
        derived = Rows()
        pattern_rows(derived, result["patterns_ms"], result["patterns_yardstick_ms"])
        by_key = {r["key"]: r for r in derived.rows}
        rows.rows = [by_key.get(r["key"], r) for r in rows.rows]
        add_first_run(rows)
        result["rows"] = rows.rows
        RESULTS.write_text(json.dumps(result, indent=1, ensure_ascii=False) + "\n")
        write_readme(result)
        return
    build, peer = Path(a.build).resolve(), Path(a.peer)
    if not (build / "tests/curdle_bench").exists():
        sys.exit("build first: cmake --build --preset release")
    with_peer = not a.no_peer and (peer / "peer_numpy.py").exists()
    result = dict(date=datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
                  machine=machine(), load_before=load())
    rows = Rows()
    with tempfile.TemporaryDirectory() as work:
        engine_and_processes(build, peer, rows, with_peer, work)
        result["patterns_ms"], result["patterns_yardstick_ms"] = patterns_whole(build, rows, work)
    if not a.no_page and not a.agree:
        page(build, rows)
        building_page(build, rows)
        if shutil.which("blender"):
            blender_import(build, rows)
    add_first_run(rows)
    result["load_after"] = load()
    result["rows"] = rows.rows
    for r in rows.rows:
        met = "" if r["ok"] is None else ("ok" if r["ok"] else "NOT MET")
        ratio = (f"{r['ratio']:8.1f}x" if r.get("ratio") else
                 f"{r['yardsticks']:6.3g}ys" if r.get("yardsticks") else " " * 9)
        print(f"{r['key']:18} {number(r['value'], r['unit']):>16} {ratio} {met:8} {r['what']}")
    previous = json.loads(RESULTS.read_text()) if RESULTS.exists() else {}
    if a.agree:
        lines, agree, rated = agreement(rows.rows, previous)
        print(f"here: {result['machine']}, {result['date']}, load {result['load_before']} / "
              f"{result['load_after']}; committed: {previous.get('machine')}, {previous.get('date')}, "
              f"load {previous.get('load_before')} / {previous.get('load_after')}")
        print("\n".join(lines))
        print(f"{agree} of {rated} rows' ratios agree within {AGREE:.0%} of the committed run's")
        return
    worse = compare(rows.rows, previous)
    for w in worse:
        print("WORSE THAN COMMITTED (> 20 %):", w)
    if a.accept or not previous:
        RESULTS.write_text(json.dumps(result, indent=1, ensure_ascii=False) + "\n")
        print(f"kept as {RESULTS.relative_to(ROOT)}")
    if a.readme:
        write_readme(result)
    sys.exit(1 if worse and not a.accept else 0)


if __name__ == "__main__":
    main()
