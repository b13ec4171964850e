#!/usr/bin/env bash
# The page from a change to the pixels drawn, in headless Chromium over loopback
# (tests/js/page_redraw.mjs), on the fig. 8 pattern at 256 x 256, 1024 x 1024 and
# 2048 x 2048 cells (the largest the server draws): half the changes with the page at rest,
# half while the 3-D view's reload of the change before is under way. Goals: under 16 ms at
# 1024 x 1024 and under 50 ms at 2048 x 2048 (medians at rest), and under 16 ms at
# 1024 x 1024 with the reload under way. Prints one JSON line per size, then the verdicts.
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
    verdicts = [r["idle_ms_median"] < goal] + ([r["redraw_ms_median"] < goal] if r["cells"] == "1024x1024" else [])
    bad += not all(verdicts)
    print(f"{r['cells']}: change to pixels {r['idle_ms_median']:.1f} ms median at rest (p90 "
          f"{r['idle_ms_p90']:.1f}), {r['redraw_ms_median']:.1f} ms (p90 {r['redraw_ms_p90']:.1f}) with the "
          f"3-D view's reload under way ({r['reload_in_flight']} of {r['rounds']} found it on its way), "
          f"goal < {goal} ms: {'ok' if all(verdicts) else 'ABOVE'}; of it the server "
          f"{r['server_ms_median']:.1f} ms; the browser's floor, a 67 x 67 field asked for alone, "
          f"{r['floor_ms_median']:.1f} ms")
sys.exit(1 if bad else 0)
PY
