// pbr/brdf/f_iridescence.hlsl: thin-film iridescence Fresnel (KHR_materials_iridescence).
//
// Provides: vec3  pbr_F_Iridescence(float outsideIor, float filmIor, float cosTheta1,
//                                   float thicknessNm, vec3 baseF0)
//           struct pbr_ThinFilm
//           pbr_ThinFilm pbr_thin_film(float outsideIor, float filmIor, float cosTheta1,
//                                      float thicknessNm)
//           vec3  pbr_F_Iridescence_thin_film(pbr_ThinFilm film, vec3 baseF0)
//                (pbr_F_Iridescence split: the terms that do not read the base, then one base's)
//           vec3  pbr_iridescence_airy(pbr_ThinFilm film, vec3 baseF0)
//           float pbr_iridescence_airy_channel(pbr_ThinFilm film, float eta3, float S1, float S2)
//           vec3  pbr_iridescence_select(pbr_ThinFilm film, vec3 baseF0, vec3 I)
//                (pbr_F_Iridescence_thin_film's two steps: the Airy sum, then the special cases)
//           vec3  pbr_iridescence_sensitivity(float opdNm, vec3 shift)
//           vec3  pbr_iridescence_sensitivity_xyz(float opdNm)
//           vec3  pbr_iridescence_xyz_to_rec709(vec3 xyz)
//           vec3  pbr_iridescence_mix(vec3 F, vec3 Firidescence, float iridescenceFactor)
//           float pbr_iridescence_thickness(float thicknessMin, float thicknessMax, float textureG)
// Include:  "pbr/brdf/f_iridescence.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Model: Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for the Modeling
// of Varying Iridescence" (ACM TOG 36(4)), in the approximate form the glTF extension
// KHR_materials_iridescence (ratified 2022, "Iridescence Fresnel", non-normative) writes:
// a dielectric film of index filmIor and thickness thicknessNm (nanometres) between the
// outside medium (outsideIor: 1 for air, the clearcoat's IOR under a coat) and the base,
// whose IOR is recovered from F0 per channel, eta3 = (1 + √F0)/(1 − √F0) (pbr_ior_from_f0;
// exact for dielectrics, the spec's approximation for metals: extinction taken as 0).
//   R12 = Schlick(((n2 − n1)/(n2 + n1))², cosθ1), T121 = 1 − R12       (outside -> film)
//   cos²θ2 = 1 − (n1/n2)² (1 − cos²θ1); cos²θ2 < 0: total internal reflection, F = 1
//   R23 = Schlick(((eta3 − n2)/(eta3 + n2))², cosθ2)                    (film -> base)
//   phases: φ21 = π − φ12 (φ12 = π if n2 < n1), φ23 = π if eta3 < n2; φ = φ21 + φ23
//   OPD = 2 n2 d cosθ2 (first-order optical path difference, nm)
//   Airy series (paper §4, eq. 11-13), R123 = R12 R23, Rs = T121² R23 / (1 − R123):
//   F = R12 + Rs + Σ_{m=1,2} 2 (Rs − T121) R123^(m/2) S(m OPD, m φ)
// with S the XYZ sensitivity of a Dirac at optical path m·OPD: the Fourier transform of
// the CIE 1931 colour-matching functions, fitted by the paper with one Gaussian per
// channel plus a second one for x (§4.2, the constants below), normalised so that S(0, 0)
// = (1, 1, 1) in XYZ: illuminant E, and converted to linear Rec. 709 (conventions.hlsl 2)
// by the sRGB matrix of IEC 61966-2-1 (Lindbloom's D65 values, as the spec writes them).
// The DC term R12 + Rs is used as RGB directly (the spec's simplification: white = 1).
//
// Thickness 0 (decided, after the Khronos glTF Sample Renderer, which the spec's authors
// maintain: iridescence.hlsl forces the film IOR to the outside IOR by
// mix(n1, n2, smoothstep(0, 0.03, d)) and material_info sets iridescenceFactor = 0 when
// d == 0): d <= 0 (or NaN) returns pbr_F_Schlick(baseF0, cosTheta1) bit for bit, the
// Schlick Fresnel of glTF B.3.4 that the extension mixes towards; 0 < d < 0.03 nm fades the
// film IOR to n1 (the spec's own formula at n2 = n1 still has R12 = (1 − cosθ1)⁵ from
// Schlick, hence the explicit d = 0 rule).
// Deviations from the spec's listing, each measured by tests/library/test_iridescence.py:
//   * base F0 clamped at PBR_IRIDESCENCE_MAX_BASE_F0 = 0.9999 (the Sample Renderer's
//     guard) instead of the spec text's baseF0 + 0.0001, which biases every base IOR;
//   * R123 floored at PBR_IRIDESCENCE_MIN_R123 = 0, not the spec's 1e-5: its floor adds a
//     spurious 2 √1e-5 (R23 − 1) S(OPD) (up to 0.008) where there is no film interface
//     (n2 = n1, normal view), and sqrt(0) is defined; identical where R12 R23 >= 1e-5;
//   * the result is saturated to [0, 1] (the spec clamps at 0 only: the fitted S exceeds 1
//     in red, so the spec's F overshoots 1 by up to 0.24: film IOR 1.2-2, 0-1200 nm);
//   * OPD is capped at PBR_IRIDESCENCE_MAX_OPD_NM inside S, where every Gaussian envelope
//     is exactly 0 in float32 (exp(−4.3e9 (2π 1e5 1e-9)²) = e^−1700): costs nothing, keeps
//     phase² finite for any thickness.
//   * the phase shift φ (0, π or 2π: φ21 and φ23 are each 0 or π) is applied as the sign
//     cos φ = ±1 of each channel's XYZ term, S(m OPD, m φ) = M (cos(m φ) ⊙ S_xyz(m OPD)), not
//     added to the cosine's argument: equal in exact arithmetic (cos(x + π) = −cos x), so the
//     second order (cos 2φ = 1) and the first order's XYZ terms are shared by every base
//     under the same film; the float32 argument x + φ (x <= 133 rad) is not rounded any more.
//     Against the spec's form (pbr_iridescence_sensitivity with the shift) F differs by that
//     rounding and the device's cosine at the two arguments only: within a per-sample bound
//     derived from them (at most 4.0e-5, where the envelope is 1 at the largest arguments),
//     measured at most 8.9e-7 (llvmpipe; tests/library/test_iridescence.py), and nearer the
//     float64 method (worst 1.6e-6 against 1.9e-6 at outside IOR 1).
// Error against the physics (float64, independent spectral reference: exact Airy
// reflectance per wavelength, s and p averaged, against Wyman, Sloan & Shirley 2013's
// analytic CIE 1931 fit; harness/pbrlab/maths/reference/iridescence.py): see
// worst |F - reference| 0.2206 (bound PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL = 0.23) over
// outside IOR 1, film IOR 1.2-2, thickness 0-1200 nm, cosθ1 0.05-1, dielectric base F0
// 0.02-0.08, at cosθ1 = 0.15 (Schlick's grazing error and the two-order truncation);
// 0.0434 for cosθ1 >= 0.7 (bound PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL_NEAR_NORMAL =
// 0.045). The reference is white-balanced (a perfect mirror is 1: the DC term's white);
// against the unbalanced E white the worst is 0.218. For metal F0 read as dielectric IORs
// the worst is 0.54 (F0 0.5, cosθ1 0.15, film IOR 2): neither side is the physics there.
// Guards: cosTheta1 and baseF0 saturated; thickness < 0 is 0. Domain: IORs in [1/16, 16],
// thickness finite.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_BRDF_F_IRIDESCENCE_HLSL
#define PBR_BRDF_F_IRIDESCENCE_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/brdf/f_iridescence.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

#include "pbr/common/constants.hlsl"
#include "pbr/common/math.hlsl"
#include "pbr/brdf/f_schlick.hlsl"
#include "pbr/material/ior.hlsl"

// Belcour & Barla 2017 §4.2 Gaussian fit of the CIE 1931 XYZ sensitivity (as in the spec):
// amplitude val, position pos (1/m) and variance var (1/m²) per channel; a second x lobe.
#define PBR_IRIDESCENCE_XYZ_VAL float3(5.4856e-13, 4.4201e-13, 5.2481e-13)
#define PBR_IRIDESCENCE_XYZ_POS float3(1.6810e+06, 1.7953e+06, 2.2084e+06)
#define PBR_IRIDESCENCE_XYZ_VAR float3(4.3278e+09, 9.3046e+09, 6.6121e+09)
#define PBR_IRIDESCENCE_X2_VAL 9.7470e-14
#define PBR_IRIDESCENCE_X2_POS 2.2399e+06
#define PBR_IRIDESCENCE_X2_VAR 4.5282e+09
#define PBR_IRIDESCENCE_XYZ_NORM 1.0685e-7  // makes S(0, 0) = (1, 1, 1) within 1.1e-3
// CIE XYZ -> linear Rec. 709 rows (IEC 61966-2-1, Lindbloom's digits, as in the spec).
#define PBR_XYZ_TO_REC709_ROW0 float3(3.2404542, -1.5371385, -0.4985314)
#define PBR_XYZ_TO_REC709_ROW1 float3(-0.9692660, 1.8760108, 0.0415560)
#define PBR_XYZ_TO_REC709_ROW2 float3(0.0556434, -0.2040259, 1.0572252)
#define PBR_IRIDESCENCE_MAX_BASE_F0 0.9999      // Sample Renderer's guard (base IOR <= 4e4)
#define PBR_IRIDESCENCE_MIN_R123 0.0            // spec: 1e-5 (see above)
#define PBR_IRIDESCENCE_MAX_R123 0.9999         // spec: keeps 1 − R123 > 0 at grazing
#define PBR_IRIDESCENCE_FILM_FADE_NM 0.03       // Sample Renderer: smoothstep(0, 0.03, d)
#define PBR_IRIDESCENCE_MAX_OPD_NM 1.0e5        // S is exactly 0 in float32 beyond ~3e4 nm
// Measured worst |F − spectral reference| (float64; tests check it on the GPU)
#define PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL 0.23
#define PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL_NEAR_NORMAL 0.045  // cosTheta1 >= 0.7

// S(OPD, shift): the spec's evalSensitivity, in linear Rec. 709. opdNm in nanometres;
// phase = 2π OPD 1e-9 (1/m units of pos and var).
float3 pbr_iridescence_sensitivity(float opdNm, float3 shift) {
    float phase = PBR_TWO_PI * 1.0e-9 * clamp(opdNm, 0.0, PBR_IRIDESCENCE_MAX_OPD_NM);
    float phase2 = phase * phase;
    float3 amplitude = PBR_IRIDESCENCE_XYZ_VAL * sqrt(PBR_TWO_PI * PBR_IRIDESCENCE_XYZ_VAR);
    float3 xyz = amplitude * cos(PBR_IRIDESCENCE_XYZ_POS * phase + shift)
             * exp(-phase2 * PBR_IRIDESCENCE_XYZ_VAR);
    xyz.x += PBR_IRIDESCENCE_X2_VAL * sqrt(PBR_TWO_PI * PBR_IRIDESCENCE_X2_VAR)
           * cos(PBR_IRIDESCENCE_X2_POS * phase + shift.x) * exp(-phase2 * PBR_IRIDESCENCE_X2_VAR);
    xyz /= PBR_IRIDESCENCE_XYZ_NORM;
    return float3(dot(PBR_XYZ_TO_REC709_ROW0, xyz), dot(PBR_XYZ_TO_REC709_ROW1, xyz),
                dot(PBR_XYZ_TO_REC709_ROW2, xyz));
}

// S_xyz(OPD): the sensitivity's normalised XYZ terms at zero phase shift (pbr_iridescence_sensitivity
// before its matrix, shift 0); a shift of π negates a channel's terms, 2π leaves them.
float3 pbr_iridescence_sensitivity_xyz(float opdNm) {
    float phase = PBR_TWO_PI * 1.0e-9 * clamp(opdNm, 0.0, PBR_IRIDESCENCE_MAX_OPD_NM);
    float phase2 = phase * phase;
    float3 amplitude = PBR_IRIDESCENCE_XYZ_VAL * sqrt(PBR_TWO_PI * PBR_IRIDESCENCE_XYZ_VAR);
    float3 xyz = amplitude * cos(PBR_IRIDESCENCE_XYZ_POS * phase) * exp(-phase2 * PBR_IRIDESCENCE_XYZ_VAR);
    xyz.x += PBR_IRIDESCENCE_X2_VAL * sqrt(PBR_TWO_PI * PBR_IRIDESCENCE_X2_VAR)
           * cos(PBR_IRIDESCENCE_X2_POS * phase) * exp(-phase2 * PBR_IRIDESCENCE_X2_VAR);
    return xyz / PBR_IRIDESCENCE_XYZ_NORM;
}

// CIE XYZ to linear Rec. 709 (the rows above).
float3 pbr_iridescence_xyz_to_rec709(float3 xyz) {
    return float3(dot(PBR_XYZ_TO_REC709_ROW0, xyz), dot(PBR_XYZ_TO_REC709_ROW1, xyz),
                dot(PBR_XYZ_TO_REC709_ROW2, xyz));
}

// The film's terms that do not read the base (Belcour & Barla 2017: only the film -> base
// interface, R23 and φ23, depends on the base's IOR): what every base under this film at this
// view shares. xyz1: S_xyz(OPD), the first order's XYZ terms before the base's phase signs;
// S2: the second order's S (its shift 2φ is 0, 2π or 4π: no sign).
struct pbr_ThinFilm {
    float n1;           // outside IOR
    float n2;           // the film's IOR, faded to n1 below PBR_IRIDESCENCE_FILM_FADE_NM
    float c1;           // cos θ1, saturated
    float cos2Sq;       // cos² θ2 (< 0: total internal reflection)
    float c2;           // cos θ2
    float R12;          // outside -> film reflectance (Schlick)
    float T121;         // 1 − R12
    float thicknessNm;  // as given (<= 0 or NaN: no film)
    float3 xyz1;          // S_xyz(OPD)
    float3 S2;            // S(2 OPD, 2φ)
};

pbr_ThinFilm pbr_thin_film(float outsideIor, float filmIor, float cosTheta1, float thicknessNm) {
    pbr_ThinFilm f;
    f.n1 = outsideIor;
    f.thicknessNm = thicknessNm;
    f.c1 = pbr_saturate(cosTheta1);
    f.n2 = lerp(f.n1, filmIor, smoothstep(0.0, PBR_IRIDESCENCE_FILM_FADE_NM, thicknessNm));
    // Snell's law into the film
    float ratio = f.n1 / f.n2;
    f.cos2Sq = 1.0 - ratio * ratio * (1.0 - f.c1 * f.c1);
    f.c2 = sqrt(max(f.cos2Sq, 0.0));  // cos2Sq < 0: total internal reflection (selected at the end)
    // outside -> film
    float r0 = (f.n2 - f.n1) / (f.n2 + f.n1);
    f.R12 = pbr_F_Schlick(r0 * r0, f.c1);
    f.T121 = 1.0 - f.R12;
    float opd = 2.0 * f.n2 * thicknessNm * f.c2;
    f.xyz1 = pbr_iridescence_sensitivity_xyz(opd);
    f.S2 = pbr_iridescence_xyz_to_rec709(pbr_iridescence_sensitivity_xyz(2.0 * opd));
    return f;
}

// One channel's Airy sum, F = R12 + Rs + C1 2 S1 + C2 2 S2, from the base's IOR eta3 and the
// channel's S of each order. Per channel, so that a channel's terms die before the next one's.
float pbr_iridescence_airy_channel(pbr_ThinFilm f, float eta3, float S1, float S2) {
    // film -> base
    float r1 = (eta3 - f.n2) / (eta3 + f.n2);
    float R23 = pbr_F_Schlick(r1 * r1, f.c2);
    float R123 = clamp(f.R12 * R23, PBR_IRIDESCENCE_MIN_R123, PBR_IRIDESCENCE_MAX_R123);
    float r123 = sqrt(R123);
    float Rs = (f.T121 * f.T121) * R23 / (1.0 - R123);
    float C1 = (Rs - f.T121) * r123;
    float C2 = C1 * r123;
    return f.R12 + Rs + C1 * (2.0 * S1) + C2 * (2.0 * S2);
}

// The Airy sum of baseF0 under the film, before the special cases (pbr_iridescence_select):
// the base's IOR and phase signs, its first order's S from the film's shared XYZ terms, then
// each channel's sum.
float3 pbr_iridescence_airy(pbr_ThinFilm f, float3 baseF0) {
    // base IOR from F0 per channel
    float3 f0 = clamp(baseF0, 0.0, PBR_IRIDESCENCE_MAX_BASE_F0);
    float3 eta3 = float3(pbr_ior_from_f0(f0.x), pbr_ior_from_f0(f0.y), pbr_ior_from_f0(f0.z));
    // phases: φ21 = π − φ12 (φ12 = π if n2 < n1), φ23 = π if eta3 < n2; φ = φ21 + φ23 and
    // cos φ = −1 where exactly one of them is π
    bool pi21 = !(f.n2 < f.n1);
    float3 cosPhi = float3((eta3.x < f.n2) != pi21 ? -1.0 : 1.0, (eta3.y < f.n2) != pi21 ? -1.0 : 1.0,
                       (eta3.z < f.n2) != pi21 ? -1.0 : 1.0);
    float3 S1 = pbr_iridescence_xyz_to_rec709(cosPhi * f.xyz1);
    // Airy series: DC term and the first two orders
    return float3(pbr_iridescence_airy_channel(f, eta3.x, S1.x, f.S2.x),
                pbr_iridescence_airy_channel(f, eta3.y, S1.y, f.S2.y),
                pbr_iridescence_airy_channel(f, eta3.z, S1.z, f.S2.z));
}

// The film's special cases around an Airy sum I: total internal reflection at the film's top
// (F = 1), no film (thickness <= 0 or NaN: the base's Schlick Fresnel, decided), else I
// saturated.
float3 pbr_iridescence_select(pbr_ThinFilm f, float3 baseF0, float3 I) {
    float3 F = f.cos2Sq < 0.0 ? ((float3)(1.0)) : pbr_saturate(I);  // total internal reflection at the film's top
    float3 noFilm = pbr_F_Schlick(baseF0, f.c1);  // formed here: a call inside ?: is a branch
    return f.thicknessNm > 0.0 ? F : noFilm;  // d <= 0 or NaN: no film (decided)
}

// pbr_F_Iridescence of baseF0 under a film pbr_thin_film evaluated: bases under one film (a
// base's F0 and its coat's) share one pbr_thin_film, bit for bit the values of separate calls.
float3 pbr_F_Iridescence_thin_film(pbr_ThinFilm f, float3 baseF0) {
    return pbr_iridescence_select(f, baseF0, pbr_iridescence_airy(f, baseF0));
}

float3 pbr_F_Iridescence(float outsideIor, float filmIor, float cosTheta1, float thicknessNm, float3 baseF0) {
    // Branch-free (both special cases select at the end): a program that inlines this
    // function in more than one place (the environment's lighting call and each light's, which
    // see the same NdotV) can then share one evaluation; with early returns each call kept its
    // own copy (benchmarks/whole_program_cost.py, iridescence with one light and an
    // environment: 1332 -> 836 RDNA3 instructions; the no-film Schlick formed before the select
    // instead of inside it, where glslang made the ?: a branch: 836 -> 806). The selected values
    // are the same. The phase shift as a sign and the Airy sum per channel: 806 -> 738, and
    // with the coat's film from the same pbr_ThinFilm 60 -> 48 VGPRs (docs/bench.md).
    return pbr_F_Iridescence_thin_film(pbr_thin_film(outsideIor, filmIor, cosTheta1, thicknessNm), baseF0);
}

// KHR_materials_iridescence, "Implementation Notes": F = mix(F_schlick, F_iridescence,
// iridescence), iridescence = iridescenceFactor · texture.r (saturated: the schema's range).
float3 pbr_iridescence_mix(float3 F, float3 Firidescence, float iridescenceFactor) {
    return lerp(F, Firidescence, pbr_saturate(iridescenceFactor));
}

// KHR_materials_iridescence, "Properties": thickness = mix(min, max, texture.g); min MAY
// exceed max; without a texture g = 1 (the maximum). g saturated (a UNORM texel).
float pbr_iridescence_thickness(float thicknessMin, float thicknessMax, float textureG) {
    return lerp(thicknessMin, thicknessMax, pbr_saturate(textureG));
}

#endif // PBR_BRDF_F_IRIDESCENCE_HLSL
