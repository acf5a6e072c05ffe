# Imports .glb files written with the simulated kimono into Blender (headless) one after the
# other, the way a user would, and writes as JSON what Blender makes of each file's "kimono_cloth"
# object: its shape keys, its animation's keyframes, and its evaluated mesh (the depsgraph's,
# shape keys applied) in Blender's world coordinates at chosen times of the file.
#
#   blender -b --factory-startup --python-exit-code 1 -P blender_kimono.py -- OUT.json FILE TIMES [FILE TIMES ...]
#
# TIMES is a comma list of seconds. glTF's time 0 is Blender's frame 0, sampled at the scene's
# fps: a time t is evaluated at frame t * fps (a subframe where it falls between frames).
import json
import math
import sys

import bpy

arguments = sys.argv[sys.argv.index("--") + 1:]
output, jobs = arguments[0], arguments[1:]
if len(jobs) == 0 or len(jobs) % 2 != 0:
    raise SystemExit("expected FILE TIMES pairs")

# Debian's Blender 3.4 glTF importer uses numpy's `np.bool`, an alias Debian's numpy 1.24 no longer has.
import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = bool


def clear():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for collection in (bpy.data.meshes, bpy.data.armatures, bpy.data.actions, bpy.data.materials):
        for block in list(collection):
            collection.remove(block)


def action_of(animation_data):
    if animation_data is None:
        return None
    if animation_data.action is None:
        # The glTF importer may keep an animation in an NLA track.
        for track in animation_data.nla_tracks:
            for strip in track.strips:
                animation_data.action = strip.action
    return animation_data.action


scene = bpy.context.scene
result = {"files": []}
for path, times in zip(jobs[0::2], jobs[1::2]):
    clear()
    bpy.ops.import_scene.gltf(filepath=path)
    kimonos = [o for o in scene.objects if o.type == "MESH" and o.name.startswith("kimono_cloth")]
    if len(kimonos) != 1:
        raise SystemExit("%s: expected one kimono object, got %s" % (path, [o.name for o in scene.objects]))
    kimono = kimonos[0]
    keys = kimono.data.shape_keys
    if keys is None:
        raise SystemExit(path + ": the kimono has no shape keys")
    action = action_of(keys.animation_data)
    if action is None:
        raise SystemExit(path + ": the kimono's shape keys are not animated")
    for armature in (o for o in scene.objects if o.type == "ARMATURE"):
        action_of(armature.animation_data)
    curves = [c for c in action.fcurves if c.data_path.startswith("key_blocks")]
    first_key = min(c.keyframe_points[0].co.x for c in curves if len(c.keyframe_points) > 0)
    fps = scene.render.fps / scene.render.fps_base
    entry = {"file": path, "object": kimono.name, "shape_keys": len(keys.key_blocks), "animated_keys": len(curves),
             "keyframes": max(len(c.keyframe_points) for c in curves), "first_keyframe": first_key, "scene_fps": fps,
             "vertices": len(kimono.data.vertices),
             "meshes": sorted(o.name for o in scene.objects if o.type == "MESH"), "times": [], "frames": [], "positions": []}
    for t in (float(x) for x in times.split(",")):
        frame = first_key + t * fps
        whole = math.floor(frame + 1e-9)
        scene.frame_set(int(whole), subframe=max(0.0, frame - whole))
        depsgraph = bpy.context.evaluated_depsgraph_get()
        evaluated = kimono.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        world = evaluated.matrix_world
        entry["times"].append(t)
        entry["frames"].append(frame)
        entry["positions"].append([list(world @ v.co) for v in mesh.vertices])
        evaluated.to_mesh_clear()
    result["files"].append(entry)

with open(output, "w") as out:
    json.dump(result, out)
