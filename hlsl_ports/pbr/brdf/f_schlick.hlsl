// pbr/brdf/f_schlick.hlsl: Schlick's Fresnel approximation and its variants.
//
// Provides: float pbr_F_Schlick(float f0, float VdotH)
//           vec3  pbr_F_Schlick(vec3 f0, float VdotH)
//           vec3  pbr_F_Schlick(vec3 f0, float f90, float VdotH)
//           vec3  pbr_F_SchlickSG(vec3 f0, float VdotH)
//           vec3  pbr_F_SchlickSG(vec3 f0, float f90, float VdotH)
//           float pbr_f90_from_f0(vec3 f0)
// Include:  "pbr/brdf/f_schlick.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering":
//   F = F0 + (1 - F0)(1 - VdotH)^5                (the lecture's "Schlick approximation")
// and with an explicit grazing reflectance F90 (Burley 2012 §5.5; Filament §4.4.3):
//   F = F0 + (F90 - F0)(1 - VdotH)^5.
// In microfacet specular the cosine is VdotH (= LdotH), the angle to the microfacet
// normal h, NOT NdotV: the lecture's "reflective paradox" (Reed, thetenthplanet.de/255).
// F -> 1 at grazing (VdotH -> 0) for every F0: "everything has Fresnel" (tested).
// (1 - VdotH)^5 by multiplication (pbr_pow5).
// Spherical-Gaussian form: Lagarde 2012, "Spherical Gaussian approximation for Blinn-Phong,
// Phong and Fresnel"; Karis 2013, "Real Shading in Unreal Engine 4", p. 3:
//   F ≈ F0 + (1 - F0) · 2^((-5.55473 VdotH - 6.98316) VdotH).
// Its worst absolute deviation from Schlick over VdotH in [0, 1], any F0 in [0, 1], is
// 0.00377 · (1 - F0), at VdotH = 0.0554 (float64, 1e5 samples); exact at VdotH = 0.
// Bound PBR_F_SCHLICK_SG_MAX_ABS_ERROR, checked on the GPU by
// tests/library/test_brdf_terms.py::test_F_SchlickSG_error_bound.
// F90 from F0 (what pbr/shading/dispatch.hlsl feeds every Schlick form): Schüler 2009,
// "An Efficient and Physically Plausible Real-Time Shading Model" (ShaderX7, ch. 2.6):
// no real material has F0 below 0.02, so a smaller F0 is read as baked-in specular
// occlusion and the grazing reflectance fades with it; Filament's brdf.fs fresnel()
// writes it f90 = saturate(dot(f0, vec3(50 * 0.33))). F0 = 0 gives F90 = 0: no specular
// at all (Unity reaches the same end with any(specColor) in BRDF1_Unity_PBS). Grey F0 at
// or above 1 / (3 * 16.5) = 0.0202 keeps F90 = 1 ("everything has Fresnel").
// Guard: VdotH is saturated in every form (VdotH slightly above 1 from rounding would make
// (1 - VdotH)^5 negative and F < F0, below 0 for F0 = 0); bit-identical on [0, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_F_SCHLICK_HLSL
#define PBR_BRDF_F_SCHLICK_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/f_schlick.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"

#define PBR_F_SCHLICK_SG_A -5.55473  // Lagarde 2012 / Karis 2013 fit coefficients
#define PBR_F_SCHLICK_SG_B -6.98316
#define PBR_F_SCHLICK_SG_MAX_ABS_ERROR 0.0038  // bound on |SG - Schlick|, see above
#define PBR_F90_FROM_F0_SCALE 16.5  // 50 * 0.33, Schüler 2009 / Filament brdf.fs (see above)

float pbr_F_Schlick(float f0, float VdotH) {
    return f0 + (1.0 - f0) * pbr_pow5(1.0 - pbr_saturate(VdotH));
}

float3 pbr_F_Schlick(float3 f0, float VdotH) {
    return f0 + (((float3)(1.0)) - f0) * pbr_pow5(1.0 - pbr_saturate(VdotH));
}

float3 pbr_F_Schlick(float3 f0, float f90, float VdotH) {
    return f0 + (((float3)(f90)) - f0) * pbr_pow5(1.0 - pbr_saturate(VdotH));
}

float3 pbr_F_SchlickSG(float3 f0, float VdotH) {
    VdotH = pbr_saturate(VdotH);
    float w = exp2((PBR_F_SCHLICK_SG_A * VdotH + PBR_F_SCHLICK_SG_B) * VdotH);
    return f0 + (((float3)(1.0)) - f0) * w;
}

float3 pbr_F_SchlickSG(float3 f0, float f90, float VdotH) {
    VdotH = pbr_saturate(VdotH);
    float w = exp2((PBR_F_SCHLICK_SG_A * VdotH + PBR_F_SCHLICK_SG_B) * VdotH);
    return f0 + (((float3)(f90)) - f0) * w;
}

float pbr_f90_from_f0(float3 f0) {
    return pbr_saturate(dot(f0, ((float3)(PBR_F90_FROM_F0_SCALE))));
}

#endif // PBR_BRDF_F_SCHLICK_HLSL
