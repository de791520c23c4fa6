// pbr/shading/dispatch.glsl: variant selection for the specular D, V, F and diffuse terms.
//
// Provides: float pbr_specular_D(float NdotH, float alpha)
//           float pbr_specular_V(float NdotL, float NdotV, float NdotH, float VdotH, float alpha)
//           vec3  pbr_specular_F(vec3 f0, float VdotH)
//           float pbr_diffuse_Fd(float NdotV, float NdotL, float LdotH, float perceptualRoughness)
//           and the selector values below.
// Include:  "pbr/shading/dispatch.glsl" (path relative to glsl/)
// Config macros read: (each has a default, set with #ifndef below)
//   PBR_QUALITY     PBR_QUALITY_HIGH (default) | PBR_QUALITY_LOW; picks the defaults below
//   PBR_SPECULAR_D  PBR_SPECULAR_D_GGX (default) | _BECKMANN | _BLINN_PHONG
//   PBR_SPECULAR_V  PBR_SPECULAR_V_SMITH_GGX_CORRELATED (HIGH default)
//                   | _SMITH_GGX_CORRELATED_FAST (LOW default) | _SMITH_GGX | _SCHLICK_GGX
//                   | _COOK_TORRANCE | _KELEMEN | _IMPLICIT
//   PBR_SPECULAR_F  PBR_SPECULAR_F_SCHLICK (default) | _SCHLICK_SG | _NONE (F = 1, for
//                   white-furnace checks and debugging)
//   PBR_DIFFUSE     PBR_DIFFUSE_LAMBERT (default) | PBR_DIFFUSE_BURLEY
//
// The one variant mechanism of the library (pbr/common/conventions.glsl §8): every
// alternative is its own function in pbr/brdf/; a numbered #define selects it; each
// dispatcher below holds the only #if chain of its term. Every dispatcher takes the same
// parameters whatever the variant, so callers never change. Parameter mapping:
//   D Blinn-Phong: specPower = pbr_specPower_from_alpha(alpha) (Walter 2007 §5.2).
//   D Beckmann:    the GGX alpha is used as the Beckmann RMS slope.
//   V Schlick-GGX: k = alpha / 2 (Karis 2013, eq. 4).
//   V Smith GGX:   the separable form; V Cook-Torrance, Kelemen, Implicit: see their files.
// The Python twin is harness/pbrlab/reference/shading.py (same names, lower-case keywords).
#ifndef PBR_SHADING_DISPATCH_GLSL
#define PBR_SHADING_DISPATCH_GLSL

#include "pbr/material/remap.glsl"
#include "pbr/brdf/fd_lambert.glsl"
#include "pbr/brdf/fd_burley.glsl"
#include "pbr/brdf/d_ggx.glsl"
#include "pbr/brdf/d_beckmann.glsl"
#include "pbr/brdf/d_blinn_phong.glsl"
#include "pbr/brdf/v_smith_ggx_correlated.glsl"
#include "pbr/brdf/g_smith_ggx.glsl"
#include "pbr/brdf/g_schlick_ggx.glsl"
#include "pbr/brdf/g_cook_torrance.glsl"
#include "pbr/brdf/v_kelemen.glsl"
#include "pbr/brdf/v_implicit.glsl"
#include "pbr/brdf/f_schlick.glsl"

#define PBR_SPECULAR_D_GGX         0
#define PBR_SPECULAR_D_BECKMANN    1
#define PBR_SPECULAR_D_BLINN_PHONG 2

#define PBR_SPECULAR_V_SMITH_GGX_CORRELATED      0
#define PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST 1
#define PBR_SPECULAR_V_SMITH_GGX                 2
#define PBR_SPECULAR_V_SCHLICK_GGX               3
#define PBR_SPECULAR_V_COOK_TORRANCE             4
#define PBR_SPECULAR_V_KELEMEN                   5
#define PBR_SPECULAR_V_IMPLICIT                  6

#define PBR_SPECULAR_F_SCHLICK    0
#define PBR_SPECULAR_F_SCHLICK_SG 1
#define PBR_SPECULAR_F_NONE       2

#define PBR_DIFFUSE_LAMBERT 0
#define PBR_DIFFUSE_BURLEY  1

#define PBR_QUALITY_LOW  0
#define PBR_QUALITY_HIGH 1

#ifndef PBR_QUALITY
#define PBR_QUALITY PBR_QUALITY_HIGH
#endif

// Quality tiers -> selector defaults: the only place tiers are interpreted. An explicit
// selector always wins over the tier.
#if PBR_QUALITY == PBR_QUALITY_LOW
#  ifndef PBR_SPECULAR_V
#  define PBR_SPECULAR_V PBR_SPECULAR_V_SMITH_GGX_CORRELATED_FAST
#  endif
#elif PBR_QUALITY != PBR_QUALITY_HIGH
#  error "PBR_QUALITY: unknown value"
#endif

#ifndef PBR_SPECULAR_D
#define PBR_SPECULAR_D PBR_SPECULAR_D_GGX
#endif
#ifndef PBR_SPECULAR_V
#define PBR_SPECULAR_V PBR_SPECULAR_V_SMITH_GGX_CORRELATED
#endif
#ifndef PBR_SPECULAR_F
#define PBR_SPECULAR_F PBR_SPECULAR_F_SCHLICK
#endif
#ifndef PBR_DIFFUSE
#define PBR_DIFFUSE PBR_DIFFUSE_LAMBERT
#endif

float pbr_specular_D(float NdotH, float alpha) {
#if PBR_SPECULAR_D == PBR_SPECULAR_D_GGX
    return pbr_D_GGX(NdotH, alpha);
#elif PBR_SPECULAR_D == PBR_SPECULAR_D_BECKMANN
    return pbr_D_Beckmann(NdotH, alpha);
#elif PBR_SPECULAR_D == PBR_SPECULAR_D_BLINN_PHONG
    return pbr_D_BlinnPhong(NdotH, pbr_specPower_from_alpha(alpha));
#else
#error "PBR_SPECULAR_D: unknown value"
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
#else
#error "PBR_SPECULAR_V: unknown value"
#endif
}

vec3 pbr_specular_F(vec3 f0, float VdotH) {
#if PBR_SPECULAR_F == PBR_SPECULAR_F_SCHLICK
    return pbr_F_Schlick(f0, VdotH);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_SCHLICK_SG
    return pbr_F_SchlickSG(f0, VdotH);
#elif PBR_SPECULAR_F == PBR_SPECULAR_F_NONE
    return vec3(1.0);
#else
#error "PBR_SPECULAR_F: unknown value"
#endif
}

float pbr_diffuse_Fd(float NdotV, float NdotL, float LdotH, float perceptualRoughness) {
#if PBR_DIFFUSE == PBR_DIFFUSE_LAMBERT
    return pbr_Fd_Lambert();
#elif PBR_DIFFUSE == PBR_DIFFUSE_BURLEY
    return pbr_Fd_Burley(NdotV, NdotL, LdotH, perceptualRoughness);
#else
#error "PBR_DIFFUSE: unknown value"
#endif
}

#endif // PBR_SHADING_DISPATCH_GLSL
