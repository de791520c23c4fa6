// pbr/lighting/sh9.glsl: irradiance from order-2 spherical harmonics (9 RGB coefficients).
//
// Provides: vec3 pbr_sh9_irradiance(vec3 sh[9], vec3 n)
// Include:  "pbr/lighting/sh9.glsl" (path relative to glsl/)
// Config macros read: none.
//
// sh[] holds the projection of the environment's radiance on the real SH basis, in the
// order L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (harness/pbrlab/scene/environment.py
// computes it). The result is the irradiance E(n); a Lambert surface reflects
// diffuseColor * E(n) / pi. For a constant radiance L the result is exactly pi * L.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_LIGHTING_SH9_GLSL
#define PBR_LIGHTING_SH9_GLSL

// Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment
// Maps", eq. 13: the clamped-cosine convolution folded into five constants.
#define PBR_SH9_C1 0.429043
#define PBR_SH9_C2 0.511664
#define PBR_SH9_C3 0.743125
#define PBR_SH9_C4 0.886227
#define PBR_SH9_C5 0.247708

vec3 pbr_sh9_irradiance(vec3 sh[9], vec3 n) {
    return PBR_SH9_C1 * sh[8] * (n.x * n.x - n.y * n.y) + PBR_SH9_C3 * sh[6] * n.z * n.z
         + PBR_SH9_C4 * sh[0] - PBR_SH9_C5 * sh[6]
         + 2.0 * PBR_SH9_C1 * (sh[4] * n.x * n.y + sh[7] * n.x * n.z + sh[5] * n.y * n.z)
         + 2.0 * PBR_SH9_C2 * (sh[3] * n.x + sh[1] * n.y + sh[2] * n.z);
}
#endif
