#!/usr/bin/env bash
# Runs the engine benchmarks and the numpy peer (../shared/bench) in one run on this machine
# and prints the speed ratios the issue asks for. Absolute times on a shared machine are noise;
# the ratios are the result. Usage: tests/benchmarks/compare_with_peer.sh [BUILD_DIR] [PEER_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
peer=${2:-$root/../shared/bench}
py=/usr/bin/python3
[ -x "$build/tests/curdle_bench" ] || { echo "build first: cmake --build --preset release" >&2; exit 2; }
[ -f "$peer/peer_numpy.py" ] || { echo "peer not found in $peer" >&2; exit 2; }

# curdle first: after the peer's 6 GiB cube the kernel is still reclaiming memory, which slows
# whatever runs next by up to half again.
# A surveyor's site drawing of 10,003 entities (patterns/sites/make_sites.py --survey).
survey=$(mktemp -d)
$py "$root/patterns/sites/make_sites.py" "$survey" --survey
echo "curdle: the three cases, the page's requests, the schedule, the survey ..."
ours=$(CURDLE_SURVEY_DIR=$survey /usr/bin/time -f '%M' -o /tmp/curdle-bench-rss "$build/tests/curdle_bench" --benchmark_format=json 2>/dev/null)
p07=$(printf '0.7,%.0s' {1..14}); p07=${p07%,}
p08=$(printf '0.8,%.0s' {1..5}); p08=${p08%,}
# Whole processes, as a user runs them: curdle generate --outputs report.json on the same
# cases, start-up included (best of five), and `curdle --help`.
cases=$(mktemp -d)
trap 'rm -rf "$cases" "$survey"' EXIT
printf 'name = "plane"\n[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nname = "c"\nprobabilities = [%s]\n' "$p07" > "$cases/plane.toml"
printf 'name = "cube"\n[lattice]\nbase = 4\ndimension = 3\n[[curds]]\nname = "c"\nprobabilities = [%s]\n' "$p08" > "$cases/cube.toml"
whole() {  # best wall time of five runs, in ms
  $py -c 'import subprocess, sys, time
best = 1e9
for _ in range(5):
    t = time.perf_counter(); subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, check=True)
    best = min(best, time.perf_counter() - t)
print(best * 1e3)' "$@"
}
echo "curdle: whole processes ..."
help_ms=$(whole "$build/curdle" --help)
plane_ms=$(whole "$build/curdle" generate "$cases/plane.toml" --outputs report.json --out "$cases/out")
cube_ms=$(whole "$build/curdle" generate "$cases/cube.toml" --outputs report.json --out "$cases/out")
screen_ms=$(whole "$build/curdle" generate "$root/patterns/perforated-aluminium-screen.toml" --outputs layout.glb --out "$cases/out")
site_ms=$(whole "$build/curdle" generate "$survey/survey.toml" --outputs schedule.csv --out "$cases/out")
# A three-state Markov curd on 4096 x 4096 beside two overlaid curds of the same size (p = 3/4
# for the curds and for the chain's living set), generate --outputs report.json.
p34=$(printf '"3/4",%.0s' {1..12}); p34=${p34%,}
printf 'name = "markov"\n[lattice]\nbase = 2\ndimension = 2\nstages = 12\n[[curds]]\nname = "tone"\nstates = ["dark", "mid"]\nstart = "dark"\nstages = 12\ntransitions = [["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]\n' > "$cases/markov.toml"
printf 'name = "overlay"\n[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nname = "a"\nprobabilities = [%s]\n[[curds]]\nname = "b"\nprobabilities = [%s]\n' "$p34" "$p34" > "$cases/overlay.toml"
markov_ms=$(whole "$build/curdle" generate "$cases/markov.toml" --outputs report.json --out "$cases/out")
overlay_ms=$(whole "$build/curdle" generate "$cases/overlay.toml" --outputs report.json --out "$cases/out")
echo "peer: plane b=2 E=2 K=14 p=0.7 (2^28 cells) ..."
plane_start=$(date +%s%N)
plane=$($py "$peer/peer_numpy.py" 2 2 "$p07" 1 1)
plane_peer_ms=$(( ($(date +%s%N) - plane_start) / 1000000 ))
echo "peer: cube b=4 E=3 K=5 p=0.8 (2^30 cells) ..."
cube_start=$(date +%s%N)
cube=$(/usr/bin/time -f '%M' -o /tmp/curdle-peer-cube-rss $py "$peer/peer_numpy.py" 4 3 "$p08" 1 1)
cube_peer_ms=$(( ($(date +%s%N) - cube_start) / 1000000 ))
echo "peer: seed search 64 x 64, b=4, 2/3 1/2 1/3 ..."
search=$($py "$peer/peer_numpy_search.py" 4 2/3,1/2,1/3 3000 0.111 1.5)

MARKOV_MS=$markov_ms OVERLAY_MS=$overlay_ms HELP_MS=$help_ms SCREEN_MS=$screen_ms SITE_MS=$site_ms PLANE_MS=$plane_ms CUBE_MS=$cube_ms PLANE_PEER_MS=$plane_peer_ms \
CUBE_PEER_MS=$cube_peer_ms PLANE="$plane" CUBE="$cube" SEARCH="$search" OURS="$ours" \
PEER_RSS=$(cat /tmp/curdle-peer-cube-rss) OUR_RSS=$(cat /tmp/curdle-bench-rss) $py - <<'PY'
import json, os
plane, cube, search = (json.loads(os.environ[k]) for k in ("PLANE", "CUBE", "SEARCH"))
ours = {}
for b in json.loads(os.environ["OURS"])["benchmarks"]:
    ours.setdefault(b["name"].split("/")[0], b)   # the first of a family by its family's name
    ours["/".join(b["name"].split("/")[:2])] = b  # and each by name and argument
def ms(b): return b["real_time"] * {"ms": 1, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
rows = [
  ("plane 2^28 cells, generate + report", (plane["generate_s"] + plane["boxcount_s"]) * 1e3,
   ms(ours["BM_Plane_b2_K14_p07"]), 300, "ms"),
  ("cube 2^30 cells, generate + report", (cube["generate_s"] + cube["boxcount_s"]) * 1e3,
   ms(ours["BM_Cube_b4_K5_p08"]), 50, "ms"),
]
print(f"\n{'case':40} {'peer':>12} {'curdle':>12} {'ratio':>9} {'target':>8}")
for name, peer, mine, target, unit in rows:
  r = peer / mine
  print(f"{name:40} {peer:10.1f}{unit} {mine:10.1f}{unit} {r:8.0f}x {target:>7}x {'ok' if r >= target else 'BELOW'}")
print("\nwhole processes (start-up included; curdle best of five, peer once):")
for name, peer_ms, mine_ms, target in (
    ("plane, generate --outputs report.json", float(os.environ["PLANE_PEER_MS"]), float(os.environ["PLANE_MS"]), 300),
    ("cube, generate --outputs report.json", float(os.environ["CUBE_PEER_MS"]), float(os.environ["CUBE_MS"]), 50)):
  r = peer_ms / mine_ms
  print(f"{name:40} {peer_ms:10.1f}ms {mine_ms:10.1f}ms {r:8.0f}x {target:>7}x {'ok' if r >= target else 'BELOW'}")
help_ms = float(os.environ["HELP_MS"])
print(f"{'curdle --help':40} {'':>12} {help_ms:10.1f}ms {'':>9} {'< 20 ms':>8} {'ok' if help_ms < 20 else 'ABOVE'}\n")
s_peer = search["seeds_per_s"]; s_ours = ours["BM_SeedSearch_64x64"]["seeds_per_s"]
r = s_ours / s_peer
print(f"{'seed search 64x64, seeds per second':40} {s_peer:12.0f} {s_ours:12.0f} {r:8.0f}x {100:>7}x {'ok' if r >= 100 else 'BELOW'}")
serve = ms(ours["BM_Serve_Generate_256x256"])
print(f"{'page: regenerate 256x256 (server time)':40} {'':>12} {serve:10.2f}ms {'':>9} {'< 50 ms':>8} {'ok' if serve < 50 else 'ABOVE'}")
print(f"{'page: segment report 67x67':40} {'':>12} {ms(ours['BM_Serve_Segment_67x67']):10.2f}ms")
print(f"{'(layout.svg of 256x256 tiles, not used to redraw)':40} {'':>12} {ms(ours['BM_Serve_LayoutSvg_256x256']):10.1f}ms {ours['BM_Serve_LayoutSvg_256x256']['svg_bytes'] / 1e6:8.1f} MB")
glb, screen = ms(ours["BM_Screen_LayoutGlb"]), float(os.environ["SCREEN_MS"])
print(f"{'screen layout.glb, recipe to bytes':40} {'':>12} {glb:10.1f}ms {'':>9} {'< 300 ms':>8} {'ok' if glb < 300 else 'ABOVE'} {ours['BM_Screen_LayoutGlb']['glb_bytes'] / 1e6:.1f} MB")
print(f"{'screen, generate --outputs layout.glb':40} {'':>12} {screen:10.1f}ms {'':>9} {'< 300 ms':>8} {'ok' if screen < 300 else 'ABOVE'}")
site, site_whole = ms(ours["BM_Site_Survey_10000_entities"]), float(os.environ["SITE_MS"])
print(f"{'survey DXF, 10,003 entities, to schedule':40} {'':>12} {site:10.1f}ms {'':>9} {'< 1000 ms':>8} {'ok' if site < 1000 else 'ABOVE'}")
print(f"{'survey, generate --outputs schedule.csv':40} {'':>12} {site_whole:10.1f}ms {'':>9} {'< 1000 ms':>8} {'ok' if site_whole < 1000 else 'ABOVE'}")
markov, overlay = (ms(ours["BM_Markov_Engine_4096/" + a]) for a in ("1", "0"))
print(f"{'Markov 3 states vs 2 curds, 4096^2, engine':40} {overlay:12.1f}ms {markov:10.1f}ms {markov / overlay:8.2f}x {'< 1.5x':>8} {'ok' if markov < 1.5 * overlay else 'ABOVE'}")
mw, ow = float(os.environ["MARKOV_MS"]), float(os.environ["OVERLAY_MS"])
print(f"{'Markov vs overlay, generate report.json':40} {ow:12.1f}ms {mw:10.1f}ms {mw / ow:8.2f}x {'< 1.5x':>8} {'ok' if mw < 1.5 * ow else 'ABOVE'}")
print(f"\npeak memory: peer cube {int(os.environ['PEER_RSS'])/1024:.0f} MiB; "
      f"curdle benchmark process {int(os.environ['OUR_RSS'])/1024:.0f} MiB")
PY
