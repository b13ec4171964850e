#!/usr/bin/env bash
# examples/blender_layout.py in Debian's Blender, headless, for a paving cut along an outline,
# a perforated screen, a stack of blocks and a brick façade; then every saved scene is checked
# against the program's schedule.csv (tests/blender/check_scene.py), all in one Blender start
# (tests/blender/build_and_check.py).
# Usage: blender_test.sh CURDLE SOURCE_DIR PYTHONPATH
set -euo pipefail
curdle=$1 src=$2
export CURDLE_PYTHONPATH=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
steps=()
for pattern in patterns/courtyard-l-shaped.toml patterns/paper/fig4-perforation.toml \
               patterns/stacked-blocks.toml patterns/brick-facade-stretcher-bond.toml; do
  name=$(basename "$pattern" .toml)
  "$curdle" generate "$src/$pattern" --seed 5 --out "$tmp/$name" --outputs schedule.csv > /dev/null
  steps+=("$src/$pattern" 5 "$tmp/$name.blend" "$tmp/$name/schedule.csv")
done
# --python-exit-code: a step that raises fails the test (Blender exits 0 after a script's
# uncaught exception otherwise).
blender -b --factory-startup --python-exit-code 1 --python "$src/tests/blender/build_and_check.py" -- \
  "$src/examples/blender_layout.py" "$src/tests/blender/check_scene.py" "${steps[@]}" \
  > "$tmp/blender.log" 2>&1 || { cat "$tmp/blender.log"; exit 1; }
grep -E "^(blender_layout|check_scene):" "$tmp/blender.log"
