#!/usr/bin/env bash
# What a clean build costs, in CPU-seconds per target and per unit: configures a fresh build
# tree whose compiler runs under /usr/bin/time, builds what README command 1 builds (`curdle`),
# then everything, and prints the sum per target (its CMakeFiles/<target>.dir) and the ten
# dearest units, with the machine's load. Usage: tests/benchmarks/build_cost.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$(mktemp -d)}
log=$build/compile-times.log
mkdir -p "$build"
: > "$log"
launcher=$build/timed-compile.sh
cat > "$launcher" <<LAUNCH
#!/usr/bin/env bash
# Runs one compile and appends "user+sys seconds, object file" to the log.
out=""; prev=""
for a in "\$@"; do [ "\$prev" = "-o" ] && out=\$a; prev=\$a; done
exec /usr/bin/time -a -o "$log" -f "%U %S \$out" "\$@"
LAUNCH
chmod +x "$launcher"
echo "load: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" > /dev/null
summary() {
  python3 - "$log" "$1" <<'PY'
import collections, re, sys
per_target, per_unit = collections.Counter(), {}
for line in open(sys.argv[1]):
    user, system, obj = line.split(maxsplit=2)
    seconds = float(user) + float(system)
    obj = obj.strip()
    target = re.search(r"CMakeFiles/([^/]+)\.dir/", obj)
    per_target[target.group(1) if target else "?"] += seconds
    per_unit[obj] = seconds
total = sum(per_target.values())
print(f"{sys.argv[2]}: {total:.0f} CPU-seconds of compiling in {len(per_unit)} units")
for target, seconds in per_target.most_common():
    print(f"  {target:28} {seconds:7.1f} s")
print("  dearest units:")
for obj, seconds in sorted(per_unit.items(), key=lambda kv: -kv[1])[:10]:
    print(f"    {seconds:6.1f} s  {re.sub(r'.*CMakeFiles/', '', obj)}")
PY
}
start=$(date +%s)
cmake --build "$build" -j2 --target curdle > /dev/null
echo "curdle alone: $(( $(date +%s) - start )) s wall"
summary "README command 1 (--target curdle)"
start=$(date +%s)
cmake --build "$build" -j2 > /dev/null
echo "the rest: $(( $(date +%s) - start )) s wall"
summary "everything"
