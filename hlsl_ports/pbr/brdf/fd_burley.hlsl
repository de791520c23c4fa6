// pbr/brdf/fd_burley.hlsl: the Disney ("Burley") diffuse BRDF.
//
// Provides: float pbr_Fd_Burley(float NdotV, float NdotL, float LdotH, float perceptualRoughness)
// Include:  "pbr/brdf/fd_burley.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Burley 2012, "Physically-Based Shading at Disney", §5.3 (diffuse model details):
//   f_d = (1/π) · (1 + (F_D90 - 1)(1 - NdotL)^5) · (1 + (F_D90 - 1)(1 - NdotV)^5),
//   F_D90 = 0.5 + 2 · roughness · LdotH²,
// where Burley's "roughness" is our perceptualRoughness. Returns the 1/π but not the base
// colour. Reciprocal (symmetric in NdotL, NdotV; LdotH == VdotH). Not energy conserving
// by design (retro-reflection lifts grazing albedo above 1 for rough surfaces, Burley
// 2012 §5.3); the white-furnace test reports it rather than asserting <= 1.
// Guard: the three cosines and perceptualRoughness are saturated, so Fd stays in
// [0.25/π, 6.25/π] whatever the normal; bit-identical on [0, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_FD_BURLEY_HLSL
#define PBR_BRDF_FD_BURLEY_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/fd_burley.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/math.hlsl"

#define PBR_BURLEY_FD90_BASE 0.5  // F_D90 at roughness 0 or LdotH = 0 (Burley 2012 §5.3)

float pbr_Fd_Burley(float NdotV, float NdotL, float LdotH, float perceptualRoughness) {
    LdotH = pbr_saturate(LdotH);
    float fd90 = PBR_BURLEY_FD90_BASE + 2.0 * pbr_saturate(perceptualRoughness) * LdotH * LdotH;
    float lightScatter = 1.0 + (fd90 - 1.0) * pbr_pow5(1.0 - pbr_saturate(NdotL));
    float viewScatter  = 1.0 + (fd90 - 1.0) * pbr_pow5(1.0 - pbr_saturate(NdotV));
    return lightScatter * viewScatter * PBR_INV_PI;
}

#endif // PBR_BRDF_FD_BURLEY_HLSL
