#!/usr/bin/env bash
# Every example command of the README runs as written: each indented line that starts with
# build/release/curdle is run from a folder laid out as the source is (patterns/ and examples/
# beside build/release/curdle), must exit 0, and must write every output it names.
# (The README's two set-up commands are what .ci/run runs.)
#
# Usage: readme_examples.sh SOURCE_DIR CURDLE
set -euo pipefail
source_dir=$(realpath "$1")
curdle=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$source_dir/patterns" "$work/patterns"
ln -s "$source_dir/examples" "$work/examples"
mkdir -p "$work/build/release"
ln -s "$curdle" "$work/build/release/curdle"

mapfile -t commands < <(grep -E '^    build/release/curdle ' "$source_dir/README.md" | sed 's/^    //')
[ "${#commands[@]}" -ge 5 ] || { echo "the README has ${#commands[@]} example commands, not 5"; exit 1; }
failed=0
for command in "${commands[@]}"; do
  if ! (cd "$work" && bash -c "$command" >"$work/out.txt" 2>&1); then
    echo "FAIL (exit): $command"; cat "$work/out.txt"; failed=$((failed + 1)); continue
  fi
  recipe=$(echo "$command" | awk '{print $3}')
  outputs=$(echo "$command" | sed -n 's/.*--outputs \([^ ]*\).*/\1/p')
  for output in ${outputs//,/ }; do
    if [ ! -e "$work/curdle-out/$(basename "$recipe" .toml)/$output" ]; then
      echo "FAIL (no $output): $command"; failed=$((failed + 1))
    fi
  done
  echo "ran: $command"
done
echo "${#commands[@]} README examples, $failed failures"
[ "$failed" -eq 0 ]
