"""Every piece agrees across schedule.csv, layout.dxf, layout.glb, layout.svg, install.svg and
the sheet DXFs.

For one recipe and every origin corner its layout kind takes, runs `curdle generate` and checks
each element of schedule.csv against the other files within 0.01 mm: the DXF's piece on its
material layer (bounding box, or circle) and its ID on layer ID at the piece's centre; the glTF
node named by its ID (the extent of its boxes, or an opening's centre); its ID in layout.svg;
the installer's map's drawing of the element; a perforation's sheet DXF. Also that the DXF is in
millimetres (AutoCAD 2007, $INSUNITS 4) and audits clean, and that the schedule's areas add up
to the quantities' laid areas.

Usage: pieces_agree.py CURDLE WORKDIR RECIPE[@CORNER,CORNER,...][|KEY=VALUE...] ...
(Debian's python3 with python3-ezdxf; each recipe at every corner unless some are named after
an @, or at its own where the kind takes none; each KEY=VALUE after a | is a --set of its runs;
several recipes in one process, so that Python and ezdxf start once)
"""
import csv
import json
import os
import struct
import tomllib
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


def drawn_extents(doc):
    """The extents of everything drawn but text. Circles and straight polylines (most of a
    layout) are measured here, exactly; ezdxf measures the rest (its path for a circle took a
    quarter of this check's time)."""
    from ezdxf import bbox
    own, rest = bbox.BoundingBox(), []
    for e in doc.modelspace():
        t = e.dxftype()
        if t == "CIRCLE":
            c, r = e.dxf.center, e.dxf.radius
            own.extend([(c[0] - r, c[1] - r), (c[0] + r, c[1] + r)])
        elif t == "LWPOLYLINE" and not e.has_arc:
            own.extend(e.get_points("xy"))
        elif t != "TEXT":
            rest.append(e)
    if rest:
        other = bbox.extents(rest, fast=True)
        if other.has_data:
            own.extend([other.extmin, other.extmax])
    return own


def dxf_pieces(path, dx=0.0, dy=0.0):
    """Pieces by layer (bounding boxes and circles) and ID positions of one DXF."""
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    if auditor.errors or auditor.fixes:
        fail(f"{path}: ezdxf audit found {len(auditor.errors)} errors, {len(auditor.fixes)} fixes")
    if doc.dxfversion < "AC1021":
        fail(f"{path}: DXF {doc.dxfversion}, not AutoCAD 2007 or later (UTF-8 text)")
    if doc.header.get("$INSUNITS") != 4:
        fail(f"{path}: $INSUNITS is {doc.header.get('$INSUNITS')}, not 4 (millimetres)")
    # The header's extents are the drawing's: what CAD zooms to fits what is drawn (geometry;
    # text is measured by each program its own way, so within 3 % of the drawing's size).
    if "$EXTMIN" in doc.header and dx == 0 and dy == 0:
        drawn = drawn_extents(doc)
        lo, hi = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
        size = max(drawn.size.x, drawn.size.y)
        if drawn.has_data and (lo[0] > drawn.extmin.x + 1e-6 or lo[1] > drawn.extmin.y + 1e-6 or
                               hi[0] < drawn.extmax.x - 1e-6 or hi[1] < drawn.extmax.y - 1e-6 or
                               hi[0] - lo[0] > drawn.size.x + 0.03 * size or
                               hi[1] - lo[1] > drawn.size.y + 0.03 * size + 3 * size / 100):
            fail(f"{path}: header extents {tuple(lo)[:2]} to {tuple(hi)[:2]}, but the drawing "
                 f"spans {tuple(drawn.extmin)[:2]} to {tuple(drawn.extmax)[:2]}")
    layer = doc.layers.get("ID")
    if layer is None or layer.dxf.get("plot", 1) != 0:
        fail(f"{path}: the ID layer is missing or plots")
    boxes, ids = {}, {}
    for e in doc.modelspace():
        t = e.dxftype()
        if t == "TEXT" and e.dxf.layer == "ID":
            p = e.dxf.align_point
            ids[e.dxf.text] = (p[0] + dx, p[1] + dy)
        elif t == "LWPOLYLINE" and e.dxf.layer not in ("OUTLINE", "OPENINGS", "ZONES"):
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


def has_parts(boxes, b):
    """A piece in parts (a MULTIPOLYGON: a sett cut in two by a tree pit) is one polyline a
    part: the parts lying in its extent must span it exactly."""
    inside = [c for key in range(round(b[0]) - 1, round(b[2]) + 2) for c in boxes.get(key, [])
              if c[0] > b[0] - 0.01 and c[1] > b[1] - 0.01 and c[2] < b[2] + 0.01 and c[3] < b[3] + 0.01]
    if len(inside) < 2:
        return False
    span = (min(c[0] for c in inside), min(c[1] for c in inside),
            max(c[2] for c in inside), max(c[3] for c in inside))
    return all(near(u, v) for u, v in zip(b, span))


def wkt_boxes(wkt):
    """The box of each polygon of a WKT MULTIPOLYGON (its outer ring's points)."""
    out = []
    for polygon in re.findall(r"\(\(([^()]*)\)", wkt):
        pts = [tuple(map(float, p.split())) for p in polygon.split(",")]
        out.append(box_of_points(pts))
    return out


def install_boxes(path):
    """Each element's extent in install.svg, layout millimetres: the drawing's units are layout
    millimetres (drawn at the installer's scale through its size), the layout's frame its first
    rectangle, y running down."""
    text = open(path, encoding="utf-8").read()
    outline = re.search(r'<rect x="([-\d.]+)" y="([-\d.]+)" width="([-\d.]+)" height="([-\d.]+)"', text)
    left, top = float(outline.group(1)), float(outline.group(2)) + float(outline.group(4))
    out = {}
    for m in re.finditer(r'<g id="([^"]+)" class="element"[^>]*>(.*?)</g>', text):
        pts = []
        for r in re.finditer(r'<rect x="([-\d.]+)" y="([-\d.]+)" width="([-\d.]+)" height="([-\d.]+)"', m.group(2)):
            x, y, w, h = map(float, r.groups())
            pts += [(x - left, top - y - h), (x - left + w, top - y)]
        for path in re.finditer(r'<path d="([^"]+)"', m.group(2)):
            for px, py in re.findall(r'[ML]([-\d.]+) ([-\d.]+)', path.group(1)):
                pts.append((float(px) - left, top - float(py)))
        for c in re.finditer(r'<circle cx="([-\d.]+)" cy="([-\d.]+)" r="([-\d.]+)"', m.group(2)):
            cx, cy, r = map(float, c.groups())
            x, y = cx - left, top - cy
            pts += [(x - r, y - r), (x + r, y + r)]
        out[m.group(1)] = box_of_points(pts)
    return out


def glb_nodes(path, upright):
    """Per named node of a binary glTF: its extent in layout millimetres from its meshes' bounds
    (boxes, trees), or its position when it has no mesh (an opening), as (x0, y0, x1, y1)."""
    data = open(path, "rb").read()
    length, kind = struct.unpack_from("<I4s", data, 12)
    doc = json.loads(data[20:20 + length])
    nodes, meshes, accessors = doc["nodes"], doc.get("meshes", []), doc["accessors"]

    def to_mm(p):  # glTF metres to layout millimetres: x right, y up the wall or into the floor
        return (p[0] * 1000, p[1] * 1000) if upright else (p[0] * 1000, -p[2] * 1000)

    def extent(index, offset, scale, pts):
        n = nodes[index]
        t, s = n.get("translation", [0, 0, 0]), n.get("scale", [1, 1, 1])
        o = [offset[i] + scale[i] * t[i] for i in range(3)]
        sc = [scale[i] * s[i] for i in range(3)]
        if "mesh" in n and "scale" in n:  # a unit box (a block may show only some faces)
            for corner in (-0.5, 0.5):
                pts.append(to_mm([o[i] + sc[i] * corner for i in range(3)]))
        elif "mesh" in n:
            for prim in meshes[n["mesh"]]["primitives"]:
                a = accessors[prim["attributes"]["POSITION"]]
                for corner in ((a["min"], a["max"]), (a["max"], a["min"])):
                    pts.append(to_mm([o[i] + sc[i] * corner[0][i] for i in range(3)]))
        for c in n.get("children", []):
            extent(c, o, sc, pts)
        return o

    out = {}
    for root in doc["scenes"][0]["nodes"]:
        name = nodes[root].get("name")
        if not name:
            continue
        pts = []
        o = extent(root, [0, 0, 0], [1, 1, 1], pts)
        out[name] = box_of_points(pts) if pts else to_mm(o) * 2
    return out


def glb_markers(path):
    """Per named node of a binary glTF that has no mesh (a screen's opening, marked at the
    middle of its face): its place in building millimetres (x east, y north, z up)."""
    data = open(path, "rb").read()
    length, _ = struct.unpack_from("<I4s", data, 12)
    doc = json.loads(data[20:20 + length])
    return {n["name"]: (n["translation"][0] * 1000, -n["translation"][2] * 1000,
                        n["translation"][1] * 1000)
            for n in doc["nodes"] if n.get("name") and "mesh" not in n and "translation" in n}


def glb_faces(path):
    """Per named node of a building's binary glTF: the outer face of each of its boxes, as
    (centre, along, half length, half height) in building millimetres (x east, y north, z up):
    a unit box turned about the vertical, its local +z the outside; or, for a corner unit's
    prism (a mesh moved by its node), each of its upright walls likewise."""
    import math
    data = open(path, "rb").read()
    length, _ = struct.unpack_from("<I4s", data, 12)
    doc = json.loads(data[20:20 + length])
    nodes = doc["nodes"]
    binary = data[20 + length + 8:]

    def read(accessor, width):
        a = doc["accessors"][accessor]
        view = doc["bufferViews"][a["bufferView"]]
        at = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        form = {5126: "f", 5125: "I", 5123: "H"}[a["componentType"]]
        size = {"SCALAR": 1, "VEC3": 3}[a["type"]]
        flat = struct.unpack_from(f"<{a['count'] * size}{form}", binary, at)
        return [flat[k:k + width] for k in range(0, len(flat), width)]

    mesh_walls = {}  # mesh index: its walls about the node's origin (many nodes share a mesh)

    def walls_of(mesh):
        walls = []
        for prim in doc["meshes"][mesh]["primitives"]:
            pos = read(prim["attributes"]["POSITION"], 3)
            tris = read(prim["indices"], 3)
            for a, b, c in tris:
                pts = [(pos[v][0] * 1000, -pos[v][2] * 1000, pos[v][1] * 1000) for v in (a, b, c)]
                zs = (pts[0][2], pts[1][2], pts[2][2])
                if max(zs) - min(zs) < 1e-6:
                    continue  # a cap
                # An upright triangle: its wall's horizontal extent (its longest edge in plan)
                # and height.
                span, i, j = max(((math.dist(pts[i][:2], pts[j][:2]), i, j)
                                  for i, j in ((0, 1), (0, 2), (1, 2))), key=lambda e: e[0])
                if span < 1e-6:
                    continue
                along = ((pts[j][0] - pts[i][0]) / span, (pts[j][1] - pts[i][1]) / span)
                centre = ((pts[i][0] + pts[j][0]) / 2, (pts[i][1] + pts[j][1]) / 2,
                          (max(zs) + min(zs)) / 2)
                walls.append((centre, along, span / 2, (max(zs) - min(zs)) / 2))
        return walls

    def prism_walls(n, out):
        t = n["translation"]
        if n["mesh"] not in mesh_walls:
            mesh_walls[n["mesh"]] = walls_of(n["mesh"])
        shift = (t[0] * 1000, -t[2] * 1000, t[1] * 1000)
        for centre, along, half_l, half_h in mesh_walls[n["mesh"]]:
            out.append(((centre[0] + shift[0], centre[1] + shift[1], centre[2] + shift[2]),
                        along, half_l, half_h))

    def faces(index, out):
        n = nodes[index]
        if "mesh" in n and "scale" not in n and "translation" in n:
            prism_walls(n, out)
        elif "mesh" in n and "scale" in n:
            t, s, q = n["translation"], n["scale"], n.get("rotation", [0, 0, 0, 1])
            turn = 2 * math.atan2(q[1], q[3])
            along = (math.cos(turn), math.sin(turn))        # plan x east, y north
            outward = (along[1], -along[0])
            centre = (t[0] * 1000 + outward[0] * s[2] * 500, -t[2] * 1000 + outward[1] * s[2] * 500,
                      t[1] * 1000)
            out.append((centre, along, s[0] * 500, s[1] * 500))
        for c in n.get("children", []):
            faces(c, out)
        return out

    return {nodes[r]["name"]: faces(r, []) for r in doc["scenes"][0]["nodes"] if nodes[r].get("name")}


def on_a_face(point, faces, exact):
    """Whether a schedule position lies on one of a unit's outer faces (at its centre when the
    unit is one box)."""
    for centre, along, half_l, half_h in faces:
        d = [point[i] - centre[i] for i in range(3)]
        u = d[0] * along[0] + d[1] * along[1]
        off = d[0] * -along[1] + d[1] * along[0]  # across the face: 0 on it
        if abs(off) <= TOL and abs(d[2]) <= half_h + TOL and (
                abs(u) <= TOL if exact else abs(u) <= half_l + TOL):
            return True
    return False


def svg_ids(path):
    """Element IDs named in layout.svg: by id, in data-elements lists, and in ranges first:last."""
    text = open(path, encoding="utf-8").read()
    ids = set(re.findall(r' id="([A-Z]-[^"]+)"', text))
    ranges = []
    for listed in re.findall(r'data-elements="([^"]+)"', text):
        for item in listed.split():
            if ":" in item:
                ranges.append(item.split(":"))
            else:
                ids.add(item)
    return ids, ranges


ID = re.compile(r"([A-Z])-R(\d+)-C(\d+)(-.+)?")


def ids_in_ranges(ranges):
    """The (kind, part, row, column) of every element in merged runs first:last (rows and
    columns inclusive, one kind and part)."""
    out = set()
    for first, last in ranges:
        a, b = ID.fullmatch(first), ID.fullmatch(last)
        if not (a and b and a.group(1) == b.group(1) and a.group(4) == b.group(4)):
            fail(f"layout.svg: a run {first}:{last} that is not one kind")
            continue
        for r in range(int(a.group(2)), int(b.group(2)) + 1):
            for c in range(int(a.group(3)), int(b.group(3)) + 1):
                out.add((a.group(1), a.group(4), r, c))
    return out


def in_runs(eid, runs):
    m = ID.fullmatch(eid)
    return bool(m) and (m.group(1), m.group(4), int(m.group(2)), int(m.group(3))) in runs


def check(curdle, recipe, out, corner, sets=()):
    with open(recipe, "rb") as f:
        kind = tomllib.load(f).get("layout", {}).get("kind", "tile")
    outputs = "schedule.csv,quantities.csv,layout.dxf,layout.glb,layout.svg,install.svg,sheets"
    args = [curdle, "generate", recipe, "--out", out,
            "--outputs", outputs + (",punching.csv" if kind == "perforation" else "")]
    for s in sets:
        args += ["--set", s]
    if corner:
        args += ["--set", f'layout.origin="{corner}"']
    run = subprocess.run(args, capture_output=True, text=True)
    if run.returncode != 0:
        fail(f"{' '.join(args)}: exit {run.returncode}: {run.stderr.strip()}")
        return
    where = f"{os.path.basename(recipe)} origin {corner or 'default'}"
    rows = read_csv(os.path.join(out, "schedule.csv"))
    boxes, ids = dxf_pieces(os.path.join(out, "layout.dxf"))
    drawn = install_boxes(os.path.join(out, "install.svg"))
    building = "building" in layout_table(recipe)
    modelled = glb_nodes(os.path.join(out, "layout.glb"), kind in ("facade", "façade", "rhythm", "perforation"))
    faces = glb_faces(os.path.join(out, "layout.glb")) if building else {}
    markers = glb_markers(os.path.join(out, "layout.glb")) if building else {}
    named, ranges = svg_ids(os.path.join(out, "layout.svg"))
    runs = ids_in_ranges(ranges)
    sheet_offsets = {}
    sheets = os.path.join(out, "sheets")
    area = 0.0
    for row in rows:
        eid = row["element_id"]
        x, y, w = float(row["x_mm"]), float(row["y_mm"]), float(row["width_mm"])
        if building:  # x, y, z in the building; the strip's drawings from strip_x, strip_y
            point = (x, y, float(row["z_mm"]))
            f = faces.get(eid, [])
            if row["element_type"] == "opening":  # a screen's: its node marks its face's middle
                m = markers.get(eid)
                if m is None or max(abs(u - v) for u, v in zip(m, point)) > 0.01:
                    fail(f"{where}: {eid} at {point} in the schedule is marked at {m} in "
                         f"layout.glb")
            elif not on_a_face(point, f, len(f) == 1):
                fail(f"{where}: {eid} at {point} in the schedule is on no face of its node in "
                     f"layout.glb")
            x, y = float(row["strip_x_mm"]), float(row["strip_y_mm"])
        h = float(row["depth_mm"]) if row["depth_mm"] else float(row["height_mm"])
        b = (x, y, x + w, y + h)
        area += float(row["area_m2"])
        parts = row["shape_wkt"].startswith("MULTIPOLYGON")
        label = b
        if building and parts:
            # A unit round the closing corner: one brick in the schedule (its box runs on past
            # the strip's end), two parts at the strip's ends in the drawings, labelled on the
            # larger.
            pieces = wkt_boxes(row["shape_wkt"])
            if x + w > max(q[2] for q in pieces) + 0.01:
                b = box_of_points([(q[0], q[1]) for q in pieces] + [(q[2], q[3]) for q in pieces])
                label = max(pieces, key=lambda q: (q[2] - q[0]) * (q[3] - q[1]))
                if not near(sum(q[2] - q[0] for q in pieces), w):
                    fail(f"{where}: {eid}'s parts are {pieces}, not {w} mm along the strip")
        if not (has_parts(boxes, b) if parts else has_box(boxes, b)):
            fail(f"{where}: {eid} at {b} has no piece of that extent in layout.dxf")
        p = ids.get(eid)
        if p is None or not (near(p[0], (label[0] + label[2]) / 2) and near(p[1], (label[1] + label[3]) / 2)):
            fail(f"{where}: {eid}'s ID in layout.dxf is at {p}, not at its centre")
        g = modelled.get(eid)
        if building:
            pass  # checked in 3-D above
        elif g is None:
            fail(f"{where}: {eid} has no node in layout.glb")
        elif g[0] == g[2] and g[1] == g[3]:  # an opening: its node marks the centre
            if not (near(g[0], x + w / 2) and near(g[1], y + h / 2)):
                fail(f"{where}: {eid}'s node in layout.glb is at {g[:2]}, not at its centre")
        elif not all(near(u, v) for u, v in zip(g, b)):
            fail(f"{where}: {eid} is modelled at {g} in layout.glb, {b} in the schedule")
        if eid not in named and not in_runs(eid, runs):
            fail(f"{where}: {eid} is not named in layout.svg")
        d = drawn.get(eid)
        if d is None or not all(near(u, v) for u, v in zip(d, b)):
            fail(f"{where}: {eid} is drawn at {d} in install.svg, {b} in the schedule")
        if row["opening_diameter_mm"]:
            dia = float(row["opening_diameter_mm"])
            if not (near(w, dia) and near(h, dia)):
                fail(f"{where}: {eid} is {w} x {h}, its diameter {dia}")
        if not row["shape_wkt"].startswith(("POLYGON ((", "MULTIPOLYGON (((")):
            fail(f"{where}: {eid} has shape_wkt {row['shape_wkt'][:40]}")
    # Exactly, per order line: the schedule's rows (to the mm²) sum to the line's laid area.
    def micro(text):
        return round(float(text) * 1e6)
    # Openings are one line per size (a tool's diameter), whichever curds cut them.
    def opening_size(size):
        return size if size.startswith("D") else "merged" if size == "merged opening" else "other"
    by_line = {}
    for row in rows:
        if row["element_type"] == "opening":
            d = row["opening_diameter_mm"]
            key = ("opening", f"D{d}" if d else
                   "merged" if row["shape_wkt"].startswith(("POLYGON", "MULTIPOLYGON")) else "other")
        else:
            key = (row["element_type"], row["material"], row["colour"])
        by_line.setdefault(key, 0)
        by_line[key] += micro(row["area_m2"])
    # A one-brick wall's backing: a unit behind every face piece that does not run through it,
    # so behind all but its headers and queen closers (and the cuts of its header courses).
    faced = [r for r in rows if r.get("facade")]
    through = sum(r["element_type"].endswith((", header", ", queen closer")) for r in faced)
    cuts = sum(r["element_type"].endswith(", cut to fit") for r in faced)
    backing = 0
    lines = {}
    for q in read_csv(os.path.join(out, "quantities.csv")):
        if q["element_type"].endswith(", backing"):
            backing += int(q["count"])
            continue
        key = (("opening", opening_size(q["size_mm"])) if q["element_type"] == "opening" else
               (q["element_type"], q["material"], q["colour"]))
        lines[key] = lines.get(key, 0) + micro(q["laid_area_m2"])
    if backing and not len(faced) - through - cuts <= backing <= len(faced) - through:
        fail(f"{where}: {backing} backing units behind {len(faced)} face pieces, {through} of "
             f"them through the wall and {cuts} cut")
    if by_line != lines:
        wrong = [k for k in set(by_line) | set(lines) if by_line.get(k) != lines.get(k)]
        fail(f"{where}: the schedule's areas do not add up to the quantities' laid areas for "
             f"{wrong[:3]}: {[by_line.get(k) for k in wrong[:3]]} vs {[lines.get(k) for k in wrong[:3]]} mm2")
    # Sheet DXFs are in millimetres from each sheet's corner; the schedule's lot names the sheet.
    # A sheet rolled to an arc is drawn as its blank: its length along the arc developed at
    # mid-thickness, (r + t/2) / (r + t) of the outer face's for an inside radius r where the arc
    # bows out, (r + t/2) / r where it bows in.
    if os.path.isdir(sheets):
        by_sheet = {}
        for row in rows:
            by_sheet.setdefault(row["lot"], []).append(row)
        punched = {r["sheet_id"]: r for r in read_csv(os.path.join(out, "punching.csv"))} \
            if building and os.path.exists(os.path.join(out, "punching.csv")) else {}
        for name, members in by_sheet.items():
            path = os.path.join(sheets, name + ".dxf")
            if not os.path.exists(path):
                fail(f"{where}: no {name}.dxf for its openings")
                continue
            sboxes, sids = dxf_pieces(path)
            k = 1.0
            if building:  # on the strip; rolled: the blank's scale, from its two outermost IDs
                placed = sorted((float(r["strip_x_mm"]) + float(r["width_mm"]) / 2, sids[r["element_id"]][0])
                                for r in members if r["element_id"] in sids)
                if len(placed) >= 2 and placed[-1][0] - placed[0][0] > 1:
                    k = (placed[-1][1] - placed[0][1]) / (placed[-1][0] - placed[0][0])
                radius = punched.get(name, {}).get("bend_radius_mm", "")
                t = float(punched.get(name, {}).get("thickness_mm") or 0)
                wanted = [1.0] if not radius else [(float(radius) + t / 2) / (float(radius) + t),
                                                   (float(radius) + t / 2) / float(radius)]
                if not any(abs(k - u) < 1e-6 for u in wanted):
                    fail(f"{where}: {name}.dxf is drawn at {k:.7f} of the strip, not {wanted}")
            for row in members:
                eid = row["element_id"]
                x, y = float(row["x_mm"]), float(row["y_mm"])
                if building:
                    x, y = float(row["strip_x_mm"]), float(row["strip_y_mm"])
                w, h = float(row["width_mm"]), float(row["height_mm"])
                x = (x + w / 2) * k - w / 2  # its middle where the blank has it; a hole keeps its size
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


def layout_table(recipe):
    with open(recipe, "rb") as f:
        return tomllib.load(f).get("layout", {})


def main():
    curdle, work = sys.argv[1:3]
    for i, item in enumerate(sys.argv[3:]):
        item, *sets = item.split("|")
        recipe, _, named = item.partition("@")
        corners = named.split(",") if named else CORNERS
        out = os.path.join(work, f"{i:02d}-{os.path.basename(recipe)[:-5]}")
        os.makedirs(out, exist_ok=True)
        # Every corner when the kind takes one (the recipe's own is among them), else as written.
        with open(recipe, "rb") as f:
            layout = tomllib.load(f).get("layout")
        if layout is None:
            print(f"{os.path.basename(recipe)}: no [layout], so no pieces to compare")
        elif layout.get("kind", "tile") in ("rhythm", "blocks") or "building" in layout:
            check(curdle, recipe, os.path.join(out, "out"), None, sets)
        else:
            for k, corner in enumerate(corners):
                check(curdle, recipe, os.path.join(out, f"out{k}"), corner, sets)
    if failures:
        print(f"{len(failures)} disagreements")
        sys.exit(1)


if __name__ == "__main__":
    main()
