"""Run in Blender: a saved layout scene rendered in perspective (Workbench, material colours)
for the README.   blender -b SCENE.blend --python render_scene.py -- OUT.png"""

import math
import sys

import bpy
from mathutils import Vector

out = sys.argv[sys.argv.index("--") + 1]
scene = bpy.context.scene
objects = [o for o in scene.objects if o.type == "MESH"]
low = Vector([min(min((o.matrix_world @ Vector(c))[i] for c in o.bound_box) for o in objects)
              for i in range(3)])
high = Vector([max(max((o.matrix_world @ Vector(c))[i] for c in o.bound_box) for o in objects)
               for i in range(3)])
centre, size = (low + high) / 2, (high - low).length
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
upright = bool(scene.get("curdle upright"))
direction = Vector((0.35, -1.0, 0.25)) if upright else Vector((-0.45, -0.9, 0.75))
camera.location = centre + direction.normalized() * size * 1.2
camera.rotation_euler = (centre - camera.location).to_track_quat("-Z", "Y").to_euler()
camera.data.lens = 35
scene.camera = camera
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.light = "STUDIO"
scene.display.shading.color_type = "MATERIAL"
scene.display.shading.show_shadows = True
scene.world = scene.world or bpy.data.worlds.new("world")
scene.world.color = (0.85, 0.85, 0.85)
scene.render.resolution_x, scene.render.resolution_y = 1000, 640
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
