# Checks that Blender plays a Mannequin point cache as Mannequin wrote it:
# imports the exported mesh (OBJ, frame 1), gives it a Mesh Cache modifier
# reading the .pc2, and compares every frame's evaluated vertices with the
# cache's samples. Not part of the test suite (Blender is not
# a build dependency); tests/blender/roundtrip.sh runs it, or by hand:
#
#   mannequin-cli simulate resources/scenes/garment_tshirt_walk.json --frames 10 \
#       --export-dir /tmp/pc2 --export-format pc2
#   blender -b --python tests/blender/pc2_in_blender.py -- /tmp/pc2/garment0_T-shirt [pc2|mdd]
#
# Prints the largest difference in metres and exits 1 past 1e-5.
import struct
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
stem = args[0]
fmt = args[1] if len(args) > 1 else "pc2"  # or mdd

if fmt == "pc2":
    with open(stem + ".pc2", "rb") as f:
        signature, version, points, start, rate, samples = struct.unpack("<12siiffi", f.read(32))
        frames = [struct.unpack("<%df" % (3 * points), f.read(12 * points)) for _ in range(samples)]
    assert signature == b"POINTCACHE2\0" and version == 1
else:  # MDD: big-endian counts, the frames' times, then the frames
    with open(stem + ".mdd", "rb") as f:
        samples, points = struct.unpack(">ii", f.read(8))
        f.read(4 * samples)
        frames = [struct.unpack(">%df" % (3 * points), f.read(12 * points)) for _ in range(samples)]
    start = 1

bpy.ops.wm.read_factory_settings(use_empty=True)
if hasattr(bpy.ops.wm, "obj_import"):
    bpy.ops.wm.obj_import(filepath=stem + ".obj")
else:
    bpy.ops.import_scene.obj(filepath=stem + ".obj", split_mode="OFF")
obj = bpy.context.selected_objects[0]
assert len(obj.data.vertices) == points, (len(obj.data.vertices), points)
cache = obj.modifiers.new("cache", "MESH_CACHE")
cache.cache_format = fmt.upper()
cache.filepath = stem + "." + fmt
# The importer keeps the mesh in the file's Y-up space and turns the object
# to Blender's Z-up, so the cache is read as it is (the default axes). Blender
# takes the cache's first sample at the modifier's Frame Start (0 by
# default), not at the file's start frame: set it to the file's (1).
cache.frame_start = start

worst = 0.0
scene = bpy.context.scene
for i, sample in enumerate(frames):
    scene.frame_set(int(start) + i)
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    for v, vertex in enumerate(evaluated.data.vertices):
        worst = max(worst, *(abs(vertex.co[k] - sample[3 * v + k]) for k in range(3)))
print(fmt + " in Blender: %d frames of %d vertices, largest difference %.3g m" % (len(frames), points, worst))
sys.exit(0 if worst <= 1e-5 else 1)
