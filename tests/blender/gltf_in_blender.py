# Checks that Blender plays a Mannequin glTF export as Mannequin posed it:
# imports the file with Blender's glTF importer, and at each check's time
# compares the evaluated vertices of one object (skinning, shape keys and
# their animation applied by Blender) with a reference OBJ that
# mannequin-cli wrote for that time. Not part of the test suite (Blender is
# not a build dependency); tests/blender/roundtrip.sh runs it:
#
#   blender -b --python-exit-code 1 --python tests/blender/gltf_in_blender.py -- \
#       OUT.glb --fps 30 --check OBJECT TIME REFERENCE.obj|.ply [--check ...]
#
# The distance of each Blender vertex to the nearest reference vertex, and
# back, over the reference's bounding-box diagonal: prints the largest per
# check, exits 1 past --tolerance (1e-4). --check-subset compares one way
# only: every Blender vertex near a reference vertex (hair guides against
# every strand that `simulate` wrote). References are OBJ, or the binary PLY
# of hair strands.
import math
import struct
import sys

import bpy
import numpy

# Blender 3.4's glTF importer still says numpy.bool, which the numpy of
# Debian 12 (1.24) no longer has.
if not hasattr(numpy, "bool"):
    numpy.bool = bool
from mathutils import Vector
from mathutils.kdtree import KDTree

args = sys.argv[sys.argv.index("--") + 1:]
path = args[0]
fps = 30
tolerance = 1e-4
checks = []
i = 1
while i < len(args):
    if args[i] == "--fps":
        fps = int(args[i + 1])
        i += 2
    elif args[i] == "--tolerance":
        tolerance = float(args[i + 1])
        i += 2
    elif args[i] in ("--check", "--check-subset"):
        checks.append((args[i + 1], float(args[i + 2]), args[i + 3], args[i] == "--check-subset"))
        i += 4
    else:
        sys.exit("unknown argument " + args[i])


def blender_axes(x, y, z):
    return Vector((x, -z, y))  # glTF's Y up -> Blender's Z up


def read_obj(filename):
    points = []
    with open(filename) as f:
        for line in f:
            if line.startswith("v "):
                points.append(blender_axes(*map(float, line.split()[1:4])))
    return points


def read_strands_ply(filename):
    with open(filename, "rb") as f:
        count = 0
        while True:
            line = f.readline().decode("ascii").strip()
            if line.startswith("element vertex"):
                count = int(line.split()[2])
            if line == "end_header":
                break
        data = f.read(12 * count)
    return [blender_axes(*struct.unpack_from("<3f", data, 12 * k)) for k in range(count)]


def read_reference(filename):
    return read_strands_ply(filename) if filename.endswith(".ply") else read_obj(filename)


def kd_tree(points):
    tree = KDTree(len(points))
    for k, p in enumerate(points):
        tree.insert(p, k)
    tree.balance()
    return tree


def evaluated_points(obj):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    points = [evaluated.matrix_world @ v.co for v in mesh.vertices]
    evaluated.to_mesh_clear()
    return points


bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.context.scene.render.fps = fps
bpy.ops.import_scene.gltf(filepath=path)
# The importer leaves each animation as an action; one take plays them all.
for obj in bpy.data.objects:
    if obj.animation_data and obj.animation_data.action is None and obj.animation_data.nla_tracks:
        obj.animation_data.action = obj.animation_data.nla_tracks[0].strips[0].action

worst = 0.0
for name, time, reference, subset in checks:
    candidates = [o for o in bpy.data.objects if o.type == "MESH" and o.name.startswith(name)]
    if not candidates:
        sys.exit("no mesh object named %s in %s (objects: %s)" % (name, path, [o.name for o in bpy.data.objects]))
    obj = candidates[0]
    frame = time * fps
    bpy.context.scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
    ours = read_reference(reference)
    theirs = evaluated_points(obj)
    low = Vector([min(p[d] for p in ours) for d in range(3)])
    high = Vector([max(p[d] for p in ours) for d in range(3)])
    diagonal = (high - low).length
    ours_tree, theirs_tree = kd_tree(ours), kd_tree(theirs)
    distance = max(ours_tree.find(p)[2] for p in theirs)
    if not subset:
        distance = max(distance, max(theirs_tree.find(p)[2] for p in ours))
    relative = distance / diagonal
    worst = max(worst, relative)
    print("%-12s t=%.4f s  %6d vertices (ours %6d)  max distance %.3g m  = %.3g of the diagonal (%.3f m)"
          % (name, time, len(theirs), len(ours), distance, relative, diagonal))
print("worst: %.3g of the diagonal (tolerance %.0e)" % (worst, tolerance))
sys.exit(0 if worst <= tolerance else 1)
