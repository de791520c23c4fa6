// pbr/brdf/d_blinn_phong.hlsl: the Blinn-Phong microfacet distribution.
//
// Provides: float pbr_D_BlinnPhong(float NdotH, float specPower)
// Include:  "pbr/brdf/d_blinn_phong.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// D_BP(h) = (s + 2) / (2π) · NdotH^s: the lecture's "Blinn-Phong microfacet distribution";
// Blinn 1977 for the shape, the (s+2)/(2π) normalisation makes ∫ D (n·h) dω_h = 1 exactly
// (Akenine-Möller, Haines, Hoffman 2008, RTR 3rd ed., eq. 7.47; tested by quadrature).
// Use pbr_specPower_from_alpha (pbr/material/remap.hlsl) to match a GGX/Beckmann alpha.
// NdotH in [0, 1], specPower > 0. pow(x, s) with s up to 8192 (Call of Duty range) loses
// relative accuracy ~ s · 2^-24 · |log x| on GPUs that implement pow as exp2(s · log2 x).
// Guards: NdotH saturated, specPower >= 0, pow through pbr_pow_safe (0^0 = 1: power 0 is
// the uniform lobe 1/π); bit-identical on NdotH in [2^-126, 1], specPower >= 0.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_D_BLINN_PHONG_HLSL
#define PBR_BRDF_D_BLINN_PHONG_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/d_blinn_phong.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/guards.hlsl"

float pbr_D_BlinnPhong(float NdotH, float specPower) {
    specPower = max(specPower, 0.0);
    return (specPower + 2.0) * (0.5 * PBR_INV_PI) * pbr_pow_safe(pbr_saturate(NdotH), specPower);
}

#endif // PBR_BRDF_D_BLINN_PHONG_HLSL
