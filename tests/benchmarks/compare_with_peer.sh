#!/usr/bin/env bash
# The benchmarks beside the numpy peer (../shared/bench) in one run: start-up alone, the engine
# alone and whole processes, each against the peer where it has one, and the rest of the table
# (tests/benchmarks/table.py, which compares each row with the committed results).
# Usage: tests/benchmarks/compare_with_peer.sh [BUILD_DIR] [PEER_DIR] [table.py options]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
peer=${2:-$root/../shared/bench}
shift $(( $# < 2 ? $# : 2 ))
exec /usr/bin/python3 "$root/tests/benchmarks/table.py" --build "$build" --peer "$peer" "$@"
