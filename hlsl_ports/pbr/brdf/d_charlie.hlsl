// pbr/brdf/d_charlie.hlsl: the "Charlie" sheen distribution of KHR_materials_sheen.
//
// Provides: float pbr_D_Charlie(float NdotH, float alpha)
//           PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS, PBR_SHEEN_MIN_ALPHA
// Include:  "pbr/brdf/d_charlie.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF" (SIGGRAPH 2017 course
// "Physically Based Shading in Theory and Practice"), eq. 2, an exponentiated sine:
//   D = (2 + 1/alpha) sin(θh)^(1/alpha) / (2π),
// with alpha = sheenPerceptualRoughness² (KHR_materials_sheen's alpha_g; the paper's r).
// Fibres stand along n, so their normals lie near the horizon: D peaks at NdotH = 0 and is 0
// at NdotH = 1. Normalised: ∫ D (n·h) dω_h = (2 + k) ∫ sin^(k+1) θ cos θ dθ = 1, k = 1/alpha
// (tested). Written as (2 + 1/alpha) · (sin²θh)^(1/(2 alpha)) · 1/(2π), sin²θh = (1 - NdotH)(1 + NdotH).
// Guards: NdotH saturated; alpha clamped to [PBR_SHEEN_MIN_ALPHA, 1]. The floor is
// perceptual roughness 0.07 (three.js's sheen clamp), alpha = 0.0049: at alpha -> 0 the
// exponent 1/(2 alpha) diverges (KHR's default sheenRoughness is 0), and GLSL's pow inherits
// log2's absolute error 2^-21 times the exponent (GLSL 4.60 §4.7.1): at the floor the
// exponent is 102 and the relative error of D at most ln2 · 102 · 2^-21 = 3.4e-5 (measured on
// llvmpipe against float64: tests/library/test_sheen.py). Roughness 0 returns D at the floor
// (peak (2 + 1/0.0049)/(2π) = 32.8 1/sr), exactly. The same floor keeps the sheen albedo table
// (harness/pbrlab/gpu/sheen_table.py) resolvable: E's grazing peak narrows with alpha.
// sin²θh = 0 (NdotH = 1) raises 0 to a positive power: pbr_pow_safe returns the limit 0.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_D_CHARLIE_HLSL
#define PBR_BRDF_D_CHARLIE_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/d_charlie.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/math.hlsl"
#include "pbr/common/guards.hlsl"

// The sheen roughness floor (see above); shared with harness/pbrlab/maths/reference/sheen.py
// SHEEN_MIN_PERCEPTUAL_ROUGHNESS and SHEEN_MIN_ALPHA (tested equal).
#define PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS 0.07
#define PBR_SHEEN_MIN_ALPHA 0.0049

float pbr_D_Charlie(float NdotH, float alpha) {
    alpha = clamp(alpha, PBR_SHEEN_MIN_ALPHA, 1.0);
    NdotH = pbr_saturate(NdotH);
    float invAlpha = 1.0 / alpha;
    float sin2h = (1.0 - NdotH) * (1.0 + NdotH);
    return (2.0 + invAlpha) * pbr_pow_safe(sin2h, 0.5 * invAlpha) * (0.5 * PBR_INV_PI);
}

#endif // PBR_BRDF_D_CHARLIE_HLSL
