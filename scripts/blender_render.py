# Blender 3.4's command line as the peer of `firsthit frames` on a glTF file
# (scripts/bench_gltf.sh):
#   blender -b --factory-startup -P scripts/blender_render.py -- MODEL.glb OUT_DIR FRAMES SIZE
# imports the file, films it with its first camera (or, without one, a
# camera framing its bounds from the front, above, as firsthit's default
# does), adds a sun where it has no light, and renders FRAMES frames with
# Cycles: 1 sample, no denoising, 2 threads, SIZE x SIZE. Prints key: value
# lines: the import time and the frames' render time and frames per second.
import math
import sys
import time

import numpy

# Debian 12's numpy 1.24 dropped the alias Blender 3.4's glTF importer uses.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
path, out, frames, size = args[0], args[1], int(args[2]), int(args[3])

bpy.ops.wm.read_factory_settings(use_empty=True)
start = time.time()
bpy.ops.import_scene.gltf(filepath=path)
import_s = time.time() - start
scene = bpy.context.scene

cameras = [o for o in scene.objects if o.type == "CAMERA"]
if cameras:
    scene.camera = cameras[0]
else:
    bpy.context.view_layer.update()  # matrix_world after the import
    corners = [o.matrix_world @ Vector(c) for o in scene.objects if o.type == "MESH" for c in o.bound_box]
    lo = Vector([min(c[i] for c in corners) for i in range(3)])
    hi = Vector([max(c[i] for c in corners) for i in range(3)])
    centre, radius = (lo + hi) / 2, (hi - lo).length / 2
    data = bpy.data.cameras.new("frame")
    data.angle = math.radians(45)
    camera = bpy.data.objects.new("frame", data)
    scene.collection.objects.link(camera)
    camera.location = centre + Vector((0, -2.2, 1.1)).normalized() * radius / math.sin(data.angle / 2)
    camera.rotation_euler = (centre - camera.location).to_track_quat("-Z", "Y").to_euler()
    scene.camera = camera
if not any(o.type == "LIGHT" for o in scene.objects):
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    sun.rotation_euler = (math.radians(40), math.radians(20), 0)
    scene.collection.objects.link(sun)

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 1
scene.cycles.use_denoising = False
scene.render.threads_mode = "FIXED"
scene.render.threads = 2
scene.render.resolution_x = scene.render.resolution_y = size
scene.render.resolution_percentage = 100
scene.render.filepath = out + "/frame_####"
scene.frame_start, scene.frame_end = 0, frames - 1
start = time.time()
bpy.ops.render.render(animation=True)
render_s = time.time() - start
print(f"blender_import_s: {import_s:.3f}")
print(f"blender_frames: {frames}")
print(f"blender_render_s: {render_s:.3f}")
print(f"blender_frames_per_second: {frames / render_s:.3f}")
