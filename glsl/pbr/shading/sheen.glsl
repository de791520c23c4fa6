// pbr/shading/sheen.glsl: the sheen layer of KHR_materials_sheen: the lobe, its directional
// albedo (table or fit) and the albedo scaling of the base beneath it.
//
// Provides: float pbr_sheen_alpha(float sheenPerceptualRoughness)
//           float pbr_sheen_V(float NdotL, float NdotV, float alpha)      (PBR_SHEEN_V dispatch)
//           vec3 pbr_sheen_lobe(float NdotL, float NdotV, float NdotH, vec3 sheenColor,
//                               float sheenPerceptualRoughness)
//           vec2 pbr_sheen_lut_uv(float NdotV, float sheenPerceptualRoughness)
//           PBR_SHEEN_LUT_WIDTH, PBR_SHEEN_LUT_HEIGHT and the table's axis constants
//           float pbr_sheen_albedo_approx(float NdotV, float sheenPerceptualRoughness)
//           float pbr_sheen_albedo(float NdotV, float sheenPerceptualRoughness)
//           float pbr_sheen_albedo_scaling(vec3 sheenColor, float E)
//           float pbr_sheen_albedo_scaling_punctual(vec3 sheenColor, float NdotV, float NdotL,
//                                                   float sheenPerceptualRoughness)
// Include:  "pbr/shading/sheen.glsl" (path relative to glsl/)
// Config macros read: PBR_SHEEN_V = PBR_SHEEN_V_CHARLIE (1, default: Estevez & Kulla's
//           visibility, KHR's reference) or PBR_SHEEN_V_NEUBELT (2: Ashikhmin's, cheaper);
//           other values are a compile error. PBR_SHEEN_LUT_LOOKUP(NdotV, sheenPerceptualRoughness),
//           a hook the caller may define to read its sheen albedo table (it owns the sampler),
//           returning the float E: typically
//             texture(table, pbr_sheen_lut_uv(NdotV, sheenPerceptualRoughness)).r
//           with bilinear filtering and clamp to edge (harness/pbrlab/gpu/sheen_table.py makes the
//           table, data/sheen_albedo_lut.npy, for PBR_SHEEN_V_CHARLIE). Undefined, the analytic
//           fit pbr_sheen_albedo_approx is used.
//
// The layer (KHR_materials_sheen, "Implementation Notes"; Estevez & Kulla 2017 §4):
//   f = sheenColor · D_Charlie · V + f_base · sheen_albedo_scaling,
//   sheen_albedo_scaling = min(1 - max3(sheenColor) E(NdotV), 1 - max3(sheenColor) E(NdotL))
// for a light (pbr_sheen_albedo_scaling_punctual), and 1 - max3(sheenColor) E(NdotV) for the
// environment (pbr_sheen_albedo_scaling(sheenColor, pbr_sheen_albedo(NdotV, r)); KHR's cheaper
// form, allowed for lights too). E is the directional albedo of the white lobe, ∫ D V (n·l) dω.
// Decided: the scaling is clamped to [0, 1]. KHR's fitted Λ masks too little at grazing
// (pbr/brdf/v_charlie.glsl): E exceeds 1 for grazing views of sheens smoother than
// perceptual roughness 0.27 (2.94 at the 0.07 floor, NdotV 1.7e-3), where 1 - E would make the
// base negative; there the white sheen alone reflects more than it receives (measured, pinned
// by tests/library/test_sheen.py), a property of the spec's visibility, not of the table.
// Table: 128 x 128 float32 (64 KiB), texel (i, j) exact at x = i/127, y = j/127 of
//   x = log2(max(NdotV, PBR_MIN_NDOTV) / PBR_MIN_NDOTV) / log2(1 / PBR_MIN_NDOTV)
//   y = log2(max(r, PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS) / PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS)
//       / log2(1 / PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS),
// both clamped to [0, 1] (E is constant below both floors: V and D clamp there). A log axis
// in NdotV resolves E's grazing peak (width ~1e-3); measured bilinear error through this
// lookup against a much finer independent quadrature: tests/library/test_sheen.py.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_SHADING_SHEEN_GLSL
#define PBR_SHADING_SHEEN_GLSL

#include "pbr/common/math.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/brdf/d_charlie.glsl"
#include "pbr/brdf/v_charlie.glsl"

#define PBR_SHEEN_V_CHARLIE 1
#define PBR_SHEEN_V_NEUBELT 2
#ifndef PBR_SHEEN_V
// PBR_SHEEN_V_CHARLIE as a number (glsl/README.md, one-level preprocessors)
#define PBR_SHEEN_V 1
#endif

// alpha_g = sheenRoughness² (KHR), perceptual roughness clamped to [the floor, 1].
float pbr_sheen_alpha(float sheenPerceptualRoughness) {
    float r = clamp(sheenPerceptualRoughness, PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS, 1.0);
    return r * r;
}

float pbr_sheen_V(float NdotL, float NdotV, float alpha) {
#if PBR_SHEEN_V == PBR_SHEEN_V_CHARLIE
    return pbr_V_Charlie(NdotL, NdotV, alpha);
#elif PBR_SHEEN_V == PBR_SHEEN_V_NEUBELT
    return pbr_V_Neubelt(NdotL, NdotV);
#else
#error PBR_SHEEN_V: unknown value
#endif
}

// The sheen BRDF in 1/sr (no cosine, no Fresnel: KHR's sheen has none); 0 for NdotL <= 0
// (or NaN). NdotH from h = normalize(l + v).
vec3 pbr_sheen_lobe(float NdotL, float NdotV, float NdotH, vec3 sheenColor, float sheenPerceptualRoughness) {
    if (!(NdotL > 0.0)) {
        return vec3(0.0);
    }
    float alpha = pbr_sheen_alpha(sheenPerceptualRoughness);
    return sheenColor * (pbr_D_Charlie(NdotH, alpha) * pbr_sheen_V(NdotL, NdotV, alpha));
}

// The table's layout (harness/pbrlab/gpu/sheen_table.py writes it; shared constants tested equal).
#define PBR_SHEEN_LUT_WIDTH 128.0
#define PBR_SHEEN_LUT_HEIGHT 128.0
#define PBR_SHEEN_LUT_NDOTV_LOG_NORM 0.0752574989      // 1 / log2(1 / PBR_MIN_NDOTV)
#define PBR_SHEEN_LUT_ROUGHNESS_LOG_NORM 0.260654156   // 1 / log2(1 / PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS)

vec2 pbr_sheen_lut_uv(float NdotV, float sheenPerceptualRoughness) {
    float x = log2(clamp(NdotV, PBR_MIN_NDOTV, 1.0)) * PBR_SHEEN_LUT_NDOTV_LOG_NORM + 1.0;
    float y = log2(clamp(sheenPerceptualRoughness, PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS, 1.0))
            * PBR_SHEEN_LUT_ROUGHNESS_LOG_NORM + 1.0;
    vec2 size = vec2(PBR_SHEEN_LUT_WIDTH, PBR_SHEEN_LUT_HEIGHT);
    return (clamp(vec2(x, y), 0.0, 1.0) * (size - 1.0) + 0.5) / size;
}

// Analytic fallback (when PBR_SHEEN_LUT_LOOKUP is undefined): a least-squares fit of the
// shipped table (Charlie visibility) on its own axes x, y (above),
//   E ≈ exp(sum_i x^i (C_i · (1, y, y², y³))) - 0.001,   i = 0..3,
// fitted by Gauss-Newton on the absolute error over the 128 x 128 texels (harness/pbrlab/
// sheen_table.py fit_sheen_albedo_approx). Worst absolute error 0.16, rms 0.041 (E spans
// 0 .. 2.94): good for previews and tiers without a texture unit, not a substitute for the
// table. Shared with harness/pbrlab/maths/reference/sheen.py SHEEN_ALBEDO_APPROX (tested equal).
#define PBR_SHEEN_ALBEDO_APPROX_C0 vec4(1.035856, -2.405441, -0.8081028, 2.034246)
#define PBR_SHEEN_ALBEDO_APPROX_C1 vec4(-1.120514, -0.4725056, 2.033727, -0.8119602)
#define PBR_SHEEN_ALBEDO_APPROX_C2 vec4(8.214515, -0.7163682, -6.965961, 3.255338)
#define PBR_SHEEN_ALBEDO_APPROX_C3 vec4(-12.93151, 8.414441, 3.456867, -3.622073)
#define PBR_SHEEN_ALBEDO_APPROX_OFFSET 0.001

float pbr_sheen_albedo_approx(float NdotV, float sheenPerceptualRoughness) {
    float x = clamp(log2(clamp(NdotV, PBR_MIN_NDOTV, 1.0)) * PBR_SHEEN_LUT_NDOTV_LOG_NORM + 1.0, 0.0, 1.0);
    float y = clamp(log2(clamp(sheenPerceptualRoughness, PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS, 1.0))
                    * PBR_SHEEN_LUT_ROUGHNESS_LOG_NORM + 1.0, 0.0, 1.0);
    vec4 ys = vec4(1.0, y, y * y, y * y * y);
    float p = ((dot(PBR_SHEEN_ALBEDO_APPROX_C3, ys) * x + dot(PBR_SHEEN_ALBEDO_APPROX_C2, ys)) * x
               + dot(PBR_SHEEN_ALBEDO_APPROX_C1, ys)) * x + dot(PBR_SHEEN_ALBEDO_APPROX_C0, ys);
    return max(exp(p) - PBR_SHEEN_ALBEDO_APPROX_OFFSET, 0.0);
}

float pbr_sheen_albedo(float NdotV, float sheenPerceptualRoughness) {
#if defined(PBR_SHEEN_LUT_LOOKUP)
    return PBR_SHEEN_LUT_LOOKUP(NdotV, sheenPerceptualRoughness);
#else
    return pbr_sheen_albedo_approx(NdotV, sheenPerceptualRoughness);
#endif
}

// KHR_materials_sheen's albedo scaling of the base, 1 - max3(sheenColor) E, clamped to [0, 1]
// (decided, see the header: E > 1 at grazing for smooth sheens).
float pbr_sheen_albedo_scaling(vec3 sheenColor, float E) {
    return pbr_saturate(1.0 - pbr_max3(sheenColor) * E);
}

// For a punctual light, as KHR defines it: the smaller of the scalings at the view and at the
// light, min(1 - max3(c) E(NdotV), 1 - max3(c) E(NdotL)) (two table reads).
float pbr_sheen_albedo_scaling_punctual(vec3 sheenColor, float NdotV, float NdotL, float sheenPerceptualRoughness) {
    return min(pbr_sheen_albedo_scaling(sheenColor, pbr_sheen_albedo(NdotV, sheenPerceptualRoughness)),
               pbr_sheen_albedo_scaling(sheenColor, pbr_sheen_albedo(NdotL, sheenPerceptualRoughness)));
}

#endif // PBR_SHADING_SHEEN_GLSL
