#!/usr/bin/python3
"""The manual's "From your drawing" picture (docs/layouts.md): the architect's DXF as drawn
(left, every entity of its layers read with ezdxf, in the layer's colour) beside the layout curdle lays from it (right,
its layout.svg), at one scale. Needs rsvg-convert (librsvg2-bin).

    site_picture.py DRAWING.dxf LAYOUT.svg OUT.png
"""
import re
import subprocess
import sys
import tempfile

import ezdxf
from ezdxf import path as dxfpath

drawing, layout_svg, out = sys.argv[1:4]
doc = ezdxf.readfile(drawing)
palette = {1: "#c0392b", 2: "#b7950b", 3: "#1e8449", 4: "#17a589", 5: "#2e86c1", 6: "#8e44ad", 7: "#222"}
shapes, texts = [], []
x0 = y0 = 1e300
x1 = y1 = -1e300
for e in doc.modelspace():
    layer = doc.layers.get(e.dxf.layer)
    colour = palette.get(layer.color if layer else 7, "#222")
    if e.dxftype() in ("LWPOLYLINE", "CIRCLE", "LINE", "ARC", "INSERT"):
        entities = e.virtual_entities() if e.dxftype() == "INSERT" else [e]
        for v in entities:
            points = [(p.x, p.y) for p in dxfpath.make_path(v).flattening(0.5)]
            shapes.append((colour, points, e.dxf.layer))
            for x, y in points:
                x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
    elif e.dxftype() == "TEXT":
        texts.append((colour, e.dxf.insert.x, e.dxf.insert.y, e.dxf.height, e.dxf.text))
margin = 0.08 * max(x1 - x0, y1 - y0)
W, H = x1 - x0 + 2 * margin, y1 - y0 + 2 * margin
body = []
for colour, points, layer in shapes:
    d = " ".join(f"{x - x0 + margin:.1f},{y1 - y + margin:.1f}" for x, y in points)
    body.append(f'<polyline points="{d}" fill="none" stroke="{colour}" stroke-width="{W / 400:.1f}"/>')
for colour, x, y, h, t in texts:
    body.append(f'<text x="{x - x0 + margin:.1f}" y="{y1 - y + margin:.1f}" font-size="{h:.0f}" '
                f'font-family="DejaVu Sans" fill="{colour}">{t}</text>')
labels = {}
for colour, points, layer in shapes:
    labels.setdefault(layer, (colour, points[0]))
for i, (layer, (colour, _)) in enumerate(labels.items()):
    body.append(f'<text x="{margin:.0f}" y="{margin + (i + 1) * W / 40:.0f}" font-size="{W / 45:.0f}" '
                f'font-family="DejaVu Sans" fill="{colour}">layer {layer}</text>')
with tempfile.TemporaryDirectory() as work:
    left = f"{work}/drawing.svg"
    open(left, "w").write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{W:.0f}" height="{H:.0f}" '
                          f'viewBox="0 0 {W:.0f} {H:.0f}"><rect width="100%" height="100%" fill="#fff"/>'
                          + "".join(body) + "</svg>")
    subprocess.run(["rsvg-convert", "-h", "700", left, "-o", f"{work}/left.png"], check=True)
    subprocess.run(["rsvg-convert", "-h", "700", layout_svg, "-o", f"{work}/right.png"], check=True)
    # Side by side, through one more SVG that places both pictures.
    import base64
    def size(png):
        import struct
        data = open(png, "rb").read(24)
        return struct.unpack(">II", data[16:24])
    (lw, lh), (rw, rh) = size(f"{work}/left.png"), size(f"{work}/right.png")
    def image(png, x):
        b64 = base64.b64encode(open(png, "rb").read()).decode()
        return f'<image x="{x}" y="0" width="{size(png)[0]}" height="{size(png)[1]}" href="data:image/png;base64,{b64}"/>'
    both = f"{work}/both.svg"
    open(both, "w").write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{lw + rw + 20}" height="{max(lh, rh)}">'
                          f'<rect width="100%" height="100%" fill="#fff"/>{image(f"{work}/left.png", 0)}'
                          f'{image(f"{work}/right.png", lw + 20)}</svg>')
    subprocess.run(["rsvg-convert", both, "-o", out], check=True)
