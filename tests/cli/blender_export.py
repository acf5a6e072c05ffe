# Makes FBX, glTF and Collada takes from BVH files the way a user would in Blender 3.4, then
# imports every FBX and glTF file it made with Blender's own importers and writes the bones' world
# positions at sampled times: the peer for bunraku's reader of those formats (tests/cli/
# blender_formats_test.cpp). One Blender process for the whole test run.
#
#   blender -b --factory-startup --python-exit-code 1 -P blender_export.py -- OUTDIR OUT.json BVH...
#
# For each BVH file STEM.bvh (centimetres, y up) it writes into OUTDIR:
#   STEM.fbx       FBX binary, default options (Blender's scene in metres: FBX in cm, y up;
#                  its curves simplified)       STEM_exact.fbx  the same with every key kept
#   STEM.glb       glTF binary, default options          STEM.gltf  glTF text with a .bin beside it
#   STEM.dae       Collada, default options (z up, metres)
#   STEM_zup.fbx   FBX with z up and y forward (every key kept, as the next)
#   STEM_units.fbx FBX with its unit scale in the file (FBX_SCALE_UNITS: metres, UnitScaleFactor 100)
#   STEM_cm.dae    Collada of a scene whose unit is the centimetre (<unit meter="0.01">)
# Blender 3.4 has no FBX ASCII exporter (only binary FBX 7.4), so no ASCII file is made; its
# Collada exporter always writes <up_axis>Z_UP</up_axis> (its "Y up" option turns the data but not
# the file's axis) and its glTF exporter's "+Y up" off writes z-up data into a y-up format, so
# the up-axis variant is FBX's.
# OUT.json: {file name: {"fps": scene fps after the import, "keys": keys of the longest curve,
#   "frames": [file frame k], "positions": {k: {bone: [x, y, z] in Blender's world, metres}}}}
#   for the FBX and glTF files, frame k evaluated at the time of the k-th key.
import builtins
import json
import os
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
outdir, output, sources = args[0], args[1], args[2:]

# Debian's Blender 3.4 BVH importer opens files with mode 'rU', which its Python 3.11 rejects.
_open = builtins.open


def open_without_u(file, mode="r", *a, **kw):
    if isinstance(mode, str):
        mode = mode.replace("U", "")
    return _open(file, mode, *a, **kw)


builtins.open = open_without_u

# Its glTF importer uses numpy's `np.bool`, an alias Debian's numpy 1.24 no longer has.
import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = bool


def clear():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def import_bvh(path, scale):
    bpy.ops.import_anim.bvh(filepath=path, global_scale=scale, frame_start=1, use_fps_scale=False,
                            update_scene_fps=True, update_scene_duration=True, rotate_mode="NATIVE",
                            axis_forward="-Z", axis_up="Y")
    # The exporters that bake the scene's frame range (Collada) take the action's.
    scene = bpy.context.scene
    armature = [o for o in scene.objects if o.type == "ARMATURE"][0]
    first, last = armature.animation_data.action.frame_range
    scene.frame_start, scene.frame_end = int(first), int(last)


def out(name):
    return os.path.join(outdir, name)


made = []
for source in sources:
    stem = os.path.splitext(os.path.basename(source))[0]
    # The BVH is in centimetres: Blender's scene in metres.
    clear()
    import_bvh(source, 0.01)
    bpy.ops.export_scene.fbx(filepath=out(stem + ".fbx"))
    # Its default simplifies the baked curves (bake_anim_simplify_factor 1.0) for its own Bezier
    # tangents, which FBX readers that interpolate keys linearly (assimp, Blender's own importer)
    # do not follow: the variants below keep every key.
    bpy.ops.export_scene.fbx(filepath=out(stem + "_exact.fbx"), bake_anim_simplify_factor=0.0)
    bpy.ops.export_scene.fbx(filepath=out(stem + "_zup.fbx"), axis_up="Z", axis_forward="Y", bake_anim_simplify_factor=0.0)
    bpy.ops.export_scene.fbx(filepath=out(stem + "_units.fbx"), apply_scale_options="FBX_SCALE_UNITS", bake_anim_simplify_factor=0.0)
    bpy.ops.export_scene.gltf(filepath=out(stem + ".glb"))
    bpy.ops.export_scene.gltf(filepath=out(stem + ".gltf"), export_format="GLTF_SEPARATE")
    bpy.ops.wm.collada_export(filepath=out(stem + ".dae"))
    made += [stem + s for s in (".fbx", "_exact.fbx", "_zup.fbx", "_units.fbx", ".glb", ".gltf")]
    # The same take in a scene whose unit is the centimetre.
    clear()
    bpy.context.scene.unit_settings.scale_length = 0.01
    import_bvh(source, 1.0)
    bpy.ops.wm.collada_export(filepath=out(stem + "_cm.dae"))

result = {}
for name in made:
    clear()
    path = out(name)
    if name.endswith(".fbx"):
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    scene = bpy.context.scene
    armatures = [o for o in scene.objects if o.type == "ARMATURE"]
    if len(armatures) != 1:
        raise SystemExit("%s: expected one armature, got %d" % (name, len(armatures)))
    armature = armatures[0]
    action = armature.animation_data.action if armature.animation_data else None
    if action is None:
        for track in (armature.animation_data.nla_tracks if armature.animation_data else []):
            for strip in track.strips:
                action = strip.action
                armature.animation_data.action = action
    if action is None:
        raise SystemExit(name + ": the armature has no animation")
    fps = scene.render.fps / scene.render.fps_base
    curves = [c for c in action.fcurves if c.data_path.startswith("pose.bones")]
    longest = max(curves, key=lambda c: len(c.keyframe_points))
    keys = [k.co.x for k in longest.keyframe_points]
    # The file's frames 0, a third, two thirds and the last, evaluated at their keys' times.
    count = len(keys)
    frames = sorted(set([0, count // 3, 2 * count // 3, count - 1]))
    entry = {"fps": fps, "keys": count, "frames": frames, "positions": {}}
    for k in frames:
        frame = keys[k]
        whole = int(frame // 1)
        scene.frame_set(whole, subframe=frame - whole)
        bpy.context.view_layer.update()
        world = armature.matrix_world
        entry["positions"][str(k)] = {pb.name: list(world @ pb.head) for pb in armature.pose.bones}
    result[name] = entry

with _open(output, "w") as f:
    json.dump(result, f)
