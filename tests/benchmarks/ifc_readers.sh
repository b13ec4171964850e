#!/usr/bin/env bash
# Every shipped pattern's layout.ifc read back by web-ifc and IFClite with the suite's checks
# (tests/js/ifc_run.sh; the suite itself reads one pattern for each kind of element), then how
# long each reader takes to open and mesh each model whole (the perforated screen's thousands of
# openings included), and the slowest; fails when a check fails or a model takes web-ifc more
# than 30 s. Usage: tests/benchmarks/ifc_readers.sh [BUILD_DIR]
set -euo pipefail
source "$(dirname "$0")/prologue.sh"
run="$root/tests/js/ifc_run.sh"
CURDLE="$build/curdle" bash "$run" "$root" "$work" write-all
# Each reader's problems and its summary, not the line of every model that agrees.
bash "$run" "$root" "$work" web-ifc | { grep -v ' agree ' || true; }
bash "$run" "$root" "$work" ifclite | { grep -v ' agree ' || true; }
echo "every pattern's layout.ifc read back by both readers"
mapfile -t dirs < <(find "$work" -mindepth 1 -maxdepth 1 -type d | sort)
cd "$root/tests/js" && node ifc_timing.mjs --limit 30 "${dirs[@]}"
