"""Run in Blender: each saved scene against its schedule.csv. One object per row, named by its
ID, with its value, curd bits, material name and lot; one material per value; and each object's
extent equal to the row's box (0.02 mm: Blender keeps vertices in single precision).

    blender -b --python check_scene.py -- SCENE.blend SCHEDULE.csv [SCENE.blend SCHEDULE.csv ...]
"""

import csv
import io
import sys
from pathlib import Path

import bpy

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def extent_mm(obj):
    xs, ys, zs = zip(*(v.co for v in obj.data.vertices))
    return [(min(a) * 1000, max(a) * 1000) for a in (xs, ys, zs)]


def check_scene(blend, schedule):
    bpy.ops.wm.open_mainfile(filepath=blend)
    text = Path(schedule).read_text(encoding="utf-8-sig")
    rows = list(csv.DictReader(io.StringIO(text, newline="")))
    header = list(rows[0].keys())
    curds = header[header.index("value") + 1:header.index("element_type")]
    objects = {o.name: o for o in bpy.context.scene.objects}
    check(len(objects) == len(rows), f"{blend}: {len(objects)} objects for {len(rows)} rows")
    material_of_value = {}
    upright = bool(bpy.context.scene["curdle upright"])
    for r in rows:
        name = r["element_id"]
        o = objects.get(name)
        if o is None:
            failures.append(f"{blend}: no object {name}")
            continue
        where = f"{blend} {name}"
        check(o["value"] == int(r["value"]), f"{where}: value {o['value']} != {r['value']}")
        check(o["curds"] == ",".join(r[c] for c in curds), f"{where}: curds {o['curds']}")
        for c in curds:
            check(o["curd " + c] == int(r[c]), f"{where}: curd {c}")
        check(o["material"] == r["material"], f"{where}: material {o['material']}")
        check(o["lot"] == r["lot"], f"{where}: lot")
        # Pieces of one value share one material; park elements one per kind and colour.
        m = o.data.materials[0].name
        key = (r["value"], r["element_type"], r["material"], r["colour"])
        check(material_of_value.setdefault(key, m) == m, f"{where}: a second material {m}")
        (x0, x1), (y0, y1), (z0, z1) = extent_mm(o)
        x, y, w, h = (float(r[k]) for k in ("x_mm", "y_mm", "width_mm", "height_mm"))
        if r["level"]:  # a block: plan x, y with its depth, storey up
            box = [(x, x + w), (y, y + float(r["depth_mm"])), (float(r["z_mm"]), float(r["z_mm"]) + h)]
        elif upright:
            box = [(x, x + w), None, (y, y + h)]
        else:
            box = [(x, x + w), (y, y + h), None]
        for axis, (got, want) in enumerate(zip([(x0, x1), (y0, y1), (z0, z1)], box)):
            if want is not None:
                check(abs(got[0] - want[0]) <= 0.02 and abs(got[1] - want[1]) <= 0.02,
                      f"{where}: axis {'xyz'[axis]} spans {got}, the schedule says {want}")
    materials = {o.data.materials[0].name for o in objects.values()}
    values = {r["value"] for r in rows}
    check(len(materials) >= len(values), f"{blend}: {len(materials)} materials, {len(values)} values")
    print(f"check_scene: {blend}: {len(rows)} objects, {len(materials)} materials")


args = sys.argv[sys.argv.index("--") + 1:]
for blend, schedule in zip(args[::2], args[1::2]):
    check_scene(blend, schedule)
for f in failures[:30]:
    print("FAIL:", f)
print(f"check_scene: {len(failures)} failures")
sys.exit(1 if failures else 0)
