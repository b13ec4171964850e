#!/usr/bin/env bash
# examples/blender_layout.py in Debian's Blender, headless, for a paving cut along an outline,
# a perforated screen and a stack of blocks; then one Blender start checks every saved scene
# against the program's schedule.csv (tests/blender/check_scene.py).
# Usage: blender_test.sh CURDLE SOURCE_DIR PYTHONPATH
set -euo pipefail
curdle=$1 src=$2
export CURDLE_PYTHONPATH=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
checks=()
for pattern in patterns/courtyard-l-shaped.toml patterns/paper/fig4-perforation.toml \
               patterns/stacked-blocks.toml patterns/brick-facade-stretcher-bond.toml; do
  name=$(basename "$pattern" .toml)
  "$curdle" generate "$src/$pattern" --seed 5 --out "$tmp/$name" --outputs schedule.csv > /dev/null
  blender -b --factory-startup --python "$src/examples/blender_layout.py" -- "$src/$pattern" \
    --seed 5 --out "$tmp/$name.blend" > "$tmp/$name.log" 2>&1 || { cat "$tmp/$name.log"; exit 1; }
  grep "blender_layout:" "$tmp/$name.log"
  checks+=("$tmp/$name.blend" "$tmp/$name/schedule.csv")
done
blender -b --factory-startup --python "$src/tests/blender/check_scene.py" -- "${checks[@]}" \
  > "$tmp/check.log" 2>&1 || { cat "$tmp/check.log"; exit 1; }
grep "check_scene:" "$tmp/check.log"
