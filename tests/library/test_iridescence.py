"""Thin-film iridescence (glsl/pbr/brdf/f_iridescence.glsl, KHR_materials_iridescence) against
its two float64 references (harness/pbrlab/maths/reference/iridescence.py): (a) the same analytic
method, to float32 rounding; (b) the spectral physics (exact Airy film per wavelength, CIE 1931
by Wyman et al. 2013), within the method's measured error, stated in the GLSL header.

Units: F is a reflectance (unitless, [0, 1]); tolerances are absolute.
"""

import numpy as np
import pytest

from library_helpers import F32_EPS, as_f32, assert_close, evaluate, vec3
from pbrlab.maths.reference import brdf, iridescence, specular_extension, surface

INCLUDE = ("pbr/brdf/f_iridescence.glsl",)
CALL = "pbr_F_Iridescence(n1, n2, c, d, f0)"

# (a) GLSL vs the same method in float64. F is a sum of six terms, each at most |C_m| 2 |S|
# <= 2 * 5.3 in size, of ~40 float32 operations; the phase argument pos * 2π 1e-9 * m OPD
# reaches 133 rad at 1200 nm, film IOR 2, m = 2 (one rounding of it: 8e-6 rad, times an
# envelope <= 1.6e-7 there). Measured worst 1.9e-6 (llvmpipe); 1e-5 leaves 5x headroom and
# catches any formula change (a wrong constant or phase is >= 1e-3 off).
ATOL_FLOAT32 = 1e-5
# The method is discontinuous where a phase flips (base IOR = film IOR: φ23 jumps by π while
# Schlick's R23 = (1 - cosθ2)^5 is not 0; and the total internal reflection edge, where F
# jumps to 1): there float32 and float64 may land on different sides. Points within this
# relative distance of a tie are compared by the bound test instead.
TIE_RELATIVE = 1e-5


def _grid():
    d = as_f32(np.concatenate([[0.0, 0.01, 0.03], np.linspace(1.0, 1200.0, 300)]))
    c = as_f32(np.concatenate([np.linspace(0.0, 1.0, 65), np.geomspace(1e-6, 1e-2, 9)]))
    film = as_f32([1.0, 1.2, 1.33, 1.5, 1.8, 2.0, 0.8])     # 1.0: no film interface; 0.8: TIR
    f0 = as_f32([[0.02, 0.04, 0.08], [0.9, 0.6, 0.3], [0.0, 0.5, 1.0], [0.04, 0.04, 0.04]])
    D, C, N, K = np.meshgrid(d, c, film, np.arange(len(f0)), indexing="ij")
    return D, C, N, f0[K]


def _away_from_ties(n1, N, C, f0):
    eta3 = iridescence.ior_from_f0(np.clip(f0, 0.0, iridescence.MAX_BASE_F0))
    tie = (np.abs(eta3 - N[..., None]) <= TIE_RELATIVE * N[..., None]).any(axis=-1)
    cos2_sq = 1.0 - (n1 / N) ** 2 * (1.0 - C ** 2)
    return ~tie & (np.abs(cos2_sq) > TIE_RELATIVE)


def _conditioning_atol(n1, N, C, D):
    """Near the critical angle (outside IOR above the film's) cosθ2 = sqrt(cos²θ2) is
    ill-conditioned: a rounding of cos²θ2 (<= 8 eps (n1/n2)², a few operations) moves cosθ2 by
    that over 2 cosθ2, and F moves by dF/dcosθ2 <= 5 (Schlick's slope) + Σ_m 2 · 5.3 (|C_m| <= 1,
    |S| <= 5.3) · dθ_m/dcosθ2 · envelope_m, θ_m = pos_max 2π 1e-9 m 2 n2 d cosθ2 the phase."""
    ratio2 = (n1 / N) ** 2
    # floored where _away_from_ties excludes (|cos²θ2| <= TIE_RELATIVE) or F = 1 (TIR)
    c2 = np.sqrt(np.maximum(1.0 - ratio2 * (1.0 - C ** 2), TIE_RELATIVE))
    k = 5.0
    for m in (1, 2):
        phase = 2 * np.pi * 1e-9 * m * 2 * N * D * c2
        dtheta = max(iridescence.XYZ_POS + (iridescence.X2_POS,)) * 2 * np.pi * 1e-9 * m * 2 * N * D
        k = k + 2 * 5.3 * dtheta * np.exp(-min(iridescence.XYZ_VAR) * phase ** 2)
    return ATOL_FLOAT32 + 8 * F32_EPS * ratio2 / (2 * c2) * k


@pytest.mark.parametrize("n1", [1.0, 1.5])   # air; under a clearcoat of IOR 1.5
def test_F_Iridescence_matches_the_float64_method(n1):
    D, C, N, f0 = _grid()
    got = evaluate(CALL, INCLUDE, n1=n1, n2=N, c=C, d=D, f0=vec3(f0))
    ref = iridescence.F_Iridescence(n1, N, C, D, f0)
    atol = _conditioning_atol(n1, N, C, D)[..., None]
    assert_close(f"pbr_F_Iridescence (outside IOR {n1})", got, ref, rtol=0.0, atol=atol,
                 where=_away_from_ties(n1, N, C, f0))


def test_iridescence_sensitivity_matches_reference():
    opd = as_f32(np.linspace(0.0, 1.0e4, 4001))[:, None]
    shift = as_f32([[0.0, 0.0, 0.0], [np.pi, np.pi, np.pi], [2 * np.pi, np.pi, 0.0], [4 * np.pi, 2 * np.pi, 0.0]])
    got = evaluate("pbr_iridescence_sensitivity(o, s)", INCLUDE, o=opd, s=vec3(shift[None]))
    ref = iridescence.iridescence_sensitivity(opd, shift[None])
    # |S| <= 5.3; measured 2.6e-6 absolute; arguments up to 1.4e2 rad
    assert_close("pbr_iridescence_sensitivity", got, ref, rtol=0.0, atol=ATOL_FLOAT32)


def test_F_Iridescence_within_its_stated_error_of_the_spectral_physics():
    """The bound the GLSL header states (PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL, measured
    0.2206 in float64 on this grid, at cosθ1 = 0.15: Schlick's interfaces and the two-order
    series), checked on the GPU; near normal view (cosθ1 >= 0.7) the tighter 0.045."""
    d = as_f32(np.linspace(0.0, 1200.0, 121))
    c = as_f32([1.0, 0.85, 0.7, 0.5, 0.3, 0.15, 0.05])
    film = as_f32([1.2, 1.5, 2.0])
    grey = as_f32([0.02, 0.04, 0.08])     # dielectric bases (IOR 1.33, 1.5, 1.79)
    D, C, N, G = np.meshgrid(d, c, film, grey, indexing="ij")
    f0 = np.repeat(G[..., None], 3, axis=-1)
    got = evaluate(CALL, INCLUDE, n1=1.0, n2=N, c=C, d=D, f0=vec3(f0))
    physics = iridescence.spectral_F_Iridescence(1.0, N, C, D, f0)
    err = np.abs(got - physics)
    assert err.max() <= iridescence.F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL, err.max()
    near_normal = C >= 0.7
    assert err[near_normal].max() <= iridescence.F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL_NEAR_NORMAL
    assert evaluate("PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL", INCLUDE, x=0.0) == np.float32(
        iridescence.F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL)
    assert evaluate("PBR_F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL_NEAR_NORMAL", INCLUDE, x=0.0) == np.float32(
        iridescence.F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL_NEAR_NORMAL)


def test_spectral_reference_without_a_film_is_the_exact_dielectric_fresnel():
    """The reference checks itself: film IOR = outside IOR leaves one interface, whose
    spectrally flat reflectance must integrate to the exact Fresnel (brdf.F_Dielectric)."""
    c = np.array([1.0, 0.7, 0.3, 0.05])
    f0 = np.array([0.02, 0.04, 0.5])
    got = iridescence.spectral_F_Iridescence(1.0, 1.0, c, 300.0, f0)
    eta = iridescence.ior_from_f0(f0)
    np.testing.assert_allclose(got, brdf.F_Dielectric(c[:, None], eta), rtol=1e-12, atol=1e-14)


def test_thickness_zero_is_the_schlick_base_fresnel_bit_for_bit():
    """The extension mixes towards glTF's Schlick F (B.3.4), and its Sample Renderer turns
    iridescence off at thickness 0: pbr_F_Schlick(baseF0, cosTheta1), not the exact Fresnel."""
    D, C, N, f0 = _grid()
    sel = (slice(0, 1),)   # d = 0 (and -0, NaN below)
    for d in (0.0, -0.0, -5.0, np.nan):
        got = evaluate(CALL, INCLUDE, n1=1.0, n2=N[sel], c=C[sel], d=d, f0=vec3(f0[sel]))
        base = evaluate("pbr_F_Schlick(f0, c)", INCLUDE, c=C[sel], f0=vec3(f0[sel]))
        np.testing.assert_array_equal(got, base)


def test_F_Iridescence_is_finite_and_a_reflectance_at_the_edges():
    D, C, N, f0 = _grid()
    C = np.concatenate([C[:, :2], np.full_like(C[:, :1], 1.01), np.full_like(C[:, :1], -0.5)], axis=1)
    shape = C.shape
    D, N, f0 = D[:, :4], N[:, :4], f0[:, :4]
    for n1 in (1.0, 1.5, 1.0 / 16.0, 16.0):
        got = evaluate(CALL, INCLUDE, n1=n1, n2=N, c=C, d=D, f0=vec3(f0))
        assert got.shape == shape + (3,)
        assert np.isfinite(got).all() and (got >= 0.0).all() and (got <= 1.0).all(), n1
    # total internal reflection inside the film (film IOR below the outside IOR): F = 1
    got = evaluate(CALL, INCLUDE, n1=1.5, n2=1.0, c=0.2, d=300.0, f0=vec3([0.04, 0.04, 0.04]))
    np.testing.assert_array_equal(got, np.ones(3, np.float32))
    # grazing: the film's top reflects everything
    got = evaluate(CALL, INCLUDE, n1=1.0, n2=1.5, c=0.0, d=300.0, f0=vec3([0.04, 0.5, 1.0]))
    np.testing.assert_allclose(got, 1.0, atol=1e-6)


def test_iridescence_mix_and_thickness_match_the_extension():
    rng = np.random.default_rng(7)
    F, Fi = as_f32(rng.random((1000, 3))), as_f32(rng.random((1000, 3)))
    t = as_f32(np.linspace(-0.5, 1.5, 1000))
    got = evaluate("pbr_iridescence_mix(F, Fi, t)", INCLUDE, F=vec3(F), Fi=vec3(Fi), t=t)
    assert_close("pbr_iridescence_mix", got, iridescence.iridescence_mix(F, Fi, t), rtol=1e-6, atol=1e-7)
    lo, hi = as_f32(rng.uniform(0, 1200, 1000)), as_f32(rng.uniform(0, 1200, 1000))   # min may exceed max
    got = evaluate("pbr_iridescence_thickness(lo, hi, g)", INCLUDE, lo=lo, hi=hi, g=t)
    assert_close("pbr_iridescence_thickness", got, iridescence.iridescence_thickness(lo, hi, t),
                 rtol=1e-6, atol=1e-4)
    # defaults of the extension: min 100, max 400, g = 1 (no texture) -> the maximum
    assert evaluate("pbr_iridescence_thickness(100.0, 400.0, 1.0)", INCLUDE, x=0.0) == 400.0


# pbr_F_Iridescence's operations as early returns (its two special cases were early returns before
# it was made branch-free; now both are selected at the end, so a program inlining it more than
# once can share one evaluation: benchmarks/whole_program_cost.py). Kept here to show the selects
# are image-neutral.
_BRANCHING_FORM = """
#include "pbr/brdf/f_iridescence.glsl"
vec3 branching_F_Iridescence(float outsideIor, float filmIor, float cosTheta1, float thicknessNm, vec3 baseF0) {
    if (!(thicknessNm > 0.0)) return pbr_F_Schlick(baseF0, cosTheta1);
    float c1 = pbr_saturate(cosTheta1);
    float n1 = outsideIor;
    float n2 = mix(n1, filmIor, smoothstep(0.0, PBR_IRIDESCENCE_FILM_FADE_NM, thicknessNm));
    float ratio = n1 / n2;
    float cos2Sq = 1.0 - ratio * ratio * (1.0 - c1 * c1);
    if (cos2Sq < 0.0) return vec3(1.0);
    float c2 = sqrt(cos2Sq);
    float r0 = (n2 - n1) / (n2 + n1);
    float R12 = pbr_F_Schlick(r0 * r0, c1);
    float T121 = 1.0 - R12;
    float opd = 2.0 * n2 * thicknessNm * c2;
    vec3 f0 = clamp(baseF0, 0.0, PBR_IRIDESCENCE_MAX_BASE_F0);
    vec3 eta3 = vec3(pbr_ior_from_f0(f0.x), pbr_ior_from_f0(f0.y), pbr_ior_from_f0(f0.z));
    bool pi21 = !(n2 < n1);
    vec3 cosPhi = vec3((eta3.x < n2) != pi21 ? -1.0 : 1.0, (eta3.y < n2) != pi21 ? -1.0 : 1.0,
                       (eta3.z < n2) != pi21 ? -1.0 : 1.0);
    vec3 S1 = pbr_iridescence_xyz_to_rec709(cosPhi * pbr_iridescence_sensitivity_xyz(opd));
    vec3 S2 = pbr_iridescence_xyz_to_rec709(pbr_iridescence_sensitivity_xyz(2.0 * opd));
    vec3 r1 = (eta3 - vec3(n2)) / (eta3 + vec3(n2));
    vec3 R23 = pbr_F_Schlick(r1 * r1, c2);
    vec3 R123 = clamp(R12 * R23, PBR_IRIDESCENCE_MIN_R123, PBR_IRIDESCENCE_MAX_R123);
    vec3 r123 = sqrt(R123);
    vec3 Rs = (T121 * T121) * R23 / (vec3(1.0) - R123);
    vec3 C1 = (Rs - vec3(T121)) * r123;
    vec3 C2 = C1 * r123;
    vec3 I = vec3(R12) + Rs + C1 * (2.0 * S1) + C2 * (2.0 * S2);
    return pbr_saturate(I);
}
"""
# pbr_F_Iridescence as it was before the phase shift became a sign (issue 35): the spec's
# evalSensitivity with the shift added to the cosine's argument, branch-free as the library had it.
_SHIFTED_FORM = """
#include "pbr/brdf/f_iridescence.glsl"
vec3 shifted_F_Iridescence(float outsideIor, float filmIor, float cosTheta1, float thicknessNm, vec3 baseF0) {
    float c1 = pbr_saturate(cosTheta1);
    float n1 = outsideIor;
    float n2 = mix(n1, filmIor, smoothstep(0.0, PBR_IRIDESCENCE_FILM_FADE_NM, thicknessNm));
    float ratio = n1 / n2;
    float cos2Sq = 1.0 - ratio * ratio * (1.0 - c1 * c1);
    float c2 = sqrt(max(cos2Sq, 0.0));
    float r0 = (n2 - n1) / (n2 + n1);
    float R12 = pbr_F_Schlick(r0 * r0, c1);
    float T121 = 1.0 - R12;
    float phi21 = n2 < n1 ? 0.0 : PBR_PI;
    vec3 f0 = clamp(baseF0, 0.0, PBR_IRIDESCENCE_MAX_BASE_F0);
    vec3 eta3 = vec3(pbr_ior_from_f0(f0.x), pbr_ior_from_f0(f0.y), pbr_ior_from_f0(f0.z));
    vec3 r1 = (eta3 - vec3(n2)) / (eta3 + vec3(n2));
    vec3 R23 = pbr_F_Schlick(r1 * r1, c2);
    vec3 phi23 = vec3(eta3.x < n2 ? PBR_PI : 0.0, eta3.y < n2 ? PBR_PI : 0.0, eta3.z < n2 ? PBR_PI : 0.0);
    vec3 phi = vec3(phi21) + phi23 + vec3(SHIFT_ERROR);
    float opd = 2.0 * n2 * thicknessNm * c2;
    vec3 R123 = clamp(R12 * R23, PBR_IRIDESCENCE_MIN_R123, PBR_IRIDESCENCE_MAX_R123);
    vec3 r123 = sqrt(R123);
    vec3 Rs = (T121 * T121) * R23 / (vec3(1.0) - R123);
    vec3 C1 = (Rs - vec3(T121)) * r123;
    vec3 C2 = C1 * r123;
    vec3 I = vec3(R12) + Rs
           + C1 * (2.0 * pbr_iridescence_sensitivity(opd, phi))
           + C2 * (2.0 * pbr_iridescence_sensitivity(2.0 * opd, 2.0 * phi));
    vec3 F = cos2Sq < 0.0 ? vec3(1.0) : pbr_saturate(I);
    vec3 noFilm = pbr_F_Schlick(baseF0, cosTheta1);
    return thicknessNm > 0.0 ? F : noFilm;
}
"""


def test_branch_free_form_equals_the_branching_form_bit_for_bit(tmp_path):
    """The selects return what the early returns did, on the whole grid (thickness 0 and the
    fade, total internal reflection with film IOR 0.8 and outside IOR 1.5 / 16, grazing and
    out-of-range cosines): equality, no tolerance (same operations, same inputs)."""
    (tmp_path / "branching.glsl").write_text(_BRANCHING_FORM)
    D, C, N, f0 = _grid()
    D = np.concatenate([D[:, :1], np.full_like(D[:, :1], -5.0), D], axis=1)
    C = np.concatenate([C[:, :1], C[:, :1], C], axis=1)
    N = np.concatenate([N[:, :1], N[:, :1], N], axis=1)
    f0 = np.concatenate([f0[:, :1], f0[:, :1], f0], axis=1)
    for n1 in (1.0, 1.5, 1.0 / 16.0, 16.0):
        new = evaluate(CALL, INCLUDE, n1=n1, n2=N, c=C, d=D, f0=vec3(f0))
        old = evaluate("branching_F_Iridescence(n1, n2, c, d, f0)", ("branching.glsl",),
                       include_dirs=(str(tmp_path),), n1=n1, n2=N, c=C, d=D, f0=vec3(f0))
        np.testing.assert_array_equal(new, old)
    # control: the comparison sees a changed case (TIR returning 0.5 instead of 1)
    (tmp_path / "changed.glsl").write_text(_BRANCHING_FORM.replace("return vec3(1.0);", "return vec3(0.5);"))
    changed = evaluate("branching_F_Iridescence(n1, n2, c, d, f0)", ("changed.glsl",), include_dirs=(str(tmp_path),),
                       n1=1.5, n2=1.0, c=0.2, d=300.0, f0=vec3([0.04, 0.04, 0.04]))
    assert not np.array_equal(changed, evaluate(CALL, INCLUDE, n1=1.5, n2=1.0, c=0.2, d=300.0,
                                                f0=vec3([0.04, 0.04, 0.04])))


# ---- the film split into its base-independent terms and each base's (issue 35) ----

F32_PI_ERROR = abs(float(np.float32(np.pi)) - np.pi)   # 8.7e-8: PBR_PI in float32


def _ulp32(x):
    return np.spacing(np.abs(np.asarray(x, np.float64)).astype(np.float32)).astype(np.float64)


def _device_cos_error():
    """The evaluator's cos against float64 over the film's arguments (0 to 150 rad: at most
    pos 2.24e6 · 2π 1e-9 · 2 · 2 n2 d cosθ2 = 135 rad at 1200 nm, film IOR 2, plus 4π): the
    device's own error, which enters both forms of the film at different arguments."""
    x = as_f32(np.linspace(0.0, 150.0, 300001))
    return float(np.abs(evaluate("cos(x)", (), x=x).astype(np.float64) - np.cos(x.astype(np.float64))).max())


def _sign_form_atol(n1, N, C, D, cos_error):
    """|sign form - shifted form| per sample, from what differs between them: the shifted form
    rounds the argument x + mφ (½ ulp of it, besides the ½ ulp of x both round) and carries
    PBR_PI's representation error (2m · 8.7e-8 for mφ <= 2m π), and the device's cos errs at two
    different arguments (2 ε_cos). Each XYZ term moves by its amplitude A_k times its envelope
    times that (|d cos| <= |d arg|); the normalisation rounds each side (1 ulp of |xyz|), each
    matrix row's three roundings on each side (3 ulp of Σ|M_jk||xyz_k|), the Airy sum takes
    2 |C_m| (|C_m| <= 1: |Rs - T121| <= T121 <= 1, r123 <= 1) of each order's change, and its
    product and sum round on each side (1 ulp of 2|S| and of 1 + 2|S|). TIR and no film select
    the same values in both (difference 0; the bound holds there too)."""
    film = iridescence.thin_film(n1, N, C, D)
    opd = 2.0 * film["n2"] * film["thickness"] * film["c2"]
    M = np.abs(np.array(iridescence.XYZ_TO_REC709))
    lobes = [(iridescence.XYZ_VAL[k], iridescence.XYZ_POS[k], iridescence.XYZ_VAR[k], k) for k in range(3)]
    lobes.append((iridescence.X2_VAL, iridescence.X2_POS, iridescence.X2_VAR, 0))
    total = 0.0
    for m in (1, 2):
        phase = 2.0 * np.pi * 1e-9 * np.clip(m * opd, 0.0, iridescence.MAX_OPD_NM)
        dxyz, mag = [0.0] * 3, [0.0] * 3
        for val, pos, var, k in lobes:
            amplitude_envelope = val * np.sqrt(2.0 * np.pi * var) / iridescence.XYZ_NORM * np.exp(-var * phase ** 2)
            x = pos * phase
            darg = 0.5 * _ulp32(x) + 0.5 * _ulp32(x + 2 * m * np.pi) + 2 * m * F32_PI_ERROR
            dxyz[k] = dxyz[k] + amplitude_envelope * (darg + 2.0 * cos_error)
            mag[k] = mag[k] + amplitude_envelope
        dxyz = [dxyz[k] + _ulp32(mag[k]) for k in range(3)]
        dS = np.stack([sum(M[j, k] * dxyz[k] for k in range(3)) + 3 * _ulp32(sum(M[j, k] * mag[k] for k in range(3)))
                       for j in range(3)], axis=-1)
        S = np.stack([sum(M[j, k] * mag[k] for k in range(3)) for j in range(3)], axis=-1)
        total = total + 2.0 * dS + _ulp32(2.0 * S) + _ulp32(1.0 + 2.0 * S)
    return total


def test_sign_form_is_the_shifted_form_to_the_arguments_rounding(tmp_path):
    """The phase shift φ (0, π or 2π) applied as the sign cos φ of each channel's XYZ terms
    instead of added to the cosine's argument: the same method (cos(x + φ) = cos φ cos x), so
    the sign form differs from the library's former shifted form only where float32 rounds
    the argument x + φ and by the device's cos at the two arguments (_sign_form_atol, per
    sample: at most 4.0e-5 where the envelope is 1 at the largest arguments; measured worst
    8.9e-7 on llvmpipe). Control: the shifted form with φ off by 1e-3 rad is caught."""
    cos_error = _device_cos_error()
    D, C, N, f0 = _grid()
    for n1 in (1.0, 1.5):
        new = evaluate(CALL, INCLUDE, n1=n1, n2=N, c=C, d=D, f0=vec3(f0)).astype(np.float64)
        atol = _sign_form_atol(n1, N, C, D, cos_error)
        for error, caught in ((0.0, False), (1e-3, True)):
            (tmp_path / "shifted.glsl").write_text(f"#define SHIFT_ERROR {error!r}\n" + _SHIFTED_FORM)
            old = evaluate("shifted_F_Iridescence(n1, n2, c, d, f0)", ("shifted.glsl",),
                           include_dirs=(str(tmp_path),), n1=n1, n2=N, c=C, d=D, f0=vec3(f0))
            over = np.abs(new - old) > atol
            assert over.any() == caught, (n1, error, np.abs(new - old).max())


def test_thin_film_reference_is_the_float64_method():
    """reference/iridescence.py's twin of the split (thin_film, F_Iridescence_thin_film: the
    sign form) against F_Iridescence (the shifted form) in float64: equal to float64 rounding,
    ~40 operations on values up to 1 + 4 · 5.3 (1e-13 >= 40 · 23 · 2^-52 = 2e-13 / 2)."""
    D, C, N, f0 = _grid()
    for n1 in (1.0, 1.5, 1.0 / 16.0, 16.0):
        split = iridescence.F_Iridescence_thin_film(iridescence.thin_film(n1, N, C, D), f0)
        np.testing.assert_allclose(split, iridescence.F_Iridescence(n1, N, C, D, f0), rtol=0.0, atol=1e-13)


def test_sensitivity_xyz_and_matrix_match_reference():
    """pbr_iridescence_sensitivity_xyz and pbr_iridescence_xyz_to_rec709 against their float64
    twins (|S_xyz| <= 1.0011, arguments up to 1.4e2 rad as in the shifted test above: the same
    ATOL_FLOAT32); and M (cos φ ⊙ S_xyz) is S(OPD, φ) for φ in {0, π, 2π} in float64."""
    opd = as_f32(np.linspace(0.0, 1.0e4, 4001))
    got = evaluate("pbr_iridescence_sensitivity_xyz(o)", INCLUDE, o=opd)
    assert_close("pbr_iridescence_sensitivity_xyz", got, iridescence.sensitivity_xyz(opd), rtol=0.0,
                 atol=ATOL_FLOAT32)
    xyz = as_f32(np.random.default_rng(35).uniform(-1.0, 1.0, (1000, 3)))
    got = evaluate("pbr_iridescence_xyz_to_rec709(x)", INCLUDE, x=vec3(xyz))
    # |rgb| <= 5.28: each dot product's three roundings, 3 ulp(5.28) = 1.4e-6
    assert_close("pbr_iridescence_xyz_to_rec709", got, iridescence.xyz_to_rec709(xyz), rtol=0.0, atol=1.5e-6)
    for cos_phi in ([1.0, 1.0, 1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, -1.0]):
        shift = np.arccos(cos_phi)   # 0 or π
        for extra in (0.0, 2.0 * np.pi):
            np.testing.assert_allclose(
                iridescence.xyz_to_rec709(np.array(cos_phi) * iridescence.sensitivity_xyz(opd.astype(np.float64))),
                iridescence.iridescence_sensitivity(opd, (shift + extra)[None]), rtol=0.0, atol=1e-12)


LIGHTING = ("pbr/surface/lighting_iridescence.glsl",)


def test_with_coat_forms_are_the_separate_calls_bit_for_bit():
    """pbr_iridescent_f0[_f90]_with_coat (one pbr_thin_film for the base's F0 and its coat's)
    return exactly what two pbr_iridescent_f0[_f90] calls return: the same operations on the
    same inputs. Control: a different coat F0 gives a different coat value."""
    rng = np.random.default_rng(3535)
    n = 4096
    x = {"f0": as_f32(rng.uniform(0.0, 1.0, (n, 3))), "cf0": as_f32(rng.uniform(0.0, 0.2, (n, 3))),
         "c": as_f32(np.concatenate([rng.uniform(0.0, 1.0, n - 4), [0.0, 1e-4, 1.0, 1.0]])),
         "t": as_f32(rng.uniform(-0.2, 1.2, n)), "n2": as_f32(rng.uniform(0.8, 2.2, n)),
         "d": as_f32(np.concatenate([rng.uniform(0.0, 1200.0, n - 4), [0.0, -1.0, 0.01, 400.0]])),
         "f90": as_f32(rng.uniform(0.0, 1.0, n)), "cf90": as_f32(rng.uniform(0.0, 1.0, n))}
    x["f0"] = np.minimum(x["f0"], x["f90"][:, None])
    x["cf0"] = np.minimum(x["cf0"], x["cf90"][:, None])
    args = {k: vec3(v) if v.ndim == 2 else v for k, v in x.items()}
    film = "pbr_Iridescence(t, n2, d)"
    for member, other in (("f0", "f0"), ("coatF0", "cf0")):
        both = evaluate(f"pbr_iridescent_f0_with_coat(f0, cf0, c, {film}).{member}", LIGHTING, **args)
        one = evaluate(f"pbr_iridescent_f0({other}, c, {film})", LIGHTING, **args)
        np.testing.assert_array_equal(both, one)
        both = evaluate(f"pbr_iridescent_f0_f90_with_coat(f0, f90, cf0, cf90, c, {film}).{member}", LIGHTING, **args)
        f90 = "f90" if other == "f0" else "cf90"
        one = evaluate(f"pbr_iridescent_f0_f90({other}, {f90}, c, {film})", LIGHTING, **args)
        np.testing.assert_array_equal(both, one)
    changed = evaluate(f"pbr_iridescent_f0_with_coat(f0, cf0 + vec3(0.01), c, {film}).coatF0", LIGHTING, **args)
    assert not np.array_equal(changed, evaluate(f"pbr_iridescent_f0(cf0, c, {film})", LIGHTING, **args))
    # the float64 twins are the separate references, the same way
    base, coat = surface.iridescent_f0_with_coat(x["f0"], x["cf0"], x["c"], x["t"], x["n2"], x["d"])
    np.testing.assert_allclose(base, surface.iridescent_f0(x["f0"], x["c"], x["t"], x["n2"], x["d"]), rtol=0.0,
                               atol=1e-12)
    np.testing.assert_allclose(coat, surface.iridescent_f0(x["cf0"], x["c"], x["t"], x["n2"], x["d"]), rtol=0.0,
                               atol=1e-12)
    base, coat = specular_extension.iridescent_f0_f90_with_coat(x["f0"], x["f90"], x["cf0"], x["cf90"], x["c"],
                                                                x["t"], x["n2"], x["d"])
    np.testing.assert_allclose(coat, specular_extension.iridescent_f0_f90(x["cf0"], x["cf90"], x["c"], x["t"],
                                                                          x["n2"], x["d"]), rtol=0.0, atol=1e-12)
