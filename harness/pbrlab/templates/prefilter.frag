#version 330 core
// One face of one level of the GGX-prefiltered environment cube (harness/pbrlab/gpu/ibl.py):
// each texel is the environment convolved with the GGX lobe around its direction, n = v = r
// (Karis 2013). The source stays the equirectangular image; the target is a cube face, so
// no texel of the result sits on a pole or a seam (issue 38).
#include "pbr/ibl/importance_sampling.glsl"
#include "pbr/ibl/equirect.glsl"
#include "pbr/brdf/d_ggx.glsl"

uniform sampler2D u_source;        // equirect radiance with a full mip chain
uniform vec2 u_source_size;
uniform float u_source_max_lod;
uniform float u_perceptual_roughness;
uniform int u_sample_count;
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
    if (u_perceptual_roughness == 0.0) {  // a mirror: the source itself
        out_radiance = vec4(textureLod(u_source, pbr_equirect_uv(n), 0.0).rgb, 1.0);
        return;
    }
    float alpha = u_perceptual_roughness * u_perceptual_roughness;
    // Solid angle of one source texel (average over the sphere).
    float texelSolidAngle = 4.0 * PBR_PI / (u_source_size.x * u_source_size.y);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    uint count = uint(u_sample_count);
    for (uint i = 0u; i < count; ++i) {
        vec3 h = pbr_tangent_to_world(pbr_importance_sample_GGX(pbr_hammersley(i, count), alpha), n);
        vec3 l = 2.0 * dot(n, h) * h - n;
        float NdotL = dot(n, l);
        if (NdotL <= 0.0) continue;
        // Filtered importance sampling (Krivanek & Colbert 2008, eq. 10): read the source
        // at the mip whose texel matches the sample's solid angle 1 / (N pdf), with
        // pdf_l = D NdotH / (4 VdotH) = D / 4 here (n = v).
        float NdotH = max(dot(n, h), 0.0);
        float pdf = pbr_D_GGX(NdotH, alpha) * 0.25;
        float sampleSolidAngle = 1.0 / (float(count) * pdf + 1e-6);
        float lod = clamp(0.5 * log2(sampleSolidAngle / texelSolidAngle) + 1.0, 0.0, u_source_max_lod);
        sum += textureLod(u_source, pbr_equirect_uv(l), lod).rgb * NdotL;
        weight += NdotL;
    }
    out_radiance = vec4(sum / max(weight, 1e-6), 1.0);
}
