"""Every piece agrees across schedule.csv, layout.dxf, install.svg and the sheet DXFs.

For one recipe and every origin corner its layout kind takes, runs `curdle generate` and checks
each element of schedule.csv against the other files within 0.01 mm: the DXF's piece on its
material layer (bounding box, or circle) and its ID on layer ID at the piece's centre; the
installer's map's drawing of the element; a perforation's sheet DXF. Also that the DXF is in
millimetres (AutoCAD 2000, $INSUNITS 4) and audits clean, and that the schedule's areas add up
to the quantities' laid areas.

Usage: pieces_agree.py CURDLE RECIPE WORKDIR   (Debian's python3 with python3-ezdxf)
"""
import csv
import os
import re
import subprocess
import sys

import ezdxf

TOL = 0.01
CORNERS = ["bottom-left", "bottom-right", "top-left", "top-right"]
failures = []


def fail(message):
    failures.append(message)
    if len(failures) <= 20:
        print("FAIL:", message)


def near(a, b):
    return abs(a - b) <= TOL


def read_csv(path):
    with open(path, newline="", encoding="utf-8-sig") as f:
        return list(csv.DictReader(f, strict=True))


def box_of_points(points):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return (min(xs), min(ys), max(xs), max(ys))


def dxf_pieces(path, dx=0.0, dy=0.0):
    """Pieces by layer (bounding boxes and circles) and ID positions of one DXF."""
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    if auditor.errors or auditor.fixes:
        fail(f"{path}: ezdxf audit found {len(auditor.errors)} errors, {len(auditor.fixes)} fixes")
    if doc.dxfversion < "AC1015":
        fail(f"{path}: DXF {doc.dxfversion}, not AutoCAD 2000 or later")
    if doc.header.get("$INSUNITS") != 4:
        fail(f"{path}: $INSUNITS is {doc.header.get('$INSUNITS')}, not 4 (millimetres)")
    layer = doc.layers.get("ID")
    if layer is None or layer.dxf.get("plot", 1) != 0:
        fail(f"{path}: the ID layer is missing or plots")
    boxes, ids = {}, {}
    for e in doc.modelspace():
        t = e.dxftype()
        if t == "TEXT" and e.dxf.layer == "ID":
            p = e.dxf.align_point
            ids[e.dxf.text] = (p[0] + dx, p[1] + dy)
        elif t == "LWPOLYLINE" and e.dxf.layer not in ("OUTLINE", "OPENINGS"):
            b = box_of_points([(p[0] + dx, p[1] + dy) for p in e.get_points("xy")])
            boxes.setdefault(round(b[0]), []).append(b)
        elif t == "CIRCLE":
            c, r = e.dxf.center, e.dxf.radius
            b = (c[0] + dx - r, c[1] + dy - r, c[0] + dx + r, c[1] + dy + r)
            boxes.setdefault(round(b[0]), []).append(b)
    return boxes, ids


def has_box(boxes, b):
    for key in (round(b[0]) - 1, round(b[0]), round(b[0]) + 1):
        for c in boxes.get(key, []):
            if all(near(u, v) for u, v in zip(b, c)):
                return True
    return False


def install_boxes(path):
    text = open(path, encoding="utf-8").read()
    outline = re.search(r'<rect x="([-\d.]+)" y="([-\d.]+)" width="([-\d.]+)" height="([-\d.]+)"', text)
    margin, height = float(outline.group(1)), float(outline.group(4))
    out = {}
    for m in re.finditer(r'<g id="([^"]+)" class="element"[^>]*>(.*?)</g>', text):
        pts = []
        for r in re.finditer(r'<rect x="([-\d.]+)" y="([-\d.]+)" width="([-\d.]+)" height="([-\d.]+)"', m.group(2)):
            x, y, w, h = map(float, r.groups())
            pts += [(x - margin, margin + height - y - h), (x - margin + w, margin + height - y)]
        for path in re.finditer(r'<path d="([^"]+)"', m.group(2)):
            for px, py in re.findall(r'[ML]([-\d.]+) ([-\d.]+)', path.group(1)):
                pts.append((float(px) - margin, margin + height - float(py)))
        for c in re.finditer(r'<circle cx="([-\d.]+)" cy="([-\d.]+)" r="([-\d.]+)"', m.group(2)):
            cx, cy, r = map(float, c.groups())
            x, y = cx - margin, margin + height - cy
            pts += [(x - r, y - r), (x + r, y + r)]
        out[m.group(1)] = box_of_points(pts)
    return out


def check(curdle, recipe, out, corner):
    args = [curdle, "generate", recipe, "--out", out,
            "--outputs", "schedule.csv,quantities.csv,layout.dxf,install.svg,sheets"]
    if corner:
        args += ["--set", f'layout.origin="{corner}"']
    run = subprocess.run(args, capture_output=True, text=True)
    if run.returncode != 0:
        if corner and "origin" in run.stderr:
            return False  # this kind has no origin corner
        if not corner and "needs a [layout]" in run.stderr:
            print(f"{os.path.basename(recipe)}: no [layout], so no pieces to compare")
            return False
        fail(f"{' '.join(args)}: exit {run.returncode}: {run.stderr.strip()}")
        return True
    where = f"{os.path.basename(recipe)} origin {corner or 'default'}"
    rows = read_csv(os.path.join(out, "schedule.csv"))
    boxes, ids = dxf_pieces(os.path.join(out, "layout.dxf"))
    drawn = install_boxes(os.path.join(out, "install.svg"))
    sheet_offsets = {}
    sheets = os.path.join(out, "sheets")
    area = 0.0
    for row in rows:
        eid = row["element_id"]
        x, y, w = float(row["x_mm"]), float(row["y_mm"]), float(row["width_mm"])
        h = float(row["depth_mm"]) if row["depth_mm"] else float(row["height_mm"])
        b = (x, y, x + w, y + h)
        area += float(row["area_m2"])
        if not has_box(boxes, b):
            fail(f"{where}: {eid} at {b} has no piece of that extent in layout.dxf")
        p = ids.get(eid)
        if p is None or not (near(p[0], x + w / 2) and near(p[1], y + h / 2)):
            fail(f"{where}: {eid}'s ID in layout.dxf is at {p}, not at its centre")
        d = drawn.get(eid)
        if d is None or not all(near(u, v) for u, v in zip(d, b)):
            fail(f"{where}: {eid} is drawn at {d} in install.svg, {b} in the schedule")
        if row["opening_diameter_mm"]:
            dia = float(row["opening_diameter_mm"])
            if not (near(w, dia) and near(h, dia)):
                fail(f"{where}: {eid} is {w} x {h}, its diameter {dia}")
        if row["shape_wkt"] and not row["shape_wkt"].startswith(("POLYGON ((", "MULTIPOLYGON (((")):
            fail(f"{where}: {eid} has shape_wkt {row['shape_wkt'][:40]}")
    laid = sum(float(q["laid_area_m2"]) for q in read_csv(os.path.join(out, "quantities.csv")))
    if abs(laid - area) > 1e-4 * max(1.0, area):
        fail(f"{where}: the schedule's areas add up to {area:.6f} m2, the quantities' to {laid:.6f}")
    # Sheet DXFs are in millimetres from each sheet's corner; the schedule's lot names the sheet.
    if os.path.isdir(sheets):
        by_sheet = {}
        for row in rows:
            by_sheet.setdefault(row["lot"], []).append(row)
        for name, members in by_sheet.items():
            path = os.path.join(sheets, name + ".dxf")
            if not os.path.exists(path):
                fail(f"{where}: no {name}.dxf for its openings")
                continue
            sboxes, sids = dxf_pieces(path)
            for row in members:
                eid = row["element_id"]
                x, y = float(row["x_mm"]), float(row["y_mm"])
                w, h = float(row["width_mm"]), float(row["height_mm"])
                p = sids.get(eid)
                if p is None:
                    fail(f"{where}: {eid} missing from {name}.dxf")
                    continue
                # The sheet's offset, from this element's ID: every other must agree with it.
                ox, oy = x + w / 2 - p[0], y + h / 2 - p[1]
                by_sheet_offset = sheet_offsets.setdefault(name, (ox, oy))
                if not (near(ox, by_sheet_offset[0]) and near(oy, by_sheet_offset[1])):
                    fail(f"{where}: {eid} is off by {(ox, oy)} in {name}.dxf")
                if not has_box(sboxes, (x - ox, y - oy, x - ox + w, y - oy + h)):
                    fail(f"{where}: {eid} has no piece of its extent in {name}.dxf")
    print(f"{where}: {len(rows)} pieces checked")
    return True


def main():
    curdle, recipe, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    for i, corner in enumerate([None] + CORNERS):
        if not check(curdle, recipe, os.path.join(work, f"out{i}"), corner):
            break
    if failures:
        print(f"{len(failures)} disagreements")
        sys.exit(1)


if __name__ == "__main__":
    main()
