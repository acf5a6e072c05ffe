#version 330 core
// One program draws everything: lit meshes (puppet, axis bars, markers), unlit lines (grid,
// orbits) and the part-ID pass for picking. Positions in cm, world frame z up.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_colour;

uniform mat4 u_model;          // world_T_mesh
uniform mat4 u_viewProjection; // clip_T_world
uniform mat3 u_normalMatrix;   // inverse transpose of u_model's 3x3 part

out vec3 v_worldPosition;
out vec3 v_normal;
out vec3 v_colour;

void main()
{
    vec4 world = u_model * vec4(a_position, 1.0);
    v_worldPosition = world.xyz;
    v_normal = u_normalMatrix * a_normal;
    v_colour = a_colour;
    gl_Position = u_viewProjection * world;
}
