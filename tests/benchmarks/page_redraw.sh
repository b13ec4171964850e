#!/usr/bin/env bash
# The page from a change to the pixels drawn, in headless Chromium over loopback
# (tests/js/page_redraw.mjs), on the fig. 8 pattern at 256 x 256, 1024 x 1024 and
# 2048 x 2048 cells (the largest the server draws). Goals: under 16 ms at 1024 x 1024 and
# under 50 ms at 2048 x 2048 (medians). Prints one JSON line per size, then the verdicts.
# Usage: tests/benchmarks/page_redraw.sh [BUILD_DIR] [ROUNDS]
set -euo pipefail
source "$(dirname "$0")/prologue.sh"
rounds=${2:-15}
recipes=()
for side in 256 1024 2048; do
  sed "s/^cells = .*/cells = [$side, $side]/" "$root/patterns/paper/fig8-segment-of-large-curd.toml" \
    > "$work/field-$side.toml"
  recipes+=("$work/field-$side.toml")
done
cd "$root/tests/js"
node page_redraw.mjs "$build/curdle" "$rounds" "${recipes[@]}" | tee "$work/lines"
/usr/bin/python3 - "$work/lines" <<'PY'
import json, sys
goals = {"1024x1024": 16, "2048x2048": 50}
bad = 0
for line in open(sys.argv[1]):
    r = json.loads(line)
    goal = goals.get(r["cells"])
    if goal is None:
        continue
    ok = r["redraw_ms_median"] < goal
    bad += not ok
    print(f"{r['cells']}: change to pixels {r['redraw_ms_median']:.1f} ms median "
          f"(p90 {r['redraw_ms_p90']:.1f}), goal < {goal} ms: {'ok' if ok else 'ABOVE'}; "
          f"of it the server {r['server_ms_median']:.1f} ms; the browser's floor, a 67 x 67 field "
          f"asked for alone, {r['floor_ms_median']:.1f} ms")
sys.exit(1 if bad else 0)
PY
