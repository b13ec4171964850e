"""Run in Blender: a massing model as an office exports one, for curdle to read its plan by a
child node's name. An L-shaped block ("Block A", 20 x 12 m with an 8 x 6 m bite, 7.05 m high)
and a ground slab ("Ground", 40 x 30 m) under an empty ("Massing") that is moved 50 m east and
10 m north, exported as glTF binary with Blender's own exporter (+Y up, metres).

    blender -b --factory-startup --python export_massing.py -- OUT.glb
"""

import sys

import bmesh
import bpy
import numpy

# Debian's Blender 3.4 with NumPy 1.24: its glTF add-on still names np.bool.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

out = sys.argv[sys.argv.index("--") + 1:][-1]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def block(name, boxes, height):
    """A mesh object of boxes (plan metres x0, y0, x1, y1), merged into one closed solid."""
    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    for x0, y0, x1, y1 in boxes:
        result = bmesh.ops.create_cube(bm, size=1.0)
        for v in result["verts"]:
            v.co.x = x0 if v.co.x < 0 else x1
            v.co.y = y0 if v.co.y < 0 else y1
            v.co.z = 0.0 if v.co.z < 0 else height
    bmesh.ops.remove_doubles(bm, verts=bm.verts, dist=1e-6)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    return obj


parent = bpy.data.objects.new("Massing", None)
scene.collection.objects.link(parent)
parent.location = (50.0, 10.0, 0.0)
a = block("Block A", [(0, 0, 12, 6), (12, 0, 20, 6), (0, 6, 12, 12)], 7.05)
ground = block("Ground", [(-10, -10, 30, 20)], 0.3)
ground.location.z = -0.3
for child in (a, ground):
    child.parent = parent
bpy.ops.export_scene.gltf(filepath=out, export_format="GLB", export_apply=True)
print("export_massing: wrote", out)
