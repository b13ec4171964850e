# What every benchmark script begins with (sourced, after `set -euo pipefail`): root, the source
# tree; build, the build tree given as the first argument (build/release without one), which
# must hold curdle; work, a directory removed on exit; and the machine's load, printed.
root=$(cd "$(dirname "${BASH_SOURCE[1]}")/../.." && pwd)
build=$(cd "${1:-$root/build/release}" 2> /dev/null && pwd) || build=${1:-$root/build/release}
[ -x "$build/curdle" ] || { echo "build first: cmake --build --preset release" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
