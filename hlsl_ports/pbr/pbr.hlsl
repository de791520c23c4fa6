// pbr/pbr.hlsl: the umbrella include: every public file of the pbrlab shading library.
//
// Provides: everything below.
// Include:  "pbr/pbr.hlsl" (path relative to hlsl_ports/), or the individual files you need
// Config macros read: PBR_COLOR_TRANSFER (pbr/color/transfer.hlsl); PBR_QUALITY,
//           PBR_SPECULAR_D, PBR_SPECULAR_V, PBR_SPECULAR_F, PBR_DIFFUSE
//           (pbr/shading/dispatch.hlsl); PBR_SHEEN_V, PBR_SHEEN_LUT_LOOKUP (pbr/shading/sheen.hlsl);
//           PBR_TONEMAP (pbr/tonemap/tonemap.hlsl).
//           Define them before this include.
// Conventions: pbr/common/conventions.hlsl. Naming rule and function table: glsl/README.md.
// tests/library/test_glsl_layout.py checks that every .glsl file under pbr/ is listed here.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_PBR_HLSL
#define PBR_PBR_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/pbr.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// conventions and maths
#include "pbr/common/constants.hlsl"
#include "pbr/common/math.hlsl"
#include "pbr/common/guards.hlsl"
#include "pbr/common/precision.hlsl"
#include "pbr/common/conventions.hlsl"

// colour
#include "pbr/color/srgb.hlsl"
#include "pbr/color/gamma.hlsl"
#include "pbr/color/luminance.hlsl"
#include "pbr/color/transfer.hlsl"

// material remapping
#include "pbr/material/remap.hlsl"
#include "pbr/material/workflow.hlsl"
#include "pbr/material/f0_tables.hlsl"
#include "pbr/material/ior.hlsl"

// BRDF terms
#include "pbr/brdf/fd_lambert.hlsl"
#include "pbr/brdf/fd_burley.hlsl"
#include "pbr/brdf/blinn_phong.hlsl"
#include "pbr/brdf/d_blinn_phong.hlsl"
#include "pbr/brdf/d_ggx.hlsl"
#include "pbr/brdf/d_ggx_anisotropic.hlsl"
#include "pbr/brdf/d_beckmann.hlsl"
#include "pbr/brdf/g_cook_torrance.hlsl"
#include "pbr/brdf/g_smith_ggx.hlsl"
#include "pbr/brdf/g_schlick_ggx.hlsl"
#include "pbr/brdf/v_smith_ggx_correlated.hlsl"
#include "pbr/brdf/v_smith_ggx_correlated_anisotropic.hlsl"
#include "pbr/brdf/dv_ggx_smith_correlated.hlsl"
#include "pbr/brdf/dv_ggx_smith_correlated_fast.hlsl"
#include "pbr/brdf/dv_ggx_smith_bound.hlsl"
#include "pbr/brdf/v_implicit.hlsl"
#include "pbr/brdf/v_kelemen.hlsl"
#include "pbr/brdf/v_smith_ggx_bound.hlsl"
#include "pbr/brdf/f_schlick.hlsl"
#include "pbr/brdf/f_dielectric.hlsl"
#include "pbr/brdf/btdf_walter.hlsl"
#include "pbr/brdf/f_iridescence.hlsl"
#include "pbr/brdf/d_charlie.hlsl"
#include "pbr/brdf/v_charlie.hlsl"

// shading models
#include "pbr/shading/dispatch.hlsl"
#include "pbr/shading/standard.hlsl"
#include "pbr/shading/energy_conservation.hlsl"
#include "pbr/shading/clearcoat.hlsl"
#include "pbr/shading/anisotropy.hlsl"
#include "pbr/shading/sheen.hlsl"
#include "pbr/shading/transmission.hlsl"
#include "pbr/shading/valid_reflection_normal.hlsl"

// light integration
#include "pbr/lighting/punctual.hlsl"
#include "pbr/lighting/attenuation.hlsl"
#include "pbr/lighting/sh9.hlsl"
#include "pbr/lighting/disc_light.hlsl"

// image-based light
#include "pbr/ibl/importance_sampling.hlsl"
#include "pbr/ibl/equirect.hlsl"
#include "pbr/ibl/environment_brdf.hlsl"
#include "pbr/ibl/horizon_occlusion.hlsl"
#include "pbr/ibl/dominant_direction.hlsl"

// the surface API core (pbr/unity/ adds Unity's names on top: include it yourself)
#include "pbr/surface/lighting_standard.hlsl"
#include "pbr/surface/lighting_clearcoat.hlsl"
#include "pbr/surface/lighting_sheen.hlsl"
#include "pbr/surface/lighting_anisotropy.hlsl"
#include "pbr/surface/lighting_iridescence.hlsl"
#include "pbr/surface/lighting_transmission.hlsl"

// HDR
#include "pbr/tonemap/exposure.hlsl"
#include "pbr/tonemap/reinhard.hlsl"
#include "pbr/tonemap/hable.hlsl"
#include "pbr/tonemap/aces.hlsl"
#include "pbr/tonemap/khronos_neutral.hlsl"
#include "pbr/tonemap/tonemap.hlsl"

#endif // PBR_PBR_HLSL
