#!/usr/bin/env bash
# layout.ifc read back by two independent readers, in steps ctest runs side by side:
#   write    writes the layout.ifc of the patterns ifc_suite_models.txt names, with its
#            schedule.csv, into MODELS (one of them twice: the bytes must agree); a pattern as
#            shipped is linked from CURDLE_PATTERN_OUTPUTS (the cli.pattern tests' outputs)
#            where that is set;
#   write-all  the same for every pattern (tests/benchmarks/ifc_readers.sh);
#   web-ifc  reads them back with web-ifc (ifc_check.mjs);
#   ifclite  reads them back with IFClite, checking every entity against the IFC4 schema
#            (ifc_lite_check.mjs).
# A reader's step may take a shard, K/N: every N-th model from the K-th, so that ctest runs the
# shards side by side.
# Usage: CURDLE=path/to/curdle ifc_run.sh SOURCE_DIR MODELS write|write-all|web-ifc|ifclite [K/N]
set -euo pipefail
src=${1:?source dir}
models=${2:?models dir}
step=${3:?write, web-ifc or ifclite}
shard=${4:-1/1}
here=$(cd "$(dirname "$0")" && pwd)
# The models of this shard: the largest first, each to the shard that holds the fewest bytes
# so far, so that the shards take about as long (the pavilion alone is a third of them).
shard_models() {
  python3 - "$models" "${shard%/*}" "${shard#*/}" <<'PY'
import os, sys
models, k, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
dirs = sorted(os.path.join(models, d) for d in os.listdir(models))
size = lambda d: os.path.getsize(os.path.join(d, "layout.ifc"))
load, mine = [0] * n, []
for d in sorted(dirs, key=lambda d: (-size(d), d)):
    s = load.index(min(load))
    load[s] += size(d)
    if s == k - 1:
        mine.append(d)
print("\n".join(sorted(mine)))
PY
}
case $step in
  write | write-all)
    curdle=${CURDLE:?path to curdle}
    rm -rf "$models" && mkdir -p "$models"
    # A line of ifc_suite_models.txt: a pattern, then any options its run takes (--set ...).
    if [ "$step" = write ]; then
      mapfile -t lines < <(sed 's/#.*//; /^ *$/d; s| *$||' "$here/ifc_suite_models.txt")
    else
      mapfile -t lines < <(cd "$src/patterns" && find . -name '*.toml' | sort | sed 's|^\./||; s|\.toml$||')
    fi
    for line in "${lines[@]}"; do
      read -r -a words <<< "$line"
      recipe=$src/patterns/${words[0]}.toml
      [ -f "$recipe" ] || { echo "ifc_run.sh: no pattern $recipe" >&2; exit 2; }
      grep -q '^\[layout\]' "$recipe" || continue
      name=$(basename "$recipe" .toml)
      # A pattern as shipped: the outputs its cli.pattern test wrote, where ctest keeps them.
      written=${CURDLE_PATTERN_OUTPUTS:-}/$name
      if [ "$step" = write ] && [ ${#words[@]} -eq 1 ] && [ -n "${CURDLE_PATTERN_OUTPUTS:-}" ] \
         && [ -s "$written/layout.ifc" ]; then
        ln -s "$written" "$models/$name"
        continue
      fi
      "$curdle" generate "$recipe" "${words[@]:1}" --out "$models/$name" \
        --outputs layout.ifc,schedule.csv,layout.gpkg,report.json > /dev/null
    done
    again=$(mktemp -d)
    trap 'rm -rf "$again"' EXIT
    "$curdle" generate "$src/patterns/courtyard-l-shaped.toml" --out "$again" --outputs layout.ifc > /dev/null
    cmp "$models/courtyard-l-shaped/layout.ifc" "$again/layout.ifc"
    echo "ifc: $(ls "$models" | wc -l) models written, the same bytes twice" ;;
  web-ifc) mapfile -t dirs < <(shard_models) && cd "$here" && node ifc_check.mjs "${dirs[@]}" ;;
  ifclite) mapfile -t dirs < <(shard_models) && cd "$here" && node ifc_lite_check.mjs "${dirs[@]}" ;;
  *) echo "ifc_run.sh: unknown step '$step' (write, write-all, web-ifc or ifclite)" >&2; exit 2 ;;
esac
