# Imports one of our .glb exports into Blender (headless) as a user would, reports what Blender
# made of it (armature, skinned mesh, vertex groups, frames) and renders Blender's evaluated,
# skinned mesh as a flat silhouette through orthographic cameras given by the test; one Blender
# process does every render of a test.
#
#   blender -b --factory-startup --python-exit-code 1 -P blender_silhouette.py -- JOB.json
#
# JOB.json: {"file": glb, "fps": scene frame rate to import at (the take's rate: one file frame
# per Blender frame), "output": result json,
#            "renders": [{"frame": file frame, "eye": [x, y, z], "right": [...], "up": [...],
#                         "forward": [...] (Blender's world, metres), "ortho_scale": metres,
#                         "size": pixels (square), "png": path}],
#            "axis_frames": [file frames at which to report each vertex group's principal axis;
#                            any: also its |cos| with its bone at rest]}
import json
import math
import sys

import bpy
from mathutils import Matrix, Vector

job_path = sys.argv[sys.argv.index("--") + 1]
with open(job_path) as f:
    job = json.load(f)

# Debian's Blender 3.4 glTF importer uses numpy's `np.bool`, an alias Debian's numpy 1.24 lacks.
import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = bool

scene = bpy.context.scene
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
fps = job.get("fps")
if fps:
    scene.render.fps = int(fps)
    scene.render.fps_base = 1.0
bpy.ops.import_scene.gltf(filepath=job["file"])

armatures = [o for o in scene.objects if o.type == "ARMATURE"]
if len(armatures) != 1:
    raise SystemExit("expected one armature, got %d" % len(armatures))
armature = armatures[0]
meshes = [o for o in scene.objects if o.type == "MESH"]
skinned = [o for o in meshes if any(m.type == "ARMATURE" and m.object == armature for m in o.modifiers)]
if len(skinned) != 1:
    raise SystemExit("expected one mesh skinned to the armature, got %d (of %d meshes)" % (len(skinned), len(meshes)))
mesh = skinned[0]

anim = armature.animation_data
action = anim.action if anim else None
if action is None and anim:
    # The glTF importer may keep the animation in an NLA track.
    for track in anim.nla_tracks:
        for strip in track.strips:
            action = strip.action
    anim.action = action
if action is None:
    raise SystemExit("the armature has no animation")
curves = [c for c in action.fcurves if c.data_path.startswith("pose.bones")]
longest = max(curves, key=lambda c: len(c.keyframe_points))
times = [k.co.x for k in longest.keyframe_points]

bone_names = {b.name for b in armature.data.bones}
groups = [g.name for g in mesh.vertex_groups]
influences = max((sum(1 for g in v.groups if g.weight > 0.0) for v in mesh.data.vertices), default=0)
result = {
    "bones": len(armature.data.bones),
    "frames": len(times),
    "scene_fps": scene.render.fps,
    "vertices": len(mesh.data.vertices),
    "vertex_groups": len(groups),
    "groups_named_as_bones": all(g in bone_names for g in groups),
    "max_influences": influences,
    "armature_modifier": True,
    "renders": [],
    "axes": {},
}


def go_to(frame):
    t = times[frame]
    whole = math.floor(t + 1e-6)
    scene.frame_set(int(whole), subframe=max(0.0, t - whole))
    bpy.context.view_layer.update()
    return t - whole


def evaluated_vertices():
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh.evaluated_get(depsgraph)
    data = evaluated.to_mesh()
    world = evaluated.matrix_world
    points = [world @ v.co for v in data.vertices]
    evaluated.to_mesh_clear()
    return points


# A flat silhouette: Workbench, flat lighting, one colour, transparent film (alpha is coverage),
# no anti-aliasing (one sample per pixel centre, as our ID pass).
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.light = "FLAT"
scene.display.shading.color_type = "SINGLE"
scene.display.shading.single_color = (1.0, 1.0, 1.0)
scene.display.render_aa = "OFF"
scene.render.film_transparent = True
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_mode = "RGBA"
camera_data = bpy.data.cameras.new("silhouette")
camera_data.type = "ORTHO"
camera_data.sensor_fit = "AUTO"
camera_data.clip_start = 0.01
camera_data.clip_end = 1000.0
camera = bpy.data.objects.new("silhouette", camera_data)
scene.collection.objects.link(camera)
scene.camera = camera

for render in job.get("renders", []):
    off = go_to(render["frame"])
    if off > 1e-4:
        raise SystemExit("file frame %d is at Blender frame %.4f, not a whole frame" % (render["frame"], times[render["frame"]]))
    right, up, forward = (Vector(render[k]) for k in ("right", "up", "forward"))
    # A Blender camera looks along its local -Z with local +Y up and +X right.
    rotation = Matrix((right, up, -forward)).transposed()
    camera.matrix_world = Matrix.Translation(Vector(render["eye"])) @ rotation.to_4x4()
    camera_data.ortho_scale = render["ortho_scale"]
    scene.render.resolution_x = render["size"]
    scene.render.resolution_y = render["size"]
    scene.render.filepath = render["png"]
    bpy.ops.render.render(write_still=True)
    result["renders"].append({"frame": render["frame"], "png": render["png"], "blender_frame": scene.frame_current})

# Each vertex group's principal axis (Blender's world) in the evaluated mesh.
# A vertex belongs to the group that weighs most on it.
members = {}
for v in mesh.data.vertices:
    heaviest = max(v.groups, key=lambda g: g.weight, default=None)
    if heaviest is not None and heaviest.weight > 0.0:
        members.setdefault(mesh.vertex_groups[heaviest.group].name, []).append(v.index)
# At rest (the undeformed mesh against the armature's rest bones, head to tail), as a user
# inspecting the imported file would measure it.
if job.get("axis_frames"):
    rest = {}
    for name, indices in members.items():
        pts = numpy.array([tuple(mesh.matrix_world @ mesh.data.vertices[i].co) for i in indices])
        centred = pts - pts.mean(axis=0)
        values, vectors = numpy.linalg.eigh(centred.T @ centred)
        bone = armature.data.bones.get(name)
        if bone is None:
            continue
        along = numpy.array(armature.matrix_world @ bone.tail_local) - numpy.array(armature.matrix_world @ bone.head_local)
        along /= numpy.linalg.norm(along)
        rest[name] = {"vertices": len(indices), "cos": float(abs(vectors[:, -1] @ along))}
    result["rest_axes"] = rest
for frame in job.get("axis_frames", []):
    go_to(frame)
    points = numpy.array([tuple(p) for p in evaluated_vertices()])
    axes = {}
    for name, indices in members.items():
        pts = points[indices]
        centred = pts - pts.mean(axis=0)
        values, vectors = numpy.linalg.eigh(centred.T @ centred)
        axes[name] = {"vertices": len(indices), "axis": vectors[:, -1].tolist(),
                      "spread": [float(math.sqrt(max(0.0, x / len(indices)))) for x in values[::-1]]}
    result["axes"][str(frame)] = axes

with open(job["output"], "w") as out:
    json.dump(result, out)
