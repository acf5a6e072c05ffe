#version 330 core
// A light at the camera (thesis 6): diffuse shading, two-sided so scanned meshes with mixed
// winding still read, and a faint highlight. Unlit mode writes the colour exactly (lines and
// the part-ID pass, whose 8-bit values must survive unchanged).
in vec3 v_worldPosition;
in vec3 v_normal;
in vec3 v_colour;

uniform vec4 u_colour;          // multiplies the vertex colour, or replaces it
uniform int u_useVertexColour;  // 1: v_colour * u_colour.rgb, 0: u_colour.rgb
uniform int u_lit;              // 1: shaded by the light at u_lightPosition
uniform vec3 u_lightPosition;   // world, cm

out vec4 fragColour;

void main()
{
    vec3 base = u_useVertexColour != 0 ? v_colour * u_colour.rgb : u_colour.rgb;
    if (u_lit == 0) {
        fragColour = vec4(base, u_colour.a);
        return;
    }
    vec3 n = normalize(v_normal);
    vec3 l = normalize(u_lightPosition - v_worldPosition);
    float diffuse = abs(dot(n, l));
    float highlight = pow(diffuse, 40.0) * 0.12;
    fragColour = vec4(base * (0.45 + 0.55 * diffuse) + vec3(highlight), u_colour.a);
}
