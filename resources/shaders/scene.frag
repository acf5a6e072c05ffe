#version 330 core
// A light at the camera (thesis 6): diffuse shading, two-sided so scanned meshes with mixed
// winding still read, and a faint highlight; the figures also take a key light fixed in the
// world (render/shadow_map.h) and a sky from above. The floor is lit by the key light only where
// the figures do not shadow it (a depth map seen from the light), and fades into the background
// at its rim. A shadow's edge is as soft as the light is far from what casts it (percentage-
// closer soft shadows, Fernando 2005): sharp where a foot or the hem meets the floor, wide under
// a raised hand. Unlit mode writes the colour exactly (lines and
// the part-ID pass, whose 8-bit values must survive unchanged). The modelled puppet
// (skinned.vert) adds a sheen per material and paint evaluated per pixel: the kashira's eyes,
// brows, lips and blush, the kimono's kanoko dots and the obi's weave.
in vec3 v_worldPosition;
in vec3 v_normal;
in vec3 v_colour;
in float v_sheen;
in vec3 v_paint;
flat in int v_region;
flat in int v_part;

uniform vec4 u_colour;          // multiplies the vertex colour, or replaces it
uniform int u_useVertexColour;  // 1: v_colour * u_colour.rgb, 0: u_colour.rgb
uniform int u_lit;              // 1: shaded by the light at u_lightPosition
uniform vec3 u_lightPosition;   // world, cm
uniform int u_partIdBase;       // >= 0: the ID pass of the skinned puppet, red = base + v_part
uniform int u_boneIds;          // 1 (the performer's body): red = base, green + 256 blue = 1 + v_part
uniform vec3 u_keyDirection;    // world, unit, towards the key light
uniform int u_floor;            // 1: the floor (shadowed, faded at u_floorRadius cm from the origin)
uniform float u_floorRadius;
uniform vec3 u_background;
uniform int u_shadows;          // 1: u_shadowMap holds the figures' depths seen from the key light
uniform sampler2DShadow u_shadowMap; // compared with the depth looked up
uniform sampler2D u_shadowDepth;     // the same map, read as depths
uniform mat4 u_lightViewProjection;
uniform float u_shadowUvPerCm;  // the map's texture coordinates per cm across the light
uniform float u_shadowCmPerDepth; // cm along the light per unit of the map's depth
uniform int u_shadowDraft;      // 1: a moving view's frame - 4 comparisons over 1 cm, no search

out vec4 fragColour;

vec3 paintFace(vec3 base, vec3 p)
{
    if (p.x < 4.6) return base;
    float ay = abs(p.y);
    float blush = exp(-((ay - 2.2) * (ay - 2.2) + (p.z - 13.1) * (p.z - 13.1)) / 0.8);
    base = mix(base, vec3(0.95, 0.66, 0.66), 0.25 * blush);
    // Narrow almond eyes, the outer corners a little higher; a dark upper lid line.
    vec2 e = vec2((ay - 1.55) / 0.68, (p.z - 14.5 - 0.16 * (ay - 1.55)) / 0.2);
    float eye = dot(e, e);
    if (eye < 1.0) return vec3(0.06, 0.05, 0.05);
    if (eye < 1.6 && e.y > 0.3) return mix(base, vec3(0.25, 0.12, 0.1), 0.8);
    // Thin painted brows, high on the forehead.
    float u = (ay - 1.45) / 0.9;
    float browZ = 16.3 - 0.22 * u * u;
    if (ay > 0.65 && ay < 2.35 && abs(p.z - browZ) < 0.08) return vec3(0.12, 0.1, 0.1);
    // Small red lips, the lower a little narrower.
    float lz = (p.z - 12.2) / 0.36;
    float halfWidth = lz > 0.0 ? 0.62 : 0.5;
    if (p.x > 5.6 && abs(lz) < 1.0 && ay < halfWidth * sqrt(1.0 - lz * lz)) return vec3(0.74, 0.05, 0.12);
    return base;
}

vec3 paintKimono(vec3 base, vec3 p)
{
    if (p.z < -51.6) return base; // the lining at the hem
    // Kanoko: a lattice of small tie-dye rings.
    vec3 q = p / 1.7;
    q.x += 0.5 * mod(floor(q.z), 2.0);
    vec3 f = fract(q) - 0.5;
    float r = length(f);
    if (r < 0.09) return base * 0.8;
    if (r < 0.2) return mix(base, vec3(0.97, 0.86, 0.84), 0.85);
    return base;
}

vec3 paintObi(vec3 base, vec3 p)
{
    float weave = 0.5 + 0.5 * sin(p.z * 6.0) * sin((p.x + p.y) * 2.2);
    return base * (0.82 + 0.22 * weave);
}

// The fraction of the key light reaching a world point; outside the light's box, all of it.
// The casters within 8 cm (across the light) give the mean distance to the floor, which sets the
// filter's half width (3 % of it, a lamp of about 3.4 deg; 0.3 to 4 cm); 16 filtered depth
// comparisons over that square, turned per pixel.
float keyLight(vec3 world)
{
    vec4 clip = u_lightViewProjection * vec4(world, 1.0);
    vec3 p = clip.xyz / clip.w * 0.5 + 0.5;
    if (p.x <= 0.0 || p.x >= 1.0 || p.y <= 0.0 || p.y >= 1.0 || p.z >= 1.0) return 1.0;
    if (u_shadowDraft != 0) {
        vec2 d = vec2(0.5 * u_shadowUvPerCm);
        return 0.25 * (texture(u_shadowMap, vec3(p.xy + vec2(-d.x, -d.y), p.z)) + texture(u_shadowMap, vec3(p.xy + vec2(d.x, -d.y), p.z)) +
                       texture(u_shadowMap, vec3(p.xy + vec2(-d.x, d.y), p.z)) + texture(u_shadowMap, vec3(p.xy + vec2(d.x, d.y), p.z)));
    }
    float blockers = 0.0;
    float count = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            vec2 offset = (vec2(float(i), float(j)) - 1.0) * 8.0 * u_shadowUvPerCm;
            float depth = texture(u_shadowDepth, p.xy + offset).r;
            if (depth < p.z) {
                blockers += depth;
                count += 1.0;
            }
        }
    if (count == 0.0) return 1.0;
    float gap = (p.z - blockers / count) * u_shadowCmPerDepth;
    float spread = clamp(0.03 * gap, 0.3, 4.0) * u_shadowUvPerCm;
    // The 4 x 4 pattern turned per pixel (interleaved gradient noise): no banding.
    float angle = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    mat2 turn = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    float sum = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            vec2 offset = turn * ((vec2(float(i), float(j)) - 1.5) / 1.5) * spread;
            sum += texture(u_shadowMap, vec3(p.xy + offset, p.z));
        }
    return sum / 16.0;
}

void main()
{
    if (u_partIdBase >= 0) {
        if (u_boneIds != 0) {
            int id = v_part + 1;
            fragColour = vec4(float(u_partIdBase) / 255.0, float(id % 256) / 255.0, float(id / 256) / 255.0, 1.0);
        } else {
            fragColour = vec4(float(u_partIdBase + v_part) / 255.0, 0.0, 0.0, 1.0);
        }
        return;
    }
    vec3 base = u_useVertexColour != 0 ? v_colour * u_colour.rgb : u_colour.rgb;
    if (u_floor != 0) { // the floor and its grid lines
        float lit = u_shadows != 0 ? keyLight(v_worldPosition) : 1.0;
        float rim = smoothstep(0.55, 1.0, length(v_worldPosition.xy) / u_floorRadius);
        fragColour = vec4(mix(base * (0.58 + 0.42 * lit), u_background, rim), 1.0);
        return;
    }
    if (u_lit == 0) {
        fragColour = vec4(base, u_colour.a);
        return;
    }
    vec3 n = normalize(v_normal);
    vec3 l = normalize(u_lightPosition - v_worldPosition);
    float diffuse = abs(dot(n, l));
    float key = max(dot(gl_FrontFacing ? n : -n, u_keyDirection), 0.0);
    if (v_sheen < 0.0) {
        float highlight = pow(diffuse, 40.0) * 0.12;
        fragColour = vec4(base * (0.45 + 0.55 * diffuse) + vec3(highlight), u_colour.a);
        return;
    }
    if (v_region == 1) base = paintFace(base, v_paint);
    else if (v_region == 2) base = paintKimono(base, v_paint);
    else if (v_region == 3) base = paintObi(base, v_paint);
    // The light sits at the eye, so the half vector is the light direction: a Blinn highlight
    // whose size and strength follow the material (silk broad and soft, lacquer tight).
    float shininess = mix(10.0, 80.0, v_sheen);
    float highlight = pow(diffuse, shininess) * 0.45 * v_sheen;
    float sky = 0.5 + 0.5 * (gl_FrontFacing ? n.z : -n.z);
    fragColour = vec4(base * (0.3 + 0.4 * diffuse + 0.2 * key + 0.12 * sky) + vec3(highlight), u_colour.a);
}
