#!/usr/bin/env bash
# Hostile input: every example that once crashed, hung or wrote a bad file now exits 2 (or a
# 4xx from the server) with a message; the server keeps answering; an interrupted or failing
# run leaves the previous output set intact and no temporary files.
# Usage: CURDLE=path/to/curdle hostile_test.sh SOURCE_DIR SECTION   (recipes, options, kills, server)
set -u
src=${1:?source dir}
section=${2:?section}
curdle=${CURDLE:?path to curdle}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
p="$src/patterns"

# Runs curdle (at most 60 s), expecting exit 2, a message containing $1, and no output.
refused() {
  local pattern=$1
  shift
  rm -rf "$work/out"
  timeout 60 "$curdle" "$@" --out "$work/out" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  if [ "$got" -ne 2 ]; then
    fail "curdle $* exited $got, expected 2: $(head -c 300 "$work/stderr")"
  elif ! grep -qF -- "$pattern" "$work/stderr"; then
    fail "curdle $*: message lacks '$pattern': $(head -c 300 "$work/stderr")"
  elif [ -e "$work/out" ]; then
    fail "curdle $*: a refused run left $work/out"
  else
    pass
  fi
}

section_recipes() {
  refused "each from 1 mm" generate "$p/paper/fig7-paving-20m.toml" --set 'layout.floor=[1e-300,1e-300]'
  refused "sizes from 1" generate "$p/paper/fig3-two-curds.toml" --set 'field.window=[0,0,-1,-1]'
  refused "layout.widths.3" generate "$p/fins-facade-rhythm.toml" --set 'layout.widths=[0,100,180,nan]'
  refused "layout.widths.0" generate "$p/fins-facade-rhythm.toml" --set 'layout.widths=[inf,100,180,0]'
  refused "from 0.001 mm" generate "$p/perforated-aluminium-screen.toml" --set layout.chord_tolerance=1e-9
  refused "layout.holes.0.offset" generate "$p/perforated-aluminium-screen.toml" --set 'layout.holes.0.offset=[nan,0]'
  refused "probabilities.0" generate "$p/paper/fig3-two-curds.toml" --set 'curds.0.probabilities=[nan,0.5]'
  refused "not valid UTF-8" generate "$p/paper/fig3-two-curds.toml" --set $'name=\xff\xfe'
  refused "control character" generate "$p/paper/fig3-two-curds.toml" --set $'description=a\x1bb'
  refused "memory limit" generate "$p/paper/fig6-decreasing.toml" --set lattice.base=2 \
    --set lattice.dimension=1 --set "curds.0.probabilities=[$(printf '0.5,%.0s' {1..55})0.5]" \
    --max-memory 1G
  refused "not a regular file" generate "$p"
  sed 's|^mask = .*|mask = "/dev/zero"|' "$p/gallery-facade-mask.toml" > "$work/zero.toml"
  refused "not a regular file" generate "$work/zero.toml"
  # A small PNG that decodes to 12,000 x 12,000 pixels: refused from its header.
  python3 - "$work/big.png" <<'PY'
import struct, sys, zlib
w = h = 12000
raw = zlib.compress(b''.join(b'\0' + b'\0' * w for _ in range(h)), 9)
chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
open(sys.argv[1], 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 0, 0, 0, 0)) + chunk(b'IDAT', raw) + chunk(b'IEND', b''))
PY
  sed 's|^mask = .*|mask = "big.png"|' "$p/gallery-facade-mask.toml" > "$work/big.toml"
  refused "12000 x 12000 pixels" generate "$work/big.toml" --max-memory 128M
  # A density image: a device, and a picture over the 4096 x 4096 pixels a field may have.
  density_image() {
    printf '%s\n' "$(sed '/^\[curds.density\]/,/^$/d' "$p/plaza-radial-density.toml")" | sed "/^colour = \"#3f3e3b\"/a [curds.density]\nkind = \"image\"\npath = \"$1\"\nvalues = [0, 2]"
  }
  density_image /dev/zero > "$work/plaza-zero.toml"
  refused "not a regular file" generate "$work/plaza-zero.toml"
  density_image big.png > "$work/plaza-big.toml"
  refused "12000 x 12000 pixels" generate "$work/plaza-big.toml"
  refused "lattice.mode = \"canonical\"" generate "$p/plaza-radial-density.toml" --set lattice.mode=quota
  refused "values" generate "$p/plaza-radial-density.toml" --set 'curds.0.density.values=[nan,1]'
  # Markup in a name is text in every drawing, never markup.
  timeout 60 "$curdle" generate "$p/brick-facade-five-storeys.toml" --set 'name=Smith & Sons <script>' \
    --outputs layout.svg,install.svg --out "$work/named" > /dev/null 2>&1 && pass || fail "a name with & and < was refused"
  for f in layout.svg install.svg; do
    xmllint --noout "$work/named/$f" && pass || fail "$f with a name holding & and < is not XML"
    grep -q '<script' "$work/named/$f" && fail "$f holds a live <script>" || pass
  done
}

section_options() {
  f3="$p/paper/fig3-two-curds.toml"
  refused "must lie inside the field" generate "$f3" --set 'field.cells=[16,16]' --window 9223372036854775807,0,1,1
  refused "is not a size" generate "$f3" --max-memory 16777216T
  refused "is empty" generate "$f3" --window ''
  refused "is empty" generate "$f3" --max-memory ''
  refused "is empty" generate "$f3" --seed ''
  refused "at most 2^40 cells" search "$f3" --seeds 1..1 --target empty=4611687117939015680,0,4611686018427387904,1
  refused "at most 2^40 seeds" search "$f3" --seeds 0..18446744073709551614
  refused "above the budget" search "$f3" --set 'field.cells=[1024,1024]' --seeds 0..100000000
}

# Site drawings: every broken or hostile DXF is refused with the file, layer and handle and what
# to do, and nothing is written; a far origin and Windows-1252 layer names are read.
section_sites() {
  local d="$work/sites"
  mkdir -p "$d"
  /usr/bin/python3 - "$d" <<'PY' || fail "could not write the hostile drawings"
import os, sys
import ezdxf
d = sys.argv[1]
def drawing(units=4):
    doc = ezdxf.new("R2013", setup=False)
    doc.header["$INSUNITS"] = units
    return doc, doc.modelspace()
def outline(msp, points, layer="A-OTLN", **kw):
    return msp.add_lwpolyline(points, close=True, dxfattribs={"layer": layer, **kw})
square = [(0, 0), (8000, 0), (8000, 6000), (0, 6000)]
doc, msp = drawing()
for a, b in [((0, 0), (8000, 0)), ((8000, 0), (8000, 6000)), ((8000, 6000), (0, 6000)), ((0, 6000), (0, 5))]:
    msp.add_line(a, b, dxfattribs={"layer": "A-OTLN"})
doc.saveas(f"{d}/open.dxf")
doc, msp = drawing(); outline(msp, [(0, 0), (8000, 6000), (8000, 0), (0, 6000)]); doc.saveas(f"{d}/bowtie.dxf")
doc, msp = drawing(); outline(msp, square); outline(msp, [(9000, 0), (9500, 0), (9500, 500)], "PIT"); doc.saveas(f"{d}/outside.dxf")
doc, msp = drawing(); outline(msp, square); doc.saveas(f"{d}/nopit.dxf")
doc, msp = drawing(6); outline(msp, square); doc.saveas(f"{d}/km.dxf")
doc, msp = drawing(0); outline(msp, square); doc.saveas(f"{d}/unitless.dxf")
doc, msp = drawing(); msp.add_polyline3d([(0, 0, 0), (8000, 0, 0), (8000, 6000, 900), (0, 6000, 0)], close=True, dxfattribs={"layer": "A-OTLN"}); doc.saveas(f"{d}/tilted.dxf")
doc, msp = drawing(6); outline(msp, [(5123456.789 + x / 1000, 2345678.123 + y / 1000) for x, y in square]); doc.saveas(f"{d}/utm.dxf")
# 250,000 lines, written as text: ezdxf took ten seconds to make them one by one.
lines = "".join(f"0\nLINE\n8\nA-OTLN\n10\n{i % 8000}\n20\n0\n11\n{i % 8000}\n21\n10\n" for i in range(250000))
open(f"{d}/many.dxf", "w").write("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" + lines + "0\nENDSEC\n0\nEOF\n")
doc, msp = drawing()
loop = doc.blocks.new("LOOP"); loop.add_blockref("LOOP", (1, 1))
outline(msp, square); msp.add_blockref("LOOP", (0, 0), dxfattribs={"layer": "PIT"}); doc.saveas(f"{d}/loop.dxf")
open(f"{d}/binary.dxf", "wb").write(b"AutoCAD Binary DXF\r\n\x1a\x00" + bytes(64))
open(f"{d}/drawing.dxf", "wb").write(b"AC1032" + bytes(64))
open(f"{d}/page.dxf", "w").write("<html><body>site</body></html>")
with open(f"{d}/huge.dxf", "wb") as f:
    f.write(b"0\nSECTION\n2\nENTITIES\n"); f.truncate(65 << 20)
svg = '<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="6000mm" viewBox="0 0 8000 6000">{body}</svg>'
square_path = '<path id="o" d="M0 0 H8000 V6000 H0 Z"/>'
open(f"{d}/laughs.svg", "w").write('<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]>' + svg.format(w="8000mm", body='<g id="A-OTLN">' + square_path + '</g>'))
open(f"{d}/badpath.svg", "w").write(svg.format(w="8000mm", body='<g id="A-OTLN"><path id="edge" d="M0 0 L 8000 0 Q"/></g>'))
open(f"{d}/px.svg", "w").write(svg.format(w="8000", body='<g id="A-OTLN">' + square_path + '</g>'))
open(f"{d}/notsvg.svg", "w").write("<html><body><svg>")
text = open(f"{d}/nopit.dxf", encoding="utf-8").read().replace("A-OTLN", "Gr\u00e8s")
open(f"{d}/cp1252.dxf", "wb").write(text.encode("cp1252"))
PY
  site_recipe() {  # file, outline layer, then extra lines
    local file=$1 layer=$2
    shift 2
    sed '/^\[layout.site\]/,$d' "$p/courtyard-from-dxf.toml" > "$d/$file.toml"
    printf '[layout.site]\nfile = "%s"\noutline = "%s"\n' "$file" "$layer" >> "$d/$file.toml"
    printf '%s\n' "$@" >> "$d/$file.toml"
    echo "$d/$file.toml"
  }
  local pit='[[layout.site.zones]]' rule='rule = "exclude"'
  refused "is not closed" generate "$(site_recipe open.dxf A-OTLN)"
  refused "(0, 5) (" generate "$(site_recipe open.dxf A-OTLN)"
  refused "crosses itself at (4000, 3000)" generate "$(site_recipe bowtie.dxf A-OTLN)"
  refused "lies outside the outline" generate "$(site_recipe outside.dxf A-OTLN "$pit" 'layer = "PIT"' "$rule")"
  refused 'layer "PIT" (a zone) has nothing on it' generate "$(site_recipe nopit.dxf A-OTLN "$pit" 'layer = "PIT"' "$rule")"
  refused "too large" generate "$(site_recipe km.dxf A-OTLN)"
  refused 'units = "mm"' generate "$(site_recipe km.dxf A-OTLN)"
  refused "does not say its units" generate "$(site_recipe unitless.dxf A-OTLN)"
  refused "the POLYLINE with handle 2F on layer \"A-OTLN\" does not lie in the plan's plane" generate "$(site_recipe tilted.dxf A-OTLN)"
  refused "more than 200000 shapes" generate "$(site_recipe many.dxf A-OTLN)"
  refused "nested more than 16 deep" generate "$(site_recipe loop.dxf A-OTLN "$pit" 'layer = "PIT"' "$rule")"
  refused "binary DXF; save it as an ASCII DXF" generate "$(site_recipe binary.dxf A-OTLN)"
  refused "DWG drawing" generate "$(site_recipe drawing.dxf A-OTLN)"
  refused "is not a DXF drawing" generate "$(site_recipe page.dxf A-OTLN)"
  refused "at most 64 MiB" generate "$(site_recipe huge.dxf A-OTLN)"
  refused "missing.dxf: cannot read the drawing: No such file" generate "$(site_recipe missing.dxf A-OTLN)"
  ln -sf /dev/zero "$d/zero.dxf"
  refused "not a regular file" generate "$(site_recipe zero.dxf A-OTLN)"
  refused "layout.site.units" generate "$(site_recipe unitless.dxf A-OTLN 'units = "furlong"')"
  refused "give one or the other" generate "$(site_recipe nopit.dxf A-OTLN)" --set 'layout.outline=[[0,0],[1,0],[1,1]]'
  refused "declares XML entities" generate "$(site_recipe laughs.svg A-OTLN)"
  refused '<path> "edge" has path data curdle cannot read' generate "$(site_recipe badpath.svg A-OTLN)"
  refused "does not say its units" generate "$(site_recipe px.svg A-OTLN)"
  refused "is not an SVG drawing" generate "$(site_recipe notsvg.svg A-OTLN)"
  # Read: a survey 5,000 km from its origin (the datum moved and said), and old layer names.
  timeout 60 "$curdle" generate "$(site_recipe utm.dxf A-OTLN)" --outputs schedule.csv --out "$d/utm" > "$d/utm.out" 2>&1 \
    && grep -q "datum (0, 0) is the drawing's point (5,123,456,789, 2,345,678,123) mm" "$d/utm.out" \
    && pass || fail "the far survey was not read with its datum: $(head -c 300 "$d/utm.out")"
  timeout 60 "$curdle" generate "$(site_recipe cp1252.dxf $'Gr\xc3\xa8s')" --outputs schedule.csv --out "$d/cp" > "$d/cp.out" 2>&1 \
    && pass || fail "a Windows-1252 layer name was not read: $(head -c 300 "$d/cp.out")"
}

# Interrupted runs: the previous set stays whole (byte for byte), no temporary is left; a run
# that finishes replaces the set whole.
section_kills() {
  f7="$p/paper/fig7-paving-20m.toml"
  "$curdle" generate "$f7" --seed 1 --outputs report.json,schedule.csv,layout.svg --out "$work/kill/out" > /dev/null || fail "first run failed"
  (cd "$work/kill/out" && md5sum ./* > "$work/before.md5")
  local interrupted=0
  for delay in 0.02 0.05 0.1 0.2 0.3 0.5; do
    for signal in INT TERM; do
      "$curdle" generate "$f7" --seed 2 --set 'field.cells=[3000,3000]' --window 10,10,67,67 \
        --outputs report.json,cells.csv,preview.png --out "$work/kill/out" > /dev/null 2>&1 &
      local pid=$!
      sleep "$delay"
      kill -"$signal" "$pid" 2> /dev/null
      wait "$pid"
      local code=$?
      if [ "$code" -eq 130 ] || [ "$code" -eq 143 ]; then
        interrupted=$((interrupted + 1))
        # Replaced whole or not at all: the previous set as it was, or (a signal that came
        # after the new set was swapped in) the new set complete and nothing of the old.
        if (cd "$work/kill/out" && md5sum --quiet -c "$work/before.md5" > /dev/null 2>&1); then
          pass
        elif grep -q '"seed": 2' "$work/kill/out/report.json" 2> /dev/null \
          && [ "$(ls "$work/kill/out" | tr '\n' ' ')" = "cells.csv preview.png report.json " ]; then
          pass
          "$curdle" generate "$f7" --seed 1 --outputs report.json,schedule.csv,layout.svg --out "$work/kill/out" > /dev/null
        else
          fail "an interrupted run ($signal after ${delay}s) left a mixed set: $(ls "$work/kill/out")"
        fi
      elif [ "$code" -eq 0 ]; then
        grep -q '"seed": 2' "$work/kill/out/report.json" && [ ! -e "$work/kill/out/schedule.csv" ] \
          && pass || fail "a finished run did not replace the set whole"
        "$curdle" generate "$f7" --seed 1 --outputs report.json,schedule.csv,layout.svg --out "$work/kill/out" > /dev/null
      else
        fail "an interrupted run exited $code"
      fi
      [ "$(ls -A "$work/kill")" = "out" ] && pass || fail "temporaries left: $(ls -A "$work/kill")"
      [ -z "$(ls -A "$work/kill/out" | grep '^\.')" ] && pass || fail "hidden files left in the set"
    done
  done
  [ "$interrupted" -gt 0 ] && pass || fail "no run was interrupted: the test did not test"
}

section_server() {
  "$curdle" serve "$p/paper/fig8-segment-of-large-curd.toml" --port 0 > "$work/serve.out" 2>&1 &
  local pid=$!
  for _ in $(seq 50); do grep -q "open http" "$work/serve.out" && break; sleep 0.1; done
  local port
  port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/serve.out")
  python3 - "$port" <<'PY' && pass || fail "hostile requests"
import http.client, json, socket, sys, time
port = int(sys.argv[1])
def get(path, headers=None, method="GET"):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    c.request(method, path, headers=headers or {})
    r = c.getresponse()
    return r.status, r.read()
bad = 0
cases = [
    ("/api/search?seeds=1..1&target=empty=4611687117939015680,0,4611686018427387904,1", 400),
    ("/api/generate?layout.floor=%5B1e-300,1e-300%5D", 400),
    ("/api/generate?field.window=%5B0,0,-1,-1%5D", 400),
    ("/api/export?file=layout.svg&layout.tile=%5Bnan,300%5D", 400),
    ("/api/generate?window=9223372036854775807,0,1,1", 400),
    ("/api/generate?name=%FF%FE", 400),
    ("/api/generate?window=", 400),
    ("/api/search?seeds=1..268435456", 413),
    ("/api/export?file=layout.svg&layout.mask=%22%2Fdev%2Fzero%22", 400),
    ("/api/generate?curds.0.density=%7Bkind%3D%22image%22%2Cpath%3D%22%2Fdev%2Fzero%22%2Cvalues%3D%5B0%2C1%5D%7D", 400),
    ("/api/generate?layout.site=%7Bfile%3D%22%2Fetc%2Fpasswd.dxf%22%2Coutline%3D%22A%22%7D", 400),
    ("/api/generate?layout.site.file=%22%2Fetc%2Fsite.dxf%22", 400),
    ("/api/generate?layout=%7Bkind%3D%22facade%22%2Cwall%3D%5B1000%2C1000%5D%2Cmask%3D%22%2Fany%2Fpath%22%7D", 400),
]
for path, status in cases:
    got, body = get(path)
    if got != status or b"error" not in body:
        print("FAIL", path, got, body[:200]); bad += 1
for method in ("PATCH", "OPTIONS", "POST", "PUT", "DELETE"):
    got, _ = get("/api/recipe", method=method)
    if got != 405: print("FAIL", method, got); bad += 1
for headers in ({"Host": "evil.example:%d" % port}, {"Origin": "http://evil.example"},
                {"Sec-Fetch-Site": "cross-site"}):
    got, _ = get("/api/recipe", headers)
    if got != 403: print("FAIL", headers, got); bad += 1
# Slow clients: eight sockets sending a header line every second do not stop the server.
slow = []
for _ in range(8):
    s = socket.create_connection(("127.0.0.1", port)); s.sendall(b"GET / HTTP/1.1\r\n"); slow.append(s)
time.sleep(1)
for s in slow:
    try: s.sendall(b"X-Slow: 1\r\n")
    except OSError: pass
start = time.time()
got, _ = get("/api/recipe")
if got != 200 or time.time() - start > 5: print("FAIL slow clients", got, time.time() - start); bad += 1
for s in slow: s.close()
got, body = get("/api/generate?seed=3&cells=0")
if got != 200: print("FAIL the server no longer answers", got); bad += 1
sys.exit(1 if bad else 0)
PY
  kill -TERM "$pid"
  local start=$(date +%s%N)
  wait "$pid" && pass || fail "serve exited $? on SIGTERM"
  [ $(( ($(date +%s%N) - start) / 1000000 )) -lt 1500 ] && pass || fail "serve took over a second to stop"
}

if ! declare -F "section_$section" > /dev/null; then
  echo "unknown section '$section'" >&2
  exit 2
fi
"section_$section"
echo "hostile $section: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
