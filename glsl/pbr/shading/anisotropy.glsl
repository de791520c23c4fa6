// pbr/shading/anisotropy.glsl: anisotropic specular as KHR_materials_anisotropy defines it.
//
// Provides: vec2 pbr_anisotropic_alphas(float alpha, float strength)
//           vec3 pbr_anisotropy_direction(vec3 t, vec3 b, vec2 directionSample, float rotation)
//           vec3 pbr_brdf_anisotropic_specular(vec3 n, vec3 v, vec3 l, vec3 t, vec3 b, vec3 f0,
//                                              float perceptualRoughness, float strength)
//           vec3 pbr_brdf_anisotropic_specular_f90(vec3 n, vec3 v, vec3 l, vec3 t, vec3 b, vec3 f0,
//                                                  float f90, float perceptualRoughness,
//                                                  float strength)  (an explicit F90)
//           void  pbr_brdf_anisotropic_terms(vec3 n, vec3 v, vec3 l, vec3 t, vec3 b,
//                                            float perceptualRoughness, float strength,
//                                            out float DV, out float LdotH)  (the lobe before F)
//           vec3 pbr_anisotropic_bent_normal(vec3 n, vec3 v, vec3 anisotropicDirection,
//                                            float strength, float perceptualRoughness)
//           PBR_ANISOTROPIC_BENT_NORMAL_MAX_REL_ERROR (the bent normal's measured error bound)
// Include:  "pbr/shading/anisotropy.glsl" (path relative to glsl/)
// Config macros read: those of pbr/shading/dispatch.glsl through pbr/shading/standard.glsl
//           (PBR_QUALITY sets the roughness floor and the lobe cap).
//
// The extension (Khronos, KHR_materials_anisotropy, "Implementation"):
//  - Mapping. alphaRoughness = perceptualRoughness²; the tangent roughness grows with the
//    strength, the bitangent keeps the material's:
//      alphaT = mix(alphaRoughness, 1, strength²),   alphaB = alphaRoughness.
//    pbr_anisotropic_alphas returns vec2(alphaT, alphaB). strength in [0, 1] (the spec's
//    anisotropyStrength times the texture's blue channel); only strength² enters, so a
//    negative strength acts as its magnitude, and |strength| > 1 as 1 (decided: no alphaT > 1).
//  - Direction. directionSample = anisotropyTexture.rg · 2 - 1 (in [-1, 1]², the caller's
//    decode), or (1, 0) without a texture; it is rotated by anisotropyRotation (radians,
//    counter-clockwise from the tangent t towards b):
//      d = mat2(cos r, sin r, -sin r, cos r) · directionSample,
//      anisotropicT = normalize(t · d.x + b · d.y),
//    with t, b the surface's tangent frame (glTF TANGENT: b = cross(n, t) · tangent.w). The
//    caller forms anisotropicB = cross(n, anisotropicT) for the lobe and the bent normal.
//    Decided: a zero sample (texel (0.5, 0.5): no direction, normalize(0) is NaN) reads as
//    the untextured default (1, 0); a degenerate t, b gives the zero vector
//    (pbr_safe_normalize).
//  - Lobe (direct light). D · V · F with D = pbr_D_GGX_Anisotropic, V =
//    pbr_V_SmithGGXCorrelated_Anisotropic (alphaT along anisotropicT = t, alphaB along b),
//    F = pbr_F_Schlick(f0, pbr_f90_from_f0(f0), VdotH) (the _f90 form: the caller's F90), in 1/sr (no light, no cosine, as
//    pbr_brdf_standard's specular; multiply by PBR_LIGHT_UNIT_SCALE · NdotL · radiance).
//    strength = 0 is pbr_brdf_standard's GGX / height-correlated Smith / Schlick specular
//    (tested to float32 rounding). The guards are pbr_brdf_standard's: perceptual roughness
//    clamped to the tier's floor (pbr_clamp_perceptual_roughness), NdotV to
//    [PBR_MIN_NDOTV, 1]; h = (l + v)/|l + v| is formed only as cosines scaled by
//    inversesqrt(|l + v|²) with |l + v|² clamped to [PBR_MIN_NDOT_HALF_SUM², 4]
//    (no 1 - NdotH²: the anisotropic D takes TdotH and BdotH, which carry their own
//    precision at the peak); VdotH = |l + v|/2; D · V through pbr_specular_lobe_limit.
//    Edges (selects, not branches), pbr_brdf_standard's selection in every tier: the lobe
//    where NdotL and n·(l + v) both reach PBR_MIN_NDOT_HALF_SUM (2^-50; one min, one
//    compare), else 0: NdotL <= 0, l = -v and h below the surface. The selected |l + v|² is
//    then >= 2^-100, so the clamp's floor changes nothing there. Not a threshold on
//    |l + v|²: a grazing mirror (NdotL = NdotV = c) has a short l + v but a defined h and a
//    lobe that grows as c -> 0; the former tier threshold dropped it below c = 5e-6 (HIGH,
//    MEDIUM) and c = 3.9e-3 (LOW) (issue 25; tests/checking/hardcases/test_grazing_mirrors.py).
//    Contract: n, v, l, t, b unit vectors, t and b orthogonal to n and to each other (the
//    anisotropic frame: t = anisotropicT, b = anisotropicB).
//  - Image-based light. The bent reflection normal of the Khronos glTF sample viewer
//    (getIBLRadianceAnisotropy; Filament's getReflectedVector builds the same
//    anisotropicNormal but bends by |anisotropy| · saturate(5 perceptualRoughness)): with
//    d = anisotropicDirection,
//      anisotropicNormal = cross(cross(d, v), d)     (v with its component along d removed)
//      bend = 1 - strength (1 - perceptualRoughness)
//      bentNormal = normalize(mix(anisotropicNormal, n, bend⁴)),
//    and the caller samples its prefiltered environment at reflect(-v, bentNormal) with the
//    isotropic roughness (sample viewer: lod = perceptualRoughness · (mipCount - 1)).
//    d is the anisotropic BITANGENT, cross(n, anisotropicT), as the sample viewer passes it
//    (Filament: anisotropicB for anisotropy >= 0): the highlight stretches across the
//    rough tangent direction. Decided: strength as in the alphas (|strength|, at most 1),
//    perceptualRoughness saturated; where the mixed vector vanishes (v along d at
//    strength 1, roughness 0) the result is n.
//    Error, measured against the float64 exact anisotropic specular integral (F = 1) under a
//    test environment (sky + a 0.2 rad sun off the lobe's symmetry planes;
//    harness/pbrlab/maths/reference/anisotropy.py, tests/library/test_anisotropy.py), the
//    approximation being the GGX-prefiltered environment (isotropic alpha = r²) at
//    reflect(-v, bentNormal) times the exact anisotropic albedo (so only the lobe's
//    direction and shape are measured), over r 0.2 ... 0.8, strength 0.5 and 1, views
//    0°, 45°, 70° at azimuths 0° and 60° from t: worst relative error 2.05 (+205 %, r = 0.2,
//    strength 0.5, view 45° in the (t, n) plane: the bent reflection swings towards v and
//    catches the sun the true lobe barely reaches), mean 0.26; the unbent reflect(-v, n)
//    measures worst 0.62, mean 0.25. It is a heuristic: it moves the highlight the right
//    way on average, not accurately.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_ANISOTROPY_GLSL
#define PBR_SHADING_ANISOTROPY_GLSL

#include "pbr/common/conventions.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/material/remap.glsl"
#include "pbr/brdf/d_ggx_anisotropic.glsl"
#include "pbr/brdf/v_smith_ggx_correlated_anisotropic.glsl"
#include "pbr/brdf/f_schlick.glsl"
#include "pbr/shading/standard.glsl"

// Worst relative error of the bent-normal image-based specular (measured 2.046, see
// above); shared with reference/anisotropy.py BENT_NORMAL_MAX_REL_ERROR.
#define PBR_ANISOTROPIC_BENT_NORMAL_MAX_REL_ERROR 2.05

vec2 pbr_anisotropic_alphas(float alpha, float strength) {
    float strength2 = min(strength * strength, 1.0);
    alpha = pbr_saturate(alpha);
    return vec2(mix(alpha, 1.0, strength2), alpha);
}

vec3 pbr_anisotropy_direction(vec3 t, vec3 b, vec2 directionSample, float rotation) {
    bool hasDirection = dot(directionSample, directionSample) >= PBR_FLT_MIN;
    float x = hasDirection ? directionSample.x : 1.0;
    float y = hasDirection ? directionSample.y : 0.0;
    float c = cos(rotation);
    float s = sin(rotation);
    return pbr_safe_normalize(t * (c * x - s * y) + b * (s * x + c * y));
}

// D · V with pbr_brdf_standard's selection, and LdotH = VdotH for F: shared by the two forms
// below, which differ only in the F90 their Fresnel takes (computed last in both, so the plain
// form compiles to the program it was before the explicit F90 existed).
void pbr_brdf_anisotropic_terms(vec3 n, vec3 v, vec3 l, vec3 t, vec3 b, float perceptualRoughness,
                                float strength, out float DV, out float LdotH) {
    float NdotL = dot(n, l);
    float NdotV = clamp(dot(n, v), PBR_MIN_NDOTV, 1.0);
    float roughness = pbr_clamp_perceptual_roughness(perceptualRoughness);
    vec2 alphas = pbr_anisotropic_alphas(pbr_alpha_from_perceptual_roughness(roughness), strength);

    // h = (l + v) / |l + v| only as scaled cosines (see header)
    vec3 halfSum = l + v;
    float halfLength2 = dot(halfSum, halfSum);
    LdotH = 0.5 * sqrt(halfLength2);  // == VdotH for unit l, v (standard.glsl)
    float invHalfLength = inversesqrt(clamp(halfLength2, PBR_MIN_NDOT_HALF_SUM * PBR_MIN_NDOT_HALF_SUM, 4.0));
    float nDotHalfSum = dot(n, halfSum);
    float D = pbr_D_GGX_Anisotropic(nDotHalfSum * invHalfLength, dot(t, halfSum) * invHalfLength,
                                    dot(b, halfSum) * invHalfLength, alphas.x, alphas.y);
    float V = pbr_V_SmithGGXCorrelated_Anisotropic(NdotL, NdotV, dot(t, v), dot(b, v), dot(t, l), dot(b, l),
                                                   alphas.x, alphas.y);
    DV = pbr_specular_lobe_limit(D * V);
    // pbr_brdf_standard's selection (a select: the unselected values are finite)
    DV = min(NdotL, nDotHalfSum) >= PBR_MIN_NDOT_HALF_SUM ? DV : 0.0;
}

vec3 pbr_brdf_anisotropic_specular(vec3 n, vec3 v, vec3 l, vec3 t, vec3 b, vec3 f0,
                                   float perceptualRoughness, float strength) {
    float DV, LdotH;
    pbr_brdf_anisotropic_terms(n, v, l, t, b, perceptualRoughness, strength, DV, LdotH);
    return DV * pbr_F_Schlick(f0, pbr_f90_from_f0(f0), LdotH);
}

// The same with an explicit F90 (KHR_materials_specular's specularFactor, >= every channel of
// f0): the sample viewer's dielectric Fresnel F_Schlick(f0 · specularWeight, specularWeight,
// VdotH) on its anisotropic lobe as on the isotropic one.
vec3 pbr_brdf_anisotropic_specular_f90(vec3 n, vec3 v, vec3 l, vec3 t, vec3 b, vec3 f0, float f90,
                                       float perceptualRoughness, float strength) {
    float DV, LdotH;
    pbr_brdf_anisotropic_terms(n, v, l, t, b, perceptualRoughness, strength, DV, LdotH);
    return DV * pbr_F_Schlick(f0, f90, LdotH);
}

vec3 pbr_anisotropic_bent_normal(vec3 n, vec3 v, vec3 anisotropicDirection, float strength,
                                 float perceptualRoughness) {
    float s = min(abs(strength), 1.0);
    vec3 anisotropicTangent = cross(anisotropicDirection, v);
    vec3 anisotropicNormal = cross(anisotropicTangent, anisotropicDirection);
    float bend = 1.0 - s * (1.0 - pbr_saturate(perceptualRoughness));
    float bend2 = bend * bend;
    vec3 bent = pbr_safe_normalize(mix(anisotropicNormal, n, bend2 * bend2));
    return dot(bent, bent) > 0.0 ? bent : n;
}

#endif // PBR_SHADING_ANISOTROPY_GLSL
