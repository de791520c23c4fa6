// pbr/ibl/horizon_occlusion.hlsl: the share of an environment's light that the geometric
// surface itself blocks when a normal map tilts the shading normal.
//
// Provides: float pbr_lobe_share_above(float c, float alpha)
//           float pbr_specular_horizon_occlusion(float RdotNg, float NdotV, float alpha)
//           float pbr_diffuse_horizon_occlusion(float NdotNg)
// Include:  "pbr/ibl/horizon_occlusion.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// A normal map tilts the shading normal n away from the geometric normal Ng (the interpolated
// vertex normal). The split sum's lobes are built around n, so part of them can point below
// the geometric surface: light from there would have to pass through the object. A path
// tracer sees those directions blocked (Cycles evaluates no reflection below Ng); an
// environment lookup alone does not (Russell 2015, "Horizon Occlusion for Normal Mapped
// Reflections", Marmoset; Filament section 5.6.2.1 fades it with (1 + r.Ng)^2, a hand-chosen
// falloff). Here the falloff is the lobe's own:
//
// * specular: the GGX lobe reflected about the shading normal, modelled in the tangent
//   plane of its mirror direction r: a microfacet slope s turns the reflected direction by
//   about 2 s, and the marginal of GGX's slope distribution along one axis is
//   P(s) = 1 / (2 alpha (1 + s^2 / alpha^2)^(3/2)) (Heitz 2014, "Understanding the
//   Masking-Shadowing Function in Microfacet-Based BRDFs", the slope distribution P22 of
//   section 5.2 integrated over the other axis), with cumulative 1/2 (1 + u / sqrt(1 + u^2)),
//   u = s / alpha. A plane whose normal makes cos c with r lies about c (the sine of r's
//   elevation) below r, so it blocks the slopes below -c / 2: the share above it is
//   1/2 (1 + c / sqrt(4 alpha^2 + c^2)) (pbr_lobe_share_above: one inverse square root;
//   the exact half-angle tan(asin(c) / 2) in place of c / 2 costs a square root more and
//   was measured no closer). The shading hemisphere (c = NdotV) already removes its own part
//   through the environment BRDF, so the occlusion is the ratio of the two shares, at most 1:
//   exactly 1 where n = Ng (no normal map, no change), 0 for a mirror direction below Ng, a
//   step at Ng's horizon as alpha -> 0.
//   Against the float64 share of the whole lobe (D, height-correlated G2, n.l, no Fresnel)
//   in a uniform environment (harness/pbrlab/maths/reference/horizon_occlusion.py), over
//   alpha 0.02..1, NdotV 0.05..1, tilts to 70 deg: mean error 0.035, worst 0.33 at grazing
//   view (NdotV 0.05), against 0.097 / 0.79 for Filament's falloff and 0.16 / 1.0 for none
//   (tests/library/test_horizon_occlusion.py). Its cost in whole programs:
//   benchmarks/environment_read_cost.py.
// * diffuse: the share of a cosine lobe around n that lies above the plane of Ng in a
//   uniform environment, the sky view factor of a tilted plane: (1 + n.Ng) / 2 (exact for a
//   uniform sky; 1 where n = Ng).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_HORIZON_OCCLUSION_HLSL
#define PBR_IBL_HORIZON_OCCLUSION_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/ibl/horizon_occlusion.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// The share of a GGX-reflected lobe of roughness alpha around a direction r that lies above
// a plane whose normal makes cosine c with r: 1/2 (1 + c / sqrt(4 alpha^2 + c^2)); alpha = 0
// gives the step without a division by zero, and the floor keeps c = alpha = 0 finite (the
// share is 1/2 there).
#define PBR_HORIZON_MIN_SCALE_SQUARED 1e-30
float pbr_lobe_share_above(float c, float alpha) {
    return 0.5 + 0.5 * c * rsqrt(max(4.0 * alpha * alpha + c * c, PBR_HORIZON_MIN_SCALE_SQUARED));
}

// The specular environment's horizon occlusion: RdotNg = r.Ng for the mirror direction r of
// the lookup, NdotV = n.v (= r.n) of the shading normal (> 0 in the library's clamped use:
// the share is then >= 1/2), alpha the lobe's GGX roughness.
float pbr_specular_horizon_occlusion(float RdotNg, float NdotV, float alpha) {
    return min(pbr_lobe_share_above(RdotNg, alpha) / pbr_lobe_share_above(NdotV, alpha), 1.0);
}

// The diffuse environment's horizon occlusion: the sky view factor (1 + n.Ng) / 2.
float pbr_diffuse_horizon_occlusion(float NdotNg) {
    return clamp(0.5 + 0.5 * NdotNg, 0.0, 1.0);
}

#endif // PBR_IBL_HORIZON_OCCLUSION_HLSL
