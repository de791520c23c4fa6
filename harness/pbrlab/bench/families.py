"""The benchmarked families: inputs and their domain, the float64 reference, the variants.

A family names its primary inputs as ``(name, lo, hi)`` (the documented input domain,
sampled on a regular grid for the error and by a per-pixel hash for the timing), derived
values as ``(glsl_type, name, glsl, numpy)`` (computed in both kernels and the error run,
so they cost nothing in the figures), the float64 ``reference`` every variant is compared
with, and the ``exact`` variant that time ratios are taken against.

A variant is one GLSL expression (what a caller writes: the library's function, or its
dispatcher under a selector ``#define``). ``kind`` marks the two measurements that are not
an expression: ``texture`` (a fetch from a bound texture, whose plain fetch is the
baseline) and ``hardware_encode`` (the sRGB framebuffer, measured per pixel).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ..maths.reference import (anisotropy, brdf, clearcoat, color, iridescence, remap, shading, sheen, specular_extension, tonemap)


@dataclass(frozen=True)
class Variant:
    name: str
    expression: str | None
    note: str = ""
    defines: dict = field(default_factory=dict)
    kind: str = "alu"            # alu | texture | hardware_encode
    texture: str | None = None   # texture kernels: srgb8 | unorm8 | dfg
    self_reference: Callable | None = None  # float64 twin of this variant (float32 error)
    peer: str = ""               # a peer engine's code it calls: a file of bench/peers (not the library)


@dataclass(frozen=True)
class Family:
    name: str
    title: str
    inputs: tuple            # (name, lo, hi)
    reference: Callable      # dict of float64 arrays -> float64 array (last axis: components)
    reference_name: str
    exact: str               # the variant time ratios are taken against
    variants: tuple
    derived: tuple = ()      # (glsl_type, name, glsl, numpy(dict) -> array)
    diagonal: bool = False   # all inputs share one 1-D grid (colour channels)
    rel_floor: float = 1e-6  # |ref| below this is not used for the relative error
    domain_note: str = ""
    grid_points: int = 0     # override of points per axis (full run)
    own_reference: bool = False  # no exact model: each variant against its own float64 twin


def _vec3(name):
    return f"vec3({name}0, {name}1, {name}2)"


def _stack(d, name, f):
    return np.stack([f(d[f"{name}{i}"]) for i in range(3)], axis=-1)


# ---- colour transfer --------------------------------------------------------------------
_C3 = tuple((f"c{i}", 0.0, 1.0) for i in range(3))

SRGB_DECODE = Family(
    name="srgb_decode", title="sRGB decode (texel -> linear)",
    inputs=_C3, reference=lambda d: _stack(d, "c", color.srgb_to_linear),
    reference_name="IEC 61966-2-1 decode, float64 (reference.color.srgb_to_linear)",
    exact="exact", diagonal=True, rel_floor=1e-4,
    domain_note="encoded value c in [0, 1] per channel (65536 points; hardware: the 256 codes)",
    variants=(
        Variant("exact", f"pbr_srgb_to_linear({_vec3('c')})", "piecewise IEC curve (pow 2.4)"),
        Variant("gamma22", f"pbr_degamma({_vec3('c')})", "pow(c, 2.2)"),
        Variant("fast", f"pbr_degamma_fast({_vec3('c')})", "c * c"),
        Variant("hardware", "texelFetch(pbrlab_tex, ivec2(int(c0 * 255.0 + 0.5), 0), 0).rgb",
                "GL_SRGB8_ALPHA8 texture; cost = sRGB fetch minus the same UNORM8 fetch",
                kind="texture", texture="srgb8"),
    ))

SRGB_ENCODE = Family(
    name="srgb_encode", title="sRGB encode (linear -> display)",
    inputs=_C3, reference=lambda d: _stack(d, "c", color.linear_to_srgb),
    reference_name="IEC 61966-2-1 encode, float64 (reference.color.linear_to_srgb)",
    exact="exact", diagonal=True, rel_floor=1e-4,
    domain_note="linear value c in [0, 1] per channel (65536 points)",
    variants=(
        Variant("exact", f"pbr_linear_to_srgb({_vec3('c')})", "piecewise IEC curve (pow 1/2.4)"),
        Variant("gamma22", f"pbr_regamma({_vec3('c')})", "pow(c, 1/2.2)"),
        Variant("fast", f"pbr_regamma_fast({_vec3('c')})", "sqrt(c)"),
        Variant("hardware", None, "GL_SRGB8_ALPHA8 framebuffer + GL_FRAMEBUFFER_SRGB; error includes "
                "the 8-bit quantisation; cost = per pixel, sRGB target minus UNORM8 target",
                kind="hardware_encode"),
    ))

# ---- Fresnel ------------------------------------------------------------------------------


def _f0_from_eta(eta):
    return ((eta - 1.0) / (eta + 1.0)) ** 2


FRESNEL = Family(
    name="fresnel", title="Fresnel (dielectric, external reflection)",
    inputs=(("VdotH", 0.0, 1.0), ("eta", 1.25, 2.0)),
    derived=(("float", "f0", "((eta - 1.0) / (eta + 1.0)) * ((eta - 1.0) / (eta + 1.0))",
              lambda d: _f0_from_eta(d["eta"])),),
    reference=lambda d: brdf.F_Dielectric(d["VdotH"], d["eta"])[..., None],
    reference_name="exact unpolarised dielectric Fresnel, float64 (reference.brdf.F_Dielectric)",
    exact="dielectric", rel_floor=1e-6,
    domain_note="VdotH in [0, 1] x IOR eta in [1.25, 2] (F0 = 0.012 ... 0.111); Schlick takes F0 of eta",
    variants=(
        Variant("dielectric", "pbr_F_Dielectric(VdotH, eta)", "exact (Walter 2007 eq. 22)"),
        Variant("schlick", "pbr_F_Schlick(f0, VdotH)", "Schlick pow5 (PBR_SPECULAR_F_SCHLICK)",
                self_reference=lambda d: brdf.F_Schlick(d["f0"], d["VdotH"])[..., None]),
        Variant("schlick_sg", "pbr_F_SchlickSG(vec3(f0), VdotH).x", "spherical-Gaussian exp2 (…_SCHLICK_SG)",
                self_reference=lambda d: brdf.F_SchlickSG(d["f0"], d["VdotH"])[..., None]),
        Variant("none", "1.0", "F = 1 (PBR_SPECULAR_F_NONE)",
                self_reference=lambda d: np.ones(np.shape(d["VdotH"]) + (1,))),
    ))

# ---- distributions ----------------------------------------------------------------------


def _gloss_cod(alpha):
    s = np.maximum(2.0 / alpha ** 2 - 2.0, 1.0)
    return np.clip(np.log2(s) / 13.0, 0.0, 1.0)


DISTRIBUTION = Family(
    name="distribution", title="Normal distribution D",
    inputs=(("NdotH", 0.0, 1.0), ("r", 0.045, 1.0)),
    derived=(("float", "alpha", "r * r", lambda d: d["r"] ** 2),
             ("float", "g_cod", "clamp(log2(max(2.0 / (alpha * alpha) - 2.0, 1.0)) / 13.0, 0.0, 1.0)",
              lambda d: _gloss_cod(d["alpha"])),
             ("float", "g_crytek", "clamp((1.0 - r) / 0.7, 0.0, 1.0)",
              lambda d: np.clip((1.0 - d["r"]) / 0.7, 0.0, 1.0)),
             ("float", "g_unreal", "1.0 - r", lambda d: 1.0 - d["r"])),
    reference=lambda d: brdf.D_GGX(d["NdotH"], d["alpha"])[..., None],
    reference_name="GGX D at the same alpha, float64 (reference.brdf.D_GGX); for Beckmann and "
                   "Blinn-Phong the error is the model difference from GGX",
    exact="ggx", rel_floor=1e-2,
    domain_note="NdotH in [0, 1] x perceptual roughness r in [0.045, 1] (alpha = r^2); gloss "
                "variants receive the gloss that maps to that alpha (clamped to the remap's range); "
                "relative error where D > 0.01 1/sr",
    variants=(
        Variant("ggx", "pbr_D_GGX(NdotH, alpha)", "Walter 2007 (PBR_SPECULAR_D_GGX)"),
        Variant("beckmann", "pbr_D_Beckmann(NdotH, alpha)", "Walter 2007 (…_BECKMANN)",
                self_reference=lambda d: brdf.D_Beckmann(d["NdotH"], d["alpha"])[..., None]),
        Variant("blinn_phong", "pbr_D_BlinnPhong(NdotH, pbr_specPower_from_alpha(alpha))",
                "s = 2/alpha^2 - 2 (…_BLINN_PHONG)",
                self_reference=lambda d: brdf.D_BlinnPhong(
                    d["NdotH"], remap.specPower_from_alpha(d["alpha"]))[..., None]),
        Variant("blinn_phong_cod", "pbr_D_BlinnPhong(NdotH, pbr_specPower_from_gloss_CallOfDuty(g_cod))",
                "gloss remap Call of Duty s = 8192^g (r >= 0.125 reachable)",
                self_reference=lambda d: brdf.D_BlinnPhong(
                    d["NdotH"], remap.specPower_from_gloss_CallOfDuty(d["g_cod"]))[..., None]),
        Variant("blinn_phong_crytek",
                "pbr_D_BlinnPhong(NdotH, pbr_specPower_from_alpha(pbr_alpha_from_gloss_Crytek(g_crytek)))",
                "gloss remap Crytek alpha = (1 - 0.7 g)^2 (r >= 0.3 reachable)",
                self_reference=lambda d: brdf.D_BlinnPhong(d["NdotH"], remap.specPower_from_alpha(
                    remap.alpha_from_gloss_Crytek(d["g_crytek"])))[..., None]),
        Variant("blinn_phong_unreal",
                "pbr_D_BlinnPhong(NdotH, pbr_specPower_from_alpha(pbr_alpha_from_gloss_Unreal(g_unreal)))",
                "gloss remap Unreal alpha = (1 - g)^2",
                self_reference=lambda d: brdf.D_BlinnPhong(d["NdotH"], remap.specPower_from_alpha(
                    remap.alpha_from_gloss_Unreal(d["g_unreal"])))[..., None]),
    ))

# ---- geometry / visibility ---------------------------------------------------------------


def _LdotV(d):
    sl = np.sqrt(np.maximum(1.0 - d["NdotL"] ** 2, 0.0))
    sv = np.sqrt(np.maximum(1.0 - d["NdotV"] ** 2, 0.0))
    return sl * sv * np.cos(d["phi"]) + d["NdotL"] * d["NdotV"]


_LDOTV_GLSL = ("sqrt(max(1.0 - NdotL * NdotL, 0.0)) * sqrt(max(1.0 - NdotV * NdotV, 0.0)) * cos(phi)"
               " + NdotL * NdotV")
_GEOMETRY_DERIVED = (
    ("float", "alpha", "r * r", lambda d: d["r"] ** 2),
    ("float", "VdotH", f"0.5 * sqrt(max(2.0 + 2.0 * ({_LDOTV_GLSL}), 1e-12))",
     lambda d: 0.5 * np.sqrt(np.maximum(2.0 + 2.0 * _LdotV(d), 1e-12))),
    ("float", "NdotH", "min((NdotL + NdotV) / (2.0 * VdotH), 1.0)",
     lambda d: np.minimum((d["NdotL"] + d["NdotV"]) / (2.0 * d["VdotH"]), 1.0)),
)


def _v_ref(name, fn):
    return lambda d: fn(d)[..., None]


VISIBILITY = Family(
    name="visibility", title="Geometry / visibility V = G / (4 NdotL NdotV)",
    inputs=(("NdotL", 0.01, 1.0), ("NdotV", 0.01, 1.0), ("phi", 0.0, np.pi), ("r", 0.045, 1.0)),
    derived=_GEOMETRY_DERIVED,
    reference=lambda d: brdf.V_SmithGGXCorrelated(d["NdotL"], d["NdotV"], d["alpha"])[..., None],
    reference_name="height-correlated Smith GGX, float64 (reference.brdf.V_SmithGGXCorrelated, Heitz 2014 eq. 99)",
    exact="smith_ggx_correlated", rel_floor=1e-6,
    domain_note="NdotL, NdotV in [0.01, 1] x azimuth phi in [0, pi] (gives NdotH, VdotH) x r in [0.045, 1]",
    variants=(
        Variant("smith_ggx_correlated", "pbr_V_SmithGGXCorrelated(NdotL, NdotV, alpha)", "exact (HIGH tier)"),
        Variant("smith_ggx_correlated_fast", "pbr_V_SmithGGXCorrelatedFast(NdotL, NdotV, alpha)",
                "Hammon 2017 (MEDIUM, LOW tiers)",
                self_reference=_v_ref("fast", lambda d: brdf.V_SmithGGXCorrelatedFast(d["NdotL"], d["NdotV"], d["alpha"]))),
        Variant("smith_ggx", "pbr_V_SmithGGX(NdotL, NdotV, alpha)", "separable Smith",
                self_reference=_v_ref("sep", lambda d: brdf.V_SmithGGX(d["NdotL"], d["NdotV"], d["alpha"]))),
        Variant("schlick_ggx_alpha", "pbr_V_SchlickGGX(NdotL, NdotV, pbr_k_SchlickGGX_from_alpha(alpha))",
                "Schlick-GGX k = alpha/2 (Karis 2013)",
                self_reference=_v_ref("sk", lambda d: brdf.V_SchlickGGX(
                    d["NdotL"], d["NdotV"], brdf.k_SchlickGGX_from_alpha(d["alpha"])))),
        Variant("schlick_ggx_hotness", "pbr_V_SchlickGGX(NdotL, NdotV, pbr_k_SchlickGGX_hotness(r))",
                "Schlick-GGX k = (r/2 + 1/2)^2 / 2 (Karis 2013, analytic lights)",
                self_reference=_v_ref("skh", lambda d: brdf.V_SchlickGGX(
                    d["NdotL"], d["NdotV"], brdf.k_SchlickGGX_hotness(d["r"])))),
        Variant("cook_torrance", "pbr_V_CookTorrance(NdotL, NdotV, NdotH, VdotH)", "Cook & Torrance 1982",
                self_reference=_v_ref("ct", lambda d: brdf.V_CookTorrance(
                    d["NdotL"], d["NdotV"], d["NdotH"], d["VdotH"]))),
        Variant("kelemen", "pbr_V_Kelemen(VdotH)", "Kelemen 2001",
                self_reference=_v_ref("k", lambda d: brdf.V_Kelemen(d["VdotH"]))),
        Variant("implicit", "pbr_V_Implicit()", "Hoffman 2010 (V = 1/4)",
                self_reference=_v_ref("i", lambda d: np.full(np.shape(d["NdotL"]), 0.25))),
    ))

# ---- the whole BRDF per quality tier -------------------------------------------------------
# The shading frame turns with the inputs (issue 25): n = R·z, l = R·(sin θl, 0, NdotL), v =
# R·(sin θv cos phi, sin θv sin phi, NdotV), with R = Rz(gamma) Rx(beta) and beta, gamma
# functions of the hashed inputs, so every component of n, v and l varies per invocation
# and per evaluation. With the constant n = +z of the first bench, the compiler folded the
# products with n's zeros and ones (53.9 RDNA3 instructions reported where a shader with a
# varying normal pays 61). The frame's construction is in the baseline (derived values),
# so it costs nothing in the figures; the domain is unchanged (NdotL, NdotV, phi, r).
_FRAME_BETA, _FRAME_GAMMA = "1.3 * phi + 0.7 * r", "2.1 * NdotL + 0.5 * phi"


def _frame(d):
    """The columns R·x, R·y, R·z of the turning frame, float64 (last axis: components)."""
    beta = 1.3 * d["phi"] + 0.7 * d["r"]
    gamma = 2.1 * d["NdotL"] + 0.5 * d["phi"]
    sb, cb, sg, cg = np.sin(beta), np.cos(beta), np.sin(gamma), np.cos(gamma)
    return (np.stack([cg, sg, 0.0 * cg], -1), np.stack([-sg * cb, cg * cb, sb], -1),
            np.stack([sg * sb, -cg * sb, cb], -1))


def _local(d, x, y, z):
    tx, ty, tz = _frame(d)
    return x[..., None] * tx + y[..., None] * ty + z[..., None] * tz


def _sin(c):
    return np.sqrt(np.maximum(1.0 - c * c, 0.0))


_TIER_DERIVED = (
    ("float", "frame_beta", _FRAME_BETA, lambda d: 1.3 * d["phi"] + 0.7 * d["r"]),
    ("float", "frame_gamma", _FRAME_GAMMA, lambda d: 2.1 * d["NdotL"] + 0.5 * d["phi"]),
    ("vec3", "tx", "vec3(cos(frame_gamma), sin(frame_gamma), 0.0)", lambda d: _frame(d)[0]),
    ("vec3", "ty", "vec3(-sin(frame_gamma) * cos(frame_beta), cos(frame_gamma) * cos(frame_beta), "
                   "sin(frame_beta))", lambda d: _frame(d)[1]),
    ("vec3", "n", "vec3(sin(frame_gamma) * sin(frame_beta), -cos(frame_gamma) * sin(frame_beta), "
                  "cos(frame_beta))", lambda d: _frame(d)[2]),
    ("vec3", "l", "sqrt(max(1.0 - NdotL * NdotL, 0.0)) * tx + NdotL * n",
     lambda d: _local(d, _sin(d["NdotL"]), 0.0 * d["NdotL"], d["NdotL"])),
    ("vec3", "v", "sqrt(max(1.0 - NdotV * NdotV, 0.0)) * (cos(phi) * tx + sin(phi) * ty) + NdotV * n",
     lambda d: _local(d, _sin(d["NdotV"]) * np.cos(d["phi"]), _sin(d["NdotV"]) * np.sin(d["phi"]), d["NdotV"])),
)
_TIER_DIFFUSE, _TIER_F0 = (0.5, 0.4, 0.3), (0.04, 0.04, 0.04)
_TIER_EXPR = f"pbr_brdf_standard(n, v, l, vec3{_TIER_DIFFUSE}, vec3{_TIER_F0}, r)"


def _tier_ref(quality):
    return lambda d: shading.brdf_standard(d["n"], d["v"], d["l"], np.array(_TIER_DIFFUSE),
                                           np.array(_TIER_F0), d["r"], quality=quality)


BRDF_TIER = Family(
    name="brdf_tier", title="Whole BRDF (pbr_brdf_standard) per quality tier",
    inputs=(("NdotL", 0.01, 1.0), ("NdotV", 0.01, 1.0), ("phi", 0.0, np.pi), ("r", 0.0, 1.0)),
    derived=_TIER_DERIVED,
    reference=_tier_ref("HIGH"),
    reference_name="the HIGH-tier model in float64 (reference.shading.brdf_standard, quality=HIGH)",
    exact="high", rel_floor=1e-3,
    domain_note="a frame (n, tx, ty) that turns with the inputs (n varies per evaluation); l at NdotL "
                "in the (tx, n) plane, v at NdotV and azimuth phi from tx; r in [0, 1] "
                f"(clamped per tier); diffuse colour {_TIER_DIFFUSE}, F0 {_TIER_F0}; GGX D, Lambert",
    variants=tuple(
        Variant(q.lower(), _TIER_EXPR, f"PBR_QUALITY_{q}", defines={"PBR_QUALITY": f"PBR_QUALITY_{q}"},
                self_reference=None if q == "HIGH" else _tier_ref(q))
        for q in ("HIGH", "MEDIUM", "LOW")) + (
        Variant("filament", _TIER_EXPR.replace("pbr_brdf_standard", "peer_filament_brdf"),
                "peer: Filament's desktop standard lobe and clamps (bench/peers/filament_standard.glsl), "
                "for the cost comparison", peer="filament_standard.glsl"),),
)

# ---- tonemappers ----------------------------------------------------------------------------
TONEMAP = Family(
    name="tonemap", title="Tonemappers (pbr_tonemap under PBR_TONEMAP)",
    inputs=tuple((f"x{i}", 0.0, 16.0) for i in range(3)),
    reference=None,
    reference_name="no tonemapper is exact: each is compared with its own float64 twin "
                   "(reference.tonemap.tonemap); ratios are to the default, Khronos PBR Neutral",
    exact="khronos_neutral", rel_floor=1e-3, own_reference=True,
    domain_note="linear RGB, each channel in [0, 16] (64^3 grid)",
    variants=tuple(
        Variant(t.lower(), "pbr_tonemap(vec3(x0, x1, x2))", f"PBR_TONEMAP_{t}",
                defines={"PBR_TONEMAP": f"PBR_TONEMAP_{t}"},
                self_reference=(lambda t: lambda d: tonemap.tonemap(np.stack([d["x0"], d["x1"], d["x2"]], -1), t))(t))
        for t in ("KHRONOS_NEUTRAL", "NONE", "REINHARD", "HABLE", "ACES_FITTED", "ACES_NARKOWICZ")),
)

# ---- environment BRDF --------------------------------------------------------------------------
ENV_BRDF = Family(
    name="env_brdf", title="Environment BRDF (split-sum DFG: scale A, bias B)",
    inputs=(("NdotV", 1e-4, 1.0), ("r", 0.045, 1.0)),
    reference=None,  # set in measure.py: reference.directional_albedo (slow; per grid)
    reference_name="reference.directional_albedo: float64 quadrature of the integral (converged to 2e-8)",
    exact="dfg_lut", rel_floor=1e-3,
    domain_note="NdotV in [1e-4, 1] x perceptual roughness r in [0.045, 1]: what the renderer reads "
                "(PBR_MIN_NDOTV, PBR_MIN_PERCEPTUAL_ROUGHNESS)",
    grid_points=96,
    variants=(
        Variant("dfg_lut", "texture(pbrlab_tex, pbr_dfg_lut_uv(NdotV, r)).rg",
                "256x256 RG32F table on warped axes, bilinear at the texel centres (the renderer's "
                "PBR_DFG_LUT_LOOKUP); cost = the coordinate warp and the filtered fetch",
                kind="texture", texture="dfg"),
        Variant("analytic", "pbr_env_brdf(NdotV, r)",
                "Karis 2014 fit (EnvBRDFApprox), the table-free option: PBR_ENV_BRDF_ANALYTIC "
                "(also the fallback where no table hook is defined)",
                defines={"PBR_ENV_BRDF": "PBR_ENV_BRDF_ANALYTIC"}),
    ))

# ---- the layers of current engines' materials, beside the base lobe they add to ----------
_LAYER_DERIVED = _TIER_DERIVED + (
    ("float", "NdotH", "dot(n, normalize(l + v))",
     lambda d: np.sum(d["n"] * (d["l"] + d["v"]), -1) / np.linalg.norm(d["l"] + d["v"], axis=-1)),
    ("vec3", "t", "tx", lambda d: _frame(d)[0]),
    ("vec3", "b", "ty", lambda d: _frame(d)[1]),
)
_LAYER_F0 = (0.04, 0.04, 0.04)

LAYERS = Family(
    name="layers", title="Layer lobes (explicit F90, clear coat, sheen, anisotropy, iridescence) beside the base lobe",
    inputs=(("NdotL", 0.01, 1.0), ("NdotV", 0.01, 1.0), ("phi", 0.0, np.pi), ("r", 0.0, 1.0)),
    derived=_LAYER_DERIVED,
    reference=_tier_ref("HIGH"),
    reference_name="each lobe's own float64 twin (reference.clearcoat, .sheen, .anisotropy, .iridescence)",
    exact="base", rel_floor=1e-3, own_reference=True,
    domain_note="the brdf_tier geometry; each layer at roughness r: what one layer adds to the cost of "
                "a light's shading (time ratios against the base lobe, pbr_brdf_standard)",
    variants=(
        Variant("base", _TIER_EXPR, "pbr_brdf_standard (HIGH): what every layer adds to",
                self_reference=_tier_ref("HIGH")),
        Variant("specular_f90", f"pbr_brdf_standard_f90(n, v, l, vec3{_TIER_DIFFUSE}, vec3{_TIER_F0}, 0.5, r)",
                "the base lobe with KHR_materials_specular's explicit F90 (0.5 here) in place of F90 from F0",
                self_reference=lambda d: shading.brdf_standard(
                    d["n"], d["v"], d["l"], np.array(_TIER_DIFFUSE), np.array(_TIER_F0), d["r"], quality="HIGH",
                    f90=np.full(np.shape(d["r"]), 0.5))),
        Variant("clearcoat", "pbr_clearcoat_punctual(n, v, l, vec3(1.0), r)",
                "KHR_materials_clearcoat's lobe (pbr/shading/clearcoat.glsl)",
                self_reference=lambda d: clearcoat.clearcoat_punctual(d["n"], d["v"], d["l"], np.ones(3), d["r"])),
        Variant("sheen", "pbr_sheen_lobe(NdotL, NdotV, NdotH, vec3(1.0), r)",
                "Charlie D x Estevez-Kulla V (pbr/shading/sheen.glsl)",
                self_reference=lambda d: sheen.sheen_lobe(d["NdotL"], d["NdotV"], d["NdotH"], np.ones(3), d["r"])),
        Variant("anisotropic", f"pbr_brdf_anisotropic_specular(n, v, l, t, b, vec3{_LAYER_F0}, r, 0.8)",
                "anisotropic GGX x Smith, strength 0.8 (pbr/shading/anisotropy.glsl)",
                self_reference=lambda d: anisotropy.brdf_anisotropic_specular(
                    d["n"], d["v"], d["l"], d["t"], d["b"], np.array(_LAYER_F0), d["r"], 0.8)),
        Variant("anisotropic_f90", f"pbr_brdf_anisotropic_specular_f90(n, v, l, t, b, vec3{_LAYER_F0}, 0.5, r, 0.8)",
                "the anisotropic lobe with KHR_materials_specular's explicit F90 (0.5 here)",
                self_reference=lambda d: anisotropy.brdf_anisotropic_specular(
                    d["n"], d["v"], d["l"], d["t"], d["b"], np.array(_LAYER_F0), d["r"], 0.8,
                    f90=np.full(np.shape(d["r"]), 0.5))),
        Variant("iridescence", f"pbr_F_Iridescence(1.0, 1.3, NdotV, 200.0 + 800.0 * r, vec3{_LAYER_F0})",
                "thin-film Fresnel, 200-1000 nm (pbr/brdf/f_iridescence.glsl)",
                self_reference=lambda d: iridescence.F_Iridescence(1.0, 1.3, d["NdotV"], 200.0 + 800.0 * d["r"],
                                                                  np.array(_LAYER_F0))),
        Variant("iridescence_f90", f"pbr_iridescent_f0_f90(0.5 * vec3{_LAYER_F0}, 0.5, NdotV, "
                "pbr_Iridescence(1.0, 1.3, 200.0 + 800.0 * r))",
                "the film folded into F0 with KHR_materials_specular's explicit F90 (0.5 here: the film over "
                "F0 / F90, scaled by F90; pbr/surface/lighting_iridescence.glsl)",
                self_reference=lambda d: specular_extension.iridescent_f0_f90(
                    0.5 * np.broadcast_to(np.array(_LAYER_F0), np.shape(d["r"]) + (3,)), np.full(np.shape(d["r"]), 0.5),
                    d["NdotV"], 1.0, 1.3, 200.0 + 800.0 * d["r"])),
    ))

FAMILIES = (SRGB_DECODE, SRGB_ENCODE, FRESNEL, DISTRIBUTION, VISIBILITY, BRDF_TIER, TONEMAP, ENV_BRDF, LAYERS)
BY_NAME = {f.name: f for f in FAMILIES}
