#!/usr/bin/env bash
# Generates every pattern's layout.glb (and one .gltf + .bin), validates them all with the
# Khronos glTF-Validator, and opens them in three.js in headless Chromium.
# Usage: CURDLE=path/to/curdle run.sh SOURCE_DIR SCREENSHOT_DIR
set -euo pipefail
src=${1:?source dir}
shots=${2:?screenshot dir}
curdle=${CURDLE:?path to curdle}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Every model is validated; the shipped patterns and the paper's figs. 3 and 5a (a tiling and a
# park) are also opened in the browser: the paper's other tilings draw the same way.
models=()
shown=()
while IFS= read -r recipe; do
  grep -q '^\[layout\]' "$recipe" || continue
  out="$work/$(basename "$recipe" .toml)"
  "$curdle" generate "$recipe" --out "$out" --outputs layout.glb > /dev/null
  models+=("$out/layout.glb")
  case "$recipe" in
    */paper/fig3-*|*/paper/fig5a-*) shown+=("$out/layout.glb") ;;
    */paper/*) ;;
    *) shown+=("$out/layout.glb") ;;
  esac
done < <(find "$src/patterns" -name '*.toml' | sort)
"$curdle" generate "$src/patterns/paper/fig3-two-curds.toml" --out "$work/as-gltf" --outputs layout.gltf > /dev/null
cd "$here"
node validate.mjs "${models[@]}" "$work/as-gltf/layout.gltf"
node render.mjs "$shots" "${shown[@]}"
echo "gltf: ${#models[@]} models valid, ${#shown[@]} rendered; screenshots in $shots"
