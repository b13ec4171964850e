#!/usr/bin/env bash
# examples/blender_layout.py in Debian's Blender, headless, for a paving cut along an outline,
# a perforated screen, a stack of blocks and a brick façade; then every saved scene is checked
# against the program's schedule.csv (tests/blender/check_scene.py), and a massing model grouped
# under a parent exported (tests/blender/export_massing.py) for curdle to read by a child node's
# name, all in one Blender start (tests/blender/build_and_check.py).
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
CURDLE_MASSING_GLB="$tmp/massing.glb" \
blender -b --factory-startup --python-exit-code 1 --python "$src/tests/blender/build_and_check.py" -- \
  "$src/examples/blender_layout.py" "$src/tests/blender/check_scene.py" "${steps[@]}" \
  > "$tmp/blender.log" 2>&1 || { cat "$tmp/blender.log"; exit 1; }
grep -E "^(blender_layout|check_scene):" "$tmp/blender.log"

# The massing model Blender exported above, grouped under a parent: curdle reads the building's
# plan by the child node's name, and its height from the model.
cat > "$tmp/massing.toml" << 'TOML'
name = "massing"
seed = 1
[lattice]
base = 3
dimension = 2
mode = "canonical"
[[curds]]
name = "dark"
probabilities = ["3/4", "2/3"]
[layout]
kind = "facade"
panel = [215, 65]
joint = 10
[layout.building]
[layout.building.site]
file = "massing.glb"
plan = "Block A"
TOML
said=$("$curdle" generate "$tmp/massing.toml" --out "$tmp/massing" --outputs report.json)
echo "$said" | grep -q "plan: outline 20,000 x 12,000 mm from massing.glb, units m" ||
  { echo "the grouped model's child was not read as the plan: $said"; exit 1; }
python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1]))["layout"]["height_mm"] != 7050)' \
  "$tmp/massing/report.json" || { echo "the model's height (7,050 mm) is not the building's"; exit 1; }
echo "massing: Blender's grouped model read by its child node \"Block A\", 20 x 12 m, 7.05 m high"
