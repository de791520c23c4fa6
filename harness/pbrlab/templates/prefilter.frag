#version 330 core
// One face of the mirror level (roughness 0) of the GGX-prefiltered environment cube
// (harness/pbrlab/gpu/ibl.py): the equirectangular source resampled (bilinear) at each texel's
// direction. The rougher levels are summed on the CPU (ibl.py); the target is a cube face, so
// no texel of the result sits on a pole or a seam (issue 38).
#include "pbr/ibl/equirect.glsl"

uniform sampler2D u_source;        // equirect radiance
uniform int u_face;                // 0..5: +X, -X, +Y, -Y, +Z, -Z
uniform float u_face_size;         // texels per edge of this level's faces
out vec4 out_radiance;

// The direction of a face texel: the OpenGL 4.6 specification, table 8.19 (major axis
// direction, sc, tc per face), with s = x / size, t = y / size and sc, tc = 2 s - 1, 2 t - 1
// (scene/cubemap.py, face_directions, the same table).
vec3 pbrlab_cube_face_direction(int face, vec2 st) {
    vec2 c = st * 2.0 - 1.0;
    vec3 d;
    if (face == 0) d = vec3(1.0, -c.y, -c.x);
    else if (face == 1) d = vec3(-1.0, -c.y, c.x);
    else if (face == 2) d = vec3(c.x, 1.0, c.y);
    else if (face == 3) d = vec3(c.x, -1.0, -c.y);
    else if (face == 4) d = vec3(c.x, -c.y, 1.0);
    else d = vec3(-c.x, -c.y, -1.0);
    return normalize(d);
}

void main() {
    vec3 n = pbrlab_cube_face_direction(u_face, gl_FragCoord.xy / u_face_size);
    out_radiance = vec4(textureLod(u_source, pbr_equirect_uv(n), 0.0).rgb, 1.0);
}
