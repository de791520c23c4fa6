// pbr/brdf/fd_lambert.glsl: the Lambertian diffuse BRDF.
//
// Provides: float pbr_Fd_Lambert()
// Include:  "pbr/brdf/fd_lambert.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Lambert 1760, "Photometria"; as a BRDF f = M_diff / π (the lecture's "classic diffuse
// lighting model"). Returns the 1/π only; multiply by the diffuse colour. Reciprocal
// (constant) and energy conserving: ∫ (1/π) cos dω = 1 over the hemisphere.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_FD_LAMBERT_GLSL
#define PBR_BRDF_FD_LAMBERT_GLSL

#include "pbr/common/constants.glsl"

float pbr_Fd_Lambert() { return PBR_INV_PI; }

#endif // PBR_BRDF_FD_LAMBERT_GLSL
