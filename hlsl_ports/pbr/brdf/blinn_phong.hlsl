// pbr/brdf/blinn_phong.hlsl: the lecture's Blinn-Phong lighting models (not microfacet).
//
// Provides: float pbr_BRDF_BlinnPhongClassic(float NdotH, float NdotL, float specPower)
//           float pbr_BRDF_BlinnPhongModified(float NdotH, float specPower)
//           float pbr_BRDF_BlinnPhongNormalized(float NdotH, float specPower)
// Include:  "pbr/brdf/blinn_phong.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Each returns the BRDF divided by the specular colour M_spec (1/sr); multiply by M_spec.
// Blinn 1977, "Models of Light Reflection for Computer Synthesized Pictures"; the forms
// and names are the lecture's (slides "Classic Blinn-Phong", "Modified Blinn-Phong",
// "Normalized modified Blinn-Phong", after McAuley 2011 and Driscoll 2009):
//   classic     (1/π) · NdotH^s / NdotL  for NdotL > 0 (0 otherwise). The 1/NdotL cancels
//               the lighting cosine so that C = C_light · M_spec · NdotH^s, the fixed-
//               function result; it makes the BRDF NOT reciprocal (tested).
//   modified    (1/π) · NdotH^s: reciprocal (tested), but not normalised: its
//               directional albedo falls like ~8/s as s grows, so sharper highlights
//               get dimmer (the lecture's "Without Normalization Factor").
//   normalized  (s + 8) / (8π) · NdotH^s: Akenine-Möller, Haines, Hoffman 2008,
//               "Real-Time Rendering" 3rd ed., eq. 7.49; the (s+8)/8 factor is an
//               approximation of the exact normalisation; its directional albedo is
//               measured by the white-furnace test (tests/library/test_brdf_properties.py).
// Guards (pbr/common/guards.hlsl): NdotH saturated, specPower >= 0, pow through
// pbr_pow_safe (0^0 = 1); the classic form divides by max(NdotL, PBR_MIN_NDOTV) (its 1/NdotL
// would be 1/denormal at grazing; the lit value pow · NdotL / max(NdotL, 1e-4) still goes
// to 0 with NdotL). Bit-identical for NdotH in [2^-126, 1], specPower >= 0, NdotL >= 1e-4.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_BLINN_PHONG_HLSL
#define PBR_BRDF_BLINN_PHONG_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/blinn_phong.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/guards.hlsl"

// NdotH^s with the guards above.
float pbr_blinn_phong_lobe(float NdotH, float specPower) {
    return pbr_pow_safe(pbr_saturate(NdotH), max(specPower, 0.0));
}

float pbr_BRDF_BlinnPhongClassic(float NdotH, float NdotL, float specPower) {
    return NdotL > 0.0
        ? PBR_INV_PI * pbr_blinn_phong_lobe(NdotH, specPower) / max(NdotL, PBR_MIN_NDOTV)
        : 0.0;
}

float pbr_BRDF_BlinnPhongModified(float NdotH, float specPower) {
    return PBR_INV_PI * pbr_blinn_phong_lobe(NdotH, specPower);
}

float pbr_BRDF_BlinnPhongNormalized(float NdotH, float specPower) {
    return (max(specPower, 0.0) + 8.0) / (8.0 * PBR_PI) * pbr_blinn_phong_lobe(NdotH, specPower);
}

#endif // PBR_BRDF_BLINN_PHONG_HLSL
