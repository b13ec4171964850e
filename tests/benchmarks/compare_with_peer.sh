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
echo "curdle: the three cases, the page's requests, the schedule ..."
ours=$(/usr/bin/time -f '%M' -o /tmp/curdle-bench-rss "$build/tests/curdle_bench" --benchmark_format=json 2>/dev/null)
p07=$(printf '0.7,%.0s' {1..14}); p07=${p07%,}
p08=$(printf '0.8,%.0s' {1..5}); p08=${p08%,}
echo "peer: plane b=2 E=2 K=14 p=0.7 (2^28 cells) ..."
plane=$($py "$peer/peer_numpy.py" 2 2 "$p07" 1 1)
echo "peer: cube b=4 E=3 K=5 p=0.8 (2^30 cells) ..."
cube=$(/usr/bin/time -f '%M' -o /tmp/curdle-peer-cube-rss $py "$peer/peer_numpy.py" 4 3 "$p08" 1 1)
echo "peer: seed search 64 x 64, b=4, 2/3 1/2 1/3 ..."
search=$($py "$peer/peer_numpy_search.py" 4 2/3,1/2,1/3 3000 0.111 1.5)

PLANE="$plane" CUBE="$cube" SEARCH="$search" OURS="$ours" \
PEER_RSS=$(cat /tmp/curdle-peer-cube-rss) OUR_RSS=$(cat /tmp/curdle-bench-rss) $py - <<'PY'
import json, os
plane, cube, search = (json.loads(os.environ[k]) for k in ("PLANE", "CUBE", "SEARCH"))
ours = {b["name"].split("/")[0]: b for b in json.loads(os.environ["OURS"])["benchmarks"]}
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
s_peer = search["seeds_per_s"]; s_ours = ours["BM_SeedSearch_64x64"]["seeds_per_s"]
r = s_ours / s_peer
print(f"{'seed search 64x64, seeds per second':40} {s_peer:12.0f} {s_ours:12.0f} {r:8.0f}x {100:>7}x {'ok' if r >= 100 else 'BELOW'}")
serve = ms(ours["BM_Serve_Generate_256x256"])
print(f"{'page: regenerate 256x256 (server time)':40} {'':>12} {serve:10.2f}ms {'':>9} {'< 50 ms':>8} {'ok' if serve < 50 else 'ABOVE'}")
print(f"{'page: segment report 67x67':40} {'':>12} {ms(ours['BM_Serve_Segment_67x67']):10.2f}ms")
print(f"{'(layout.svg of 256x256 tiles, not used to redraw)':40} {'':>12} {ms(ours['BM_Serve_LayoutSvg_256x256']):10.1f}ms")
print(f"\npeak memory: peer cube {int(os.environ['PEER_RSS'])/1024:.0f} MiB; "
      f"curdle benchmark process {int(os.environ['OUR_RSS'])/1024:.0f} MiB")
PY
