// pbr/material/ior.hlsl: F0 <-> index of refraction at normal incidence.
//
// Provides: pbr_f0_from_ior(float eta), pbr_ior_from_f0(float f0).
// Include:  "pbr/material/ior.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Fresnel's equations at normal incidence (Born & Wolf, "Principles of Optics", §1.5.3,
// eq. 1.5.(22) for theta = 0): F0 = ((eta - 1) / (eta + 1))², eta = n_inside / n_outside
// (real part only: valid for dielectrics, not metals). Inverse: eta = (1 + sqrt F0) /
// (1 - sqrt F0), for F0 in [0, 1). pbr_f0_from_ior(eta) == pbr_F_Dielectric(1.0, eta)
// (tested). float64 twin: reference/material.py.
// Guard: pbr_ior_from_f0 saturates F0 and caps eta at PBR_MAX_IOR: F0 = 1 is a perfect mirror,
// eta = 2/0 = Inf (decided: PBR_MAX_IOR). Domain of pbr_f0_from_ior: finite eta >= 0.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_MATERIAL_IOR_HLSL
#define PBR_MATERIAL_IOR_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/material/ior.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// Largest eta pbr_ior_from_f0 returns: 2^25 = 2 / 2^-24, what the formula gives one float32
// step below F0 = 1 (1 - sqrt F0 = 2^-24). Cost: none for F0 <= 1 - 2^-23.
#define PBR_MAX_IOR 33554432.0

float pbr_f0_from_ior(float eta) {
    float r = (eta - 1.0) / (eta + 1.0);
    return r * r;
}

float pbr_ior_from_f0(float f0) {
    float s = sqrt(clamp(f0, 0.0, 1.0));
    return min((1.0 + s) / (1.0 - s), PBR_MAX_IOR);  // 2/0 = +Inf -> PBR_MAX_IOR (min of Inf is defined)
}

#endif // PBR_MATERIAL_IOR_HLSL
