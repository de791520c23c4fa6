// pbr/material/remap.hlsl: roughness vocabulary converters and the lecture's gloss remaps.
//
// Provides: pbr_perceptual_roughness_from_smoothness, pbr_alpha_from_perceptual_roughness,
//           pbr_perceptual_roughness_from_alpha, pbr_alpha_from_smoothness,
//           pbr_specPower_from_gloss_CallOfDuty, pbr_alpha_from_gloss_Crytek,
//           pbr_alpha_from_gloss_Unreal, pbr_specPower_from_alpha, pbr_alpha_from_specPower.
// Include:  "pbr/material/remap.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Vocabulary (pbr/common/conventions.hlsl §3): smoothness = gloss g (0 rough .. 1 smooth)
// -> perceptualRoughness = 1 - g -> alpha = perceptualRoughness². The lecture's "gloss" g
// is the same quantity as Unity's smoothness. float64 twin: reference/remap.py.
//
// Guards (pbr/common/guards.hlsl): pbr_perceptual_roughness_from_alpha takes sqrt(max(alpha, 0))
// (sqrt of a negative is undefined); pbr_specPower_from_alpha clamps alpha to
// [PBR_MIN_ALPHA, 1] (alpha = 0 is 2/0: decided s = 2e14, the power of the narrowest
// representable lobe; alpha > 1 would give s < 0); pbr_alpha_from_specPower takes s >= 0.
// Bit-identical inside those ranges. The other remaps are polynomials on [0, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_MATERIAL_REMAP_HLSL
#define PBR_MATERIAL_REMAP_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/material/remap.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/guards.hlsl"

// Unity Standard shader: perceptualRoughness = 1 - smoothness (UnityStandardBRDF.cginc,
// SmoothnessToPerceptualRoughness).
float pbr_perceptual_roughness_from_smoothness(float smoothness) { return 1.0 - smoothness; }

// Burley 2012, "Physically-Based Shading at Disney", §5.4 (specular D): alpha = roughness², which makes
// the roughness slider perceptually linear. Karis 2013 ("Real Shading in Unreal Engine 4")
// adopts it.
float pbr_alpha_from_perceptual_roughness(float perceptualRoughness) {
    return perceptualRoughness * perceptualRoughness;
}

float pbr_perceptual_roughness_from_alpha(float alpha) { return sqrt(max(alpha, 0.0)); }

float pbr_alpha_from_smoothness(float smoothness) {
    return pbr_alpha_from_perceptual_roughness(pbr_perceptual_roughness_from_smoothness(smoothness));
}

// Call of Duty: Black Ops (Lazarov 2011, "Physically-Based Lighting in Call of Duty:
// Black Ops", SIGGRAPH course; the lecture's "Blinn-Phong microfacet distribution"):
// s = 8192^g = 2^(13 g), so s spans 1 .. 8192.
#define PBR_CALLOFDUTY_LOG2_MAX_SPEC_POWER 13.0  // log2(8192)
float pbr_specPower_from_gloss_CallOfDuty(float gloss) {
    return exp2(PBR_CALLOFDUTY_LOG2_MAX_SPEC_POWER * gloss);
}

// Crytek, as quoted by the lecture ("GGX microfacet distribution"): alpha = (1 - 0.7 g)²,
// which keeps alpha >= 0.09 at g = 1 (no perfect mirrors).
#define PBR_CRYTEK_GLOSS_SCALE 0.7
float pbr_alpha_from_gloss_Crytek(float gloss) {
    float r = 1.0 - PBR_CRYTEK_GLOSS_SCALE * gloss;
    return r * r;
}

// Unreal (Karis 2013, "Real Shading in Unreal Engine 4", p. 2): alpha = (1 - g)², the
// Disney roughness squared; identical to pbr_alpha_from_smoothness.
float pbr_alpha_from_gloss_Unreal(float gloss) {
    float r = 1.0 - gloss;
    return r * r;
}

// Blinn-Phong exponent <-> microfacet alpha: Walter et al. 2007, "Microfacet Models for
// Refraction through Rough Surfaces", §5.2 (after eq. 33): s = 2 / alpha² - 2 makes the
// Phong/Blinn-Phong distribution match Beckmann of width alpha (and is the usual match for
// GGX). Valid for alpha in (0, 1]: alpha = 1 gives s = 0; alpha -> 0 gives s -> infinity.
float pbr_specPower_from_alpha(float alpha) {
    alpha = clamp(alpha, PBR_MIN_ALPHA, 1.0);
    return 2.0 / (alpha * alpha) - 2.0;
}
float pbr_alpha_from_specPower(float specPower) { return sqrt(2.0 / (max(specPower, 0.0) + 2.0)); }

#endif // PBR_MATERIAL_REMAP_HLSL
