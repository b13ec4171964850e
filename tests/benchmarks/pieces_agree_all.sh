#!/usr/bin/env bash
# Every piece of every shipped pattern, at every origin corner its kind takes, agrees across
# schedule.csv, layout.dxf, layout.glb, layout.svg, install.svg and the sheet DXFs
# (tests/consistency/pieces_agree.py; the suite checks each pattern at one or two corners and
# leaves out the pavilion). Prints the time it took; fails when any piece disagrees.
# Usage: tests/benchmarks/pieces_agree_all.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
[ -x "$build/curdle" ] || { echo "build first: cmake --build --preset release" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
mapfile -t recipes < <(grep -l '^\[layout\]' $(find "$root/patterns" -name '*.toml' | sort))
start=$(date +%s)
/usr/bin/python3 "$root/tests/consistency/pieces_agree.py" "$build/curdle" "$work" "${recipes[@]}" |
  { grep -v ' pieces checked$' || true; }
echo "pieces_agree_all: ${#recipes[@]} patterns at every corner agree, in $(( $(date +%s) - start )) s"
