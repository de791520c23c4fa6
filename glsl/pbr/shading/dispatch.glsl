// pbr/shading/dispatch.glsl: variant selection for the specular D, V, F and diffuse terms.
//
// Provides: float pbr_specular_D(float NdotH, float oneMinusNdotH2, float alpha)
//           float pbr_specular_V(float NdotL, float NdotV, float NdotH, float VdotH, float alpha)
//           vec3  pbr_specular_F(vec3 f0, float VdotH)
//           vec3  pbr_specular_F_f90(vec3 f0, float f90, float VdotH)  (an explicit F90)
//           vec3  pbr_specular_F_deviation_bound(vec3 f0)  (max |F - Schlick's F| over VdotH)
//           vec3  pbr_specular_F_deviation_bound_f90(vec3 f0, float f90)
//           float pbr_diffuse_Fd(float NdotV, float NdotL, float LdotH, float perceptualRoughness)
//           float pbr_specular_lobe_limit(float DV)  (the tier's cap on D · V)
//           PBR_MIN_PERCEPTUAL_ROUGHNESS, PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP,
//           PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS and the selector values below.
// Include:  "pbr/shading/dispatch.glsl" (path relative to glsl/)
// Config macros read: (each has a default, set below where undefined)
//   PBR_QUALITY     PBR_QUALITY_HIGH (default, the exact model) | PBR_QUALITY_MEDIUM
//                   (Hammon's V) | PBR_QUALITY_LOW (a cheaper lobe: V bounded without a square
//                   root, Schlick's Fresnel kept); see the tier block below; picks the defaults
//   PBR_SPECULAR_D  PBR_SPECULAR_D_GGX (default) | _BECKMANN | _BLINN_PHONG
//   PBR_SPECULAR_V  PBR_SPECULAR_V_SMITH_GGX_CORRELATED (HIGH default)
//                   | _SMITH_GGX_CORRELATED_FAST (MEDIUM default) | _SMITH_GGX | _SCHLICK_GGX
//                   | _COOK_TORRANCE | _KELEMEN | _IMPLICIT | _SMITH_GGX_BOUND (LOW default)
//   PBR_SPECULAR_F  PBR_SPECULAR_F_SCHLICK (every tier's default) | _SCHLICK_SG | _NONE (F = 1,
//                   for white-furnace checks and debugging) | _F0 (F = f0, no Fresnel rise:
//                   an explicit choice only, no tier selects it: at a grazing mirror it
//                   reflects 1 % of Schlick's lobe); both Schlick forms take F90 =
//                   pbr_f90_from_f0(f0), or the caller's F90 through the _f90 forms
//                   (KHR_materials_specular)
//   PBR_DIFFUSE     PBR_DIFFUSE_LAMBERT (default) | PBR_DIFFUSE_BURLEY
//   PBR_BRDF_MODEL  PBR_BRDF_MODEL_PBRLAB (default: the library's physical shading) |
//                   PBR_BRDF_MODEL_UNITY (Unity's built-in BRDFs formula for formula,
//                   pbr/unity/brdf_unity.glsl; read by pbr/unity/surface_standard.glsl)
//   PBR_UNITY_BRDF  PBR_UNITY_BRDF_1 (HIGH default) | _2 (MEDIUM) | _3 (LOW): which of Unity's
//                   BRDF1/2/3_Unity_PBS the unity model uses (the tier block below)
//   PBR_ENERGY_COMPENSATION     1 (HIGH, MEDIUM default): the environment's specular albedo
//                   compensates multiple scattering (pbr/surface/lighting_standard.glsl) | 0 (LOW
//                   default): single scattering, which only loses energy
//   PBR_IBL_DOMINANT_DIRECTION  1 (HIGH, MEDIUM default): read the prefiltered environment along
//                   the lobe's dominant direction (pbr/ibl/dominant_direction.glsl) | 0 (LOW
//                   default): along the mirror direction
//   PBR_IBL_HORIZON_OCCLUSION   1 (HIGH, MEDIUM default): a caller whose normal can tilt from
//                   the geometric one takes out the lobes' share below its horizon
//                   (pbr/ibl/horizon_occlusion.glsl) | 0 (LOW default): it does not
//   PBR_SPECULAR_OCCLUSION      PBR_SPECULAR_OCCLUSION_LAGARDE (HIGH, MEDIUM default: Lagarde &
//                   de Rousiers' fit of the lobe's occlusion from ambient occlusion) |
//                   _AMBIENT (LOW default: the ambient occlusion itself; pbr/ibl/environment_brdf.glsl)
//   (The last four are the tier's choices for the environment read: issue 35, LOW's whole
//   pixel; docs/shading.md, "What each tier changes in the whole pixel".)
//   PBR_NORMAL_MAP_FRAME        PBR_NORMAL_MAP_FRAME_ORTHONORMAL (HIGH, MEDIUM default: a
//                   tangent-space normal goes to the world through the interpolated tangent made
//                   orthogonal to n and unit, Gram-Schmidt) | _MIKKTSPACE (LOW default: through
//                   the interpolated tangent as it arrives, bitangent sign · n × t, the result
//                   normalised once: the pixel-shader form mikktspace.h prescribes for maps it
//                   baked). Read by the caller that maps normals (pbrlab's scene template,
//                   pbrlab_tangent_to_world_normal); the library maps none itself.
//   PBR_DFG_LUT_LAYOUT          PBR_DFG_LUT_LAYOUT_WARPED (HIGH, MEDIUM default) | _SQRT (LOW
//                   default): the axes of the DFG table pbr_dfg_lut_uv addresses
//                   (pbr/ibl/environment_brdf.glsl; the caller binds the table of that layout).
//
// The one variant mechanism of the library (pbr/common/conventions.glsl §8): every
// alternative is its own function in pbr/brdf/; a numbered macro selects it; each
// dispatcher below holds the only conditional chain of its term. Every dispatcher takes the same
// parameters whatever the variant, so callers never change. Parameter mapping:
//   D GGX, Beckmann: take 1 - NdotH² separately (pbr_one_minus_dot2: |n × h|², see d_ggx.glsl).
//   D Blinn-Phong: specPower = pbr_specPower_from_alpha(alpha) (Walter 2007 §5.2).
//   D Beckmann:    the GGX alpha is used as the Beckmann RMS slope.
//   V Schlick-GGX: k = alpha / 2 (Karis 2013, eq. 4).
//   V Smith GGX:   the separable form; V Cook-Torrance, Kelemen, Implicit: see their files.
// The Python twin is harness/pbrlab/maths/reference/shading.py (same names, lower-case keywords).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_DISPATCH_GLSL
#define PBR_SHADING_DISPATCH_GLSL

#include "pbr/common/guards.glsl"
#include "pbr/common/precision.glsl"
#include "pbr/material/remap.glsl"
#include "pbr/brdf/fd_lambert.glsl"
#include "pbr/brdf/fd_burley.glsl"
#include "pbr/brdf/d_ggx.glsl"
#include "pbr/brdf/d_beckmann.glsl"
#include "pbr/brdf/d_blinn_phong.glsl"
#include "pbr/brdf/v_smith_ggx_correlated.glsl"
#include "pbr/brdf/dv_ggx_smith_correlated.glsl"
#include "pbr/brdf/dv_ggx_smith_correlated_fast.glsl"
#include "pbr/brdf/dv_ggx_smith_bound.glsl"
#include "pbr/brdf/v_smith_ggx_bound.glsl"
#include "pbr/brdf/g_smith_ggx.glsl"
#include "pbr/brdf/g_schlick_ggx.glsl"
#include "pbr/brdf/g_cook_torrance.glsl"
#include "pbr/brdf/v_kelemen.glsl"
#include "pbr/brdf/v_implicit.glsl"
#include "pbr/brdf/f_schlick.glsl"

// Every selector family counts from 1: an undefined name (a typo) reads as 0 in a conditional,
// which no value matches, so the dispatcher's compile error names the selector instead of
// picking a term.
#define PBR_SPECULAR_D_GGX 1
#define PBR_SPECULAR_D_BECKMANN 2
#define PBR_SPECULAR_D_BLINN_PHONG 3

#define PBR_SPECULAR_V_SMITH_GGX_CORRELATED 1
#define PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST 2
#define PBR_SPECULAR_V_SMITH_GGX 3
#define PBR_SPECULAR_V_SCHLICK_GGX 4
#define PBR_SPECULAR_V_COOK_TORRANCE 5
#define PBR_SPECULAR_V_KELEMEN 6
#define PBR_SPECULAR_V_IMPLICIT 7
#define PBR_SPECULAR_V_SMITH_GGX_BOUND 8

#define PBR_SPECULAR_F_SCHLICK 1
#define PBR_SPECULAR_F_SCHLICK_SG 2
#define PBR_SPECULAR_F_NONE 3
#define PBR_SPECULAR_F_F0 4

#define PBR_DIFFUSE_LAMBERT 1
#define PBR_DIFFUSE_BURLEY 2

#define PBR_SPECULAR_OCCLUSION_LAGARDE 1
#define PBR_SPECULAR_OCCLUSION_AMBIENT 2

#define PBR_NORMAL_MAP_FRAME_ORTHONORMAL 1
#define PBR_NORMAL_MAP_FRAME_MIKKTSPACE 2

#define PBR_DFG_LUT_LAYOUT_WARPED 1
#define PBR_DFG_LUT_LAYOUT_SQRT 2

#define PBR_QUALITY_LOW 1
#define PBR_QUALITY_HIGH 2
#define PBR_QUALITY_MEDIUM 3

#ifndef PBR_QUALITY
// PBR_QUALITY_HIGH as a number (glsl/README.md, one-level preprocessors)
#define PBR_QUALITY 2
#endif

// The BRDF model: non-zero values, so that an undefined name (which the preprocessor reads
// as 0) is an error rather than a silent choice.
#define PBR_BRDF_MODEL_PBRLAB 1
#define PBR_BRDF_MODEL_UNITY 2
#ifndef PBR_BRDF_MODEL
// PBR_BRDF_MODEL_PBRLAB as a number (glsl/README.md, one-level preprocessors)
#define PBR_BRDF_MODEL 1
#endif
#if PBR_BRDF_MODEL != PBR_BRDF_MODEL_PBRLAB && PBR_BRDF_MODEL != PBR_BRDF_MODEL_UNITY
#error PBR_BRDF_MODEL: unknown value (PBR_BRDF_MODEL_PBRLAB or PBR_BRDF_MODEL_UNITY)
#endif

// Unity's three BRDFs (UnityStandardBRDF.cginc), used by the unity model only.
#define PBR_UNITY_BRDF_1 1
#define PBR_UNITY_BRDF_2 2
#define PBR_UNITY_BRDF_3 3

// Smallest perceptual roughness of the HIGH tier: Filament's MIN_PERCEPTUAL_ROUGHNESS
// (Guy & Agopian, "Physically Based Rendering in Filament", §4.8.3.3, common_material.fs):
// alpha = 0.045² = 2.0e-3, alpha² = 4.1e-6 keeps D_GGX's peak 1/(π alpha²) ≈ 7.8e4 and
// alpha² · NdotH² far inside float32 range. Shared with reference/shading.py.
#define PBR_MIN_PERCEPTUAL_ROUGHNESS 0.045
// Smallest perceptual roughness of the half-safe LOW tier: Filament's mobile value
// (common_material.fs, TARGET_MOBILE): alpha = 0.089² = 7.92e-3, alpha² = 6.27e-5 is just
// above half's smallest normal 6.10e-5 (below it alpha² loses bits as a half denormal), and
// D's peak 1/(π alpha²) = 5073 fits half (max 65504) with a 12x margin. Measured cost and
// the half-precision study: glsl/README.md. Shared with reference/shading.py.
#define PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP 0.089

// Quality tiers -> selector defaults and tier guards: the only place tiers are
// interpreted. An explicit selector always wins over the tier. Each tier is GGX D, Schlick F
// (F90 from F0) and Lambert, with a fused D · V (pbr_specular_DV); measured error and cost
// per evaluation on RDNA3, RDNA2, GCN5 and llvmpipe: docs/bench (brdf_tier).
//   HIGH   float32, V -> SMITH_GGX_CORRELATED (Heitz 2014): the exact model.
//   MEDIUM float32, V -> SMITH_GGX_CORRELATED_FAST (Hammon 2017, no square roots, at most
//          29 % from the exact V); the HIGH tier's guards. The tier that buys ALU time.
//   LOW    a different lobe (issue 25: a tier that buys instructions): GGX D (HIGH's
//          cancellation-free |n × h|² form) times V -> SMITH_GGX_BOUND = 0.5 / n·(l + v)
//          (Heitz's V with its square roots bounded by 1: no more energy than the exact lobe),
//          Schlick's F as the other tiers (issue 35: "everything has Fresnel"; the former
//          F -> F0 left a grazing mirror at 1 % of HIGH's lobe, 51 against 5069 1/sr at
//          NdotL = NdotV = 1e-3, roughness 0.5, F0 0.04), minimum perceptual roughness 0.089
//          (Filament's mobile floor: D's peak fits half, below). Per light 49.5 / 47.5 / 48.5
//          RDNA3 / RDNA2 / GCN5 instructions, 0.80x HIGH on RDNA3 (issue 25's lobe, F = F0 and
//          the cancelling 1 - NdotH² (1 - alpha²): 39.5 / 37.5 / 39.75, 0.64x; Schlick's rise
//          costs 6 on RDNA3, the spherical-Gaussian form 6.1; the |n × h|² form 4 more, bought
//          by rotated frames, where the cancelling form was off by up to 9e4: dv_ggx_smith_bound.glsl).
//          Where floats may be 16-bit (PBR_HALF_ARITHMETIC) D · V is capped at PBR_HALF_MAX
//          (pbr_specular_lobe_limit), and Hammon's V, if selected, runs in half's range
//          (pbr_DV_GGX_SmithCorrelatedFast_half: the half study, tests/checking/hardcases/test_half.py).
//          The environment read (issue 35: a tier of the lobe alone saved 3 % of the whole
//          lit pixel): LOW reads it along the mirror direction (no dominant direction), without
//          horizon occlusion, without multiple-scattering compensation (single scattering:
//          it loses the energy of further bounces, gains none) and with the ambient occlusion
//          itself as the specular occlusion (no pow), and it maps normal-map normals through
//          MikkTSpace's pixel-shader frame (PBR_NORMAL_MAP_FRAME: no Gram-Schmidt, one
//          normalisation) and reads its DFG table at x = sqrt(NdotV), y = perceptual roughness
//          (PBR_DFG_LUT_LAYOUT: no logarithms); RDNA3 instructions each saves
//          and the image error: docs/shading.md, "What each tier changes in the whole pixel".
//          HIGH and MEDIUM keep all four (PBR_ENERGY_COMPENSATION, PBR_IBL_DOMINANT_DIRECTION,
//          PBR_IBL_HORIZON_OCCLUSION 1, PBR_SPECULAR_OCCLUSION_LAGARDE); an explicit value wins over the tier, as for the terms.
//   In the unity model (PBR_BRDF_MODEL_UNITY) the tiers pick Unity's BRDFs the way Unity's
//   graphics tiers do (UNITY_PBS_USE_BRDF1/2/3): HIGH -> BRDF1, MEDIUM -> BRDF2, LOW -> BRDF3;
//   Unity's BRDFs carry their own guards, so the pbrlab guards above do not apply to them.
#if PBR_QUALITY == PBR_QUALITY_LOW
#  ifndef PBR_UNITY_BRDF
// PBR_UNITY_BRDF_3 as a number (glsl/README.md, one-level preprocessors)
#define PBR_UNITY_BRDF 3
#  endif
#  ifndef PBR_ENERGY_COMPENSATION
#define PBR_ENERGY_COMPENSATION 0
#  endif
#  ifndef PBR_IBL_DOMINANT_DIRECTION
#define PBR_IBL_DOMINANT_DIRECTION 0
#  endif
#  ifndef PBR_IBL_HORIZON_OCCLUSION
#define PBR_IBL_HORIZON_OCCLUSION 0
#  endif
#  ifndef PBR_SPECULAR_OCCLUSION
// PBR_SPECULAR_OCCLUSION_AMBIENT as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_OCCLUSION 2
#  endif
#  ifndef PBR_NORMAL_MAP_FRAME
// PBR_NORMAL_MAP_FRAME_MIKKTSPACE as a number (glsl/README.md, one-level preprocessors)
#define PBR_NORMAL_MAP_FRAME 2
#  endif
#  ifndef PBR_DFG_LUT_LAYOUT
// PBR_DFG_LUT_LAYOUT_SQRT as a number (glsl/README.md, one-level preprocessors)
#define PBR_DFG_LUT_LAYOUT 2
#  endif
#  ifndef PBR_SPECULAR_V
// PBR_SPECULAR_V_SMITH_GGX_BOUND as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_V 8
#  endif
#  define PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP
#elif PBR_QUALITY == PBR_QUALITY_MEDIUM
#  ifndef PBR_UNITY_BRDF
// PBR_UNITY_BRDF_2 as a number (glsl/README.md, one-level preprocessors)
#define PBR_UNITY_BRDF 2
#  endif
#  ifndef PBR_SPECULAR_V
// PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_V 2
#  endif
#  define PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS PBR_MIN_PERCEPTUAL_ROUGHNESS
#elif PBR_QUALITY == PBR_QUALITY_HIGH
#  ifndef PBR_UNITY_BRDF
// PBR_UNITY_BRDF_1 as a number (glsl/README.md, one-level preprocessors)
#define PBR_UNITY_BRDF 1
#  endif
#  define PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS PBR_MIN_PERCEPTUAL_ROUGHNESS
#else
#  error PBR_QUALITY: unknown value
#endif

// The environment read's defaults of HIGH and MEDIUM (LOW's are set in its block above).
#ifndef PBR_ENERGY_COMPENSATION
#define PBR_ENERGY_COMPENSATION 1
#endif
#ifndef PBR_IBL_DOMINANT_DIRECTION
#define PBR_IBL_DOMINANT_DIRECTION 1
#endif
#ifndef PBR_IBL_HORIZON_OCCLUSION
#define PBR_IBL_HORIZON_OCCLUSION 1
#endif
#ifndef PBR_SPECULAR_OCCLUSION
// PBR_SPECULAR_OCCLUSION_LAGARDE as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_OCCLUSION 1
#endif
#ifndef PBR_NORMAL_MAP_FRAME
// PBR_NORMAL_MAP_FRAME_ORTHONORMAL as a number (glsl/README.md, one-level preprocessors)
#define PBR_NORMAL_MAP_FRAME 1
#endif
// Read by the caller that maps normals, not here: checked here, so a misspelt value fails in
// every program that includes the library, mapping or not.
#if PBR_NORMAL_MAP_FRAME != PBR_NORMAL_MAP_FRAME_ORTHONORMAL && PBR_NORMAL_MAP_FRAME != PBR_NORMAL_MAP_FRAME_MIKKTSPACE
#error PBR_NORMAL_MAP_FRAME: unknown value (PBR_NORMAL_MAP_FRAME_ORTHONORMAL or PBR_NORMAL_MAP_FRAME_MIKKTSPACE)
#endif

#ifndef PBR_SPECULAR_D
// PBR_SPECULAR_D_GGX as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_D 1
#endif
#ifndef PBR_SPECULAR_V
// PBR_SPECULAR_V_SMITH_GGX_CORRELATED as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_V 1
#endif
#ifndef PBR_SPECULAR_F
// PBR_SPECULAR_F_SCHLICK as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_F 1
#endif
#ifndef PBR_DIFFUSE
// PBR_DIFFUSE_LAMBERT as a number (glsl/README.md, one-level preprocessors)
#define PBR_DIFFUSE 1
#endif

float pbr_specular_D(float NdotH, float oneMinusNdotH2, float alpha) {
#if PBR_SPECULAR_D == PBR_SPECULAR_D_GGX
    return pbr_D_GGX_fromOneMinusNdotH2(NdotH, oneMinusNdotH2, alpha);
#elif PBR_SPECULAR_D == PBR_SPECULAR_D_BECKMANN
    return pbr_D_Beckmann_fromOneMinusNdotH2(NdotH, oneMinusNdotH2, alpha);
#elif PBR_SPECULAR_D == PBR_SPECULAR_D_BLINN_PHONG
    return pbr_D_BlinnPhong(NdotH, pbr_specPower_from_alpha(alpha));
#else
#error PBR_SPECULAR_D: unknown value
#endif
}

float pbr_specular_V(float NdotL, float NdotV, float NdotH, float VdotH, float alpha) {
#if PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX_CORRELATED
    return pbr_V_SmithGGXCorrelated(NdotL, NdotV, alpha);
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST
    return pbr_V_SmithGGXCorrelatedFast(NdotL, NdotV, alpha);
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX
    return pbr_V_SmithGGX(NdotL, NdotV, alpha);
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_SCHLICK_GGX
    return pbr_V_SchlickGGX(NdotL, NdotV, pbr_k_SchlickGGX_from_alpha(alpha));
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_COOK_TORRANCE
    return pbr_V_CookTorrance(NdotL, NdotV, NdotH, VdotH);
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_KELEMEN
    return pbr_V_Kelemen(VdotH);
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_IMPLICIT
    return pbr_V_Implicit();
#elif PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX_BOUND
    return pbr_V_SmithGGXBound(NdotL, NdotV);
#else
#error PBR_SPECULAR_V: unknown value
#endif
}

// D · V of the selected terms, from any positive multiple h of the half vector (pbr_brdf_standard
// passes l + v): nDotH = n·h, nCrossH2 = |n × h|², h2 = |h|² + 2^-126 in [2^-126, 4]
// (pbr_length2_nonzero). n·h is negative for an h below the surface, which a view below the
// horizon gives; pbr_brdf_standard then sets the lobe to 0 (χ+), and the value here only has
// to be finite (so it is below the horizon, NdotL = 0, where nCrossH2 / h2 may exceed 1):
// GGX is even in n·h (its denominator (1 - c²) + c² alpha² >= alpha² for unit h) and is
// evaluated at |n·ĥ|; Beckmann and Blinn-Phong take n·ĥ
// clamped to [0, 1] (0 below the surface). GGX with each tier's V is fused into one
// quotient that needs no normalised h and none of the terms' own clamps: the
// height-correlated Smith V (HIGH, pbr_DV_GGX_SmithCorrelated) and Hammon's fast form of it
// (MEDIUM, and LOW where selected, pbr_DV_GGX_SmithCorrelatedFast; LOW in half's range where
// floats may be 16-bit, PBR_HALF_ARITHMETIC) and LOW's bound of it (pbr_DV_GGX_SmithBound), all
// three from |n × h|² (no cancellation at the peak in any frame); their other preconditions are pbr_brdf_standard's: NdotL in
// [0, 1], NdotV in [PBR_MIN_NDOTV, 1], alpha from the tier's clamped roughness. Every other pair is the
// product of the two dispatchers above, from the normalised h (each V term floors its
// cosines at PBR_MIN_NDOTV itself).
float pbr_specular_DV(float nDotH, float nCrossH2, float h2, float NdotL, float NdotV,
                      float VdotH, float alpha) {
#if PBR_SPECULAR_D == PBR_SPECULAR_D_GGX && PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX_CORRELATED
    return pbr_DV_GGX_SmithCorrelated(nDotH, nCrossH2, h2, NdotL, NdotV, alpha);
#elif PBR_SPECULAR_D == PBR_SPECULAR_D_GGX && PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST
#  if PBR_QUALITY == PBR_QUALITY_LOW && PBR_HALF_ARITHMETIC != 0
    return pbr_DV_GGX_SmithCorrelatedFast_half(nDotH, nCrossH2, h2, NdotL, NdotV, alpha);
#  else
    return pbr_DV_GGX_SmithCorrelatedFast(nDotH, nCrossH2, h2, NdotL, NdotV, alpha);
#  endif
#elif PBR_SPECULAR_D == PBR_SPECULAR_D_GGX && PBR_SPECULAR_V == PBR_SPECULAR_V_SMITH_GGX_BOUND
    return pbr_DV_GGX_SmithBound(nDotH, nCrossH2, h2, NdotL, NdotV, alpha);
#else
    float invLength = inversesqrt(h2);
    float cosine = nDotH * invLength;
    float oneMinusNdotH2 = nCrossH2 * (invLength * invLength);
    float NdotH = clamp(cosine, 0.0, 1.0);
#  if PBR_SPECULAR_D == PBR_SPECULAR_D_GGX
    float D = pbr_specular_D(abs(cosine), oneMinusNdotH2, alpha);
#  else
    float D = pbr_specular_D(NdotH, oneMinusNdotH2, alpha);
#  endif
    return D * pbr_specular_V(NdotL, NdotV, NdotH, VdotH, alpha);
#endif
}

// F with an explicit grazing reflectance f90 (KHR_materials_specular: F90 = specularFactor ·
// specularTexture.a, whatever F0; Khronos, KHR_materials_specular README, "Implementation":
// dielectric_f90 = specular). Precondition: f90 >= every channel of f0 (the extension's
// min(..., 1) · specular <= specular), which pbr_specular_F_deviation_bound_f90 relies on.
vec3 pbr_specular_F_f90(vec3 f0, float f90, float VdotH) {
#if PBR_SPECULAR_F == PBR_SPECULAR_F_SCHLICK
    return pbr_F_Schlick(f0, f90, VdotH);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_SCHLICK_SG
    return pbr_F_SchlickSG(f0, f90, VdotH);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_NONE
    return vec3(1.0);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_F0
    return f0;
#else
#error PBR_SPECULAR_F: unknown value
#endif
}

// F90 follows F0 (pbr_f90_from_f0, Schüler 2009 / Filament): F0 = 0 reflects nothing.
vec3 pbr_specular_F(vec3 f0, float VdotH) {
    return pbr_specular_F_f90(f0, pbr_f90_from_f0(f0), VdotH);
}

// The largest |pbr_specular_F_f90 - pbr_F_Schlick(f0, f90, VdotH)| over VdotH in [0, 1]: how
// far the selected F can reflect beyond the Schlick weights of the split-sum table (used by the
// diffuse-specular coupling, pbr_specular_albedo_bound_f90). SG: PBR_F_SCHLICK_SG_MAX_ABS_ERROR
// times (f90 - f0) (f_schlick.glsl); NONE (F = 1): 1 - f0, F's distance from Schlick at VdotH = 1;
// F0: 0 (F = f0 <= Schlick's weights, since f90 >= every channel of f0: pbr_f90_from_f0(f0) is,
// and an explicit f90 must be, pbr_specular_F_f90).
vec3 pbr_specular_F_deviation_bound_f90(vec3 f0, float f90) {
#if PBR_SPECULAR_F == PBR_SPECULAR_F_SCHLICK
    return vec3(0.0);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_SCHLICK_SG
    return PBR_F_SCHLICK_SG_MAX_ABS_ERROR * (vec3(f90) - f0);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_NONE
    return vec3(1.0) - f0;
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_F0
    return vec3(0.0);
#else
#error PBR_SPECULAR_F: unknown value
#endif
}

vec3 pbr_specular_F_deviation_bound(vec3 f0) {
    return pbr_specular_F_deviation_bound_f90(f0, pbr_f90_from_f0(f0));
}

float pbr_specular_lobe_limit(float DV) {
#if PBR_QUALITY == PBR_QUALITY_LOW && PBR_HALF_ARITHMETIC != 0
    return min(DV, PBR_HALF_MAX);  // also maps a half +Inf to 65504 (min of Inf is defined)
#else
    return DV;
#endif
}

float pbr_diffuse_Fd(float NdotV, float NdotL, float LdotH, float perceptualRoughness) {
#if PBR_DIFFUSE == PBR_DIFFUSE_LAMBERT
    return pbr_Fd_Lambert();
#elif PBR_DIFFUSE == PBR_DIFFUSE_BURLEY
    return pbr_Fd_Burley(NdotV, NdotL, LdotH, perceptualRoughness);
#else
#error PBR_DIFFUSE: unknown value
#endif
}

#endif // PBR_SHADING_DISPATCH_GLSL
