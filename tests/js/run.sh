#!/usr/bin/env bash
# Generates every pattern's layout.glb (and one .gltf + .bin), validates them all with the
# Khronos glTF-Validator, and opens them in three.js in headless Chromium. With
# CURDLE_PATTERN_OUTPUTS set (ctest), the cli.pattern tests' layout.glb are read instead.
# Usage: CURDLE=path/to/curdle run.sh SOURCE_DIR SCREENSHOT_DIR
set -euo pipefail
src=${1:?source dir}
shots=${2:?screenshot dir}
curdle=${CURDLE:?path to curdle}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Every model is validated; four whose geometry differs most are also opened in the browser (a
# floor with its bed, an upright wall with openings, a perforated sheet, voxels): each costs a
# software render.
models=()
shown=()
while IFS= read -r recipe; do
  grep -q '^\[layout\]' "$recipe" || continue
  out="$work/$(basename "$recipe" .toml)"
  # The layout.glb its cli.pattern test wrote, where ctest keeps them, else made here.
  written=${CURDLE_PATTERN_OUTPUTS:-}/$(basename "$recipe" .toml)
  if [ -n "${CURDLE_PATTERN_OUTPUTS:-}" ] && [ -s "$written/layout.glb" ]; then
    out=$written
  else
    "$curdle" generate "$recipe" --out "$out" --outputs layout.glb > /dev/null
  fi
  models+=("$out/layout.glb")
  case "$recipe" in
    */brick-facade-five-*|*/perforated-aluminium-*|*/stacked-blocks*|*/courtyard-l-shaped*)
      shown+=("$out/layout.glb") ;;
  esac
done < <(find "$src/patterns" -name '*.toml' | sort)
"$curdle" generate "$src/patterns/paper/fig3-two-curds.toml" --out "$work/as-gltf" --outputs layout.gltf > /dev/null
cd "$here"
node validate.mjs "${models[@]}" "$work/as-gltf/layout.gltf"
node render.mjs "$shots" "${shown[@]}"
echo "gltf: ${#models[@]} models valid, ${#shown[@]} rendered; screenshots in $shots"
