#!/usr/bin/python3
"""Sites read from the architect's drawing, judged by ezdxf (an independent DXF reader).

The shipped courtyard and elevation are laid from patterns/sites/*.dxf; the input drawing and
the outputs are read back and compared: the outline's corners and bulges, the tree pit and the
drain in layout.dxf within 0.01 mm of the drawing; every piece of schedule.csv inside the true
outline (within the chord tolerance along the arc, 0.01 mm along straight edges) and off the
pit and drain; the arcs in layout.ifc; the setting-out on sheet 1 by centre and radius; the
report line; the windows of the elevation's blocks as its openings; a perforated screen's sheets
cut along an arch as bulges; and the same courtyard
drawn in m, cm, mm and inches, and saved as SVG, giving byte-identical schedules.

    sites.py CURDLE SOURCE_DIR
"""
import csv
import io
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import ezdxf
import numpy

CURDLE, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
PATTERNS = os.path.join(SOURCE, "patterns")
CHORD = 0.05  # layout.chord_tolerance's default, mm
problems = []


def check(ok, what):
    if not ok:
        problems.append(what)


def generate(recipe, out, *extra):
    return subprocess.run([CURDLE, "generate", recipe, "--out", out, *extra], check=True,
                          capture_output=True, text=True).stdout


def arc_of(a, b, bulge):
    """Centre, radius, start angle and sweep of the edge a -> b with its bulge."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    chord = math.hypot(dx, dy)
    offset = chord * (1 - bulge * bulge) / (4 * bulge)
    centre = ((a[0] + b[0]) / 2 - dy / chord * offset, (a[1] + b[1]) / 2 + dx / chord * offset)
    radius = chord * (1 + bulge * bulge) / (4 * abs(bulge))
    return centre, radius, math.atan2(a[1] - centre[1], a[0] - centre[0]), 4 * math.atan(bulge)


def fine_ring(vertices):
    """The outline with its arcs at 1 µm: what 'inside the true outline' is measured against."""
    ring = []
    for i, (x, y, b) in enumerate(vertices):
        ring.append((x, y))
        if b:
            nx, ny, _ = vertices[(i + 1) % len(vertices)]
            c, r, start, sweep = arc_of((x, y), (nx, ny), b)
            n = 4000
            ring += [(c[0] + r * math.cos(start + sweep * k / n), c[1] + r * math.sin(start + sweep * k / n))
                     for k in range(1, n)]
    return ring


# A ring's edges as numpy arrays (a 4,000-point arc is asked about thousands of corners): edge i
# runs from vertex i - 1 to vertex i.
def edges(ring):
    b = numpy.array(ring, dtype=float)
    a = numpy.roll(b, 1, axis=0)
    return a[:, 0], a[:, 1], b[:, 0], b[:, 1]


def inside(ring_edges, x, y):
    """Even-odd: the edges a ray to +x from (x, y) crosses."""
    ax, ay, bx, by = ring_edges
    spans = (ay > y) != (by > y)
    with numpy.errstate(divide="ignore", invalid="ignore"):
        crossing = x < (bx - ax) * (y - ay) / (by - ay) + ax
    return bool(numpy.count_nonzero(spans & crossing) % 2)


def distance_to(ring_edges, x, y):
    ax, ay, bx, by = ring_edges
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = numpy.clip(((x - ax) * dx + (y - ay) * dy) / numpy.where(length2 == 0, 1, length2), 0, 1)
    return float(numpy.min(numpy.hypot(ax + t * dx - x, ay + t * dy - y)))


def piece_corners(row):
    wkt = row["shape_wkt"]
    if wkt:
        return [(float(a), float(b)) for a, b in re.findall(r"(-?[\d.]+) (-?[\d.]+)", wkt)]
    x, y, w, h = (float(row[k]) for k in ("x_mm", "y_mm", "width_mm", "height_mm"))
    return [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]


def schedule(path):
    with open(path, encoding="utf-8-sig", newline="") as f:
        return list(csv.DictReader(f))


def courtyard(work):
    recipe = os.path.join(PATTERNS, "courtyard-from-dxf.toml")
    out = os.path.join(work, "courtyard")
    said = generate(recipe, out)
    check("site: outline 14,000 x 9,000 mm with 1 arc; 2 zones (TREE_PIT exclude, DRAIN exclude) "
          "from sites/courtyard.dxf, units mm" in said, "the run does not say what it read: " + said[:300])

    drawing = ezdxf.readfile(os.path.join(PATTERNS, "sites", "courtyard.dxf")).modelspace()
    given = drawing.query('LWPOLYLINE[layer=="A-OTLN"]').first
    outline = [(x, y, b) for x, y, _, _, b in given.get_points("xyseb")]
    pit = drawing.query('CIRCLE[layer=="TREE_PIT"]').first
    drain = [(x, y) for x, y in drawing.query('LWPOLYLINE[layer=="DRAIN"]').first.get_points("xy")]

    # layout.dxf: the same outline with the same bulges, the pit a circle, the drain its corners.
    doc = ezdxf.readfile(os.path.join(out, "layout.dxf"))
    check(doc.header["$INSUNITS"] == 4, "layout.dxf is not in millimetres")
    written = doc.modelspace().query('LWPOLYLINE[layer=="OUTLINE"]')
    check(len(written) == 1, f"{len(written)} outlines in layout.dxf")
    back = [(x, y, b) for x, y, _, _, b in written.first.get_points("xyseb")]
    check(len(back) == len(outline), f"outline of {len(back)} corners, drawn with {len(outline)}")
    for (x, y, b), (u, v, c) in zip(outline, back):
        check(math.hypot(x - u, y - v) <= 0.01 and abs(b - c) < 1e-9,
              f"outline corner ({u}, {v}, bulge {c}) is not the drawing's ({x}, {y}, bulge {b})")
    circles = doc.modelspace().query('CIRCLE[layer=="ZONES"]')
    check(len(circles) == 1 and math.hypot(circles.first.dxf.center.x - pit.dxf.center.x,
                                           circles.first.dxf.center.y - pit.dxf.center.y) <= 0.01
          and abs(circles.first.dxf.radius - pit.dxf.radius) <= 0.01, "the tree pit is not the drawing's circle")
    zones = doc.modelspace().query('LWPOLYLINE[layer=="ZONES"]')
    check(len(zones) == 1 and all(min(math.hypot(x - u, y - v) for u, v in zones.first.get_points("xy")) <= 0.01
                                  for x, y in drain), "the drain is not the drawing's")

    # Every piece inside the true outline, off the pit and the drain.
    ring = edges(fine_ring(outline))
    rows = schedule(os.path.join(out, "schedule.csv"))
    worst_out, worst_pit = 0.0, 0.0
    cx, cy, r = pit.dxf.center.x, pit.dxf.center.y, pit.dxf.radius
    for row in rows:
        for x, y in piece_corners(row):
            if not inside(ring, x, y):
                worst_out = max(worst_out, distance_to(ring, x, y))
            worst_pit = max(worst_pit, r - math.hypot(x - cx, y - cy))
            check(not (drain[0][0] + 0.01 < x < drain[1][0] - 0.01 and drain[0][1] + 0.01 < y < drain[2][1] - 0.01),
                  f"{row['element_id']} reaches into the drain")
    check(worst_out <= CHORD + 0.01, f"a piece lies {worst_out:.4f} mm beyond the true outline")
    check(worst_pit <= CHORD + 0.01, f"a piece lies {worst_pit:.4f} mm inside the tree pit")
    report = json.load(open(os.path.join(out, "report.json")))
    pit_area = [z for z in report["layout"]["zones"] if z["name"] == "TREE_PIT"][0]["area_m2"]
    check(abs(pit_area - math.pi * 0.49) < 1e-9, f"the tree pit's area is {pit_area}, not π 0.7²")

    # layout.ifc: one arc on the outline, two half turns round the pit.
    ifc = open(os.path.join(out, "layout.ifc"), encoding="utf-8").read()
    check(ifc.count("IFCARCINDEX(") == 3, f"{ifc.count('IFCARCINDEX(')} arcs in layout.ifc, not 3")
    # Sheet 1 sets the arc and the pit out by centre and radius, and no chord's corner.
    text = subprocess.run(["pdftotext", "-f", "1", "-l", "1", os.path.join(out, "layout.pdf"), "-"],
                          check=True, capture_output=True, text=True).stdout
    for line in ("A1: arc, centre (9000, 21000), radius 13000, from (14000, 9000) to (4000, 9000)",
                 "TREE_PIT: circle, centre (5000, 4000), radius 700"):
        check(line in text, f"sheet 1 does not set out '{line}'")
    check("8605.6" not in text, "sheet 1 still lists the arc's chord corners")
    return rows, out


def units(work, mm_rows_path):
    """The courtyard drawn in m, cm and inches: the same schedule, byte for byte."""
    expected = open(mm_rows_path, "rb").read()
    make = os.path.join(PATTERNS, "sites", "make_sites.py")
    recipe = os.path.join(PATTERNS, "courtyard-from-dxf.toml")
    for unit in ("m", "cm", "in"):
        subprocess.run(["/usr/bin/python3", make, work, "--units", unit], check=True)
        out = os.path.join(work, "in-" + unit)
        generate(recipe, out, "--outputs", "schedule.csv",
                 "--set", f"layout.site.file={os.path.join(work, f'courtyard-{unit}.dxf')}")
        check(open(os.path.join(out, "schedule.csv"), "rb").read() == expected,
              f"the courtyard drawn in {unit} gives another schedule")
    # The same courtyard as Inkscape saves it: layers as labelled groups, y down, an SVG arc.
    out = os.path.join(work, "svg")
    generate(recipe, out, "--outputs", "schedule.csv",
             "--set", f"layout.site.file={os.path.join(PATTERNS, 'sites', 'courtyard.svg')}")
    check(open(os.path.join(out, "schedule.csv"), "rb").read() == expected,
          "the courtyard drawn as SVG gives another schedule")


def elevation(work):
    recipe = os.path.join(PATTERNS, "brick-elevation-from-dxf.toml")
    out = os.path.join(work, "elevation")
    said = generate(recipe, out, "--outputs", "layout.dxf,schedule.csv")
    check("8 openings from sites/elevation.dxf" in said, "the elevation's openings are not 8: " + said[:300])
    # The windows and the door as ezdxf places their blocks: each INSERT's largest closed shape.
    drawing = ezdxf.readfile(os.path.join(PATTERNS, "sites", "elevation.dxf")).modelspace()
    expected = []
    for insert in drawing.query("INSERT"):
        boxes = []
        for e in insert.virtual_entities():
            if e.dxftype() == "LWPOLYLINE" and e.closed:  # in world coordinates: a mirror is an OCS
                xs, ys = zip(*((v.x, v.y) for v in e.vertices_in_wcs()))
                boxes.append((min(xs), min(ys), max(xs), max(ys)))
        expected.append(max(boxes, key=lambda b: (b[2] - b[0]) * (b[3] - b[1])))
    got = []
    for e in ezdxf.readfile(os.path.join(out, "layout.dxf")).modelspace().query('LWPOLYLINE[layer=="OPENINGS"]'):
        xs, ys = zip(*e.get_points("xy"))
        got.append((min(xs), min(ys), max(xs), max(ys)))
    check(len(got) == len(expected) == 8, f"{len(got)} openings in layout.dxf, {len(expected)} in the drawing")
    for box in expected:
        check(any(max(abs(a - b) for a, b in zip(box, g)) <= 0.01 for g in got),
              f"the drawing's opening {box} is not in layout.dxf")
    # No brick over an opening.
    for row in schedule(os.path.join(out, "schedule.csv")):
        for x0, y0, x1, y1 in got:
            for x, y in piece_corners(row):
                check(not (x0 + 0.01 < x < x1 - 0.01 and y0 + 0.01 < y < y1 - 0.01),
                      f"{row['element_id']} lies in an opening")


def arched_screen(work):
    """A perforated screen under an arch: the sheets it crosses are cut along the true arc."""
    out = os.path.join(work, "screen")
    generate(os.path.join(PATTERNS, "perforated-aluminium-screen.toml"), out, "--outputs",
             "sheets", "--set", "layout.outline=[[0,0],[3000,0],[3000,5400,0.3],[0,5400]]")
    half = math.tan(math.atan(0.3) / 2)  # the arch meets the seam at x = 1500: two halves
    for name in ("S-R3-C1", "S-R3-C2"):
        sheet = ezdxf.readfile(os.path.join(out, "sheets", name + ".dxf")).modelspace()
        bulges = [b for e in sheet.query('LWPOLYLINE[layer=="OUTLINE"]')
                  for *_, b in e.get_points("xyseb") if b]
        check(len(bulges) == 1 and abs(bulges[0] - half) < 1e-9,
              f"sheet {name} is not cut along the arch as a bulge of {half:.6f}: {bulges}")


with tempfile.TemporaryDirectory() as work:
    arched_screen(work)
    rows, out = courtyard(work)
    units(work, os.path.join(out, "schedule.csv"))
    elevation(work)
    for p in problems[:20]:
        print("  " + p)
    print(f"sites: arched screen, courtyard ({len(rows)} pieces), 3 other units and SVG, elevation: "
          f"{len(problems)} problems")
    sys.exit(1 if problems else 0)
