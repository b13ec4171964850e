#!/usr/bin/env bash
# Every piece of every shipped pattern, at every origin corner its kind takes, agrees across
# schedule.csv, layout.dxf, layout.glb, layout.svg, install.svg and the sheet DXFs
# (tests/consistency/pieces_agree.py; the suite checks each pattern at one or two corners and
# leaves out the pavilion). Prints the time it took; fails when any piece disagrees.
# Usage: tests/benchmarks/pieces_agree_all.sh [BUILD_DIR]
set -euo pipefail
source "$(dirname "$0")/prologue.sh"
mapfile -t recipes < <(grep -l '^\[layout\]' $(find "$root/patterns" -name '*.toml' | sort))
start=$(date +%s)
/usr/bin/python3 "$root/tests/consistency/pieces_agree.py" "$build/curdle" "$work" "${recipes[@]}" |
  { grep -v ' pieces checked$' || true; }
echo "pieces_agree_all: ${#recipes[@]} patterns at every corner agree, in $(( $(date +%s) - start )) s"
