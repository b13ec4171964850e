#!/usr/bin/python3
"""A site drawing made as an office makes one, laid with no edit, judged by ezdxf.

The drawing (written here with ezdxf): metres ($INSUNITS 6) on a survey grid at E 530,000
N 180,000, NCS layer names; the outline drawn as a LINE, an ARC, a SPLINE given by fit points
alone and an open LWPOLYLINE with a bulge, on a layer that also holds the neighbouring plot; a
tree-pit block (pit circle, trunk circle, five grille LINEs, a TEXT) inserted three times,
scaled, turned and nested; a channel drain drawn as an open LWPOLYLINE 150 mm wide; a HATCH
over one pit's boundary, a DIMENSION, an MTEXT, a frozen older boundary and a paper-space
sheet.

Checked: the run lays it; the spline edge lies within the chord tolerance of the curve ezdxf
computes from the same fit points (fit_points_to_cad_cv), both ways; each pit is one zone; the
drain is a strip 150 mm wide; the outline picked by a point on the layer that holds two.

    office_site.py CURDLE
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import ezdxf
from ezdxf.addons import iterdxf
import numpy
from ezdxf.math import fit_points_to_cad_cv

CURDLE = os.path.abspath(sys.argv[1])
E, N = 530000.0, 180000.0
# The layout's datum: the outline's bottom-left corner (the west arc bows 3 m out).
DATUM = (E - 3, N)
CHORD = 0.05  # mm, layout.chord_tolerance's default
problems = []


def check(ok, what):
    if not ok:
        problems.append(what)


FIT = [(E + 40, N + 0), (E + 44, N + 8), (E + 41, N + 16), (E + 46, N + 24), (E + 40, N + 30)]


def make_drawing(path):
    doc = ezdxf.new("R2018", setup=True)
    doc.header["$INSUNITS"] = 6
    doc.header["$LUPREC"] = 3
    for name in ("L-SITE-BNDY", "L-PLNT-PITS", "C-DRAN", "L-SITE-BNDY-OLD", "A-ANNO-DIMS", "L-PAVE-HTCH"):
        doc.layers.add(name)
    doc.layers.get("L-SITE-BNDY-OLD").freeze()
    msp = doc.modelspace()
    # The outline: south edge LINE, east edge SPLINE by fit points, north edge open LWPOLYLINE
    # with a bulge, west edge ARC.
    bnd = {"layer": "L-SITE-BNDY"}
    msp.add_line((E + 0, N + 0), (E + 40, N + 0), dxfattribs=bnd)
    msp.add_spline(fit_points=[(x, y, 0) for x, y in FIT], dxfattribs=bnd)
    msp.add_lwpolyline([(E + 40, N + 30, 0.2), (E + 20, N + 30, 0), (E + 0, N + 30, 0)],
                       format="xyb", dxfattribs=bnd)
    # West edge: an arc bowing out through (-3, 15) from (0, 30) to (0, 0).
    r = (15 ** 2 + 3 ** 2) / (2 * 3)
    cx = -3 + r
    half = math.degrees(math.asin(15 / r))
    msp.add_arc((E + cx, N + 15), r, 180 - half, 180 + half, dxfattribs=bnd)
    # The neighbouring plot on the same layer, side by side.
    msp.add_lwpolyline([(E + 60, N), (E + 80, N), (E + 80, N + 30), (E + 60, N + 30)], close=True, dxfattribs=bnd)
    # The older boundary, frozen.
    msp.add_lwpolyline([(E - 5, N - 5), (E + 50, N - 5), (E + 50, N + 35), (E - 5, N + 35)], close=True,
                       dxfattribs={"layer": "L-SITE-BNDY-OLD"})
    # The tree pit: 1.5 m pit, 0.4 m trunk, five grille lines and a label, in metres.
    pit = doc.blocks.new("PIT")
    pit.add_circle((0, 0), 0.75)
    pit.add_circle((0, 0), 0.2)
    for k in range(5):
        y = -0.5 + 0.25 * k
        pit.add_line((-math.sqrt(0.75 ** 2 - y * y) + 0.05, y), (math.sqrt(0.75 ** 2 - y * y) - 0.05, y))
    pit.add_text("TREE", dxfattribs={"height": 0.1})
    pits = doc.blocks.new("PIT-PAIR")
    pits.add_blockref("PIT", (0, 0))
    pits.add_blockref("PIT", (6, 0), dxfattribs={"xscale": 1.2, "yscale": 1.2})
    pit_layer = {"layer": "L-PLNT-PITS"}
    msp.add_blockref("PIT", (E + 8, N + 8), dxfattribs={**pit_layer, "rotation": 30})
    msp.add_blockref("PIT-PAIR", (E + 14, N + 20), dxfattribs=pit_layer)
    # A hatch over the first pit's boundary, on the pits' layer.
    hatch = msp.add_hatch(dxfattribs=pit_layer)
    hatch.paths.add_edge_path().add_arc((E + 8, N + 8), 0.75, 0, 360)
    # The drain: an open polyline 150 mm wide.
    msp.add_lwpolyline([(E + 5, N + 3), (E + 30, N + 3), (E + 30, N + 12)],
                       dxfattribs={"layer": "C-DRAN", "const_width": 0.15})
    # Annotation: a dimension, a note, and a paper-space sheet.
    dim = msp.add_linear_dim(base=(E, N - 2), p1=(E, N), p2=(E + 40, N), dxfattribs={"layer": "A-ANNO-DIMS"})
    dim.render()
    msp.add_mtext("Site boundary per survey", dxfattribs={"layer": "A-ANNO-DIMS", "insert": (E, N + 35)})
    doc.layout("Layout1").add_lwpolyline([(0, 0), (420, 0), (420, 297), (0, 297)], close=True,
                                          dxfattribs={"layer": "L-SITE-BNDY"})
    doc.saveas(path)


RECIPE = """
name = "office-site"
seed = 7

[lattice]
base = 3
dimension = 2
mode = "canonical"

[[curds]]
name = "dark"
probabilities = ["3/4", "2/3"]
colour = "#4f5559"

[layout]
kind = "paving"
tile = [1200, 1200]
joint = 5
colours = ["#cfcac0", "#4f5559"]

[layout.site]
file = "site.dxf"
outline = {{ layer = "L-SITE-BNDY", around = [{x}, {y}] }}
[[layout.site.zones]]
layer = "L-PLNT-PITS"
rule = "exclude"
[[layout.site.zones]]
layer = "C-DRAN"
rule = "exclude"
"""


def spline_curve():
    """ezdxf's curve through the same fit points, finely, in mm from the datum."""
    cv = fit_points_to_cad_cv([(x, y, 0) for x, y in FIT])
    return [((p.x - DATUM[0]) * 1000, (p.y - DATUM[1]) * 1000) for p in cv.approximate(20000)]


def distance_to_polyline(points, x, y):
    """The distance from (x, y) to the polyline through `points` (numpy, all segments at once)."""
    p = points if isinstance(points, numpy.ndarray) else numpy.asarray(points, dtype=float)
    a, d = p[:-1], p[1:] - p[:-1]
    length2 = numpy.maximum((d * d).sum(axis=1), 1e-300)
    t = numpy.clip(((x - a[:, 0]) * d[:, 0] + (y - a[:, 1]) * d[:, 1]) / length2, 0.0, 1.0)
    return float(numpy.hypot(a[:, 0] + t * d[:, 0] - x, a[:, 1] + t * d[:, 1] - y).min())


def main():
    work = tempfile.mkdtemp(prefix="office-site-")
    make_drawing(os.path.join(work, "site.dxf"))
    with open(os.path.join(work, "site.toml"), "w") as f:
        f.write(RECIPE.format(x=E + 20, y=N + 15))
    out = os.path.join(work, "out")
    run = subprocess.run([CURDLE, "generate", os.path.join(work, "site.toml"), "--out", out, "--outputs",
                          "report.json,layout.dxf,layout-site.dxf,layout.pdf"], capture_output=True, text=True)
    said = run.stdout + run.stderr
    if run.returncode != 0:
        print("the office site was refused:\n" + said)
        return 1
    check("3 L-PLNT-PITS exclude" in said, "the pits are not three zones: " + said[:600])
    check("C-DRAN exclude" in said, "the drain is not a zone: " + said[:600])
    check("splines given by fit points" in said, "the note does not say the spline was fitted")
    check("closed shapes inside others passed over" in said, "the trunks are not said passed over")

    # Only the outline and the zones are read (ezdxf's streaming reader: the tiles are many).
    with open(os.path.join(out, "layout.dxf"), "rb") as f:
        wanted = [e for e in iterdxf.single_pass_modelspace(f, types=["LWPOLYLINE", "CIRCLE"])
                  if e.dxf.layer in ("OUTLINE", "ZONES")]
    outline = [e for e in wanted if e.dxftype() == "LWPOLYLINE" and e.dxf.layer == "OUTLINE"]
    check(len(outline) == 1, f"{len(outline)} outlines in layout.dxf")
    ring = [(x, y) for x, y in outline[0].get_points("xy")]
    # The east edge: outline vertices with x above 40 m lie on the spline.
    curve = numpy.asarray(spline_curve(), dtype=float)
    east = [(x, y) for x, y in ring if x > 42999]
    check(len(east) > 10, f"the spline edge has only {len(east)} vertices")
    worst = max(distance_to_polyline(curve, x, y) for x, y in east)
    check(worst <= 0.001, f"an outline vertex lies {worst:.4f} mm off ezdxf's spline")
    ring_closed = numpy.asarray(ring + ring[:1], dtype=float)
    worst_back = max(distance_to_polyline(ring_closed, x, y) for x, y in curve[::10])
    check(worst_back <= CHORD + 0.001, f"ezdxf's spline strays {worst_back:.4f} mm from the outline")

    # The zones: three circles for the pits (no trunk), the drain a strip 150 mm wide.
    circles = [e for e in wanted if e.dxftype() == "CIRCLE" and e.dxf.layer == "ZONES"]
    radii = sorted(round(c.dxf.radius, 3) for c in circles)
    check(radii == [750.0, 750.0, 900.0], f"the pits' circles are {radii}, not 750, 750 and 900 mm")
    strips = [e for e in wanted if e.dxftype() == "LWPOLYLINE" and e.dxf.layer == "ZONES"]
    check(len(strips) == 1, f"{len(strips)} strips for the drain")
    if strips:
        pts = [(x, y) for x, y in strips[0].get_points("xy")]
        area = 0.5 * abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1])))
        check(abs(area - 150 * (25000 + 9000)) < 1, f"the drain covers {area:.0f} mm², not 150 x 34,000")
    back_onto_the_drawing(work, out)
    from_inkscape(work, said)
    georeferenced_from_the_drawing(work)
    if problems:
        print("\n".join(problems))
        return 1
    print("the office site lays as drawn: spline within %.4f mm of ezdxf's curve" % worst_back)
    return 0


def back_onto_the_drawing(work, out):
    """layout-site.dxf overlays site.dxf at (0, 0, 0), scale 1: in metres at the survey grid."""
    with open(os.path.join(out, "layout-site.dxf"), "rb") as f:
        header = f.read(4000).decode("utf-8", "replace")
    check("$INSUNITS\n 70\n6" in header.replace("\r", "") or "$INSUNITS\n70\n6" in header.replace("\r", ""),
          "layout-site.dxf is not in metres")
    with open(os.path.join(out, "layout-site.dxf"), "rb") as f:
        wanted = [e for e in iterdxf.single_pass_modelspace(f, types=["LWPOLYLINE", "CIRCLE"])
                  if e.dxf.layer in ("OUTLINE", "ZONES")]
    outline = [e for e in wanted if e.dxftype() == "LWPOLYLINE" and e.dxf.layer == "OUTLINE"]
    check(len(outline) == 1, "layout-site.dxf has no outline")
    if not outline:
        return
    ring = numpy.asarray([(x, y) for x, y in outline[0].get_points("xy")], dtype=float)
    source = ezdxf.readfile(os.path.join(work, "site.dxf")).modelspace()
    corners = [(E, N), (E + 40, N), (E + 40, N + 30), (E + 20, N + 30), (E, N + 30)]
    worst = max(float(numpy.hypot(ring[:, 0] - x, ring[:, 1] - y).min()) for x, y in corners)
    check(worst * 1000 <= 0.01, f"layout-site.dxf's outline lies {worst * 1000:.4f} mm off the drawing's corners")
    pits = [(i.dxf.insert.x, i.dxf.insert.y) for i in source.query('INSERT[layer=="L-PLNT-PITS"]')
            if i.dxf.name == "PIT"]
    circles = [e for e in wanted if e.dxftype() == "CIRCLE" and e.dxf.layer == "ZONES"]
    for x, y in pits:
        near = min((math.hypot(c.dxf.center.x - x, c.dxf.center.y - y) for c in circles), default=1)
        check(near * 1000 <= 0.01, f"the pit at ({x}, {y}) lies {near * 1000:.4f} mm off in layout-site.dxf")
    report = json.load(open(os.path.join(out, "report.json")))
    site = report["layout"].get("site_drawing", {})
    check(site.get("datum") == [E - 3, N] and site.get("units") == "m",
          f"report.json does not give the datum's survey coordinates: {site}")
    text = subprocess.run(["pdftotext", "-f", "1", "-l", "1", os.path.join(out, "layout.pdf"), "-"],
                          capture_output=True, text=True).stdout
    check("datum (0, 0) = E 529,997.000 N 180,000.000 m in site.dxf" in " ".join(text.split()),
          "sheet 1 does not state the datum's survey coordinates")
    # One zone, and so one label, a pit: the trunks inside them are no zones of their own.
    check("L-PLNT-PITS 3" in text and "L-PLNT-PITS 4" not in text,
          "sheet 1 does not label each of the three pits once")


def inkscape_svg(path):
    """The same site as Inkscape saves it: mm user units, y down, a layer a group with
    inkscape:groupmode="layer" and its label, inner groups with automatic ids (the pits split over
    two), the spline edge as the Bézier curves ezdxf decomposes it into."""
    h = 35000.0  # the page's height, mm: y is turned down from it

    def p(x, y):  # drawing metres on the grid to the page's mm
        return f"{(x - DATUM[0]) * 1000:.4f},{h - (y - DATUM[1]) * 1000:.4f}"

    spline = fit_points_to_cad_cv([(x, y, 0) for x, y in FIT])
    curve = " ".join("C " + " ".join(p(q.x, q.y) for q in seg[1:]) for seg in spline.bezier_decomposition())
    r = (15 ** 2 + 3 ** 2) / (2 * 3) * 1000
    # North edge: the LWPOLYLINE's arc (bulge 0.2 over 20 m) then a line; west edge: the arc.
    north_r = 20000 * (1 + 0.2 ** 2) / (4 * 0.2)
    outline = (f"M {p(E, N)} L {p(E + 40, N)} {curve} A {north_r:.4f},{north_r:.4f} 0 0 0 {p(E + 20, N + 30)} "
               f"L {p(E, N + 30)} A {r:.4f},{r:.4f} 0 0 0 {p(E, N)} Z")
    pit = lambda x, y, rr: (f'<circle cx="{(x - DATUM[0]) * 1000:.4f}" cy="{h - (y - DATUM[1]) * 1000:.4f}" r="{rr}"/>'
                            f'<circle cx="{(x - DATUM[0]) * 1000:.4f}" cy="{h - (y - DATUM[1]) * 1000:.4f}" r="200"/>')
    drain = " ".join(p(x, y) for x, y in [(E + 5, N + 2.925), (E + 30.075, N + 2.925), (E + 30.075, N + 12),
                                          (E + 29.925, N + 12), (E + 29.925, N + 3.075), (E + 5, N + 3.075)])
    svg = f"""<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     width="50000mm" height="{h:.0f}mm" viewBox="0 0 50000 {h:.0f}">
  <g inkscape:groupmode="layer" inkscape:label="L-SITE-BNDY" id="layer1">
    <g id="g640"><path id="path641" d="{outline}" fill="none" stroke="black"/></g>
  </g>
  <g inkscape:groupmode="layer" inkscape:label="L-PLNT-PITS" id="layer2">
    <g id="g812">{pit(E + 8, N + 8, 750)}{pit(E + 14, N + 20, 750)}</g>
    <g id="g900"><g id="g901">{pit(E + 20, N + 20, 900)}</g></g>
  </g>
  <g inkscape:groupmode="layer" inkscape:label="C-DRAN" id="layer3"><path id="path77" d="M {drain} Z"/></g>
  <text x="10" y="10">Site plan</text>
</svg>
"""
    with open(path, "w") as f:
        f.write(svg)


def from_inkscape(work, said_from_dxf):
    """The same site from Inkscape's SVG, by its layers' labels: the same outline, pits and drain."""
    inkscape_svg(os.path.join(work, "site.svg"))
    with open(os.path.join(work, "site.toml")) as f:
        recipe = f.read()
    recipe = re.sub(r'outline = \{[^}]*\}', 'outline = "L-SITE-BNDY"', recipe).replace('"site.dxf"', '"site.svg"')
    with open(os.path.join(work, "svg.toml"), "w") as f:
        f.write(recipe)
    run = subprocess.run([CURDLE, "generate", os.path.join(work, "svg.toml"), "--out", os.path.join(work, "svg"),
                          "--outputs", "report.json"], capture_output=True, text=True)
    said = run.stdout + run.stderr
    check(run.returncode == 0, "Inkscape's SVG of the site is refused: " + said[:400])
    if run.returncode != 0:
        return
    check("3 L-PLNT-PITS exclude" in said and "C-DRAN exclude" in said,
          "the SVG's pits or drain are not read by their layers' labels: " + said[:400])
    size = lambda text: re.search(r"outline ([\d,.]+) x ([\d,.]+) mm", text)
    a, b = size(said_from_dxf), size(said)
    check(a and b and all(abs(float(a.group(k).replace(",", "")) - float(b.group(k).replace(",", ""))) < 0.2
                          for k in (1, 2)),
          f"the SVG's outline ({b and b.group(0)}) is not the DXF's ({a and a.group(0)})")


def georeferenced_from_the_drawing(work):
    """[layout.georef] from = "site": layout.gpkg at the drawing's grid coordinates."""
    with open(os.path.join(work, "site.toml")) as f:
        recipe = f.read()
    with open(os.path.join(work, "georef.toml"), "w") as f:
        f.write(recipe + '\n[layout.georef]\nepsg = 27700\nfrom = "site"\n')
    out = os.path.join(work, "georef")
    run = subprocess.run([CURDLE, "generate", os.path.join(work, "georef.toml"), "--out", out,
                          "--outputs", "layout.gpkg"], capture_output=True, text=True)
    check(run.returncode == 0, "the georeferenced run failed: " + run.stderr[:300])
    if run.returncode != 0:
        return
    from osgeo import ogr
    ds = ogr.Open(os.path.join(out, "layout.gpkg"))
    x0, x1, y0, y1 = ds.GetLayer(0).GetExtent()
    check(abs(x0 - (E - 3)) < 5 and abs(y0 - N) < 5 and x1 < E + 50 and y1 < N + 35,
          f"layout.gpkg lies at E {x0:.1f}..{x1:.1f} N {y0:.1f}..{y1:.1f}, not on the drawing's grid")


if __name__ == "__main__":
    sys.exit(main())
