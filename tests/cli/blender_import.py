# Imports a .bvh or .glb into Blender (headless) the way a user would, and writes what Blender
# made of it as JSON: the armature's bone count, the animation's frame count and every bone's
# head in Blender's world coordinates at chosen frames of the file.
#
#   blender -b --factory-startup --python-exit-code 1 -P blender_import.py -- KIND FILE OUT.json FRAMES
#
# KIND is bvh or glb; FRAMES a comma list of 0-based frame indices of the file.
import builtins
import json
import math
import sys

import bpy

kind, path, output, frames = sys.argv[sys.argv.index("--") + 1:][:4]
frames = [int(f) for f in frames.split(",")]

# Debian's Blender 3.4 BVH importer opens files with mode 'rU', which its Python 3.11 rejects.
_open = builtins.open


def open_without_u(file, mode="r", *args, **kwargs):
    if isinstance(mode, str):
        mode = mode.replace("U", "")
    return _open(file, mode, *args, **kwargs)


builtins.open = open_without_u

# Its glTF importer uses numpy's `np.bool`, an alias Debian's numpy 1.24 no longer has.
import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = bool

for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
scene = bpy.context.scene
if kind == "bvh":
    bpy.ops.import_anim.bvh(filepath=path, global_scale=1.0, frame_start=1, use_fps_scale=False,
                            update_scene_fps=True, update_scene_duration=True, rotate_mode="NATIVE",
                            axis_forward="-Z", axis_up="Y")
elif kind == "glb":
    bpy.ops.import_scene.gltf(filepath=path)
else:
    raise SystemExit("unknown kind " + kind)

armatures = [o for o in scene.objects if o.type == "ARMATURE"]
if len(armatures) != 1:
    raise SystemExit("expected one armature, got %d" % len(armatures))
armature = armatures[0]
action = armature.animation_data.action if armature.animation_data else None
if action is None:
    # The glTF importer may keep the animation in an NLA track.
    for track in (armature.animation_data.nla_tracks if armature.animation_data else []):
        for strip in track.strips:
            action = strip.action
            armature.animation_data.action = action
if action is None:
    raise SystemExit("the armature has no animation")
curves = [c for c in action.fcurves if c.data_path.startswith("pose.bones")]
keyframes = max(len(c.keyframe_points) for c in curves)
# Keyframe times (Blender frames) of the file's frames, from the longest curve.
longest = max(curves, key=lambda c: len(c.keyframe_points))
times = [k.co.x for k in longest.keyframe_points]

result = {"bones": len(armature.data.bones), "frames": keyframes, "scene_fps": scene.render.fps,
          "bone_names": [b.name for b in armature.data.bones], "positions": {}}
for f in frames:
    t = times[f]
    whole = math.floor(t)
    scene.frame_set(int(whole), subframe=t - whole)
    bpy.context.view_layer.update()
    world = armature.matrix_world
    result["positions"][str(f)] = {pb.name: list(world @ pb.head) for pb in armature.pose.bones}
with _open(output, "w") as out:
    json.dump(result, out)
