#!/usr/bin/env bash
# End-to-end tests of the `curdle` program: every pattern generates, bad input exits 2 with a
# message naming what is wrong and leaves no output, threads do not change a byte, and the
# golden outputs still come out. Each section is its own ctest entry, so that they run side by
# side. Usage: CURDLE=path/to/curdle cli_test.sh SOURCE_DIR SECTION [ARGUMENT]
#   sections: pattern RECIPE, bad_recipes, bad_options, segments, overrides, threads,
#             golden, report, search, measure, fit, serve, printf
set -u
src=${1:?source dir}
section=${2:?section}
argument=${3:-}
curdle=${CURDLE:?path to curdle}
fig3="$src/patterns/paper/fig3-two-curds.toml"
fig7="$src/patterns/paper/fig7-paving-20m.toml"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# Runs curdle, expecting exit code $1 and stderr containing $2; the rest are arguments.
expect() {
  local code=$1 pattern=$2
  shift 2
  "$curdle" "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  if [ "$got" -ne "$code" ]; then
    fail "curdle $* exited $got, expected $code: $(head -c 400 "$work/stderr")"
  elif ! grep -qF -- "$pattern" "$work/stderr" "$work/stdout"; then
    fail "curdle $*: output lacks '$pattern': $(head -c 400 "$work/stderr")"
  else
    pass
  fi
}

# No file (not even a hidden temporary) may be left in a directory after a failed run.
expect_empty() {
  if [ -n "$(ls -A "$1" 2>/dev/null)" ]; then fail "$2 left files: $(ls -A "$1")"; else pass; fi
}

# A pattern loads and generates all outputs: into CURDLE_PATTERN_OUTPUTS/NAME where ctest
# keeps them for the read-back tests (IFC, GeoPackage), else into a directory of this run's.
section_pattern() {
  local recipe=$1 f
  out="${CURDLE_PATTERN_OUTPUTS:-$work/patterns}/$(basename "$recipe" .toml)"
  rm -rf "$out"
  expect 0 "outputs in" generate "$recipe" --out "$out"
  for f in report.json cells.csv preview.png; do
    [ -s "$out/$f" ] && pass || fail "$recipe: $f missing"
  done
  # Recipes with a [layout] also draw it; the SVG parses in a real XML parser.
  if grep -q '^\[layout\]' "$recipe"; then
    for f in layout.png layout.glb schedule.csv quantities.csv install.svg; do
      [ -s "$out/$f" ] && pass || fail "$recipe: $f missing"
    done
    xmllint --noout --huge "$out/layout.svg" && pass || fail "$recipe: layout.svg does not parse"
    if grep -q '^sheet_size' "$recipe"; then  # cutting files for every sheet
      [ -n "$(ls "$out"/sheets/*.dxf 2>/dev/null)" ] && pass || fail "$recipe: no sheets/*.dxf"
      for f in "$out"/sheets/*.svg; do xmllint --noout "$f" && pass || fail "$f does not parse"; done
    fi
  fi
}

# Every recipe in tests/bad_recipes: exit 2 with its '# expect:' words and the file's name, and
# no output directory. One entry for all of them: each is a start of the program, not a test.
section_bad_recipes() {
  for recipe in "$src"/tests/bad_recipes/*.toml; do
    want=$(sed -n 's/^# expect: //p' "$recipe")
    [ -n "$want" ] && pass || fail "$recipe has no '# expect:' line"
    out="$work/bad/$(basename "$recipe" .toml)"
    expect 2 "$want" generate "$recipe" --out "$out"
    grep -qF "$(basename "$recipe")" "$work/stderr" && pass || fail "$recipe: message does not name the file"
    [ ! -e "$out" ] && pass || fail "$recipe: a failed run left a new directory: $(ls -A "$out")"
  done
}

# Bad command lines exit 2 with a message naming the option, and no output.
section_bad_options() {
o="$work/badcli"
expect 2 "cannot read the recipe" generate "$work/missing.toml" --out "$o"
expect 2 "X,Y,W,H" generate "$fig3" --window 1,2,3 --out "$o"
expect 2 "inside the field" generate "$fig3" --window 10,10,8,8 --out "$o"
expect 2 "--set lattice.base" generate "$fig3" --set lattice.base=1 --out "$o"
expect 2 "did you mean" generate "$fig3" --set lattice.mdoe=exact --out "$o"
expect 2 "not a whole number" generate "$fig3" --set lattice.mode=exact --out "$o"
expect 2 "unknown output" generate "$fig3" --outputs report.json,pictures --out "$o"
expect 2 "needs a [layout] section" generate "$src/patterns/paper/fig6-decreasing.toml" --outputs layout.svg --out "$o"
expect 2 "memory limit" generate "$fig3" --set 'field.cells=[3200,3200]' --max-memory 1M --out "$o"
expect 2 "memory limit" generate "$fig3" --set 'field.cells=[3200,3200]' --max-memory 2M --outputs report.json --out "$o"
expect 2 "not a size" generate "$fig3" --max-memory lots --out "$o"
expect 2 "memory limit" generate "$src/patterns/paper/fig7-paving-20m.toml" --set 'layout.floor=[300000,300000]' --max-memory 200M --out "$o"
expect 2 "threads" generate "$fig3" --threads 0 --out "$o"
expect 2 "seed" generate "$fig3" --seed minus-one --out "$o"
expect 2 "not a seed" generate "$fig3" --seed -1 --out "$o"
expect 2 "not a seed" generate "$fig3" --seed 18446744073709551616 --out "$o"
version=$(sed -n 's/^project(curdle VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
expect 0 "curdle $version (GPL-3.0-or-later" --version
expect 2 "unknown command" frobnicate "$fig3"
expect 2 "A subcommand is required"
expect_empty "$o" "bad command lines"
expect 2 "cannot create the output directory" generate "$fig3" --out /proc/curdle-cannot-write
touch "$work/a-file"
expect 2 "cannot create the output directory" generate "$fig3" --out "$work/a-file"
# A run that fails after its checks (a mask that is not an image) leaves no new directory.
printf 'not an image' > "$work/mask.png"
sed 's|^kind = "facade"|kind = "facade"\nmask = "mask.png"|' "$src/patterns/brick-facade-five-storeys.toml" > "$work/masked.toml"
grep -q '^mask = "mask.png"' "$work/masked.toml" && pass || fail "masked.toml has no mask"
expect 2 "cannot read the mask image" generate "$work/masked.toml" --out "$work/new/deeper"
[ ! -e "$work/new" ] && pass || fail "a failed run left $(find "$work/new")"
# A target that cannot be replaced: nothing is renamed into place, no temporary is left.
mkdir -p "$work/blocked/cells.csv"
expect 2 "cannot write" generate "$fig3" --out "$work/blocked"
[ "$(ls -A "$work/blocked")" = "cells.csv" ] && pass || fail "blocked run left: $(ls -A "$work/blocked" | tr '\n' ' ')"
}

# A fixed floor is laid from a segment of exactly its own size, never from a part of it.
section_segments() {
expect 2 "takes exactly 67 x 67 cells" generate "$fig7" --window 10,10,20,20 --out "$work/win-floor"
[ ! -e "$work/win-floor/layout.svg" ] && pass || fail "a refused window left layout.svg"
expect 2 "make it at least that large" generate "$fig7" --set 'field.cells=[60,80]' --out "$work/win-floor"
# A segment of a larger curd: the one at the origin is the floor itself, cell for cell.
expect 0 "outputs in" generate "$fig7" --outputs schedule.csv --out "$work/floor-plain"
expect 0 "outputs in" generate "$fig7" --set 'field.cells=[256,256]' --outputs schedule.csv --out "$work/floor-seg0"
cmp -s "$work/floor-plain/schedule.csv" "$work/floor-seg0/schedule.csv" && pass || fail "the segment at the origin differs from the floor"
expect 0 "layout: 4489 paving tiles" generate "$fig7" --set 'field.cells=[256,256]' --window 100,40,67,67 --out "$work/floor-seg"
grep -q '^P-R00-C00,1,,0,0,0,0,' "$work/floor-seg/schedule.csv" && pass || fail "a segment's floor does not start at its own origin"
}

# Overrides and windows.
section_overrides() {
expect 0 "outputs in" generate "$fig3" --set lattice.mode=exact \
  --set 'curds.0.probabilities=["3/4","1/2"]' --set 'curds.1.probabilities=["1/2","1/2"]' --out "$work/set"
grep -q '"mode": "exact"' "$work/set/report.json" && pass || fail "--set lattice.mode not applied"
expect 0 "outputs in" generate "$fig3" --window 4,2,8,10 --out "$work/win"
[ "$(wc -l < "$work/win/cells.csv")" -eq 81 ] && pass || fail "window cells.csv should have 80 rows"
# The window's rows are the same as the whole curd's rows for those cells.
expect 0 "outputs in" generate "$fig3" --outputs cells.csv --out "$work/patterns/fig3-two-curds"
awk -F, 'NR > 1 && $1 >= 4 && $1 < 12 && $2 >= 2 && $2 < 12' "$work/patterns/fig3-two-curds/cells.csv" \
  | sort > "$work/whole-part.csv"
tail -n +2 "$work/win/cells.csv" | sort > "$work/win-part.csv"
cmp -s "$work/whole-part.csv" "$work/win-part.csv" && pass || fail "window differs from the whole curd"
}

# One and two threads give byte-identical outputs (2^22 cells, split between threads).
section_threads() {
big="$work/big.toml"
cat > "$big" <<'TOML'
name = "threads"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "a"
probabilities = ["0.7", "0.7", "0.7", "0.7", "0.7", "0.7", "0.7", "0.7", "0.7", "0.7", "0.7"]
[[curds]]
name = "b"
probabilities = ["3/4", "3/4", "3/4", "3/4", "3/4", "3/4", "3/4", "3/4", "3/4", "3/4", "3/4"]
TOML
expect 0 "outputs in" generate "$big" --threads 1 --out "$work/t1" --outputs report.json,cells.csv,preview.png
expect 0 "outputs in" generate "$big" --threads 2 --out "$work/t2" --outputs report.json,cells.csv,preview.png
for f in report.json cells.csv preview.png; do
  cmp -s "$work/t1/$f" "$work/t2/$f" && pass || fail "$f differs between 1 and 2 threads"
done
# Every output of a laid recipe, written one at a time and side by side: the same bytes.
local screen="$src/patterns/perforated-aluminium-screen.toml" f
expect 0 "outputs in" generate "$screen" --threads 1 --out "$work/s1"
expect 0 "outputs in" generate "$screen" --threads 2 --out "$work/s2"
[ "$(cd "$work/s1" && find . -type f | sort)" = "$(cd "$work/s2" && find . -type f | sort)" ] && pass \
  || fail "the screen's files differ between 1 and 2 threads"
while IFS= read -r f; do
  cmp -s "$work/s1/$f" "$work/s2/$f" && pass || fail "$f differs between 1 and 2 threads"
done < <(cd "$work/s1" && find . -type f)
}

# Golden outputs lock the random stream layout.
section_golden() {
expect 0 "outputs in" generate "$fig3" --seed 3 --out "$work/golden" --outputs cells.csv
cmp -s "$work/golden/cells.csv" "$src/tests/golden/fig3-seed3-cells.csv" && pass \
  || fail "fig3 seed 3 cells.csv differs from tests/golden (the stream layout changed?)"
expect 0 "outputs in" generate "$src/patterns/paper/fig7-three-stages.toml" --seed 7 --out "$work/golden7" --outputs cells.csv
cmp -s "$work/golden7/cells.csv" "$src/tests/golden/fig7-three-stages-seed7-cells.csv" && pass \
  || fail "fig7 seed 7 cells.csv differs from tests/golden"
}

# The report command, and cells.csv skipped by default above 10 million cells (a recipe
# without a layout, so that nothing else is large).
section_report() {
expect 0 "box dimension: fit" report "$fig3" --seed 3
grep -q "survivors" "$work/stdout" && pass || fail "report table lacks its header"
plain="$src/patterns/paper/fig6-decreasing.toml"
grep -q '^\[layout\]' "$plain" && fail "$plain has a layout"
expect 0 "outputs in" generate "$plain" --set 'field.cells=[3200,3200]' --out "$work/huge" --outputs report.json,cells.csv
[ -f "$work/huge/cells.csv" ] && pass || fail "named cells.csv should be written even when large"
expect 0 "cells.csv skipped" generate "$plain" --set 'field.cells=[3200,3200]' --out "$work/huge2"
[ ! -f "$work/huge2/cells.csv" ] && pass || fail "cells.csv should be skipped above 10 million cells"
[ -f "$work/huge2/preview.png" ] && pass || fail "the other outputs should still be written"
# Progress goes to a terminal only: not into this pipe.
grep -q "%" "$work/stderr" && fail "progress printed into a pipe" || pass
# Start-up maps only what every command needs: the drawing, SVG, image and GIS libraries load
# when a drawing, an SVG, a picture or a GeoPackage is made or read, not before.
local heavy='libcairo|libxml2|libOpenImageIO|libgdal'
for args in "--help" "generate $plain --out $work/plain --outputs report.json"; do
  # shellcheck disable=SC2086
  LD_DEBUG=libs "$curdle" $args 2>"$work/libs" >/dev/null
  grep -q "calling init" "$work/libs" || fail "LD_DEBUG printed no libraries for curdle $args"
  grep -E "calling init: .*($heavy)" "$work/libs" && fail "curdle $args mapped a library it needs not" || pass
done
# ...and a drawing loads cairo then.
LD_DEBUG=libs "$curdle" generate "$fig7" --out "$work/drawn" --outputs layout.pdf 2>"$work/libs" >/dev/null
grep -qE "calling init: .*libcairo" "$work/libs" && pass || fail "layout.pdf was drawn without loading cairo"
[ -s "$work/drawn/layout.pdf" ] && pass || fail "layout.pdf missing"
}

# Search: ranked seeds and segments, their previews and search.csv; the command printed for
# the best one reproduces its segment, whose report gives the measured ratio.
section_search() {
expect 0 "rank" search "$fig7" --set 'field.cells=[256,256]' --seeds 1..40 --top 3 \
  --target ratio:dark=0.111 --target 'cluster:dark<=6' --target 'empty=0,0,10,10' --out "$work/search"
[ "$(ls "$work/search" | grep -c '^rank-0[1-3]-seed-.*\.png$')" = 3 ] && pass || fail "search previews: $(ls "$work/search")"
[ "$(grep -c . "$work/search/search.csv")" = 4 ] && pass || fail "search.csv should have a header and 3 rows"
best=$(grep '^best: ' "$work/stdout" | sed 's/^best: curdle //')
case "$best" in *"--window "*",67,67"*) pass ;; *) fail "the best hit is not a 67 x 67 segment: $best" ;; esac
eval "\"\$curdle\" $best --out \"\$work/search-best\" --outputs report.json,schedule.csv" >/dev/null 2>&1 \
  && pass || fail "the printed command did not run: $best"
ratio=$(python3 -c "import csv;print(list(csv.DictReader(open('$work/search/search.csv')))[0]['ratio:dark=0.111'])")
dark=$(python3 -c "import json;r=json.load(open('$work/search-best/report.json'));print([v['count'] for v in r['values'] if v['label']=='dark'][0])")
python3 -c "import sys; sys.exit(abs($dark/4489 - $ratio) > 1e-5)" && pass || fail "search measured $ratio, the report of its segment $dark / 4489"
expect 0 "the whole field" search "$fig3" --seeds 0..500 --no-previews --out "$work/search-whole"
[ "$(ls "$work/search-whole")" = "search.csv" ] && pass || fail "--no-previews still wrote: $(ls "$work/search-whole")"
expect 2 "no value 'nope'" search "$fig7" --seeds 1..5 --target ratio:nope=0.1 --out "$work/search-bad"
expect 2 "not a range of seeds" search "$fig7" --seeds 9..1 --out "$work/search-bad"
expect 2 "must fit in the view" search "$fig7" --seeds 1..5 --window 100,100 --out "$work/search-bad"
expect 2 "inside the segment" search "$fig7" --seeds 1..5 --target 'empty=60,60,10,10' --out "$work/search-bad"
[ ! -e "$work/search-bad" ] && pass || fail "a refused search left $work/search-bad"
}

# Measure: a picture's values come out in measure.json and a plot; bad pictures and options
# exit 2 and leave nothing.
section_measure() {
local mask="$src/patterns/gallery-facade-mask.png"
expect 0 "outputs in" measure "$mask" --out "$work/measure"
[ -s "$work/measure/measure.png" ] && pass || fail "no measure.png"
/usr/bin/python3 - "$work/measure/measure.json" <<'PY' && pass || fail "measure.json is not as described"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["size"] == [240, 120] and j["base"] == 2, j
ground, figure = j["values"]
assert ground["ground"] and "box_dimension" not in ground, ground
assert figure["colour"] == "#000000" and 0 < figure["box_dimension"]["fit"] <= 2, figure
assert abs(ground["share"] + figure["share"] - 1) < 1e-9
assert figure["box_dimension"]["sizes"][0] == 1 and len(figure["box_dimension"]["counts"]) == 7
PY
expect 0 "(ground)" measure "$mask" --threshold 0.5 --base 3 --out "$work/measure3"
expect 2 "is not a regular file" measure /dev/zero --out "$work/measure-bad"
expect 2 "no such file" measure "$work/no-such.png" --out "$work/measure-bad"
expect 2 "not a PNG, JPEG, TIFF or BMP" measure "$fig3" --out "$work/measure-bad"
# Other formats never reach a decoder, whatever their name: an SGI picture once aborted one.
printf '\001\332\001\001\000\003' > "$work/sgi.png" && head -c 600 /dev/zero >> "$work/sgi.png"
expect 2 "not a PNG, JPEG, TIFF or BMP" measure "$work/sgi.png" --out "$work/measure-bad"
expect 2 "must be from 2 to 16" measure "$mask" --values 40 --out "$work/measure-bad"
expect 2 "must be a luminance" measure "$mask" --threshold 1.5 --out "$work/measure-bad"
expect 2 "must be from 2 to 64" measure "$mask" --base 1 --out "$work/measure-bad"
[ ! -e "$work/measure-bad" ] && pass || fail "a refused measure left $work/measure-bad"
}

# Fit: a curd drawn here (canonical, p = 0.8 at every stage, its own generator) is fitted back,
# and the recipe written reads back and curdles; bad options exit 2 and write nothing.
section_fit() {
/usr/bin/python3 - "$work/curd.png" <<'PY'
import random, struct, sys, zlib
random.seed(5)
alive = [[True]]
for _ in range(8):
    n = len(alive) * 2
    alive = [[alive[y // 2][x // 2] and random.random() < 0.8 for x in range(n)] for y in range(n)]
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
rows = b"".join(b"\0" + bytes(0 if a else 255 for a in row) for row in alive)  # 8-bit grey
with open(sys.argv[1], "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 256, 256, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
PY
expect 0 "recipe in" fit "$work/curd.png" --base 2 --stages 8 --out "$work/fit/curd.toml"
/usr/bin/python3 - "$work/fit/curd.toml" <<'PY' && pass || fail "the fitted probabilities are not near 0.8"
import sys, tomllib
r = tomllib.load(open(sys.argv[1], "rb"))
p = r["curds"][0]["probabilities"]
assert r["field"]["cells"] == [256, 256] and len(p) == 8, r
assert all(abs(x - 0.8) < 0.02 for x in p[-2:]), p  # thousands of cells: within 0.02
assert all(abs(x - 0.8) < 0.1 for x in p[2:]), p
PY
expect 0 "outputs in" generate "$work/fit/curd.toml" --out "$work/fit-out" --outputs report.json
# A cells.csv brings its curds: fig. 3's on 16 x 16 roots come back near 3/4, 2/3, 3/4, 2/3.
expect 0 "outputs in" generate "$fig3" --set 'field.cells=[256,256]' --set lattice.stages=4 \
  --set 'curds.0.probabilities=["3/4","2/3","3/4","2/3"]' \
  --set 'curds.1.probabilities=["3/4","2/3","3/4","2/3"]' --out "$work/fig3-big" --outputs cells.csv
expect 0 "curd 'blue'" fit "$work/fig3-big/cells.csv" --base 4 --stages 4 --out "$work/fit/fig3.toml"
/usr/bin/python3 - "$work/fit/fig3.toml" <<'PY' && pass || fail "the cells.csv fit is off"
import sys, tomllib
r = tomllib.load(open(sys.argv[1], "rb"))
assert [c["name"] for c in r["curds"]] == ["red", "blue"], r
for c in r["curds"]:
    assert abs(c["probabilities"][3] - 2 / 3) < 0.02 and abs(c["probabilities"][2] - 0.75) < 0.04, c
PY
expect 2 "must be from 1 to 30" fit "$work/curd.png" --stages 0 --out "$work/fit-bad/x.toml"
expect 2 "must be from 1 to 4" fit "$work/curd.png" --stages 3 --curds 9 --out "$work/fit-bad/x.toml"
# b^K past 64 bits wrapped to 0 and was divided by (SIGFPE): refused, naming --stages.
expect 2 "stages with this base" fit "$work/curd.png" --stages 30 --base 64 --out "$work/fit-bad/x.toml"
expect 2 "is not a regular file" fit /dev/zero --stages 3 --out "$work/fit-bad/x.toml"
# A Markov curd: the three-tone paving's preview fitted as a chain of two states, the chain
# supported over two overlaid curds, and its recipe runs; measure --stages prints the same.
local paving="$src/patterns/paving-three-tone-markov.toml"
expect 0 "outputs in" generate "$paving" --out "$work/paving" --outputs preview.png,cells.csv
expect 0 "chain by" fit "$work/paving/preview.png" --base 4 --stages 3 --states 2 --stage-wise \
  --out "$work/fit/paving.toml"
expect 0 "supported  one Markov curd" fit "$work/paving/cells.csv" --base 4 --stages 3 \
  --out "$work/fit/paving-cells.toml"
/usr/bin/python3 - "$work/fit/paving.toml" "$work/fit/paving-cells.toml" <<'PY' && pass || fail "the chain's recipe is not as fitted"
import sys, tomllib
picture, cells = (tomllib.load(open(p, "rb")) for p in sys.argv[1:])
chain = picture["curds"][0]
assert len(chain["states"]) == 2 and len(chain["transitions"]) == 3, chain
for matrix in chain["transitions"]:
    for row in matrix:
        assert sum(round(float(x) * 10000) for x in row) == 10000, row
assert cells["curds"][0]["states"] == ["dark", "mid"], cells
PY
expect 0 "outputs in" generate "$work/fit/paving.toml" --out "$work/fit-paving" --outputs report.json
expect 0 "boxes holding a finest cell" measure "$work/paving/preview.png" --values 3 --base 4 \
  --stages 3 --out "$work/measure-chain"
/usr/bin/python3 - "$work/measure-chain/measure.json" <<'PY' && pass || fail "measure.json has no chain"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["chain"]["supported"] == "chain" and len(j["chain"]["levels"]) == 4, j["chain"].keys()
PY
expect 2 "needs 3 (the lightest is the ground" fit "$work/curd.png" --stages 8 --states 2 \
  --out "$work/fit-bad/x.toml"
expect 2 "give --states S with them" fit "$work/curd.png" --stages 8 --wheys --out "$work/fit-bad/x.toml"
expect 2 "from 1 to 15 living states" fit "$work/curd.png" --stages 8 --states 99 --out "$work/fit-bad/x.toml"
expect 2 "not to a threshold" measure "$work/curd.png" --threshold 0.5 --stages 3 --out "$work/fit-bad"
[ ! -e "$work/fit-bad" ] && pass || fail "a refused fit left $work/fit-bad"
}

# Serve: bad recipes, a busy port and missing page files exit 2; SIGINT stops it cleanly.
section_serve() {
expect 2 "cannot read the recipe" serve "$work/no-such-recipe.toml" --port 0
# README command 1 builds curdle alone: without curdle-serve beside it, serve says how to build it.
mkdir -p "$work/alone" && cp "$curdle" "$work/alone/curdle"
"$work/alone/curdle" serve "$fig3" --port 0 > "$work/alone.out" 2>&1
alone=$?
[ "$alone" -eq 1 ] && grep -q "curdle-serve, which is not built beside this curdle.*--target curdle_serve" "$work/alone.out" \
  && pass || fail "serve without curdle-serve exited $alone: $(cat "$work/alone.out")"
expect 2 "index.html missing" serve "$fig3" --port 0 --web-root "$work"
"$curdle" serve "$fig3" --port 0 > "$work/serve.out" 2>&1 &
serve_pid=$!
for _ in $(seq 50); do grep -q "open http" "$work/serve.out" && break; sleep 0.1; done
port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/serve.out")
[ -n "$port" ] && pass || fail "serve printed no address: $(cat "$work/serve.out")"
expect 2 "cannot listen on 127.0.0.1:$port" serve "$fig3" --port "$port"
kill -INT "$serve_pid"
for _ in $(seq 50); do kill -0 "$serve_pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$serve_pid" 2>/dev/null; then
  fail "serve did not stop on SIGINT"; kill -KILL "$serve_pid"
else
  wait "$serve_pid" && pass || fail "serve exited $? on SIGINT"
fi
grep -q "curdle: stopped" "$work/serve.out" && pass || fail "serve did not say it stopped"
}

# The programs' own printf paths: GDAL brings libquadmath, whose printf hooks would send every
# printf in the process down glibc's slow path (src/cli/printf_hooks.cpp), so its three
# registrations must reach curdle's refusals, not glibc, when layout.gpkg loads GDAL; and cairo's
# snprintf must reach curdle's fast path for "%f" (src/cli/fixed_point_snprintf.cpp) when
# layout.pdf is drawn. curdle-serve, which loads both, exports the same.
section_printf() {
  LD_DEBUG=bindings LD_DEBUG_OUTPUT="$work/bindings" \
    "$curdle" generate "$fig7" --out "$work/printf" --outputs layout.gpkg layout.pdf > /dev/null 2>&1 \
    && pass || fail "generate with layout.gpkg and layout.pdf failed"
  local serve
  serve="$(dirname "$curdle")/curdle-serve"
  for binding in "libquadmath register_printf_specifier" "libquadmath register_printf_modifier" \
                 "libquadmath register_printf_type" "libcairo __snprintf_chk"; do
    set -- $binding
    if cat "$work"/bindings.* | grep -q "$1.*to .*curdle.*\`$2'"; then
      pass
    else
      fail "$1's $2 did not bind to curdle: $(cat "$work"/bindings.* | grep "$1.*\`$2'" | head -3)"
    fi
    if [ -x "$serve" ]; then
      nm -D --defined-only "$serve" | grep -qw "$2" && pass || fail "curdle-serve does not export $2"
    fi
  done
}

if ! declare -F "section_$section" > /dev/null; then
  echo "unknown section '$section'" >&2
  exit 2
fi
"section_$section" $argument
echo "cli $section: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
