#version 330 core
// One program draws everything but the skinned puppet (skinned.vert): lit meshes (axis bars,
// markers, a body of primitives), unlit lines (grid, orbits) and the part-ID pass for picking.
// Positions in cm, world frame z up.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_colour;

uniform mat4 u_model;          // world_T_mesh
uniform mat4 u_viewProjection; // clip_T_world
uniform mat3 u_normalMatrix;   // inverse transpose of u_model's 3x3 part

out vec3 v_worldPosition;
out vec3 v_normal;
out vec3 v_colour;
out float v_sheen;  // < 0: the plain shading of scene.frag
out vec3 v_paint;
flat out int v_region;
flat out int v_part;

void main()
{
    vec4 world = u_model * vec4(a_position, 1.0);
    v_worldPosition = world.xyz;
    v_normal = u_normalMatrix * a_normal;
    v_colour = a_colour;
    v_sheen = -1.0;
    v_paint = vec3(0.0);
    v_region = 0;
    v_part = 0;
    gl_Position = u_viewProjection * world;
}
