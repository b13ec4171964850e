#!/usr/bin/env bash
# How long every shipped pattern's layout.ifc takes web-ifc and IFClite to open and mesh whole
# (the perforated screen's thousands of openings included), and the slowest; fails when one
# takes web-ifc more than 30 s. Usage: tests/benchmarks/ifc_readers.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
[ -x "$build/curdle" ] || { echo "build first: cmake --build --preset release" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dirs=()
while IFS= read -r recipe; do
  grep -q '^\[layout\]' "$recipe" || continue
  out="$work/$(basename "$recipe" .toml)"
  "$build/curdle" generate "$recipe" --out "$out" --outputs layout.ifc > /dev/null
  dirs+=("$out")
done < <(find "$root/patterns" -name '*.toml' | sort)
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
cd "$root/tests/js" && node ifc_timing.mjs --limit 30 "${dirs[@]}"
