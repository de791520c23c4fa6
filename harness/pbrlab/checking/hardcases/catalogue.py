"""The hard-case catalogue: every public function of the library (pbr_shade_punctual and
pbr_brdf_standard at each quality tier and variant), its argument kinds, the physical bound of
its value, and its hard cases, each with a sentence saying why it is hard.

Cases come from two places: every argument's kind contributes its catalogued edge values
(domains.KINDS, the other arguments at their typical value), and ``EXTRA_CASES`` adds the
cases that need several arguments at once (V = -L, a light at the shaded point, ...) and the
values the library decides where the maths has none, which are checked exactly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...maths.reference import anisotropy, color, shading
from . import domains


@dataclass(frozen=True)
class Bound:
    """lo <= value <= hi for every component, and finite (NaN and Inf always fail)."""
    text: str
    lo: float = -math.inf
    hi: float = math.inf

    def holds(self, values: np.ndarray) -> np.ndarray:
        """Per sample (first axis): all components finite and within [lo, hi]. NaN fails
        because every comparison with NaN is False; nothing here uses min/max."""
        v = np.asarray(values, np.float64).reshape(len(values), -1)
        return (np.isfinite(v) & (v >= self.lo) & (v <= self.hi)).all(axis=1)


def _ge0(what): return Bound(f"{what} >= 0", 0.0)
def _unit(what): return Bound(f"0 <= {what} <= 1", 0.0, 1.0)


D = _ge0("D")
G = _unit("G")
V = _ge0("V")
F = _unit("F")
BRDF = _ge0("BRDF")
COLOUR = _ge0("colour")
ENCODED = Bound("0 <= sRGB <= 1", 0.0, 1.0)
TONEMAPPED = Bound("0 <= tonemapped <= 1", 0.0, 1.0)
# |n x h|² <= |n|²|h|² = 1 for unit vectors; float32 unit vectors are unit within a few ulps
ONE_MINUS_DOT2 = Bound("0 <= 1 - (n.h)^2 <= 1 (+4 ulp)", 0.0, 1.0 + 4 * 2.0 ** -23)
# |l + v|² + 2^-126 of unit l, v: never 0 (its job), at most 4 within a few ulps
LENGTH2_NONZERO = Bound("2^-126 <= |l + v|^2 + 2^-126 <= 4 (+8 ulp)", 2.0 ** -126, 4.0 * (1.0 + 8 * 2.0 ** -23))
# |v| of a normalised float32 vector: 1 within a few ulps (or exactly 0, see pbr_safe_normalize)
UNIT_OR_ZERO = Bound("each |component| <= 1 (+4 ulp)", -1.0 - 4 * 2.0 ** -23, 1.0 + 4 * 2.0 ** -23)


@dataclass(frozen=True)
class Arg:
    name: str
    kind: str          # a domains.KINDS key, or "dir" (a direction for the shading model)
    vec3: bool = False


@dataclass(frozen=True)
class Function:
    name: str                   # the GLSL function
    expression: str             # the call, in the argument names
    args: tuple[Arg, ...]
    bound: Bound
    variant: str = ""           # e.g. "quality=LOW" for the shading model
    defines: tuple = ()         # ((macro, value), ...)

    @property
    def label(self) -> str:
        return f"{self.name} [{self.variant}]" if self.variant else self.name


@dataclass(frozen=True)
class SameAs:
    """The decided value is, bit for bit, the value of another case of the same function."""
    case_name: str


@dataclass(frozen=True)
class Near:
    """The value follows the maths: within ``rel`` (relative, per component) of the float64
    reference's ``value`` for the same float32 inputs (a check the bound alone cannot make:
    a lobe dropped to 0 is still >= 0)."""
    value: tuple
    rel: float
    source: str


@dataclass(frozen=True)
class Case:
    function: Function
    name: str
    why: str
    inputs: dict = field(hash=False)
    exact: object = None        # None, a float, a GLSL expression in the same inputs, or SameAs
    expression: str = ""        # overrides the function's call (e.g. to normalise an input)
    near: object = None         # Near: where the maths has a value, the float64 reference's

    @property
    def call(self) -> str:
        return self.expression or self.function.expression


def _a(spec: str) -> tuple[Arg, ...]:
    """'NdotH:cosine alpha:alpha f0:unit3' -> args (a kind ending in 3 is a vec3)."""
    out = []
    for item in spec.split():
        name, kind = item.split(":")
        out.append(Arg(name, kind.rstrip("3"), kind.endswith("3")))
    return tuple(out)


def _f(name, args, bound, call=None):
    arg_list = _a(args)
    return Function(name, call or f"{name}({', '.join(a.name for a in arg_list)})", arg_list, bound)


# The D · V arguments from directions, as pbr_brdf_standard makes them (h = l + v unnormalised,
# |h|² + 2^-126, n·h = saturate(n·l) + n·v and |n × h|² as the rejection's squared length, the
# cosines and roughness clamped): the preconditions of the fused quotients. Where
# pbr_brdf_standard does not select the lobe (n·(l + v) < 2^-50: h below the surface, l = -v),
# h = n stands in. lambdaSum is the exact lambdas' smallest sum, NdotV alpha (NdotL -> 0).
def dv_arguments(parts: str, low: bool = False) -> str:
    """The call's arguments, in order, from ``parts`` (space-separated names of
    ``_DV_PARTS``), for the HIGH/MEDIUM guards or (``low``) the LOW tier's."""
    floor = "PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP" if low else "PBR_TIER_MIN_PERCEPTUAL_ROUGHNESS"
    # pbr_brdf_standard's selection (issue 25): the lobe where n·(l + v), with n·l saturated,
    # reaches PBR_MIN_NDOT_HALF_SUM
    n_dot_sum = "(clamp(dot(n, l), 0.0, 1.0) + dot(n, v))"
    selected = f"({n_dot_sum} >= PBR_MIN_NDOT_HALF_SUM)"
    h = f"({selected} ? l + v : n)"
    n_dot_h = f"({selected} ? {n_dot_sum} : 1.0)"
    rejection = f"({h} - {n_dot_h} * n)"
    alpha = f"pbr_alpha_from_perceptual_roughness(clamp(roughness, {floor}, 1.0))"
    values = {"nDotH": n_dot_h, "nCrossH2": f"dot({rejection}, {rejection})",
              "h2": f"pbr_length2_nonzero({h})", "NdotL": "clamp(dot(n, l), 0.0, 1.0)",
              "NdotV": "clamp(dot(n, v), PBR_MIN_NDOTV, 1.0)", "VdotH": "0.5 * length(l + v)",
              "alpha": alpha, "lambdaSum": f"clamp(dot(n, v), PBR_MIN_NDOTV, 1.0) * {alpha}"}
    return ", ".join(values[name] for name in parts.split())


DV_ARGUMENTS = dv_arguments("nDotH nCrossH2 h2 NdotL NdotV alpha")
# called with n, v, l of light through the surface (domains.transmission_geometry)
TRANSMISSION_FUNCTIONS = ("pbr_BTDF_Walter_GGX_cosine", "pbr_BTDF_Walter_GGX", "pbr_transmission_punctual",
                          "pbr_transmission_thin_punctual", "pbr_mirror_through_surface", "pbr_refraction_direction")
DV_FUNCTIONS = ("pbr_DV_GGX_SmithCorrelated", "pbr_DV_GGX_fromLambdaSum", "pbr_DV_GGX_SmithCorrelatedFast",
                "pbr_DV_GGX_SmithCorrelatedFast_half", "pbr_DV_GGX_SmithBound", "pbr_specular_DV")

# Every public function of glsl/pbr/ (tests/checking/hardcases/test_catalogue.py checks the list is
# complete), with its argument kinds and bound.
TERMS: tuple[Function, ...] = (
    # common/
    _f("pbr_saturate", "x:signed", _unit("saturate")),
    _f("pbr_sq", "x:signed", _ge0("x²")),
    _f("pbr_pow5", "x:unit", _unit("x^5")),
    _f("pbr_max3", "c:unit3", _unit("max3")),
    _f("pbr_min3", "c:unit3", _unit("min3")),
    _f("pbr_pow_safe", "x:unit s:specPower", _unit("x^s")),
    _f("pbr_sanitize", "c:hdr3", _unit("sanitised"), "pbr_sanitize(c, 1.0)"),
    _f("pbr_safe_normalize", "d:coordinate3", UNIT_OR_ZERO),
    _f("pbr_one_minus_dot2", "n:dir h:dir", ONE_MINUS_DOT2),
    _f("pbr_length2_nonzero", "l:dir v:dir", LENGTH2_NONZERO, call="pbr_length2_nonzero(l + v)"),
    # color/
    _f("pbr_srgb_to_linear", "c:hdr3", ENCODED),
    _f("pbr_linear_to_srgb", "c:hdr3", ENCODED),
    _f("pbr_degamma", "c:hdr3", ENCODED), _f("pbr_regamma", "c:hdr3", ENCODED),
    _f("pbr_degamma_fast", "c:hdr3", ENCODED), _f("pbr_regamma_fast", "c:hdr3", ENCODED),
    _f("pbr_luminance", "c:radiance3", _ge0("luminance")),
    # material/
    _f("pbr_perceptual_roughness_from_smoothness", "s:unit", _unit("perceptualRoughness")),
    _f("pbr_alpha_from_perceptual_roughness", "r:unit", _unit("alpha")),
    _f("pbr_perceptual_roughness_from_alpha", "a:alpha", Bound("0 <= perceptualRoughness <= sqrt(huge)", 0.0)),
    _f("pbr_alpha_from_smoothness", "s:unit", _unit("alpha")),
    _f("pbr_specPower_from_gloss_CallOfDuty", "g:unit", Bound("1 <= s <= 8192", 1.0, 8192.0)),
    _f("pbr_alpha_from_gloss_Crytek", "g:unit", _unit("alpha")),
    _f("pbr_alpha_from_gloss_Unreal", "g:unit", _unit("alpha")),
    _f("pbr_specPower_from_alpha", "a:alpha", _ge0("specPower")),
    _f("pbr_alpha_from_specPower", "s:specPower", Bound("0 < alpha <= 1", 0.0, 1.0)),
    _f("pbr_f0_from_metallic", "albedo:unit3 m:unit", F),
    _f("pbr_diffuse_from_metallic", "albedo:unit3 m:unit", _unit("diffuse")),
    _f("pbr_f0_from_metallic_dielectric", "albedo:unit3 m:unit d:unit3", F),
    _f("pbr_diffuse_from_metallic_dielectric", "albedo:unit3 m:unit d:unit3", _unit("diffuse")),
    _f("pbr_f90_from_metallic", "f90:unit m:unit", _unit("F90")),
    _f("pbr_diffuse_from_specular", "albedo:unit3 s:unit3", _unit("diffuse")),
    _f("pbr_diffuse_from_specular_per_channel", "albedo:unit3 s:unit3", _unit("diffuse")),
    _f("pbr_f0_from_ior", "eta:eta", F),
    _f("pbr_ior_from_f0", "f0:unit", Bound("1 <= eta <= PBR_MAX_IOR", 1.0, 2.0 ** 25)),
    # brdf/
    _f("pbr_Fd_Lambert", "", Bound("Fd = 1/π", 1 / math.pi - 1e-7, 1 / math.pi + 1e-7), "pbr_Fd_Lambert()"),
    _f("pbr_Fd_Burley", "NdotV:cosine NdotL:cosine LdotH:cosine r:roughness",
       Bound("0.25/π <= Fd <= 6.25/π", 0.25 / math.pi * (1 - 1e-6), 6.25 / math.pi * (1 + 1e-6))),
    _f("pbr_BRDF_BlinnPhongClassic", "NdotH:cosine NdotL:cosine s:specPower", BRDF),
    _f("pbr_BRDF_BlinnPhongModified", "NdotH:cosine s:specPower", BRDF),
    _f("pbr_BRDF_BlinnPhongNormalized", "NdotH:cosine s:specPower", BRDF),
    _f("pbr_blinn_phong_lobe", "NdotH:cosine s:specPower", _unit("NdotH^s")),
    _f("pbr_D_BlinnPhong", "NdotH:cosine s:specPower", D),
    _f("pbr_D_GGX", "NdotH:cosine alpha:alpha", D),
    Function("pbr_D_GGX", "pbr_D_GGX(n, h, alpha)", _a("n:dir h:dir alpha:alpha"), D, "vec3"),
    _f("pbr_D_GGX_fromOneMinusNdotH2", "NdotH:cosine s2:unit alpha:alpha", D),
    _f("pbr_D_Beckmann", "NdotH:cosine alpha:alpha", D),
    _f("pbr_D_Beckmann_fromOneMinusNdotH2", "NdotH:cosine s2:unit alpha:alpha", D),
    _f("pbr_G_CookTorrance", "NdotL:cosine NdotV:cosine NdotH:cosine VdotH:cosine", G),
    _f("pbr_V_CookTorrance", "NdotL:cosine NdotV:cosine NdotH:cosine VdotH:cosine", V),
    _f("pbr_SmithGGX_denominator", "NdotX:unit alpha:unit", _ge0("denominator")),
    _f("pbr_G1_SmithGGX", "NdotX:cosine alpha:alpha", G),
    _f("pbr_G_SmithGGX", "NdotL:cosine NdotV:cosine alpha:alpha", G),
    _f("pbr_V_SmithGGX", "NdotL:cosine NdotV:cosine alpha:alpha", V),
    _f("pbr_G1_SchlickGGX", "NdotX:cosine k:k", G),
    _f("pbr_G_SchlickGGX", "NdotL:cosine NdotV:cosine k:k", G),
    _f("pbr_V_SchlickGGX", "NdotL:cosine NdotV:cosine k:k", V),
    _f("pbr_k_SchlickGGX_from_alpha", "a:unit", _unit("k")),
    _f("pbr_k_SchlickGGX_hotness", "r:unit", _unit("k")),
    _f("pbr_V_SmithGGXCorrelated", "NdotL:cosine NdotV:cosine alpha:alpha", V),
    _f("pbr_V_SmithGGXCorrelatedFast", "NdotL:cosine NdotV:cosine alpha:alpha", V),
    _f("pbr_G_Implicit", "NdotL:cosine NdotV:cosine", G),
    _f("pbr_V_Implicit", "", Bound("V = 1/4", 0.25, 0.25), "pbr_V_Implicit()"),
    _f("pbr_G_Kelemen", "NdotL:cosine NdotV:cosine VdotH:cosine", G),
    _f("pbr_V_Kelemen", "VdotH:cosine", V),
    _f("pbr_V_SmithGGXBound", "NdotL:cosine NdotV:cosine", V),
    _f("pbr_F_Schlick", "f0:unit VdotH:cosine", F),
    Function("pbr_F_Schlick", "pbr_F_Schlick(f0, VdotH)", _a("f0:unit3 VdotH:cosine"), F, "vec3"),
    Function("pbr_F_Schlick", "pbr_F_Schlick(f0, f90, VdotH)", _a("f0:unit3 f90:unit VdotH:cosine"), F, "F90"),
    _f("pbr_F_SchlickSG", "f0:unit3 VdotH:cosine", F),
    Function("pbr_F_SchlickSG", "pbr_F_SchlickSG(f0, f90, VdotH)", _a("f0:unit3 f90:unit VdotH:cosine"), F, "F90"),
    _f("pbr_f90_from_f0", "f0:unit3", _unit("F90")),
    # the clear coat (pbr/shading/clearcoat.glsl): its lobe through pbr_shade_punctual, its
    # albedo and the base's weight from the environment BRDF at the coat's (NdotV, roughness)
    _f("pbr_clearcoat_punctual", "n:dir v:dir l:dir radiance:radiance3 r:roughness", COLOUR),
    _f("pbr_clearcoat_albedo", "NdotV:cosine r:roughness", _unit("E_coat"),
       "pbr_clearcoat_albedo(pbr_env_brdf(max(NdotV, PBR_MIN_NDOTV), pbr_clamp_perceptual_roughness(r)))"),
    _f("pbr_clearcoat_base_weight", "mask:unit NdotV:cosine r:roughness", _unit("base weight"),
       "pbr_clearcoat_base_weight(mask, max(NdotV, PBR_MIN_NDOTV), "
       "pbr_env_brdf(max(NdotV, PBR_MIN_NDOTV), pbr_clamp_perceptual_roughness(r)))"),
    # the fused HIGH-tier lobe, called as pbr_brdf_standard calls it (its preconditions)
    Function("pbr_DV_GGX_SmithCorrelated", "pbr_DV_GGX_SmithCorrelated(" + DV_ARGUMENTS + ")",
             _a("n:dir v:dir l:dir roughness:roughness"), _ge0("D·V")),
    Function("pbr_DV_GGX_fromLambdaSum",
             "pbr_DV_GGX_fromLambdaSum(" + dv_arguments("nDotH nCrossH2 h2 alpha lambdaSum") + ")",
             _a("n:dir v:dir l:dir roughness:roughness"), _ge0("D·V")),
    Function("pbr_DV_GGX_SmithCorrelatedFast", "pbr_DV_GGX_SmithCorrelatedFast(" + DV_ARGUMENTS + ")",
             _a("n:dir v:dir l:dir roughness:roughness"), _ge0("D·V")),
    # LOW's lobe, under pbr_brdf_standard's selection (n·(l + v) >= PBR_MIN_NDOT_HALF_SUM: it
    # divides by n·(l + v)), at LOW's roughness floor
    Function("pbr_DV_GGX_SmithBound", "pbr_DV_GGX_SmithBound(" + dv_arguments("nDotH nCrossH2 h2 NdotL NdotV alpha", low=True) + ")",
             _a("n:dir v:dir l:dir roughness:roughness"), _ge0("D·V")),
    # LOW's lobe in half's range, at LOW's roughness floor and threshold (float32 here)
    Function("pbr_DV_GGX_SmithCorrelatedFast_half", "pbr_DV_GGX_SmithCorrelatedFast_half(" + dv_arguments("nDotH nCrossH2 h2 NdotL NdotV alpha", low=True) + ")",
             _a("n:dir v:dir l:dir roughness:roughness"), _ge0("D·V")),
    # anisotropy (brdf/d_ggx_anisotropic.glsl, brdf/v_smith_ggx_correlated_anisotropic.glsl,
    # shading/anisotropy.glsl). The sweep draws only n and h as unit directions, so the lobe and
    # the bent normal take a fixed frame (n = z, t = x, b = y) and their other vectors as
    # coordinates normalised by the library's guard; the direction stands t, b in with n, h.
    _f("pbr_D_GGX_Anisotropic", "NdotH:cosine TdotH:cosine BdotH:cosine alphaT:alpha alphaB:alpha", D),
    _f("pbr_V_SmithGGXCorrelated_Anisotropic", "NdotL:cosine NdotV:cosine TdotV:cosine BdotV:cosine "
       "TdotL:cosine BdotL:cosine alphaT:alpha alphaB:alpha", V),
    _f("pbr_anisotropic_alphas", "alpha:alpha strength:signed", _unit("alphaT, alphaB"),
       "vec3(pbr_anisotropic_alphas(alpha, strength), 0.0)"),
    _f("pbr_anisotropy_direction", "n:dir h:dir d:coordinate3 rotation:signed", UNIT_OR_ZERO,
       "pbr_anisotropy_direction(n, h, d.xy, rotation)"),
    _f("pbr_brdf_anisotropic_specular", "v:coordinate3 l:coordinate3 f0:unit3 roughness:roughness strength:signed",
       BRDF, "pbr_brdf_anisotropic_specular(vec3(0.0, 0.0, 1.0), pbr_safe_normalize(v), pbr_safe_normalize(l), "
       "vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), f0, roughness, strength)"),
    # the explicit F90 (KHR_materials_specular) on the anisotropic lobe, under its precondition f90 >= max(f0)
    _f("pbr_brdf_anisotropic_specular_f90",
       "v:coordinate3 l:coordinate3 f0:unit3 f90:unit roughness:roughness strength:signed", BRDF,
       "pbr_brdf_anisotropic_specular_f90(vec3(0.0, 0.0, 1.0), pbr_safe_normalize(v), pbr_safe_normalize(l), "
       "vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), f0, max(f90, pbr_max3(f0)), roughness, strength)"),
    _f("pbr_anisotropic_bent_normal", "v:coordinate3 d:coordinate3 strength:signed roughness:roughness", UNIT_OR_ZERO,
       "pbr_anisotropic_bent_normal(vec3(0.0, 0.0, 1.0), pbr_safe_normalize(v), pbr_safe_normalize(d), strength, "
       "roughness)"),
    # shading/valid_reflection_normal.glsl: the geometric normal fixed (+z), n and v any coordinates
    # normalised by the library's guard (v below the plane and n = 0 included)
    _f("pbr_valid_reflection_normal", "n:coordinate3 v:coordinate3", UNIT_OR_ZERO,
       "pbr_valid_reflection_normal(pbr_safe_normalize(n), vec3(0.0, 0.0, 1.0), pbr_safe_normalize(v))"),
    # brdf/d_charlie.glsl, brdf/v_charlie.glsl, shading/sheen.glsl (KHR_materials_sheen)
    _f("pbr_D_Charlie", "NdotH:cosine alpha:alpha", D),
    _f("pbr_disc_light_alpha", "alpha:alpha angularRadius:angle", _unit("widened alpha")),
    _f("pbr_sheen_lambda_exponent", "x:cosine alpha:alpha", Bound("|L| <= 30", -30.0, 30.0)),
    _f("pbr_sheen_lambda", "cosTheta:cosine alpha:alpha", Bound("0 <= Λ <= 2.2e4", 0.0, 2.2e4)),
    # V's largest values at the cosine floor 1e-4 (float32 1e-4 is 1e-4 (1 - 2.5e-9)): Neubelt 1/(8e-4),
    # Charlie 1/((1 + 2 Λ(1e-4)) 4e-8) = 1536 at alpha = 1 (the smallest Λ(1e-4), 8138)
    _f("pbr_V_Charlie", "NdotL:cosine NdotV:cosine alpha:alpha", Bound("0 <= V <= 1.6e3", 0.0, 1.6e3)),
    _f("pbr_V_Neubelt", "NdotL:cosine NdotV:cosine", Bound("0 <= V <= 1250 (+1e-4)", 0.0, 1250.0 * (1 + 1e-4))),
    _f("pbr_sheen_alpha", "r:roughness", Bound("0.0049 <= alpha <= 1", 0.0049 * (1 - 1e-6), 1.0)),
    _f("pbr_sheen_lobe", "NdotL:cosine NdotV:cosine NdotH:cosine sheenColor:unit3 r:roughness", BRDF),
    _f("pbr_sheen_lut_uv", "NdotV:cosine r:roughness", _unit("uv")),
    _f("pbr_sheen_albedo_approx", "NdotV:cosine r:roughness", Bound("0 <= E <= 3.2", 0.0, 3.2)),
    _f("pbr_sheen_albedo", "NdotV:cosine r:roughness", Bound("0 <= E <= 3.2", 0.0, 3.2)),
    _f("pbr_sheen_albedo_scaling", "sheenColor:unit3 E:unit", _unit("albedo scaling")),
    _f("pbr_sheen_albedo_scaling_punctual", "sheenColor:unit3 NdotV:cosine NdotL:cosine r:roughness",
       _unit("albedo scaling")),
    # surface/lighting_sheen.glsl (the default PBR_SHEEN_ENERGY_NORMALIZED): E up to 3.2 (the fit)
    _f("pbr_sheen_energy_scale", "E:unit", Bound("0 < scale <= 1", 0.0, 1.0)),
    _f("pbr_sheen_effective_albedo", "E:unit", _unit("E'")),
    # shading/energy_conservation.glsl
    _f("pbr_diffuse_albedo_from_diffuse_color", "diffuseColor:unit3 f0:unit3", _unit("diffuse albedo")),
    _f("pbr_coupled_diffuse_color", "diffuseColor:unit3 f0:unit3 specularAlbedo:unit3", _unit("coupled diffuse")),
    _f("pbr_F_Dielectric", "c:cosine eta:eta", F),
    _f("pbr_F_Iridescence", "n1:eta n2:eta c:cosine d:thickness f0:unit3", F),
    # light through a surface (brdf/btdf_walter.glsl, shading/transmission.glsl)
    _f("pbr_T_Dielectric", "c:cosine eta:eta", _unit("T")),
    _f("pbr_BTDF_Walter_GGX_cosine", "n:dir v:dir l:dir alpha:alpha eta:eta", _ge0("ft |n.l|")),
    _f("pbr_transmission_punctual", "n:dir v:dir l:dir radiance:radiance3 base:unit3 r:roughness eta:eta", COLOUR),
    _f("pbr_transmission_thin_punctual", "n:dir v:dir l:dir radiance:radiance3 base:unit3 r:roughness", COLOUR),
    _f("pbr_BTDF_Walter_GGX", "n:dir v:dir l:dir alpha:alpha eta:eta", _ge0("ft")),
    _f("pbr_mirror_through_surface", "n:dir l:dir", Bound("finite", -np.inf, np.inf)),
    _f("pbr_refraction_direction", "n:dir v:dir eta:eta", Bound("finite", -np.inf, np.inf)),
    _f("pbr_volume_attenuation", "d:distance c:unit3 D:distance", _unit("T")),
    _f("pbr_beer_lambert", "c:unit x:distance", _unit("T")),
    # S of the film's optical path: |S| <= (row sums of the XYZ -> Rec. 709 matrix 5.28) · 1.0011
    _f("pbr_iridescence_sensitivity", "opd:thickness shift:phase3", Bound("|S| <= 5.3", -5.3, 5.3)),
    _f("pbr_iridescence_mix", "F:unit3 Fi:unit3 t:unit", F),
    # the film split into its base-independent terms (pbr_thin_film) and each base's (issue 35):
    # S_xyz's terms at zero shift are at most their value at OPD 0, 1.0011 (x: both lobes)
    _f("pbr_iridescence_sensitivity_xyz", "opd:thickness", Bound("|S_xyz| <= 1.0012", -1.0012, 1.0012)),
    # rows of |M| sum to at most 5.2761: |rgb| <= 5.2761 for |xyz| <= 1, plus three roundings
    _f("pbr_iridescence_xyz_to_rec709", "xyz:unit3", Bound("|rgb| <= 5.2762", -5.2762, 5.2762)),
    # S2, the struct's one vector that is not a copy of an input: |S| <= 5.3 as S's
    _f("pbr_thin_film", "n1:eta n2:eta c:cosine d:thickness", Bound("|S2| <= 5.3", -5.3, 5.3),
       "pbr_thin_film(n1, n2, c, d).S2"),
    # one channel's Airy sum with S1, S2 in [0, 1]: 0 <= R12 + Rs <= 1 (Rs <= T121), |C_m| <= 1
    # (|Rs - T121| <= T121, r123 <= 1), so -4 <= I <= 5 (plus a few roundings: 1e-5)
    _f("pbr_iridescence_airy_channel", "n1:eta n2:eta c:cosine d:thickness eta3:eta s1:unit s2:unit",
       Bound("-4 <= I <= 5 (+1e-5)", -4.00001, 5.00001), "pbr_iridescence_airy_channel(pbr_thin_film(n1, n2, c, d), "
       "eta3, s1, s2)"),
    # the unsaturated sum with the film's own S (|S| <= 5.3): -21.2 <= I <= 22.2 (+1e-4)
    _f("pbr_iridescence_airy", "n1:eta n2:eta c:cosine d:thickness f0:unit3",
       Bound("-21.2 <= I <= 22.2 (+1e-4)", -21.2001, 22.2001), "pbr_iridescence_airy(pbr_thin_film(n1, n2, c, d), f0)"),
    _f("pbr_iridescence_select", "n1:eta n2:eta c:cosine d:thickness f0:unit3 I:signed3", F,
       "pbr_iridescence_select(pbr_thin_film(n1, n2, c, d), f0, I)"),
    _f("pbr_F_Iridescence_thin_film", "n1:eta n2:eta c:cosine d:thickness f0:unit3", F,
       "pbr_F_Iridescence_thin_film(pbr_thin_film(n1, n2, c, d), f0)"),
    # the film with an explicit F90 (surface/lighting_iridescence.glsl), under f90 >= max(f0):
    # 0 <= F0' <= F90 <= 1
    _f("pbr_iridescent_f0_f90", "f0:unit3 f90:unit c:cosine t:unit n2:eta d:thickness", _unit("F0'"),
       "pbr_iridescent_f0_f90(min(f0, vec3(f90)), f90, c, pbr_Iridescence(t, n2, d))"),
    # both films at once (surface/lighting_iridescence.glsl): the base's F0' and the coat's, each
    # a pbr_iridescent_f0[_f90]: 0 <= F0' <= F90 <= 1
    _f("pbr_iridescent_f0_with_coat", "f0:unit3 cf0:unit3 c:cosine t:unit n2:eta d:thickness", _unit("F0'"),
       "pbr_iridescent_f0_with_coat(f0, cf0, c, pbr_Iridescence(t, n2, d)).f0"),
    _f("pbr_iridescent_f0_f90_with_coat", "f0:unit3 f90:unit cf0:unit3 cf90:unit c:cosine t:unit n2:eta d:thickness",
       _unit("F0'"), "pbr_iridescent_f0_f90_with_coat(min(f0, vec3(f90)), f90, min(cf0, vec3(cf90)), cf90, c, "
       "pbr_Iridescence(t, n2, d)).coatF0"),
    _f("pbr_iridescence_thickness", "lo:thickness hi:thickness g:unit",
       Bound("|thickness| <= 1e30 (+1 %)", -1.01e30, 1.01e30)),
    # tonemap/
    _f("pbr_apply_exposure", "c:radiance3 ev:ev", COLOUR),
    _f("pbr_tonemap_reinhard", "c:hdr3", TONEMAPPED),
    _f("pbr_tonemap_reinhard_extended", "c:hdr3 w:whitePoint", TONEMAPPED),
    _f("pbr_hable_curve", "x:unit", Bound("Hable f(x) on [0, 1] >= -1 ulp", -1e-7)),
    _f("pbr_tonemap_hable", "c:hdr3", TONEMAPPED),
    _f("pbr_aces_rrt_odt_fit", "v:unit3", Bound("RRT+ODT fit on [0, 1] in [-4e-4, 1]", -4e-4, 1.0)),
    _f("pbr_tonemap_aces_fitted", "c:hdr3", TONEMAPPED),
    _f("pbr_tonemap_aces_narkowicz", "c:hdr3", TONEMAPPED),
    _f("pbr_tonemap_khronos_neutral", "c:hdr3", TONEMAPPED),
)

# Dispatchers and tier helpers, per variant (the selector macro and its values).
_DISPATCH_TEMPLATES = (
    (_f("pbr_specular_D", "NdotH:cosine s2:unit alpha:alpha", D), "PBR_SPECULAR_D", shading.SPECULAR_D),
    (_f("pbr_specular_V", "NdotL:cosine NdotV:cosine NdotH:cosine VdotH:cosine alpha:alpha", V),
     "PBR_SPECULAR_V", shading.SPECULAR_V),
    (Function("pbr_specular_DV", "pbr_specular_DV(" + dv_arguments("nDotH nCrossH2 h2 NdotL NdotV VdotH alpha")
              + ")", _a("n:dir v:dir l:dir roughness:roughness"), _ge0("D·V")), "PBR_SPECULAR_V", shading.SPECULAR_V),
    (_f("pbr_specular_F", "f0:unit3 VdotH:cosine", F), "PBR_SPECULAR_F", shading.SPECULAR_F),
    (_f("pbr_specular_F_deviation_bound", "f0:unit3", _unit("F deviation")), "PBR_SPECULAR_F", shading.SPECULAR_F),
    # the explicit F90 (KHR_materials_specular), called under its precondition f90 >= max(f0)
    (_f("pbr_specular_F_f90", "f0:unit3 f90:unit VdotH:cosine", F,
        "pbr_specular_F_f90(f0, max(f90, pbr_max3(f0)), VdotH)"), "PBR_SPECULAR_F", shading.SPECULAR_F),
    (_f("pbr_specular_F_deviation_bound_f90", "f0:unit3 f90:unit", _unit("F deviation"),
        "pbr_specular_F_deviation_bound_f90(f0, max(f90, pbr_max3(f0)))"), "PBR_SPECULAR_F", shading.SPECULAR_F),
    (_f("pbr_diffuse_Fd", "NdotV:cosine NdotL:cosine LdotH:cosine r:roughness", Bound("0 <= Fd <= 6.25/π", 0.0, 2.0)),
     "PBR_DIFFUSE", shading.DIFFUSE),
    (_f("pbr_sheen_V", "NdotL:cosine NdotV:cosine alpha:alpha", Bound("0 <= V <= 1.6e3", 0.0, 1.6e3)),
     "PBR_SHEEN_V", ("CHARLIE", "NEUBELT")),
    (_f("pbr_specular_lobe_limit", "DV:radiance", _ge0("D·V")), "PBR_QUALITY", shading.QUALITY),
    (_f("pbr_clamp_perceptual_roughness", "r:roughness", _unit("perceptualRoughness")), "PBR_QUALITY", shading.QUALITY),
    (_f("pbr_decode_color_texel", "c:unit3", _unit("linear")), "PBR_COLOR_TRANSFER", color.TRANSFERS),
    (_f("pbr_encode_final_color", "c:hdr3", ENCODED), "PBR_COLOR_TRANSFER", color.TRANSFERS),
    (_f("pbr_tonemap", "c:hdr3", TONEMAPPED), "PBR_TONEMAP", ("NONE", "REINHARD", "HABLE", "ACES_FITTED",
                                                               "ACES_NARKOWICZ", "KHRONOS_NEUTRAL")),
)

SHADE_ARGS = _a("n:dir v:dir l:dir radiance:radiance3 diffuseColor:unit3 f0:unit3 roughness:roughness")
_SHADING_TEMPLATES = (
    Function("pbr_brdf_standard", "pbr_brdf_standard(n, v, l, diffuseColor, f0, roughness)",
             tuple(a for a in SHADE_ARGS if a.name != "radiance"), BRDF),
    Function("pbr_shade_punctual", "pbr_shade_punctual(n, v, l, radiance, diffuseColor, f0, roughness)",
             SHADE_ARGS, COLOUR),
    # the explicit F90 (KHR_materials_specular), under its precondition f90 >= max(f0)
    Function("pbr_brdf_standard_f90",
             "pbr_brdf_standard_f90(n, v, l, diffuseColor, f0, max(f90, pbr_max3(f0)), roughness)",
             tuple(a for a in SHADE_ARGS if a.name != "radiance") + _a("f90:unit"), BRDF),
    Function("pbr_shade_punctual_f90",
             "pbr_shade_punctual_f90(n, v, l, radiance, diffuseColor, f0, max(f90, pbr_max3(f0)), roughness)",
             SHADE_ARGS + _a("f90:unit"), COLOUR),
)


# The unity BRDF model's lobes (pbr/unity/brdf_unity.glsl: Unity's BRDF1/2/3 with flat
# parameters, and the tier dispatcher). The normal is normalised in the call, as
# LightingStandard does (Unity: s.Normal = normalize(s.Normal)) before every Unity BRDF.
# Bound: colour >= -1e-20, not 0: Unity's FresnelLerp extrapolates by (1 - cos)^5 when a
# float32 cosine exceeds 1 by an ulp, (-1.2e-7)^5 = -2e-35 of the light, formula for formula.
UNITY_COLOUR = Bound("colour >= -1e-20 (Unity's FresnelLerp at a cosine of 1 + ulp)", -1e-20)
UNITY_SHADE_ARGS = _a("n:dir v:dir l:dir radiance:radiance3 diffuseColor:unit3 f0:unit3 omr:unit smoothness:unit "
                      "idiff:radiance3 ispec:radiance3")
UNITY_SHADE_CALL = "({}(diffuseColor, f0, omr, smoothness, normalize(n), v, radiance, l, idiff, ispec))"
UNITY_INCLUDE = "pbr/unity/brdf_unity.glsl"


def unity_functions() -> list[Function]:
    out = [Function(name, UNITY_SHADE_CALL.format(name), UNITY_SHADE_ARGS, UNITY_COLOUR)
           for name in ("pbr_unity_brdf1", "pbr_unity_brdf2", "pbr_unity_brdf3")]
    out += [Function("pbr_unity_brdf_pbs", UNITY_SHADE_CALL.format("pbr_unity_brdf_pbs"), UNITY_SHADE_ARGS,
                     UNITY_COLOUR, f"quality={q}", (("PBR_QUALITY", f"PBR_QUALITY_{q}"),))
            for q in shading.QUALITY]
    out += [_f("pbr_unity_NHxRoughness", "x:unit r:unit", Bound("0 <= specular <= LUT_RANGE 16", 0.0, 16.0)),
            # Unity's terms take the cosines BRDF1 passes them: saturated (nv: |n.v|, within an
            # ulp of [0, 1] for unit vectors)
            _f("GGXTerm", "NdotH:cosine r:unit", D, "GGXTerm(pbr_saturate(NdotH), r)"),
            _f("SmithJointGGXVisibilityTerm", "NdotL:cosine NdotV:cosine r:unit", V,
               "SmithJointGGXVisibilityTerm(pbr_saturate(NdotL), pbr_saturate(NdotV), r)"),
            _f("DisneyDiffuse", "NdotV:cosine NdotL:cosine LdotH:cosine r:unit",
               Bound("0 <= DisneyDiffuse <= 6.25", 0.0, 6.25 * (1 + 1e-6)),
               "DisneyDiffuse(pbr_saturate(NdotV), pbr_saturate(NdotL), pbr_saturate(LdotH), r)"),
            _f("PerceptualRoughnessToSpecPower", "r:unit", Bound("1e-4 <= n <= 2e4", 1e-4 * (1 - 1e-6), 2e4))]
    return out


def shading_variants() -> list[tuple[str, dict]]:
    """Each quality tier, and each non-default selector value at the HIGH tier."""
    out = [(f"quality={q}", shading.glsl_defines(quality=q)) for q in shading.QUALITY]
    for selector, values in (("specular_d", shading.SPECULAR_D), ("specular_v", shading.SPECULAR_V),
                             ("specular_f", shading.SPECULAR_F), ("diffuse", shading.DIFFUSE)):
        out += [(f"{selector}={v}", shading.glsl_defines(**{selector: v})) for v in values[1:]]
    return out


def functions() -> list[Function]:
    """The catalogue's functions: terms, each dispatcher per variant, the shading model per
    tier and variant."""
    out = list(TERMS)
    for template, macro, values in _DISPATCH_TEMPLATES:
        out += [Function(template.name, template.expression, template.args, template.bound, f"{macro}={v}",
                         ((macro, f"{macro}_{v}"),)) for v in values]
    for template in _SHADING_TEMPLATES:
        out += [Function(template.name, template.expression, template.args, template.bound, label,
                         tuple(sorted(defines.items()))) for label, defines in shading_variants()]
    return out + unity_functions()


# ---- cases ---------------------------------------------------------------------------

UP = (0.0, 0.0, 1.0)
_S = math.sqrt(0.5)
TYPICAL_GEOMETRY = {"n": UP, "v": (0.6, 0.0, 0.8), "l": (-0.28, 0.0, 0.96)}


def typical_inputs(function: Function) -> dict:
    out = {}
    for a in function.args:
        if a.kind == "dir":
            out[a.name] = TYPICAL_GEOMETRY.get(a.name, UP if a.name == "n" else (_S, 0.0, _S))
        else:
            t = domains.KINDS[a.kind].typical
            out[a.name] = (t, t, t) if a.vec3 else t
    return out


def _edge_cases(function: Function) -> list[Case]:
    cases = []
    for a in function.args:
        if a.kind == "dir":
            continue
        for edge in domains.KINDS[a.kind].edges:
            inputs = typical_inputs(function)
            inputs[a.name] = (edge.value,) * 3 if a.vec3 else edge.value
            cases.append(Case(function, f"{a.name} = {edge.name}", edge.why, inputs))
    return cases


# The shading model's geometric hard cases: (name, why, n, v, l, exact value or None).
# "exact" GLSL expressions restate the library's decided value with the same operations.
_DIFFUSE_FD = ("pbr_diffuse_Fd(clamp(dot(n, v), PBR_MIN_NDOTV, 1.0), dot(n, l), "
               "0.0, pbr_clamp_perceptual_roughness(roughness))")
_DIFFUSE_ONLY = f"diffuseColor * {_DIFFUSE_FD}"
# pbr_shade_punctual's light term is π BRDF times NdotL, the 1/π and the light unit's π cancelled
# in the source (pbr/lighting/punctual.glsl): the decided diffuse-only value in that order
_DIFFUSE_ONLY_LIT = (f"radiance * (diffuseColor * (PBR_PI * {_DIFFUSE_FD})) * clamp(dot(n, l), 0.0, 1.0)")
_GEOMETRY_CASES = (
    ("V = -L", "l and v opposite: no half vector exists (l + v = 0); decided: no specular, diffuse kept",
     UP, (-0.6, 0.0, -0.8), (0.6, 0.0, 0.8), "diffuse"),
    ("V ≈ -L", "|l + v|² = 4e-10, n·(l + v) = 2e-5: D · V from l + v of length 2e-5 (a direction above "
     "the surface, so a lobe), VdotH = 1e-5", UP, (-0.6, 0.0, -0.8 + 2e-5), (0.6, 0.0, 0.8), None),
    ("NdotL = 0", "light exactly at the horizon: the BRDF at NdotL = 0, no light", UP, (0.6, 0.0, 0.8),
     (1.0, 0.0, 0.0), "unlit"),
    ("NdotL < 0", "light behind the surface: the BRDF at NdotL = 0 (saturated), no light", UP,
     (0.6, 0.0, 0.8), (0.6, 0.0, -0.8), "unlit"),
    ("V = -L, light behind", "l = -v with the view above the horizon: l + v = 0 exactly while n·l is taken "
     "as 0, so n·(l + v) = n·v selects the lobe; |l + v|² + 2^-126 (pbr_length2_nonzero) keeps 1/|l + v|² "
     "finite (without it: 0 · Inf, NaN); no light", UP, (0.6, 0.0, 0.8), (-0.6, 0.0, -0.8), "unlit"),
    ("light at the shaded point", "l = pbr_safe_normalize(0) = 0 (a point light touching the surface): "
     "no direction, NdotL = 0: no light", UP, (0.6, 0.0, 0.8), (0.0, 0.0, 0.0), "unlit"),
    ("zero view vector", "v = pbr_safe_normalize(0) (camera at the point): NdotV clamps, finite",
     UP, (0.0, 0.0, 0.0), (0.6, 0.0, 0.8), None),
    ("NdotV = 0", "grazing view: V divides by NdotV", UP, (1.0, 0.0, 0.0), (0.6, 0.0, 0.8), None),
    ("NdotV < 0", "back-facing view from a normal map", UP, (0.8, 0.0, -0.6), (0.6, 0.0, 0.8), None),
    ("mirror, NdotH = 1", "the peak of the sharpest lobe: 1 - NdotH² = 0 exactly", UP,
     (-0.6, 0.0, 0.8), (0.6, 0.0, 0.8), None),
    ("mirror at grazing", "peak of the lobe with NdotL = NdotV = 1e-3: D and V both near their maxima",
     UP, (-0.9999995, 0.0, 1e-3), (0.9999995, 0.0, 1e-3), None),
    ("mirror at grazing, 1e-3, lobe kept", "NdotL = NdotV = 1e-3 at the peak: |l + v|² = 4e-6 is short but h = n "
     "is defined and the lobe is thousands of 1/sr; a threshold on |l + v|² (2^-14, the former LOW tier's) "
     "dropped it (issue 25); checked against the tier's float64 model", UP,
     (-0.9999995, 0.0, 1e-3), (0.9999995, 0.0, 1e-3), "follows"),
    ("mirror at grazing, 1e-6, lobe kept", "NdotL = NdotV = 1e-6 at the peak: |l + v|² = 4e-12, below the former "
     "1e-10 threshold of the HIGH tier, which dropped the lobe; checked against the tier's float64 model", UP,
     (-1.0, 0.0, 1e-6), (1.0, 0.0, 1e-6), "follows"),
    ("l = v", "retro-reflection: h = v, VdotH = 1 exactly", UP, (0.6, 0.0, 0.8), (0.6, 0.0, 0.8), None),
    ("|n| = 1.01", "unnormalised interpolated normal: NdotL, NdotV, NdotH above 1 near the peak",
     (0.0, 0.0, 1.01), (0.0, 0.0, 1.0), (0.0, 0.0, 1.0), None),
    ("|n| = 1 + ulp", "interpolated normal one ulp long: dot products exceed 1 by one rounding",
     (0.0, 0.0, domains.ULP_ABOVE_ONE), (-0.6, 0.0, 0.8), (0.6, 0.0, 0.8), None),
    ("far camera", "v = pbr_safe_normalize(1e30 · direction): dot(v, v) would overflow in normalize(); "
     "the shading model takes a unit v (its contract: an unnormalised v above 1e19 overflows |l + v|²)",
     UP, (-6e29, 0.0, 8e29), (0.6, 0.0, 0.8), "safe_normalize_v"),
)
_MATERIAL_CASES = (
    ("roughness = 0 (smoothness 1)", {"roughness": 0.0}, "roughness_floor"),
    ("roughness < 0", {"roughness": -0.5}, "roughness_floor"),
    ("roughness = 1", {"roughness": 1.0}, None),
    ("metal F0 = 1", {"f0": (1.0, 1.0, 1.0), "diffuseColor": (0.0, 0.0, 0.0)}, None),
    ("F0 = 0", {"f0": (0.0, 0.0, 0.0)}, None),
    ("albedo 0", {"diffuseColor": (0.0, 0.0, 0.0)}, None),
    ("albedo 1", {"diffuseColor": (1.0, 1.0, 1.0)}, None),
)
_MATERIAL_WHY = {
    "roughness = 0 (smoothness 1)": "a perfect mirror: D is a Dirac; decided: the tier's minimum roughness, exactly",
    "roughness < 0": "an out-of-range texture value; decided: the tier's minimum roughness, exactly",
    "roughness = 1": "the roughest lobe",
    "metal F0 = 1": "a perfect metal: F = 1 at every angle, the largest specular",
    "F0 = 0": "no specular at normal incidence: F is all Fresnel rise",
    "albedo 0": "black diffuse: exact zeros",
    "albedo 1": "white diffuse: the energy limit",
}


# Relative tolerance of a shading value against its tier's float64 model at a case: float32
# conditioning of the lobe near the mirror (the HIGH tier's measured worst over the bench
# domain is 6.0e-4, docs/bench), with a margin of 1.7x.
FOLLOWS_REL = 1e-3


def _follows(function: Function, inputs: dict) -> Near:
    """The tier's float64 model (reference.shading) at the case's float32 inputs."""
    variants = {k: v for k, v in (item.split("=") for item in function.variant.split(",") if item)}
    quality = variants.get("quality", "HIGH")
    d = {k: np.asarray(np.float32(inputs[k]), np.float64) for k in ("n", "v", "l", "diffuseColor", "f0")}
    roughness = float(np.float32(inputs["roughness"]))
    # the _f90 forms' explicit F90, as their expression passes it (at least max(f0))
    f90 = None if "f90" not in inputs else max(float(np.float32(inputs["f90"])), float(d["f0"].max()))
    if "radiance" in function.expression:
        value = shading.shade_punctual(d["n"], d["v"], d["l"], np.asarray(np.float32(inputs["radiance"]), np.float64),
                                       d["diffuseColor"],
                                       d["f0"], roughness, quality=quality, diffuse=variants.get("diffuse", "LAMBERT"),
                                       f90=f90)
    else:
        value = shading.brdf_standard(d["n"], d["v"], d["l"], d["diffuseColor"], d["f0"], roughness,
                                      quality=quality, diffuse=variants.get("diffuse", "LAMBERT"), f90=f90)
    return Near(tuple(float(x) for x in np.ravel(value)), FOLLOWS_REL,
                f"reference.shading ({function.variant or 'quality=HIGH'}) within {FOLLOWS_REL:g} relative")


def _follows_anisotropic(inputs: dict) -> Near:
    """pbr_brdf_anisotropic_specular[_f90]'s float64 model (reference.anisotropy, HIGH) at the
    case's float32 inputs, in the catalogue's frame (n = z, t = x, b = y); an explicit F90 as
    the _f90 entry's expression passes it (at least max(f0))."""
    d = {k: np.asarray(np.float32(inputs[k]), np.float64) for k in ("v", "l", "f0")}
    unit = {k: d[k] / np.linalg.norm(d[k]) for k in ("v", "l")}
    f90 = None if "f90" not in inputs else max(float(np.float32(inputs["f90"])), float(d["f0"].max()))
    value = anisotropy.brdf_anisotropic_specular(UP, unit["v"], unit["l"], (1.0, 0.0, 0.0), (0.0, 1.0, 0.0),
                                                 d["f0"], float(np.float32(inputs["roughness"])),
                                                 float(np.float32(inputs["strength"])), f90=f90)
    return Near(tuple(float(x) for x in np.ravel(value)), FOLLOWS_REL,
                f"reference.anisotropy (quality=HIGH) within {FOLLOWS_REL:g} relative")


def _shading_cases(function: Function) -> list[Case]:
    cases = []
    base = typical_inputs(function)
    base.update(n=UP, v=(-0.6, 0.0, 0.8), l=(0.6, 0.0, 0.8), roughness=0.0)
    # The decided values live in pbr_brdf_standard before any variant's term is called:
    # checked exactly at each tier and diffuse variant, by bound for the other selectors.
    exact_here = function.variant.startswith(("quality=", "diffuse="))
    for name, why, n, v, l, exact in _GEOMETRY_CASES:
        if exact == "unlit":  # pbr_shade_punctual: exactly no light; the BRDF: its float64 model
            exact = 0.0 if "radiance" in function.expression else "follows"
        if exact in ("diffuse", "follows") and not exact_here:
            exact = None
        inputs = dict(base, n=n, v=v, l=l, roughness=0.3)
        expression, near = "", None
        if exact == "follows":
            exact, near = None, (_follows(function, inputs) if exact_here else None)
        elif exact == "diffuse":
            exact = _DIFFUSE_ONLY_LIT if "radiance" in function.expression else _DIFFUSE_ONLY
        elif exact == "safe_normalize_v":  # the far camera normalised by the library's guard
            exact, expression = None, function.expression.replace("(n, v,", "(n, pbr_safe_normalize(v),")
        cases.append(Case(function, name, why, inputs, exact, expression, near))
    quality = dict(function.defines).get("PBR_QUALITY", "PBR_QUALITY_HIGH").removeprefix("PBR_QUALITY_")
    floor = float(np.float32(shading.QUALITY_MIN_PERCEPTUAL_ROUGHNESS[quality]))
    cases.append(Case(function, "roughness = tier minimum", "the guard itself: the smallest roughness the "
                      "tier uses, reference for the clamped cases", dict(base, roughness=floor)))
    for name, change, exact in _MATERIAL_CASES:
        if exact == "roughness_floor":
            exact = SameAs("roughness = tier minimum")
        cases.append(Case(function, name, _MATERIAL_WHY[name], dict(base, **change), exact))
    return cases


# Values the library decides where the maths has none, per function (checked exactly).
DECIDED = {
    "pbr_D_GGX": [("alpha = 0 at the peak", "D_GGX(1, 0) is 0/0 (a Dirac); decided: D at PBR_MIN_ALPHA",
                   {"NdotH": 1.0, "alpha": 0.0}, "pbr_D_GGX(1.0, PBR_MIN_ALPHA)")],
    "pbr_D_GGX_Anisotropic": [
        ("alphas = 0 at the peak", "a Dirac (1/(π αt αb) = 1/0); decided: D at PBR_MIN_ALPHA",
         {"NdotH": 1.0, "TdotH": 0.0, "BdotH": 0.0, "alphaT": 0.0, "alphaB": 0.0},
         "pbr_D_GGX_Anisotropic(1.0, 0.0, 0.0, PBR_MIN_ALPHA, PBR_MIN_ALPHA)"),
        ("anisotropy 1 at the peak", "alphaT = 1, alphaB at the floor: the narrowest line lobe, 1/(π·1e-7)",
         {"NdotH": 1.0, "TdotH": 0.0, "BdotH": 0.0, "alphaT": 1.0, "alphaB": 0.0},
         "pbr_D_GGX_Anisotropic(1.0, 0.0, 0.0, 1.0, PBR_MIN_ALPHA)"),
        ("h = 0", "no half vector (all cosines 0): |f|² = 0 is floored at (αt αb)², the peak's value",
         {"NdotH": 0.0, "TdotH": 0.0, "BdotH": 0.0, "alphaT": 0.25, "alphaB": 0.25},
         "pbr_D_GGX_Anisotropic(1.0, 0.0, 0.0, 0.25, 0.25)"),
        ("grazing h along b", "h at the horizon across the narrow direction: D ~ αb² / (π αt αb³), tiny",
         {"NdotH": 0.0, "TdotH": 0.0, "BdotH": 1.0, "alphaT": 1.0, "alphaB": 1e-7}, None)],
    "pbr_V_SmithGGXCorrelated_Anisotropic": [
        ("both grazing, alphas 0", "0.5 / (0 + 0) at the horizon with no roughness; guarded: cosines at "
         "PBR_MIN_NDOTV, alphas at PBR_MIN_ALPHA",
         {"NdotL": 0.0, "NdotV": 0.0, "TdotV": 1.0, "BdotV": 0.0, "TdotL": 0.0, "BdotL": 1.0,
          "alphaT": 0.0, "alphaB": 0.0},
         "pbr_V_SmithGGXCorrelated_Anisotropic(PBR_MIN_NDOTV, PBR_MIN_NDOTV, 1.0, 0.0, 0.0, 1.0, "
         "PBR_MIN_ALPHA, PBR_MIN_ALPHA)"),
        ("grazing along the rough tangent", "alphaT = 1 (anisotropy 1), both directions at the horizon "
         "along t: Λ is largest", {"NdotL": 1e-7, "NdotV": 1e-7, "TdotV": 1.0, "BdotV": 0.0, "TdotL": -1.0,
                                   "BdotL": 0.0, "alphaT": 1.0, "alphaB": 0.002025}, None)],
    "pbr_anisotropic_alphas": [
        ("strength 1", "fully anisotropic: alphaT = 1 exactly", {"alpha": 0.25, "strength": 1.0},
         "vec3(1.0, 0.25, 0.0)"),
        ("strength -1", "KHR strength is in [0, 1]; decided: the sign is ignored (s²)", {"alpha": 0.25, "strength": -1.0},
         "vec3(1.0, 0.25, 0.0)"),
        ("strength 0", "isotropic: both alphas are the material's, exactly", {"alpha": 0.25, "strength": 0.0},
         "vec3(0.25, 0.25, 0.0)")],
    "pbr_anisotropy_direction": [
        ("zero sample", "texel (0.5, 0.5) decodes to no direction (normalize(0) is NaN); decided: the "
         "untextured default (1, 0)", {"d": (0.0, 0.0, 0.0), "rotation": 0.0},
         "pbr_anisotropy_direction(n, h, vec2(1.0, 0.0), 0.0)")],
    "pbr_brdf_anisotropic_specular": [
        ("V = -L", "l and v opposite: no half vector (l + v = 0); decided 0, as pbr_brdf_standard",
         {"v": (-0.6, 0.0, -0.8), "l": (0.6, 0.0, 0.8)}, 0.0),
        ("NdotL < 0", "light behind the surface: decided 0", {"v": (0.6, 0.0, 0.8), "l": (0.6, 0.0, -0.8)}, 0.0),
        ("light at the shaded point", "l = pbr_safe_normalize(0) = 0: no direction, decided 0",
         {"v": (0.6, 0.0, 0.8), "l": (0.0, 0.0, 0.0)}, 0.0),
        ("mirror along b, strength 1, roughness 0", "the peak of the narrowest line lobe (alphaB at the tier "
         "floor, alphaT = 1): D·V largest", {"v": (0.0, -0.6, 0.8), "l": (0.0, 0.6, 0.8), "roughness": 0.0,
                                             "strength": 1.0}, None),
        ("grazing mirror, strength 1", "NdotL = NdotV = 1e-3 at the peak: D and V both near their maxima",
         {"v": (-0.9999995, 0.0, 1e-3), "l": (0.9999995, 0.0, 1e-3), "roughness": 0.0, "strength": 1.0}, None),
        ("grazing mirror, 1e-6, lobe kept", "NdotL = NdotV = 1e-6 at the peak: |l + v|² = 4e-12, below the former "
         "1e-10 threshold on |l + v|², which dropped the lobe (issue 25); h = n is defined: checked against "
         "reference.anisotropy", {"v": (-1.0, 0.0, 1e-6), "l": (1.0, 0.0, 1e-6), "roughness": 0.3, "strength": 0.5},
         "follows"),
        ("strength -1", "outside KHR's [0, 1]: acts as 1 (only s² enters)",
         {"v": (-0.6, 0.0, 0.8), "l": (0.6, 0.0, 0.8), "strength": -1.0},
         "pbr_brdf_anisotropic_specular(vec3(0.0, 0.0, 1.0), pbr_safe_normalize(v), pbr_safe_normalize(l), "
         "vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), f0, roughness, 1.0)")],
    "pbr_brdf_anisotropic_specular_f90": [
        ("F90 0, F0 0", "KHR_materials_specular at specularFactor 0: no reflection at any angle, exactly 0",
         {"v": (-0.9999995, 0.0, 1e-3), "l": (0.9999995, 0.0, 1e-3), "f0": (0.0, 0.0, 0.0), "f90": 0.0}, 0.0),
        ("mirror along b, strength 1, roughness 0, F90 0.5", "the narrowest line lobe's peak under a halved "
         "grazing reflectance: checked against reference.anisotropy with the F90",
         {"v": (0.0, -0.6, 0.8), "l": (0.0, 0.6, 0.8), "roughness": 0.0, "strength": 1.0, "f90": 0.5}, "follows"),
        ("grazing mirror, strength 1, F90 0.5", "NdotL = NdotV = 1e-3 at the peak, where Schlick's weight is "
         "largest: the F90 carries the lobe", {"v": (-0.9999995, 0.0, 1e-3), "l": (0.9999995, 0.0, 1e-3),
                                                "roughness": 0.0, "strength": 1.0, "f90": 0.5}, "follows"),
        ("grazing mirror, 1e-6, lobe kept, F90 0.3", "NdotL = NdotV = 1e-6 at the peak (the lobe kept, issue 25) "
         "with an explicit F90", {"v": (-1.0, 0.0, 1e-6), "l": (1.0, 0.0, 1e-6), "roughness": 0.3, "strength": 0.5,
                                  "f90": 0.3}, "follows"),
        ("F90 from F0", "the plain lobe is this form at F90 = pbr_f90_from_f0(f0) (1 for F0 0.1), bit for bit",
         {"v": (-0.6, 0.0, 0.8), "l": (0.6, 0.0, 0.8), "f0": (0.1, 0.1, 0.1), "f90": 1.0},
         "pbr_brdf_anisotropic_specular(vec3(0.0, 0.0, 1.0), pbr_safe_normalize(v), pbr_safe_normalize(l), "
         "vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), f0, roughness, strength)")],
    "pbr_iridescent_f0_with_coat": [
        ("the plain film", "one pbr_thin_film for two F0s: the base's F0' is pbr_iridescent_f0 of it, bit for bit",
         {"c": 0.3, "d": 700.0, "t": 1.0}, "pbr_iridescent_f0(f0, c, pbr_Iridescence(t, n2, d))"),
        ("thickness 0", "no film for either base: the film's select at d = 0 with the shared terms",
         {"d": 0.0, "t": 1.0}, "pbr_iridescent_f0(f0, c, pbr_Iridescence(t, n2, d))")],
    "pbr_iridescent_f0_f90_with_coat": [
        ("the coat's film", "the coat's F0' is pbr_iridescent_f0_f90 of the coat's F0 and F90, bit for bit",
         {"c": 0.2, "d": 300.0, "cf90": 0.5, "t": 1.0},
         "pbr_iridescent_f0_f90(min(cf0, vec3(cf90)), cf90, c, pbr_Iridescence(t, n2, d))"),
        ("coat F90 0", "specularFactor 0 on the coat: F0 0 and the film's fold 0; decided 0",
         {"cf0": (0.3, 0.3, 0.3), "cf90": 0.0}, "vec3(0.0)")],
    "pbr_F_Iridescence_thin_film": [
        ("thickness 0", "the split's select: no film, the base's Schlick Fresnel (as pbr_F_Iridescence)", {"d": 0.0},
         "pbr_F_Schlick(f0, c)"),
        ("TIR in the film", "film IOR below the outside IOR past the critical angle: F = 1 from the shared cos²θ2",
         {"n1": 1.5, "n2": 1.0, "c": 0.2}, 1.0)],
    "pbr_iridescent_f0_f90": [
        ("F90 0", "specularFactor 0 (then F0 0): no reflection, the film's included; decided 0 (F0 / max(F90, "
         "FLT_MIN) = 0)", {"f0": (0.3, 0.3, 0.3), "f90": 0.0}, "vec3(0.0)"),
        ("F90 1", "the plain film exactly (F0 / 1, 1 x F0')", {"f90": 1.0},
         "pbr_iridescent_f0(f0, c, pbr_Iridescence(t, n2, d))"),
        ("thickness 0, grazing", "no film at the grazing end of the inversion: F90 x F0 / F90 up to one rounding",
         {"d": 0.0, "c": 1e-4, "f90": 0.5, "f0": (0.02, 0.02, 0.02)}, None)],
    "pbr_anisotropic_bent_normal": [
        ("v along d, strength 1, roughness 0", "cross(d, v) = 0 and bend⁴ = 0: the mixed vector vanishes; "
         "decided n", {"v": (0.0, 1.0, 0.0), "d": (0.0, 1.0, 0.0), "strength": 1.0, "roughness": 0.0},
         "vec3(0.0, 0.0, 1.0)"),
        ("strength 0", "no anisotropy: bend = 1, the normal itself", {"v": (0.6, 0.0, 0.8), "d": (0.0, 1.0, 0.0),
                                                                      "strength": 0.0, "roughness": 0.3},
         "vec3(0.0, 0.0, 1.0)")],
    "pbr_valid_reflection_normal": [
        ("n = Ng", "no normal map: the reflection is the view's mirror about Ng, v.Ng above the threshold; "
         "decided n itself", {"n": (0.0, 0.0, 1.0), "v": (0.6, 0.0, 0.8)}, "vec3(0.0, 0.0, 1.0)"),
        ("view on the plane, n tilted away", "v.Ng = 0: threshold 0, c = 0 and a = vx^2; the reflection "
         "brought to the plane: n' = Ng exactly (w = (b + root) / 4a = 1, u = 0)",
         {"n": (-0.6, 0.0, 0.8), "v": (1.0, 0.0, 0.0)}, "vec3(0.0, 0.0, 1.0)")],
    "pbr_disc_light_alpha": [("radius 0", "a point source: sqrt(alpha²) is alpha exactly for float32 alpha in "
                              "[2^-63, 1], so the lobe is the light's own", {"alpha": 0.25, "angularRadius": 0.0}, 0.25)],
    "pbr_D_Beckmann": [("NdotH = 0", "0/0 (exp(-inf) / 0); decided: 0, the limit", {"NdotH": 0.0, "alpha": 0.5}, 0.0)],
    "pbr_G1_SmithGGX": [("NdotX = 0, alpha = 0", "2·0/(0 + 0); decided 0: no light along the horizon",
                         {"NdotX": 0.0, "alpha": 0.0}, 0.0)],
    "pbr_G1_SchlickGGX": [("NdotX = 0, k = 0", "0/0; decided 0", {"NdotX": 0.0, "k": 0.0}, 0.0)],
    "pbr_F_Dielectric": [("eta = 1 at grazing", "0/0: F = 0 for eta = 1, F -> 1 at grazing for eta != 1; "
                          "decided 0 (no interface)", {"c": 0.0, "eta": 1.0}, 0.0)],
    "pbr_F_Iridescence": [("thickness 0", "a film of no thickness is no film; decided: the base Schlick Fresnel "
                           "(Khronos Sample Renderer: iridescence off at d = 0)", {"d": 0.0},
                           "pbr_F_Schlick(f0, c)"),
                          ("TIR in the film", "film IOR below the outside IOR past the critical angle: "
                           "the spec's F = 1", {"n1": 1.5, "n2": 1.0, "c": 0.2}, 1.0),
                          ("film IOR = outside IOR", "no film interface: R12 is Schlick's (1 - c)^5 only, "
                           "R123 reaches the floor 0", {"n1": 1.0, "n2": 1.0, "c": 1.0}, None),
                          ("base IOR = film IOR", "phase φ23 flips by π where Schlick's R23 is not 0: the "
                           "method's discontinuity", {"n2": 1.5, "f0": (0.04, 0.04, 0.04), "c": 0.2}, None)],
    "pbr_ior_from_f0": [("F0 = 1", "a perfect mirror: eta = 2/0; decided PBR_MAX_IOR", {"f0": 1.0}, "PBR_MAX_IOR")],
    "pbr_specPower_from_alpha": [("alpha = 0", "s = 2/0; decided: s at PBR_MIN_ALPHA (2e14)", {"a": 0.0},
                                  "pbr_specPower_from_alpha(PBR_MIN_ALPHA)")],
    "pbr_D_BlinnPhong": [("NdotH = 0, s = 0", "pow(0, 0) is undefined in GLSL; decided 0^0 = 1 (uniform lobe 1/π)",
                          {"NdotH": 0.0, "s": 0.0}, "PBR_INV_PI")],
    "pbr_D_Charlie": [("alpha = 0", "sin^(1/alpha) with 1/alpha = Inf; decided: D at PBR_SHEEN_MIN_ALPHA",
                       {"NdotH": 0.3, "alpha": 0.0}, "pbr_D_Charlie(NdotH, PBR_SHEEN_MIN_ALPHA)"),
                      ("NdotH = 1", "sin θh = 0 raised to 1/(2 alpha): the limit 0", {"NdotH": 1.0}, 0.0)],
    "pbr_sheen_lobe": [("NdotL = 0", "light at the horizon: decided 0 (no cosine-weighted light)",
                        {"NdotL": 0.0}, 0.0),
                       ("roughness = 0", "KHR's default sheenRoughness 0: decided the 0.07 floor's value",
                        {"r": 0.0}, "pbr_sheen_lobe(NdotL, NdotV, NdotH, sheenColor, PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS)")],
    "pbr_sheen_albedo_scaling": [("E = 2.94, white", "the spec's E exceeds 1 at grazing for smooth sheens: "
                                  "1 - E < 0, decided 0", {"sheenColor": (1.0, 1.0, 1.0), "E": 2.94}, 0.0)],
    "pbr_pow_safe": [("0^0", "undefined in GLSL; decided 1", {"x": 0.0, "s": 0.0}, 1.0),
                     ("0^s", "pow(0, s) = exp2(s · log2 0); decided 0, the limit", {"x": 0.0, "s": 2.0}, 0.0)],
    "pbr_length2_nonzero": [("l = -v", "l + v = 0 exactly: |l + v|² = 0, whose reciprocal pbr_brdf_standard "
                             "takes; decided 2^-126", {"l": (0.6, 0.0, 0.8), "v": (-0.6, 0.0, -0.8)},
                             "PBR_FLT_MIN")],
    "pbr_safe_normalize": [("zero vector", "no direction; decided the zero vector", {"d": (0.0, 0.0, 0.0)}, 0.0),
                           ("denormal vector", "GPUs may flush denormals, so its direction is not portable; "
                            "decided the zero vector on every GPU", {"d": (domains.DENORMAL, 0.0, 0.0)}, 0.0),
                           ("tiny vector", "dot(d, d) = 1e-60 underflows to 0 in normalize()",
                            {"d": (1e-30, 0.0, 0.0)}, "vec3(1.0, 0.0, 0.0)"),
                           ("huge vector", "dot(d, d) overflows to Inf in normalize(): a camera 1e30 away",
                            {"d": (0.0, 1e30, 0.0)}, "vec3(0.0, 1.0, 0.0)")],
    "pbr_linear_to_srgb": [("NaN", "decided: NaN encodes as 0 (black)", {"c": (np.nan,) * 3}, 0.0),
                           ("+Inf", "decided: +Inf encodes like 1 (white)", {"c": (np.inf,) * 3},
                            "pbr_linear_to_srgb(vec3(1.0))"),
                           ("negative", "decided: negatives encode as 0", {"c": (-1.0,) * 3}, 0.0)],
    "pbr_encode_final_color": [("NaN", "decided: NaN encodes as 0 on every transfer path", {"c": (np.nan,) * 3}, 0.0),
                               ("+Inf", "decided: +Inf encodes like 1", {"c": (np.inf,) * 3},
                                "pbr_encode_final_color(vec3(1.0))")],
}
for _name in ("pbr_tonemap", "pbr_tonemap_reinhard", "pbr_tonemap_hable", "pbr_tonemap_aces_fitted", "pbr_tonemap_aces_narkowicz",
              "pbr_tonemap_khronos_neutral"):
    DECIDED[_name] = [("NaN", "decided: NaN maps to black, like 0", {"c": (np.nan,) * 3}, f"{_name}(vec3(0.0))"),
                      ("+Inf", "decided: +Inf maps like 65504, the white of every curve", {"c": (np.inf,) * 3},
                       f"{_name}(vec3(PBR_HALF_MAX))")]


# The unity model's material corners (Unity decides nothing here that pbrlab's tests could
# restate exactly: these are checked against the bound, the values against the transcription
# in tests/importers/unity/).
_UNITY_MATERIAL_CASES = (
    ("smoothness 1", {"smoothness": 1.0}, "a mirror: BRDF1's roughness floor 0.002 and GGXTerm's 1e-7 "
     "bound the peak; BRDF2's a² = 0 kills its lobe; BRDF3's lookup saturates at 16"),
    ("smoothness 0", {"smoothness": 0.0}, "the roughest lobe; spec power 1e-4: pow(x, 6e-6)"),
    ("black specular", {"f0": (0.0, 0.0, 0.0), "omr": 1.0}, "Unity's any(specColor) = false: no direct "
     "highlight, while the environment still lerps towards the grazing term"),
    ("dark metal", {"f0": (0.02, 0.02, 0.02), "diffuseColor": (0.0, 0.0, 0.0), "omr": 0.0},
     "metal with albedo 0.02: grazing term saturate(smoothness + 1) = 1 from a dark F0"),
)


def _unity_cases(function: Function) -> list[Case]:
    cases = []
    base = dict(typical_inputs(function), n=UP, v=(-0.6, 0.0, 0.8), l=(0.6, 0.0, 0.8))
    for name, why, n, v, l, _ in _GEOMETRY_CASES:
        if name == "far camera":  # Unity's BRDFs take a unit viewDir (the caller normalises)
            continue
        cases.append(Case(function, name, why, dict(base, n=n, v=v, l=l)))
    for name, change, why in _UNITY_MATERIAL_CASES:
        cases.append(Case(function, name, why, dict(base, **change)))
    return cases


def cases_of(function: Function) -> list[Case]:
    if function.name in ("pbr_brdf_standard", "pbr_shade_punctual", "pbr_brdf_standard_f90", "pbr_shade_punctual_f90"):
        return _shading_cases(function) + _edge_cases(function)
    if function.expression.startswith("(pbr_unity_brdf"):
        return _unity_cases(function) + _edge_cases(function)
    if not function.args:
        return [Case(function, "constant", "no inputs: the value itself must be exact", {"x": 0.0})]
    arg_names = {a.name for a in function.args}
    decided = [Case(function, name, why, dict(typical_inputs(function), **inputs), exact)
               if exact != "follows" else
               Case(function, name, why, dict(typical_inputs(function), **inputs), None, "",
                    _follows_anisotropic(dict(typical_inputs(function), **inputs)))
               for name, why, inputs, exact in DECIDED.get(function.name, []) if set(inputs) <= arg_names]
    dirs = [] if not any(a.kind == "dir" for a in function.args) else [
        Case(function, "typical directions", "unit vectors at a typical angle", typical_inputs(function))]
    return decided + dirs + _edge_cases(function)


def catalogue() -> list[Case]:
    return [case for function in functions() for case in cases_of(function)]
