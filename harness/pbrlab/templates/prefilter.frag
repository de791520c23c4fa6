#version 330 core
// One level of the GGX-prefiltered environment (harness/pbrlab/gpu/ibl.py): each texel is
// the environment convolved with the GGX lobe around its direction, n = v = r (Karis 2013).
#include "pbr/ibl/importance_sampling.glsl"
#include "pbr/ibl/equirect.glsl"
#include "pbr/brdf/d_ggx.glsl"

uniform sampler2D u_source;        // equirect radiance with a full mip chain
uniform vec2 u_source_size;
uniform float u_source_max_lod;
uniform float u_perceptual_roughness;
uniform int u_sample_count;
uniform vec2 u_target_size;
out vec4 out_radiance;

void main() {
    vec3 n = pbr_equirect_direction(gl_FragCoord.xy / u_target_size);
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
