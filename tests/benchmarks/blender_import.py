"""Run in Blender: imports a layout.glb with Blender's own glTF importer, timed, and checks that
every element the file names is an object of that name. Prints one JSON line.

    blender -b --factory-startup --python blender_import.py -- LAYOUT.glb
"""

import json
import struct
import sys
import time

import bpy
import numpy

# Debian's Blender 3.4 with NumPy 1.24: its glTF add-on still names np.bool.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

path = sys.argv[sys.argv.index("--") + 1]
with open(path, "rb") as f:
    head = f.read(20)
    names = [n.get("name", "") for n in json.loads(f.read(struct.unpack("<I", head[12:16])[0]))["nodes"]]
bpy.ops.wm.read_factory_settings(use_empty=True)
start = time.perf_counter()
bpy.ops.import_scene.gltf(filepath=path)
seconds = time.perf_counter() - start
objects = set(o.name for o in bpy.data.objects)
missing = [n for n in names if n and n not in objects]
print(json.dumps({"import_s": round(seconds, 3), "nodes": len(names), "objects": len(objects),
                  "meshes": len(bpy.data.meshes), "missing": len(missing), "first_missing": missing[:3]}))
