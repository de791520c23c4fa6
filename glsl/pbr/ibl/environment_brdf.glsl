// pbr/ibl/environment_brdf.glsl: the split-sum environment BRDF and what surrounds it:
// specular occlusion, multiple-scattering energy compensation, prefiltered-mip choice.
//
// Provides: vec2 pbr_env_brdf_approx(float NdotV, float perceptualRoughness)
//           vec2 pbr_env_brdf(float NdotV, float perceptualRoughness)
//           vec2 pbr_dfg_lut_uv(float NdotV, float perceptualRoughness)
//           PBR_DFG_LUT_WIDTH, PBR_DFG_LUT_HEIGHT and the table's axis constants
//           vec3 pbr_specular_albedo(vec3 f0, vec2 dfg)
//           vec3 pbr_specular_albedo_f90(vec3 f0, float f90, vec2 dfg)
//           vec3 pbr_specular_albedo_bound(vec3 f0, vec2 dfg)
//           vec3 pbr_specular_albedo_bound_f90(vec3 f0, float f90, vec2 dfg)
//           vec3 pbr_energy_compensation(vec3 f0, vec2 dfg)
//           float pbr_specular_occlusion(float NdotV, float occlusion, float alpha)
//           float pbr_ibl_lod_from_perceptual_roughness(float perceptualRoughness, float lodCount)
// Include:  "pbr/ibl/environment_brdf.glsl" (path relative to glsl/)
// Config macros read: PBR_SPECULAR_OCCLUSION (the tier's default: pbr/shading/dispatch.glsl),
//           how pbr_specular_occlusion derives the lobe's occlusion from ambient occlusion;
//           PBR_ENV_BRDF (default PBR_ENV_BRDF_TABLE), which environment BRDF
//           pbr_env_brdf returns:
//             PBR_ENV_BRDF_TABLE     the DFG table through PBR_DFG_LUT_LOOKUP (the accurate
//                                    option); the analytic fit where the hook is undefined
//             PBR_ENV_BRDF_ANALYTIC  the analytic fit (pbr_env_brdf_approx) even where a
//                                    table is given: no texture, no fetch (the table-free
//                                    option; its error and cost: docs/shading.md)
//           PBR_DFG_LUT_LAYOUT (the tier's default: pbr/shading/dispatch.glsl), the axes of
//           the table pbr_dfg_lut_uv addresses:
//             PBR_DFG_LUT_LAYOUT_WARPED  (HIGH, MEDIUM) logarithmic in NdotV and alpha, below
//             PBR_DFG_LUT_LAYOUT_SQRT    (LOW) x = sqrt(NdotV), y = perceptual roughness: one
//                                        square root, no logarithm (its own table,
//                                        harness/pbrlab/gpu/ibl.py)
//           PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness), a hook the caller
//           may define to sample its DFG table (it owns the sampler), returning vec2(A, B):
//           typically texture(table, pbr_dfg_lut_uv(NdotV, perceptualRoughness)).rg with
//           bilinear filtering and clamp to edge (every tier reads the table when it is
//           given: the diffuse-specular coupling of pbr/surface/lighting_standard.glsl needs
//           the albedo of the library's own V).
//
// Split sum (Karis 2013, "Real Shading in Unreal Engine 4", eq. 8): the specular
// reflection of an environment is prefiltered radiance times the directional albedo of
// the BRDF, written f0 * A + f90 * B with A, B tabulated over (NdotV, roughness)
// (harness/pbrlab/gpu/ibl.py integrates the table with the library's own V term; the float64
// reference of the integral is harness/pbrlab/maths/reference/directional_albedo.py).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_IBL_ENVIRONMENT_BRDF_GLSL
#define PBR_IBL_ENVIRONMENT_BRDF_GLSL
#include "pbr/shading/dispatch.glsl"
#include "pbr/common/math.glsl"

// PBR_SPECULAR_OCCLUSION's default is the tier's, set by pbr/shading/dispatch.glsl (included
// above); this file's own default (every file that reads a selector has one) is never taken.
#ifndef PBR_SPECULAR_OCCLUSION
// PBR_SPECULAR_OCCLUSION_LAGARDE as a number (glsl/README.md, one-level preprocessors)
#define PBR_SPECULAR_OCCLUSION 1
#endif

// The selector's values (count from 1: a misspelt value is a compile error, glsl/README.md).
#define PBR_ENV_BRDF_TABLE 1
#define PBR_ENV_BRDF_ANALYTIC 2
#ifndef PBR_ENV_BRDF
// PBR_ENV_BRDF_TABLE as a number (glsl/README.md, one-level preprocessors)
#define PBR_ENV_BRDF 1
#endif

// Karis 2014, "Physically Based Shading on Mobile" (UE4's EnvBRDFApprox): a fit of the
// table for GGX + Schlick-GGX visibility; takes perceptual roughness. Against the float64
// integral of pbrlab's own lobe (height-correlated Smith, reference/directional_albedo.py)
// over NdotV in [1e-4, 1] x roughness in [0.045, 1]: A and B within 0.50 (mean 0.115; A + B
// within 0.55), against 4.0e-5 for the table (measured: tests/surface/test_env_brdf_selector.py,
// the bench's env_brdf family). Float64 twin: reference/surface.py env_brdf_approx.
vec2 pbr_env_brdf_approx(float NdotV, float perceptualRoughness) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = perceptualRoughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;
    return vec2(-1.04, 1.04) * a004 + r.zw;
}

// The DFG table's layout (harness/pbrlab/gpu/ibl.py writes it; shared constants tested equal).
// Texel (i, j), i, j from 0, holds (A, B) exactly at x = i / (WIDTH - 1), y = j / (HEIGHT - 1)
// of the warped axes below, so a bilinear fetch at the texel-centre coordinates
// (x (WIDTH - 1) + 0.5) / WIDTH interpolates between exact values and never reads past the
// table's edge values (a plain (NdotV, r) lookup reads NdotV = 1 half a texel short).
// Axes: the directional albedo has a dip of width ~alpha near NdotV -> 0 (E -> 1 at
// NdotV = 0, a minimum near NdotV ~ alpha) that a uniform grid misses by up to 5e-2, so
//   x = log2(1 + NdotV / c) / log2(1 + 1 / c),                          c = 0.003,
//   y = log2((alpha + c) / (alpha_min + c)) / log2((1 + c) / (alpha_min + c)),
// with alpha_min = PBR_MIN_PERCEPTUAL_ROUGHNESS² (smaller roughness reads the first row,
// which every tier clamps to anyway). Measured bilinear error: glsl/README.md.
#define PBR_DFG_LUT_WIDTH 256.0
#define PBR_DFG_LUT_HEIGHT 256.0
#define PBR_DFG_LUT_NDOTV_INV_SCALE 333.333333       // 1 / c of the NdotV axis, c = 0.003
#define PBR_DFG_LUT_NDOTV_LOG_NORM 0.119258545        // 1 / log2(1 + 1 / 0.003)
#define PBR_DFG_LUT_ALPHA_OFFSET 0.003                // c of the alpha axis
#define PBR_DFG_LUT_ALPHA_MIN_INV 199.004975          // 1 / (0.045² + 0.003)
#define PBR_DFG_LUT_ALPHA_LOG_NORM 0.130873226        // 1 / log2((1 + 0.003) / (0.045² + 0.003))

// The LOW tier's layout (PBR_DFG_LUT_LAYOUT_SQRT): texel (i, j) holds (A, B) at
// x = sqrt(NdotV) = i / (WIDTH - 1), y = perceptual roughness = j / (HEIGHT - 1), the same
// 256 x 256 and texel-centre convention as the warped table. The square root spreads the
// grazing dip (texel spacing in NdotV 1.5e-5 at 0); the roughness axis is linear, enough
// above LOW's floor 0.089 (alpha 7.9e-3): as sampled within 1.3e-4 of the float64 integral in
// A and B over NdotV in [1e-4, 1] x roughness in [0.089, 1] (tests/surface/test_dfg_table.py),
// against 4.0e-5 for the warped table; both inside the table's 1e-3 bound. One square root
// where the warped axes take two logarithms (RDNA3 instructions: docs/shading.md). (Texel
// centres at the axis values themselves would save the remap's two multiply-adds, but clamp
// to edge then holds the last half texel, 2.7e-3 off at NdotV = 1, roughness 1: measured.)
// Both layouts remap as one multiply-add per axis, xy (size - 1) / size + 0.5 / size, whose
// constants fold.
// (The selector's values are pbr/shading/dispatch.glsl's, with the tier's default; this file's
// own default is never taken.)
#ifndef PBR_DFG_LUT_LAYOUT
// PBR_DFG_LUT_LAYOUT_WARPED as a number (glsl/README.md, one-level preprocessors)
#define PBR_DFG_LUT_LAYOUT 1
#endif

vec2 pbr_dfg_lut_uv(float NdotV, float perceptualRoughness) {
    vec2 size = vec2(PBR_DFG_LUT_WIDTH, PBR_DFG_LUT_HEIGHT);
#if PBR_DFG_LUT_LAYOUT == PBR_DFG_LUT_LAYOUT_SQRT
    vec2 xy = vec2(sqrt(pbr_saturate(NdotV)), pbr_saturate(perceptualRoughness));
#elif PBR_DFG_LUT_LAYOUT == PBR_DFG_LUT_LAYOUT_WARPED
    float alpha = perceptualRoughness * perceptualRoughness;
    float x = log2(1.0 + pbr_saturate(NdotV) * PBR_DFG_LUT_NDOTV_INV_SCALE) * PBR_DFG_LUT_NDOTV_LOG_NORM;
    float y = log2((pbr_saturate(alpha) + PBR_DFG_LUT_ALPHA_OFFSET) * PBR_DFG_LUT_ALPHA_MIN_INV)
            * PBR_DFG_LUT_ALPHA_LOG_NORM;
    vec2 xy = clamp(vec2(x, y), 0.0, 1.0);
#else
#error PBR_DFG_LUT_LAYOUT: unknown value (PBR_DFG_LUT_LAYOUT_WARPED or PBR_DFG_LUT_LAYOUT_SQRT)
#endif
    return xy * ((size - 1.0) / size) + 0.5 / size;
}

vec2 pbr_env_brdf(float NdotV, float perceptualRoughness) {
#if PBR_ENV_BRDF == PBR_ENV_BRDF_ANALYTIC
    return pbr_env_brdf_approx(NdotV, perceptualRoughness);
#elif PBR_ENV_BRDF == PBR_ENV_BRDF_TABLE
#  if defined(PBR_DFG_LUT_LOOKUP)
    return PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness);
#  else
    return pbr_env_brdf_approx(NdotV, perceptualRoughness);
#  endif
#else
#error PBR_ENV_BRDF: unknown value
#endif
}

// Directional albedo of the single-scattering specular lobe: Schlick's F0 and F90 weights
// of the split sum, E = f0 A + f90 B (Karis 2013, eq. 8 with Schlick's F = f0 + (f90 - f0)
// (1 - VdotH)^5, linear in f0 and f90). The _f90 form takes the caller's F90
// (KHR_materials_specular: F90 = specularFactor · specularTexture.a, pbr_specular_F_f90);
// the plain form F90 = pbr_f90_from_f0(f0), as in the BRDF (pbr/shading/dispatch.glsl).
vec3 pbr_specular_albedo_f90(vec3 f0, float f90, vec2 dfg) {
    return f0 * dfg.x + f90 * dfg.y;
}

vec3 pbr_specular_albedo(vec3 f0, vec2 dfg) {
    return pbr_specular_albedo_f90(f0, pbr_f90_from_f0(f0), dfg);
}

// An upper bound of the albedo of the tier's own direct specular lobe, for the
// diffuse-specular coupling of punctual lights. The table holds Schlick's weights; a
// Fresnel within pbr_specular_F_deviation_bound(f0) of Schlick at every VdotH (the MEDIUM
// tier's spherical-Gaussian form: PBR_F_SCHLICK_SG_MAX_ABS_ERROR (f90 - f0)) reflects at
// most f0 A + f90 B + that deviation times A + B (measured without it: a white F0 = 0.02
// dielectric reflected 1.0025 of a direct light at MEDIUM). The fast and separable V terms
// have at most the albedo of the exact height-correlated V the table holds (their
// denominators are larger, Hammon 2017 / Heitz 2014), so they need no margin.
vec3 pbr_specular_albedo_bound_f90(vec3 f0, float f90, vec2 dfg) {
    return pbr_specular_albedo_f90(f0, f90, dfg) + pbr_specular_F_deviation_bound_f90(f0, f90) * (dfg.x + dfg.y);
}

vec3 pbr_specular_albedo_bound(vec3 f0, vec2 dfg) {
    return pbr_specular_albedo_bound_f90(f0, pbr_f90_from_f0(f0), dfg);
}

// Single-scattering GGX loses energy at high roughness (up to 69 % at roughness 1, see
// glsl/README.md). Scale the specular lobe by 1 + f0 (1/E - 1), E = A + B the albedo at
// f0 = 1: Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", as simplified in Filament ("Physically Based Rendering in
// Filament", section 5.3.4.7). A white metal in a white furnace then reflects 1.
// Lower bound of E in the division: the table's smallest E (roughness 1, head-on) is
// 0.307, so the guard only protects against a caller's zero dfg. With an explicit F90 (a
// lobe s · Schlick(c, 1), KHR_materials_specular's F0 = c s, F90 = s) the compensation stays
// the one of its F0 = c s: at most s times that of the lobe Schlick(c, 1), whose compensated
// albedo is at most 1, so the compensated albedo stays at most s <= 1.
// Coloured F0: against the float64 random walk on the Smith microsurface (Heitz et al. 2016,
// harness/pbrlab/maths/reference/multiple_scattering.py) the compensated albedo errs by at
// most +0.058 (roughness 1 facing the view: too bright) and -0.046 (grazing, low roughness),
// mean 0.006, over gold, copper, red and a 0.04 dielectric; Kulla & Conty's and
// Fdez-Aguera's Fresnel-weighted forms err by 0.051 and 0.075 (too dark): docs/shading.md,
// tests/library/test_multiple_scattering.py.
#define PBR_MIN_SPECULAR_ALBEDO 1e-4

vec3 pbr_energy_compensation(vec3 f0, vec2 dfg) {
    return 1.0 + f0 * (1.0 / max(dfg.x + dfg.y, PBR_MIN_SPECULAR_ALBEDO) - 1.0);
}

// Specular occlusion from ambient occlusion, the tier's choice (PBR_SPECULAR_OCCLUSION,
// pbr/shading/dispatch.glsl): Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing
// 26: saturate((NdotV + ao)^exp2(-16 alpha - 1) - 1 + ao) (HIGH, MEDIUM); or the ambient
// occlusion itself (LOW: no pow, and where the material has no occlusion, ao = 1, nothing).
// Both are in [0, 1] for ao in [0, 1]: an occluded lobe reflects less, never more.
float pbr_specular_occlusion(float NdotV, float occlusion, float alpha) {
#if PBR_SPECULAR_OCCLUSION == PBR_SPECULAR_OCCLUSION_LAGARDE
    return clamp(pow(NdotV + occlusion, exp2(-16.0 * alpha - 1.0)) - 1.0 + occlusion, 0.0, 1.0);
#elif PBR_SPECULAR_OCCLUSION == PBR_SPECULAR_OCCLUSION_AMBIENT
    return occlusion;
#else
#error PBR_SPECULAR_OCCLUSION: unknown value
#endif
}

// The mip of a prefiltered environment whose level i was filtered for perceptual
// roughness i / (lodCount - 1) (harness/pbrlab/gpu/ibl.py builds it that way).
float pbr_ibl_lod_from_perceptual_roughness(float perceptualRoughness, float lodCount) {
    return perceptualRoughness * (lodCount - 1.0);
}
#endif
