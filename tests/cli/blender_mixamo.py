# Makes Mixamo-style FBX takes from BVH files with Blender 3.4, for the tutorial's FBX section
# (docs/TUTORIAL.md, "9. A Mixamo FBX take"; tests/cli/tutorial_mixamo_test.cpp): each Bandai BVH
# take is imported, its bones get Mixamo's names (mixamorig:Hips, mixamorig:Spine, ...,
# mixamorig:RightForeArm, mixamorig:RightHand), the unmoving joint_Root is removed so that
# mixamorig:Hips is the root bone under an object named "Armature" as in Mixamo's downloads, and
# the take is exported as binary FBX with Blender's defaults, every frame keyed (Mixamo's files
# key every frame; Blender's default would simplify the curves). Never committed: made at test
# time from the shared data.
#
#   blender -b --factory-startup --python-exit-code 1 -P blender_mixamo.py -- OUTDIR BVH...
#
# writes OUTDIR/STEM.fbx for each STEM.bvh.
import builtins
import os
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
outdir, sources = args[0], args[1:]

# Debian's Blender 3.4 BVH importer opens files with mode 'rU', which its Python 3.11 rejects.
_open = builtins.open


def open_without_u(file, mode="r", *a, **kw):
    if isinstance(mode, str):
        mode = mode.replace("U", "")
    return _open(file, mode, *a, **kw)


builtins.open = open_without_u

# Bandai's joints and Mixamo's names for them (Bandai has two spine joints, Mixamo three: the
# chest, where the arms branch, is Mixamo's Spine2).
MIXAMO = {"Hips": "Hips", "Spine": "Spine", "Chest": "Spine2", "Neck": "Neck", "Head": "Head"}
for bandai_side, side in (("L", "Left"), ("R", "Right")):
    MIXAMO.update({
        "Shoulder_" + bandai_side: side + "Shoulder",
        "UpperArm_" + bandai_side: side + "Arm",
        "LowerArm_" + bandai_side: side + "ForeArm",
        "Hand_" + bandai_side: side + "Hand",
        "UpperLeg_" + bandai_side: side + "UpLeg",
        "LowerLeg_" + bandai_side: side + "Leg",
        "Foot_" + bandai_side: side + "Foot",
        "Toes_" + bandai_side: side + "ToeBase",
    })

for source in sources:
    stem = os.path.splitext(os.path.basename(source))[0]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # The BVH is in centimetres: Blender's scene in metres.
    bpy.ops.import_anim.bvh(filepath=source, global_scale=0.01, frame_start=1, use_fps_scale=False,
                            update_scene_fps=True, update_scene_duration=True, rotate_mode="NATIVE",
                            axis_forward="-Z", axis_up="Y")
    scene = bpy.context.scene
    armature = [o for o in scene.objects if o.type == "ARMATURE"][0]
    action = armature.animation_data.action
    first, last = action.frame_range
    scene.frame_start, scene.frame_end = int(first), int(last)

    # joint_Root never moves: without it the hips' pose (relative to their rest) is the same.
    bpy.context.view_layer.objects.active = armature
    bpy.ops.object.mode_set(mode="EDIT")
    bones = armature.data.edit_bones
    root = bones.get("joint_Root")
    if root is not None:
        for child in list(root.children):
            child.parent = None
        bones.remove(root)
    bpy.ops.object.mode_set(mode="OBJECT")
    for curve in [c for c in action.fcurves if c.data_path.startswith('pose.bones["joint_Root"]')]:
        action.fcurves.remove(curve)
    for group in [g for g in action.groups if g.name == "joint_Root"]:
        action.groups.remove(group)

    # Renaming a bone renames its curves' paths and groups with it.
    for bone in armature.data.bones:
        if bone.name not in MIXAMO:
            raise SystemExit("%s: no Mixamo name for the joint %s" % (source, bone.name))
    for bone in list(armature.data.bones):
        bone.name = "mixamorig:" + MIXAMO[bone.name]
    armature.name = "Armature"
    action.name = "mixamo.com"

    bpy.ops.export_scene.fbx(filepath=os.path.join(outdir, stem + ".fbx"), bake_anim_simplify_factor=0.0)
