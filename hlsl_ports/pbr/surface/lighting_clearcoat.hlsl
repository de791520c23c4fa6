// pbr/surface/lighting_clearcoat.hlsl: a clear coat over a lit base, for one punctual light
// and the environment: the coat layer of the surface API (pbr/unity/surface_layers.hlsl
// gives it Unity's names).
//
// Provides: struct pbr_ClearCoat
//           vec3 pbr_lighting_clearcoat(vec3 base, pbr_ClearCoat coat, vec3 v, pbr_GI gi,
//                                       vec3 coatPrefiltered, float occlusion)
// Include:  "pbr/surface/lighting_clearcoat.hlsl" (path relative to hlsl_ports/)
// Config macros read: those of pbr/shading/clearcoat.hlsl and pbr/surface/lighting_standard.hlsl.
//
// base is what the base material reflects of gi (pbr_lighting_standard, or any model) plus
// whatever lies under the coat (emission: KHR_materials_clearcoat puts the coat "on top of
// emission"); the result is base · pbr_clearcoat_base_weight + mask · (the coat's reflection
// of gi.light + coatPrefiltered · E_coat · specular occlusion). coatPrefiltered is the
// prefiltered environment along reflect(-v, coat.normal) at the coat's roughness (0 for a
// call that carries only a punctual light, as gi.light.color is 0 for the environment's
// call). coat.normal is in world space, unit; coat.mask in [0, 1]. The coat reflects at
// most E_coat of a white environment and the base keeps 1 - mask · E_coat (the default
// layering), so a base that reflects at most 1 stays at most 1 coated
// (tests/render/test_white_furnace.py). Python twin: reference/clearcoat.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SURFACE_LIGHTING_CLEARCOAT_HLSL
#define PBR_SURFACE_LIGHTING_CLEARCOAT_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/surface/lighting_clearcoat.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/surface/lighting_standard.hlsl"
#include "pbr/shading/clearcoat.hlsl"

struct pbr_ClearCoat {
    float mask;                 // 0: no coat, 1: full coat (glTF clearcoatFactor x texture.r)
    float perceptualRoughness;  // glTF clearcoatRoughnessFactor x texture.g
    float3 normal;                // world space (glTF: the geometric normal unless mapped)
};

float3 pbr_lighting_clearcoat(float3 base, pbr_ClearCoat coat, float3 v, pbr_GI gi,
                            float3 coatPrefiltered, float occlusion) {
    float roughness = pbr_clamp_perceptual_roughness(coat.perceptualRoughness);
    float NcdotV = max(dot(coat.normal, v), PBR_MIN_NDOTV);
    float2 dfg = pbr_env_brdf(NcdotV, roughness);
    float3 direct = pbr_clearcoat_punctual(coat.normal, v, gi.light.dir, gi.light.color, roughness);
    float3 environment = coatPrefiltered * (pbr_clearcoat_albedo(dfg)
                     * pbr_specular_occlusion(NcdotV, occlusion, roughness * roughness));
    return base * pbr_clearcoat_base_weight(coat.mask, NcdotV, dfg) + coat.mask * (direct + environment);
}
#endif
