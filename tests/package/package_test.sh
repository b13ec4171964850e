#!/usr/bin/env bash
# The installed package as its users meet it: `cmake --install` into a temporary prefix; a
# consumer project configured with find_package(curdle REQUIRED), built and run, its files equal
# to the installed program's; the Python module imported from the prefix's site-packages, and
# the image module found beside the installed library.
# Usage: package_test.sh BUILD_DIR SOURCE_DIR PYTHON
set -euo pipefail
build=$1 src=$2 python=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" > "$tmp/install.log"
for f in lib/cmake/curdle/curdleConfig.cmake lib/cmake/curdle/curdleConfigVersion.cmake \
         lib/cmake/curdle/curdleTargets.cmake include/curdle/app/generated_run.h \
         include/curdle/curdle/report.h bin/curdle share/doc/curdle/LICENSE \
         share/doc/curdle/THIRD-PARTY-NOTICES; do
  [ -e "$prefix/$f" ] || fail "the install has no $f"
done
ls "$prefix"/lib/libcurdle.so.* > /dev/null || fail "no versioned libcurdle.so"
# The package names no path of the build or the source tree.
if grep -rl -e "$build" -e "$src" "$prefix/lib/cmake/curdle"; then fail "build paths in the package"; fi

# The manual's C++ example is the consumer's: docs/library.md's cpp block, as its text stands
# (layout aside: clang-format may break its lines elsewhere).
"$python" - "$src/docs/library.md" "$src/tests/package/consumer/main.cpp" <<'PY' || fail "docs/library.md's C++ example is not the consumer's"
import sys
doc, code = (open(p, encoding="utf-8").read() for p in sys.argv[1:])
block = doc.split("```cpp\n", 1)[1].split("```", 1)[0]
sys.exit(0 if "".join(block.split()) in "".join(code.split()) else "not in the consumer: " + block)
PY
cmake -S "$src/tests/package/consumer" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" > "$tmp/configure.log" || { cat "$tmp/configure.log"; fail "configure"; }
cmake --build "$tmp/consumer" -j2 > "$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; fail "build"; }
recipe=$src/patterns/courtyard-l-shaped.toml
"$tmp/consumer/consumer" "$recipe" 7 "$tmp/library-out" | tee "$tmp/consumer.out"
grep -q "courtyard-l-shaped, seed 7, [0-9]* elements" "$tmp/consumer.out" || fail "consumer's output"
"$prefix/bin/curdle" generate "$recipe" --seed 7 --out "$tmp/program-out" \
  --outputs layout.svg,schedule.csv > /dev/null
for f in layout.svg schedule.csv; do
  cmp "$tmp/library-out/$f" "$tmp/program-out/$f" || fail "$f differs from the program's"
done

site=$(echo "$prefix"/lib/python3*/site-packages)
PYTHONPATH=$site "$python" - "$prefix" "$recipe" "$tmp/python-out" <<'PY'
import struct, sys, curdle
prefix, recipe, out = sys.argv[1:]
assert curdle.__file__.startswith(prefix), curdle.__file__
run = curdle.generate(recipe, seed=7)
run.write(["preview.png"], out=out)
curdle.measure(out + "/preview.png")  # a PNG, read in process
# A BMP goes through the image module, which must be found in the installed tree.
rows = bytes([0, 0, 0, 255, 255, 255, 0, 0]) * 2
head = struct.pack("<2sIHHI", b"BM", 54 + len(rows), 0, 0, 54)
info = struct.pack("<IiiHHIIiiII", 40, 2, 2, 1, 24, 0, len(rows), 2835, 2835, 0, 0)
open(out + "/picture.bmp", "wb").write(head + info + rows)
curdle.measure(out + "/picture.bmp")
loaded = [l.split()[-1] for l in open("/proc/self/maps") if "curdle" in l and ".so" in l]
libs = sorted(set(loaded))
assert any(l.startswith(prefix + "/lib/libcurdle.so") for l in libs), libs
assert any(l.startswith(prefix + "/lib/curdle/") for l in libs), libs  # the image module
print("python: curdle", curdle.__version__, "from", curdle.__file__)
PY
# One version: the program's, the module's and the package's are the project's.
version=$(sed -n 's/^project(curdle VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
"$prefix/bin/curdle" --version | grep -q "^curdle $version " || fail "curdle --version is not $version"
PYTHONPATH=$site "$python" -c "import curdle, sys; sys.exit(curdle.__version__ != '$version')" ||
  fail "curdle.__version__ is not $version"
echo "package: installed, consumed by CMake and Python"
