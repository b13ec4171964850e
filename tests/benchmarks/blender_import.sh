#!/usr/bin/env bash
# Blender's own glTF importer (Debian's Blender 3.4) on the pavilion's layout.glb (23,252
# elements): the import's time, the whole process's time and peak memory, and every element
# found as an object of its name. Fails when one is missing.
# Usage: tests/benchmarks/blender_import.sh [BUILD_DIR]
set -euo pipefail
source "$(dirname "$0")/prologue.sh"
command -v blender > /dev/null || { echo "no blender (setup.sh installs it)" >&2; exit 2; }
"$build/curdle" generate "$root/patterns/pavilion-l-shaped.toml" --out "$work/out" --outputs layout.glb > /dev/null
/usr/bin/time -f '{"process_s": %e, "peak_mb": %M}' -o "$work/time" \
  blender -b --factory-startup --python "$root/tests/benchmarks/blender_import.py" -- "$work/out/layout.glb" \
  > "$work/log" 2>&1 || { cat "$work/log" >&2; exit 1; }
line=$(grep '^{"import_s"' "$work/log") || { cat "$work/log" >&2; exit 1; }
/usr/bin/python3 - "$line" "$(cat "$work/time")" "$(stat -c %s "$work/out/layout.glb")" <<'PY'
import json, sys
r = json.loads(sys.argv[1])
t = json.loads(sys.argv[2])
r.update(process_s=t["process_s"], peak_mb=round(t["peak_mb"] / 1024), glb_mb=round(int(sys.argv[3]) / 2**20, 1))
print(json.dumps(r))
print(f"Blender imported {r['nodes']} nodes ({r['glb_mb']} MB) as {r['objects']} objects sharing {r['meshes']} meshes "
      f"in {r['import_s']:.1f} s ({r['process_s']:.1f} s and {r['peak_mb']} MB the whole process); "
      f"elements missing: {r['missing']}")
sys.exit(1 if r["missing"] else 0)
PY
