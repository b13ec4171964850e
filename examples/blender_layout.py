"""A curdle layout as a Blender scene: one object per element, named by its ID, with its value,
curd bits, material name and lot as custom properties, and one material per value in the
drawings' colours. Saves a .blend.

    blender -b --python examples/blender_layout.py -- RECIPE [--seed N] [--out FILE.blend]

Blender finds the curdle module on its own path, in $CURDLE_PYTHONPATH, or in the build tree
beside this example (build/release/python). Meshes are built through bpy directly: Debian's
Blender 3.4 with NumPy 1.24 cannot run its own glTF importer (it uses np.bool).

Units are metres, Z up. A ground layout lies in the XY plane, north along +Y; a wall stands in
the XZ plane with its face at Y = 0 towards -Y and its thickness behind it.
"""

import argparse
import os
import sys
from pathlib import Path


def import_curdle():
    here = Path(__file__).resolve().parent
    for extra in [os.environ.get("CURDLE_PYTHONPATH"), here.parent / "build/release/python"]:
        if extra and str(extra) not in sys.path and Path(extra, "curdle").is_dir():
            sys.path.append(str(extra))
    try:
        import curdle
    except ImportError as error:
        sys.exit(f"blender_layout: cannot import curdle ({error}); build it, or set "
                 "CURDLE_PYTHONPATH to the directory holding the curdle package")
    return curdle


def arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="blender -b --python blender_layout.py --")
    p.add_argument("recipe")
    p.add_argument("--seed", type=int, default=None, help="default: the recipe's")
    p.add_argument("--out", default=None, help="default: curdle-out/<recipe>.blend")
    return p.parse_args(argv)


def linear(channel):
    """An sRGB channel (0-255) as Blender's linear colour."""
    v = channel / 255
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def value_materials(bpy, layout):
    """One material per value present, named as the legend names it, in its colour."""
    materials = {}
    for entry in layout.legend:
        name = f"value {entry['value']} {entry['label']}"
        m = bpy.data.materials.new(name)
        h = entry["colour"].lstrip("#")
        rgb = [linear(int(h[i:i + 2], 16)) for i in (0, 2, 4)]
        m.diffuse_color = (*rgb, 1.0)
        m.use_nodes = True
        m.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*rgb, 1.0)
        materials[entry["value"]] = m
    return materials


def own_colour_material(bpy, materials, element):
    """Park elements (trees, benches, lawn) keep their own colour and material name."""
    key = (element.material, element.colour)
    if key not in materials:
        m = bpy.data.materials.new(element.material)
        h = element.colour.lstrip("#")
        m.diffuse_color = (*[linear(int(h[i:i + 2], 16)) for i in (0, 2, 4)], 1.0)
        materials[key] = m
    return materials[key]


def outline(element, segments=32):
    """The element's outline in plan (mm): a round opening's circle (through its extremes, so
    that it spans the schedule's box), else its polygon's outer ring."""
    import math
    if element.opening and element.opening[2]:
        cx, cy, d = element.opening
        return [(cx + d / 2 * math.cos(2 * math.pi * i / segments),
                 cy + d / 2 * math.sin(2 * math.pi * i / segments)) for i in range(segments)]
    return max((part[0] for part in element.polygon), key=len)


def prism(ring, bottom, top, place):
    """A ring extruded from `bottom` to `top` (mm): vertices placed by `place(x, y, up)` in
    metres, faces outward."""
    ring = [tuple(p) for p in ring]
    if len(ring) > 1 and ring[0] == ring[-1]:
        ring = ring[:-1]
    area = sum(ring[i - 1][0] * ring[i][1] - ring[i][0] * ring[i - 1][1] for i in range(len(ring)))
    if area < 0:
        ring = ring[::-1]  # counter-clockwise
    n = len(ring)
    verts = [place(x, y, bottom) for x, y in ring] + [place(x, y, top) for x, y in ring]
    faces = [list(range(n))[::-1], list(range(n, 2 * n))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return verts, faces


def build_scene(bpy, curdle, run):
    layout = run.layout
    scene = bpy.context.scene
    scene.name = run.name
    scene.unit_settings.system = "METRIC"
    collection = bpy.data.collections.new(run.name)
    scene.collection.children.link(collection)
    materials = value_materials(bpy, layout)
    thickness = layout.thickness_mm or 20.0
    if layout.upright:
        def place(x, y, up):  # face at Y = 0 looking -Y, thickness behind
            return (x / 1000, up / 1000, y / 1000)
    else:
        def place(x, y, up):
            return (x / 1000, y / 1000, up / 1000)
    for element in layout.elements:
        if layout.dimension == 3:  # a block: plan x, y (depth), storey from z
            x, y, w, d = element.x_mm, element.y_mm, element.width_mm, element.depth_mm
            ring = [(x, y), (x + w, y), (x + w, y + d), (x, y + d)]
            verts, faces = prism(ring, element.z_mm, element.z_mm + element.height_mm, place)
        else:
            verts, faces = prism(outline(element), 0.0, thickness, place)
        mesh = bpy.data.meshes.new(element.element_id)
        mesh.from_pydata(verts, [], faces)
        mesh.update()
        material = materials.get(element.value) if element.element_type == layout.element_type \
            or element.element_type == "opening" else None
        mesh.materials.append(material or own_colour_material(bpy, materials, element))
        obj = bpy.data.objects.new(element.element_id, mesh)
        obj["element_id"] = element.element_id
        obj["value"] = element.value
        obj["curds"] = ",".join(str(element.curds[n]) for n in run.curd_names)
        for name, bit in element.curds.items():
            obj["curd " + name] = bit
        obj["material"] = element.material
        obj["element_type"] = element.element_type
        obj["lot"] = element.lot
        obj["cut"] = element.cut
        collection.objects.link(obj)
    scene["curdle recipe"] = run.recipe.path
    scene["curdle seed"] = str(run.seed)
    scene["curdle upright"] = bool(layout.upright)
    return scene


def main():
    import bpy
    curdle = import_curdle()
    args = arguments()
    try:
        run = curdle.generate(args.recipe, seed=args.seed)
    except curdle.InputError as error:
        sys.exit(f"blender_layout: {error}")
    if run.layout is None:
        sys.exit(f"blender_layout: {args.recipe} has no [layout]; add one (patterns/README.md)")
    # A new file: only this layout's scene in it.
    bpy.ops.wm.read_homefile(use_empty=True)
    build_scene(bpy, curdle, run)
    out = Path(args.out or Path("curdle-out") / (Path(args.recipe).stem + ".blend")).resolve()
    out.parent.mkdir(parents=True, exist_ok=True)
    bpy.ops.wm.save_as_mainfile(filepath=str(out))
    print(f"blender_layout: {len(run.layout.elements)} objects, {len(run.layout.legend)} values, "
          f"seed {run.seed}, saved {out}")


if __name__ == "__main__":
    main()
