# Makes a character with a skinned mesh from a BVH take with Blender 3.4, for the file's own mesh
# (the "File's mesh" figure; tests/render/file_mesh_test.cpp): the take is imported, a tube is
# built along every bone (a few rings of eight vertices, each bone's radius a little different so
# that no two vertices share a rest position) and weighted by hand - each ring to its bone, the
# rings at a bone's head blended with its parent (and a little with the grandparent), those at its
# tail with its first child - so that vertices carry one to three weights; the mesh is deformed by
# an armature modifier (Blender's default linear blending). The character is exported as binary
# glTF, as binary FBX and as Collada with Blender's defaults (every frame sampled), and Blender's
# own evaluated (depsgraph) vertex positions - at rest and at the frames asked for - and bone
# heads are written as JSON, in Blender's world (metres, z up). Never committed: made at test time from the shared data.
#
#   blender -b --factory-startup --python-exit-code 1 -P blender_skinned_mesh.py -- OUTDIR BVH FRAME...
#
# writes OUTDIR/character.glb, .fbx, .dae and OUTDIR/evaluated.json; FRAME numbers are
# Blender's (the BVH's first frame is 1).
import builtins
import json
import math
import os
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
outdir, source, frames = args[0], args[1], [int(f) for f in args[2:]]

# Debian's Blender 3.4 BVH importer opens files with mode 'rU', which its Python 3.11 rejects.
_open = builtins.open


def open_without_u(file, mode="r", *a, **kw):
    if isinstance(mode, str):
        mode = mode.replace("U", "")
    return _open(file, mode, *a, **kw)


builtins.open = open_without_u

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_anim.bvh(filepath=source, global_scale=0.01, frame_start=1, use_fps_scale=False,
                        update_scene_fps=True, update_scene_duration=True, rotate_mode="NATIVE",
                        axis_forward="-Z", axis_up="Y")
scene = bpy.context.scene
armature = [o for o in scene.objects if o.type == "ARMATURE"][0]
action = armature.animation_data.action
first, last = action.frame_range
scene.frame_start, scene.frame_end = int(first), int(last)

SIDES = 8
RINGS = (0.0, 0.2, 0.5, 0.8, 1.0)
vertices, faces, groups = [], [], []  # groups: per vertex [(bone, weight)]
bones = [b for b in armature.data.bones if b.name != "joint_Root" and b.length > 0.005]
kept = {b.name for b in bones}


def tube(index, head, tail, own, parent, grandparent, child):
    """A tube of rings from head to tail: each ring weighted to `own`, near the head blended with
    `parent` (and at the head a little with `grandparent`), near the tail with `child`."""
    axis = (tail - head).normalized()
    side = axis.orthogonal().normalized()
    other = axis.cross(side)
    radius = 0.02 + 0.0007 * index
    first_vertex = len(vertices)
    for t in RINGS:
        weights = {own: 1.0}
        if t < 0.3 and parent is not None:
            share = 0.5 * (1.0 - t / 0.3)
            weights = {own: 1.0 - share, parent: share}
            if grandparent is not None and t == 0.0:
                weights = {own: 0.5, parent: 0.35, grandparent: 0.15}
        elif t > 0.7 and child is not None:
            share = 0.4 * (t - 0.7) / 0.3
            weights = {own: 1.0 - share, child: share}
        for k in range(SIDES):
            angle = 2.0 * math.pi * k / SIDES
            point = head + (tail - head) * t + radius * (math.cos(angle) * side + math.sin(angle) * other)
            vertices.append(tuple(point))
            groups.append(weights)
    for r in range(len(RINGS) - 1):
        for k in range(SIDES):
            a = first_vertex + r * SIDES + k
            b = first_vertex + r * SIDES + (k + 1) % SIDES
            faces.append((a, b, b + SIDES, a + SIDES))
    faces.append(tuple(first_vertex + k for k in reversed(range(SIDES))))
    faces.append(tuple(first_vertex + (len(RINGS) - 1) * SIDES + k for k in range(SIDES)))


index = 0
for bone in bones:
    head = armature.matrix_world @ bone.head_local
    tail = armature.matrix_world @ bone.tail_local
    parent = bone.parent if bone.parent is not None and bone.parent.name in kept else None
    grandparent = parent.parent if parent is not None and parent.parent is not None and parent.parent.name in kept else None
    child = next((c for c in bone.children if c.name in kept), None)
    tube(index, head, tail, bone.name, parent.name if parent else None, grandparent.name if grandparent else None,
         child.name if child else None)
    index += 1
    # A bone whose head is not at its parent's tail (the branches at the hips and the chest) is
    # joined to its parent's head by a link tube, so the mesh is one piece.
    if parent is not None:
        parent_head = armature.matrix_world @ parent.head_local
        parent_tail = armature.matrix_world @ parent.tail_local
        if (head - parent_tail).length > 0.01 and (head - parent_head).length > 0.01:
            tube(index, parent_head, head, parent.name, None, None, bone.name)
            index += 1

mesh = bpy.data.meshes.new("Body")
mesh.from_pydata(vertices, [], faces)
mesh.update()
body = bpy.data.objects.new("Body", mesh)
scene.collection.objects.link(body)
for bone in bones:
    body.vertex_groups.new(name=bone.name)
for v, weights in enumerate(groups):
    for name, weight in weights.items():
        body.vertex_groups[name].add([v], weight, "REPLACE")
body.parent = armature
modifier = body.modifiers.new("Armature", "ARMATURE")
modifier.object = armature


def evaluated():
    depsgraph = bpy.context.evaluated_depsgraph_get()
    shown = body.evaluated_get(depsgraph)
    data = shown.to_mesh()
    points = [list(shown.matrix_world @ v.co) for v in data.vertices]
    shown.to_mesh_clear()
    heads = {b.name: list(armature.matrix_world @ b.head) for b in armature.pose.bones}
    return {"vertices": points, "heads": heads}


out = {"fps": scene.render.fps / scene.render.fps_base, "first": int(first), "frames": {}}
armature.data.pose_position = "REST"
scene.frame_set(int(first))
out["rest"] = evaluated()
armature.data.pose_position = "POSE"
for f in frames:
    scene.frame_set(f)
    out["frames"][str(f)] = evaluated()
scene.frame_set(int(first))

bpy.ops.export_scene.gltf(filepath=os.path.join(outdir, "character.glb"), export_format="GLB")
bpy.ops.export_scene.fbx(filepath=os.path.join(outdir, "character.fbx"), bake_anim_simplify_factor=0.0)
bpy.ops.wm.collada_export(filepath=os.path.join(outdir, "character.dae"), include_animations=True, sampling_rate=1,
                          keep_smooth_curves=False)
with open(os.path.join(outdir, "evaluated.json"), "w") as f:
    json.dump(out, f)
