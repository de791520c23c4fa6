// pbr/surface/lighting_iridescence.glsl: KHR_materials_iridescence's thin film on the base, as
// the base's specular colour (F0) for one view.
//
// Provides: struct pbr_Iridescence
//           PBR_IRIDESCENCE_MAX_SCHLICK_WEIGHT
//           vec3 pbr_f0_from_schlick(vec3 F, float cosTheta)
//           vec3 pbr_iridescent_f0(vec3 f0, float NdotV, pbr_Iridescence film)
//           vec3 pbr_iridescent_f0_f90(vec3 f0, float f90, float NdotV, pbr_Iridescence film)
//                (an explicit F90: KHR_materials_specular's specularFactor)
//           vec3 pbr_iridescent_diffuse_color(vec3 diffuseColor, vec3 coatF0, vec3 filmCoatF0)
//           struct pbr_IridescentF0
//           pbr_IridescentF0 pbr_iridescent_f0_with_coat(vec3 f0, vec3 coatF0, float NdotV,
//                                                        pbr_Iridescence film)
//           pbr_IridescentF0 pbr_iridescent_f0_f90_with_coat(vec3 f0, float f90, vec3 coatF0,
//                                                            float coatF90, float NdotV,
//                                                            pbr_Iridescence film)
//                (the film over the base's F0 and over its coat's, the film evaluated once)
// Include:  "pbr/surface/lighting_iridescence.glsl" (path relative to glsl/)
// Config macros read: none.
//
// The film (Belcour & Barla 2017 in KHR_materials_iridescence's form: pbr_F_Iridescence,
// pbr/brdf/f_iridescence.glsl) is evaluated once per shaded point, at the view's cosine
// NdotV, over the base's F0, with outside IOR 1; the Khronos Sample Renderer does the same
// (evalIridescence(1.0, iridescenceIor, NdotV, thickness, f0) in its pbr.frag). pbrlab
// then folds it into the base's F0, as the Sample Renderer does for its image-based light
// (Schlick_to_F0):
//   F0_film = (F_iridescence(NdotV) − x) / (1 − x),  x = min((1 − NdotV)⁵, 0.9999),
// the F0 whose Schlick curve (F90 = 1) passes through the film's reflectance at this view,
// saturated, and
//   F0' = mix(F0, F0_film, iridescence)        (KHR: mix(F_schlick, F_iridescence, iridescence)).
// Every Fresnel of the base then reads F0' (direct light at VdotH, the split sum, the energy
// compensation, the diffuse's coupling to the coat over it: the caller passes its coat's F0
// through the same function), so the film costs one pbr_F_Iridescence per F0 and pixel and
// the base's energy bookkeeping holds as it does for any F0 in [0, 1]. The diffuse colour is
// rescaled with the coat's F0 (pbr_iridescent_diffuse_color) so that the diffuse albedo rho
// the coupling recovers from it (pbr_diffuse_albedo_from_diffuse_color) stays the
// material's: without it a film whose F0' is below the base's 0.04 darkened a white
// dielectric's diffuse by up to 0.016 in a white furnace, and one above it was only saved
// by rho's cap at 1 (tests/render/test_white_furnace.py, filmed rows). Decided:
//  - outside IOR 1, coated or not (the Sample Renderer's choice; the specification's text
//    puts the coat's IOR above the film where KHR_materials_clearcoat is present);
//  - direct light reads Schlick(F0', VdotH) rather than the Sample Renderer's
//    mix(Schlick(F0, VdotH), F_iridescence(NdotV), iridescence): equal at VdotH = NdotV, and
//    the film's colour then follows Schlick's angular trend, not the film's own;
//  - F90 follows F0' (pbr_f90_from_f0), 1 unless the film's F0 is below 0.02 grey.
// With an explicit F90 (KHR_materials_specular: F0 = c · s, F90 = s, s = specularFactor ·
// specularTexture.a, c the dielectric's F0 colour), pbr_iridescent_f0_f90 evaluates the film
// over the unit-strength F0 c = F0 / F90 (the film's base is the dielectric's own reflectance:
// the Sample Renderer passes its f0_dielectric, before the specular weight, to
// evalIridescence) and scales the result back by F90:
//   F0' = F90 · mix(c, F0_film(c), iridescence),  F90 unchanged,
// so every Fresnel of the base reads Schlick(F0', F90) = F90 · Schlick(mix(c, F0_film, t), 1):
// the Sample Renderer's 2023 form (BRDF_specularGGXIridescence, getIBLRadianceGGXIridescence:
// specularWeight · mix(F_Schlick(f0, 1, VdotH), F_iridescence, iridescence)) with pbrlab's
// fold into F0 above. Its later releases mix the film's Fresnel in without the specular weight
// (rgb_mix(diffuse, specular, F_iridescence)): a filmed region then ignores specularFactor,
// and specularFactor 0 ("disables the specular reflection", KHR_materials_specular) still
// reflects the film; pbrlab keeps the weight. F0' <= F90, so the energy bookkeeping holds as
// for any F0 <= F90. F90 = 1 is pbr_iridescent_f0 exactly (f0 / 1, 1 · x).
// Python twin: harness/pbrlab/maths/reference/specular_extension.py iridescent_f0_f90.
// iridescence = 0 returns f0 exactly (mix with weight 0); thickness 0 is pbr_F_Schlick of the
// base (pbr_F_Iridescence's rule), so F0_film = F0 up to the inversion's float32 rounding.
// Python twin: harness/pbrlab/maths/reference/surface.py iridescent_f0.
// A base and the coat over its diffuse see the same film at the same view: the _with_coat forms
// return both F0' (each bit for bit pbr_iridescent_f0[_f90] of its F0) from one pbr_thin_film
// (pbr/brdf/f_iridescence.glsl): the coat's Airy sum, then the base's, then both selected and
// folded, so the film's shared terms die once both sums are formed. Register demand of the
// iridescence class's program (benchmarks/whole_program_cost.py, RDNA3 before ACO's
// scheduler): two pbr_iridescent_f0 calls 50 (60 VGPRs allocated), each base finished in
// turn 49 (60), this order 48 (48).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SURFACE_LIGHTING_IRIDESCENCE_GLSL
#define PBR_SURFACE_LIGHTING_IRIDESCENCE_GLSL
#include "pbr/common/math.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/brdf/f_iridescence.glsl"
#include "pbr/shading/energy_conservation.glsl"

// Largest Schlick weight (1 − cosθ)⁵ the inversion divides by 1 minus (the Sample
// Renderer's clamp in Schlick_to_F0): at grazing views F0 is not recoverable from F, and
// 1/(1 − 0.9999) = 1e4 bounds the amplification of F's rounding. Shared with
// reference/surface.py IRIDESCENCE_MAX_SCHLICK_WEIGHT.
#define PBR_IRIDESCENCE_MAX_SCHLICK_WEIGHT 0.9999

struct pbr_Iridescence {
    float factor;       // 0 = no film .. 1 (glTF iridescenceFactor x texture.r)
    float ior;          // the film's IOR (glTF iridescenceIor, default 1.3)
    float thicknessNm;  // nanometres (pbr_iridescence_thickness of glTF's min, max, texture.g)
};

// Schlick 1994 solved for F0 with F90 = 1: F = F0 + (1 − F0) x  =>  F0 = (F − x) / (1 − x).
vec3 pbr_f0_from_schlick(vec3 F, float cosTheta) {
    float x = min(pbr_pow5(1.0 - pbr_saturate(cosTheta)), PBR_IRIDESCENCE_MAX_SCHLICK_WEIGHT);
    return pbr_saturate((F - vec3(x)) / (1.0 - x));
}

vec3 pbr_iridescent_f0(vec3 f0, float NdotV, pbr_Iridescence film) {
    vec3 filmF = pbr_F_Iridescence(1.0, film.ior, NdotV, film.thicknessNm, f0);
    return pbr_iridescence_mix(f0, pbr_f0_from_schlick(filmF, NdotV), film.factor);
}

struct pbr_IridescentF0 {
    vec3 f0;      // the base's F0' (pbr_iridescent_f0[_f90] of its F0)
    vec3 coatF0;  // the coat's F0' over the diffuse (the same of the coat's F0)
};

pbr_IridescentF0 pbr_iridescent_f0_with_coat(vec3 f0, vec3 coatF0, float NdotV, pbr_Iridescence film) {
    pbr_ThinFilm thin = pbr_thin_film(1.0, film.ior, NdotV, film.thicknessNm);
    pbr_IridescentF0 r;
    vec3 coatI = pbr_iridescence_airy(thin, coatF0);
    vec3 I = pbr_iridescence_airy(thin, f0);
    vec3 F = pbr_iridescence_select(thin, f0, I);
    vec3 coatF = pbr_iridescence_select(thin, coatF0, coatI);
    r.coatF0 = pbr_iridescence_mix(coatF0, pbr_f0_from_schlick(coatF, NdotV), film.factor);
    r.f0 = pbr_iridescence_mix(f0, pbr_f0_from_schlick(F, NdotV), film.factor);
    return r;
}

// With an explicit F90 (f90 >= every channel of f0): the film over the unit-strength F0
// c = f0 / f90, scaled back by f90 (see the header). f90 = 0 (then f0 = 0) returns 0.
vec3 pbr_iridescent_f0_f90(vec3 f0, float f90, float NdotV, pbr_Iridescence film) {
    vec3 unitF0 = pbr_saturate(f0 / max(f90, PBR_FLT_MIN));
    return f90 * pbr_iridescent_f0(unitF0, NdotV, film);
}

pbr_IridescentF0 pbr_iridescent_f0_f90_with_coat(vec3 f0, float f90, vec3 coatF0, float coatF90, float NdotV,
                                                 pbr_Iridescence film) {
    pbr_ThinFilm thin = pbr_thin_film(1.0, film.ior, NdotV, film.thicknessNm);
    vec3 unitCoatF0 = pbr_saturate(coatF0 / max(coatF90, PBR_FLT_MIN));
    vec3 unitF0 = pbr_saturate(f0 / max(f90, PBR_FLT_MIN));
    vec3 coatI = pbr_iridescence_airy(thin, unitCoatF0);
    vec3 I = pbr_iridescence_airy(thin, unitF0);
    vec3 F = pbr_iridescence_select(thin, unitF0, I);
    vec3 coatF = pbr_iridescence_select(thin, unitCoatF0, coatI);
    pbr_IridescentF0 r;
    r.coatF0 = coatF90 * pbr_iridescence_mix(unitCoatF0, pbr_f0_from_schlick(coatF, NdotV), film.factor);
    r.f0 = f90 * pbr_iridescence_mix(unitF0, pbr_f0_from_schlick(F, NdotV), film.factor);
    return r;
}

// The diffuse colour whose albedo under the filmed coat (filmCoatF0 = pbr_iridescent_f0 of
// coatF0) is the one diffuseColor has under coatF0: rho (1 - max3(filmCoatF0)), rho =
// pbr_diffuse_albedo_from_diffuse_color(diffuseColor, coatF0) (the same floor on 1 - max3).
vec3 pbr_iridescent_diffuse_color(vec3 diffuseColor, vec3 coatF0, vec3 filmCoatF0) {
    return pbr_diffuse_albedo_from_diffuse_color(diffuseColor, coatF0)
         * max(1.0 - pbr_max3(filmCoatF0), PBR_MIN_ONE_MINUS_REFLECTIVITY);
}
#endif
