// pbr/shading/clearcoat.hlsl: a clear coat over any base: a second, white GGX lobe of its
// own roughness and normal, and the base attenuated by what the coat reflects.
//
// Provides: PBR_CLEARCOAT_IOR, PBR_CLEARCOAT_F0, the PBR_CLEARCOAT_LAYERING_* values
//           vec3  pbr_clearcoat_punctual(vec3 nc, vec3 v, vec3 l, vec3 lightRadiance,
//                                        float coatPerceptualRoughness)
//           float pbr_clearcoat_albedo(vec2 dfgCoat)
//           float pbr_clearcoat_base_weight(float coatMask, float NcdotV, vec2 dfgCoat)
// Include:  "pbr/shading/clearcoat.hlsl" (path relative to hlsl_ports/)
// Config macros read: PBR_CLEARCOAT_LAYERING  PBR_CLEARCOAT_LAYERING_ALBEDO (default) |
//           PBR_CLEARCOAT_LAYERING_FRESNEL; those of pbr/shading/dispatch.hlsl (the coat
//           lobe is the tier's own D · V, with Schlick F).
//
// KHR_materials_clearcoat ("Clearcoat" and "Layering" sections of the extension's README):
//   coated = mix(base, coat_brdf, clearcoat · F_coat),   coat_brdf = D · V of the coat's
//   alpha = clearcoatRoughness² and normal, F_coat from IOR 1.5 (F0 = 0.04, F90 = 1).
// The coat lobe here is D · V · F(VdotH) of pbr_brdf_standard with no diffuse and f0 = 0.04
// (F90 = pbr_f90_from_f0(0.04) = 1), through pbr_shade_punctual's light units. What the base
// keeps (pbr_clearcoat_base_weight) has two forms:
//   _FRESNEL  1 - mask · F_Schlick(0.04, 1, NcdotV): the specification's (and the Khronos
//             sample viewer's) Fresnel at the view angle. It takes from the base what a
//             smooth coat reflects, which a rough coat does not: under a white furnace
//             (base albedo 1, mask 1) coat + base lose up to 91 % at grazing view and
//             roughness 1 (E_coat 0.085 against F 0.996) and gain 9e-4 where E_coat > F
//             (NcdotV 0.5, roughness 0.25), above the furnace bound of 1e-4 (measured in
//             float64: tests/library/test_clearcoat.py).
//   _ALBEDO   1 - mask · E_coat(NcdotV), E_coat the coat's single-scattering directional
//             albedo from the same DFG values as the split sum (f0 A + f90 B, Karis 2013):
//             what the coat reflects is taken from the base, so base ≤ 1 gives
//             coat + base ≤ 1 at every roughness (Kulla & Conty 2017, "Revisiting Physically
//             Based Shading at Imageworks", albedo scaling; Filament §4.9 uses F(NcdotV) as
//             the cheap form of the same idea). Equal to _FRESNEL for a smooth coat.
// Both are v-only factors: the base's direct and environment light are scaled alike, as
// the specification's layering does. Contract: nc, v, l unit; coatPerceptualRoughness is
// clamped by the tier (pbr_clamp_perceptual_roughness); mask in [0, 1]. dfgCoat =
// pbr_env_brdf(NcdotV, coat roughness). Python twin: harness/pbrlab/maths/reference/clearcoat.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_CLEARCOAT_HLSL
#define PBR_SHADING_CLEARCOAT_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/shading/clearcoat.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/lighting/punctual.hlsl"
#include "pbr/ibl/environment_brdf.hlsl"
#include "pbr/brdf/f_schlick.hlsl"
#include "pbr/common/math.hlsl"

// KHR_materials_clearcoat: "The clearcoat layer ... has an index of refraction of 1.5":
// F0 = ((1.5 - 1) / (1.5 + 1))² = 0.04 exactly.
#define PBR_CLEARCOAT_IOR 1.5
#define PBR_CLEARCOAT_F0 0.04

#define PBR_CLEARCOAT_LAYERING_ALBEDO 1
#define PBR_CLEARCOAT_LAYERING_FRESNEL 2
#ifndef PBR_CLEARCOAT_LAYERING
// PBR_CLEARCOAT_LAYERING_ALBEDO as a number (glsl/README.md, one-level preprocessors)
#define PBR_CLEARCOAT_LAYERING 1
#endif
#if PBR_CLEARCOAT_LAYERING != PBR_CLEARCOAT_LAYERING_ALBEDO && PBR_CLEARCOAT_LAYERING != PBR_CLEARCOAT_LAYERING_FRESNEL
#error "PBR_CLEARCOAT_LAYERING: unknown value"
#endif

// The coat's reflection of one punctual light: the lecture's C_light · π · BRDF · NdotL with
// the coat's lobe (no diffuse).
float3 pbr_clearcoat_punctual(float3 nc, float3 v, float3 l, float3 lightRadiance, float coatPerceptualRoughness) {
    return pbr_shade_punctual(nc, v, l, lightRadiance, ((float3)(0.0)), ((float3)(PBR_CLEARCOAT_F0)),
                              coatPerceptualRoughness);
}

// The coat's directional albedo (single scattering, Schlick F with F0 0.04 and F90 1),
// saturated: the analytic DFG fit (pbr_env_brdf without a table) reaches 1.04 at grazing view.
float pbr_clearcoat_albedo(float2 dfgCoat) {
    return pbr_saturate(PBR_CLEARCOAT_F0 * dfgCoat.x + pbr_f90_from_f0(((float3)(PBR_CLEARCOAT_F0))) * dfgCoat.y);
}

// What the base keeps under a coat of this mask (see the header for the two forms).
float pbr_clearcoat_base_weight(float coatMask, float NcdotV, float2 dfgCoat) {
#if PBR_CLEARCOAT_LAYERING == PBR_CLEARCOAT_LAYERING_FRESNEL
    float reflected = pbr_F_Schlick(((float3)(PBR_CLEARCOAT_F0)), 1.0, NcdotV).x;
#else
    float reflected = pbr_clearcoat_albedo(dfgCoat);
#endif
    return 1.0 - coatMask * reflected;
}

#endif // PBR_SHADING_CLEARCOAT_HLSL
