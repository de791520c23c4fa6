// pbr/brdf/fd_lambert.hlsl: the Lambertian diffuse BRDF.
//
// Provides: float pbr_Fd_Lambert()
// Include:  "pbr/brdf/fd_lambert.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Lambert 1760, "Photometria"; as a BRDF f = M_diff / π (the lecture's "classic diffuse
// lighting model"). Returns the 1/π only; multiply by the diffuse colour. Reciprocal
// (constant) and energy conserving: ∫ (1/π) cos dω = 1 over the hemisphere.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_FD_LAMBERT_HLSL
#define PBR_BRDF_FD_LAMBERT_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/fd_lambert.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"

float pbr_Fd_Lambert() { return PBR_INV_PI; }

#endif // PBR_BRDF_FD_LAMBERT_HLSL
