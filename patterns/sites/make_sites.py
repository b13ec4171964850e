#!/usr/bin/python3
"""Writes the example site drawings as an architect's CAD would export them (ezdxf, DXF R2013).

courtyard.svg: the same courtyard as Inkscape saves it (layers as labelled groups, mm).

courtyard.dxf: a 14 x 9 m courtyard whose outline (layer A-OTLN) has a notch and an arched
edge (an LWPOLYLINE with a bulge), a round tree pit (a CIRCLE on TREE_PIT), a drain (a thin
closed polyline on DRAIN), and notes and dimensions on layers curdle passes over.

elevation.dxf: a 12 x 6.3 m brick elevation (wall outline on A-WALL) whose windows are
INSERTs of a window block (frame, sash and a glazing bar, on layer 0) on A-GLAZ, and whose
door is a mirrored INSERT of a door block on A-DOOR.

kiosk.dxf: the plan of an 8 x 5 m brick kiosk whose south front bows out on an arc (an
LWPOLYLINE on A-WALL with a bulge of 0.2 on that edge: 800 mm out on its 8 m chord), with a
title on A-ANNO; read as [layout.building.site].

    make_sites.py OUT_DIR [--units mm|cm|m|in]   (the courtyard in other units, for tests)
    make_sites.py OUT_DIR --survey                (survey.dxf and survey.toml, the benchmark's)

survey.dxf: a 60 x 40 m plaza as a surveyor delivers it, 10,003 entities: the boundary (layer
BOUNDARY) a wavy north edge of 5,000 LINEs and an east edge of 1,000 ARCs, 20 round tree pits,
and 3,980 spot levels (TEXT on LEVELS) that curdle passes over.
"""
import math
import sys

import ezdxf

INSUNITS = {"in": 1, "mm": 4, "cm": 5, "m": 6}
MM = {"in": 25.4, "mm": 1.0, "cm": 10.0, "m": 1000.0}


def courtyard(path, units="mm"):
    k = 1.0 / MM[units]
    doc = ezdxf.new("R2013", setup=False)
    doc.header["$INSUNITS"] = INSUNITS[units]
    doc.header["$MEASUREMENT"] = 1
    for name, colour in (("A-OTLN", 7), ("TREE_PIT", 3), ("DRAIN", 5), ("A-ANNO", 2)):
        doc.layers.add(name, color=colour)
    msp = doc.modelspace()
    # Counter-clockwise from the datum; the top edge from (14, 9) to (4, 9) m is an arch that
    # dips 1 m into the courtyard (bulge -0.2 on a 10 m chord); the notch is 4 x 2 m.
    outline = [(0, 0, 0), (14000, 0, 0), (14000, 9000, -0.2), (4000, 9000, 0), (4000, 7000, 0),
               (0, 7000, 0)]
    msp.add_lwpolyline([(x * k, y * k, 0, 0, b) for x, y, b in outline], format="xyseb",
                       close=True, dxfattribs={"layer": "A-OTLN"})
    msp.add_circle((5000 * k, 4000 * k), 700 * k, dxfattribs={"layer": "TREE_PIT"})
    msp.add_lwpolyline([(9000 * k, 1500 * k), (13000 * k, 1500 * k), (13000 * k, 1650 * k),
                        (9000 * k, 1650 * k)], close=True, dxfattribs={"layer": "DRAIN"})
    msp.add_text("COURTYARD", dxfattribs={"layer": "A-ANNO", "height": 250 * k}).set_placement(
        (6000 * k, 5000 * k))
    msp.add_linear_dim(base=(0, -800 * k), p1=(0, 0), p2=(14000 * k, 0),
                       dxfattribs={"layer": "A-ANNO"}).render()
    doc.saveas(path)


def courtyard_svg(path):
    """The same courtyard as Inkscape saves it: mm on the page, a viewBox in mm, y down, one
    layer a group with its inkscape:label, the arch as an SVG arc, the pit a <circle>."""
    # y down from the page's top edge at 9000 mm; the arch: radius 13,000 mm, dipping inwards.
    flip = lambda y: 9000 - y
    svg = f"""<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     width="14000mm" height="9000mm" viewBox="0 0 14000 9000" version="1.1">
  <g inkscape:groupmode="layer" id="layer1" inkscape:label="A-OTLN">
    <path id="outline" style="fill:none;stroke:#000000"
          d="M 0,{flip(0)} H 14000 V {flip(9000)} A 13000,13000 0 0 1 4000,{flip(9000)} V {flip(7000)} H 0 Z"/>
  </g>
  <g inkscape:groupmode="layer" id="layer2" inkscape:label="TREE_PIT">
    <circle id="pit" cx="5000" cy="{flip(4000)}" r="700" style="fill:none;stroke:#008000"/>
  </g>
  <g inkscape:groupmode="layer" id="layer3" inkscape:label="DRAIN" transform="translate(9000,0)">
    <rect id="drain" x="0" y="{flip(1650)}" width="4000" height="150" style="fill:none;stroke:#0000ff"/>
  </g>
  <g inkscape:groupmode="layer" id="layer4" inkscape:label="A-ANNO">
    <text x="6000" y="{flip(5000)}" style="font-size:250px">COURTYARD</text>
  </g>
</svg>
"""
    open(path, "w").write(svg)


def elevation(path):
    doc = ezdxf.new("R2013", setup=False)
    doc.header["$INSUNITS"] = 4
    for name in ("A-WALL", "A-GLAZ", "A-DOOR", "A-ANNO"):
        doc.layers.add(name)
    window = doc.blocks.new("WIN-1200x1500", base_point=(0, 0))
    window.add_lwpolyline([(0, 0), (1200, 0), (1200, 1500), (0, 1500)], close=True)
    window.add_lwpolyline([(50, 50), (1150, 50), (1150, 1450), (50, 1450)], close=True)
    window.add_line((600, 50), (600, 1450))  # the glazing bar
    door = doc.blocks.new("DOOR-1000x2250", base_point=(1000, 0))
    door.add_lwpolyline([(0, 0), (1000, 0), (1000, 2250), (0, 2250)], close=True)
    door.add_arc((0, 0), 1000, 0, 90)  # the swing, drawn as on a plan: inside the frame
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (12000, 0), (12000, 6300), (0, 6300)], close=True,
                       dxfattribs={"layer": "A-WALL"})
    for storey, sill in enumerate((900, 4050)):
        for x in (1500, 4500, 7500, 10500 - 1200 * (storey == 0)):
            if storey == 0 and x == 4500:
                continue  # the door stands there
            msp.add_blockref("WIN-1200x1500", (x, sill), dxfattribs={"layer": "A-GLAZ"})
    # The door, mirrored (hinged on the other side): x scale -1 about its base point.
    msp.add_blockref("DOOR-1000x2250", (4600, 0), dxfattribs={"layer": "A-DOOR", "xscale": -1})
    msp.add_text("SOUTH ELEVATION", dxfattribs={"layer": "A-ANNO", "height": 200}).set_placement(
        (0, -600))
    doc.saveas(path)


def survey(out):
    doc = ezdxf.new("R2013", setup=False)
    doc.header["$INSUNITS"] = 4
    for name in ("BOUNDARY", "TREE_PIT", "LEVELS"):
        doc.layers.add(name)
    msp = doc.modelspace()
    line = {"layer": "BOUNDARY"}
    msp.add_line((0, 0), (60000, 0), dxfattribs=line)
    # The east edge: 1,000 arcs bulging out by 5 mm, 40 mm chords up to (60000, 40000).
    for k in range(1000):
        y0, y1 = 40.0 * k, 40.0 * (k + 1)
        r = (20 ** 2 + 5 ** 2) / 10  # the radius through the chord's ends and its 5 mm sagitta
        cx, cy = 60000 + 5 - r, (y0 + y1) / 2
        half = math.degrees(math.asin(20 / r))
        msp.add_arc((cx, cy), r, -half, half, dxfattribs=line)
    # The north edge: 5,000 lines waving 150 mm about y = 40 m, east to west.
    wave = lambda x: 40000 + 150 * math.sin(x / 2000) if 0 < x < 60000 else 40000
    for k in range(5000):
        x0, x1 = 60000 - 12.0 * k, 60000 - 12.0 * (k + 1)
        msp.add_line((x0, wave(x0)), (x1, wave(x1)), dxfattribs=line)
    msp.add_line((0, 40000), (0, 0), dxfattribs=line)
    for k in range(20):
        msp.add_circle((4000 + 13000 * (k % 5), 6000 + 8000 * (k // 5)), 700, dxfattribs={"layer": "TREE_PIT"})
    for k in range(3980):
        msp.add_text(f"+{12.3 + k / 1000:.3f}", dxfattribs={"layer": "LEVELS", "height": 150}).set_placement(
            (1000 + 1500 * (k % 39), 1000 + 380 * (k // 39)))
    doc.saveas(f"{out}/survey.dxf")
    open(f"{out}/survey.toml", "w").write("""name = "survey"
seed = 1
[lattice]
base = 3
dimension = 2
[[curds]]
name = "dark"
probabilities = ["3/4", "2/3"]
[layout]
kind = "paving"
tile = [600, 600]
joint = 5
[layout.site]
file = "survey.dxf"
outline = "BOUNDARY"
[[layout.site.zones]]
layer = "TREE_PIT"
rule = "exclude"
""")


def kiosk(path):
    doc = ezdxf.new("R2013", setup=False)
    doc.header["$INSUNITS"] = 4
    for name in ("A-WALL", "A-ANNO"):
        doc.layers.add(name)
    msp = doc.modelspace()
    # Counter-clockwise from the south-west corner; the south edge's bulge bows it out.
    msp.add_lwpolyline([(0, 0, 0, 0, 0.2), (8000, 0), (8000, 5000), (0, 5000)], format="xyseb",
                       close=True, dxfattribs={"layer": "A-WALL"})
    msp.add_text("KIOSK - PLAN", dxfattribs={"layer": "A-ANNO", "height": 200}).set_placement(
        (0, 5600))
    doc.saveas(path)


if __name__ == "__main__":
    out = sys.argv[1]
    units = sys.argv[3] if len(sys.argv) > 3 and sys.argv[2] == "--units" else None
    if sys.argv[2:] == ["--survey"]:
        survey(out)
    elif units:
        courtyard(f"{out}/courtyard-{units}.dxf", units)
    else:
        courtyard(f"{out}/courtyard.dxf")
        courtyard_svg(f"{out}/courtyard.svg")
        elevation(f"{out}/elevation.dxf")
        kiosk(f"{out}/kiosk.dxf")
