#!/usr/bin/env bash
# Writes every pattern's layout.ifc with its schedule.csv, twice for one of them (the bytes
# must agree), and reads them all back with web-ifc (ifc_check.mjs).
# Usage: CURDLE=path/to/curdle ifc_run.sh SOURCE_DIR
set -euo pipefail
src=${1:?source dir}
curdle=${CURDLE:?path to curdle}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dirs=()
while IFS= read -r recipe; do
  grep -q '^\[layout\]' "$recipe" || continue
  out="$work/$(basename "$recipe" .toml)"
  "$curdle" generate "$recipe" --out "$out" --outputs layout.ifc,schedule.csv > /dev/null
  dirs+=("$out")
done < <(find "$src/patterns" -name '*.toml' | sort)
"$curdle" generate "$src/patterns/courtyard-l-shaped.toml" --out "$work/again" --outputs layout.ifc > /dev/null
cmp "$work/courtyard-l-shaped/layout.ifc" "$work/again/layout.ifc"
cd "$here"
node ifc_check.mjs "${dirs[@]}"
echo "ifc: ${#dirs[@]} models read back by web-ifc"
