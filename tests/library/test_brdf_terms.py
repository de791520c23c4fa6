"""Every BRDF term of glsl/pbr/brdf/ against its float64 reference (harness/pbrlab/maths/reference/brdf.py)
over a dense grid of its valid domain.

Tolerances are ``atol + rtol·|ref|`` in the unit of the term (1/sr for D, V, Fd, BRDFs;
unitless for G, F). Well-conditioned terms use RTOL_WELL_CONDITIONED (1e-5, see
library_helpers); terms whose float32 evaluation is ill-conditioned get a per-element
bound derived from the conditioning, written next to the test.
"""

import numpy as np
import pytest

from library_helpers import (seeded_rng, F32_EPS, MIN_ALPHA, RTOL_WELL_CONDITIONED, alphas, as_f32, assert_close,
                             cosines, evaluate, grid, perceptual_roughnesses, unit_vectors, v_cosines, vec3)
from pbrlab.maths.reference import brdf, remap

# Blinn-Phong exponents: the Call of Duty range 1..8192 plus the exponents the shading
# model reaches through pbr_specPower_from_alpha (alpha down to MIN_ALPHA: s ≈ 4.9e5).
_POWERS = np.concatenate([np.geomspace(1.0, 8192.0, 27), remap.specPower_from_alpha(alphas(9))])
SPEC_POWERS = as_f32(np.unique(_POWERS[_POWERS > 0.0]))  # s > 0: pow(0, 0) is undefined in GLSL


def pow_rtol(x, s):
    """Relative error allowed for float32 pow(x, s) by the GLSL spec (4.60 §4.7.1: pow is
    "inherited from exp2(y · log2(x))"; log2 has an ABSOLUTE error < 2^-21 for x in
    [0.5, 2] and 3 ulp outside; exp2 3 + 2|x| ulp). The log2 error is multiplied by s and
    exp2 turns an exponent error δ into a relative error ≈ δ·ln 2, so for s ~ 1e5 near
    x = 1 a conforming GPU may be several % off: ill-conditioning of pow itself, not of the
    formula. Measured on llvmpipe: 4.3 % at s = 4.9e5 (glsl/README.md)."""
    log2x = np.abs(np.log2(np.maximum(x, np.finfo(np.float64).tiny)))
    exponent_error = s * (2.0 ** -21 + 3 * 2.0 ** -23 * log2x) + 2.0 ** -24 * s * log2x
    return RTOL_WELL_CONDITIONED + np.log(2.0) * exponent_error + 8 * 2.0 ** -23 * (1 + s * log2x)


# ---- diffuse ----------------------------------------------------------------------------

def test_Fd_Lambert_is_inverse_pi():
    got = evaluate("pbr_Fd_Lambert()", x=0.0)
    assert got == np.float32(1.0 / np.pi)


def test_Fd_Burley_matches_reference():
    c = cosines(129)
    NdotV, NdotL, LdotH, r = grid(c, c, c[::8], perceptual_roughnesses(9))
    got = evaluate("pbr_Fd_Burley(NdotV, NdotL, LdotH, r)", NdotV=NdotV, NdotL=NdotL, LdotH=LdotH, r=r)
    assert_close("pbr_Fd_Burley", got, brdf.Fd_Burley(NdotV, NdotL, LdotH, r), rtol=RTOL_WELL_CONDITIONED)


# ---- Blinn-Phong lighting models and distribution -------------------------------------

@pytest.mark.parametrize("name", ["BlinnPhongModified", "BlinnPhongNormalized"])
def test_BRDF_BlinnPhong_matches_reference(name):
    NdotH, s = grid(cosines(1025), SPEC_POWERS)
    got = evaluate(f"pbr_BRDF_{name}(NdotH, s)", NdotH=NdotH, s=s)
    ref = getattr(brdf, f"BRDF_{name}")(NdotH, s)
    # atol: values below 1e-30 are float32 denormal/underflow territory (pow flushes them)
    assert_close(f"pbr_BRDF_{name}", got, ref, rtol=pow_rtol(NdotH, s), atol=1e-30)


def test_BRDF_BlinnPhongClassic_matches_reference():
    # NdotL <= 0 (the 0 branch) and NdotL >= PBR_MIN_NDOTV: below 1e-4 the classic form
    # divides by the floor instead (guards.glsl; tested in tests/checking/hardcases)
    NdotH, NdotL, s = grid(cosines(257), np.concatenate([[-0.5, 0.0], v_cosines(33)]), SPEC_POWERS[::4])
    got = evaluate("pbr_BRDF_BlinnPhongClassic(NdotH, NdotL, s)", NdotH=NdotH, NdotL=NdotL, s=s)
    ref = brdf.BRDF_BlinnPhongClassic(NdotH, NdotL, s)
    assert_close("pbr_BRDF_BlinnPhongClassic", got, ref, rtol=pow_rtol(NdotH, s), atol=1e-30)


def test_D_BlinnPhong_matches_reference():
    NdotH, s = grid(cosines(), SPEC_POWERS)
    got = evaluate("pbr_D_BlinnPhong(NdotH, s)", NdotH=NdotH, s=s)
    assert_close("pbr_D_BlinnPhong", got, brdf.D_BlinnPhong(NdotH, s), rtol=pow_rtol(NdotH, s), atol=1e-30)


# ---- distributions -------------------------------------------------------------------

def test_D_GGX_matches_reference():
    NdotH, alpha = grid(cosines(), alphas())
    got = evaluate("pbr_D_GGX(NdotH, alpha)", NdotH=NdotH, alpha=alpha)
    assert_close("pbr_D_GGX", got, brdf.D_GGX(NdotH, alpha), rtol=RTOL_WELL_CONDITIONED)


def test_D_GGX_peak_keeps_precision_for_tiny_alpha():
    """The lecture's textbook form loses ~12 % at NdotH = 1 for alpha = 1e-3 in float32;
    the rearranged form must not (see d_ggx.glsl)."""
    alpha = as_f32(np.geomspace(1e-4, 1e-2, 50))
    got = evaluate("pbr_D_GGX(1.0, alpha)", alpha=alpha)
    assert_close("pbr_D_GGX peak (alpha 1e-4..1e-2)", got, 1.0 / (np.pi * alpha ** 2), rtol=RTOL_WELL_CONDITIONED)


def test_D_Beckmann_matches_reference():
    NdotH, alpha = grid(cosines(), alphas())
    got = evaluate("pbr_D_Beckmann(NdotH, alpha)", NdotH=NdotH, alpha=alpha)
    ref = brdf.D_Beckmann(NdotH, alpha)
    # exp(x) with x = -tan²θ/alpha² computed in float32 (~4 roundings): relative error
    # ~4·eps·|x|; |x| reaches ~87 before the result underflows (atol covers underflow).
    with np.errstate(divide="ignore", invalid="ignore"):
        x = np.where(NdotH > 0, (1.0 - NdotH ** 2) / (alpha ** 2 * NdotH ** 2), 0.0)
    # Where x > ~87 exp underflows in float32 and the reference is < 1e-30 (atol); there
    # the rtol cap of 1e-3 is irrelevant, elsewhere 8·eps·x <= 4.2e-5.
    rtol = np.minimum(RTOL_WELL_CONDITIONED + 8 * F32_EPS * x, 1e-3)
    assert_close("pbr_D_Beckmann", got, ref, rtol=rtol, atol=1e-30)


# ---- masking-shadowing and visibility ------------------------------------------------

@pytest.fixture(scope="module")
def microfacet_geometry():
    """Consistent cosines from real directions: n = +z, v and l in the upper hemisphere."""
    rng = seeded_rng("microfacet_geometry")
    v = unit_vectors(rng, 200_000, min_z=1e-3)
    l = unit_vectors(rng, 200_000, min_z=1e-3)
    h = (l + v) / np.linalg.norm(l + v, axis=-1, keepdims=True)
    return {"NdotL": as_f32(l[:, 2]), "NdotV": as_f32(v[:, 2]), "NdotH": as_f32(h[:, 2]),
            "VdotH": as_f32(np.sum(v * h, axis=-1))}


def test_G_CookTorrance_matches_reference(microfacet_geometry):
    g = microfacet_geometry
    got = evaluate("pbr_G_CookTorrance(NdotL, NdotV, NdotH, VdotH)", **g)
    ref = brdf.G_CookTorrance(g["NdotL"], g["NdotV"], g["NdotH"], g["VdotH"])
    assert_close("pbr_G_CookTorrance", got, ref, rtol=RTOL_WELL_CONDITIONED)
    assert (got <= 1.0).all() and (got >= 0.0).all()


def test_V_CookTorrance_is_G_over_4_NdotL_NdotV(microfacet_geometry):
    g = microfacet_geometry
    got = evaluate("pbr_V_CookTorrance(NdotL, NdotV, NdotH, VdotH)", **g)
    ref = brdf.V_CookTorrance(g["NdotL"], g["NdotV"], g["NdotH"], g["VdotH"])
    assert_close("pbr_V_CookTorrance", got, ref, rtol=RTOL_WELL_CONDITIONED)


def test_G1_SmithGGX_matches_reference():
    NdotX, alpha = grid(cosines(), alphas())
    got = evaluate("pbr_G1_SmithGGX(NdotX, alpha)", NdotX=NdotX, alpha=alpha)
    # atol 1e-7: G1 is unitless in [0, 1]; at NdotX = 0 both are exactly 0
    assert_close("pbr_G1_SmithGGX", got, brdf.G1_SmithGGX(NdotX, alpha), rtol=RTOL_WELL_CONDITIONED, atol=1e-7)


@pytest.mark.parametrize("term", ["G_SmithGGX", "V_SmithGGX", "V_SmithGGXCorrelated", "V_SmithGGXCorrelatedFast"])
def test_smith_GGX_terms_match_reference(term):
    c = v_cosines(257)  # the unguarded domain of V, NdotL, NdotV >= PBR_MIN_NDOTV
    NdotL, NdotV, alpha = grid(c, c, alphas(17))
    got = evaluate(f"pbr_{term}(NdotL, NdotV, alpha)", NdotL=NdotL, NdotV=NdotV, alpha=alpha)
    ref = getattr(brdf, term)(NdotL, NdotV, alpha)
    assert_close(f"pbr_{term}", got, ref, rtol=RTOL_WELL_CONDITIONED)


def test_V_SmithGGXCorrelated_is_G2_over_4_NdotL_NdotV():
    """The GLSL's rearranged form equals Heitz's G2 / (4 NdotL NdotV) (same check as above,
    from the other side: G2 recovered from the GPU value stays in [0, 1])."""
    c = v_cosines(257)
    NdotL, NdotV, alpha = grid(c, c, alphas(17))
    V = evaluate("pbr_V_SmithGGXCorrelated(NdotL, NdotV, alpha)", NdotL=NdotL, NdotV=NdotV, alpha=alpha)
    G2 = V * 4.0 * NdotL * NdotV
    assert (G2 <= 1.0 + 1e-5).all() and (G2 > 0.0).all()


def test_V_SmithGGXCorrelatedFast_error_bound():
    """The fast form's documented worst relative error (PBR_V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR)
    holds on the GPU against the float64 exact form, and is not loose by more than 1 %."""
    c = np.geomspace(1e-4, 1.0, 257)
    NdotL, NdotV, alpha = grid(c, c, alphas(33))
    fast = evaluate("pbr_V_SmithGGXCorrelatedFast(NdotL, NdotV, alpha)", NdotL=NdotL, NdotV=NdotV, alpha=alpha)
    bound = float(evaluate("PBR_V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR", x=0.0))
    rel = np.abs(fast / brdf.V_SmithGGXCorrelated(NdotL, NdotV, alpha) - 1.0)
    assert rel.max() <= bound
    assert rel.max() >= 0.99 * bound - 1e-3


@pytest.mark.parametrize("term", ["G1_SchlickGGX"])
def test_G1_SchlickGGX_matches_reference(term):
    NdotX, k = grid(cosines(), alphas(17) / 2)
    got = evaluate(f"pbr_{term}(NdotX, k)", NdotX=NdotX, k=k)
    assert_close(f"pbr_{term}", got, getattr(brdf, term)(NdotX, k), rtol=RTOL_WELL_CONDITIONED, atol=1e-7)


@pytest.mark.parametrize("term", ["G_SchlickGGX", "V_SchlickGGX"])
def test_SchlickGGX_terms_match_reference(term):
    c = v_cosines(257) if term.startswith("V") else cosines(257)  # V: unguarded domain
    k = np.concatenate([alphas(9) / 2, brdf.k_SchlickGGX_hotness(perceptual_roughnesses(5))])
    NdotL, NdotV, k = grid(c, c, k)
    got = evaluate(f"pbr_{term}(NdotL, NdotV, k)", NdotL=NdotL, NdotV=NdotV, k=k)
    assert_close(f"pbr_{term}", got, getattr(brdf, term)(NdotL, NdotV, k), rtol=RTOL_WELL_CONDITIONED, atol=1e-7)


def test_k_SchlickGGX_remaps_match_reference():
    a = alphas()
    r = perceptual_roughnesses(65)
    assert_close("pbr_k_SchlickGGX_from_alpha", evaluate("pbr_k_SchlickGGX_from_alpha(a)", a=a),
                 brdf.k_SchlickGGX_from_alpha(a), rtol=RTOL_WELL_CONDITIONED)
    assert_close("pbr_k_SchlickGGX_hotness", evaluate("pbr_k_SchlickGGX_hotness(r)", r=r),
                 brdf.k_SchlickGGX_hotness(r), rtol=RTOL_WELL_CONDITIONED)
    # the lecture: Disney standard k = alpha/2 = (g - 1)²/2; hotness k = (0.5 + (1 - g)/2)²/2
    g = 1.0 - r
    np.testing.assert_allclose(brdf.k_SchlickGGX_from_alpha(remap.alpha_from_gloss_Unreal(g)), (g - 1) ** 2 / 2)
    np.testing.assert_allclose(brdf.k_SchlickGGX_hotness(r), (0.5 + (1 - g) / 2) ** 2 / 2)


def test_implicit_and_Kelemen_match_reference(microfacet_geometry):
    g = microfacet_geometry
    assert evaluate("pbr_V_Implicit()", x=0.0) == np.float32(brdf.V_Implicit()) == 0.25
    got = evaluate("pbr_G_Implicit(NdotL, NdotV)", NdotL=g["NdotL"], NdotV=g["NdotV"])
    assert_close("pbr_G_Implicit", got, brdf.G_Implicit(g["NdotL"], g["NdotV"]), rtol=RTOL_WELL_CONDITIONED)
    got = evaluate("pbr_V_Kelemen(VdotH)", VdotH=g["VdotH"])
    assert_close("pbr_V_Kelemen", got, brdf.V_Kelemen(g["VdotH"]), rtol=RTOL_WELL_CONDITIONED)
    got = evaluate("pbr_G_Kelemen(NdotL, NdotV, VdotH)", NdotL=g["NdotL"], NdotV=g["NdotV"], VdotH=g["VdotH"])
    assert_close("pbr_G_Kelemen", got, brdf.G_Kelemen(g["NdotL"], g["NdotV"], g["VdotH"]), rtol=RTOL_WELL_CONDITIONED)


@pytest.mark.parametrize("G, V", [("pbr_G_Implicit(NdotL, NdotV)", "pbr_V_Implicit()"),
                                  ("pbr_G_Kelemen(NdotL, NdotV, VdotH)", "pbr_V_Kelemen(VdotH)"),
                                  ("pbr_G_SmithGGX(NdotL, NdotV, 0.3)", "pbr_V_SmithGGX(NdotL, NdotV, 0.3)"),
                                  ("pbr_G_SchlickGGX(NdotL, NdotV, 0.15)", "pbr_V_SchlickGGX(NdotL, NdotV, 0.15)"),
                                  ("pbr_G_CookTorrance(NdotL, NdotV, NdotH, VdotH)",
                                   "pbr_V_CookTorrance(NdotL, NdotV, NdotH, VdotH)")])
def test_every_V_is_its_G_over_4_NdotL_NdotV(G, V, microfacet_geometry):
    """The naming convention: V_ = G_ / (4 NdotL NdotV), never G itself."""
    g = {k: v[:20000] for k, v in microfacet_geometry.items()}
    got = evaluate(f"{V} * 4.0 * NdotL * NdotV", **g)
    assert_close(f"V*4NL*NV vs G: {G.split('(')[0]}", got, evaluate(G, **g), rtol=4 * RTOL_WELL_CONDITIONED)


# ---- Fresnel ---------------------------------------------------------------------------

# Fresnel values are unitless reflectances in [0, 1]. atol 3e-7 (~5 float32 ulps of 1):
# F = f0 + (f90 - f0)·w cancels when f90 < f0 and w -> 1 (F -> f90, e.g. 0), and F = 0
# exactly for f0 = 0 at VdotH = 1, where no relative tolerance can help.
F_ATOL = 3e-7
F0_RGB = np.array([[0.0, 0.02, 0.04], [0.5, 0.9, 1.0], [1.0, 0.765557, 0.336057]])  # incl. gold


def test_F_Schlick_scalar_and_rgb_match_reference():
    VdotH, f0 = grid(cosines(), np.linspace(0.0, 1.0, 21))
    got = evaluate("pbr_F_Schlick(f0, VdotH)", f0=f0, VdotH=VdotH)
    assert_close("pbr_F_Schlick (float)", got, brdf.F_Schlick(f0, VdotH), rtol=RTOL_WELL_CONDITIONED, atol=F_ATOL)
    VdotH = cosines()[:, None]
    got = evaluate("pbr_F_Schlick(f0, VdotH)", f0=vec3(F0_RGB[None]), VdotH=VdotH)
    ref = brdf.F_Schlick(F0_RGB[None], VdotH[..., None])
    assert_close("pbr_F_Schlick (vec3)", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=F_ATOL)


def test_F_Schlick_with_F90_matches_reference():
    VdotH, f90 = grid(cosines(), np.linspace(0.0, 1.0, 11))
    f0 = np.array([0.04, 0.5, 0.9])
    got = evaluate("pbr_F_Schlick(vec3(0.04, 0.5, 0.9), f90, VdotH)", f90=f90, VdotH=VdotH)
    ref = brdf.F_Schlick(f0, VdotH[..., None], f90=f90[..., None])
    assert_close("pbr_F_Schlick (F90)", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=F_ATOL)


def test_F_SchlickSG_matches_reference():
    VdotH = cosines()[:, None]
    got = evaluate("pbr_F_SchlickSG(f0, VdotH)", f0=vec3(F0_RGB[None]), VdotH=VdotH)
    ref = brdf.F_SchlickSG(F0_RGB[None], VdotH[..., None])
    assert_close("pbr_F_SchlickSG", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=F_ATOL)


def test_F_SchlickSG_error_bound():
    """|SG - Schlick| <= PBR_F_SCHLICK_SG_MAX_ABS_ERROR, and the bound is tight (within 2 %)."""
    VdotH = as_f32(np.linspace(0.0, 1.0, 100001))
    got = evaluate("pbr_F_SchlickSG(vec3(0.0), VdotH).x", VdotH=VdotH)
    bound = float(evaluate("PBR_F_SCHLICK_SG_MAX_ABS_ERROR", x=0.0))
    err = np.abs(got - brdf.F_Schlick(0.0, VdotH))
    assert err.max() <= bound
    assert err.max() >= 0.98 * bound


ETAS = np.unique(np.concatenate([np.linspace(1.05, 3.0, 40), 1.0 / np.linspace(1.05, 3.0, 40)]))


def test_F_Dielectric_matches_reference():
    cos_theta, eta = grid(cosines(), ETAS)
    got = evaluate("pbr_F_Dielectric(c, eta)", c=cos_theta, eta=eta)
    ref = brdf.F_Dielectric(cos_theta, eta)
    # Near the critical angle (eta < 1, g = sqrt(eta² - 1 + c²) -> 0) F has an infinite
    # slope: the float32 rounding of g² (~4 eps absolute) moves g by ~4 eps / (2 g) and F
    # by about as much (|dF/dg| <= ~4 there). Tolerance: that propagated error, plus rtol.
    g2 = eta ** 2 - 1.0 + cos_theta ** 2
    g = np.sqrt(np.maximum(g2, 0.0))
    conditioning = np.where(g2 > 0, 16.0 * F32_EPS / np.maximum(g, 1e-12), 0.0)
    assert_close("pbr_F_Dielectric", got, ref, rtol=RTOL_WELL_CONDITIONED, atol=1e-7 + conditioning)
