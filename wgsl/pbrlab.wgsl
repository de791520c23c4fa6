// pbrlab.wgsl: the pbrlab shading library (glsl/pbr/pbr.glsl, every public file) in WGSL, for
// WebGPU: wgpu, Bevy, browsers. Paste it above your own WGSL or load it as a module source.
// Generated from glsl/ by harness/pbrlab/gpu/port_wgsl.py with naga 30.0.1 (the translator of wgpu):
// do not edit; edit the GLSL, then run python -m pbrlab.gpu.port_wgsl. docs/wgsl.md explains it.
//
// One configuration (WGSL has no preprocessor): every selector at its default (glsl/README.md),
// no hooks, so the environment BRDF is the analytic fit (pbr_env_brdf_approx), not the DFG table.
// Names: the library's (glsl/README.md), except where naga changed them: an overload gets _1, _2
// in declaration order; a name ending in a digit gets a trailing _ (functions, parameters and
// struct members alike: pbr_PreparedSurface.f0_ and .f90_); parameters and locals get numeric
// suffixes where names repeat. The library's #define constants are inlined as numbers.
// Renamed functions (WGSL name and parameter types <- GLSL name):
//   pbr_saturate_1(vec3<f32>) -> vec3<f32>   <- GLSL pbr_saturate (overload)
//   pbr_pow5_(f32) -> f32   <- GLSL pbr_pow5 (ends in a digit)
//   pbr_max3_(vec3<f32>) -> f32   <- GLSL pbr_max3 (ends in a digit)
//   pbr_min3_(vec3<f32>) -> f32   <- GLSL pbr_min3 (ends in a digit)
//   pbr_sanitize_1(vec3<f32>, f32) -> vec3<f32>   <- GLSL pbr_sanitize (overload)
//   pbr_one_minus_dot2_(vec3<f32>, vec3<f32>) -> f32   <- GLSL pbr_one_minus_dot2 (ends in a digit)
//   pbr_srgb_to_linear_1(vec3<f32>) -> vec3<f32>   <- GLSL pbr_srgb_to_linear (overload)
//   pbr_linear_to_srgb_1(vec3<f32>) -> vec3<f32>   <- GLSL pbr_linear_to_srgb (overload)
//   pbr_ior_from_f0_(f32) -> f32   <- GLSL pbr_ior_from_f0 (ends in a digit)
//   pbr_D_GGX_fromOneMinusNdotH2_(f32, f32, f32) -> f32   <- GLSL pbr_D_GGX_fromOneMinusNdotH2 (ends in a digit)
//   pbr_D_GGX_1(vec3<f32>, vec3<f32>, f32) -> f32   <- GLSL pbr_D_GGX (overload)
//   pbr_D_Beckmann_fromOneMinusNdotH2_(f32, f32, f32) -> f32   <- GLSL pbr_D_Beckmann_fromOneMinusNdotH2 (ends in a digit)
//   pbr_F_Schlick_1(vec3<f32>, f32) -> vec3<f32>   <- GLSL pbr_F_Schlick (overload)
//   pbr_F_Schlick_2(vec3<f32>, f32, f32) -> vec3<f32>   <- GLSL pbr_F_Schlick (overload)
//   pbr_F_SchlickSG_1(vec3<f32>, f32, f32) -> vec3<f32>   <- GLSL pbr_F_SchlickSG (overload)
//   pbr_f90_from_f0_(vec3<f32>) -> f32   <- GLSL pbr_f90_from_f0 (ends in a digit)
//   pbr_iridescence_xyz_to_rec709_(vec3<f32>) -> vec3<f32>   <- GLSL pbr_iridescence_xyz_to_rec709 (ends in a digit)
//   pbr_specular_F_f90_(vec3<f32>, f32, f32) -> vec3<f32>   <- GLSL pbr_specular_F_f90 (ends in a digit)
//   pbr_specular_F_deviation_bound_f90_(vec3<f32>, f32) -> vec3<f32>   <- GLSL pbr_specular_F_deviation_bound_f90 (ends in a digit)
//   pbr_brdf_standard_f90_(vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, f32, f32) -> vec3<f32>   <- GLSL pbr_brdf_standard_f90 (ends in a digit)
//   pbr_shade_punctual_f90_(vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, f32, f32) -> vec3<f32>   <- GLSL pbr_shade_punctual_f90 (ends in a digit)
//   pbr_specular_albedo_f90_(vec3<f32>, f32, vec2<f32>) -> vec3<f32>   <- GLSL pbr_specular_albedo_f90 (ends in a digit)
//   pbr_specular_albedo_bound_f90_(vec3<f32>, f32, vec2<f32>) -> vec3<f32>   <- GLSL pbr_specular_albedo_bound_f90 (ends in a digit)
//   pbr_brdf_anisotropic_specular_f90_(vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, vec3<f32>, f32, f32, f32) -> vec3<f32>   <- GLSL pbr_brdf_anisotropic_specular_f90 (ends in a digit)
//   pbr_indirect_specular_albedo_f90_(vec3<f32>, f32, vec2<f32>) -> vec3<f32>   <- GLSL pbr_indirect_specular_albedo_f90 (ends in a digit)
//   pbr_indirect_specular_split_sum_f90_(vec3<f32>, vec3<f32>, f32, f32, f32, f32, vec2<f32>) -> vec3<f32>   <- GLSL pbr_indirect_specular_split_sum_f90 (ends in a digit)
//   pbr_indirect_diffuse_color_f90_(vec3<f32>, vec3<f32>, f32, vec2<f32>) -> vec3<f32>   <- GLSL pbr_indirect_diffuse_color_f90 (ends in a digit)
//   pbr_prepare_surface_f90_(vec3<f32>, vec3<f32>, f32, vec3<f32>, f32, f32, f32, vec3<f32>, vec3<f32>) -> pbr_PreparedSurface   <- GLSL pbr_prepare_surface_f90 (ends in a digit)
//   pbr_lighting_standard_f90_(vec3<f32>, vec3<f32>, f32, vec3<f32>, f32, f32, f32, vec3<f32>, vec3<f32>, pbr_GI) -> vec3<f32>   <- GLSL pbr_lighting_standard_f90 (ends in a digit)
//   pbr_lighting_anisotropic_f90_(vec3<f32>, vec3<f32>, f32, vec3<f32>, f32, f32, f32, vec3<f32>, vec3<f32>, pbr_GI, pbr_Anisotropy) -> vec3<f32>   <- GLSL pbr_lighting_anisotropic_f90 (ends in a digit)
//   pbr_iridescent_f0_(vec3<f32>, f32, pbr_Iridescence) -> vec3<f32>   <- GLSL pbr_iridescent_f0 (ends in a digit)
//   pbr_iridescent_f0_f90_(vec3<f32>, f32, f32, pbr_Iridescence) -> vec3<f32>   <- GLSL pbr_iridescent_f0_f90 (ends in a digit)
//   pbr_lighting_transmission_f90_(vec3<f32>, vec3<f32>, f32, f32, f32, vec3<f32>, vec3<f32>, pbr_GI, vec3<f32>, pbr_Transmission) -> vec3<f32>   <- GLSL pbr_lighting_transmission_f90 (ends in a digit)
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
struct pbr_ThinFilm {
    n1_: f32,
    n2_: f32,
    c1_: f32,
    cos2Sq: f32,
    c2_: f32,
    R12_: f32,
    T121_: f32,
    thicknessNm: f32,
    xyz1_: vec3<f32>,
    S2_: vec3<f32>,
}

struct pbr_Light {
    color: vec3<f32>,
    dir: vec3<f32>,
}

struct pbr_Indirect {
    diffuse: vec3<f32>,
    specular: vec3<f32>,
}

struct pbr_GI {
    light: pbr_Light,
    indirect: pbr_Indirect,
}

struct pbr_PreparedSurface {
    n: vec3<f32>,
    v: vec3<f32>,
    f0_: vec3<f32>,
    f90_: f32,
    perceptualRoughness: f32,
    occlusion: f32,
    directDiffuseColor: vec3<f32>,
    indirectDiffuseColor: vec3<f32>,
    indirectSpecularAlbedo: vec3<f32>,
    specularOcclusion: f32,
}

struct pbr_ClearCoat {
    mask: f32,
    perceptualRoughness: f32,
    normal: vec3<f32>,
}

struct pbr_Sheen {
    color: vec3<f32>,
    perceptualRoughness: f32,
}

struct pbr_Anisotropy {
    strength: f32,
    direction: vec3<f32>,
}

struct pbr_AnisotropicFrame {
    t: vec3<f32>,
    b: vec3<f32>,
    strength: f32,
}

struct pbr_Iridescence {
    factor: f32,
    ior: f32,
    thicknessNm: f32,
}

struct pbr_IridescentF0_ {
    f0_: vec3<f32>,
    coatF0_: vec3<f32>,
}

struct pbr_Transmission {
    factor: f32,
    thickness: f32,
    attenuationColor: vec3<f32>,
    attenuationDistance: f32,
    ior: f32,
}

struct pbr_PreparedTransmission {
    s: pbr_PreparedSurface,
    rho: vec3<f32>,
    weight: vec3<f32>,
    volume: bool,
    ior: f32,
}

fn pbr_saturate(x: f32) -> f32 {
    var x_1: f32;

    x_1 = x;
    let _e2 = x_1;
    return clamp(_e2, 0f, 1f);
}

fn pbr_saturate_1(x_2: vec3<f32>) -> vec3<f32> {
    var x_3: vec3<f32>;

    x_3 = x_2;
    let _e2 = x_3;
    return clamp(_e2, vec3(0f), vec3(1f));
}

fn pbr_sq(x_4: f32) -> f32 {
    var x_5: f32;

    x_5 = x_4;
    let _e2 = x_5;
    let _e3 = x_5;
    return (_e2 * _e3);
}

fn pbr_pow5_(x_6: f32) -> f32 {
    var x_7: f32;
    var x2_: f32;

    x_7 = x_6;
    let _e2 = x_7;
    let _e3 = x_7;
    x2_ = (_e2 * _e3);
    let _e6 = x2_;
    let _e7 = x2_;
    let _e9 = x_7;
    return ((_e6 * _e7) * _e9);
}

fn pbr_max3_(v: vec3<f32>) -> f32 {
    var v_1: vec3<f32>;

    v_1 = v;
    let _e2 = v_1;
    let _e4 = v_1;
    let _e6 = v_1;
    return max(_e2.x, max(_e4.y, _e6.z));
}

fn pbr_min3_(v_2: vec3<f32>) -> f32 {
    var v_3: vec3<f32>;

    v_3 = v_2;
    let _e2 = v_3;
    let _e4 = v_3;
    let _e6 = v_3;
    return min(_e2.x, min(_e4.y, _e6.z));
}

fn pbr_pow_safe(x_8: f32, s: f32) -> f32 {
    var x_9: f32;
    var s_1: f32;
    var p: f32;
    var local: f32;
    var local_1: f32;

    x_9 = x_8;
    s_1 = s;
    let _e4 = s_1;
    s_1 = max(_e4, 0f);
    let _e7 = x_9;
    let _e10 = s_1;
    p = pow(max(_e7, 0.000000000000000000000000000000000000011754944f), _e10);
    let _e13 = x_9;
    if (_e13 > 0f) {
        let _e16 = p;
        local_1 = _e16;
    } else {
        let _e17 = s_1;
        if (_e17 > 0f) {
            local = 0f;
        } else {
            local = 1f;
        }
        let _e23 = local;
        local_1 = _e23;
    }
    let _e25 = local_1;
    return _e25;
}

fn pbr_sanitize(x_10: f32, hi: f32) -> f32 {
    var x_11: f32;
    var hi_1: f32;
    var local_2: f32;

    x_11 = x_10;
    hi_1 = hi;
    let _e4 = x_11;
    if (_e4 > 0f) {
        let _e7 = x_11;
        local_2 = _e7;
    } else {
        local_2 = 0f;
    }
    let _e10 = local_2;
    let _e11 = hi_1;
    return min(_e10, _e11);
}

fn pbr_sanitize_1(x_12: vec3<f32>, hi_2: f32) -> vec3<f32> {
    var x_13: vec3<f32>;
    var hi_3: f32;

    x_13 = x_12;
    hi_3 = hi_2;
    let _e4 = x_13;
    let _e6 = hi_3;
    let _e7 = pbr_sanitize(_e4.x, _e6);
    let _e8 = x_13;
    let _e10 = hi_3;
    let _e11 = pbr_sanitize(_e8.y, _e10);
    let _e12 = x_13;
    let _e14 = hi_3;
    let _e15 = pbr_sanitize(_e12.z, _e14);
    return vec3<f32>(_e7, _e11, _e15);
}

fn pbr_safe_normalize(v_4: vec3<f32>) -> vec3<f32> {
    var v_5: vec3<f32>;
    var m: f32;
    var local_3: f32;
    var k: f32;
    var s_2: vec3<f32>;
    var unit: vec3<f32>;
    var local_4: vec3<f32>;

    v_5 = v_4;
    let _e2 = v_5;
    let _e4 = pbr_max3_(abs(_e2));
    m = _e4;
    let _e6 = m;
    if (_e6 > 42535296000000000000000000000000000000f) {
        local_3 = 0.0625f;
    } else {
        local_3 = 1f;
    }
    let _e12 = local_3;
    k = _e12;
    let _e14 = v_5;
    let _e15 = k;
    let _e17 = m;
    let _e18 = k;
    s_2 = ((_e14 * _e15) / vec3((_e17 * _e18)));
    let _e23 = s_2;
    let _e24 = s_2;
    let _e25 = s_2;
    unit = (_e23 * inverseSqrt(dot(_e24, _e25)));
    let _e30 = m;
    if (_e30 >= 0.000000000000000000000000000000000000011754944f) {
        let _e33 = unit;
        local_4 = _e33;
    } else {
        local_4 = vec3(0f);
    }
    let _e37 = local_4;
    return _e37;
}

fn pbr_one_minus_dot2_(a: vec3<f32>, b: vec3<f32>) -> f32 {
    var a_1: vec3<f32>;
    var b_1: vec3<f32>;
    var c: vec3<f32>;
    var local_5: f32;

    a_1 = a;
    b_1 = b;
    let _e4 = a_1;
    let _e5 = b_1;
    c = cross(_e4, _e5);
    let _e8 = a_1;
    let _e9 = b_1;
    if (dot(_e8, _e9) > 0f) {
        let _e13 = c;
        let _e14 = c;
        local_5 = dot(_e13, _e14);
    } else {
        local_5 = 1f;
    }
    let _e18 = local_5;
    return _e18;
}

fn pbr_length2_nonzero(x_14: vec3<f32>) -> f32 {
    var x_15: vec3<f32>;

    x_15 = x_14;
    let _e2 = x_15;
    let _e4 = x_15;
    let _e7 = x_15;
    let _e9 = x_15;
    let _e12 = x_15;
    let _e14 = x_15;
    return ((_e2.x * _e4.x) + ((_e7.y * _e9.y) + ((_e12.z * _e14.z) + 0.000000000000000000000000000000000000011754944f)));
}

fn pbr_srgb_to_linear(c_1: f32) -> f32 {
    var c_2: f32;
    var local_6: f32;

    c_2 = c_1;
    let _e2 = c_2;
    let _e4 = pbr_sanitize(_e2, 1f);
    c_2 = _e4;
    let _e5 = c_2;
    if (_e5 <= 0.04045f) {
        let _e8 = c_2;
        local_6 = (_e8 / 12.92f);
    } else {
        let _e11 = c_2;
        local_6 = pow(((_e11 + 0.055f) / 1.055f), 2.4f);
    }
    let _e21 = local_6;
    return _e21;
}

fn pbr_srgb_to_linear_1(c_3: vec3<f32>) -> vec3<f32> {
    var c_4: vec3<f32>;

    c_4 = c_3;
    let _e2 = c_4;
    let _e4 = pbr_srgb_to_linear(_e2.x);
    let _e5 = c_4;
    let _e7 = pbr_srgb_to_linear(_e5.y);
    let _e8 = c_4;
    let _e10 = pbr_srgb_to_linear(_e8.z);
    return vec3<f32>(_e4, _e7, _e10);
}

fn pbr_linear_to_srgb(c_5: f32) -> f32 {
    var c_6: f32;
    var local_7: f32;

    c_6 = c_5;
    let _e2 = c_6;
    let _e4 = pbr_sanitize(_e2, 1f);
    c_6 = _e4;
    let _e5 = c_6;
    if (_e5 <= 0.0031308f) {
        let _e8 = c_6;
        local_7 = (_e8 * 12.92f);
    } else {
        let _e14 = c_6;
        local_7 = ((1.055f * pow(_e14, 0.41666666f)) - 0.055f);
    }
    let _e23 = local_7;
    return _e23;
}

fn pbr_linear_to_srgb_1(c_7: vec3<f32>) -> vec3<f32> {
    var c_8: vec3<f32>;

    c_8 = c_7;
    let _e2 = c_8;
    let _e4 = pbr_linear_to_srgb(_e2.x);
    let _e5 = c_8;
    let _e7 = pbr_linear_to_srgb(_e5.y);
    let _e8 = c_8;
    let _e10 = pbr_linear_to_srgb(_e8.z);
    return vec3<f32>(_e4, _e7, _e10);
}

fn pbr_degamma(c_9: vec3<f32>) -> vec3<f32> {
    var c_10: vec3<f32>;

    c_10 = c_9;
    let _e2 = c_10;
    let _e4 = pbr_sanitize_1(_e2, 1f);
    return pow(_e4, vec3(2.2f));
}

fn pbr_regamma(c_11: vec3<f32>) -> vec3<f32> {
    var c_12: vec3<f32>;

    c_12 = c_11;
    let _e2 = c_12;
    let _e4 = pbr_sanitize_1(_e2, 1f);
    return pow(_e4, vec3(0.45454547f));
}

fn pbr_degamma_fast(c_13: vec3<f32>) -> vec3<f32> {
    var c_14: vec3<f32>;

    c_14 = c_13;
    let _e2 = c_14;
    let _e4 = pbr_sanitize_1(_e2, 1f);
    c_14 = _e4;
    let _e5 = c_14;
    let _e6 = c_14;
    return (_e5 * _e6);
}

fn pbr_regamma_fast(c_15: vec3<f32>) -> vec3<f32> {
    var c_16: vec3<f32>;

    c_16 = c_15;
    let _e2 = c_16;
    let _e4 = pbr_sanitize_1(_e2, 1f);
    return sqrt(_e4);
}

fn pbr_luminance(linearColor: vec3<f32>) -> f32 {
    var linearColor_1: vec3<f32>;

    linearColor_1 = linearColor;
    let _e2 = linearColor_1;
    return dot(_e2, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn pbr_decode_color_texel(texel: vec3<f32>) -> vec3<f32> {
    var texel_1: vec3<f32>;

    texel_1 = texel;
    let _e2 = texel_1;
    return _e2;
}

fn pbr_encode_final_color(linearColor_2: vec3<f32>) -> vec3<f32> {
    var linearColor_3: vec3<f32>;

    linearColor_3 = linearColor_2;
    let _e2 = linearColor_3;
    let _e4 = pbr_sanitize_1(_e2, 1f);
    return _e4;
}

fn pbr_perceptual_roughness_from_smoothness(smoothness: f32) -> f32 {
    var smoothness_1: f32;

    smoothness_1 = smoothness;
    let _e3 = smoothness_1;
    return (1f - _e3);
}

fn pbr_alpha_from_perceptual_roughness(perceptualRoughness: f32) -> f32 {
    var perceptualRoughness_1: f32;

    perceptualRoughness_1 = perceptualRoughness;
    let _e2 = perceptualRoughness_1;
    let _e3 = perceptualRoughness_1;
    return (_e2 * _e3);
}

fn pbr_perceptual_roughness_from_alpha(alpha: f32) -> f32 {
    var alpha_1: f32;

    alpha_1 = alpha;
    let _e2 = alpha_1;
    return sqrt(max(_e2, 0f));
}

fn pbr_alpha_from_smoothness(smoothness_2: f32) -> f32 {
    var smoothness_3: f32;

    smoothness_3 = smoothness_2;
    let _e2 = smoothness_3;
    let _e3 = pbr_perceptual_roughness_from_smoothness(_e2);
    let _e4 = pbr_alpha_from_perceptual_roughness(_e3);
    return _e4;
}

fn pbr_specPower_from_gloss_CallOfDuty(gloss: f32) -> f32 {
    var gloss_1: f32;

    gloss_1 = gloss;
    let _e3 = gloss_1;
    return exp2((13f * _e3));
}

fn pbr_alpha_from_gloss_Crytek(gloss_2: f32) -> f32 {
    var gloss_3: f32;
    var r: f32;

    gloss_3 = gloss_2;
    let _e4 = gloss_3;
    r = (1f - (0.7f * _e4));
    let _e8 = r;
    let _e9 = r;
    return (_e8 * _e9);
}

fn pbr_alpha_from_gloss_Unreal(gloss_4: f32) -> f32 {
    var gloss_5: f32;
    var r_1: f32;

    gloss_5 = gloss_4;
    let _e3 = gloss_5;
    r_1 = (1f - _e3);
    let _e6 = r_1;
    let _e7 = r_1;
    return (_e6 * _e7);
}

fn pbr_specPower_from_alpha(alpha_2: f32) -> f32 {
    var alpha_3: f32;

    alpha_3 = alpha_2;
    let _e2 = alpha_3;
    alpha_3 = clamp(_e2, 0.0000001f, 1f);
    let _e7 = alpha_3;
    let _e8 = alpha_3;
    return ((2f / (_e7 * _e8)) - 2f);
}

fn pbr_alpha_from_specPower(specPower: f32) -> f32 {
    var specPower_1: f32;

    specPower_1 = specPower;
    let _e3 = specPower_1;
    return sqrt((2f / (max(_e3, 0f) + 2f)));
}

fn pbr_f0_from_metallic_dielectric(albedo: vec3<f32>, metallic: f32, dielectricF0_: vec3<f32>) -> vec3<f32> {
    var albedo_1: vec3<f32>;
    var metallic_1: f32;
    var dielectricF0_1: vec3<f32>;

    albedo_1 = albedo;
    metallic_1 = metallic;
    dielectricF0_1 = dielectricF0_;
    let _e6 = dielectricF0_1;
    let _e7 = albedo_1;
    let _e8 = metallic_1;
    return mix(_e6, _e7, vec3(_e8));
}

fn pbr_diffuse_from_metallic_dielectric(albedo_2: vec3<f32>, metallic_2: f32, dielectricF0_2: vec3<f32>) -> vec3<f32> {
    var albedo_3: vec3<f32>;
    var metallic_3: f32;
    var dielectricF0_3: vec3<f32>;

    albedo_3 = albedo_2;
    metallic_3 = metallic_2;
    dielectricF0_3 = dielectricF0_2;
    let _e6 = albedo_3;
    let _e8 = dielectricF0_3;
    let _e9 = pbr_max3_(_e8);
    let _e12 = metallic_3;
    return (_e6 * ((1f - _e9) * (1f - _e12)));
}

fn pbr_f90_from_metallic(dielectricF90_: f32, metallic_4: f32) -> f32 {
    var dielectricF90_1: f32;
    var metallic_5: f32;

    dielectricF90_1 = dielectricF90_;
    metallic_5 = metallic_4;
    let _e4 = dielectricF90_1;
    let _e6 = metallic_5;
    return mix(_e4, 1f, _e6);
}

fn pbr_f0_from_metallic(albedo_4: vec3<f32>, metallic_6: f32) -> vec3<f32> {
    var albedo_5: vec3<f32>;
    var metallic_7: f32;

    albedo_5 = albedo_4;
    metallic_7 = metallic_6;
    let _e4 = albedo_5;
    let _e5 = metallic_7;
    let _e8 = pbr_f0_from_metallic_dielectric(_e4, _e5, vec3(0.04f));
    return _e8;
}

fn pbr_diffuse_from_metallic(albedo_6: vec3<f32>, metallic_8: f32) -> vec3<f32> {
    var albedo_7: vec3<f32>;
    var metallic_9: f32;

    albedo_7 = albedo_6;
    metallic_9 = metallic_8;
    let _e4 = albedo_7;
    let _e5 = metallic_9;
    let _e8 = pbr_diffuse_from_metallic_dielectric(_e4, _e5, vec3(0.04f));
    return _e8;
}

fn pbr_diffuse_from_specular(albedo_8: vec3<f32>, specular: vec3<f32>) -> vec3<f32> {
    var albedo_9: vec3<f32>;
    var specular_1: vec3<f32>;

    albedo_9 = albedo_8;
    specular_1 = specular;
    let _e4 = albedo_9;
    let _e6 = specular_1;
    let _e7 = pbr_max3_(_e6);
    return (_e4 * (1f - _e7));
}

fn pbr_diffuse_from_specular_per_channel(albedo_10: vec3<f32>, specular_2: vec3<f32>) -> vec3<f32> {
    var albedo_11: vec3<f32>;
    var specular_3: vec3<f32>;

    albedo_11 = albedo_10;
    specular_3 = specular_2;
    let _e4 = albedo_11;
    let _e7 = specular_3;
    return (_e4 * (vec3(1f) - _e7));
}

fn pbr_f0_from_ior(eta: f32) -> f32 {
    var eta_1: f32;
    var r_2: f32;

    eta_1 = eta;
    let _e2 = eta_1;
    let _e5 = eta_1;
    r_2 = ((_e2 - 1f) / (_e5 + 1f));
    let _e10 = r_2;
    let _e11 = r_2;
    return (_e10 * _e11);
}

fn pbr_ior_from_f0_(f0_: f32) -> f32 {
    var f0_1: f32;
    var s_3: f32;

    f0_1 = f0_;
    let _e2 = f0_1;
    s_3 = sqrt(clamp(_e2, 0f, 1f));
    let _e9 = s_3;
    let _e12 = s_3;
    return min(((1f + _e9) / (1f - _e12)), 33554432f);
}

fn pbr_Fd_Lambert() -> f32 {
    return 0.31830987f;
}

fn pbr_Fd_Burley(NdotV: f32, NdotL: f32, LdotH: f32, perceptualRoughness_2: f32) -> f32 {
    var NdotV_1: f32;
    var NdotL_1: f32;
    var LdotH_1: f32;
    var perceptualRoughness_3: f32;
    var fd90_: f32;
    var lightScatter: f32;
    var viewScatter: f32;

    NdotV_1 = NdotV;
    NdotL_1 = NdotL;
    LdotH_1 = LdotH;
    perceptualRoughness_3 = perceptualRoughness_2;
    let _e8 = LdotH_1;
    let _e9 = pbr_saturate(_e8);
    LdotH_1 = _e9;
    let _e12 = perceptualRoughness_3;
    let _e13 = pbr_saturate(_e12);
    let _e15 = LdotH_1;
    let _e17 = LdotH_1;
    fd90_ = (0.5f + (((2f * _e13) * _e15) * _e17));
    let _e22 = fd90_;
    let _e26 = NdotL_1;
    let _e27 = pbr_saturate(_e26);
    let _e29 = pbr_pow5_((1f - _e27));
    lightScatter = (1f + ((_e22 - 1f) * _e29));
    let _e34 = fd90_;
    let _e38 = NdotV_1;
    let _e39 = pbr_saturate(_e38);
    let _e41 = pbr_pow5_((1f - _e39));
    viewScatter = (1f + ((_e34 - 1f) * _e41));
    let _e45 = lightScatter;
    let _e46 = viewScatter;
    return ((_e45 * _e46) * 0.31830987f);
}

fn pbr_blinn_phong_lobe(NdotH: f32, specPower_2: f32) -> f32 {
    var NdotH_1: f32;
    var specPower_3: f32;

    NdotH_1 = NdotH;
    specPower_3 = specPower_2;
    let _e4 = NdotH_1;
    let _e5 = pbr_saturate(_e4);
    let _e6 = specPower_3;
    let _e9 = pbr_pow_safe(_e5, max(_e6, 0f));
    return _e9;
}

fn pbr_BRDF_BlinnPhongClassic(NdotH_2: f32, NdotL_2: f32, specPower_4: f32) -> f32 {
    var NdotH_3: f32;
    var NdotL_3: f32;
    var specPower_5: f32;
    var local_8: f32;

    NdotH_3 = NdotH_2;
    NdotL_3 = NdotL_2;
    specPower_5 = specPower_4;
    let _e6 = NdotL_3;
    if (_e6 > 0f) {
        let _e10 = NdotH_3;
        let _e11 = specPower_5;
        let _e12 = pbr_blinn_phong_lobe(_e10, _e11);
        let _e14 = NdotL_3;
        local_8 = ((0.31830987f * _e12) / max(_e14, 0.0001f));
    } else {
        local_8 = 0f;
    }
    let _e20 = local_8;
    return _e20;
}

fn pbr_BRDF_BlinnPhongModified(NdotH_4: f32, specPower_6: f32) -> f32 {
    var NdotH_5: f32;
    var specPower_7: f32;

    NdotH_5 = NdotH_4;
    specPower_7 = specPower_6;
    let _e5 = NdotH_5;
    let _e6 = specPower_7;
    let _e7 = pbr_blinn_phong_lobe(_e5, _e6);
    return (0.31830987f * _e7);
}

fn pbr_BRDF_BlinnPhongNormalized(NdotH_6: f32, specPower_8: f32) -> f32 {
    var NdotH_7: f32;
    var specPower_9: f32;

    NdotH_7 = NdotH_6;
    specPower_9 = specPower_8;
    let _e4 = specPower_9;
    let _e13 = NdotH_7;
    let _e14 = specPower_9;
    let _e15 = pbr_blinn_phong_lobe(_e13, _e14);
    return (((max(_e4, 0f) + 8f) / 25.132742f) * _e15);
}

fn pbr_D_BlinnPhong(NdotH_8: f32, specPower_10: f32) -> f32 {
    var NdotH_9: f32;
    var specPower_11: f32;

    NdotH_9 = NdotH_8;
    specPower_11 = specPower_10;
    let _e4 = specPower_11;
    specPower_11 = max(_e4, 0f);
    let _e7 = specPower_11;
    let _e14 = NdotH_9;
    let _e15 = pbr_saturate(_e14);
    let _e16 = specPower_11;
    let _e17 = pbr_pow_safe(_e15, _e16);
    return (((_e7 + 2f) * 0.15915494f) * _e17);
}

fn pbr_D_GGX_fromOneMinusNdotH2_(NdotH_10: f32, oneMinusNdotH2_: f32, alpha_4: f32) -> f32 {
    var NdotH_11: f32;
    var oneMinusNdotH2_1: f32;
    var alpha_5: f32;
    var a_2: f32;
    var k_1: f32;

    NdotH_11 = NdotH_10;
    oneMinusNdotH2_1 = oneMinusNdotH2_;
    alpha_5 = alpha_4;
    let _e6 = alpha_5;
    alpha_5 = clamp(_e6, 0.0000001f, 1f);
    let _e10 = NdotH_11;
    let _e11 = pbr_saturate(_e10);
    let _e12 = alpha_5;
    a_2 = (_e11 * _e12);
    let _e15 = alpha_5;
    let _e16 = oneMinusNdotH2_1;
    let _e17 = a_2;
    let _e18 = a_2;
    let _e21 = alpha_5;
    let _e22 = alpha_5;
    k_1 = (_e15 / max((_e16 + (_e17 * _e18)), (_e21 * _e22)));
    let _e27 = k_1;
    let _e28 = k_1;
    return ((_e27 * _e28) * 0.31830987f);
}

fn pbr_D_GGX(NdotH_12: f32, alpha_6: f32) -> f32 {
    var NdotH_13: f32;
    var alpha_7: f32;

    NdotH_13 = NdotH_12;
    alpha_7 = alpha_6;
    let _e4 = NdotH_13;
    let _e5 = pbr_saturate(_e4);
    NdotH_13 = _e5;
    let _e6 = NdotH_13;
    let _e8 = NdotH_13;
    let _e11 = NdotH_13;
    let _e14 = alpha_7;
    let _e15 = pbr_D_GGX_fromOneMinusNdotH2_(_e6, ((1f - _e8) * (1f + _e11)), _e14);
    return _e15;
}

fn pbr_D_GGX_1(n: vec3<f32>, h: vec3<f32>, alpha_8: f32) -> f32 {
    var n_1: vec3<f32>;
    var h_1: vec3<f32>;
    var alpha_9: f32;

    n_1 = n;
    h_1 = h;
    alpha_9 = alpha_8;
    let _e6 = n_1;
    let _e7 = h_1;
    let _e9 = n_1;
    let _e10 = h_1;
    let _e11 = pbr_one_minus_dot2_(_e9, _e10);
    let _e12 = alpha_9;
    let _e13 = pbr_D_GGX_fromOneMinusNdotH2_(dot(_e6, _e7), _e11, _e12);
    return _e13;
}

fn pbr_D_GGX_Anisotropic(NdotH_14: f32, TdotH: f32, BdotH: f32, alphaT: f32, alphaB: f32) -> f32 {
    var NdotH_15: f32;
    var TdotH_1: f32;
    var BdotH_1: f32;
    var alphaT_1: f32;
    var alphaB_1: f32;
    var a2_: f32;
    var f: vec3<f32>;
    var w2_: f32;

    NdotH_15 = NdotH_14;
    TdotH_1 = TdotH;
    BdotH_1 = BdotH;
    alphaT_1 = alphaT;
    alphaB_1 = alphaB;
    let _e10 = alphaT_1;
    alphaT_1 = clamp(_e10, 0.0000001f, 1f);
    let _e14 = alphaB_1;
    alphaB_1 = clamp(_e14, 0.0000001f, 1f);
    let _e18 = alphaT_1;
    let _e19 = alphaB_1;
    a2_ = (_e18 * _e19);
    let _e22 = alphaB_1;
    let _e23 = TdotH_1;
    let _e29 = alphaT_1;
    let _e30 = BdotH_1;
    let _e36 = a2_;
    let _e37 = NdotH_15;
    let _e38 = pbr_saturate(_e37);
    f = vec3<f32>((_e22 * clamp(_e23, -1f, 1f)), (_e29 * clamp(_e30, -1f, 1f)), (_e36 * _e38));
    let _e42 = a2_;
    let _e43 = f;
    let _e44 = f;
    let _e46 = a2_;
    let _e47 = a2_;
    w2_ = (_e42 / max(dot(_e43, _e44), (_e46 * _e47)));
    let _e52 = a2_;
    let _e53 = w2_;
    let _e55 = w2_;
    return (((_e52 * _e53) * _e55) * 0.31830987f);
}

fn pbr_D_Beckmann_fromOneMinusNdotH2_(NdotH_16: f32, oneMinusNdotH2_2: f32, alpha_10: f32) -> f32 {
    var NdotH_17: f32;
    var oneMinusNdotH2_3: f32;
    var alpha_11: f32;
    var a2_1: f32;
    var NdotH2_: f32;

    NdotH_17 = NdotH_16;
    oneMinusNdotH2_3 = oneMinusNdotH2_2;
    alpha_11 = alpha_10;
    let _e6 = NdotH_17;
    if !((_e6 >= 0.1f)) {
        return 0f;
    }
    let _e11 = alpha_11;
    alpha_11 = clamp(_e11, 0.0000001f, 1f);
    let _e15 = alpha_11;
    let _e16 = alpha_11;
    a2_1 = (_e15 * _e16);
    let _e19 = NdotH_17;
    let _e20 = NdotH_17;
    NdotH2_ = min((_e19 * _e20), 1f);
    let _e25 = oneMinusNdotH2_3;
    let _e27 = a2_1;
    let _e28 = NdotH2_;
    let _e33 = a2_1;
    let _e35 = NdotH2_;
    let _e37 = NdotH2_;
    return (exp((-(_e25) / (_e27 * _e28))) / (((3.1415927f * _e33) * _e35) * _e37));
}

fn pbr_D_Beckmann(NdotH_18: f32, alpha_12: f32) -> f32 {
    var NdotH_19: f32;
    var alpha_13: f32;

    NdotH_19 = NdotH_18;
    alpha_13 = alpha_12;
    let _e4 = NdotH_19;
    let _e5 = pbr_saturate(_e4);
    NdotH_19 = _e5;
    let _e6 = NdotH_19;
    let _e8 = NdotH_19;
    let _e11 = NdotH_19;
    let _e14 = alpha_13;
    let _e15 = pbr_D_Beckmann_fromOneMinusNdotH2_(_e6, ((1f - _e8) * (1f + _e11)), _e14);
    return _e15;
}

fn pbr_G_CookTorrance(NdotL_4: f32, NdotV_2: f32, NdotH_20: f32, VdotH: f32) -> f32 {
    var NdotL_5: f32;
    var NdotV_3: f32;
    var NdotH_21: f32;
    var VdotH_1: f32;
    var VdotHSafe: f32;

    NdotL_5 = NdotL_4;
    NdotV_3 = NdotV_2;
    NdotH_21 = NdotH_20;
    VdotH_1 = VdotH;
    let _e8 = VdotH_1;
    VdotHSafe = clamp(_e8, 0.000005f, 1f);
    let _e15 = NdotH_21;
    let _e16 = pbr_saturate(_e15);
    let _e18 = NdotV_3;
    let _e19 = NdotL_5;
    let _e21 = pbr_saturate(min(_e18, _e19));
    let _e23 = VdotHSafe;
    return min(1f, (((2f * _e16) * _e21) / _e23));
}

fn pbr_V_CookTorrance(NdotL_6: f32, NdotV_4: f32, NdotH_22: f32, VdotH_2: f32) -> f32 {
    var NdotL_7: f32;
    var NdotV_5: f32;
    var NdotH_23: f32;
    var VdotH_3: f32;

    NdotL_7 = NdotL_6;
    NdotV_5 = NdotV_4;
    NdotH_23 = NdotH_22;
    VdotH_3 = VdotH_2;
    let _e8 = NdotL_7;
    let _e9 = NdotV_5;
    let _e10 = NdotH_23;
    let _e11 = VdotH_3;
    let _e12 = pbr_G_CookTorrance(_e8, _e9, _e10, _e11);
    let _e14 = NdotL_7;
    let _e19 = NdotV_5;
    return (_e12 / ((4f * clamp(_e14, 0.0001f, 1f)) * clamp(_e19, 0.0001f, 1f)));
}

fn pbr_SmithGGX_denominator(NdotX: f32, alpha_14: f32) -> f32 {
    var NdotX_1: f32;
    var alpha_15: f32;
    var a2_2: f32;

    NdotX_1 = NdotX;
    alpha_15 = alpha_14;
    let _e4 = alpha_15;
    let _e5 = alpha_15;
    a2_2 = (_e4 * _e5);
    let _e8 = NdotX_1;
    let _e9 = a2_2;
    let _e11 = a2_2;
    let _e13 = NdotX_1;
    let _e15 = NdotX_1;
    return (_e8 + sqrt((_e9 + (((1f - _e11) * _e13) * _e15))));
}

fn pbr_G1_SmithGGX(NdotX_2: f32, alpha_16: f32) -> f32 {
    var NdotX_3: f32;
    var alpha_17: f32;

    NdotX_3 = NdotX_2;
    alpha_17 = alpha_16;
    let _e4 = NdotX_3;
    let _e5 = pbr_saturate(_e4);
    NdotX_3 = _e5;
    let _e7 = NdotX_3;
    let _e9 = NdotX_3;
    let _e10 = alpha_17;
    let _e14 = pbr_SmithGGX_denominator(_e9, clamp(_e10, 0.0000001f, 1f));
    return min(((2f * _e7) / _e14), 1f);
}

fn pbr_G_SmithGGX(NdotL_8: f32, NdotV_6: f32, alpha_18: f32) -> f32 {
    var NdotL_9: f32;
    var NdotV_7: f32;
    var alpha_19: f32;

    NdotL_9 = NdotL_8;
    NdotV_7 = NdotV_6;
    alpha_19 = alpha_18;
    let _e6 = NdotL_9;
    let _e7 = alpha_19;
    let _e8 = pbr_G1_SmithGGX(_e6, _e7);
    let _e9 = NdotV_7;
    let _e10 = alpha_19;
    let _e11 = pbr_G1_SmithGGX(_e9, _e10);
    return (_e8 * _e11);
}

fn pbr_V_SmithGGX(NdotL_10: f32, NdotV_8: f32, alpha_20: f32) -> f32 {
    var NdotL_11: f32;
    var NdotV_9: f32;
    var alpha_21: f32;

    NdotL_11 = NdotL_10;
    NdotV_9 = NdotV_8;
    alpha_21 = alpha_20;
    let _e6 = alpha_21;
    alpha_21 = clamp(_e6, 0.0000001f, 1f);
    let _e11 = NdotV_9;
    let _e15 = alpha_21;
    let _e16 = pbr_SmithGGX_denominator(clamp(_e11, 0.0001f, 1f), _e15);
    let _e17 = NdotL_11;
    let _e21 = alpha_21;
    let _e22 = pbr_SmithGGX_denominator(clamp(_e17, 0.0001f, 1f), _e21);
    return (1f / (_e16 * _e22));
}

fn pbr_G1_SchlickGGX(NdotX_4: f32, k_2: f32) -> f32 {
    var NdotX_5: f32;
    var k_3: f32;

    NdotX_5 = NdotX_4;
    k_3 = k_2;
    let _e4 = NdotX_5;
    let _e5 = pbr_saturate(_e4);
    NdotX_5 = _e5;
    let _e6 = k_3;
    k_3 = clamp(_e6, 0.00000005f, 1f);
    let _e12 = NdotX_5;
    let _e13 = NdotX_5;
    let _e15 = k_3;
    let _e18 = k_3;
    return min((_e12 / ((_e13 * (1f - _e15)) + _e18)), 1f);
}

fn pbr_G_SchlickGGX(NdotL_12: f32, NdotV_10: f32, k_4: f32) -> f32 {
    var NdotL_13: f32;
    var NdotV_11: f32;
    var k_5: f32;

    NdotL_13 = NdotL_12;
    NdotV_11 = NdotV_10;
    k_5 = k_4;
    let _e6 = NdotL_13;
    let _e7 = k_5;
    let _e8 = pbr_G1_SchlickGGX(_e6, _e7);
    let _e9 = NdotV_11;
    let _e10 = k_5;
    let _e11 = pbr_G1_SchlickGGX(_e9, _e10);
    return (_e8 * _e11);
}

fn pbr_V_SchlickGGX(NdotL_14: f32, NdotV_12: f32, k_6: f32) -> f32 {
    var NdotL_15: f32;
    var NdotV_13: f32;
    var k_7: f32;

    NdotL_15 = NdotL_14;
    NdotV_13 = NdotV_12;
    k_7 = k_6;
    let _e6 = NdotL_15;
    NdotL_15 = clamp(_e6, 0.0001f, 1f);
    let _e10 = NdotV_13;
    NdotV_13 = clamp(_e10, 0.0001f, 1f);
    let _e14 = k_7;
    k_7 = clamp(_e14, 0.00000005f, 1f);
    let _e21 = NdotL_15;
    let _e23 = k_7;
    let _e26 = k_7;
    let _e28 = NdotV_13;
    let _e30 = k_7;
    let _e33 = k_7;
    return (0.25f / (((_e21 * (1f - _e23)) + _e26) * ((_e28 * (1f - _e30)) + _e33)));
}

fn pbr_k_SchlickGGX_from_alpha(alpha_22: f32) -> f32 {
    var alpha_23: f32;

    alpha_23 = alpha_22;
    let _e3 = alpha_23;
    return (0.5f * _e3);
}

fn pbr_k_SchlickGGX_hotness(perceptualRoughness_4: f32) -> f32 {
    var perceptualRoughness_5: f32;
    var r_3: f32;

    perceptualRoughness_5 = perceptualRoughness_4;
    let _e4 = perceptualRoughness_5;
    r_3 = (0.5f + (0.5f * _e4));
    let _e9 = r_3;
    let _e11 = r_3;
    return ((0.5f * _e9) * _e11);
}

fn pbr_V_SmithGGXCorrelated(NdotL_16: f32, NdotV_14: f32, alpha_24: f32) -> f32 {
    var NdotL_17: f32;
    var NdotV_15: f32;
    var alpha_25: f32;
    var a2_3: f32;
    var lambdaV: f32;
    var lambdaL: f32;

    NdotL_17 = NdotL_16;
    NdotV_15 = NdotV_14;
    alpha_25 = alpha_24;
    let _e6 = NdotL_17;
    NdotL_17 = clamp(_e6, 0.0001f, 1f);
    let _e10 = NdotV_15;
    NdotV_15 = clamp(_e10, 0.0001f, 1f);
    let _e14 = alpha_25;
    alpha_25 = clamp(_e14, 0.0000001f, 1f);
    let _e18 = alpha_25;
    let _e19 = alpha_25;
    a2_3 = (_e18 * _e19);
    let _e22 = NdotL_17;
    let _e23 = NdotV_15;
    let _e24 = NdotV_15;
    let _e27 = a2_3;
    let _e30 = a2_3;
    lambdaV = (_e22 * sqrt((((_e23 * _e24) * (1f - _e27)) + _e30)));
    let _e35 = NdotV_15;
    let _e36 = NdotL_17;
    let _e37 = NdotL_17;
    let _e40 = a2_3;
    let _e43 = a2_3;
    lambdaL = (_e35 * sqrt((((_e36 * _e37) * (1f - _e40)) + _e43)));
    let _e49 = lambdaV;
    let _e50 = lambdaL;
    return (0.5f / (_e49 + _e50));
}

fn pbr_V_SmithGGXCorrelatedFast(NdotL_18: f32, NdotV_16: f32, alpha_26: f32) -> f32 {
    var NdotL_19: f32;
    var NdotV_17: f32;
    var alpha_27: f32;
    var lambdaV_1: f32;
    var lambdaL_1: f32;

    NdotL_19 = NdotL_18;
    NdotV_17 = NdotV_16;
    alpha_27 = alpha_26;
    let _e6 = NdotL_19;
    NdotL_19 = clamp(_e6, 0.0001f, 1f);
    let _e10 = NdotV_17;
    NdotV_17 = clamp(_e10, 0.0001f, 1f);
    let _e14 = alpha_27;
    alpha_27 = clamp(_e14, 0.0000001f, 1f);
    let _e18 = NdotL_19;
    let _e19 = NdotV_17;
    let _e21 = alpha_27;
    let _e24 = alpha_27;
    lambdaV_1 = (_e18 * ((_e19 * (1f - _e21)) + _e24));
    let _e28 = NdotV_17;
    let _e29 = NdotL_19;
    let _e31 = alpha_27;
    let _e34 = alpha_27;
    lambdaL_1 = (_e28 * ((_e29 * (1f - _e31)) + _e34));
    let _e39 = lambdaV_1;
    let _e40 = lambdaL_1;
    return (0.5f / (_e39 + _e40));
}

fn pbr_V_SmithGGXCorrelated_Anisotropic(NdotL_20: f32, NdotV_18: f32, TdotV: f32, BdotV: f32, TdotL: f32, BdotL: f32, alphaT_2: f32, alphaB_2: f32) -> f32 {
    var NdotL_21: f32;
    var NdotV_19: f32;
    var TdotV_1: f32;
    var BdotV_1: f32;
    var TdotL_1: f32;
    var BdotL_1: f32;
    var alphaT_3: f32;
    var alphaB_3: f32;
    var stretchedV: vec3<f32>;
    var stretchedL: vec3<f32>;
    var lambdaV_2: f32;
    var lambdaL_2: f32;

    NdotL_21 = NdotL_20;
    NdotV_19 = NdotV_18;
    TdotV_1 = TdotV;
    BdotV_1 = BdotV;
    TdotL_1 = TdotL;
    BdotL_1 = BdotL;
    alphaT_3 = alphaT_2;
    alphaB_3 = alphaB_2;
    let _e16 = NdotL_21;
    NdotL_21 = clamp(_e16, 0.0001f, 1f);
    let _e20 = NdotV_19;
    NdotV_19 = clamp(_e20, 0.0001f, 1f);
    let _e24 = alphaT_3;
    alphaT_3 = clamp(_e24, 0.0000001f, 1f);
    let _e28 = alphaB_3;
    alphaB_3 = clamp(_e28, 0.0000001f, 1f);
    let _e32 = alphaT_3;
    let _e33 = TdotV_1;
    let _e39 = alphaB_3;
    let _e40 = BdotV_1;
    let _e46 = NdotV_19;
    stretchedV = vec3<f32>((_e32 * clamp(_e33, -1f, 1f)), (_e39 * clamp(_e40, -1f, 1f)), _e46);
    let _e49 = alphaT_3;
    let _e50 = TdotL_1;
    let _e56 = alphaB_3;
    let _e57 = BdotL_1;
    let _e63 = NdotL_21;
    stretchedL = vec3<f32>((_e49 * clamp(_e50, -1f, 1f)), (_e56 * clamp(_e57, -1f, 1f)), _e63);
    let _e66 = NdotL_21;
    let _e67 = stretchedV;
    let _e68 = stretchedV;
    lambdaV_2 = (_e66 * sqrt(dot(_e67, _e68)));
    let _e73 = NdotV_19;
    let _e74 = stretchedL;
    let _e75 = stretchedL;
    lambdaL_2 = (_e73 * sqrt(dot(_e74, _e75)));
    let _e81 = lambdaV_2;
    let _e82 = lambdaL_2;
    return (0.5f / (_e81 + _e82));
}

fn pbr_DV_GGX_fromLambdaSum(nDotH: f32, nCrossH2_: f32, h2_: f32, alpha_28: f32, lambdaSum: f32) -> f32 {
    var nDotH_1: f32;
    var nCrossH2_1: f32;
    var h2_1: f32;
    var alpha_29: f32;
    var lambdaSum_1: f32;
    var a2_4: f32;
    var invH2_: f32;
    var dn: f32;

    nDotH_1 = nDotH;
    nCrossH2_1 = nCrossH2_;
    h2_1 = h2_;
    alpha_29 = alpha_28;
    lambdaSum_1 = lambdaSum;
    let _e10 = alpha_29;
    let _e11 = alpha_29;
    a2_4 = (_e10 * _e11);
    let _e15 = h2_1;
    invH2_ = (1f / _e15);
    let _e18 = nCrossH2_1;
    let _e19 = invH2_;
    let _e20 = invH2_;
    let _e21 = a2_4;
    let _e25 = a2_4;
    dn = ((_e18 * (_e19 - (_e20 * _e21))) + _e25);
    let _e28 = a2_4;
    let _e33 = dn;
    let _e34 = dn;
    let _e36 = lambdaSum_1;
    return ((_e28 * 0.15915494f) / ((_e33 * _e34) * _e36));
}

fn pbr_DV_GGX_SmithCorrelated(nDotH_2: f32, nCrossH2_2: f32, h2_2: f32, NdotL_22: f32, NdotV_20: f32, alpha_30: f32) -> f32 {
    var nDotH_3: f32;
    var nCrossH2_3: f32;
    var h2_3: f32;
    var NdotL_23: f32;
    var NdotV_21: f32;
    var alpha_31: f32;
    var a2_5: f32;
    var lambdaV_3: f32;
    var lambdaL_3: f32;

    nDotH_3 = nDotH_2;
    nCrossH2_3 = nCrossH2_2;
    h2_3 = h2_2;
    NdotL_23 = NdotL_22;
    NdotV_21 = NdotV_20;
    alpha_31 = alpha_30;
    let _e12 = alpha_31;
    let _e13 = alpha_31;
    a2_5 = (_e12 * _e13);
    let _e16 = NdotL_23;
    let _e17 = NdotV_21;
    let _e18 = NdotV_21;
    let _e19 = a2_5;
    let _e22 = NdotV_21;
    let _e24 = a2_5;
    lambdaV_3 = (_e16 * sqrt((((_e17 - (_e18 * _e19)) * _e22) + _e24)));
    let _e29 = NdotV_21;
    let _e30 = NdotL_23;
    let _e31 = NdotL_23;
    let _e32 = a2_5;
    let _e35 = NdotL_23;
    let _e37 = a2_5;
    lambdaL_3 = (_e29 * sqrt((((_e30 - (_e31 * _e32)) * _e35) + _e37)));
    let _e42 = nDotH_3;
    let _e43 = nCrossH2_3;
    let _e44 = h2_3;
    let _e45 = alpha_31;
    let _e46 = lambdaV_3;
    let _e47 = lambdaL_3;
    let _e49 = pbr_DV_GGX_fromLambdaSum(_e42, _e43, _e44, _e45, (_e46 + _e47));
    return _e49;
}

fn pbr_DV_GGX_SmithCorrelatedFast(nDotH_4: f32, nCrossH2_4: f32, h2_4: f32, NdotL_24: f32, NdotV_22: f32, alpha_32: f32) -> f32 {
    var nDotH_5: f32;
    var nCrossH2_5: f32;
    var h2_5: f32;
    var NdotL_25: f32;
    var NdotV_23: f32;
    var alpha_33: f32;

    nDotH_5 = nDotH_4;
    nCrossH2_5 = nCrossH2_4;
    h2_5 = h2_4;
    NdotL_25 = NdotL_24;
    NdotV_23 = NdotV_22;
    alpha_33 = alpha_32;
    let _e12 = nDotH_5;
    let _e13 = nCrossH2_5;
    let _e14 = h2_5;
    let _e15 = alpha_33;
    let _e17 = NdotL_25;
    let _e19 = NdotV_23;
    let _e21 = NdotL_25;
    let _e22 = NdotV_23;
    let _e24 = alpha_33;
    let _e26 = pbr_DV_GGX_fromLambdaSum(_e12, _e13, _e14, _e15, mix(((2f * _e17) * _e19), (_e21 + _e22), _e24));
    return _e26;
}

fn pbr_DV_GGX_SmithCorrelatedFast_half(nDotH_6: f32, nCrossH2_6: f32, h2_6: f32, NdotL_26: f32, NdotV_24: f32, alpha_34: f32) -> f32 {
    var nDotH_7: f32;
    var nCrossH2_7: f32;
    var h2_7: f32;
    var NdotL_27: f32;
    var NdotV_25: f32;
    var alpha_35: f32;
    var a_3: f32;
    var cosL: f32;
    var cosV: f32;
    var invH2_1: f32;
    var dn_1: f32;
    var k_8: f32;
    var lambdas: f32;

    nDotH_7 = nDotH_6;
    nCrossH2_7 = nCrossH2_6;
    h2_7 = h2_6;
    NdotL_27 = NdotL_26;
    NdotV_25 = NdotV_24;
    alpha_35 = alpha_34;
    let _e12 = alpha_35;
    a_3 = f32(_e12);
    let _e15 = NdotL_27;
    cosL = f32(_e15);
    let _e18 = NdotV_25;
    cosV = f32(_e18);
    let _e22 = h2_7;
    invH2_1 = (1f / _e22);
    let _e25 = nCrossH2_7;
    let _e26 = invH2_1;
    let _e29 = nDotH_7;
    let _e30 = nDotH_7;
    let _e32 = invH2_1;
    let _e35 = a_3;
    let _e36 = a_3;
    dn_1 = (f32((_e25 * _e26)) + (f32(((_e29 * _e30) * _e32)) * (_e35 * _e36)));
    let _e41 = a_3;
    let _e42 = dn_1;
    k_8 = (_e41 / _e42);
    let _e47 = cosL;
    let _e49 = cosV;
    let _e51 = cosL;
    let _e52 = cosV;
    let _e54 = a_3;
    lambdas = max(mix(((2f * _e47) * _e49), (_e51 + _e52), _e54), 0.000061035156f);
    let _e60 = k_8;
    let _e61 = k_8;
    let _e67 = lambdas;
    return f32(((_e60 * _e61) * (0.15915494f / _e67)));
}

fn pbr_DV_GGX_SmithBound(nDotH_8: f32, nCrossH2_8: f32, h2_8: f32, NdotL_28: f32, NdotV_26: f32, alpha_36: f32) -> f32 {
    var nDotH_9: f32;
    var nCrossH2_9: f32;
    var h2_9: f32;
    var NdotL_29: f32;
    var NdotV_27: f32;
    var alpha_37: f32;
    var a2_6: f32;
    var invH2_2: f32;
    var dn_2: f32;

    nDotH_9 = nDotH_8;
    nCrossH2_9 = nCrossH2_8;
    h2_9 = h2_8;
    NdotL_29 = NdotL_28;
    NdotV_27 = NdotV_26;
    alpha_37 = alpha_36;
    let _e12 = alpha_37;
    let _e13 = alpha_37;
    a2_6 = (_e12 * _e13);
    let _e17 = h2_9;
    invH2_2 = (1f / _e17);
    let _e20 = nCrossH2_9;
    let _e21 = invH2_2;
    let _e22 = invH2_2;
    let _e23 = a2_6;
    let _e27 = a2_6;
    dn_2 = ((_e20 * (_e21 - (_e22 * _e23))) + _e27);
    let _e30 = a2_6;
    let _e35 = dn_2;
    let _e36 = dn_2;
    let _e38 = nDotH_9;
    return ((_e30 * 0.15915494f) / ((_e35 * _e36) * _e38));
}

fn pbr_G_Implicit(NdotL_30: f32, NdotV_28: f32) -> f32 {
    var NdotL_31: f32;
    var NdotV_29: f32;

    NdotL_31 = NdotL_30;
    NdotV_29 = NdotV_28;
    let _e4 = NdotL_31;
    let _e5 = pbr_saturate(_e4);
    let _e6 = NdotV_29;
    let _e7 = pbr_saturate(_e6);
    return (_e5 * _e7);
}

fn pbr_V_Implicit() -> f32 {
    return 0.25f;
}

fn pbr_G_Kelemen(NdotL_32: f32, NdotV_30: f32, VdotH_4: f32) -> f32 {
    var NdotL_33: f32;
    var NdotV_31: f32;
    var VdotH_5: f32;
    var VdotHSafe_1: f32;

    NdotL_33 = NdotL_32;
    NdotV_31 = NdotV_30;
    VdotH_5 = VdotH_4;
    let _e6 = VdotH_5;
    VdotHSafe_1 = clamp(_e6, 0.000005f, 1f);
    let _e12 = NdotL_33;
    let _e13 = pbr_saturate(_e12);
    let _e14 = NdotV_31;
    let _e15 = pbr_saturate(_e14);
    let _e17 = VdotHSafe_1;
    let _e18 = VdotHSafe_1;
    return min(1f, ((_e13 * _e15) / (_e17 * _e18)));
}

fn pbr_V_Kelemen(VdotH_6: f32) -> f32 {
    var VdotH_7: f32;
    var VdotHSafe_2: f32;

    VdotH_7 = VdotH_6;
    let _e2 = VdotH_7;
    VdotHSafe_2 = clamp(_e2, 0.000005f, 1f);
    let _e8 = VdotHSafe_2;
    let _e9 = VdotHSafe_2;
    return (0.25f / (_e8 * _e9));
}

fn pbr_V_SmithGGXBound(NdotL_34: f32, NdotV_32: f32) -> f32 {
    var NdotL_35: f32;
    var NdotV_33: f32;

    NdotL_35 = NdotL_34;
    NdotV_33 = NdotV_32;
    let _e5 = NdotL_35;
    let _e9 = NdotV_33;
    return (0.5f / (clamp(_e5, 0.0001f, 1f) + clamp(_e9, 0.0001f, 1f)));
}

fn pbr_F_Schlick(f0_2: f32, VdotH_8: f32) -> f32 {
    var f0_3: f32;
    var VdotH_9: f32;

    f0_3 = f0_2;
    VdotH_9 = VdotH_8;
    let _e4 = f0_3;
    let _e6 = f0_3;
    let _e9 = VdotH_9;
    let _e10 = pbr_saturate(_e9);
    let _e12 = pbr_pow5_((1f - _e10));
    return (_e4 + ((1f - _e6) * _e12));
}

fn pbr_F_Schlick_1(f0_4: vec3<f32>, VdotH_10: f32) -> vec3<f32> {
    var f0_5: vec3<f32>;
    var VdotH_11: f32;

    f0_5 = f0_4;
    VdotH_11 = VdotH_10;
    let _e4 = f0_5;
    let _e7 = f0_5;
    let _e10 = VdotH_11;
    let _e11 = pbr_saturate(_e10);
    let _e13 = pbr_pow5_((1f - _e11));
    return (_e4 + ((vec3(1f) - _e7) * _e13));
}

fn pbr_F_Schlick_2(f0_6: vec3<f32>, f90_: f32, VdotH_12: f32) -> vec3<f32> {
    var f0_7: vec3<f32>;
    var f90_1: f32;
    var VdotH_13: f32;

    f0_7 = f0_6;
    f90_1 = f90_;
    VdotH_13 = VdotH_12;
    let _e6 = f0_7;
    let _e7 = f90_1;
    let _e9 = f0_7;
    let _e12 = VdotH_13;
    let _e13 = pbr_saturate(_e12);
    let _e15 = pbr_pow5_((1f - _e13));
    return (_e6 + ((vec3(_e7) - _e9) * _e15));
}

fn pbr_F_SchlickSG(f0_8: vec3<f32>, VdotH_14: f32) -> vec3<f32> {
    var f0_9: vec3<f32>;
    var VdotH_15: f32;
    var w: f32;

    f0_9 = f0_8;
    VdotH_15 = VdotH_14;
    let _e4 = VdotH_15;
    let _e5 = pbr_saturate(_e4);
    VdotH_15 = _e5;
    let _e8 = VdotH_15;
    let _e13 = VdotH_15;
    w = exp2((((-5.55473f * _e8) + -6.98316f) * _e13));
    let _e17 = f0_9;
    let _e20 = f0_9;
    let _e22 = w;
    return (_e17 + ((vec3(1f) - _e20) * _e22));
}

fn pbr_F_SchlickSG_1(f0_10: vec3<f32>, f90_2: f32, VdotH_16: f32) -> vec3<f32> {
    var f0_11: vec3<f32>;
    var f90_3: f32;
    var VdotH_17: f32;
    var w_1: f32;

    f0_11 = f0_10;
    f90_3 = f90_2;
    VdotH_17 = VdotH_16;
    let _e6 = VdotH_17;
    let _e7 = pbr_saturate(_e6);
    VdotH_17 = _e7;
    let _e10 = VdotH_17;
    let _e15 = VdotH_17;
    w_1 = exp2((((-5.55473f * _e10) + -6.98316f) * _e15));
    let _e19 = f0_11;
    let _e20 = f90_3;
    let _e22 = f0_11;
    let _e24 = w_1;
    return (_e19 + ((vec3(_e20) - _e22) * _e24));
}

fn pbr_f90_from_f0_(f0_12: vec3<f32>) -> f32 {
    var f0_13: vec3<f32>;

    f0_13 = f0_12;
    let _e2 = f0_13;
    let _e6 = pbr_saturate(dot(_e2, vec3(16.5f)));
    return _e6;
}

fn pbr_F_Dielectric(cosTheta: f32, eta_2: f32) -> f32 {
    var cosTheta_1: f32;
    var eta_3: f32;
    var c_17: f32;
    var etaSquaredMinusOne: f32;
    var g2_: f32;
    var g: f32;
    var gPlusC: f32;
    var gMinusC: f32;
    var a_4: f32;
    var b_2: f32;

    cosTheta_1 = cosTheta;
    eta_3 = eta_2;
    let _e4 = cosTheta_1;
    c_17 = min(abs(_e4), 1f);
    let _e9 = eta_3;
    let _e12 = eta_3;
    etaSquaredMinusOne = ((_e9 - 1f) * (_e12 + 1f));
    let _e17 = etaSquaredMinusOne;
    let _e18 = c_17;
    let _e19 = c_17;
    g2_ = (_e17 + (_e18 * _e19));
    let _e23 = g2_;
    if (_e23 < 0f) {
        return 1f;
    }
    let _e27 = g2_;
    g = sqrt(_e27);
    let _e30 = g;
    let _e31 = c_17;
    gPlusC = max((_e30 + _e31), 0.000000000000000000000000000000000000011754944f);
    let _e36 = etaSquaredMinusOne;
    let _e37 = gPlusC;
    gMinusC = (_e36 / _e37);
    let _e40 = gMinusC;
    let _e41 = gPlusC;
    a_4 = (_e40 / _e41);
    let _e44 = c_17;
    let _e45 = g;
    let _e46 = c_17;
    let _e51 = c_17;
    let _e52 = gMinusC;
    b_2 = (((_e44 * (_e45 + _e46)) - 1f) / ((_e51 * _e52) + 1f));
    let _e59 = a_4;
    let _e61 = a_4;
    let _e64 = b_2;
    let _e65 = b_2;
    return min((((0.5f * _e59) * _e61) * (1f + (_e64 * _e65))), 1f);
}

fn pbr_T_Dielectric(cosTheta_2: f32, eta_4: f32) -> f32 {
    var cosTheta_3: f32;
    var eta_5: f32;
    var c_18: f32;
    var eta2_: f32;
    var g2_1: f32;
    var g_1: f32;
    var cg4_: f32;
    var s_4: f32;
    var p_1: f32;

    cosTheta_3 = cosTheta_2;
    eta_5 = eta_4;
    let _e4 = eta_5;
    if (_e4 == 1f) {
        return 1f;
    }
    let _e8 = cosTheta_3;
    c_18 = min(abs(_e8), 1f);
    let _e13 = eta_5;
    let _e14 = eta_5;
    eta2_ = (_e13 * _e14);
    let _e17 = eta_5;
    let _e20 = eta_5;
    let _e24 = c_18;
    let _e25 = c_18;
    g2_1 = (((_e17 - 1f) * (_e20 + 1f)) + (_e24 * _e25));
    let _e29 = g2_1;
    if (_e29 <= 0f) {
        return 0f;
    }
    let _e33 = g2_1;
    g_1 = sqrt(_e33);
    let _e37 = c_18;
    let _e39 = g_1;
    cg4_ = ((4f * _e37) * _e39);
    let _e42 = cg4_;
    let _e43 = c_18;
    let _e44 = g_1;
    let _e46 = c_18;
    let _e47 = g_1;
    s_4 = (_e42 / max(((_e43 + _e44) * (_e46 + _e47)), 0.000000000000000000000000000000000000011754944f));
    let _e54 = eta2_;
    let _e55 = cg4_;
    let _e57 = eta2_;
    let _e58 = c_18;
    let _e60 = g_1;
    let _e62 = eta2_;
    let _e63 = c_18;
    let _e65 = g_1;
    p_1 = ((_e54 * _e55) / max((((_e57 * _e58) + _e60) * ((_e62 * _e63) + _e65)), 0.000000000000000000000000000000000000011754944f));
    let _e73 = s_4;
    let _e74 = p_1;
    return min((0.5f * (_e73 + _e74)), 1f);
}

fn pbr_BTDF_Walter_GGX_cosine(n_2: vec3<f32>, v_6: vec3<f32>, l: vec3<f32>, alpha_38: f32, eta_6: f32) -> f32 {
    var n_3: vec3<f32>;
    var v_7: vec3<f32>;
    var l_1: vec3<f32>;
    var alpha_39: f32;
    var eta_7: f32;
    var ht: vec3<f32>;
    var length2_: f32;
    var NdotV_34: f32;
    var NdotL_36: f32;
    var h_2: vec3<f32>;
    var local_9: vec3<f32>;
    var VdotH_18: f32;
    var LdotH_2: f32;
    var refracts: bool;
    var a_5: f32;
    var D: f32;
    var G: f32;
    var T: f32;
    var ft: f32;
    var local_10: f32;

    n_3 = n_2;
    v_7 = v_6;
    l_1 = l;
    alpha_39 = alpha_38;
    eta_7 = eta_6;
    let _e10 = eta_7;
    let _e11 = l_1;
    let _e13 = v_7;
    ht = -(((_e10 * _e11) + _e13));
    let _e17 = ht;
    let _e18 = ht;
    length2_ = dot(_e17, _e18);
    let _e21 = n_3;
    let _e22 = v_7;
    NdotV_34 = dot(_e21, _e22);
    let _e25 = n_3;
    let _e26 = l_1;
    NdotL_36 = dot(_e25, _e26);
    let _e29 = ht;
    let _e30 = length2_;
    h_2 = (_e29 * inverseSqrt(max(_e30, 0.0000000001f)));
    let _e36 = n_3;
    let _e37 = h_2;
    if (dot(_e36, _e37) < 0f) {
        let _e41 = h_2;
        local_9 = -(_e41);
    } else {
        let _e43 = h_2;
        local_9 = _e43;
    }
    let _e45 = local_9;
    h_2 = _e45;
    let _e46 = v_7;
    let _e47 = h_2;
    VdotH_18 = dot(_e46, _e47);
    let _e50 = l_1;
    let _e51 = h_2;
    LdotH_2 = dot(_e50, _e51);
    let _e54 = VdotH_18;
    let _e55 = LdotH_2;
    let _e59 = NdotV_34;
    let _e63 = NdotL_36;
    let _e67 = length2_;
    refracts = (((((_e54 * _e55) < 0f) && (_e59 > 0f)) && (_e63 < 0f)) && (_e67 >= 0.0000000001f));
    let _e72 = alpha_39;
    a_5 = max(_e72, 0.0000001f);
    let _e76 = n_3;
    let _e77 = h_2;
    let _e82 = a_5;
    let _e83 = pbr_D_GGX(clamp(dot(_e76, _e77), 0f, 1f), _e82);
    D = _e83;
    let _e85 = NdotV_34;
    let _e86 = a_5;
    let _e87 = pbr_G1_SmithGGX(_e85, _e86);
    let _e88 = NdotL_36;
    let _e90 = a_5;
    let _e91 = pbr_G1_SmithGGX(-(_e88), _e90);
    G = (_e87 * _e91);
    let _e94 = VdotH_18;
    let _e95 = eta_7;
    let _e96 = pbr_T_Dielectric(_e94, _e95);
    T = _e96;
    let _e98 = LdotH_2;
    let _e100 = VdotH_18;
    let _e103 = NdotV_34;
    let _e107 = T;
    let _e109 = G;
    let _e111 = D;
    let _e113 = length2_;
    ft = ((((((abs(_e98) * abs(_e100)) / max(_e103, 0.0001f)) * _e107) * _e109) * _e111) / max(_e113, 0.0000000001f));
    let _e118 = refracts;
    if _e118 {
        let _e119 = ft;
        local_10 = _e119;
    } else {
        local_10 = 0f;
    }
    let _e122 = local_10;
    return _e122;
}

fn pbr_BTDF_Walter_GGX(n_4: vec3<f32>, v_8: vec3<f32>, l_2: vec3<f32>, alpha_40: f32, eta_8: f32) -> f32 {
    var n_5: vec3<f32>;
    var v_9: vec3<f32>;
    var l_3: vec3<f32>;
    var alpha_41: f32;
    var eta_9: f32;

    n_5 = n_4;
    v_9 = v_8;
    l_3 = l_2;
    alpha_41 = alpha_40;
    eta_9 = eta_8;
    let _e10 = n_5;
    let _e11 = v_9;
    let _e12 = l_3;
    let _e13 = alpha_41;
    let _e14 = eta_9;
    let _e15 = pbr_BTDF_Walter_GGX_cosine(_e10, _e11, _e12, _e13, _e14);
    let _e16 = n_5;
    let _e17 = l_3;
    return (_e15 / max(-(dot(_e16, _e17)), 0.0001f));
}

fn pbr_iridescence_sensitivity(opdNm: f32, shift: vec3<f32>) -> vec3<f32> {
    var opdNm_1: f32;
    var shift_1: vec3<f32>;
    var phase: f32;
    var phase2_: f32;
    var amplitude: vec3<f32> = vec3<f32>(0.000000090458144f, 0.00000010687371f, 0.00000010696994f);
    var xyz: vec3<f32>;

    opdNm_1 = opdNm;
    shift_1 = shift;
    let _e7 = opdNm_1;
    phase = (0.000000006283185f * clamp(_e7, 0f, 100000f));
    let _e13 = phase;
    let _e14 = phase;
    phase2_ = (_e13 * _e14);
    let _e43 = amplitude;
    let _e48 = phase;
    let _e50 = shift_1;
    let _e54 = phase2_;
    xyz = ((_e43 * cos(((vec3<f32>(1681000f, 1795300f, 2208400f) * _e48) + _e50))) * exp((-(_e54) * vec3<f32>(4327800000f, 9304600000f, 6612100000f))));
    let _e65 = xyz;
    let _e74 = phase;
    let _e76 = shift_1;
    let _e81 = phase2_;
    xyz.x = (_e65.x + ((0.00000001644083f * cos(((2239900f * _e74) + _e76.x))) * exp((-(_e81) * 4528200000f))));
    let _e88 = xyz;
    xyz = (_e88 / vec3(0.00000010685f));
    let _e98 = xyz;
    let _e105 = xyz;
    let _e112 = xyz;
    return vec3<f32>(dot(vec3<f32>(3.2404542f, -1.5371385f, -0.4985314f), _e98), dot(vec3<f32>(-0.969266f, 1.8760108f, 0.041556f), _e105), dot(vec3<f32>(0.0556434f, -0.2040259f, 1.0572252f), _e112));
}

fn pbr_iridescence_sensitivity_xyz(opdNm_2: f32) -> vec3<f32> {
    var opdNm_3: f32;
    var phase_1: f32;
    var phase2_1: f32;
    var amplitude_1: vec3<f32> = vec3<f32>(0.000000090458144f, 0.00000010687371f, 0.00000010696994f);
    var xyz_1: vec3<f32>;

    opdNm_3 = opdNm_2;
    let _e5 = opdNm_3;
    phase_1 = (0.000000006283185f * clamp(_e5, 0f, 100000f));
    let _e11 = phase_1;
    let _e12 = phase_1;
    phase2_1 = (_e11 * _e12);
    let _e41 = amplitude_1;
    let _e46 = phase_1;
    let _e50 = phase2_1;
    xyz_1 = ((_e41 * cos((vec3<f32>(1681000f, 1795300f, 2208400f) * _e46))) * exp((-(_e50) * vec3<f32>(4327800000f, 9304600000f, 6612100000f))));
    let _e61 = xyz_1;
    let _e70 = phase_1;
    let _e74 = phase2_1;
    xyz_1.x = (_e61.x + ((0.00000001644083f * cos((2239900f * _e70))) * exp((-(_e74) * 4528200000f))));
    let _e81 = xyz_1;
    return (_e81 / vec3(0.00000010685f));
}

fn pbr_iridescence_xyz_to_rec709_(xyz_2: vec3<f32>) -> vec3<f32> {
    var xyz_3: vec3<f32>;

    xyz_3 = xyz_2;
    let _e8 = xyz_3;
    let _e15 = xyz_3;
    let _e22 = xyz_3;
    return vec3<f32>(dot(vec3<f32>(3.2404542f, -1.5371385f, -0.4985314f), _e8), dot(vec3<f32>(-0.969266f, 1.8760108f, 0.041556f), _e15), dot(vec3<f32>(0.0556434f, -0.2040259f, 1.0572252f), _e22));
}

fn pbr_thin_film(outsideIor: f32, filmIor: f32, cosTheta1_: f32, thicknessNm: f32) -> pbr_ThinFilm {
    var outsideIor_1: f32;
    var filmIor_1: f32;
    var cosTheta1_1: f32;
    var thicknessNm_1: f32;
    var f_1: pbr_ThinFilm;
    var ratio: f32;
    var r0_: f32;
    var opd: f32;

    outsideIor_1 = outsideIor;
    filmIor_1 = filmIor;
    cosTheta1_1 = cosTheta1_;
    thicknessNm_1 = thicknessNm;
    let _e10 = outsideIor_1;
    f_1.n1_ = _e10;
    let _e12 = thicknessNm_1;
    f_1.thicknessNm = _e12;
    let _e14 = cosTheta1_1;
    let _e15 = pbr_saturate(_e14);
    f_1.c1_ = _e15;
    let _e17 = f_1;
    let _e19 = filmIor_1;
    let _e22 = thicknessNm_1;
    f_1.n2_ = mix(_e17.n1_, _e19, smoothstep(0f, 0.03f, _e22));
    let _e25 = f_1;
    let _e27 = f_1;
    ratio = (_e25.n1_ / _e27.n2_);
    let _e33 = ratio;
    let _e34 = ratio;
    let _e37 = f_1;
    let _e39 = f_1;
    f_1.cos2Sq = (1f - ((_e33 * _e34) * (1f - (_e37.c1_ * _e39.c1_))));
    let _e46 = f_1;
    f_1.c2_ = sqrt(max(_e46.cos2Sq, 0f));
    let _e51 = f_1;
    let _e53 = f_1;
    let _e56 = f_1;
    let _e58 = f_1;
    r0_ = ((_e51.n2_ - _e53.n1_) / (_e56.n2_ + _e58.n1_));
    let _e64 = r0_;
    let _e65 = r0_;
    let _e67 = f_1;
    let _e69 = pbr_F_Schlick((_e64 * _e65), _e67.c1_);
    f_1.R12_ = _e69;
    let _e72 = f_1;
    f_1.T121_ = (1f - _e72.R12_);
    let _e76 = f_1;
    let _e79 = thicknessNm_1;
    let _e81 = f_1;
    opd = (((2f * _e76.n2_) * _e79) * _e81.c2_);
    let _e86 = opd;
    let _e87 = pbr_iridescence_sensitivity_xyz(_e86);
    f_1.xyz1_ = _e87;
    let _e90 = opd;
    let _e92 = pbr_iridescence_sensitivity_xyz((2f * _e90));
    let _e93 = pbr_iridescence_xyz_to_rec709_(_e92);
    f_1.S2_ = _e93;
    let _e94 = f_1;
    return _e94;
}

fn pbr_iridescence_airy_channel(f_2: pbr_ThinFilm, eta3_: f32, S1_: f32, S2_: f32) -> f32 {
    var f_3: pbr_ThinFilm;
    var eta3_1: f32;
    var S1_1: f32;
    var S2_1: f32;
    var r1_: f32;
    var R23_: f32;
    var R123_: f32;
    var r123_: f32;
    var Rs: f32;
    var C1_: f32;
    var C2_: f32;

    f_3 = f_2;
    eta3_1 = eta3_;
    S1_1 = S1_;
    S2_1 = S2_;
    let _e8 = eta3_1;
    let _e9 = f_3;
    let _e12 = eta3_1;
    let _e13 = f_3;
    r1_ = ((_e8 - _e9.n2_) / (_e12 + _e13.n2_));
    let _e18 = r1_;
    let _e19 = r1_;
    let _e21 = f_3;
    let _e23 = pbr_F_Schlick((_e18 * _e19), _e21.c2_);
    R23_ = _e23;
    let _e25 = f_3;
    let _e27 = R23_;
    R123_ = clamp((_e25.R12_ * _e27), 0f, 0.9999f);
    let _e33 = R123_;
    r123_ = sqrt(_e33);
    let _e36 = f_3;
    let _e38 = f_3;
    let _e41 = R23_;
    let _e44 = R123_;
    Rs = (((_e36.T121_ * _e38.T121_) * _e41) / (1f - _e44));
    let _e48 = Rs;
    let _e49 = f_3;
    let _e52 = r123_;
    C1_ = ((_e48 - _e49.T121_) * _e52);
    let _e55 = C1_;
    let _e56 = r123_;
    C2_ = (_e55 * _e56);
    let _e59 = f_3;
    let _e61 = Rs;
    let _e63 = C1_;
    let _e65 = S1_1;
    let _e69 = C2_;
    let _e71 = S2_1;
    return (((_e59.R12_ + _e61) + (_e63 * (2f * _e65))) + (_e69 * (2f * _e71)));
}

fn pbr_iridescence_airy(f_4: pbr_ThinFilm, baseF0_: vec3<f32>) -> vec3<f32> {
    var f_5: pbr_ThinFilm;
    var baseF0_1: vec3<f32>;
    var f0_14: vec3<f32>;
    var eta3_2: vec3<f32>;
    var pi21_: bool;
    var local_11: f32;
    var local_12: f32;
    var local_13: f32;
    var cosPhi: vec3<f32>;
    var S1_2: vec3<f32>;

    f_5 = f_4;
    baseF0_1 = baseF0_;
    let _e4 = baseF0_1;
    f0_14 = clamp(_e4, vec3(0f), vec3(0.9999f));
    let _e11 = f0_14;
    let _e13 = pbr_ior_from_f0_(_e11.x);
    let _e14 = f0_14;
    let _e16 = pbr_ior_from_f0_(_e14.y);
    let _e17 = f0_14;
    let _e19 = pbr_ior_from_f0_(_e17.z);
    eta3_2 = vec3<f32>(_e13, _e16, _e19);
    let _e22 = f_5;
    let _e24 = f_5;
    pi21_ = !((_e22.n2_ < _e24.n1_));
    let _e29 = eta3_2;
    let _e31 = f_5;
    let _e34 = pi21_;
    if ((_e29.x < _e31.n2_) != _e34) {
        local_11 = -1f;
    } else {
        local_11 = 1f;
    }
    let _e40 = local_11;
    let _e41 = eta3_2;
    let _e43 = f_5;
    let _e46 = pi21_;
    if ((_e41.y < _e43.n2_) != _e46) {
        local_12 = -1f;
    } else {
        local_12 = 1f;
    }
    let _e52 = local_12;
    let _e53 = eta3_2;
    let _e55 = f_5;
    let _e58 = pi21_;
    if ((_e53.z < _e55.n2_) != _e58) {
        local_13 = -1f;
    } else {
        local_13 = 1f;
    }
    let _e64 = local_13;
    cosPhi = vec3<f32>(_e40, _e52, _e64);
    let _e67 = cosPhi;
    let _e68 = f_5;
    let _e71 = pbr_iridescence_xyz_to_rec709_((_e67 * _e68.xyz1_));
    S1_2 = _e71;
    let _e73 = f_5;
    let _e74 = eta3_2;
    let _e76 = S1_2;
    let _e78 = f_5;
    let _e81 = pbr_iridescence_airy_channel(_e73, _e74.x, _e76.x, _e78.S2_.x);
    let _e82 = f_5;
    let _e83 = eta3_2;
    let _e85 = S1_2;
    let _e87 = f_5;
    let _e90 = pbr_iridescence_airy_channel(_e82, _e83.y, _e85.y, _e87.S2_.y);
    let _e91 = f_5;
    let _e92 = eta3_2;
    let _e94 = S1_2;
    let _e96 = f_5;
    let _e99 = pbr_iridescence_airy_channel(_e91, _e92.z, _e94.z, _e96.S2_.z);
    return vec3<f32>(_e81, _e90, _e99);
}

fn pbr_iridescence_select(f_6: pbr_ThinFilm, baseF0_2: vec3<f32>, I: vec3<f32>) -> vec3<f32> {
    var f_7: pbr_ThinFilm;
    var baseF0_3: vec3<f32>;
    var I_1: vec3<f32>;
    var local_14: vec3<f32>;
    var F: vec3<f32>;
    var noFilm: vec3<f32>;
    var local_15: vec3<f32>;

    f_7 = f_6;
    baseF0_3 = baseF0_2;
    I_1 = I;
    let _e6 = f_7;
    if (_e6.cos2Sq < 0f) {
        local_14 = vec3(1f);
    } else {
        let _e12 = I_1;
        let _e13 = pbr_saturate_1(_e12);
        local_14 = _e13;
    }
    let _e15 = local_14;
    F = _e15;
    let _e17 = baseF0_3;
    let _e18 = f_7;
    let _e20 = pbr_F_Schlick_1(_e17, _e18.c1_);
    noFilm = _e20;
    let _e22 = f_7;
    if (_e22.thicknessNm > 0f) {
        let _e26 = F;
        local_15 = _e26;
    } else {
        let _e27 = noFilm;
        local_15 = _e27;
    }
    let _e29 = local_15;
    return _e29;
}

fn pbr_F_Iridescence_thin_film(f_8: pbr_ThinFilm, baseF0_4: vec3<f32>) -> vec3<f32> {
    var f_9: pbr_ThinFilm;
    var baseF0_5: vec3<f32>;

    f_9 = f_8;
    baseF0_5 = baseF0_4;
    let _e4 = f_9;
    let _e5 = baseF0_5;
    let _e6 = f_9;
    let _e7 = baseF0_5;
    let _e8 = pbr_iridescence_airy(_e6, _e7);
    let _e9 = pbr_iridescence_select(_e4, _e5, _e8);
    return _e9;
}

fn pbr_F_Iridescence(outsideIor_2: f32, filmIor_2: f32, cosTheta1_2: f32, thicknessNm_2: f32, baseF0_6: vec3<f32>) -> vec3<f32> {
    var outsideIor_3: f32;
    var filmIor_3: f32;
    var cosTheta1_3: f32;
    var thicknessNm_3: f32;
    var baseF0_7: vec3<f32>;

    outsideIor_3 = outsideIor_2;
    filmIor_3 = filmIor_2;
    cosTheta1_3 = cosTheta1_2;
    thicknessNm_3 = thicknessNm_2;
    baseF0_7 = baseF0_6;
    let _e10 = outsideIor_3;
    let _e11 = filmIor_3;
    let _e12 = cosTheta1_3;
    let _e13 = thicknessNm_3;
    let _e14 = pbr_thin_film(_e10, _e11, _e12, _e13);
    let _e15 = baseF0_7;
    let _e16 = pbr_F_Iridescence_thin_film(_e14, _e15);
    return _e16;
}

fn pbr_iridescence_mix(F_1: vec3<f32>, Firidescence: vec3<f32>, iridescenceFactor: f32) -> vec3<f32> {
    var F_2: vec3<f32>;
    var Firidescence_1: vec3<f32>;
    var iridescenceFactor_1: f32;

    F_2 = F_1;
    Firidescence_1 = Firidescence;
    iridescenceFactor_1 = iridescenceFactor;
    let _e6 = F_2;
    let _e7 = Firidescence_1;
    let _e8 = iridescenceFactor_1;
    let _e9 = pbr_saturate(_e8);
    return mix(_e6, _e7, vec3(_e9));
}

fn pbr_iridescence_thickness(thicknessMin: f32, thicknessMax: f32, textureG: f32) -> f32 {
    var thicknessMin_1: f32;
    var thicknessMax_1: f32;
    var textureG_1: f32;

    thicknessMin_1 = thicknessMin;
    thicknessMax_1 = thicknessMax;
    textureG_1 = textureG;
    let _e6 = thicknessMin_1;
    let _e7 = thicknessMax_1;
    let _e8 = textureG_1;
    let _e9 = pbr_saturate(_e8);
    return mix(_e6, _e7, _e9);
}

fn pbr_D_Charlie(NdotH_24: f32, alpha_42: f32) -> f32 {
    var NdotH_25: f32;
    var alpha_43: f32;
    var invAlpha: f32;
    var sin2h: f32;

    NdotH_25 = NdotH_24;
    alpha_43 = alpha_42;
    let _e4 = alpha_43;
    alpha_43 = clamp(_e4, 0.0049f, 1f);
    let _e8 = NdotH_25;
    let _e9 = pbr_saturate(_e8);
    NdotH_25 = _e9;
    let _e11 = alpha_43;
    invAlpha = (1f / _e11);
    let _e15 = NdotH_25;
    let _e18 = NdotH_25;
    sin2h = ((1f - _e15) * (1f + _e18));
    let _e23 = invAlpha;
    let _e25 = sin2h;
    let _e27 = invAlpha;
    let _e29 = pbr_pow_safe(_e25, (0.5f * _e27));
    return (((2f + _e23) * _e29) * 0.15915494f);
}

fn pbr_sheen_lambda_exponent(x_16: f32, alpha_44: f32) -> f32 {
    var x_17: f32;
    var alpha_45: f32;
    var r_4: f32;
    var t: f32;
    var a_6: f32;
    var b_3: f32;
    var c_19: f32;
    var d: f32;
    var e: f32;

    x_17 = x_16;
    alpha_45 = alpha_44;
    let _e4 = alpha_45;
    let _e5 = pbr_saturate(_e4);
    r_4 = _e5;
    let _e8 = r_4;
    let _e11 = r_4;
    t = ((1f - _e8) * (1f - _e11));
    let _e17 = t;
    a_6 = mix(21.5473f, 25.3245f, _e17);
    let _e22 = t;
    b_3 = mix(3.82987f, 3.32435f, _e22);
    let _e27 = t;
    c_19 = mix(0.19823f, 0.16801f, _e27);
    let _e34 = t;
    d = mix(-1.9776f, -1.27393f, _e34);
    let _e41 = t;
    e = mix(-4.32054f, -4.85967f, _e41);
    let _e44 = x_17;
    x_17 = clamp(_e44, 0f, 0.5f);
    let _e48 = a_6;
    let _e50 = b_3;
    let _e51 = x_17;
    let _e52 = c_19;
    let _e53 = pbr_pow_safe(_e51, _e52);
    let _e57 = d;
    let _e58 = x_17;
    let _e61 = e;
    return (((_e48 / (1f + (_e50 * _e53))) + (_e57 * _e58)) + _e61);
}

fn pbr_sheen_lambda(cosTheta_4: f32, alpha_46: f32) -> f32 {
    var cosTheta_5: f32;
    var alpha_47: f32;
    var below: bool;
    var local_16: f32;
    var L: f32;
    var local_17: f32;

    cosTheta_5 = cosTheta_4;
    alpha_47 = alpha_46;
    let _e4 = cosTheta_5;
    cosTheta_5 = clamp(_e4, 0.0001f, 1f);
    let _e8 = alpha_47;
    alpha_47 = clamp(_e8, 0.0049f, 1f);
    let _e12 = cosTheta_5;
    below = (_e12 < 0.5f);
    let _e16 = below;
    if _e16 {
        let _e17 = cosTheta_5;
        local_16 = _e17;
    } else {
        let _e19 = cosTheta_5;
        local_16 = (1f - _e19);
    }
    let _e22 = local_16;
    let _e23 = alpha_47;
    let _e24 = pbr_sheen_lambda_exponent(_e22, _e23);
    L = _e24;
    let _e26 = below;
    if _e26 {
        let _e27 = L;
        local_17 = _e27;
    } else {
        let _e30 = alpha_47;
        let _e31 = pbr_sheen_lambda_exponent(0.5f, _e30);
        let _e33 = L;
        local_17 = ((2f * _e31) - _e33);
    }
    let _e36 = local_17;
    return exp(_e36);
}

fn pbr_V_Charlie(NdotL_37: f32, NdotV_35: f32, alpha_48: f32) -> f32 {
    var NdotL_38: f32;
    var NdotV_36: f32;
    var alpha_49: f32;
    var g2inv: f32;

    NdotL_38 = NdotL_37;
    NdotV_36 = NdotV_35;
    alpha_49 = alpha_48;
    let _e6 = NdotL_38;
    NdotL_38 = clamp(_e6, 0.0001f, 1f);
    let _e10 = NdotV_36;
    NdotV_36 = clamp(_e10, 0.0001f, 1f);
    let _e15 = NdotV_36;
    let _e16 = alpha_49;
    let _e17 = pbr_sheen_lambda(_e15, _e16);
    let _e19 = NdotL_38;
    let _e20 = alpha_49;
    let _e21 = pbr_sheen_lambda(_e19, _e20);
    g2inv = ((1f + _e17) + _e21);
    let _e25 = g2inv;
    let _e28 = NdotV_36;
    let _e30 = NdotL_38;
    return (1f / (((_e25 * 4f) * _e28) * _e30));
}

fn pbr_V_Neubelt(NdotL_39: f32, NdotV_37: f32) -> f32 {
    var NdotL_40: f32;
    var NdotV_38: f32;

    NdotL_40 = NdotL_39;
    NdotV_38 = NdotV_37;
    let _e4 = NdotL_40;
    NdotL_40 = clamp(_e4, 0.0001f, 1f);
    let _e8 = NdotV_38;
    NdotV_38 = clamp(_e8, 0.0001f, 1f);
    let _e14 = NdotL_40;
    let _e15 = NdotV_38;
    let _e17 = NdotL_40;
    let _e18 = NdotV_38;
    return (1f / (4f * ((_e14 + _e15) - (_e17 * _e18))));
}

fn pbr_specular_D(NdotH_26: f32, oneMinusNdotH2_4: f32, alpha_50: f32) -> f32 {
    var NdotH_27: f32;
    var oneMinusNdotH2_5: f32;
    var alpha_51: f32;

    NdotH_27 = NdotH_26;
    oneMinusNdotH2_5 = oneMinusNdotH2_4;
    alpha_51 = alpha_50;
    let _e6 = NdotH_27;
    let _e7 = oneMinusNdotH2_5;
    let _e8 = alpha_51;
    let _e9 = pbr_D_GGX_fromOneMinusNdotH2_(_e6, _e7, _e8);
    return _e9;
}

fn pbr_specular_V(NdotL_41: f32, NdotV_39: f32, NdotH_28: f32, VdotH_19: f32, alpha_52: f32) -> f32 {
    var NdotL_42: f32;
    var NdotV_40: f32;
    var NdotH_29: f32;
    var VdotH_20: f32;
    var alpha_53: f32;

    NdotL_42 = NdotL_41;
    NdotV_40 = NdotV_39;
    NdotH_29 = NdotH_28;
    VdotH_20 = VdotH_19;
    alpha_53 = alpha_52;
    let _e10 = NdotL_42;
    let _e11 = NdotV_40;
    let _e12 = alpha_53;
    let _e13 = pbr_V_SmithGGXCorrelated(_e10, _e11, _e12);
    return _e13;
}

fn pbr_specular_DV(nDotH_10: f32, nCrossH2_10: f32, h2_10: f32, NdotL_43: f32, NdotV_41: f32, VdotH_21: f32, alpha_54: f32) -> f32 {
    var nDotH_11: f32;
    var nCrossH2_11: f32;
    var h2_11: f32;
    var NdotL_44: f32;
    var NdotV_42: f32;
    var VdotH_22: f32;
    var alpha_55: f32;

    nDotH_11 = nDotH_10;
    nCrossH2_11 = nCrossH2_10;
    h2_11 = h2_10;
    NdotL_44 = NdotL_43;
    NdotV_42 = NdotV_41;
    VdotH_22 = VdotH_21;
    alpha_55 = alpha_54;
    let _e14 = nDotH_11;
    let _e15 = nCrossH2_11;
    let _e16 = h2_11;
    let _e17 = NdotL_44;
    let _e18 = NdotV_42;
    let _e19 = alpha_55;
    let _e20 = pbr_DV_GGX_SmithCorrelated(_e14, _e15, _e16, _e17, _e18, _e19);
    return _e20;
}

fn pbr_specular_F_f90_(f0_15: vec3<f32>, f90_4: f32, VdotH_23: f32) -> vec3<f32> {
    var f0_16: vec3<f32>;
    var f90_5: f32;
    var VdotH_24: f32;

    f0_16 = f0_15;
    f90_5 = f90_4;
    VdotH_24 = VdotH_23;
    let _e6 = f0_16;
    let _e7 = f90_5;
    let _e8 = VdotH_24;
    let _e9 = pbr_F_Schlick_2(_e6, _e7, _e8);
    return _e9;
}

fn pbr_specular_F(f0_17: vec3<f32>, VdotH_25: f32) -> vec3<f32> {
    var f0_18: vec3<f32>;
    var VdotH_26: f32;

    f0_18 = f0_17;
    VdotH_26 = VdotH_25;
    let _e4 = f0_18;
    let _e5 = f0_18;
    let _e6 = pbr_f90_from_f0_(_e5);
    let _e7 = VdotH_26;
    let _e8 = pbr_specular_F_f90_(_e4, _e6, _e7);
    return _e8;
}

fn pbr_specular_F_deviation_bound_f90_(f0_19: vec3<f32>, f90_6: f32) -> vec3<f32> {
    var f0_20: vec3<f32>;
    var f90_7: f32;

    f0_20 = f0_19;
    f90_7 = f90_6;
    return vec3(0f);
}

fn pbr_specular_F_deviation_bound(f0_21: vec3<f32>) -> vec3<f32> {
    var f0_22: vec3<f32>;

    f0_22 = f0_21;
    let _e2 = f0_22;
    let _e3 = f0_22;
    let _e4 = pbr_f90_from_f0_(_e3);
    let _e5 = pbr_specular_F_deviation_bound_f90_(_e2, _e4);
    return _e5;
}

fn pbr_specular_lobe_limit(DV: f32) -> f32 {
    var DV_1: f32;

    DV_1 = DV;
    let _e2 = DV_1;
    return _e2;
}

fn pbr_diffuse_Fd(NdotV_43: f32, NdotL_45: f32, LdotH_3: f32, perceptualRoughness_6: f32) -> f32 {
    var NdotV_44: f32;
    var NdotL_46: f32;
    var LdotH_4: f32;
    var perceptualRoughness_7: f32;

    NdotV_44 = NdotV_43;
    NdotL_46 = NdotL_45;
    LdotH_4 = LdotH_3;
    perceptualRoughness_7 = perceptualRoughness_6;
    let _e8 = pbr_Fd_Lambert();
    return _e8;
}

fn pbr_clamp_perceptual_roughness(perceptualRoughness_8: f32) -> f32 {
    var perceptualRoughness_9: f32;

    perceptualRoughness_9 = perceptualRoughness_8;
    let _e2 = perceptualRoughness_9;
    return clamp(_e2, 0.045f, 1f);
}

fn pbr_brdf_standard_terms(n_6: vec3<f32>, v_10: vec3<f32>, l_4: vec3<f32>, perceptualRoughness_10: f32, piFd: ptr<function, f32>, piDV: ptr<function, f32>, LdotH_5: ptr<function, f32>) {
    var n_7: vec3<f32>;
    var v_11: vec3<f32>;
    var l_5: vec3<f32>;
    var perceptualRoughness_11: f32;
    var NdotL_47: f32;
    var nDotV: f32;
    var NdotV_45: f32;
    var roughness: f32;
    var alpha_56: f32;
    var halfSum: vec3<f32>;
    var halfLength2_: f32;
    var nDotHalfSum: f32;
    var halfRejection: vec3<f32>;
    var local_18: f32;

    n_7 = n_6;
    v_11 = v_10;
    l_5 = l_4;
    perceptualRoughness_11 = perceptualRoughness_10;
    let _e11 = n_7;
    let _e12 = l_5;
    NdotL_47 = clamp(dot(_e11, _e12), 0f, 1f);
    let _e18 = n_7;
    let _e19 = v_11;
    nDotV = dot(_e18, _e19);
    let _e22 = nDotV;
    NdotV_45 = clamp(_e22, 0.0001f, 1f);
    let _e27 = perceptualRoughness_11;
    let _e28 = pbr_clamp_perceptual_roughness(_e27);
    roughness = _e28;
    let _e30 = roughness;
    let _e31 = pbr_alpha_from_perceptual_roughness(_e30);
    alpha_56 = _e31;
    let _e33 = l_5;
    let _e34 = v_11;
    halfSum = (_e33 + _e34);
    let _e37 = halfSum;
    let _e38 = pbr_length2_nonzero(_e37);
    halfLength2_ = _e38;
    let _e41 = halfLength2_;
    (*LdotH_5) = (0.5f * sqrt(_e41));
    let _e44 = NdotL_47;
    let _e45 = nDotV;
    nDotHalfSum = (_e44 + _e45);
    let _e48 = halfSum;
    let _e49 = nDotHalfSum;
    let _e50 = n_7;
    halfRejection = (_e48 - (_e49 * _e50));
    let _e55 = NdotV_45;
    let _e56 = NdotL_47;
    let _e57 = (*LdotH_5);
    let _e58 = roughness;
    let _e59 = pbr_diffuse_Fd(_e55, _e56, _e57, _e58);
    (*piFd) = (3.1415927f * _e59);
    let _e62 = nDotHalfSum;
    let _e63 = halfRejection;
    let _e64 = halfRejection;
    let _e66 = halfLength2_;
    let _e67 = NdotL_47;
    let _e68 = NdotV_45;
    let _e69 = (*LdotH_5);
    let _e70 = alpha_56;
    let _e71 = pbr_specular_DV(_e62, dot(_e63, _e64), _e66, _e67, _e68, _e69, _e70);
    let _e72 = pbr_specular_lobe_limit(_e71);
    (*piDV) = (3.1415927f * _e72);
    let _e74 = nDotHalfSum;
    if (_e74 >= 0.0000000000000008881784f) {
        let _e77 = (*piDV);
        local_18 = _e77;
    } else {
        local_18 = 0f;
    }
    let _e80 = local_18;
    (*piDV) = _e80;
    return;
}

fn pbr_brdf_standard(n_8: vec3<f32>, v_12: vec3<f32>, l_6: vec3<f32>, diffuseColor: vec3<f32>, f0_23: vec3<f32>, perceptualRoughness_12: f32) -> vec3<f32> {
    var n_9: vec3<f32>;
    var v_13: vec3<f32>;
    var l_7: vec3<f32>;
    var diffuseColor_1: vec3<f32>;
    var f0_24: vec3<f32>;
    var perceptualRoughness_13: f32;
    var piFd_1: f32;
    var piDV_1: f32;
    var LdotH_6: f32;

    n_9 = n_8;
    v_13 = v_12;
    l_7 = l_6;
    diffuseColor_1 = diffuseColor;
    f0_24 = f0_23;
    perceptualRoughness_13 = perceptualRoughness_12;
    let _e15 = n_9;
    let _e16 = v_13;
    let _e17 = l_7;
    let _e18 = perceptualRoughness_13;
    pbr_brdf_standard_terms(_e15, _e16, _e17, _e18, (&piFd_1), (&piDV_1), (&LdotH_6));
    let _e25 = diffuseColor_1;
    let _e26 = piFd_1;
    let _e28 = piDV_1;
    let _e29 = f0_24;
    let _e30 = LdotH_6;
    let _e31 = pbr_specular_F(_e29, _e30);
    return (((_e25 * _e26) + (_e28 * _e31)) * 0.31830987f);
}

fn pbr_brdf_standard_f90_(n_10: vec3<f32>, v_14: vec3<f32>, l_8: vec3<f32>, diffuseColor_2: vec3<f32>, f0_25: vec3<f32>, f90_8: f32, perceptualRoughness_14: f32) -> vec3<f32> {
    var n_11: vec3<f32>;
    var v_15: vec3<f32>;
    var l_9: vec3<f32>;
    var diffuseColor_3: vec3<f32>;
    var f0_26: vec3<f32>;
    var f90_9: f32;
    var perceptualRoughness_15: f32;
    var piFd_2: f32;
    var piDV_2: f32;
    var LdotH_7: f32;

    n_11 = n_10;
    v_15 = v_14;
    l_9 = l_8;
    diffuseColor_3 = diffuseColor_2;
    f0_26 = f0_25;
    f90_9 = f90_8;
    perceptualRoughness_15 = perceptualRoughness_14;
    let _e17 = n_11;
    let _e18 = v_15;
    let _e19 = l_9;
    let _e20 = perceptualRoughness_15;
    pbr_brdf_standard_terms(_e17, _e18, _e19, _e20, (&piFd_2), (&piDV_2), (&LdotH_7));
    let _e27 = diffuseColor_3;
    let _e28 = piFd_2;
    let _e30 = piDV_2;
    let _e31 = f0_26;
    let _e32 = f90_9;
    let _e33 = LdotH_7;
    let _e34 = pbr_specular_F_f90_(_e31, _e32, _e33);
    return (((_e27 * _e28) + (_e30 * _e34)) * 0.31830987f);
}

fn pbr_diffuse_albedo_from_diffuse_color(diffuseColor_4: vec3<f32>, coatF0_: vec3<f32>) -> vec3<f32> {
    var diffuseColor_5: vec3<f32>;
    var coatF0_1: vec3<f32>;
    var oneMinusReflectivity: f32;

    diffuseColor_5 = diffuseColor_4;
    coatF0_1 = coatF0_;
    let _e5 = coatF0_1;
    let _e6 = pbr_max3_(_e5);
    oneMinusReflectivity = max((1f - _e6), 0.0001f);
    let _e11 = diffuseColor_5;
    let _e12 = oneMinusReflectivity;
    return min((_e11 / vec3(_e12)), vec3(1f));
}

fn pbr_coupled_diffuse_color(diffuseColor_6: vec3<f32>, coatF0_2: vec3<f32>, coatAlbedo: vec3<f32>) -> vec3<f32> {
    var diffuseColor_7: vec3<f32>;
    var coatF0_3: vec3<f32>;
    var coatAlbedo_1: vec3<f32>;

    diffuseColor_7 = diffuseColor_6;
    coatF0_3 = coatF0_2;
    coatAlbedo_1 = coatAlbedo;
    let _e6 = diffuseColor_7;
    let _e7 = coatF0_3;
    let _e8 = pbr_diffuse_albedo_from_diffuse_color(_e6, _e7);
    let _e11 = coatAlbedo_1;
    let _e12 = pbr_saturate_1(_e11);
    return (_e8 * (vec3(1f) - _e12));
}

fn pbr_shade_punctual(n_12: vec3<f32>, v_16: vec3<f32>, l_10: vec3<f32>, lightRadiance: vec3<f32>, diffuseColor_8: vec3<f32>, f0_27: vec3<f32>, perceptualRoughness_16: f32) -> vec3<f32> {
    var n_13: vec3<f32>;
    var v_17: vec3<f32>;
    var l_11: vec3<f32>;
    var lightRadiance_1: vec3<f32>;
    var diffuseColor_9: vec3<f32>;
    var f0_28: vec3<f32>;
    var perceptualRoughness_17: f32;
    var NdotL_48: f32;
    var piFd_3: f32;
    var piDV_3: f32;
    var LdotH_8: f32;
    var piBrdf: vec3<f32>;

    n_13 = n_12;
    v_17 = v_16;
    l_11 = l_10;
    lightRadiance_1 = lightRadiance;
    diffuseColor_9 = diffuseColor_8;
    f0_28 = f0_27;
    perceptualRoughness_17 = perceptualRoughness_16;
    let _e14 = n_13;
    let _e15 = l_11;
    NdotL_48 = clamp(dot(_e14, _e15), 0f, 1f);
    let _e24 = n_13;
    let _e25 = v_17;
    let _e26 = l_11;
    let _e27 = perceptualRoughness_17;
    pbr_brdf_standard_terms(_e24, _e25, _e26, _e27, (&piFd_3), (&piDV_3), (&LdotH_8));
    let _e34 = diffuseColor_9;
    let _e35 = piFd_3;
    let _e37 = piDV_3;
    let _e38 = f0_28;
    let _e39 = LdotH_8;
    let _e40 = pbr_specular_F(_e38, _e39);
    piBrdf = ((_e34 * _e35) + (_e37 * _e40));
    let _e44 = lightRadiance_1;
    let _e45 = piBrdf;
    let _e47 = NdotL_48;
    return ((_e44 * _e45) * _e47);
}

fn pbr_shade_punctual_f90_(n_14: vec3<f32>, v_18: vec3<f32>, l_12: vec3<f32>, lightRadiance_2: vec3<f32>, diffuseColor_10: vec3<f32>, f0_29: vec3<f32>, f90_10: f32, perceptualRoughness_18: f32) -> vec3<f32> {
    var n_15: vec3<f32>;
    var v_19: vec3<f32>;
    var l_13: vec3<f32>;
    var lightRadiance_3: vec3<f32>;
    var diffuseColor_11: vec3<f32>;
    var f0_30: vec3<f32>;
    var f90_11: f32;
    var perceptualRoughness_19: f32;
    var NdotL_49: f32;
    var piFd_4: f32;
    var piDV_4: f32;
    var LdotH_9: f32;
    var piBrdf_1: vec3<f32>;

    n_15 = n_14;
    v_19 = v_18;
    l_13 = l_12;
    lightRadiance_3 = lightRadiance_2;
    diffuseColor_11 = diffuseColor_10;
    f0_30 = f0_29;
    f90_11 = f90_10;
    perceptualRoughness_19 = perceptualRoughness_18;
    let _e16 = n_15;
    let _e17 = l_13;
    NdotL_49 = clamp(dot(_e16, _e17), 0f, 1f);
    let _e26 = n_15;
    let _e27 = v_19;
    let _e28 = l_13;
    let _e29 = perceptualRoughness_19;
    pbr_brdf_standard_terms(_e26, _e27, _e28, _e29, (&piFd_4), (&piDV_4), (&LdotH_9));
    let _e36 = diffuseColor_11;
    let _e37 = piFd_4;
    let _e39 = piDV_4;
    let _e40 = f0_30;
    let _e41 = f90_11;
    let _e42 = LdotH_9;
    let _e43 = pbr_specular_F_f90_(_e40, _e41, _e42);
    piBrdf_1 = ((_e36 * _e37) + (_e39 * _e43));
    let _e47 = lightRadiance_3;
    let _e48 = piBrdf_1;
    let _e50 = NdotL_49;
    return ((_e47 * _e48) * _e50);
}

fn pbr_env_brdf_approx(NdotV_46: f32, perceptualRoughness_20: f32) -> vec2<f32> {
    var NdotV_47: f32;
    var perceptualRoughness_21: f32;
    var c0_: vec4<f32> = vec4<f32>(-1f, -0.0275f, -0.572f, 0.022f);
    var c1_: vec4<f32> = vec4<f32>(1f, 0.0425f, 1.04f, -0.04f);
    var r_5: vec4<f32>;
    var a004_: f32;

    NdotV_47 = NdotV_46;
    perceptualRoughness_21 = perceptualRoughness_20;
    let _e20 = perceptualRoughness_21;
    let _e21 = c0_;
    let _e23 = c1_;
    r_5 = ((_e20 * _e21) + _e23);
    let _e26 = r_5;
    let _e28 = r_5;
    let _e33 = NdotV_47;
    let _e37 = r_5;
    let _e40 = r_5;
    a004_ = ((min((_e26.x * _e28.x), exp2((-9.28f * _e33))) * _e37.x) + _e40.y);
    let _e48 = a004_;
    let _e50 = r_5;
    return ((vec2<f32>(-1.04f, 1.04f) * _e48) + _e50.zw);
}

fn pbr_dfg_lut_uv(NdotV_48: f32, perceptualRoughness_22: f32) -> vec2<f32> {
    var NdotV_49: f32;
    var perceptualRoughness_23: f32;
    var size: vec2<f32> = vec2<f32>(256f, 256f);
    var alpha_57: f32;
    var x_18: f32;
    var y: f32;
    var xy: vec2<f32>;

    NdotV_49 = NdotV_48;
    perceptualRoughness_23 = perceptualRoughness_22;
    let _e8 = perceptualRoughness_23;
    let _e9 = perceptualRoughness_23;
    alpha_57 = (_e8 * _e9);
    let _e13 = NdotV_49;
    let _e14 = pbr_saturate(_e13);
    x_18 = (log2((1f + (_e14 * 333.33334f))) * 0.119258545f);
    let _e22 = alpha_57;
    let _e23 = pbr_saturate(_e22);
    y = (log2(((_e23 + 0.003f) * 199.00497f)) * 0.13087323f);
    let _e32 = x_18;
    let _e33 = y;
    xy = clamp(vec2<f32>(_e32, _e33), vec2(0f), vec2(1f));
    let _e41 = xy;
    let _e42 = size;
    let _e46 = size;
    let _e50 = size;
    return ((_e41 * ((_e42 - vec2(1f)) / _e46)) + (vec2(0.5f) / _e50));
}

fn pbr_env_brdf(NdotV_50: f32, perceptualRoughness_24: f32) -> vec2<f32> {
    var NdotV_51: f32;
    var perceptualRoughness_25: f32;

    NdotV_51 = NdotV_50;
    perceptualRoughness_25 = perceptualRoughness_24;
    let _e4 = NdotV_51;
    let _e5 = perceptualRoughness_25;
    let _e6 = pbr_env_brdf_approx(_e4, _e5);
    return _e6;
}

fn pbr_specular_albedo_f90_(f0_31: vec3<f32>, f90_12: f32, dfg: vec2<f32>) -> vec3<f32> {
    var f0_32: vec3<f32>;
    var f90_13: f32;
    var dfg_1: vec2<f32>;

    f0_32 = f0_31;
    f90_13 = f90_12;
    dfg_1 = dfg;
    let _e6 = f0_32;
    let _e7 = dfg_1;
    let _e10 = f90_13;
    let _e11 = dfg_1;
    return ((_e6 * _e7.x) + vec3((_e10 * _e11.y)));
}

fn pbr_specular_albedo(f0_33: vec3<f32>, dfg_2: vec2<f32>) -> vec3<f32> {
    var f0_34: vec3<f32>;
    var dfg_3: vec2<f32>;

    f0_34 = f0_33;
    dfg_3 = dfg_2;
    let _e4 = f0_34;
    let _e5 = f0_34;
    let _e6 = pbr_f90_from_f0_(_e5);
    let _e7 = dfg_3;
    let _e8 = pbr_specular_albedo_f90_(_e4, _e6, _e7);
    return _e8;
}

fn pbr_specular_albedo_bound_f90_(f0_35: vec3<f32>, f90_14: f32, dfg_4: vec2<f32>) -> vec3<f32> {
    var f0_36: vec3<f32>;
    var f90_15: f32;
    var dfg_5: vec2<f32>;

    f0_36 = f0_35;
    f90_15 = f90_14;
    dfg_5 = dfg_4;
    let _e6 = f0_36;
    let _e7 = f90_15;
    let _e8 = dfg_5;
    let _e9 = pbr_specular_albedo_f90_(_e6, _e7, _e8);
    let _e10 = f0_36;
    let _e11 = f90_15;
    let _e12 = pbr_specular_F_deviation_bound_f90_(_e10, _e11);
    let _e13 = dfg_5;
    let _e15 = dfg_5;
    return (_e9 + (_e12 * (_e13.x + _e15.y)));
}

fn pbr_specular_albedo_bound(f0_37: vec3<f32>, dfg_6: vec2<f32>) -> vec3<f32> {
    var f0_38: vec3<f32>;
    var dfg_7: vec2<f32>;

    f0_38 = f0_37;
    dfg_7 = dfg_6;
    let _e4 = f0_38;
    let _e5 = f0_38;
    let _e6 = pbr_f90_from_f0_(_e5);
    let _e7 = dfg_7;
    let _e8 = pbr_specular_albedo_bound_f90_(_e4, _e6, _e7);
    return _e8;
}

fn pbr_energy_compensation(f0_39: vec3<f32>, dfg_8: vec2<f32>) -> vec3<f32> {
    var f0_40: vec3<f32>;
    var dfg_9: vec2<f32>;

    f0_40 = f0_39;
    dfg_9 = dfg_8;
    let _e5 = f0_40;
    let _e7 = dfg_9;
    let _e9 = dfg_9;
    return (vec3(1f) + (_e5 * ((1f / max((_e7.x + _e9.y), 0.0001f)) - 1f)));
}

fn pbr_specular_occlusion(NdotV_52: f32, occlusion: f32, alpha_58: f32) -> f32 {
    var NdotV_53: f32;
    var occlusion_1: f32;
    var alpha_59: f32;

    NdotV_53 = NdotV_52;
    occlusion_1 = occlusion;
    alpha_59 = alpha_58;
    let _e6 = NdotV_53;
    let _e7 = occlusion_1;
    let _e11 = alpha_59;
    let _e19 = occlusion_1;
    return clamp(((pow((_e6 + _e7), exp2(((-16f * _e11) - 1f))) - 1f) + _e19), 0f, 1f);
}

fn pbr_ibl_lod_from_perceptual_roughness(perceptualRoughness_26: f32, lodCount: f32) -> f32 {
    var perceptualRoughness_27: f32;
    var lodCount_1: f32;

    perceptualRoughness_27 = perceptualRoughness_26;
    lodCount_1 = lodCount;
    let _e4 = perceptualRoughness_27;
    let _e5 = lodCount_1;
    return (_e4 * (_e5 - 1f));
}

fn pbr_clearcoat_punctual(nc: vec3<f32>, v_20: vec3<f32>, l_14: vec3<f32>, lightRadiance_4: vec3<f32>, coatPerceptualRoughness: f32) -> vec3<f32> {
    var nc_1: vec3<f32>;
    var v_21: vec3<f32>;
    var l_15: vec3<f32>;
    var lightRadiance_5: vec3<f32>;
    var coatPerceptualRoughness_1: f32;

    nc_1 = nc;
    v_21 = v_20;
    l_15 = l_14;
    lightRadiance_5 = lightRadiance_4;
    coatPerceptualRoughness_1 = coatPerceptualRoughness;
    let _e10 = nc_1;
    let _e11 = v_21;
    let _e12 = l_15;
    let _e13 = lightRadiance_5;
    let _e18 = coatPerceptualRoughness_1;
    let _e19 = pbr_shade_punctual(_e10, _e11, _e12, _e13, vec3(0f), vec3(0.04f), _e18);
    return _e19;
}

fn pbr_clearcoat_albedo(dfgCoat: vec2<f32>) -> f32 {
    var dfgCoat_1: vec2<f32>;

    dfgCoat_1 = dfgCoat;
    let _e3 = dfgCoat_1;
    let _e8 = pbr_f90_from_f0_(vec3(0.04f));
    let _e9 = dfgCoat_1;
    let _e13 = pbr_saturate(((0.04f * _e3.x) + (_e8 * _e9.y)));
    return _e13;
}

fn pbr_clearcoat_base_weight(coatMask: f32, NcdotV: f32, dfgCoat_2: vec2<f32>) -> f32 {
    var coatMask_1: f32;
    var NcdotV_1: f32;
    var dfgCoat_3: vec2<f32>;
    var reflected: f32;

    coatMask_1 = coatMask;
    NcdotV_1 = NcdotV;
    dfgCoat_3 = dfgCoat_2;
    let _e6 = dfgCoat_3;
    let _e7 = pbr_clearcoat_albedo(_e6);
    reflected = _e7;
    let _e10 = coatMask_1;
    let _e11 = reflected;
    return (1f - (_e10 * _e11));
}

fn pbr_anisotropic_alphas(alpha_60: f32, strength: f32) -> vec2<f32> {
    var alpha_61: f32;
    var strength_1: f32;
    var strength2_: f32;

    alpha_61 = alpha_60;
    strength_1 = strength;
    let _e4 = strength_1;
    let _e5 = strength_1;
    strength2_ = min((_e4 * _e5), 1f);
    let _e10 = alpha_61;
    let _e11 = pbr_saturate(_e10);
    alpha_61 = _e11;
    let _e12 = alpha_61;
    let _e14 = strength2_;
    let _e16 = alpha_61;
    return vec2<f32>(mix(_e12, 1f, _e14), _e16);
}

fn pbr_anisotropy_direction(t_1: vec3<f32>, b_4: vec3<f32>, directionSample: vec2<f32>, rotation: f32) -> vec3<f32> {
    var t_2: vec3<f32>;
    var b_5: vec3<f32>;
    var directionSample_1: vec2<f32>;
    var rotation_1: f32;
    var hasDirection: bool;
    var local_19: f32;
    var x_19: f32;
    var local_20: f32;
    var y_1: f32;
    var c_20: f32;
    var s_5: f32;

    t_2 = t_1;
    b_5 = b_4;
    directionSample_1 = directionSample;
    rotation_1 = rotation;
    let _e8 = directionSample_1;
    let _e9 = directionSample_1;
    hasDirection = (dot(_e8, _e9) >= 0.000000000000000000000000000000000000011754944f);
    let _e14 = hasDirection;
    if _e14 {
        let _e15 = directionSample_1;
        local_19 = _e15.x;
    } else {
        local_19 = 1f;
    }
    let _e19 = local_19;
    x_19 = _e19;
    let _e21 = hasDirection;
    if _e21 {
        let _e22 = directionSample_1;
        local_20 = _e22.y;
    } else {
        local_20 = 0f;
    }
    let _e26 = local_20;
    y_1 = _e26;
    let _e28 = rotation_1;
    c_20 = cos(_e28);
    let _e31 = rotation_1;
    s_5 = sin(_e31);
    let _e34 = t_2;
    let _e35 = c_20;
    let _e36 = x_19;
    let _e38 = s_5;
    let _e39 = y_1;
    let _e43 = b_5;
    let _e44 = s_5;
    let _e45 = x_19;
    let _e47 = c_20;
    let _e48 = y_1;
    let _e53 = pbr_safe_normalize(((_e34 * ((_e35 * _e36) - (_e38 * _e39))) + (_e43 * ((_e44 * _e45) + (_e47 * _e48)))));
    return _e53;
}

fn pbr_brdf_anisotropic_terms(n_16: vec3<f32>, v_22: vec3<f32>, l_16: vec3<f32>, t_3: vec3<f32>, b_6: vec3<f32>, perceptualRoughness_28: f32, strength_2: f32, DV_2: ptr<function, f32>, LdotH_10: ptr<function, f32>) {
    var n_17: vec3<f32>;
    var v_23: vec3<f32>;
    var l_17: vec3<f32>;
    var t_4: vec3<f32>;
    var b_7: vec3<f32>;
    var perceptualRoughness_29: f32;
    var strength_3: f32;
    var NdotL_50: f32;
    var NdotV_54: f32;
    var roughness_1: f32;
    var alphas: vec2<f32>;
    var halfSum_1: vec3<f32>;
    var halfLength2_1: f32;
    var invHalfLength: f32;
    var nDotHalfSum_1: f32;
    var D_1: f32;
    var V: f32;
    var local_21: f32;

    n_17 = n_16;
    v_23 = v_22;
    l_17 = l_16;
    t_4 = t_3;
    b_7 = b_6;
    perceptualRoughness_29 = perceptualRoughness_28;
    strength_3 = strength_2;
    let _e16 = n_17;
    let _e17 = l_17;
    NdotL_50 = dot(_e16, _e17);
    let _e20 = n_17;
    let _e21 = v_23;
    NdotV_54 = clamp(dot(_e20, _e21), 0.0001f, 1f);
    let _e27 = perceptualRoughness_29;
    let _e28 = pbr_clamp_perceptual_roughness(_e27);
    roughness_1 = _e28;
    let _e30 = roughness_1;
    let _e31 = pbr_alpha_from_perceptual_roughness(_e30);
    let _e32 = strength_3;
    let _e33 = pbr_anisotropic_alphas(_e31, _e32);
    alphas = _e33;
    let _e35 = l_17;
    let _e36 = v_23;
    halfSum_1 = (_e35 + _e36);
    let _e39 = halfSum_1;
    let _e40 = halfSum_1;
    halfLength2_1 = dot(_e39, _e40);
    let _e44 = halfLength2_1;
    (*LdotH_10) = (0.5f * sqrt(_e44));
    let _e47 = halfLength2_1;
    invHalfLength = inverseSqrt(clamp(_e47, 0.0000000000000000000000000000007888609f, 4f));
    let _e55 = n_17;
    let _e56 = halfSum_1;
    nDotHalfSum_1 = dot(_e55, _e56);
    let _e59 = nDotHalfSum_1;
    let _e60 = invHalfLength;
    let _e62 = t_4;
    let _e63 = halfSum_1;
    let _e65 = invHalfLength;
    let _e67 = b_7;
    let _e68 = halfSum_1;
    let _e70 = invHalfLength;
    let _e72 = alphas;
    let _e74 = alphas;
    let _e76 = pbr_D_GGX_Anisotropic((_e59 * _e60), (dot(_e62, _e63) * _e65), (dot(_e67, _e68) * _e70), _e72.x, _e74.y);
    D_1 = _e76;
    let _e78 = NdotL_50;
    let _e79 = NdotV_54;
    let _e80 = t_4;
    let _e81 = v_23;
    let _e83 = b_7;
    let _e84 = v_23;
    let _e86 = t_4;
    let _e87 = l_17;
    let _e89 = b_7;
    let _e90 = l_17;
    let _e92 = alphas;
    let _e94 = alphas;
    let _e96 = pbr_V_SmithGGXCorrelated_Anisotropic(_e78, _e79, dot(_e80, _e81), dot(_e83, _e84), dot(_e86, _e87), dot(_e89, _e90), _e92.x, _e94.y);
    V = _e96;
    let _e98 = D_1;
    let _e99 = V;
    let _e101 = pbr_specular_lobe_limit((_e98 * _e99));
    (*DV_2) = _e101;
    let _e102 = NdotL_50;
    let _e103 = nDotHalfSum_1;
    if (min(_e102, _e103) >= 0.0000000000000008881784f) {
        let _e107 = (*DV_2);
        local_21 = _e107;
    } else {
        local_21 = 0f;
    }
    let _e110 = local_21;
    (*DV_2) = _e110;
    return;
}

fn pbr_brdf_anisotropic_specular(n_18: vec3<f32>, v_24: vec3<f32>, l_18: vec3<f32>, t_5: vec3<f32>, b_8: vec3<f32>, f0_41: vec3<f32>, perceptualRoughness_30: f32, strength_4: f32) -> vec3<f32> {
    var n_19: vec3<f32>;
    var v_25: vec3<f32>;
    var l_19: vec3<f32>;
    var t_6: vec3<f32>;
    var b_9: vec3<f32>;
    var f0_42: vec3<f32>;
    var perceptualRoughness_31: f32;
    var strength_5: f32;
    var DV_3: f32;
    var LdotH_11: f32;

    n_19 = n_18;
    v_25 = v_24;
    l_19 = l_18;
    t_6 = t_5;
    b_9 = b_8;
    f0_42 = f0_41;
    perceptualRoughness_31 = perceptualRoughness_30;
    strength_5 = strength_4;
    let _e18 = n_19;
    let _e19 = v_25;
    let _e20 = l_19;
    let _e21 = t_6;
    let _e22 = b_9;
    let _e23 = perceptualRoughness_31;
    let _e24 = strength_5;
    pbr_brdf_anisotropic_terms(_e18, _e19, _e20, _e21, _e22, _e23, _e24, (&DV_3), (&LdotH_11));
    let _e29 = DV_3;
    let _e30 = f0_42;
    let _e31 = f0_42;
    let _e32 = pbr_f90_from_f0_(_e31);
    let _e33 = LdotH_11;
    let _e34 = pbr_F_Schlick_2(_e30, _e32, _e33);
    return (_e29 * _e34);
}

fn pbr_brdf_anisotropic_specular_f90_(n_20: vec3<f32>, v_26: vec3<f32>, l_20: vec3<f32>, t_7: vec3<f32>, b_10: vec3<f32>, f0_43: vec3<f32>, f90_16: f32, perceptualRoughness_32: f32, strength_6: f32) -> vec3<f32> {
    var n_21: vec3<f32>;
    var v_27: vec3<f32>;
    var l_21: vec3<f32>;
    var t_8: vec3<f32>;
    var b_11: vec3<f32>;
    var f0_44: vec3<f32>;
    var f90_17: f32;
    var perceptualRoughness_33: f32;
    var strength_7: f32;
    var DV_4: f32;
    var LdotH_12: f32;

    n_21 = n_20;
    v_27 = v_26;
    l_21 = l_20;
    t_8 = t_7;
    b_11 = b_10;
    f0_44 = f0_43;
    f90_17 = f90_16;
    perceptualRoughness_33 = perceptualRoughness_32;
    strength_7 = strength_6;
    let _e20 = n_21;
    let _e21 = v_27;
    let _e22 = l_21;
    let _e23 = t_8;
    let _e24 = b_11;
    let _e25 = perceptualRoughness_33;
    let _e26 = strength_7;
    pbr_brdf_anisotropic_terms(_e20, _e21, _e22, _e23, _e24, _e25, _e26, (&DV_4), (&LdotH_12));
    let _e31 = DV_4;
    let _e32 = f0_44;
    let _e33 = f90_17;
    let _e34 = LdotH_12;
    let _e35 = pbr_F_Schlick_2(_e32, _e33, _e34);
    return (_e31 * _e35);
}

fn pbr_anisotropic_bent_normal(n_22: vec3<f32>, v_28: vec3<f32>, anisotropicDirection: vec3<f32>, strength_8: f32, perceptualRoughness_34: f32) -> vec3<f32> {
    var n_23: vec3<f32>;
    var v_29: vec3<f32>;
    var anisotropicDirection_1: vec3<f32>;
    var strength_9: f32;
    var perceptualRoughness_35: f32;
    var s_6: f32;
    var anisotropicTangent: vec3<f32>;
    var anisotropicNormal: vec3<f32>;
    var bend: f32;
    var bend2_: f32;
    var bent: vec3<f32>;
    var local_22: vec3<f32>;

    n_23 = n_22;
    v_29 = v_28;
    anisotropicDirection_1 = anisotropicDirection;
    strength_9 = strength_8;
    perceptualRoughness_35 = perceptualRoughness_34;
    let _e10 = strength_9;
    s_6 = min(abs(_e10), 1f);
    let _e15 = anisotropicDirection_1;
    let _e16 = v_29;
    anisotropicTangent = cross(_e15, _e16);
    let _e19 = anisotropicTangent;
    let _e20 = anisotropicDirection_1;
    anisotropicNormal = cross(_e19, _e20);
    let _e24 = s_6;
    let _e26 = perceptualRoughness_35;
    let _e27 = pbr_saturate(_e26);
    bend = (1f - (_e24 * (1f - _e27)));
    let _e32 = bend;
    let _e33 = bend;
    bend2_ = (_e32 * _e33);
    let _e36 = anisotropicNormal;
    let _e37 = n_23;
    let _e38 = bend2_;
    let _e39 = bend2_;
    let _e43 = pbr_safe_normalize(mix(_e36, _e37, vec3((_e38 * _e39))));
    bent = _e43;
    let _e45 = bent;
    let _e46 = bent;
    if (dot(_e45, _e46) > 0f) {
        let _e50 = bent;
        local_22 = _e50;
    } else {
        let _e51 = n_23;
        local_22 = _e51;
    }
    let _e53 = local_22;
    return _e53;
}

fn pbr_sheen_alpha(sheenPerceptualRoughness: f32) -> f32 {
    var sheenPerceptualRoughness_1: f32;
    var r_6: f32;

    sheenPerceptualRoughness_1 = sheenPerceptualRoughness;
    let _e2 = sheenPerceptualRoughness_1;
    r_6 = clamp(_e2, 0.07f, 1f);
    let _e7 = r_6;
    let _e8 = r_6;
    return (_e7 * _e8);
}

fn pbr_sheen_V(NdotL_51: f32, NdotV_55: f32, alpha_62: f32) -> f32 {
    var NdotL_52: f32;
    var NdotV_56: f32;
    var alpha_63: f32;

    NdotL_52 = NdotL_51;
    NdotV_56 = NdotV_55;
    alpha_63 = alpha_62;
    let _e6 = NdotL_52;
    let _e7 = NdotV_56;
    let _e8 = alpha_63;
    let _e9 = pbr_V_Charlie(_e6, _e7, _e8);
    return _e9;
}

fn pbr_sheen_lobe(NdotL_53: f32, NdotV_57: f32, NdotH_30: f32, sheenColor: vec3<f32>, sheenPerceptualRoughness_2: f32) -> vec3<f32> {
    var NdotL_54: f32;
    var NdotV_58: f32;
    var NdotH_31: f32;
    var sheenColor_1: vec3<f32>;
    var sheenPerceptualRoughness_3: f32;
    var alpha_64: f32;

    NdotL_54 = NdotL_53;
    NdotV_58 = NdotV_57;
    NdotH_31 = NdotH_30;
    sheenColor_1 = sheenColor;
    sheenPerceptualRoughness_3 = sheenPerceptualRoughness_2;
    let _e10 = NdotL_54;
    if !((_e10 > 0f)) {
        {
            return vec3(0f);
        }
    }
    let _e16 = sheenPerceptualRoughness_3;
    let _e17 = pbr_sheen_alpha(_e16);
    alpha_64 = _e17;
    let _e19 = sheenColor_1;
    let _e20 = NdotH_31;
    let _e21 = alpha_64;
    let _e22 = pbr_D_Charlie(_e20, _e21);
    let _e23 = NdotL_54;
    let _e24 = NdotV_58;
    let _e25 = alpha_64;
    let _e26 = pbr_sheen_V(_e23, _e24, _e25);
    return (_e19 * (_e22 * _e26));
}

fn pbr_sheen_lut_uv(NdotV_59: f32, sheenPerceptualRoughness_4: f32) -> vec2<f32> {
    var NdotV_60: f32;
    var sheenPerceptualRoughness_5: f32;
    var x_20: f32;
    var y_2: f32;
    var size_1: vec2<f32> = vec2<f32>(128f, 128f);

    NdotV_60 = NdotV_59;
    sheenPerceptualRoughness_5 = sheenPerceptualRoughness_4;
    let _e4 = NdotV_60;
    x_20 = ((log2(clamp(_e4, 0.0001f, 1f)) * 0.0752575f) + 1f);
    let _e14 = sheenPerceptualRoughness_5;
    y_2 = ((log2(clamp(_e14, 0.07f, 1f)) * 0.26065415f) + 1f);
    let _e28 = x_20;
    let _e29 = y_2;
    let _e36 = size_1;
    let _e44 = size_1;
    return (((clamp(vec2<f32>(_e28, _e29), vec2(0f), vec2(1f)) * (_e36 - vec2(1f))) + vec2(0.5f)) / _e44);
}

fn pbr_sheen_albedo_approx(NdotV_61: f32, sheenPerceptualRoughness_6: f32) -> f32 {
    var NdotV_62: f32;
    var sheenPerceptualRoughness_7: f32;
    var x_21: f32;
    var y_3: f32;
    var ys: vec4<f32>;
    var p_2: f32;

    NdotV_62 = NdotV_61;
    sheenPerceptualRoughness_7 = sheenPerceptualRoughness_6;
    let _e4 = NdotV_62;
    x_21 = clamp(((log2(clamp(_e4, 0.0001f, 1f)) * 0.0752575f) + 1f), 0f, 1f);
    let _e17 = sheenPerceptualRoughness_7;
    y_3 = clamp(((log2(clamp(_e17, 0.07f, 1f)) * 0.26065415f) + 1f), 0f, 1f);
    let _e31 = y_3;
    let _e32 = y_3;
    let _e33 = y_3;
    let _e35 = y_3;
    let _e36 = y_3;
    let _e38 = y_3;
    ys = vec4<f32>(1f, _e31, (_e32 * _e33), ((_e35 * _e36) * _e38));
    let _e49 = ys;
    let _e51 = x_21;
    let _e60 = ys;
    let _e63 = x_21;
    let _e73 = ys;
    let _e76 = x_21;
    let _e85 = ys;
    p_2 = ((((((dot(vec4<f32>(-12.93151f, 8.414441f, 3.456867f, -3.622073f), _e49) * _e51) + dot(vec4<f32>(8.214515f, -0.7163682f, -6.965961f, 3.255338f), _e60)) * _e63) + dot(vec4<f32>(-1.120514f, -0.4725056f, 2.033727f, -0.8119602f), _e73)) * _e76) + dot(vec4<f32>(1.035856f, -2.405441f, -0.8081028f, 2.034246f), _e85));
    let _e89 = p_2;
    return max((exp(_e89) - 0.001f), 0f);
}

fn pbr_sheen_albedo(NdotV_63: f32, sheenPerceptualRoughness_8: f32) -> f32 {
    var NdotV_64: f32;
    var sheenPerceptualRoughness_9: f32;

    NdotV_64 = NdotV_63;
    sheenPerceptualRoughness_9 = sheenPerceptualRoughness_8;
    let _e4 = NdotV_64;
    let _e5 = sheenPerceptualRoughness_9;
    let _e6 = pbr_sheen_albedo_approx(_e4, _e5);
    return _e6;
}

fn pbr_sheen_albedo_scaling(sheenColor_2: vec3<f32>, E: f32) -> f32 {
    var sheenColor_3: vec3<f32>;
    var E_1: f32;

    sheenColor_3 = sheenColor_2;
    E_1 = E;
    let _e5 = sheenColor_3;
    let _e6 = pbr_max3_(_e5);
    let _e7 = E_1;
    let _e10 = pbr_saturate((1f - (_e6 * _e7)));
    return _e10;
}

fn pbr_sheen_albedo_scaling_punctual(sheenColor_4: vec3<f32>, NdotV_65: f32, NdotL_55: f32, sheenPerceptualRoughness_10: f32) -> f32 {
    var sheenColor_5: vec3<f32>;
    var NdotV_66: f32;
    var NdotL_56: f32;
    var sheenPerceptualRoughness_11: f32;

    sheenColor_5 = sheenColor_4;
    NdotV_66 = NdotV_65;
    NdotL_56 = NdotL_55;
    sheenPerceptualRoughness_11 = sheenPerceptualRoughness_10;
    let _e8 = sheenColor_5;
    let _e9 = NdotV_66;
    let _e10 = sheenPerceptualRoughness_11;
    let _e11 = pbr_sheen_albedo(_e9, _e10);
    let _e12 = pbr_sheen_albedo_scaling(_e8, _e11);
    let _e13 = sheenColor_5;
    let _e14 = NdotL_56;
    let _e15 = sheenPerceptualRoughness_11;
    let _e16 = pbr_sheen_albedo(_e14, _e15);
    let _e17 = pbr_sheen_albedo_scaling(_e13, _e16);
    return min(_e12, _e17);
}

fn pbr_transmission_punctual(n_24: vec3<f32>, v_30: vec3<f32>, l_22: vec3<f32>, lightRadiance_6: vec3<f32>, baseColor: vec3<f32>, perceptualRoughness_36: f32, eta_10: f32) -> vec3<f32> {
    var n_25: vec3<f32>;
    var v_31: vec3<f32>;
    var l_23: vec3<f32>;
    var lightRadiance_7: vec3<f32>;
    var baseColor_1: vec3<f32>;
    var perceptualRoughness_37: f32;
    var eta_11: f32;
    var r_7: f32;
    var ftCosine: f32;

    n_25 = n_24;
    v_31 = v_30;
    l_23 = l_22;
    lightRadiance_7 = lightRadiance_6;
    baseColor_1 = baseColor;
    perceptualRoughness_37 = perceptualRoughness_36;
    eta_11 = eta_10;
    let _e14 = perceptualRoughness_37;
    let _e15 = pbr_clamp_perceptual_roughness(_e14);
    r_7 = _e15;
    let _e17 = n_25;
    let _e18 = v_31;
    let _e19 = l_23;
    let _e20 = r_7;
    let _e21 = r_7;
    let _e23 = eta_11;
    let _e24 = pbr_BTDF_Walter_GGX_cosine(_e17, _e18, _e19, (_e20 * _e21), _e23);
    ftCosine = _e24;
    let _e26 = lightRadiance_7;
    let _e27 = baseColor_1;
    let _e30 = ftCosine;
    return ((_e26 * _e27) * (3.1415927f * _e30));
}

fn pbr_mirror_through_surface(n_26: vec3<f32>, l_24: vec3<f32>) -> vec3<f32> {
    var n_27: vec3<f32>;
    var l_25: vec3<f32>;

    n_27 = n_26;
    l_25 = l_24;
    let _e4 = l_25;
    let _e6 = n_27;
    let _e7 = l_25;
    let _e10 = n_27;
    return (_e4 - ((2f * dot(_e6, _e7)) * _e10));
}

fn pbr_transmission_thin_punctual(n_28: vec3<f32>, v_32: vec3<f32>, l_26: vec3<f32>, lightRadiance_8: vec3<f32>, baseColor_2: vec3<f32>, perceptualRoughness_38: f32) -> vec3<f32> {
    var n_29: vec3<f32>;
    var v_33: vec3<f32>;
    var l_27: vec3<f32>;
    var lightRadiance_9: vec3<f32>;
    var baseColor_3: vec3<f32>;
    var perceptualRoughness_39: f32;
    var r_8: f32;
    var alpha_65: f32;
    var lm: vec3<f32>;
    var h_3: vec3<f32>;
    var NdotLm: f32;
    var NdotV_67: f32;
    var lobe: f32;
    var through: bool;
    var local_23: vec3<f32>;

    n_29 = n_28;
    v_33 = v_32;
    l_27 = l_26;
    lightRadiance_9 = lightRadiance_8;
    baseColor_3 = baseColor_2;
    perceptualRoughness_39 = perceptualRoughness_38;
    let _e12 = perceptualRoughness_39;
    let _e13 = pbr_clamp_perceptual_roughness(_e12);
    r_8 = _e13;
    let _e15 = r_8;
    let _e16 = r_8;
    alpha_65 = (_e15 * _e16);
    let _e19 = n_29;
    let _e20 = l_27;
    let _e21 = pbr_mirror_through_surface(_e19, _e20);
    lm = _e21;
    let _e23 = lm;
    let _e24 = v_33;
    let _e26 = pbr_safe_normalize((_e23 + _e24));
    h_3 = _e26;
    let _e28 = n_29;
    let _e29 = lm;
    NdotLm = clamp(dot(_e28, _e29), 0f, 1f);
    let _e35 = n_29;
    let _e36 = v_33;
    NdotV_67 = clamp(dot(_e35, _e36), 0.0001f, 1f);
    let _e42 = n_29;
    let _e43 = h_3;
    let _e48 = alpha_65;
    let _e49 = pbr_D_GGX(clamp(dot(_e42, _e43), 0f, 1f), _e48);
    let _e50 = NdotLm;
    let _e53 = NdotV_67;
    let _e54 = alpha_65;
    let _e55 = pbr_V_SmithGGXCorrelated(max(_e50, 0.0001f), _e53, _e54);
    lobe = (_e49 * _e55);
    let _e58 = n_29;
    let _e59 = l_27;
    let _e63 = n_29;
    let _e64 = v_33;
    through = ((dot(_e58, _e59) < 0f) && (dot(_e63, _e64) > 0f));
    let _e70 = through;
    if _e70 {
        let _e71 = lightRadiance_9;
        let _e72 = baseColor_3;
        let _e75 = lobe;
        let _e77 = NdotLm;
        local_23 = ((_e71 * _e72) * ((3.1415927f * _e75) * _e77));
    } else {
        local_23 = vec3(0f);
    }
    let _e83 = local_23;
    return _e83;
}

fn pbr_beer_lambert(c_21: f32, x_22: f32) -> f32 {
    var c_22: f32;
    var x_23: f32;
    var cs: f32;
    var xs: f32;
    var local_24: f32;
    var local_25: f32;

    c_22 = c_21;
    x_23 = x_22;
    let _e4 = c_22;
    cs = clamp(_e4, 0f, 1f);
    let _e9 = x_23;
    xs = clamp(_e9, 0f, 1000000000000000000000000000000f);
    let _e14 = cs;
    if (_e14 > 0f) {
        let _e17 = cs;
        let _e19 = xs;
        local_25 = exp2((log2(_e17) * _e19));
    } else {
        let _e22 = xs;
        if (_e22 > 0f) {
            local_24 = 0f;
        } else {
            local_24 = 1f;
        }
        let _e28 = local_24;
        local_25 = _e28;
    }
    let _e30 = local_25;
    return _e30;
}

fn pbr_volume_attenuation(distance_: f32, attenuationColor: vec3<f32>, attenuationDistance: f32) -> vec3<f32> {
    var distance_1: f32;
    var attenuationColor_1: vec3<f32>;
    var attenuationDistance_1: f32;
    var local_26: f32;
    var x_24: f32;

    distance_1 = distance_;
    attenuationColor_1 = attenuationColor;
    attenuationDistance_1 = attenuationDistance;
    let _e6 = distance_1;
    if (_e6 > 0f) {
        let _e9 = distance_1;
        let _e10 = attenuationDistance_1;
        local_26 = (_e9 / max(_e10, 0.000000000000000000000000000000000000011754944f));
    } else {
        local_26 = 0f;
    }
    let _e16 = local_26;
    x_24 = _e16;
    let _e18 = attenuationColor_1;
    let _e20 = x_24;
    let _e21 = pbr_beer_lambert(_e18.x, _e20);
    let _e22 = attenuationColor_1;
    let _e24 = x_24;
    let _e25 = pbr_beer_lambert(_e22.y, _e24);
    let _e26 = attenuationColor_1;
    let _e28 = x_24;
    let _e29 = pbr_beer_lambert(_e26.z, _e28);
    return vec3<f32>(_e21, _e25, _e29);
}

fn pbr_refraction_direction(n_30: vec3<f32>, v_34: vec3<f32>, eta_12: f32) -> vec3<f32> {
    var n_31: vec3<f32>;
    var v_35: vec3<f32>;
    var eta_13: f32;

    n_31 = n_30;
    v_35 = v_34;
    eta_13 = eta_12;
    let _e6 = v_35;
    let _e8 = n_31;
    let _e10 = eta_13;
    return refract(-(_e6), _e8, (1f / _e10));
}

fn pbr_valid_reflection_normal(n_32: vec3<f32>, ng: vec3<f32>, v_36: vec3<f32>) -> vec3<f32> {
    var n_33: vec3<f32>;
    var ng_1: vec3<f32>;
    var v_37: vec3<f32>;
    var vz: f32;
    var t_9: f32;
    var r_9: vec3<f32>;
    var across: vec3<f32>;
    var local_27: vec3<f32>;
    var x_25: vec3<f32>;
    var vx: f32;
    var a_7: f32;
    var b_12: f32;
    var c_23: f32;
    var root: f32;
    var bigB: f32;
    var w_2: f32;
    var u: f32;

    n_33 = n_32;
    ng_1 = ng;
    v_37 = v_36;
    let _e6 = v_37;
    let _e7 = ng_1;
    vz = max(dot(_e6, _e7), 0f);
    let _e13 = vz;
    t_9 = min((0.9f * _e13), 0.01f);
    let _e19 = n_33;
    let _e20 = v_37;
    let _e23 = n_33;
    let _e25 = v_37;
    r_9 = (((2f * dot(_e19, _e20)) * _e23) - _e25);
    let _e28 = r_9;
    let _e29 = ng_1;
    let _e31 = t_9;
    if (dot(_e28, _e29) >= _e31) {
        {
            let _e33 = n_33;
            return _e33;
        }
    }
    let _e34 = n_33;
    let _e35 = n_33;
    let _e36 = ng_1;
    let _e38 = ng_1;
    let _e41 = pbr_safe_normalize((_e34 - (dot(_e35, _e36) * _e38)));
    across = _e41;
    let _e43 = across;
    let _e44 = across;
    if (dot(_e43, _e44) > 0f) {
        let _e48 = across;
        local_27 = _e48;
    } else {
        let _e49 = n_33;
        local_27 = _e49;
    }
    let _e51 = local_27;
    x_25 = _e51;
    let _e53 = v_37;
    let _e54 = x_25;
    vx = dot(_e53, _e54);
    let _e57 = vx;
    let _e58 = vx;
    let _e60 = vz;
    let _e61 = vz;
    a_7 = ((_e57 * _e58) + (_e60 * _e61));
    let _e66 = a_7;
    let _e67 = vz;
    let _e68 = t_9;
    b_12 = (2f * (_e66 + (_e67 * _e68)));
    let _e73 = vz;
    let _e74 = t_9;
    let _e76 = pbr_sq((_e73 + _e74));
    c_23 = _e76;
    let _e78 = b_12;
    let _e79 = b_12;
    let _e82 = a_7;
    let _e84 = c_23;
    root = sqrt(max(((_e78 * _e79) - ((4f * _e82) * _e84)), 0f));
    let _e92 = a_7;
    let _e93 = vz;
    let _e94 = t_9;
    bigB = (2f * (_e92 - (_e93 * _e94)));
    let _e101 = vx;
    if (_e101 < 0f) {
        {
            let _e104 = b_12;
            let _e105 = root;
            let _e108 = a_7;
            w_2 = ((_e104 + _e105) / max((4f * _e108), 0.000000000000000000000000000000000000011754944f));
            let _e113 = vz;
            let _e114 = t_9;
            let _e116 = pbr_sq((_e113 - _e114));
            let _e117 = bigB;
            let _e118 = root;
            u = (_e116 / max((_e117 + _e118), 0.000000000000000000000000000000000000011754944f));
        }
    } else {
        {
            let _e123 = c_23;
            let _e124 = b_12;
            let _e125 = root;
            w_2 = (_e123 / max((_e124 + _e125), 0.000000000000000000000000000000000000011754944f));
            let _e130 = bigB;
            let _e131 = root;
            let _e134 = a_7;
            u = ((_e130 + _e131) / max((4f * _e134), 0.000000000000000000000000000000000000011754944f));
        }
    }
    let _e139 = u;
    let _e144 = x_25;
    let _e146 = w_2;
    let _e151 = ng_1;
    return ((sqrt(clamp(_e139, 0f, 1f)) * _e144) + (sqrt(clamp(_e146, 0f, 1f)) * _e151));
}

fn pbr_range_window(distance2_: f32, range: f32) -> f32 {
    var distance2_1: f32;
    var range_1: f32;
    var ratio2_: f32;
    var w_3: f32;

    distance2_1 = distance2_;
    range_1 = range;
    let _e4 = distance2_1;
    let _e5 = range_1;
    let _e6 = range_1;
    ratio2_ = (_e4 / (_e5 * _e6));
    let _e11 = ratio2_;
    let _e12 = ratio2_;
    w_3 = clamp((1f - (_e11 * _e12)), 0f, 1f);
    let _e19 = w_3;
    let _e20 = w_3;
    return (_e19 * _e20);
}

fn pbr_distance_attenuation(distance2_2: f32, range_2: f32) -> f32 {
    var distance2_3: f32;
    var range_3: f32;

    distance2_3 = distance2_2;
    range_3 = range_2;
    let _e4 = distance2_3;
    let _e5 = range_3;
    let _e6 = pbr_range_window(_e4, _e5);
    let _e7 = distance2_3;
    return (_e6 / max(_e7, 0.00000001f));
}

fn pbr_spot_attenuation(l_28: vec3<f32>, spotDirection: vec3<f32>, cosOuter: f32, invCosRange: f32) -> f32 {
    var l_29: vec3<f32>;
    var spotDirection_1: vec3<f32>;
    var cosOuter_1: f32;
    var invCosRange_1: f32;
    var t_10: f32;

    l_29 = l_28;
    spotDirection_1 = spotDirection;
    cosOuter_1 = cosOuter;
    invCosRange_1 = invCosRange;
    let _e8 = l_29;
    let _e10 = spotDirection_1;
    let _e12 = cosOuter_1;
    let _e14 = invCosRange_1;
    t_10 = clamp(((dot(-(_e8), _e10) - _e12) * _e14), 0f, 1f);
    let _e20 = t_10;
    let _e21 = t_10;
    return (_e20 * _e21);
}

fn pbr_sh9_irradiance(sh: array<vec3<f32>, 9>, n_34: vec3<f32>) -> vec3<f32> {
    var sh_1: array<vec3<f32>, 9>;
    var n_35: vec3<f32>;

    sh_1 = sh;
    n_35 = n_34;
    let _e7 = sh_1[8];
    let _e9 = n_35;
    let _e11 = n_35;
    let _e14 = n_35;
    let _e16 = n_35;
    let _e24 = sh_1[6];
    let _e26 = n_35;
    let _e29 = n_35;
    let _e36 = sh_1[0];
    let _e42 = sh_1[6];
    let _e50 = sh_1[4];
    let _e51 = n_35;
    let _e54 = n_35;
    let _e59 = sh_1[7];
    let _e60 = n_35;
    let _e63 = n_35;
    let _e69 = sh_1[5];
    let _e70 = n_35;
    let _e73 = n_35;
    let _e84 = sh_1[3];
    let _e85 = n_35;
    let _e90 = sh_1[1];
    let _e91 = n_35;
    let _e97 = sh_1[2];
    let _e98 = n_35;
    return (((((((0.429043f * _e7) * ((_e9.x * _e11.x) - (_e14.y * _e16.y))) + (((0.743125f * _e24) * _e26.z) * _e29.z)) + (0.886227f * _e36)) - (0.247708f * _e42)) + (0.858086f * ((((_e50 * _e51.x) * _e54.y) + ((_e59 * _e60.x) * _e63.z)) + ((_e69 * _e70.y) * _e73.z)))) + (1.023328f * (((_e84 * _e85.x) + (_e90 * _e91.y)) + (_e97 * _e98.z))));
}

fn pbr_disc_light_alpha(alpha_66: f32, angularRadius: f32) -> f32 {
    var alpha_67: f32;
    var angularRadius_1: f32;
    var disc: f32;

    alpha_67 = alpha_66;
    angularRadius_1 = angularRadius;
    let _e4 = angularRadius_1;
    disc = (_e4 / 1.2871885f);
    let _e10 = alpha_67;
    let _e11 = alpha_67;
    let _e13 = disc;
    let _e14 = disc;
    return min(sqrt(((_e10 * _e11) + (_e13 * _e14))), 1f);
}

fn pbr_hammersley(i: u32, count: u32) -> vec2<f32> {
    var i_1: u32;
    var count_1: u32;
    var bits: u32;

    i_1 = i;
    count_1 = count;
    let _e4 = i_1;
    let _e7 = i_1;
    bits = ((_e4 << 16u) | (_e7 >> 16u));
    let _e12 = bits;
    let _e17 = bits;
    bits = (((_e12 & 1431655765u) << 1u) | ((_e17 & 2863311530u) >> 1u));
    let _e23 = bits;
    let _e28 = bits;
    bits = (((_e23 & 858993459u) << 2u) | ((_e28 & 3435973836u) >> 2u));
    let _e34 = bits;
    let _e39 = bits;
    bits = (((_e34 & 252645135u) << 4u) | ((_e39 & 4042322160u) >> 4u));
    let _e45 = bits;
    let _e50 = bits;
    bits = (((_e45 & 16711935u) << 8u) | ((_e50 & 4278255360u) >> 8u));
    let _e56 = i_1;
    let _e58 = count_1;
    let _e61 = bits;
    return vec2<f32>((f32(_e56) / f32(_e58)), (f32(_e61) * 0.00000000023283064f));
}

fn pbr_hammersley_float(i_2: f32, count_2: f32) -> vec2<f32> {
    var i_3: f32;
    var count_3: f32;
    var rest: f32;
    var radical: f32 = 0f;
    var weight: f32 = 0.5f;
    var k_9: i32 = 0i;
    var half_rest: f32;

    i_3 = i_2;
    count_3 = count_2;
    let _e4 = i_3;
    rest = _e4;
    loop {
        let _e12 = k_9;
        if !((_e12 < 24i)) {
            break;
        }
        {
            let _e19 = rest;
            half_rest = floor((_e19 * 0.5f));
            let _e24 = radical;
            let _e25 = rest;
            let _e27 = half_rest;
            let _e30 = weight;
            radical = (_e24 + ((_e25 - (2f * _e27)) * _e30));
            let _e33 = half_rest;
            rest = _e33;
            let _e34 = weight;
            weight = (_e34 * 0.5f);
        }
        continuing {
            let _e16 = k_9;
            k_9 = (_e16 + 1i);
        }
    }
    let _e37 = i_3;
    let _e38 = count_3;
    let _e40 = radical;
    return vec2<f32>((_e37 / _e38), _e40);
}

fn pbr_importance_sample_GGX(xi: vec2<f32>, alpha_68: f32) -> vec3<f32> {
    var xi_1: vec2<f32>;
    var alpha_69: f32;
    var phi: f32;
    var cosTheta2_: f32;
    var cosTheta_6: f32;
    var sinTheta: f32;

    xi_1 = xi;
    alpha_69 = alpha_68;
    let _e7 = xi_1;
    phi = (6.2831855f * _e7.x);
    let _e12 = xi_1;
    let _e16 = alpha_69;
    let _e17 = alpha_69;
    let _e21 = xi_1;
    cosTheta2_ = ((1f - _e12.y) / (1f + (((_e16 * _e17) - 1f) * _e21.y)));
    let _e27 = cosTheta2_;
    cosTheta_6 = sqrt(_e27);
    let _e31 = cosTheta2_;
    sinTheta = sqrt(max((1f - _e31), 0f));
    let _e37 = sinTheta;
    let _e38 = phi;
    let _e41 = sinTheta;
    let _e42 = phi;
    let _e45 = cosTheta_6;
    return vec3<f32>((_e37 * cos(_e38)), (_e41 * sin(_e42)), _e45);
}

fn pbr_pdf_GGX_half_vector(NdotH_32: f32, alpha_70: f32) -> f32 {
    var NdotH_33: f32;
    var alpha_71: f32;

    NdotH_33 = NdotH_32;
    alpha_71 = alpha_70;
    let _e4 = NdotH_33;
    let _e5 = alpha_71;
    let _e6 = pbr_D_GGX(_e4, _e5);
    let _e7 = NdotH_33;
    return (_e6 * _e7);
}

fn pbr_tangent_to_world(v_38: vec3<f32>, n_36: vec3<f32>) -> vec3<f32> {
    var v_39: vec3<f32>;
    var n_37: vec3<f32>;
    var local_28: vec3<f32>;
    var up: vec3<f32>;
    var t_11: vec3<f32>;
    var b_13: vec3<f32>;

    v_39 = v_38;
    n_37 = n_36;
    let _e4 = n_37;
    if (abs(_e4.z) < 0.999f) {
        local_28 = vec3<f32>(0f, 0f, 1f);
    } else {
        local_28 = vec3<f32>(1f, 0f, 0f);
    }
    let _e18 = local_28;
    up = _e18;
    let _e20 = up;
    let _e21 = n_37;
    t_11 = normalize(cross(_e20, _e21));
    let _e25 = n_37;
    let _e26 = t_11;
    b_13 = cross(_e25, _e26);
    let _e29 = t_11;
    let _e30 = v_39;
    let _e33 = b_13;
    let _e34 = v_39;
    let _e38 = n_37;
    let _e39 = v_39;
    return (((_e29 * _e30.x) + (_e33 * _e34.y)) + (_e38 * _e39.z));
}

fn pbr_equirect_uv(dir: vec3<f32>) -> vec2<f32> {
    var dir_1: vec3<f32>;
    var u_1: f32;
    var t_12: f32;

    dir_1 = dir;
    let _e2 = dir_1;
    let _e4 = dir_1;
    u_1 = fract((atan2(_e2.x, -(_e4.z)) * 0.15915494f));
    let _e15 = dir_1;
    t_12 = (1f - (acos(clamp(_e15.y, -1f, 1f)) * 0.31830987f));
    let _e26 = u_1;
    let _e27 = t_12;
    return vec2<f32>(_e26, _e27);
}

fn pbr_equirect_direction(uv: vec2<f32>) -> vec3<f32> {
    var uv_1: vec2<f32>;
    var phi_1: f32;
    var theta: f32;

    uv_1 = uv;
    let _e5 = uv_1;
    phi_1 = (6.2831855f * _e5.x);
    let _e10 = uv_1;
    theta = ((1f - _e10.y) * 3.1415927f);
    let _e16 = theta;
    let _e18 = phi_1;
    let _e21 = theta;
    let _e23 = theta;
    let _e26 = phi_1;
    return vec3<f32>((sin(_e16) * sin(_e18)), cos(_e21), (-(sin(_e23)) * cos(_e26)));
}

fn pbr_lobe_share_above(c_24: f32, alpha_72: f32) -> f32 {
    var c_25: f32;
    var alpha_73: f32;

    c_25 = c_24;
    alpha_73 = alpha_72;
    let _e6 = c_25;
    let _e9 = alpha_73;
    let _e11 = alpha_73;
    let _e13 = c_25;
    let _e14 = c_25;
    return (0.5f + ((0.5f * _e6) * inverseSqrt(max((((4f * _e9) * _e11) + (_e13 * _e14)), 0.000000000000000000000000000001f))));
}

fn pbr_specular_horizon_occlusion(RdotNg: f32, NdotV_68: f32, alpha_74: f32) -> f32 {
    var RdotNg_1: f32;
    var NdotV_69: f32;
    var alpha_75: f32;

    RdotNg_1 = RdotNg;
    NdotV_69 = NdotV_68;
    alpha_75 = alpha_74;
    let _e6 = RdotNg_1;
    let _e7 = alpha_75;
    let _e8 = pbr_lobe_share_above(_e6, _e7);
    let _e9 = NdotV_69;
    let _e10 = alpha_75;
    let _e11 = pbr_lobe_share_above(_e9, _e10);
    return min((_e8 / _e11), 1f);
}

fn pbr_diffuse_horizon_occlusion(NdotNg: f32) -> f32 {
    var NdotNg_1: f32;

    NdotNg_1 = NdotNg;
    let _e4 = NdotNg_1;
    return clamp((0.5f + (0.5f * _e4)), 0f, 1f);
}

fn pbr_specular_dominant_direction(n_38: vec3<f32>, r_10: vec3<f32>, alpha_76: f32) -> vec3<f32> {
    var n_39: vec3<f32>;
    var r_11: vec3<f32>;
    var alpha_77: f32;
    var d_1: vec3<f32>;
    var len2_: f32;
    var local_29: vec3<f32>;

    n_39 = n_38;
    r_11 = r_10;
    alpha_77 = alpha_76;
    let _e6 = r_11;
    let _e7 = n_39;
    let _e8 = alpha_77;
    d_1 = mix(_e6, _e7, vec3(_e8));
    let _e12 = d_1;
    let _e13 = d_1;
    len2_ = dot(_e12, _e13);
    let _e16 = len2_;
    if (_e16 > 0.000000000001f) {
        let _e19 = d_1;
        let _e20 = len2_;
        local_29 = (_e19 * inverseSqrt(_e20));
    } else {
        let _e23 = n_39;
        local_29 = _e23;
    }
    let _e25 = local_29;
    return _e25;
}

fn pbr_indirect_specular_albedo_f90_(f0_45: vec3<f32>, f90_18: f32, dfg_10: vec2<f32>) -> vec3<f32> {
    var f0_46: vec3<f32>;
    var f90_19: f32;
    var dfg_11: vec2<f32>;
    var albedo_12: vec3<f32>;

    f0_46 = f0_45;
    f90_19 = f90_18;
    dfg_11 = dfg_10;
    let _e6 = f0_46;
    let _e7 = f90_19;
    let _e8 = dfg_11;
    let _e9 = pbr_specular_albedo_f90_(_e6, _e7, _e8);
    albedo_12 = _e9;
    let _e11 = albedo_12;
    let _e12 = f0_46;
    let _e13 = dfg_11;
    let _e14 = pbr_energy_compensation(_e12, _e13);
    albedo_12 = (_e11 * _e14);
    let _e16 = albedo_12;
    return _e16;
}

fn pbr_indirect_specular_albedo(f0_47: vec3<f32>, dfg_12: vec2<f32>) -> vec3<f32> {
    var f0_48: vec3<f32>;
    var dfg_13: vec2<f32>;
    var albedo_13: vec3<f32>;

    f0_48 = f0_47;
    dfg_13 = dfg_12;
    let _e4 = f0_48;
    let _e5 = dfg_13;
    let _e6 = pbr_specular_albedo(_e4, _e5);
    albedo_13 = _e6;
    let _e8 = albedo_13;
    let _e9 = f0_48;
    let _e10 = dfg_13;
    let _e11 = pbr_energy_compensation(_e9, _e10);
    albedo_13 = (_e8 * _e11);
    let _e13 = albedo_13;
    return _e13;
}

fn pbr_indirect_specular_split_sum_f90_(prefiltered: vec3<f32>, f0_49: vec3<f32>, f90_20: f32, roughness_2: f32, NdotV_70: f32, occlusion_2: f32, dfg_14: vec2<f32>) -> vec3<f32> {
    var prefiltered_1: vec3<f32>;
    var f0_50: vec3<f32>;
    var f90_21: f32;
    var roughness_3: f32;
    var NdotV_71: f32;
    var occlusion_3: f32;
    var dfg_15: vec2<f32>;

    prefiltered_1 = prefiltered;
    f0_50 = f0_49;
    f90_21 = f90_20;
    roughness_3 = roughness_2;
    NdotV_71 = NdotV_70;
    occlusion_3 = occlusion_2;
    dfg_15 = dfg_14;
    let _e14 = prefiltered_1;
    let _e15 = f0_50;
    let _e16 = f90_21;
    let _e17 = dfg_15;
    let _e18 = pbr_indirect_specular_albedo_f90_(_e15, _e16, _e17);
    let _e20 = NdotV_71;
    let _e21 = occlusion_3;
    let _e22 = roughness_3;
    let _e23 = roughness_3;
    let _e25 = pbr_specular_occlusion(_e20, _e21, (_e22 * _e23));
    return ((_e14 * _e18) * _e25);
}

fn pbr_indirect_specular_split_sum(prefiltered_2: vec3<f32>, f0_51: vec3<f32>, roughness_4: f32, NdotV_72: f32, occlusion_4: f32, dfg_16: vec2<f32>) -> vec3<f32> {
    var prefiltered_3: vec3<f32>;
    var f0_52: vec3<f32>;
    var roughness_5: f32;
    var NdotV_73: f32;
    var occlusion_5: f32;
    var dfg_17: vec2<f32>;

    prefiltered_3 = prefiltered_2;
    f0_52 = f0_51;
    roughness_5 = roughness_4;
    NdotV_73 = NdotV_72;
    occlusion_5 = occlusion_4;
    dfg_17 = dfg_16;
    let _e12 = prefiltered_3;
    let _e13 = f0_52;
    let _e14 = dfg_17;
    let _e15 = pbr_indirect_specular_albedo(_e13, _e14);
    let _e17 = NdotV_73;
    let _e18 = occlusion_5;
    let _e19 = roughness_5;
    let _e20 = roughness_5;
    let _e22 = pbr_specular_occlusion(_e17, _e18, (_e19 * _e20));
    return ((_e12 * _e15) * _e22);
}

fn pbr_indirect_diffuse_color_f90_(diffuseColor_12: vec3<f32>, coatF0_4: vec3<f32>, coatF90_: f32, dfg_18: vec2<f32>) -> vec3<f32> {
    var diffuseColor_13: vec3<f32>;
    var coatF0_5: vec3<f32>;
    var coatF90_1: f32;
    var dfg_19: vec2<f32>;

    diffuseColor_13 = diffuseColor_12;
    coatF0_5 = coatF0_4;
    coatF90_1 = coatF90_;
    dfg_19 = dfg_18;
    let _e8 = diffuseColor_13;
    let _e9 = coatF0_5;
    let _e10 = coatF0_5;
    let _e11 = coatF90_1;
    let _e12 = dfg_19;
    let _e13 = pbr_indirect_specular_albedo_f90_(_e10, _e11, _e12);
    let _e14 = pbr_coupled_diffuse_color(_e8, _e9, _e13);
    return _e14;
}

fn pbr_indirect_diffuse_color(diffuseColor_14: vec3<f32>, coatF0_6: vec3<f32>, dfg_20: vec2<f32>) -> vec3<f32> {
    var diffuseColor_15: vec3<f32>;
    var coatF0_7: vec3<f32>;
    var dfg_21: vec2<f32>;

    diffuseColor_15 = diffuseColor_14;
    coatF0_7 = coatF0_6;
    dfg_21 = dfg_20;
    let _e6 = diffuseColor_15;
    let _e7 = coatF0_7;
    let _e8 = coatF0_7;
    let _e9 = dfg_21;
    let _e10 = pbr_indirect_specular_albedo(_e8, _e9);
    let _e11 = pbr_coupled_diffuse_color(_e6, _e7, _e10);
    return _e11;
}

fn pbr_prepare_surface_f90_dfg(diffuseColor_16: vec3<f32>, f0_53: vec3<f32>, f90_22: f32, coatF0_8: vec3<f32>, coatF90_2: f32, perceptualRoughness_40: f32, occlusion_6: f32, n_40: vec3<f32>, v_40: vec3<f32>, dfg_22: vec2<f32>) -> pbr_PreparedSurface {
    var diffuseColor_17: vec3<f32>;
    var f0_54: vec3<f32>;
    var f90_23: f32;
    var coatF0_9: vec3<f32>;
    var coatF90_3: f32;
    var perceptualRoughness_41: f32;
    var occlusion_7: f32;
    var n_41: vec3<f32>;
    var v_41: vec3<f32>;
    var dfg_23: vec2<f32>;
    var s_7: pbr_PreparedSurface;

    diffuseColor_17 = diffuseColor_16;
    f0_54 = f0_53;
    f90_23 = f90_22;
    coatF0_9 = coatF0_8;
    coatF90_3 = coatF90_2;
    perceptualRoughness_41 = perceptualRoughness_40;
    occlusion_7 = occlusion_6;
    n_41 = n_40;
    v_41 = v_40;
    dfg_23 = dfg_22;
    let _e22 = n_41;
    s_7.n = _e22;
    let _e24 = v_41;
    s_7.v = _e24;
    let _e26 = f0_54;
    s_7.f0_ = _e26;
    let _e28 = f90_23;
    s_7.f90_ = _e28;
    let _e30 = perceptualRoughness_41;
    let _e31 = pbr_clamp_perceptual_roughness(_e30);
    s_7.perceptualRoughness = _e31;
    let _e33 = occlusion_7;
    s_7.occlusion = _e33;
    let _e35 = diffuseColor_17;
    let _e36 = coatF0_9;
    let _e37 = coatF0_9;
    let _e38 = coatF90_3;
    let _e39 = dfg_23;
    let _e40 = pbr_specular_albedo_bound_f90_(_e37, _e38, _e39);
    let _e41 = pbr_coupled_diffuse_color(_e35, _e36, _e40);
    s_7.directDiffuseColor = _e41;
    let _e43 = diffuseColor_17;
    let _e44 = coatF0_9;
    let _e45 = coatF90_3;
    let _e46 = dfg_23;
    let _e47 = pbr_indirect_diffuse_color_f90_(_e43, _e44, _e45, _e46);
    s_7.indirectDiffuseColor = _e47;
    let _e49 = f0_54;
    let _e50 = f90_23;
    let _e51 = dfg_23;
    let _e52 = pbr_indirect_specular_albedo_f90_(_e49, _e50, _e51);
    s_7.indirectSpecularAlbedo = _e52;
    let _e54 = n_41;
    let _e55 = v_41;
    let _e59 = occlusion_7;
    let _e60 = s_7;
    let _e62 = s_7;
    let _e65 = pbr_specular_occlusion(max(dot(_e54, _e55), 0.0001f), _e59, (_e60.perceptualRoughness * _e62.perceptualRoughness));
    s_7.specularOcclusion = _e65;
    let _e66 = s_7;
    return _e66;
}

fn pbr_prepare_surface_dfg(diffuseColor_18: vec3<f32>, f0_55: vec3<f32>, coatF0_10: vec3<f32>, perceptualRoughness_42: f32, occlusion_8: f32, n_42: vec3<f32>, v_42: vec3<f32>, dfg_24: vec2<f32>) -> pbr_PreparedSurface {
    var diffuseColor_19: vec3<f32>;
    var f0_56: vec3<f32>;
    var coatF0_11: vec3<f32>;
    var perceptualRoughness_43: f32;
    var occlusion_9: f32;
    var n_43: vec3<f32>;
    var v_43: vec3<f32>;
    var dfg_25: vec2<f32>;
    var s_8: pbr_PreparedSurface;

    diffuseColor_19 = diffuseColor_18;
    f0_56 = f0_55;
    coatF0_11 = coatF0_10;
    perceptualRoughness_43 = perceptualRoughness_42;
    occlusion_9 = occlusion_8;
    n_43 = n_42;
    v_43 = v_42;
    dfg_25 = dfg_24;
    let _e18 = n_43;
    s_8.n = _e18;
    let _e20 = v_43;
    s_8.v = _e20;
    let _e22 = f0_56;
    s_8.f0_ = _e22;
    let _e24 = perceptualRoughness_43;
    let _e25 = pbr_clamp_perceptual_roughness(_e24);
    s_8.perceptualRoughness = _e25;
    let _e27 = occlusion_9;
    s_8.occlusion = _e27;
    let _e29 = diffuseColor_19;
    let _e30 = coatF0_11;
    let _e31 = coatF0_11;
    let _e32 = dfg_25;
    let _e33 = pbr_specular_albedo_bound(_e31, _e32);
    let _e34 = pbr_coupled_diffuse_color(_e29, _e30, _e33);
    s_8.directDiffuseColor = _e34;
    let _e36 = diffuseColor_19;
    let _e37 = coatF0_11;
    let _e38 = dfg_25;
    let _e39 = pbr_indirect_diffuse_color(_e36, _e37, _e38);
    s_8.indirectDiffuseColor = _e39;
    let _e41 = f0_56;
    let _e42 = dfg_25;
    let _e43 = pbr_indirect_specular_albedo(_e41, _e42);
    s_8.indirectSpecularAlbedo = _e43;
    let _e45 = n_43;
    let _e46 = v_43;
    let _e50 = occlusion_9;
    let _e51 = s_8;
    let _e53 = s_8;
    let _e56 = pbr_specular_occlusion(max(dot(_e45, _e46), 0.0001f), _e50, (_e51.perceptualRoughness * _e53.perceptualRoughness));
    s_8.specularOcclusion = _e56;
    let _e58 = f0_56;
    let _e59 = pbr_f90_from_f0_(_e58);
    s_8.f90_ = _e59;
    let _e60 = s_8;
    return _e60;
}

fn pbr_prepare_surface_f90_(diffuseColor_20: vec3<f32>, f0_57: vec3<f32>, f90_24: f32, coatF0_12: vec3<f32>, coatF90_4: f32, perceptualRoughness_44: f32, occlusion_10: f32, n_44: vec3<f32>, v_44: vec3<f32>) -> pbr_PreparedSurface {
    var diffuseColor_21: vec3<f32>;
    var f0_58: vec3<f32>;
    var f90_25: f32;
    var coatF0_13: vec3<f32>;
    var coatF90_5: f32;
    var perceptualRoughness_45: f32;
    var occlusion_11: f32;
    var n_45: vec3<f32>;
    var v_45: vec3<f32>;
    var roughness_6: f32;
    var dfg_26: vec2<f32>;

    diffuseColor_21 = diffuseColor_20;
    f0_58 = f0_57;
    f90_25 = f90_24;
    coatF0_13 = coatF0_12;
    coatF90_5 = coatF90_4;
    perceptualRoughness_45 = perceptualRoughness_44;
    occlusion_11 = occlusion_10;
    n_45 = n_44;
    v_45 = v_44;
    let _e18 = perceptualRoughness_45;
    let _e19 = pbr_clamp_perceptual_roughness(_e18);
    roughness_6 = _e19;
    let _e21 = n_45;
    let _e22 = v_45;
    let _e26 = roughness_6;
    let _e27 = pbr_env_brdf(max(dot(_e21, _e22), 0.0001f), _e26);
    dfg_26 = _e27;
    let _e29 = diffuseColor_21;
    let _e30 = f0_58;
    let _e31 = f90_25;
    let _e32 = coatF0_13;
    let _e33 = coatF90_5;
    let _e34 = roughness_6;
    let _e35 = occlusion_11;
    let _e36 = n_45;
    let _e37 = v_45;
    let _e38 = dfg_26;
    let _e39 = pbr_prepare_surface_f90_dfg(_e29, _e30, _e31, _e32, _e33, _e34, _e35, _e36, _e37, _e38);
    return _e39;
}

fn pbr_prepare_surface(diffuseColor_22: vec3<f32>, f0_59: vec3<f32>, coatF0_14: vec3<f32>, perceptualRoughness_46: f32, occlusion_12: f32, n_46: vec3<f32>, v_46: vec3<f32>) -> pbr_PreparedSurface {
    var diffuseColor_23: vec3<f32>;
    var f0_60: vec3<f32>;
    var coatF0_15: vec3<f32>;
    var perceptualRoughness_47: f32;
    var occlusion_13: f32;
    var n_47: vec3<f32>;
    var v_47: vec3<f32>;
    var roughness_7: f32;
    var dfg_27: vec2<f32>;

    diffuseColor_23 = diffuseColor_22;
    f0_60 = f0_59;
    coatF0_15 = coatF0_14;
    perceptualRoughness_47 = perceptualRoughness_46;
    occlusion_13 = occlusion_12;
    n_47 = n_46;
    v_47 = v_46;
    let _e14 = perceptualRoughness_47;
    let _e15 = pbr_clamp_perceptual_roughness(_e14);
    roughness_7 = _e15;
    let _e17 = n_47;
    let _e18 = v_47;
    let _e22 = roughness_7;
    let _e23 = pbr_env_brdf(max(dot(_e17, _e18), 0.0001f), _e22);
    dfg_27 = _e23;
    let _e25 = diffuseColor_23;
    let _e26 = f0_60;
    let _e27 = coatF0_15;
    let _e28 = roughness_7;
    let _e29 = occlusion_13;
    let _e30 = n_47;
    let _e31 = v_47;
    let _e32 = dfg_27;
    let _e33 = pbr_prepare_surface_dfg(_e25, _e26, _e27, _e28, _e29, _e30, _e31, _e32);
    return _e33;
}

fn pbr_lighting_standard_light(s_9: pbr_PreparedSurface, light: pbr_Light) -> vec3<f32> {
    var s_10: pbr_PreparedSurface;
    var light_1: pbr_Light;

    s_10 = s_9;
    light_1 = light;
    let _e4 = s_10;
    let _e6 = s_10;
    let _e8 = light_1;
    let _e10 = light_1;
    let _e12 = s_10;
    let _e14 = s_10;
    let _e16 = s_10;
    let _e18 = s_10;
    let _e20 = pbr_shade_punctual_f90_(_e4.n, _e6.v, _e8.dir, _e10.color, _e12.directDiffuseColor, _e14.f0_, _e16.f90_, _e18.perceptualRoughness);
    return _e20;
}

fn pbr_lighting_standard_add_environment(s_11: pbr_PreparedSurface, indirect: pbr_Indirect, radiance: vec3<f32>) -> vec3<f32> {
    var s_12: pbr_PreparedSurface;
    var indirect_1: pbr_Indirect;
    var radiance_1: vec3<f32>;

    s_12 = s_11;
    indirect_1 = indirect;
    radiance_1 = radiance;
    let _e6 = radiance_1;
    let _e7 = s_12;
    let _e9 = indirect_1;
    let _e12 = s_12;
    let _e16 = indirect_1;
    let _e18 = s_12;
    let _e21 = s_12;
    return ((_e6 + ((_e7.indirectDiffuseColor * _e9.diffuse) * _e12.occlusion)) + ((_e16.specular * _e18.indirectSpecularAlbedo) * _e21.specularOcclusion));
}

fn pbr_lighting_standard_dfg(diffuseColor_24: vec3<f32>, f0_61: vec3<f32>, coatF0_16: vec3<f32>, perceptualRoughness_48: f32, occlusion_14: f32, n_48: vec3<f32>, v_48: vec3<f32>, gi: pbr_GI, dfg_28: vec2<f32>) -> vec3<f32> {
    var diffuseColor_25: vec3<f32>;
    var f0_62: vec3<f32>;
    var coatF0_17: vec3<f32>;
    var perceptualRoughness_49: f32;
    var occlusion_15: f32;
    var n_49: vec3<f32>;
    var v_49: vec3<f32>;
    var gi_1: pbr_GI;
    var dfg_29: vec2<f32>;
    var s_13: pbr_PreparedSurface;

    diffuseColor_25 = diffuseColor_24;
    f0_62 = f0_61;
    coatF0_17 = coatF0_16;
    perceptualRoughness_49 = perceptualRoughness_48;
    occlusion_15 = occlusion_14;
    n_49 = n_48;
    v_49 = v_48;
    gi_1 = gi;
    dfg_29 = dfg_28;
    let _e18 = diffuseColor_25;
    let _e19 = f0_62;
    let _e20 = coatF0_17;
    let _e21 = perceptualRoughness_49;
    let _e22 = occlusion_15;
    let _e23 = n_49;
    let _e24 = v_49;
    let _e25 = dfg_29;
    let _e26 = pbr_prepare_surface_dfg(_e18, _e19, _e20, _e21, _e22, _e23, _e24, _e25);
    s_13 = _e26;
    let _e28 = s_13;
    let _e29 = gi_1;
    let _e31 = s_13;
    let _e32 = gi_1;
    let _e34 = pbr_lighting_standard_light(_e31, _e32.light);
    let _e35 = pbr_lighting_standard_add_environment(_e28, _e29.indirect, _e34);
    return _e35;
}

fn pbr_lighting_standard(diffuseColor_26: vec3<f32>, f0_63: vec3<f32>, coatF0_18: vec3<f32>, perceptualRoughness_50: f32, occlusion_16: f32, n_50: vec3<f32>, v_50: vec3<f32>, gi_2: pbr_GI) -> vec3<f32> {
    var diffuseColor_27: vec3<f32>;
    var f0_64: vec3<f32>;
    var coatF0_19: vec3<f32>;
    var perceptualRoughness_51: f32;
    var occlusion_17: f32;
    var n_51: vec3<f32>;
    var v_51: vec3<f32>;
    var gi_3: pbr_GI;
    var s_14: pbr_PreparedSurface;

    diffuseColor_27 = diffuseColor_26;
    f0_64 = f0_63;
    coatF0_19 = coatF0_18;
    perceptualRoughness_51 = perceptualRoughness_50;
    occlusion_17 = occlusion_16;
    n_51 = n_50;
    v_51 = v_50;
    gi_3 = gi_2;
    let _e16 = diffuseColor_27;
    let _e17 = f0_64;
    let _e18 = coatF0_19;
    let _e19 = perceptualRoughness_51;
    let _e20 = occlusion_17;
    let _e21 = n_51;
    let _e22 = v_51;
    let _e23 = pbr_prepare_surface(_e16, _e17, _e18, _e19, _e20, _e21, _e22);
    s_14 = _e23;
    let _e25 = s_14;
    let _e26 = gi_3;
    let _e28 = s_14;
    let _e29 = gi_3;
    let _e31 = pbr_lighting_standard_light(_e28, _e29.light);
    let _e32 = pbr_lighting_standard_add_environment(_e25, _e26.indirect, _e31);
    return _e32;
}

fn pbr_lighting_standard_f90_dfg(diffuseColor_28: vec3<f32>, f0_65: vec3<f32>, f90_26: f32, coatF0_20: vec3<f32>, coatF90_6: f32, perceptualRoughness_52: f32, occlusion_18: f32, n_52: vec3<f32>, v_52: vec3<f32>, gi_4: pbr_GI, dfg_30: vec2<f32>) -> vec3<f32> {
    var diffuseColor_29: vec3<f32>;
    var f0_66: vec3<f32>;
    var f90_27: f32;
    var coatF0_21: vec3<f32>;
    var coatF90_7: f32;
    var perceptualRoughness_53: f32;
    var occlusion_19: f32;
    var n_53: vec3<f32>;
    var v_53: vec3<f32>;
    var gi_5: pbr_GI;
    var dfg_31: vec2<f32>;
    var s_15: pbr_PreparedSurface;

    diffuseColor_29 = diffuseColor_28;
    f0_66 = f0_65;
    f90_27 = f90_26;
    coatF0_21 = coatF0_20;
    coatF90_7 = coatF90_6;
    perceptualRoughness_53 = perceptualRoughness_52;
    occlusion_19 = occlusion_18;
    n_53 = n_52;
    v_53 = v_52;
    gi_5 = gi_4;
    dfg_31 = dfg_30;
    let _e22 = diffuseColor_29;
    let _e23 = f0_66;
    let _e24 = f90_27;
    let _e25 = coatF0_21;
    let _e26 = coatF90_7;
    let _e27 = perceptualRoughness_53;
    let _e28 = occlusion_19;
    let _e29 = n_53;
    let _e30 = v_53;
    let _e31 = dfg_31;
    let _e32 = pbr_prepare_surface_f90_dfg(_e22, _e23, _e24, _e25, _e26, _e27, _e28, _e29, _e30, _e31);
    s_15 = _e32;
    let _e34 = s_15;
    let _e35 = gi_5;
    let _e37 = s_15;
    let _e38 = gi_5;
    let _e40 = pbr_lighting_standard_light(_e37, _e38.light);
    let _e41 = pbr_lighting_standard_add_environment(_e34, _e35.indirect, _e40);
    return _e41;
}

fn pbr_lighting_standard_f90_(diffuseColor_30: vec3<f32>, f0_67: vec3<f32>, f90_28: f32, coatF0_22: vec3<f32>, coatF90_8: f32, perceptualRoughness_54: f32, occlusion_20: f32, n_54: vec3<f32>, v_54: vec3<f32>, gi_6: pbr_GI) -> vec3<f32> {
    var diffuseColor_31: vec3<f32>;
    var f0_68: vec3<f32>;
    var f90_29: f32;
    var coatF0_23: vec3<f32>;
    var coatF90_9: f32;
    var perceptualRoughness_55: f32;
    var occlusion_21: f32;
    var n_55: vec3<f32>;
    var v_55: vec3<f32>;
    var gi_7: pbr_GI;
    var s_16: pbr_PreparedSurface;

    diffuseColor_31 = diffuseColor_30;
    f0_68 = f0_67;
    f90_29 = f90_28;
    coatF0_23 = coatF0_22;
    coatF90_9 = coatF90_8;
    perceptualRoughness_55 = perceptualRoughness_54;
    occlusion_21 = occlusion_20;
    n_55 = n_54;
    v_55 = v_54;
    gi_7 = gi_6;
    let _e20 = diffuseColor_31;
    let _e21 = f0_68;
    let _e22 = f90_29;
    let _e23 = coatF0_23;
    let _e24 = coatF90_9;
    let _e25 = perceptualRoughness_55;
    let _e26 = occlusion_21;
    let _e27 = n_55;
    let _e28 = v_55;
    let _e29 = pbr_prepare_surface_f90_(_e20, _e21, _e22, _e23, _e24, _e25, _e26, _e27, _e28);
    s_16 = _e29;
    let _e31 = s_16;
    let _e32 = gi_7;
    let _e34 = s_16;
    let _e35 = gi_7;
    let _e37 = pbr_lighting_standard_light(_e34, _e35.light);
    let _e38 = pbr_lighting_standard_add_environment(_e31, _e32.indirect, _e37);
    return _e38;
}

fn pbr_lighting_clearcoat(base: vec3<f32>, coat: pbr_ClearCoat, v_56: vec3<f32>, gi_8: pbr_GI, coatPrefiltered: vec3<f32>, occlusion_22: f32) -> vec3<f32> {
    var base_1: vec3<f32>;
    var coat_1: pbr_ClearCoat;
    var v_57: vec3<f32>;
    var gi_9: pbr_GI;
    var coatPrefiltered_1: vec3<f32>;
    var occlusion_23: f32;
    var roughness_8: f32;
    var NcdotV_2: f32;
    var dfg_32: vec2<f32>;
    var direct: vec3<f32>;
    var environment: vec3<f32>;

    base_1 = base;
    coat_1 = coat;
    v_57 = v_56;
    gi_9 = gi_8;
    coatPrefiltered_1 = coatPrefiltered;
    occlusion_23 = occlusion_22;
    let _e12 = coat_1;
    let _e14 = pbr_clamp_perceptual_roughness(_e12.perceptualRoughness);
    roughness_8 = _e14;
    let _e16 = coat_1;
    let _e18 = v_57;
    NcdotV_2 = max(dot(_e16.normal, _e18), 0.0001f);
    let _e23 = NcdotV_2;
    let _e24 = roughness_8;
    let _e25 = pbr_env_brdf(_e23, _e24);
    dfg_32 = _e25;
    let _e27 = coat_1;
    let _e29 = v_57;
    let _e30 = gi_9;
    let _e33 = gi_9;
    let _e36 = roughness_8;
    let _e37 = pbr_clearcoat_punctual(_e27.normal, _e29, _e30.light.dir, _e33.light.color, _e36);
    direct = _e37;
    let _e39 = coatPrefiltered_1;
    let _e40 = dfg_32;
    let _e41 = pbr_clearcoat_albedo(_e40);
    let _e42 = NcdotV_2;
    let _e43 = occlusion_23;
    let _e44 = roughness_8;
    let _e45 = roughness_8;
    let _e47 = pbr_specular_occlusion(_e42, _e43, (_e44 * _e45));
    environment = (_e39 * (_e41 * _e47));
    let _e51 = base_1;
    let _e52 = coat_1;
    let _e54 = NcdotV_2;
    let _e55 = dfg_32;
    let _e56 = pbr_clearcoat_base_weight(_e52.mask, _e54, _e55);
    let _e58 = coat_1;
    let _e60 = direct;
    let _e61 = environment;
    return ((_e51 * _e56) + (_e58.mask * (_e60 + _e61)));
}

fn pbr_sheen_energy_scale(E_2: f32) -> f32 {
    var E_3: f32;

    E_3 = E_2;
    let _e3 = E_3;
    return (1f / max(_e3, 1f));
}

fn pbr_sheen_effective_albedo(E_4: f32) -> f32 {
    var E_5: f32;

    E_5 = E_4;
    let _e2 = E_5;
    return min(_e2, 1f);
}

fn pbr_lighting_sheen(base_2: vec3<f32>, sheen: pbr_Sheen, n_56: vec3<f32>, v_58: vec3<f32>, gi_10: pbr_GI, sheenPrefiltered: vec3<f32>, occlusion_24: f32) -> vec3<f32> {
    var base_3: vec3<f32>;
    var sheen_1: pbr_Sheen;
    var n_57: vec3<f32>;
    var v_59: vec3<f32>;
    var gi_11: pbr_GI;
    var sheenPrefiltered_1: vec3<f32>;
    var occlusion_25: f32;
    var NdotV_74: f32;
    var E_6: f32;
    var albedo_14: f32;
    var l_30: vec3<f32>;
    var NdotL_57: f32;
    var h_4: vec3<f32>;
    var NdotH_34: f32;
    var direct_1: vec3<f32>;
    var environment_1: vec3<f32>;

    base_3 = base_2;
    sheen_1 = sheen;
    n_57 = n_56;
    v_59 = v_58;
    gi_11 = gi_10;
    sheenPrefiltered_1 = sheenPrefiltered;
    occlusion_25 = occlusion_24;
    let _e14 = n_57;
    let _e15 = v_59;
    NdotV_74 = max(dot(_e14, _e15), 0.0001f);
    let _e20 = NdotV_74;
    let _e21 = sheen_1;
    let _e23 = pbr_sheen_albedo(_e20, _e21.perceptualRoughness);
    E_6 = _e23;
    let _e25 = E_6;
    let _e26 = pbr_sheen_effective_albedo(_e25);
    albedo_14 = _e26;
    let _e28 = gi_11;
    l_30 = _e28.light.dir;
    let _e32 = n_57;
    let _e33 = l_30;
    NdotL_57 = clamp(dot(_e32, _e33), 0f, 1f);
    let _e39 = l_30;
    let _e40 = v_59;
    let _e42 = pbr_safe_normalize((_e39 + _e40));
    h_4 = _e42;
    let _e44 = n_57;
    let _e45 = h_4;
    NdotH_34 = clamp(dot(_e44, _e45), 0f, 1f);
    let _e51 = NdotL_57;
    let _e52 = NdotV_74;
    let _e53 = NdotH_34;
    let _e54 = sheen_1;
    let _e56 = sheen_1;
    let _e58 = pbr_sheen_lobe(_e51, _e52, _e53, _e54.color, _e56.perceptualRoughness);
    let _e59 = gi_11;
    let _e64 = NdotL_57;
    let _e66 = E_6;
    let _e67 = pbr_sheen_energy_scale(_e66);
    direct_1 = ((_e58 * _e59.light.color) * ((3.1415927f * _e64) * _e67));
    let _e71 = sheenPrefiltered_1;
    let _e72 = sheen_1;
    let _e75 = albedo_14;
    let _e76 = occlusion_25;
    environment_1 = ((_e71 * _e72.color) * (_e75 * _e76));
    let _e80 = base_3;
    let _e81 = sheen_1;
    let _e83 = albedo_14;
    let _e84 = pbr_sheen_albedo_scaling(_e81.color, _e83);
    let _e86 = direct_1;
    let _e88 = environment_1;
    return (((_e80 * _e84) + _e86) + _e88);
}

fn pbr_anisotropic_tangent(n_58: vec3<f32>, direction: vec3<f32>) -> vec3<f32> {
    var n_59: vec3<f32>;
    var direction_1: vec3<f32>;
    var d_2: vec3<f32>;
    var t_13: vec3<f32>;
    var t2_: f32;
    var projected: vec3<f32>;
    var fallback: vec3<f32>;
    var local_30: vec3<f32>;

    n_59 = n_58;
    direction_1 = direction;
    let _e4 = direction_1;
    let _e5 = pbr_safe_normalize(_e4);
    d_2 = _e5;
    let _e7 = d_2;
    let _e8 = n_59;
    let _e9 = n_59;
    let _e10 = d_2;
    t_13 = (_e7 - (_e8 * dot(_e9, _e10)));
    let _e15 = t_13;
    let _e16 = t_13;
    t2_ = dot(_e15, _e16);
    let _e19 = t_13;
    let _e20 = t2_;
    projected = (_e19 * inverseSqrt(max(_e20, 0.000000000000000000000000000000000000011754944f)));
    let _e30 = n_59;
    let _e31 = pbr_tangent_to_world(vec3<f32>(1f, 0f, 0f), _e30);
    fallback = _e31;
    let _e33 = t2_;
    if (_e33 > 0.0000010000001f) {
        let _e38 = projected;
        local_30 = _e38;
    } else {
        let _e39 = fallback;
        local_30 = _e39;
    }
    let _e41 = local_30;
    return _e41;
}

fn pbr_anisotropic_reflection_normal(n_60: vec3<f32>, v_60: vec3<f32>, anisotropy: pbr_Anisotropy, perceptualRoughness_56: f32) -> vec3<f32> {
    var n_61: vec3<f32>;
    var v_61: vec3<f32>;
    var anisotropy_1: pbr_Anisotropy;
    var perceptualRoughness_57: f32;
    var b_14: vec3<f32>;

    n_61 = n_60;
    v_61 = v_60;
    anisotropy_1 = anisotropy;
    perceptualRoughness_57 = perceptualRoughness_56;
    let _e8 = n_61;
    let _e9 = n_61;
    let _e10 = anisotropy_1;
    let _e12 = pbr_anisotropic_tangent(_e9, _e10.direction);
    b_14 = cross(_e8, _e12);
    let _e15 = n_61;
    let _e16 = v_61;
    let _e17 = b_14;
    let _e18 = anisotropy_1;
    let _e20 = perceptualRoughness_57;
    let _e21 = pbr_clamp_perceptual_roughness(_e20);
    let _e22 = pbr_anisotropic_bent_normal(_e15, _e16, _e17, _e18.strength, _e21);
    return _e22;
}

fn pbr_anisotropic_frame(n_62: vec3<f32>, anisotropy_2: pbr_Anisotropy) -> pbr_AnisotropicFrame {
    var n_63: vec3<f32>;
    var anisotropy_3: pbr_Anisotropy;
    var frame: pbr_AnisotropicFrame;

    n_63 = n_62;
    anisotropy_3 = anisotropy_2;
    let _e6 = n_63;
    let _e7 = anisotropy_3;
    let _e9 = pbr_anisotropic_tangent(_e6, _e7.direction);
    frame.t = _e9;
    let _e11 = n_63;
    let _e12 = frame;
    frame.b = cross(_e11, _e12.t);
    let _e16 = anisotropy_3;
    frame.strength = _e16.strength;
    let _e18 = frame;
    return _e18;
}

fn pbr_lighting_anisotropic_light(s_17: pbr_PreparedSurface, frame_1: pbr_AnisotropicFrame, light_2: pbr_Light) -> vec3<f32> {
    var s_18: pbr_PreparedSurface;
    var frame_2: pbr_AnisotropicFrame;
    var light_3: pbr_Light;
    var l_31: vec3<f32>;
    var nDotL: f32;
    var halfSum_2: vec3<f32>;
    var LdotH_13: f32;
    var Fd: f32;
    var local_31: f32;
    var brdf: vec3<f32>;

    s_18 = s_17;
    frame_2 = frame_1;
    light_3 = light_2;
    let _e6 = light_3;
    l_31 = _e6.dir;
    let _e9 = s_18;
    let _e11 = l_31;
    nDotL = dot(_e9.n, _e11);
    let _e14 = l_31;
    let _e15 = s_18;
    halfSum_2 = (_e14 + _e15.v);
    let _e20 = halfSum_2;
    let _e21 = halfSum_2;
    LdotH_13 = (0.5f * sqrt(dot(_e20, _e21)));
    let _e26 = s_18;
    let _e28 = s_18;
    let _e34 = nDotL;
    let _e35 = LdotH_13;
    let _e36 = s_18;
    let _e38 = pbr_diffuse_Fd(clamp(dot(_e26.n, _e28.v), 0.0001f, 1f), _e34, _e35, _e36.perceptualRoughness);
    Fd = _e38;
    let _e40 = nDotL;
    if (_e40 > 0f) {
        let _e43 = Fd;
        local_31 = _e43;
    } else {
        local_31 = 0f;
    }
    let _e46 = local_31;
    Fd = _e46;
    let _e47 = s_18;
    let _e49 = Fd;
    let _e51 = s_18;
    let _e53 = s_18;
    let _e55 = l_31;
    let _e56 = frame_2;
    let _e58 = frame_2;
    let _e60 = s_18;
    let _e62 = s_18;
    let _e64 = s_18;
    let _e66 = frame_2;
    let _e68 = pbr_brdf_anisotropic_specular_f90_(_e51.n, _e53.v, _e55, _e56.t, _e58.b, _e60.f0_, _e62.f90_, _e64.perceptualRoughness, _e66.strength);
    brdf = ((_e47.directDiffuseColor * _e49) + _e68);
    let _e71 = light_3;
    let _e73 = brdf;
    let _e76 = nDotL;
    return ((_e71.color * _e73) * (3.1415927f * clamp(_e76, 0f, 1f)));
}

fn pbr_lighting_anisotropic_dfg(diffuseColor_32: vec3<f32>, f0_69: vec3<f32>, coatF0_24: vec3<f32>, perceptualRoughness_58: f32, occlusion_26: f32, n_64: vec3<f32>, v_62: vec3<f32>, gi_12: pbr_GI, anisotropy_4: pbr_Anisotropy, dfg_33: vec2<f32>) -> vec3<f32> {
    var diffuseColor_33: vec3<f32>;
    var f0_70: vec3<f32>;
    var coatF0_25: vec3<f32>;
    var perceptualRoughness_59: f32;
    var occlusion_27: f32;
    var n_65: vec3<f32>;
    var v_63: vec3<f32>;
    var gi_13: pbr_GI;
    var anisotropy_5: pbr_Anisotropy;
    var dfg_34: vec2<f32>;
    var s_19: pbr_PreparedSurface;

    diffuseColor_33 = diffuseColor_32;
    f0_70 = f0_69;
    coatF0_25 = coatF0_24;
    perceptualRoughness_59 = perceptualRoughness_58;
    occlusion_27 = occlusion_26;
    n_65 = n_64;
    v_63 = v_62;
    gi_13 = gi_12;
    anisotropy_5 = anisotropy_4;
    dfg_34 = dfg_33;
    let _e20 = diffuseColor_33;
    let _e21 = f0_70;
    let _e22 = coatF0_25;
    let _e23 = perceptualRoughness_59;
    let _e24 = occlusion_27;
    let _e25 = n_65;
    let _e26 = v_63;
    let _e27 = dfg_34;
    let _e28 = pbr_prepare_surface_dfg(_e20, _e21, _e22, _e23, _e24, _e25, _e26, _e27);
    s_19 = _e28;
    let _e30 = s_19;
    let _e31 = gi_13;
    let _e33 = s_19;
    let _e34 = n_65;
    let _e35 = anisotropy_5;
    let _e36 = pbr_anisotropic_frame(_e34, _e35);
    let _e37 = gi_13;
    let _e39 = pbr_lighting_anisotropic_light(_e33, _e36, _e37.light);
    let _e40 = pbr_lighting_standard_add_environment(_e30, _e31.indirect, _e39);
    return _e40;
}

fn pbr_lighting_anisotropic_f90_(diffuseColor_34: vec3<f32>, f0_71: vec3<f32>, f90_30: f32, coatF0_26: vec3<f32>, coatF90_10: f32, perceptualRoughness_60: f32, occlusion_28: f32, n_66: vec3<f32>, v_64: vec3<f32>, gi_14: pbr_GI, anisotropy_6: pbr_Anisotropy) -> vec3<f32> {
    var diffuseColor_35: vec3<f32>;
    var f0_72: vec3<f32>;
    var f90_31: f32;
    var coatF0_27: vec3<f32>;
    var coatF90_11: f32;
    var perceptualRoughness_61: f32;
    var occlusion_29: f32;
    var n_67: vec3<f32>;
    var v_65: vec3<f32>;
    var gi_15: pbr_GI;
    var anisotropy_7: pbr_Anisotropy;
    var s_20: pbr_PreparedSurface;

    diffuseColor_35 = diffuseColor_34;
    f0_72 = f0_71;
    f90_31 = f90_30;
    coatF0_27 = coatF0_26;
    coatF90_11 = coatF90_10;
    perceptualRoughness_61 = perceptualRoughness_60;
    occlusion_29 = occlusion_28;
    n_67 = n_66;
    v_65 = v_64;
    gi_15 = gi_14;
    anisotropy_7 = anisotropy_6;
    let _e22 = diffuseColor_35;
    let _e23 = f0_72;
    let _e24 = f90_31;
    let _e25 = coatF0_27;
    let _e26 = coatF90_11;
    let _e27 = perceptualRoughness_61;
    let _e28 = occlusion_29;
    let _e29 = n_67;
    let _e30 = v_65;
    let _e31 = pbr_prepare_surface_f90_(_e22, _e23, _e24, _e25, _e26, _e27, _e28, _e29, _e30);
    s_20 = _e31;
    let _e33 = s_20;
    let _e34 = gi_15;
    let _e36 = s_20;
    let _e37 = n_67;
    let _e38 = anisotropy_7;
    let _e39 = pbr_anisotropic_frame(_e37, _e38);
    let _e40 = gi_15;
    let _e42 = pbr_lighting_anisotropic_light(_e36, _e39, _e40.light);
    let _e43 = pbr_lighting_standard_add_environment(_e33, _e34.indirect, _e42);
    return _e43;
}

fn pbr_lighting_anisotropic(diffuseColor_36: vec3<f32>, f0_73: vec3<f32>, coatF0_28: vec3<f32>, perceptualRoughness_62: f32, occlusion_30: f32, n_68: vec3<f32>, v_66: vec3<f32>, gi_16: pbr_GI, anisotropy_8: pbr_Anisotropy) -> vec3<f32> {
    var diffuseColor_37: vec3<f32>;
    var f0_74: vec3<f32>;
    var coatF0_29: vec3<f32>;
    var perceptualRoughness_63: f32;
    var occlusion_31: f32;
    var n_69: vec3<f32>;
    var v_67: vec3<f32>;
    var gi_17: pbr_GI;
    var anisotropy_9: pbr_Anisotropy;
    var s_21: pbr_PreparedSurface;

    diffuseColor_37 = diffuseColor_36;
    f0_74 = f0_73;
    coatF0_29 = coatF0_28;
    perceptualRoughness_63 = perceptualRoughness_62;
    occlusion_31 = occlusion_30;
    n_69 = n_68;
    v_67 = v_66;
    gi_17 = gi_16;
    anisotropy_9 = anisotropy_8;
    let _e18 = diffuseColor_37;
    let _e19 = f0_74;
    let _e20 = coatF0_29;
    let _e21 = perceptualRoughness_63;
    let _e22 = occlusion_31;
    let _e23 = n_69;
    let _e24 = v_67;
    let _e25 = pbr_prepare_surface(_e18, _e19, _e20, _e21, _e22, _e23, _e24);
    s_21 = _e25;
    let _e27 = s_21;
    let _e28 = gi_17;
    let _e30 = s_21;
    let _e31 = n_69;
    let _e32 = anisotropy_9;
    let _e33 = pbr_anisotropic_frame(_e31, _e32);
    let _e34 = gi_17;
    let _e36 = pbr_lighting_anisotropic_light(_e30, _e33, _e34.light);
    let _e37 = pbr_lighting_standard_add_environment(_e27, _e28.indirect, _e36);
    return _e37;
}

fn pbr_f0_from_schlick(F_3: vec3<f32>, cosTheta_7: f32) -> vec3<f32> {
    var F_4: vec3<f32>;
    var cosTheta_8: f32;
    var x_26: f32;

    F_4 = F_3;
    cosTheta_8 = cosTheta_7;
    let _e5 = cosTheta_8;
    let _e6 = pbr_saturate(_e5);
    let _e8 = pbr_pow5_((1f - _e6));
    x_26 = min(_e8, 0.9999f);
    let _e12 = F_4;
    let _e13 = x_26;
    let _e17 = x_26;
    let _e21 = pbr_saturate_1(((_e12 - vec3(_e13)) / vec3((1f - _e17))));
    return _e21;
}

fn pbr_iridescent_f0_(f0_75: vec3<f32>, NdotV_75: f32, film: pbr_Iridescence) -> vec3<f32> {
    var f0_76: vec3<f32>;
    var NdotV_76: f32;
    var film_1: pbr_Iridescence;
    var filmF: vec3<f32>;

    f0_76 = f0_75;
    NdotV_76 = NdotV_75;
    film_1 = film;
    let _e7 = film_1;
    let _e9 = NdotV_76;
    let _e10 = film_1;
    let _e12 = f0_76;
    let _e13 = pbr_F_Iridescence(1f, _e7.ior, _e9, _e10.thicknessNm, _e12);
    filmF = _e13;
    let _e15 = f0_76;
    let _e16 = filmF;
    let _e17 = NdotV_76;
    let _e18 = pbr_f0_from_schlick(_e16, _e17);
    let _e19 = film_1;
    let _e21 = pbr_iridescence_mix(_e15, _e18, _e19.factor);
    return _e21;
}

fn pbr_iridescent_f0_with_coat(f0_77: vec3<f32>, coatF0_30: vec3<f32>, NdotV_77: f32, film_2: pbr_Iridescence) -> pbr_IridescentF0_ {
    var f0_78: vec3<f32>;
    var coatF0_31: vec3<f32>;
    var NdotV_78: f32;
    var film_3: pbr_Iridescence;
    var thin: pbr_ThinFilm;
    var r_12: pbr_IridescentF0_;
    var coatI: vec3<f32>;
    var I_2: vec3<f32>;
    var F_5: vec3<f32>;
    var coatF: vec3<f32>;

    f0_78 = f0_77;
    coatF0_31 = coatF0_30;
    NdotV_78 = NdotV_77;
    film_3 = film_2;
    let _e9 = film_3;
    let _e11 = NdotV_78;
    let _e12 = film_3;
    let _e14 = pbr_thin_film(1f, _e9.ior, _e11, _e12.thicknessNm);
    thin = _e14;
    let _e17 = thin;
    let _e18 = coatF0_31;
    let _e19 = pbr_iridescence_airy(_e17, _e18);
    coatI = _e19;
    let _e21 = thin;
    let _e22 = f0_78;
    let _e23 = pbr_iridescence_airy(_e21, _e22);
    I_2 = _e23;
    let _e25 = thin;
    let _e26 = f0_78;
    let _e27 = I_2;
    let _e28 = pbr_iridescence_select(_e25, _e26, _e27);
    F_5 = _e28;
    let _e30 = thin;
    let _e31 = coatF0_31;
    let _e32 = coatI;
    let _e33 = pbr_iridescence_select(_e30, _e31, _e32);
    coatF = _e33;
    let _e36 = coatF0_31;
    let _e37 = coatF;
    let _e38 = NdotV_78;
    let _e39 = pbr_f0_from_schlick(_e37, _e38);
    let _e40 = film_3;
    let _e42 = pbr_iridescence_mix(_e36, _e39, _e40.factor);
    r_12.coatF0_ = _e42;
    let _e44 = f0_78;
    let _e45 = F_5;
    let _e46 = NdotV_78;
    let _e47 = pbr_f0_from_schlick(_e45, _e46);
    let _e48 = film_3;
    let _e50 = pbr_iridescence_mix(_e44, _e47, _e48.factor);
    r_12.f0_ = _e50;
    let _e51 = r_12;
    return _e51;
}

fn pbr_iridescent_f0_f90_(f0_79: vec3<f32>, f90_32: f32, NdotV_79: f32, film_4: pbr_Iridescence) -> vec3<f32> {
    var f0_80: vec3<f32>;
    var f90_33: f32;
    var NdotV_80: f32;
    var film_5: pbr_Iridescence;
    var unitF0_: vec3<f32>;

    f0_80 = f0_79;
    f90_33 = f90_32;
    NdotV_80 = NdotV_79;
    film_5 = film_4;
    let _e8 = f0_80;
    let _e9 = f90_33;
    let _e14 = pbr_saturate_1((_e8 / vec3(max(_e9, 0.000000000000000000000000000000000000011754944f))));
    unitF0_ = _e14;
    let _e16 = f90_33;
    let _e17 = unitF0_;
    let _e18 = NdotV_80;
    let _e19 = film_5;
    let _e20 = pbr_iridescent_f0_(_e17, _e18, _e19);
    return (_e16 * _e20);
}

fn pbr_iridescent_f0_f90_with_coat(f0_81: vec3<f32>, f90_34: f32, coatF0_32: vec3<f32>, coatF90_12: f32, NdotV_81: f32, film_6: pbr_Iridescence) -> pbr_IridescentF0_ {
    var f0_82: vec3<f32>;
    var f90_35: f32;
    var coatF0_33: vec3<f32>;
    var coatF90_13: f32;
    var NdotV_82: f32;
    var film_7: pbr_Iridescence;
    var thin_1: pbr_ThinFilm;
    var unitCoatF0_: vec3<f32>;
    var unitF0_1: vec3<f32>;
    var coatI_1: vec3<f32>;
    var I_3: vec3<f32>;
    var F_6: vec3<f32>;
    var coatF_1: vec3<f32>;
    var r_13: pbr_IridescentF0_;

    f0_82 = f0_81;
    f90_35 = f90_34;
    coatF0_33 = coatF0_32;
    coatF90_13 = coatF90_12;
    NdotV_82 = NdotV_81;
    film_7 = film_6;
    let _e13 = film_7;
    let _e15 = NdotV_82;
    let _e16 = film_7;
    let _e18 = pbr_thin_film(1f, _e13.ior, _e15, _e16.thicknessNm);
    thin_1 = _e18;
    let _e20 = coatF0_33;
    let _e21 = coatF90_13;
    let _e26 = pbr_saturate_1((_e20 / vec3(max(_e21, 0.000000000000000000000000000000000000011754944f))));
    unitCoatF0_ = _e26;
    let _e28 = f0_82;
    let _e29 = f90_35;
    let _e34 = pbr_saturate_1((_e28 / vec3(max(_e29, 0.000000000000000000000000000000000000011754944f))));
    unitF0_1 = _e34;
    let _e36 = thin_1;
    let _e37 = unitCoatF0_;
    let _e38 = pbr_iridescence_airy(_e36, _e37);
    coatI_1 = _e38;
    let _e40 = thin_1;
    let _e41 = unitF0_1;
    let _e42 = pbr_iridescence_airy(_e40, _e41);
    I_3 = _e42;
    let _e44 = thin_1;
    let _e45 = unitF0_1;
    let _e46 = I_3;
    let _e47 = pbr_iridescence_select(_e44, _e45, _e46);
    F_6 = _e47;
    let _e49 = thin_1;
    let _e50 = unitCoatF0_;
    let _e51 = coatI_1;
    let _e52 = pbr_iridescence_select(_e49, _e50, _e51);
    coatF_1 = _e52;
    let _e56 = coatF90_13;
    let _e57 = unitCoatF0_;
    let _e58 = coatF_1;
    let _e59 = NdotV_82;
    let _e60 = pbr_f0_from_schlick(_e58, _e59);
    let _e61 = film_7;
    let _e63 = pbr_iridescence_mix(_e57, _e60, _e61.factor);
    r_13.coatF0_ = (_e56 * _e63);
    let _e66 = f90_35;
    let _e67 = unitF0_1;
    let _e68 = F_6;
    let _e69 = NdotV_82;
    let _e70 = pbr_f0_from_schlick(_e68, _e69);
    let _e71 = film_7;
    let _e73 = pbr_iridescence_mix(_e67, _e70, _e71.factor);
    r_13.f0_ = (_e66 * _e73);
    let _e75 = r_13;
    return _e75;
}

fn pbr_iridescent_diffuse_color(diffuseColor_38: vec3<f32>, coatF0_34: vec3<f32>, filmCoatF0_: vec3<f32>) -> vec3<f32> {
    var diffuseColor_39: vec3<f32>;
    var coatF0_35: vec3<f32>;
    var filmCoatF0_1: vec3<f32>;

    diffuseColor_39 = diffuseColor_38;
    coatF0_35 = coatF0_34;
    filmCoatF0_1 = filmCoatF0_;
    let _e6 = diffuseColor_39;
    let _e7 = coatF0_35;
    let _e8 = pbr_diffuse_albedo_from_diffuse_color(_e6, _e7);
    let _e10 = filmCoatF0_1;
    let _e11 = pbr_max3_(_e10);
    return (_e8 * max((1f - _e11), 0.0001f));
}

fn pbr_transmission_diffuse_color(diffuseColor_40: vec3<f32>, transmission: f32) -> vec3<f32> {
    var diffuseColor_41: vec3<f32>;
    var transmission_1: f32;

    diffuseColor_41 = diffuseColor_40;
    transmission_1 = transmission;
    let _e4 = diffuseColor_41;
    let _e6 = transmission_1;
    let _e7 = pbr_saturate(_e6);
    return (_e4 * (1f - _e7));
}

fn pbr_transmitted_direction(n_70: vec3<f32>, v_68: vec3<f32>, tr: pbr_Transmission) -> vec3<f32> {
    var n_71: vec3<f32>;
    var v_69: vec3<f32>;
    var tr_1: pbr_Transmission;
    var local_32: vec3<f32>;

    n_71 = n_70;
    v_69 = v_68;
    tr_1 = tr;
    let _e6 = tr_1;
    if (_e6.thickness > 0f) {
        let _e10 = n_71;
        let _e11 = v_69;
        let _e12 = tr_1;
        let _e14 = pbr_refraction_direction(_e10, _e11, _e12.ior);
        local_32 = _e14;
    } else {
        let _e15 = v_69;
        local_32 = -(_e15);
    }
    let _e18 = local_32;
    return _e18;
}

fn pbr_prepare_transmission_from_surface(s_22: pbr_PreparedSurface, diffuseColor_42: vec3<f32>, coatF0_36: vec3<f32>, tr_2: pbr_Transmission) -> pbr_PreparedTransmission {
    var s_23: pbr_PreparedSurface;
    var diffuseColor_43: vec3<f32>;
    var coatF0_37: vec3<f32>;
    var tr_3: pbr_Transmission;
    var t_14: pbr_PreparedTransmission;
    var local_33: vec3<f32>;
    var attenuation: vec3<f32>;

    s_23 = s_22;
    diffuseColor_43 = diffuseColor_42;
    coatF0_37 = coatF0_36;
    tr_3 = tr_2;
    let _e10 = s_23;
    t_14.s = _e10;
    let _e12 = diffuseColor_43;
    let _e13 = coatF0_37;
    let _e14 = pbr_diffuse_albedo_from_diffuse_color(_e12, _e13);
    t_14.rho = _e14;
    let _e16 = tr_3;
    t_14.volume = (_e16.thickness > 0f);
    let _e20 = t_14;
    if _e20.volume {
        let _e22 = tr_3;
        let _e24 = tr_3;
        let _e26 = tr_3;
        let _e28 = pbr_volume_attenuation(_e22.thickness, _e24.attenuationColor, _e26.attenuationDistance);
        local_33 = _e28;
    } else {
        local_33 = vec3(1f);
    }
    let _e32 = local_33;
    attenuation = _e32;
    let _e35 = tr_3;
    let _e37 = pbr_saturate(_e35.factor);
    let _e38 = attenuation;
    t_14.weight = (_e37 * _e38);
    let _e41 = tr_3;
    t_14.ior = _e41.ior;
    let _e43 = t_14;
    return _e43;
}

fn pbr_prepare_transmission_dfg(diffuseColor_44: vec3<f32>, coatF0_38: vec3<f32>, perceptualRoughness_64: f32, occlusion_32: f32, n_72: vec3<f32>, v_70: vec3<f32>, tr_4: pbr_Transmission, dfg_35: vec2<f32>) -> pbr_PreparedTransmission {
    var diffuseColor_45: vec3<f32>;
    var coatF0_39: vec3<f32>;
    var perceptualRoughness_65: f32;
    var occlusion_33: f32;
    var n_73: vec3<f32>;
    var v_71: vec3<f32>;
    var tr_5: pbr_Transmission;
    var dfg_36: vec2<f32>;

    diffuseColor_45 = diffuseColor_44;
    coatF0_39 = coatF0_38;
    perceptualRoughness_65 = perceptualRoughness_64;
    occlusion_33 = occlusion_32;
    n_73 = n_72;
    v_71 = v_70;
    tr_5 = tr_4;
    dfg_36 = dfg_35;
    let _e16 = diffuseColor_45;
    let _e17 = coatF0_39;
    let _e18 = coatF0_39;
    let _e19 = perceptualRoughness_65;
    let _e20 = occlusion_33;
    let _e21 = n_73;
    let _e22 = v_71;
    let _e23 = dfg_36;
    let _e24 = pbr_prepare_surface_dfg(_e16, _e17, _e18, _e19, _e20, _e21, _e22, _e23);
    let _e25 = diffuseColor_45;
    let _e26 = coatF0_39;
    let _e27 = tr_5;
    let _e28 = pbr_prepare_transmission_from_surface(_e24, _e25, _e26, _e27);
    return _e28;
}

fn pbr_prepare_transmission_f90_dfg(diffuseColor_46: vec3<f32>, coatF0_40: vec3<f32>, coatF90_14: f32, perceptualRoughness_66: f32, occlusion_34: f32, n_74: vec3<f32>, v_72: vec3<f32>, tr_6: pbr_Transmission, dfg_37: vec2<f32>) -> pbr_PreparedTransmission {
    var diffuseColor_47: vec3<f32>;
    var coatF0_41: vec3<f32>;
    var coatF90_15: f32;
    var perceptualRoughness_67: f32;
    var occlusion_35: f32;
    var n_75: vec3<f32>;
    var v_73: vec3<f32>;
    var tr_7: pbr_Transmission;
    var dfg_38: vec2<f32>;

    diffuseColor_47 = diffuseColor_46;
    coatF0_41 = coatF0_40;
    coatF90_15 = coatF90_14;
    perceptualRoughness_67 = perceptualRoughness_66;
    occlusion_35 = occlusion_34;
    n_75 = n_74;
    v_73 = v_72;
    tr_7 = tr_6;
    dfg_38 = dfg_37;
    let _e18 = diffuseColor_47;
    let _e19 = coatF0_41;
    let _e20 = coatF90_15;
    let _e21 = coatF0_41;
    let _e22 = coatF90_15;
    let _e23 = perceptualRoughness_67;
    let _e24 = occlusion_35;
    let _e25 = n_75;
    let _e26 = v_73;
    let _e27 = dfg_38;
    let _e28 = pbr_prepare_surface_f90_dfg(_e18, _e19, _e20, _e21, _e22, _e23, _e24, _e25, _e26, _e27);
    let _e29 = diffuseColor_47;
    let _e30 = coatF0_41;
    let _e31 = tr_7;
    let _e32 = pbr_prepare_transmission_from_surface(_e28, _e29, _e30, _e31);
    return _e32;
}

fn pbr_transmission_direct(t_15: pbr_PreparedTransmission, light_4: pbr_Light) -> vec3<f32> {
    var t_16: pbr_PreparedTransmission;
    var light_5: pbr_Light;
    var direct_2: vec3<f32>;

    t_16 = t_15;
    light_5 = light_4;
    let _e5 = t_16;
    if _e5.volume {
        {
            let _e7 = t_16;
            let _e10 = t_16;
            let _e13 = light_5;
            let _e15 = light_5;
            let _e17 = t_16;
            let _e19 = t_16;
            let _e22 = t_16;
            let _e24 = pbr_transmission_punctual(_e7.s.n, _e10.s.v, _e13.dir, _e15.color, _e17.rho, _e19.s.perceptualRoughness, _e22.ior);
            direct_2 = _e24;
        }
    } else {
        {
            let _e25 = t_16;
            let _e28 = t_16;
            let _e31 = light_5;
            let _e33 = light_5;
            let _e35 = t_16;
            let _e38 = t_16;
            let _e41 = pbr_transmission_thin_punctual(_e25.s.n, _e28.s.v, _e31.dir, _e33.color, _e35.s.directDiffuseColor, _e38.s.perceptualRoughness);
            direct_2 = _e41;
        }
    }
    let _e42 = direct_2;
    return _e42;
}

fn pbr_lighting_transmission_light(t_17: pbr_PreparedTransmission, light_6: pbr_Light) -> vec3<f32> {
    var t_18: pbr_PreparedTransmission;
    var light_7: pbr_Light;

    t_18 = t_17;
    light_7 = light_6;
    let _e4 = t_18;
    let _e6 = t_18;
    let _e7 = light_7;
    let _e8 = pbr_transmission_direct(_e6, _e7);
    return (_e4.weight * _e8);
}

fn pbr_lighting_transmission_environment(t_19: pbr_PreparedTransmission, transmittedIndirect: vec3<f32>) -> vec3<f32> {
    var t_20: pbr_PreparedTransmission;
    var transmittedIndirect_1: vec3<f32>;

    t_20 = t_19;
    transmittedIndirect_1 = transmittedIndirect;
    let _e4 = t_20;
    let _e6 = t_20;
    let _e9 = transmittedIndirect_1;
    let _e11 = t_20;
    return (_e4.weight * ((_e6.s.indirectDiffuseColor * _e9) * _e11.s.occlusion));
}

fn pbr_lighting_transmission_prepared(t_21: pbr_PreparedTransmission, light_8: pbr_Light, transmittedIndirect_2: vec3<f32>) -> vec3<f32> {
    var t_22: pbr_PreparedTransmission;
    var light_9: pbr_Light;
    var transmittedIndirect_3: vec3<f32>;

    t_22 = t_21;
    light_9 = light_8;
    transmittedIndirect_3 = transmittedIndirect_2;
    let _e6 = t_22;
    let _e8 = t_22;
    let _e9 = light_9;
    let _e10 = pbr_transmission_direct(_e8, _e9);
    let _e11 = t_22;
    let _e14 = transmittedIndirect_3;
    let _e16 = t_22;
    return (_e6.weight * (_e10 + ((_e11.s.indirectDiffuseColor * _e14) * _e16.s.occlusion)));
}

fn pbr_lighting_transmission(diffuseColor_48: vec3<f32>, coatF0_42: vec3<f32>, perceptualRoughness_68: f32, occlusion_36: f32, n_76: vec3<f32>, v_74: vec3<f32>, gi_18: pbr_GI, transmittedIndirect_4: vec3<f32>, tr_8: pbr_Transmission) -> vec3<f32> {
    var diffuseColor_49: vec3<f32>;
    var coatF0_43: vec3<f32>;
    var perceptualRoughness_69: f32;
    var occlusion_37: f32;
    var n_77: vec3<f32>;
    var v_75: vec3<f32>;
    var gi_19: pbr_GI;
    var transmittedIndirect_5: vec3<f32>;
    var tr_9: pbr_Transmission;
    var roughness_9: f32;
    var dfg_39: vec2<f32>;

    diffuseColor_49 = diffuseColor_48;
    coatF0_43 = coatF0_42;
    perceptualRoughness_69 = perceptualRoughness_68;
    occlusion_37 = occlusion_36;
    n_77 = n_76;
    v_75 = v_74;
    gi_19 = gi_18;
    transmittedIndirect_5 = transmittedIndirect_4;
    tr_9 = tr_8;
    let _e18 = perceptualRoughness_69;
    let _e19 = pbr_clamp_perceptual_roughness(_e18);
    roughness_9 = _e19;
    let _e21 = n_77;
    let _e22 = v_75;
    let _e26 = roughness_9;
    let _e27 = pbr_env_brdf(max(dot(_e21, _e22), 0.0001f), _e26);
    dfg_39 = _e27;
    let _e29 = diffuseColor_49;
    let _e30 = coatF0_43;
    let _e31 = roughness_9;
    let _e32 = occlusion_37;
    let _e33 = n_77;
    let _e34 = v_75;
    let _e35 = tr_9;
    let _e36 = dfg_39;
    let _e37 = pbr_prepare_transmission_dfg(_e29, _e30, _e31, _e32, _e33, _e34, _e35, _e36);
    let _e38 = gi_19;
    let _e40 = transmittedIndirect_5;
    let _e41 = pbr_lighting_transmission_prepared(_e37, _e38.light, _e40);
    return _e41;
}

fn pbr_lighting_transmission_f90_(diffuseColor_50: vec3<f32>, coatF0_44: vec3<f32>, coatF90_16: f32, perceptualRoughness_70: f32, occlusion_38: f32, n_78: vec3<f32>, v_76: vec3<f32>, gi_20: pbr_GI, transmittedIndirect_6: vec3<f32>, tr_10: pbr_Transmission) -> vec3<f32> {
    var diffuseColor_51: vec3<f32>;
    var coatF0_45: vec3<f32>;
    var coatF90_17: f32;
    var perceptualRoughness_71: f32;
    var occlusion_39: f32;
    var n_79: vec3<f32>;
    var v_77: vec3<f32>;
    var gi_21: pbr_GI;
    var transmittedIndirect_7: vec3<f32>;
    var tr_11: pbr_Transmission;
    var roughness_10: f32;
    var dfg_40: vec2<f32>;

    diffuseColor_51 = diffuseColor_50;
    coatF0_45 = coatF0_44;
    coatF90_17 = coatF90_16;
    perceptualRoughness_71 = perceptualRoughness_70;
    occlusion_39 = occlusion_38;
    n_79 = n_78;
    v_77 = v_76;
    gi_21 = gi_20;
    transmittedIndirect_7 = transmittedIndirect_6;
    tr_11 = tr_10;
    let _e20 = perceptualRoughness_71;
    let _e21 = pbr_clamp_perceptual_roughness(_e20);
    roughness_10 = _e21;
    let _e23 = n_79;
    let _e24 = v_77;
    let _e28 = roughness_10;
    let _e29 = pbr_env_brdf(max(dot(_e23, _e24), 0.0001f), _e28);
    dfg_40 = _e29;
    let _e31 = diffuseColor_51;
    let _e32 = coatF0_45;
    let _e33 = coatF90_17;
    let _e34 = roughness_10;
    let _e35 = occlusion_39;
    let _e36 = n_79;
    let _e37 = v_77;
    let _e38 = tr_11;
    let _e39 = dfg_40;
    let _e40 = pbr_prepare_transmission_f90_dfg(_e31, _e32, _e33, _e34, _e35, _e36, _e37, _e38, _e39);
    let _e41 = gi_21;
    let _e43 = transmittedIndirect_7;
    let _e44 = pbr_lighting_transmission_prepared(_e40, _e41.light, _e43);
    return _e44;
}

fn pbr_apply_exposure(color: vec3<f32>, exposureEV: f32) -> vec3<f32> {
    var color_1: vec3<f32>;
    var exposureEV_1: f32;

    color_1 = color;
    exposureEV_1 = exposureEV;
    let _e4 = color_1;
    let _e5 = exposureEV_1;
    return (_e4 * exp2(_e5));
}

fn pbr_tonemap_reinhard(color_2: vec3<f32>) -> vec3<f32> {
    var color_3: vec3<f32>;

    color_3 = color_2;
    let _e2 = color_3;
    let _e4 = pbr_sanitize_1(_e2, 65504f);
    color_3 = _e4;
    let _e5 = color_3;
    let _e8 = color_3;
    return (_e5 / (vec3(1f) + _e8));
}

fn pbr_tonemap_reinhard_extended(color_4: vec3<f32>, whitePoint: f32) -> vec3<f32> {
    var color_5: vec3<f32>;
    var whitePoint_1: f32;

    color_5 = color_4;
    whitePoint_1 = whitePoint;
    let _e4 = color_5;
    let _e5 = whitePoint_1;
    let _e8 = pbr_sanitize_1(_e4, min(_e5, 65504f));
    color_5 = _e8;
    let _e9 = color_5;
    let _e12 = color_5;
    let _e13 = whitePoint_1;
    let _e14 = whitePoint_1;
    let _e22 = color_5;
    let _e25 = pbr_saturate_1(((_e9 * (vec3(1f) + (_e12 / vec3((_e13 * _e14))))) / (vec3(1f) + _e22)));
    return _e25;
}

fn pbr_hable_curve(x_27: f32) -> f32 {
    var x_28: f32;

    x_28 = x_27;
    let _e2 = x_28;
    let _e4 = x_28;
    let _e11 = x_28;
    let _e13 = x_28;
    return ((((_e2 * ((0.15f * _e4) + 0.05f)) + 0.004f) / ((_e11 * ((0.15f * _e13) + 0.5f)) + 0.06f)) - 0.06666667f);
}

fn pbr_tonemap_hable(color_6: vec3<f32>) -> vec3<f32> {
    var color_7: vec3<f32>;
    var curve: vec3<f32>;

    color_7 = color_6;
    let _e2 = color_7;
    let _e4 = pbr_sanitize_1(_e2, 11.2f);
    color_7 = _e4;
    let _e5 = color_7;
    let _e7 = pbr_hable_curve(_e5.x);
    let _e8 = color_7;
    let _e10 = pbr_hable_curve(_e8.y);
    let _e11 = color_7;
    let _e13 = pbr_hable_curve(_e11.z);
    curve = vec3<f32>(_e7, _e10, _e13);
    let _e16 = curve;
    let _e18 = pbr_hable_curve(11.2f);
    let _e21 = pbr_saturate_1((_e16 / vec3(_e18)));
    return _e21;
}

fn pbr_aces_rrt_odt_fit(v_78: vec3<f32>) -> vec3<f32> {
    var v_79: vec3<f32>;
    var a_8: vec3<f32>;
    var b_15: vec3<f32>;

    v_79 = v_78;
    let _e2 = v_79;
    let _e3 = v_79;
    a_8 = ((_e2 * (_e3 + vec3(0.0245786f))) - vec3(0.000090537f));
    let _e12 = v_79;
    let _e14 = v_79;
    b_15 = ((_e12 * ((0.983729f * _e14) + vec3(0.432951f))) + vec3(0.238081f));
    let _e24 = a_8;
    let _e25 = b_15;
    return (_e24 / _e25);
}

fn pbr_tonemap_aces_fitted(color_8: vec3<f32>) -> vec3<f32> {
    var color_9: vec3<f32>;
    var aces: vec3<f32>;
    var fitted: vec3<f32>;
    var rgb: vec3<f32>;

    color_9 = color_8;
    let _e2 = color_9;
    let _e4 = pbr_sanitize_1(_e2, 65504f);
    color_9 = _e4;
    let _e9 = color_9;
    let _e15 = color_9;
    let _e21 = color_9;
    aces = vec3<f32>(dot(vec3<f32>(0.59719f, 0.35458f, 0.04823f), _e9), dot(vec3<f32>(0.076f, 0.90834f, 0.01566f), _e15), dot(vec3<f32>(0.0284f, 0.13383f, 0.83777f), _e21));
    let _e25 = aces;
    let _e26 = pbr_aces_rrt_odt_fit(_e25);
    fitted = _e26;
    let _e34 = fitted;
    let _e42 = fitted;
    let _e50 = fitted;
    rgb = vec3<f32>(dot(vec3<f32>(1.60475f, -0.53108f, -0.07367f), _e34), dot(vec3<f32>(-0.10208f, 1.10813f, -0.00605f), _e42), dot(vec3<f32>(-0.00327f, -0.07276f, 1.07602f), _e50));
    let _e54 = rgb;
    let _e55 = pbr_saturate_1(_e54);
    return _e55;
}

fn pbr_tonemap_aces_narkowicz(x_29: vec3<f32>) -> vec3<f32> {
    var x_30: vec3<f32>;

    x_30 = x_29;
    let _e2 = x_30;
    let _e4 = pbr_sanitize_1(_e2, 16f);
    x_30 = _e4;
    let _e5 = x_30;
    let _e7 = x_30;
    let _e13 = x_30;
    let _e15 = x_30;
    let _e25 = pbr_saturate_1(((_e5 * ((2.51f * _e7) + vec3(0.03f))) / ((_e13 * ((2.43f * _e15) + vec3(0.59f))) + vec3(0.14f))));
    return _e25;
}

fn pbr_tonemap_khronos_neutral(color_10: vec3<f32>) -> vec3<f32> {
    var color_11: vec3<f32>;
    var x_31: f32;
    var local_34: f32;
    var offset: f32;
    var peak: f32;
    var d_3: f32 = 0.24f;
    var newPeak: f32;
    var g_2: f32;

    color_11 = color_10;
    let _e2 = color_11;
    let _e4 = pbr_sanitize_1(_e2, 65504f);
    color_11 = _e4;
    let _e5 = color_11;
    let _e6 = pbr_min3_(_e5);
    x_31 = _e6;
    let _e8 = x_31;
    if (_e8 <= 0.08f) {
        let _e13 = x_31;
        let _e14 = x_31;
        let _e15 = x_31;
        local_34 = (_e13 - ((_e14 * _e15) / 0.16f));
    } else {
        local_34 = 0.04f;
    }
    let _e24 = local_34;
    offset = _e24;
    let _e26 = color_11;
    let _e27 = offset;
    color_11 = (_e26 - vec3(_e27));
    let _e30 = color_11;
    let _e31 = pbr_max3_(_e30);
    peak = _e31;
    let _e33 = peak;
    if (_e33 <= 0.76f) {
        let _e36 = color_11;
        return _e36;
    }
    let _e40 = d_3;
    let _e41 = d_3;
    let _e43 = peak;
    let _e44 = d_3;
    newPeak = (1f - ((_e40 * _e41) / ((_e43 + _e44) - 0.76f)));
    let _e51 = color_11;
    let _e52 = newPeak;
    let _e53 = peak;
    color_11 = (_e51 * (_e52 / _e53));
    let _e59 = peak;
    let _e60 = newPeak;
    g_2 = (1f - (1f / ((0.15f * (_e59 - _e60)) + 1f)));
    let _e68 = color_11;
    let _e69 = newPeak;
    let _e71 = g_2;
    return mix(_e68, vec3(_e69), vec3(_e71));
}

fn pbr_tonemap(color_12: vec3<f32>) -> vec3<f32> {
    var color_13: vec3<f32>;

    color_13 = color_12;
    let _e2 = color_13;
    let _e3 = pbr_tonemap_khronos_neutral(_e2);
    return _e3;
}
