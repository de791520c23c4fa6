// pbr/pbr.glsl: the umbrella include: every public file of the pbrlab shading library.
//
// Provides: everything below.
// Include:  "pbr/pbr.glsl" (path relative to glsl/), or the individual files you need
// Config macros read: PBR_COLOR_TRANSFER (pbr/color/transfer.glsl); PBR_QUALITY,
//           PBR_SPECULAR_D, PBR_SPECULAR_V, PBR_SPECULAR_F, PBR_DIFFUSE
//           (pbr/shading/dispatch.glsl); PBR_SHEEN_V, PBR_SHEEN_LUT_LOOKUP (pbr/shading/sheen.glsl);
//           PBR_TONEMAP (pbr/tonemap/tonemap.glsl).
//           Define them before this include.
// Conventions: pbr/common/conventions.glsl. Naming rule and function table: glsl/README.md.
// tests/library/test_glsl_layout.py checks that every .glsl file under pbr/ is listed here.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_PBR_GLSL
#define PBR_PBR_GLSL

// conventions and maths
#include "pbr/common/constants.glsl"
#include "pbr/common/math.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/common/precision.glsl"
#include "pbr/common/conventions.glsl"

// colour
#include "pbr/color/srgb.glsl"
#include "pbr/color/gamma.glsl"
#include "pbr/color/luminance.glsl"
#include "pbr/color/transfer.glsl"

// material remapping
#include "pbr/material/remap.glsl"
#include "pbr/material/workflow.glsl"
#include "pbr/material/f0_tables.glsl"
#include "pbr/material/ior.glsl"

// BRDF terms
#include "pbr/brdf/fd_lambert.glsl"
#include "pbr/brdf/fd_burley.glsl"
#include "pbr/brdf/blinn_phong.glsl"
#include "pbr/brdf/d_blinn_phong.glsl"
#include "pbr/brdf/d_ggx.glsl"
#include "pbr/brdf/d_ggx_anisotropic.glsl"
#include "pbr/brdf/d_beckmann.glsl"
#include "pbr/brdf/g_cook_torrance.glsl"
#include "pbr/brdf/g_smith_ggx.glsl"
#include "pbr/brdf/g_schlick_ggx.glsl"
#include "pbr/brdf/v_smith_ggx_correlated.glsl"
#include "pbr/brdf/v_smith_ggx_correlated_anisotropic.glsl"
#include "pbr/brdf/dv_ggx_smith_correlated.glsl"
#include "pbr/brdf/dv_ggx_smith_correlated_fast.glsl"
#include "pbr/brdf/dv_ggx_smith_bound.glsl"
#include "pbr/brdf/v_implicit.glsl"
#include "pbr/brdf/v_kelemen.glsl"
#include "pbr/brdf/v_smith_ggx_bound.glsl"
#include "pbr/brdf/f_schlick.glsl"
#include "pbr/brdf/f_dielectric.glsl"
#include "pbr/brdf/btdf_walter.glsl"
#include "pbr/brdf/f_iridescence.glsl"
#include "pbr/brdf/d_charlie.glsl"
#include "pbr/brdf/v_charlie.glsl"

// shading models
#include "pbr/shading/dispatch.glsl"
#include "pbr/shading/standard.glsl"
#include "pbr/shading/energy_conservation.glsl"
#include "pbr/shading/clearcoat.glsl"
#include "pbr/shading/anisotropy.glsl"
#include "pbr/shading/sheen.glsl"
#include "pbr/shading/transmission.glsl"
#include "pbr/shading/valid_reflection_normal.glsl"

// light integration
#include "pbr/lighting/punctual.glsl"
#include "pbr/lighting/attenuation.glsl"
#include "pbr/lighting/sh9.glsl"
#include "pbr/lighting/disc_light.glsl"

// image-based light
#include "pbr/ibl/importance_sampling.glsl"
#include "pbr/ibl/equirect.glsl"
#include "pbr/ibl/environment_brdf.glsl"
#include "pbr/ibl/horizon_occlusion.glsl"
#include "pbr/ibl/dominant_direction.glsl"

// the surface API core (pbr/unity/ adds Unity's names on top: include it yourself)
#include "pbr/surface/lighting_standard.glsl"
#include "pbr/surface/lighting_clearcoat.glsl"
#include "pbr/surface/lighting_sheen.glsl"
#include "pbr/surface/lighting_anisotropy.glsl"
#include "pbr/surface/lighting_iridescence.glsl"
#include "pbr/surface/lighting_transmission.glsl"

// HDR
#include "pbr/tonemap/exposure.glsl"
#include "pbr/tonemap/reinhard.glsl"
#include "pbr/tonemap/hable.glsl"
#include "pbr/tonemap/aces.glsl"
#include "pbr/tonemap/khronos_neutral.glsl"
#include "pbr/tonemap/tonemap.glsl"

#endif // PBR_PBR_GLSL
