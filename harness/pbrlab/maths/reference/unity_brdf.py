"""Float64 transcription of Unity's built-in Standard BRDFs and their GI inputs, written from
Unity's shader source (Unity 2019.4 built-in shaders, CGIncludes/): UnityStandardBRDF.cginc
(BRDF1_Unity_PBS, BRDF2_Unity_PBS, BRDF3_Unity_PBS and their terms), UnityStandardUtils.cginc
(DiffuseAndSpecularFromMetallic, EnergyConservationBetweenDiffuseAndSpecular),
UnityImageBasedLighting.cginc (Unity_GlossyEnvironment's mip remap), UnityGlobalIllumination.cginc
(UnityGI_Base / UnityGI_IndirectSpecular: occlusion applied to both indirect terms) and
UnityPBSLighting.cginc (LightingStandard, LightingStandardSpecular).

This module is the independent side of the Unity-mode tests: it follows Unity's formulas, not
the library's GLSL (glsl/pbr/unity/brdf_unity.glsl), and is written in numpy float64 with
Unity's own variable names where they help the comparison. Configuration reproduced: a
desktop target in linear colour space (no UNITY_COLORSPACE_GAMMA, no SHADER_API_MOBILE, no
_SPECULARHIGHLIGHTS_OFF), UNITY_BRDF_GGX = 1 (UnityStandardConfig.cginc's default),
UNITY_HANDLE_CORRECTLY_NEGATIVE_NDOTV = 0 (BRDF1's own default), UNITY_CONSERVE_ENERGY and
UNITY_CONSERVE_ENERGY_MONOCHROME = 1, SHADER_TARGET >= 30.

Units are Unity's, which are pbrlab's: light.color is the radiance of a punctual light that
"is pi times too bright" (a white Lambert surface lit along its normal by 1 returns 1), and
gi.diffuse is irradiance / pi.

Vectors carry xyz on the last axis; scalars broadcast against the leading shape.
"""

from __future__ import annotations

import numpy as np

UNITY_PI = np.pi
UNITY_INV_PI = 1.0 / np.pi
# unity_ColorSpaceDielectricSpec in linear colour space (UnityCG.cginc): rgb 0.04, a 1 - 0.04.
DIELECTRIC_SPEC = 0.04
# GGXTerm's denominator epsilon ("not intended to be running on Mobile").
GGX_EPSILON = 1e-7
# SmithJointGGXVisibilityTerm's denominator epsilon (non-Switch platforms).
SMITH_JOINT_EPSILON = 1e-5
# BRDF1: "roughness = max(roughness, 0.002)" to match HDRP's remapping.
BRDF1_MIN_ROUGHNESS = 0.002
# Unity_SafeNormalize's floor on dot(v, v).
SAFE_NORMALIZE_MIN_LENGTH2 = 0.001
# BRDF2 (GGX branch): d = nh² (a² - 1) + 1.00001; max(0.1, lh²); (roughness + 0.5).
BRDF2_D_OFFSET = 1.00001
BRDF2_MIN_LH2 = 0.1
# PerceptualRoughnessToSpecPower: max(1e-4, m²) and max(n, 1e-4).
SPEC_POWER_MIN_M2 = 1e-4
SPEC_POWER_MIN = 1e-4
# BRDF3_Direct: the lookup texture's value times LUT_RANGE (16); x = (R.L)^4 (kHorizontalWarpExp).
NHXROUGHNESS_LUT_RANGE = 16.0
NHXROUGHNESS_WARP_EXPONENT = 4.0
# UnityStandardConfig.cginc: UNITY_SPECCUBE_LOD_STEPS (6).
SPECCUBE_LOD_STEPS = 6.0

# Unity's three BRDFs per pbrlab quality tier in the unity mode (UnityPBSLighting.cginc picks
# them by UNITY_PBS_USE_BRDF1/2/3, i.e. by the graphics tier).
TIER_BRDF = {"HIGH": 1, "MEDIUM": 2, "LOW": 3}


def _f(x):
    return np.asarray(x, np.float64)


def _dot(a, b):
    return np.sum(_f(a) * _f(b), axis=-1)


def saturate(x):
    return np.clip(x, 0.0, 1.0)


def lerp(a, b, t):
    return _f(a) + (_f(b) - _f(a)) * _f(t)


# ---- UnityStandardUtils.cginc ---------------------------------------------------------------

def one_minus_reflectivity_from_metallic(metallic):
    one_minus_dielectric_spec = 1.0 - DIELECTRIC_SPEC
    return one_minus_dielectric_spec - _f(metallic) * one_minus_dielectric_spec


def diffuse_and_specular_from_metallic(albedo, metallic):
    """(diffColor, specColor, oneMinusReflectivity)."""
    metallic = _f(metallic)
    spec_color = lerp(np.full(3, DIELECTRIC_SPEC), albedo, metallic[..., None])
    omr = one_minus_reflectivity_from_metallic(metallic)
    return _f(albedo) * omr[..., None], spec_color, omr


def energy_conservation_between_diffuse_and_specular(albedo, spec_color):
    """(diffColor, oneMinusReflectivity), monochrome conservation: SpecularStrength = max channel."""
    omr = 1.0 - np.max(_f(spec_color), axis=-1)
    return _f(albedo) * omr[..., None], omr


# ---- UnityStandardBRDF.cginc: terms ---------------------------------------------------------

def pow4(x):
    x = _f(x)
    return x * x * x * x


def pow5(x):
    x = _f(x)
    return x * x * x * x * x


def fresnel_term(f0, cos_a):
    t = pow5(1.0 - _f(cos_a))[..., None]
    return _f(f0) + (1.0 - _f(f0)) * t


def fresnel_lerp(f0, f90, cos_a):
    return lerp(f0, _f(f90)[..., None], pow5(1.0 - _f(cos_a))[..., None])


def fresnel_lerp_fast(f0, f90, cos_a):
    return lerp(f0, _f(f90)[..., None], pow4(1.0 - _f(cos_a))[..., None])


def disney_diffuse(nv, nl, lh, perceptual_roughness):
    """Without its 1/pi (Unity's diffuse carries none)."""
    fd90 = 0.5 + 2.0 * _f(lh) * _f(lh) * _f(perceptual_roughness)
    light_scatter = 1.0 + (fd90 - 1.0) * pow5(1.0 - _f(nl))
    view_scatter = 1.0 + (fd90 - 1.0) * pow5(1.0 - _f(nv))
    return light_scatter * view_scatter


def smith_joint_ggx_visibility_term(nl, nv, roughness):
    """Unity's approximation of the height-correlated Smith G / (4 nl nv) (Heitz 2014),
    the #else branch: the square roots replaced by linear terms."""
    a = _f(roughness)
    lambda_v = _f(nl) * (_f(nv) * (1.0 - a) + a)
    lambda_l = _f(nv) * (_f(nl) * (1.0 - a) + a)
    return 0.5 / (lambda_v + lambda_l + SMITH_JOINT_EPSILON)


def ggx_term(nh, roughness):
    a2 = _f(roughness) * _f(roughness)
    d = (_f(nh) * a2 - _f(nh)) * _f(nh) + 1.0
    return UNITY_INV_PI * a2 / (d * d + GGX_EPSILON)


def perceptual_roughness_to_spec_power(perceptual_roughness):
    m = _f(perceptual_roughness) ** 2
    sq = np.maximum(SPEC_POWER_MIN_M2, m * m)
    n = 2.0 / sq - 2.0
    return np.maximum(n, SPEC_POWER_MIN)


def safe_normalize(v):
    dp3 = np.maximum(SAFE_NORMALIZE_MIN_LENGTH2, _dot(v, v))
    return _f(v) / np.sqrt(dp3)[..., None]


def nhx_roughness(rl_pow4, perceptual_roughness):
    """What BRDF3 reads from unity_NHxRoughness (.r * LUT_RANGE), as the analytic function
    the texture stands for. Unity bakes it in GeneratedTextures.cpp, which is not public;
    the function is Unity's own un-baked form, the `#else` branch of BRDF3_Unity_PBS in
    Unity 5.0's UnityStandardBRDF.cginc:
        n = RoughnessToSpecPower(roughness) * .25;
        specular = (n + 2.0) / (2.0 * UNITY_PI * UNITY_PI) * pow(dot(reflDir, light.dir), n) [* nl]
    a normalized Phong lobe around the mirror direction whose exponent is the Blinn-Phong
    power / 4. Written here with today's PerceptualRoughnessToSpecPower, in the texture's
    coordinates (x = (R.L)^4, so (R.L)^n = x^(n/4)), without the `* nl` (BRDF3_Unity_PBS
    multiplies by nl after the lookup; a 2-D texture cannot depend on it), clamped to the
    texture's range [0, LUT_RANGE]."""
    n = perceptual_roughness_to_spec_power(perceptual_roughness) * 0.25
    lobe = np.power(_f(rl_pow4), n / NHXROUGHNESS_WARP_EXPONENT)
    return np.minimum((n + 2.0) / (2.0 * UNITY_PI * UNITY_PI) * lobe, NHXROUGHNESS_LUT_RANGE)


# ---- UnityStandardBRDF.cginc: the three BRDFs -------------------------------------------------

def brdf1_unity_pbs(diff_color, spec_color, one_minus_reflectivity, smoothness, normal, view_dir,
                    light_color, light_dir, gi_diffuse, gi_specular):
    """BRDF1_Unity_PBS (GGX, linear colour space): colour (rgb on the last axis)."""
    smoothness = _f(smoothness)
    perceptual_roughness = 1.0 - smoothness
    half_dir = safe_normalize(_f(light_dir) + _f(view_dir))
    nv = np.abs(_dot(normal, view_dir))
    nl = saturate(_dot(normal, light_dir))
    nh = saturate(_dot(normal, half_dir))
    lh = saturate(_dot(light_dir, half_dir))
    diffuse_term = disney_diffuse(nv, nl, lh, perceptual_roughness) * nl
    roughness = np.maximum(perceptual_roughness ** 2, BRDF1_MIN_ROUGHNESS)
    V = smith_joint_ggx_visibility_term(nl, nv, roughness)
    D = ggx_term(nh, roughness)
    specular_term = V * D * UNITY_PI
    specular_term = np.maximum(0.0, specular_term * nl)
    surface_reduction = 1.0 / (roughness * roughness + 1.0)
    specular_term = specular_term * np.any(_f(spec_color) != 0.0, axis=-1)
    grazing_term = saturate(smoothness + (1.0 - _f(one_minus_reflectivity)))
    return (_f(diff_color) * (_f(gi_diffuse) + _f(light_color) * diffuse_term[..., None])
            + specular_term[..., None] * _f(light_color) * fresnel_term(spec_color, lh)
            + surface_reduction[..., None] * _f(gi_specular) * fresnel_lerp(spec_color, grazing_term, nv))


def brdf2_unity_pbs(diff_color, spec_color, one_minus_reflectivity, smoothness, normal, view_dir,
                    light_color, light_dir, gi_diffuse, gi_specular):
    """BRDF2_Unity_PBS (GGX branch, linear colour space, not SHADER_API_MOBILE)."""
    smoothness = _f(smoothness)
    half_dir = safe_normalize(_f(light_dir) + _f(view_dir))
    nl = saturate(_dot(normal, light_dir))
    nh = saturate(_dot(normal, half_dir))
    nv = saturate(_dot(normal, view_dir))
    lh = saturate(_dot(light_dir, half_dir))
    perceptual_roughness = 1.0 - smoothness
    roughness = perceptual_roughness ** 2
    a = roughness
    a2 = a * a
    d = nh * nh * (a2 - 1.0) + BRDF2_D_OFFSET
    specular_term = a2 / (np.maximum(BRDF2_MIN_LH2, lh * lh) * (roughness + 0.5) * (d * d) * 4.0)
    surface_reduction = 1.0 - roughness * perceptual_roughness * (0.6 - 0.08 * perceptual_roughness)
    grazing_term = saturate(smoothness + (1.0 - _f(one_minus_reflectivity)))
    return ((_f(diff_color) + specular_term[..., None] * _f(spec_color)) * _f(light_color) * nl[..., None]
            + _f(gi_diffuse) * _f(diff_color)
            + surface_reduction[..., None] * _f(gi_specular) * fresnel_lerp_fast(spec_color, grazing_term, nv))


def brdf3_unity_pbs(diff_color, spec_color, one_minus_reflectivity, smoothness, normal, view_dir,
                    light_color, light_dir, gi_diffuse, gi_specular, nhx=nhx_roughness):
    """BRDF3_Unity_PBS; ``nhx(rlPow4, perceptualRoughness)`` stands for the texture lookup
    times LUT_RANGE (default: the analytic function above)."""
    smoothness = _f(smoothness)
    n = _f(normal)
    refl_dir = _f(view_dir) - 2.0 * _dot(n, view_dir)[..., None] * n  # reflect(viewDir, normal)
    nl = saturate(_dot(normal, light_dir))
    nv = saturate(_dot(normal, view_dir))
    rl_pow4 = pow4(_dot(refl_dir, light_dir))
    fresnel = pow4(1.0 - nv)
    grazing_term = saturate(smoothness + (1.0 - _f(one_minus_reflectivity)))
    specular = nhx(rl_pow4, 1.0 - smoothness)
    direct = (_f(diff_color) + specular[..., None] * _f(spec_color)) * _f(light_color) * nl[..., None]
    indirect = _f(gi_diffuse) * _f(diff_color) + _f(gi_specular) * lerp(spec_color, grazing_term[..., None],
                                                                        fresnel[..., None])
    return direct + indirect


BRDFS = {1: brdf1_unity_pbs, 2: brdf2_unity_pbs, 3: brdf3_unity_pbs}


# ---- GI inputs: UnityImageBasedLighting.cginc, UnityGlobalIllumination.cginc -------------------

def glossy_environment_perceptual_roughness(perceptual_roughness):
    """Unity_GlossyEnvironment's remap before perceptualRoughnessToMipmapLevel."""
    r = _f(perceptual_roughness)
    return r * (1.7 - 0.7 * r)


def glossy_environment_mip(perceptual_roughness, lod_steps=SPECCUBE_LOD_STEPS):
    """The cubemap mip Unity samples: remapped perceptual roughness * UNITY_SPECCUBE_LOD_STEPS."""
    return glossy_environment_perceptual_roughness(perceptual_roughness) * lod_steps


def gi_indirect(sh_diffuse, glossy_specular, occlusion):
    """UnityGI_Base and UnityGI_IndirectSpecular: both indirect terms times occlusion."""
    occ = _f(occlusion)[..., None]
    return _f(sh_diffuse) * occ, _f(glossy_specular) * occ


# ---- UnityPBSLighting.cginc -------------------------------------------------------------------

def lighting_standard(albedo, metallic, smoothness, normal, view_dir, light_color, light_dir,
                      gi_diffuse, gi_specular, tier=1):
    """LightingStandard (opaque: PreMultiplyAlpha leaves the diffuse), gi already from the GI
    step (occluded). Returns rgb."""
    normal = _f(normal) / np.linalg.norm(_f(normal), axis=-1, keepdims=True)
    diff, spec, omr = diffuse_and_specular_from_metallic(albedo, metallic)
    return BRDFS[tier](diff, spec, omr, smoothness, normal, view_dir, light_color, light_dir,
                       gi_diffuse, gi_specular)


def lighting_standard_specular(albedo, specular, smoothness, normal, view_dir, light_color, light_dir,
                               gi_diffuse, gi_specular, tier=1):
    normal = _f(normal) / np.linalg.norm(_f(normal), axis=-1, keepdims=True)
    diff, omr = energy_conservation_between_diffuse_and_specular(albedo, specular)
    return BRDFS[tier](diff, specular, omr, smoothness, normal, view_dir, light_color, light_dir,
                       gi_diffuse, gi_specular)
