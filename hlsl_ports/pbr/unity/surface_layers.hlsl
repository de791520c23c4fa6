// pbr/unity/surface_layers.hlsl: the layers of current engines' materials beside Unity's
// SurfaceOutputStandard, by the names Unity's URP and HDRP give them.
//
// Provides: struct SurfaceOutputStandardLayers
//           vec4 LightingStandardLayers(vec4 base, SurfaceOutputStandardLayers s, vec3 normal,
//                                       vec3 viewDir, UnityGI gi, vec3 sheenIndirect,
//                                       vec3 coatIndirectSpecular, float occlusion)
// Include:  "pbr/unity/surface_layers.hlsl" (path relative to glsl/; it includes
//           pbr/unity/surface_standard.hlsl).
// Config macros read: PBR_LAYERS_SHEEN, PBR_LAYERS_CLEARCOAT (1 by default; a caller that
//           knows a layer is absent defines it 0 and LightingStandardLayers skips that
//           layer's code); those of pbr/surface/lighting_clearcoat.hlsl and
//           pbr/surface/lighting_sheen.hlsl.
//
// Unity's built-in pipeline has no layers; its Standard struct stays as Unity defines it.
// The fields here are named as URP's SurfaceData names them (clearCoatMask,
// clearCoatSmoothness: URP 12+, "Clear Coat" of the Complex Lit shader), capitalised as
// Unity's surface structs are. ClearCoatNormal is pbrlab's (URP coats along the geometric
// normal): tangent space as a surface function writes it, (0, 0, 1) being the interpolated
// normal, not the base's normal map (KHR_materials_clearcoat: "If clearcoatNormalTexture is
// not given, no normal mapping is applied to the clear coat layer"); the caller transforms it
// to world space before lighting, as it does s.Normal. LightingStandardLayers coats a
// base LightingStandard[Specular] result: base.rgb as pbr_lighting_clearcoat reads it (the
// emission added before, it lies under the coat), alpha kept. coatIndirectSpecular: the
// prefiltered environment along reflect(-viewDir, ClearCoatNormal) at the coat's roughness.
// The sheen (KHR_materials_sheen) lies on the base, under the coat, as the specification
// and the Khronos Sample Renderer order them: LightingStandardLayers applies
// pbr_lighting_sheen to base.rgb, then coats the result. SheenColor (linear, 0 = no sheen:
// KHR's sheenColor) and SheenSmoothness (1 - KHR's sheenRoughness, Unity's smoothness
// vocabulary as ClearCoatSmoothness) are pbrlab's names: Unity has no sheen layer beside
// its Standard model (HDRP's Fabric material, whose whole specular lobe is a sheen, calls
// the colour "Specular Color" and its roughness "Smoothness": SurfaceData.specularColor,
// perceptualSmoothness). normal: the base's world-space normal (the sheen's, per KHR);
// sheenIndirect: the prefiltered environment along reflect(-viewDir, normal) at the sheen's
// roughness.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_SURFACE_LAYERS_HLSL
#define PBR_UNITY_SURFACE_LAYERS_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/unity/surface_layers.glsl by harness/pbrlab/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/unity/surface_standard.hlsl"
#include "pbr/surface/lighting_clearcoat.hlsl"
#include "pbr/surface/lighting_sheen.hlsl"
#include "pbr/material/remap.hlsl"

struct SurfaceOutputStandardLayers {
    float ClearCoatMask;        // 0 = no coat .. 1 (the harness's default: 0)
    float ClearCoatSmoothness;  // 0 = rough .. 1 = smooth (default 1: glTF's roughness 0)
    float3 ClearCoatNormal;       // tangent space (default (0, 0, 1): the interpolated normal)
    float3 SheenColor;            // linear (default 0: no sheen)
    float SheenSmoothness;      // 0 = rough .. 1 = smooth (default 1: glTF's sheenRoughness 0)
};

#ifndef PBR_LAYERS_SHEEN
#define PBR_LAYERS_SHEEN 1
#endif
#ifndef PBR_LAYERS_CLEARCOAT
#define PBR_LAYERS_CLEARCOAT 1
#endif

float4 LightingStandardLayers(float4 base, SurfaceOutputStandardLayers s, float3 normal, float3 viewDir, UnityGI gi,
                            float3 sheenIndirect, float3 coatIndirectSpecular, float occlusion) {
    float3 c = base.rgb;
#if PBR_LAYERS_SHEEN
    pbr_Sheen sheen;
    sheen.color = s.SheenColor;
    sheen.perceptualRoughness = pbr_perceptual_roughness_from_smoothness(s.SheenSmoothness);
    c = pbr_lighting_sheen(c, sheen, normal, viewDir, gi, sheenIndirect, occlusion);
#endif
#if PBR_LAYERS_CLEARCOAT
    pbr_ClearCoat coat;
    coat.mask = s.ClearCoatMask;
    coat.perceptualRoughness = pbr_perceptual_roughness_from_smoothness(s.ClearCoatSmoothness);
    coat.normal = normalize(s.ClearCoatNormal);
    c = pbr_lighting_clearcoat(c, coat, viewDir, gi, coatIndirectSpecular, occlusion);
#endif
    return float4(c, base.a);
}
#endif
