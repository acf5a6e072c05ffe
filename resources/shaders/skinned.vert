#version 330 core
// The modelled puppet, skinned on the GPU by dual quaternion blending (Kavan et al. 2007; the
// CPU twin is analysis::skinPuppet): each joint's world_T_joint * inverse(bind) arrives as a
// unit dual quaternion (real, dual; x y z w); a vertex blends its up to four joints' with its
// weights, signs on the first joint's hemisphere, renormalised, and applies the rigid result,
// so a twisted wrist keeps its thickness. u_model then places the take (slotRoot).
layout(location = 0) in vec3 a_position;  // model space (bind pose), cm
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_colour;
layout(location = 3) in vec2 a_sheenRegion; // specular strength, painted region
layout(location = 4) in vec3 a_paint;       // the shipped puppet's model position (paint coordinates)
layout(location = 5) in uvec4 a_joints;
layout(location = 6) in vec4 a_weights;

// The performer's body (analysis/body/performer_body.h) is drawn by the same source compiled
// with BODY_JOINTS defined (analysis::kMaxBodyJoints): its joints are the skeleton's, and the
// ID pass writes the dominant joint itself.
#ifdef BODY_JOINTS
const int kJoints = BODY_JOINTS;
// A file's own mesh (analysis/core/skeleton_mesh.h) is blended linearly, as its format means it
// (glTF's and FBX's linear blend skinning; the CPU twin is analysis::skinSkeletonMesh): each
// joint's rigid transform applied, the results weighted.
uniform int u_linearBlend;
#else
const int kJoints = 9; // analysis::kPuppetJointCount
uniform int u_partOfJoint[kJoints]; // body part index of each joint (picking IDs)
#endif
uniform mat4 u_model;
uniform mat4 u_viewProjection;
uniform mat3 u_normalMatrix;
uniform vec4 u_jointReal[kJoints];
uniform vec4 u_jointDual[kJoints];

out vec3 v_worldPosition;
out vec3 v_normal;
out vec3 v_colour;
out float v_sheen;
out vec3 v_paint;
flat out int v_region;
flat out int v_part;

vec3 rotate(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }

void main()
{
    vec4 first = u_jointReal[a_joints.x];
    vec4 real = vec4(0.0);
    vec4 dual = vec4(0.0);
    vec3 position = vec3(0.0);
    vec3 normal = vec3(0.0);
    int dominant = 0;
#ifdef BODY_JOINTS
    bool linear = u_linearBlend != 0;
#else
    bool linear = false;
#endif
    for (int k = 0; k < 4; ++k) {
        float w = a_weights[k];
        int j = int(a_joints[k]);
        vec4 r = u_jointReal[j];
        if (linear) {
            vec4 d = u_jointDual[j];
            vec3 t = 2.0 * (r.w * d.xyz - d.w * r.xyz + cross(r.xyz, d.xyz));
            position += w * (rotate(r, a_position) + t);
            normal += w * rotate(r, a_normal);
        } else {
            float s = dot(r, first) < 0.0 ? -1.0 : 1.0;
            real += s * w * r;
            dual += s * w * u_jointDual[j];
        }
        if (a_weights[k] > a_weights[dominant]) dominant = k;
    }
    if (!linear) {
        float norm = length(real);
        real /= norm;
        dual /= norm;
        vec3 translation = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
        position = rotate(real, a_position) + translation;
        normal = rotate(real, a_normal);
    }
    vec4 world = u_model * vec4(position, 1.0);
    v_worldPosition = world.xyz;
    v_normal = u_normalMatrix * normal;
    v_colour = a_colour;
    v_sheen = a_sheenRegion.x;
    v_region = int(a_sheenRegion.y + 0.5);
    v_paint = a_paint;
#ifdef BODY_JOINTS
    v_part = int(a_joints[dominant]);
#else
    v_part = u_partOfJoint[int(a_joints[dominant])];
#endif
    gl_Position = u_viewProjection * world;
}
