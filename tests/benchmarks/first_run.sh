#!/usr/bin/env bash
# README command 1 as a newcomer runs it: a fresh clone of this repository (with ../shared
# beside it), then the command exactly as the README gives it (set-up, configure, build
# `curdle`, the main job), timed whole; writes the seconds and the machine's load to
# tests/benchmarks/first_run.json, which tests/benchmarks/table.py puts in the table. The
# packages setup.sh installs are whatever this machine lacks: on a fresh machine, all of them.
# Usage: tests/benchmarks/first_run.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$root" "$work/clone"
[ -e "$root/../shared" ] && ln -s "$(cd "$root/../shared" && pwd)" "$work/shared"
command=$(grep -m1 '^    ./setup.sh --main' "$root/README.md" | sed 's/^    //')
[ -n "$command" ] || { echo "README command 1 not found" >&2; exit 2; }
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
echo "$command"
before=$(cut -d' ' -f1-3 /proc/loadavg)
start=$(date +%s%N)
(cd "$work/clone" && bash -c "$command") > "$work/log" 2>&1 || { tail -20 "$work/log"; exit 1; }
seconds=$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')
grep -q "outputs in" "$work/log" || { echo "the main job printed no outputs" >&2; exit 1; }
printf '{"seconds": %.1f, "load_before": "%s", "load_after": "%s", "cores": %d, "date": "%s"}\n' \
  "$seconds" "$before" "$(cut -d' ' -f1-3 /proc/loadavg)" "$(nproc)" "$(date -u '+%Y-%m-%d %H:%M UTC')" \
  | tee "$root/tests/benchmarks/first_run.json"
