#!/usr/bin/env bash
# Installs what curdle needs to build, test and benchmark, from Debian packages only.
# Idempotent: installs only what is missing, and runs `apt-get update` at most once.
# Usage: setup.sh           everything: the build, the tests' readers (Blender, Chromium, ezdxf,
#                           GDAL, FreeCAD, LibreCAD, poppler, rsvg, Node.js and the npm
#                           packages) and clang-format
#        setup.sh --main    what building and running curdle needs, for README command 1
set -euo pipefail

main_only=false
[ "${1:-}" = "--main" ] && main_only=true

packages=(
  cmake g++ make pkg-config
  libcgal-dev libopenimageio-dev libtinygltf-dev libtomlplusplus-dev libcli11-dev
  libfmt-dev nlohmann-json3-dev libexpat1-dev libdxflib-dev libsvgpp-dev libxml2-dev librandom123-dev libtbb-dev libcpp-httplib-dev libssl-dev libgtest-dev libbenchmark-dev
  libcairo2-dev libpng-dev fonts-dejavu-core zlib1g-dev
  python3 python3-dev python3-numpy pybind11-dev
)
if ! $main_only; then
  # The programs the tests read every output back with.
  packages+=(blender python3-ezdxf librsvg2-bin libxml2-utils poppler-utils chromium clang-format)
  # The tidy preset (not run by the tests) runs .clang-tidy's checks.
  packages+=(clang-tidy)
  # DXF text read by four programs: ezdxf (above), GDAL, FreeCAD and LibreCAD.
  packages+=(gdal-bin python3-gdal freecad-python3 librecad)
  # layout.gpkg: the GeoPackage module is built against GDAL.
  packages+=(libgdal-dev)
  # The Python module as pip builds it, and mypy's stubtest for its types.
  packages+=(python3-pip python3-venv python3-mypy)
  # The benchmarks time whole processes and compiles with /usr/bin/time.
  packages+=(time)
  # Node.js and npm for the glTF validator and the browser checks, when the machine has none.
  command -v node > /dev/null || packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all packages present"
fi

$main_only && exit 0

# The npm packages, each folder as its package-lock.json locks them: the page's three.js (web/,
# copied beside the page by the build) and the glTF and browser checks (tests/js).
root="$(cd "$(dirname "$0")" && pwd)"
for js in "$root/web" "$root/tests/js"; do
  if ! cmp -s "$js/package-lock.json" "$js/node_modules/.installed-lock.json" 2>/dev/null; then
    echo "setup: installing npm packages in ${js#"$root"/}"
    (cd "$js" && npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.installed-lock.json)
  fi
done
