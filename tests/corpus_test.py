#!/usr/bin/python3
"""Drawings and models from public projects (../shared/corpus), each laid as a user would lay it
and judged against what an established reader sees in it (FILE.trusted.json: ezdxf and GDAL for
DXF, an XML reader for SVG, its own decoding for glTF).

For each file, the outline is the trusted reader's largest closed shape (picked with
pick = "largest" where its layer holds more than one); a model's plan is its largest scene
root. Each file must be read as the trusted reader reads it (the outline's area and box within
0.5 %), or refused with a message that names the file and the layer, entity, element or line
and says what to do; never a crash, a hang (10 s) or a silently different reading. Where the
trusted reading is wrong, EXPECTED says what is right and why. Writes results.md, the table the
manual quotes (docs/layouts.md).

    corpus_test.py CURDLE CORPUS_DIR OUT_DIR     (exit 77, skipped, without the corpus)
"""
import json
import os
import re
import shutil
import subprocess
import sys

CURDLE, CORPUS, OUT = (os.path.abspath(a) for a in sys.argv[1:4])
SECONDS = 10
TOLERANCE = 0.005  # of the area and of each side of the box

# Files whose trusted reading is not what the file holds, or not what a user would lay.
EXPECTED = {
    "dxfparser_arc1.dxf": "refused: the trusted reader closes a lone ARC whose ends lie 0.21 units "
                          "apart (it joins ends within 0.5 units, whatever the units); an open arc is no "
                          "outline",
    "gdal_block-insert-order.dxf": "refused: BLOCK3 inserts BLOCK4 in a tilted coordinate system "
                                   "(extrusion 0.6, 0.57, 0.57), which the trusted reading lays flat",
    "gdal_additional-entities.dxf": "refused: HATCH 108 on the outline's layer is drawn in a tilted "
                                    "coordinate system (extrusion 0.3, 0, -0.95)",
    "gdal_spline_weight.dxf": "refused: three splines share both ends; the trusted reader closes two and "
                              "leaves the third open, curdle names the third",
    "ezdxf_POLI-ALL210_12.dxf": "refused: POLYLINE 29 on the outline's layer is drawn in a tilted "
                                "coordinate system",
    "gdal_3d.dxf": "refused: the largest closed shape is a CIRCLE standing upright (extrusion "
                   "along y), which the trusted reading measures flat (area 1e-16)",
    "gdal_insert_only.dxf": "refused: the trusted reading's shape crosses itself",
    "gdal_insert_only_col_count_zero.dxf": "refused: the trusted reading's shape crosses itself",
    "librecad_v25.dxf": "refused: a 0.4 x 0.6 mm symbol, no surface (under 10 mm)",
}


def q(text):
    return json.dumps(text)


def expectation(t):
    """The recipe's keys and the outline the trusted reader sees, or None with why not."""
    if t.get("format") == "glTF":
        roots = [r for r in t.get("scene_roots", []) if r.get("lowest_faces_area_m2", 0) > 0]
        if not roots:
            return None, "no horizontal lowest faces"
        r = max(roots, key=lambda r: r["lowest_faces_area_m2"])
        b = r["lowest_faces_bbox_plan_m"]
        return {"layer": r["layer"], "gltf": True, "box_mm": [(b[2] - b[0]) * 1000, (b[3] - b[1]) * 1000],
                "units": None, "several": False}, None
    shapes = t.get("closed_shapes") or []
    if not shapes:
        return None, "the trusted reader finds no closed shape"
    big = max(shapes, key=lambda s: s["area"])
    key = "bbox_y_up" if "bbox_y_up" in big else "bbox"
    b = big[key]
    unit_mm, units = t.get("unit_mm"), None
    if not unit_mm:  # say units that make it a plausible surface, as a user would
        side = max(b[2] - b[0], b[3] - b[1])
        for units, unit_mm in (("mm", 1.0), ("cm", 10.0), ("m", 1000.0)):
            if side * unit_mm >= 2000:
                break
    layer_info = (t.get("layers") or {}).get(big["layer"], {})
    # Shapes in no group: the trusted reader's "(none)", curdle's "(root)".
    layer = "(root)" if big["layer"] == "(none)" else big["layer"]
    return {"layer": layer, "area_m2": big["area"] * unit_mm ** 2 / 1e6,
            # A DXF layer of closed shapes alone must be read; others may be refused clearly.
            "must_read": t.get("format") == "DXF" and not layer_info.get("open_chains"),
            "box_mm": [(b[2] - b[0]) * unit_mm, (b[3] - b[1]) * unit_mm], "units": units,
            "several": sum(s["layer"] == big["layer"] for s in shapes) > 1,
            "crosses": big.get("self_intersects", False), "hidden": big.get("hidden", False)}, None


def recipe(name, e):
    head = ['name = "corpus"', "seed = 1", "[lattice]", "base = 3", "dimension = 2", 'mode = "canonical"',
            "[[curds]]", 'name = "dark"', 'probabilities = ["3/4", "2/3"]', "[layout]"]
    layer = q(e["layer"])
    pick = "{ layer = %s, pick = \"largest\" }" % layer if e["several"] else layer
    if e.get("gltf"):
        return "\n".join(head + ['kind = "facade"', "panel = [215, 65]", "joint = 10", "[layout.building]",
                                 "height = 750", "[layout.building.site]", "file = %s" % q(name),
                                 "plan = %s" % pick]) + "\n"
    side = (e["area_m2"] * 1e6 / 2000) ** 0.5 if e["area_m2"] > 0 else 500
    tile = float("%.3g" % max(side, 1.0))
    lines = head + ['kind = "paving"', 'combine = "mix"', "tile = [%r, %r]" % (tile, tile),
                    "joint = %r" % float("%.3g" % (tile * 0.01)), "[layout.site]", "file = %s" % q(name),
                    "outline = %s" % pick]
    if e["units"]:
        lines.append("units = %s" % q(e["units"]))
    return "\n".join(lines) + "\n"


def judge(rc, text, e, report):
    """The class of one run: read right, refused clear, or a failure's name."""
    if rc in (124, 137):
        return "HANG"
    if rc < 0 or rc >= 128 or re.search(r"Segmentation|Aborted|terminate called|AddressSanitizer", text):
        return "CRASH"
    if rc != 0:
        first = text.strip().splitlines()[0] if text.strip() else ""
        names_file = re.search(r"\.(dxf|svg|gltf|glb)\b", first, re.I)
        names_where = re.search(r"layer|line \d|handle|node|<\w+>|INSERT|block|entity|units|outline|"
                                r"binary|DWG|not a", first, re.I)
        return "refused clear" if names_file and names_where and len(first) > 40 else "REFUSED UNCLEARLY"
    if e.get("gltf"):
        m = re.search(r"plan: outline ([\d,.]+) x ([\d,.]+) mm", text)
        size = [float(m.group(1).replace(",", "")), float(m.group(2).replace(",", ""))] if m else None
        ok = size and all(abs(size[k] - e["box_mm"][k]) <= TOLERANCE * e["box_mm"][k] + 0.1 for k in (0, 1))
        return "read right" if ok else "READ DIFFERENTLY"
    site = (report or {}).get("layout", {}).get("site_outline")
    if not site:
        return "READ DIFFERENTLY"
    b = site["box_mm"]
    size = [b[2] - b[0], b[3] - b[1]]
    ok_area = abs(site["area_m2"] - e["area_m2"]) <= TOLERANCE * e["area_m2"] + 1e-9
    ok_box = all(abs(size[k] - e["box_mm"][k]) <= TOLERANCE * e["box_mm"][k] + 0.1 for k in (0, 1))
    e["laid"] = (site["area_m2"], size)
    return "read right" if ok_area and ok_box else "READ DIFFERENTLY"


def main():
    if not os.path.isdir(CORPUS):
        print(f"corpus: {CORPUS} is absent; the corpus test is skipped (it needs ../shared/corpus)")
        return 77
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(OUT)
    files = sorted(f for f in os.listdir(CORPUS) if os.path.exists(os.path.join(CORPUS, f + ".trusted.json")))
    rows, failures = [], []
    for name in files:
        t = json.load(open(os.path.join(CORPUS, name + ".trusted.json")))
        e, why = expectation(t)
        work = os.path.join(OUT, re.sub(r"[^\w.-]", "_", name))
        os.makedirs(work)
        os.symlink(os.path.join(CORPUS, name), os.path.join(work, name))
        if e is None:  # nothing to lay: read the first layer, and it must be refused clearly
            layers = [k for k, v in (t.get("layers") or {}).items() if v.get("entities")] or ["0"]
            e = {"layer": layers[0], "area_m2": 0, "box_mm": [0, 0], "units": "mm", "several": False,
                 "gltf": t.get("format") == "glTF", "nothing": why}
        with open(os.path.join(work, "recipe.toml"), "w") as f:
            f.write(recipe(name, e))
        try:
            run = subprocess.run(["timeout", str(SECONDS), CURDLE, "generate", "recipe.toml", "--threads", "1",
                                  "--out", "out", "--outputs", "report.json"],
                                 cwd=work, capture_output=True, text=True, errors="replace")
            rc, text = run.returncode, run.stderr + run.stdout
        except OSError as error:
            rc, text = -1, str(error)
        report = None
        if rc == 0 and os.path.exists(os.path.join(work, "out", "report.json")):
            report = json.load(open(os.path.join(work, "out", "report.json")))
        verdict = judge(rc, text, e, report)
        expected = EXPECTED.get(name, "")
        if e.get("nothing") and verdict == "read right":
            verdict = "READ DIFFERENTLY"
        if verdict == "read right" and (e.get("crosses") or expected.startswith("refused")):
            verdict = "READ DIFFERENTLY"  # the trusted reading (or EXPECTED) says it cannot be laid
        if (verdict == "refused clear" and e.get("must_read") and not e.get("crosses") and
                not expected.startswith("refused")):
            verdict = "REFUSED WHAT IT SHOULD READ"
        if verdict.isupper():
            failures.append(f"{name}: {verdict}: {text.strip()[:400]}")
        first = text.strip().splitlines()[0] if text.strip() else ""
        said = first.replace("curdle: error: ", "").replace(os.path.join(work, ""), "")
        said = re.sub(r"^recipe\.toml:\d+:\d+: key '[^']+': ", "", said)
        rows.append((name, verdict, e["layer"], said if rc else (first if first else ""), expected or e.get("nothing", "")))
    with open(os.path.join(OUT, "results.md"), "w") as f:
        f.write("| file | result | outline layer | what curdle says | note |\n|---|---|---|---|---|\n")
        for name, verdict, layer, said, note in rows:
            cell = lambda s: s.replace("|", "\\|")[:220]
            f.write(f"| {name} | {verdict} | {cell(layer)} | {cell(said)} | {cell(note)} |\n")
    counts = {}
    for _, verdict, *_ in rows:
        counts[verdict] = counts.get(verdict, 0) + 1
    print("corpus: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) + f" of {len(rows)} files")
    for f in failures:
        print("FAIL " + f)
    print(f"{len(rows) - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
