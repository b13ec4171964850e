#!/usr/bin/env bash
# The Python module as pip makes and installs it: `pip wheel` builds a wheel from this source
# tree (reusing BUILD_DIR, offline), pip installs it into a fresh virtual environment, and
# there the module imports, curdles, reads a picture (the image module beside libcurdle.so),
# writes a GeoPackage (the GDAL module), the `curdle` program runs, and mypy's stubtest finds
# the package's types (its annotations and _curdle.pyi) as the module has them at run time.
# Usage: wheel_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$(cd "${1:?source dir}" && pwd)
build=$(cd "${2:?build dir}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3
cd "$work"
$py -m pip wheel --quiet --no-build-isolation --no-deps --no-index -w "$work/dist" \
  --config-settings "build-dir=$build" "$src" > "$work/wheel.log" 2>&1 \
  || { cat "$work/wheel.log"; exit 1; }
wheel=$(ls "$work"/dist/curdle-*.whl)
# A venv without its own pip (Debian's installs into it), NumPy from Debian's site packages.
$py -m venv --without-pip --system-site-packages "$work/venv"
$py -m pip --python "$work/venv/bin/python" install --quiet --no-index --no-deps "$wheel"
"$work/venv/bin/curdle" --version | grep -q "^curdle $("$work/venv/bin/python" -c 'import curdle; print(curdle.__version__)')"
"$work/venv/bin/python" - "$src" <<'PY'
import struct
import sys
from pathlib import Path
import curdle
src = Path(sys.argv[1])
assert Path(curdle.__file__).is_relative_to(Path(sys.prefix)), curdle.__file__
run = curdle.generate(src / "patterns/paper/fig5a-park.toml")
Path("preview.png").write_bytes(run.output_bytes("preview.png"))
assert curdle.measure("preview.png")["size"], "a PNG, read in process"
# A BMP goes through the image module (OpenImageIO) beside libcurdle.so.
rows = bytes([0, 0, 0, 255, 255, 255, 0, 0]) * 2
head = struct.pack("<2sIHHI", b"BM", 54 + len(rows), 0, 0, 54)
info = struct.pack("<IiiHHIIiiII", 40, 2, 2, 1, 24, 0, len(rows), 2835, 2835, 0, 0)
Path("picture.bmp").write_bytes(head + info + rows)
assert curdle.measure("picture.bmp")["size"], "the image module"
assert run.output_bytes("layout.gpkg").startswith(b"SQLite format 3"), "the GeoPackage module"
print(f"wheel: {run!r} from {curdle.__file__}")
PY
cd "$work/venv/lib/python3"*/site-packages
"$work/venv/bin/python" -m mypy.stubtest curdle --allowlist "$src/src/python/stubtest_allowlist.txt"
echo "wheel: built, installed, run, and its types match the module"
