// pbr/brdf/v_implicit.hlsl: the implicit geometric term.
//
// Provides: float pbr_G_Implicit(float NdotL, float NdotV), float pbr_V_Implicit()
// Include:  "pbr/brdf/v_implicit.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Hoffman 2010, "Physically-Based Shading Models in Film and Game Production" (SIGGRAPH
// course), and Akenine-Möller, Haines, Hoffman 2008 (RTR 3rd ed., §7.6): the "implicit"
// G = NdotL · NdotV, which cancels the microfacet denominator:
//   V_Implicit = G / (4 NdotL NdotV) = 1/4.
// Lecture discrepancy: the lecture's slide "Implicit geometric term" writes
// G_I = 4 (n·L)(n·V) and Viz_I = 1. That G reaches 4 > 1, which no masking-shadowing
// function can (G is a visible fraction), and makes GGX + Viz_I reflect up to 4x the
// energy it receives (tests/library/test_brdf_properties.py). We keep the visibility
// convention V = G / (4 NdotL NdotV) of every other term and Hoffman's G, hence 1/4;
// the lecture's Viz_I = 1 equals 4 · pbr_V_Implicit().
// Guard: G's cosines are saturated (G stays in [0, 1] for unnormalised or back-facing
// normals); bit-identical on [0, 1].
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_V_IMPLICIT_HLSL
#define PBR_BRDF_V_IMPLICIT_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/v_implicit.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/math.hlsl"

float pbr_G_Implicit(float NdotL, float NdotV) { return pbr_saturate(NdotL) * pbr_saturate(NdotV); }

float pbr_V_Implicit() { return 0.25; }

#endif // PBR_BRDF_V_IMPLICIT_HLSL
