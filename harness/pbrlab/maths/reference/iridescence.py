"""Thin-film iridescence references for glsl/pbr/brdf/f_iridescence.glsl.

Two independent float64 references:

(a) ``F_Iridescence`` and friends: the same analytic method as the GLSL (Belcour & Barla 2017
    in the form of KHR_materials_iridescence: Schlick interfaces, two orders of the Airy
    series, the paper's Gaussian fit of the XYZ sensitivity), in float64, to measure the
    GLSL's float32 rounding. Written from the formulas in the GLSL header, in textbook order.

(b) ``spectral_F_Iridescence``: the physics without the method's approximations. Per
    wavelength, the exact reflectance of a dielectric film between two dielectrics (Airy's
    summation, Born & Wolf "Principles of Optics" §7.6.1 eq. 55-58, with the s and p Fresnel
    amplitude coefficients of §1.5.2, complex cosines so that evanescent waves are exact),
    unpolarised (s and p reflectances averaged); integrated over 360-830 nm against the CIE
    1931 2° colour-matching functions in the analytic multi-lobe fit of Wyman, Sloan &
    Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
    JCGT 2(2), eq. 2-4 (σ in nm as tabulated there); illuminant E (equal energy), XYZ
    normalised by ∫ȳ so that a perfect reflector has Y = 1; then linear Rec. 709 by the same
    IEC 61966-2-1 matrix. ``white="E"``: that matrix alone (what the method's AC terms do: a
    perfect reflector is (1.205, 0.948, 0.909)); ``white="balanced"`` (default): each
    channel divided by its value for a perfect reflector (an RGB von Kries balance to the
    Rec. 709 white, which is what the method's DC term assumes: a perfect reflector is 1).
    The base is a dielectric with the IOR the method recovers from F0, channel by channel
    (channel c of the result is channel c of the spectrum computed with base IOR eta3[c]),
    so the two are comparable; for metals neither is the physics.
"""

from __future__ import annotations

import numpy as np

from .brdf import F_Schlick

# Belcour & Barla 2017 §4.2 (shared with PBR_IRIDESCENCE_* in f_iridescence.glsl)
XYZ_VAL = (5.4856e-13, 4.4201e-13, 5.2481e-13)
XYZ_POS = (1.6810e+06, 1.7953e+06, 2.2084e+06)
XYZ_VAR = (4.3278e+09, 9.3046e+09, 6.6121e+09)
X2_VAL, X2_POS, X2_VAR = 9.7470e-14, 2.2399e+06, 4.5282e+09
XYZ_NORM = 1.0685e-7
XYZ_TO_REC709 = ((3.2404542, -1.5371385, -0.4985314),
                 (-0.9692660, 1.8760108, 0.0415560),
                 (0.0556434, -0.2040259, 1.0572252))
MAX_BASE_F0 = 0.9999
MIN_R123 = 0.0
SPEC_MIN_R123 = 1e-5   # the spec's floor (not used by the library, see the GLSL header)
MAX_R123 = 0.9999
FILM_FADE_NM = 0.03
MAX_OPD_NM = 1.0e5
# Measured worst |method - spectral| (see tests/library/test_iridescence.py)
F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL = 0.23               # measured 0.2206
F_IRIDESCENCE_MAX_ABS_ERROR_SPECTRAL_NEAR_NORMAL = 0.045  # cos >= 0.7, measured 0.0434


def _f(x):
    return np.asarray(x, dtype=np.float64)


def _smoothstep(e0, e1, x):
    t = np.clip((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def iridescence_sensitivity(opd_nm, shift):
    """S(OPD, shift) in linear Rec. 709; opd_nm [...], shift [..., 3]."""
    phase = 2.0 * np.pi * 1e-9 * np.clip(_f(opd_nm), 0.0, MAX_OPD_NM)[..., None]
    shift = _f(shift)
    val, pos, var = _f(XYZ_VAL), _f(XYZ_POS), _f(XYZ_VAR)
    xyz = val * np.sqrt(2.0 * np.pi * var) * np.cos(pos * phase + shift) * np.exp(-phase ** 2 * var)
    x2 = (X2_VAL * np.sqrt(2.0 * np.pi * X2_VAR) * np.cos(X2_POS * phase[..., 0] + shift[..., 0])
          * np.exp(-X2_VAR * phase[..., 0] ** 2))
    xyz = np.concatenate([(xyz[..., 0] + x2)[..., None], xyz[..., 1:]], axis=-1) / XYZ_NORM
    return xyz @ _f(XYZ_TO_REC709).T


def ior_from_f0(f0):
    s = np.sqrt(_f(f0))
    return (1.0 + s) / (1.0 - s)


def F_Iridescence(outside_ior, film_ior, cos_theta1, thickness_nm, base_f0, *, min_r123=MIN_R123,
                  saturate=True, fade=True):
    """Method (a) in float64. Scalars broadcast [...]; base_f0 [..., 3]; returns [..., 3].
    ``min_r123=SPEC_MIN_R123, saturate=False`` is the spec's listing (for measurement)."""
    n1, n2_film, c1, d = np.broadcast_arrays(*map(_f, (outside_ior, film_ior, cos_theta1, thickness_nm)))
    base_f0 = _f(base_f0)
    shape = np.broadcast_shapes(n1.shape, base_f0.shape[:-1])
    n1, n2_film, c1, d = (np.broadcast_to(a, shape) for a in (n1, n2_film, c1, d))
    base_f0 = np.broadcast_to(base_f0, shape + (3,))
    c1 = np.clip(c1, 0.0, 1.0)
    n2 = n1 + (n2_film - n1) * (_smoothstep(0.0, FILM_FADE_NM, d) if fade else 1.0)
    cos2_sq = 1.0 - (n1 / n2) ** 2 * (1.0 - c1 ** 2)
    tir = cos2_sq < 0.0
    c2 = np.sqrt(np.maximum(cos2_sq, 0.0))
    R12 = F_Schlick(((n2 - n1) / (n2 + n1)) ** 2, c1)
    T121 = 1.0 - R12
    phi21 = np.where(n2 < n1, 0.0, np.pi)
    f0 = np.clip(base_f0, 0.0, MAX_BASE_F0)
    eta3 = ior_from_f0(f0)
    R23 = F_Schlick(((eta3 - n2[..., None]) / (eta3 + n2[..., None])) ** 2, c2[..., None])
    phi = phi21[..., None] + np.where(eta3 < n2[..., None], np.pi, 0.0)
    opd = 2.0 * n2 * d * c2
    R123 = np.clip(R12[..., None] * R23, min_r123, MAX_R123)
    r123 = np.sqrt(R123)
    Rs = T121[..., None] ** 2 * R23 / (1.0 - R123)
    out = R12[..., None] + Rs
    Cm = Rs - T121[..., None]
    for m in (1, 2):
        Cm = Cm * r123
        out = out + Cm * 2.0 * iridescence_sensitivity(m * opd, m * phi)
    out = np.clip(out, 0.0, 1.0) if saturate else np.maximum(out, 0.0)
    out = np.where(tir[..., None], 1.0, out)
    no_film = ~(d > 0.0)
    return np.where(no_film[..., None], F_Schlick(base_f0, c1[..., None]), out)


def sensitivity_xyz(opd_nm):
    """pbr_iridescence_sensitivity_xyz: the normalised XYZ terms at zero phase shift
    (iridescence_sensitivity before its matrix, shift 0); [..., 3]."""
    phase = 2.0 * np.pi * 1e-9 * np.clip(_f(opd_nm), 0.0, MAX_OPD_NM)[..., None]
    val, pos, var = _f(XYZ_VAL), _f(XYZ_POS), _f(XYZ_VAR)
    xyz = val * np.sqrt(2.0 * np.pi * var) * np.cos(pos * phase) * np.exp(-phase ** 2 * var)
    x2 = X2_VAL * np.sqrt(2.0 * np.pi * X2_VAR) * np.cos(X2_POS * phase[..., 0]) * np.exp(-X2_VAR * phase[..., 0] ** 2)
    return np.concatenate([(xyz[..., 0] + x2)[..., None], xyz[..., 1:]], axis=-1) / XYZ_NORM


def xyz_to_rec709(xyz):
    """pbr_iridescence_xyz_to_rec709: the IEC 61966-2-1 matrix; [..., 3]."""
    return _f(xyz) @ _f(XYZ_TO_REC709).T


def thin_film(outside_ior, film_ior, cos_theta1, thickness_nm):
    """pbr_thin_film: the film's terms that do not read the base, as a dict of arrays (the
    struct's fields): n1, n2, c1, cos2_sq, c2, R12, T121, thickness, xyz1 = S_xyz(OPD) [..., 3],
    S2 = S(2 OPD, 2φ) [..., 3] (cos 2φ = 1 for φ in {0, π, 2π})."""
    n1, n2_film, c1, d = np.broadcast_arrays(*map(_f, (outside_ior, film_ior, cos_theta1, thickness_nm)))
    c1 = np.clip(c1, 0.0, 1.0)
    n2 = n1 + (n2_film - n1) * _smoothstep(0.0, FILM_FADE_NM, d)
    cos2_sq = 1.0 - (n1 / n2) ** 2 * (1.0 - c1 ** 2)
    c2 = np.sqrt(np.maximum(cos2_sq, 0.0))
    R12 = F_Schlick(((n2 - n1) / (n2 + n1)) ** 2, c1)
    opd = 2.0 * n2 * d * c2
    return {"n1": n1, "n2": n2, "c1": c1, "cos2_sq": cos2_sq, "c2": c2, "R12": R12, "T121": 1.0 - R12,
            "thickness": d, "xyz1": sensitivity_xyz(opd), "S2": xyz_to_rec709(sensitivity_xyz(2.0 * opd))}


def F_Iridescence_thin_film(film, base_f0):
    """pbr_F_Iridescence_thin_film: F_Iridescence of base_f0 [..., 3] under ``thin_film``'s
    terms, the phase shift φ = φ21 + φ23 applied as the sign cos φ = ±1 of each channel's
    XYZ terms (cos(x + φ) = cos φ cos x for φ in {0, π, 2π}). The same method as
    F_Iridescence: equal to it in float64 to rounding (tests/library/test_iridescence.py)."""
    n1, n2, c2, R12, T121 = (film[k][..., None] for k in ("n1", "n2", "c2", "R12", "T121"))
    base_f0 = _f(base_f0)
    eta3 = ior_from_f0(np.clip(base_f0, 0.0, MAX_BASE_F0))
    cos_phi = np.where((eta3 < n2) != ~(n2 < n1), -1.0, 1.0)
    S1 = xyz_to_rec709(cos_phi * film["xyz1"])
    R23 = F_Schlick(((eta3 - n2) / (eta3 + n2)) ** 2, c2)
    R123 = np.clip(R12 * R23, MIN_R123, MAX_R123)
    r123 = np.sqrt(R123)
    Rs = T121 ** 2 * R23 / (1.0 - R123)
    C1 = (Rs - T121) * r123
    I = R12 + Rs + C1 * 2.0 * S1 + C1 * r123 * 2.0 * film["S2"]
    out = np.where((film["cos2_sq"] < 0.0)[..., None], 1.0, np.clip(I, 0.0, 1.0))
    no_film = ~(film["thickness"] > 0.0)
    return np.where(no_film[..., None], F_Schlick(base_f0, film["c1"][..., None]), out)


def iridescence_mix(F, F_iridescence, factor):
    t = np.clip(_f(factor), 0.0, 1.0)[..., None]
    return _f(F) + (_f(F_iridescence) - _f(F)) * t


def iridescence_thickness(thickness_min, thickness_max, texture_g):
    g = np.clip(_f(texture_g), 0.0, 1.0)
    return _f(thickness_min) + (_f(thickness_max) - _f(thickness_min)) * g


# ---- (b) the spectral reference --------------------------------------------------------

# Wyman, Sloan & Shirley 2013, multi-lobe fit of CIE 1931 2° (weight, μ, σ below μ, σ above), nm
_WYMAN_X = ((1.056, 599.8, 37.9, 31.0), (0.362, 442.0, 16.0, 26.7), (-0.065, 501.1, 20.4, 26.2))
_WYMAN_Y = ((0.821, 568.8, 46.9, 40.5), (0.286, 530.9, 16.3, 31.1))
_WYMAN_Z = ((1.217, 437.0, 11.8, 36.0), (0.681, 459.0, 26.0, 13.8))
WAVELENGTHS_NM = np.linspace(360.0, 830.0, 236)   # 2 nm steps: the fringes of a 1200 nm film
# of IOR 2 are λ²/OPD >= 27 nm apart (360 nm, normal view); halving the step moves the
# result by < 2e-7 (measured)


def cie_xyz_wyman(lam_nm):
    """x̄, ȳ, z̄ at lam_nm [...] -> [..., 3]."""
    lam = _f(lam_nm)

    def lobes(spec):
        total = np.zeros_like(lam)
        for w, mu, s_lo, s_hi in spec:
            s = np.where(lam < mu, s_lo, s_hi)
            total = total + w * np.exp(-0.5 * ((lam - mu) / s) ** 2)
        return total

    return np.stack([lobes(_WYMAN_X), lobes(_WYMAN_Y), lobes(_WYMAN_Z)], axis=-1)


def _fresnel_amplitudes(n_i, cos_i, n_t, cos_t):
    """s and p amplitude reflection coefficients (Born & Wolf §1.5.2), complex cosines."""
    rs = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t)
    rp = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t)
    return rs, rp


def airy_reflectance(n1, n2, n3, cos_theta1, thickness_nm, lam_nm):
    """Unpolarised reflectance of a film (n2, thickness) between n1 and n3 (all real),
    exact Airy summation; broadcasts; lam_nm on the last axis."""
    n1, n2, n3, c1, d, lam = np.broadcast_arrays(*(_f(x) for x in (n1, n2, n3, cos_theta1, thickness_nm, lam_nm)))
    sin1_sq = 1.0 - c1 ** 2
    c2 = np.sqrt((1.0 - (n1 / n2) ** 2 * sin1_sq).astype(complex))
    c3 = np.sqrt((1.0 - (n1 / n3) ** 2 * sin1_sq).astype(complex))
    # evanescent waves decay into the medium: Im(n cos) >= 0 with exp(+2iδ) below
    c2 = np.where(c2.imag < 0, -c2, c2)
    c3 = np.where(c3.imag < 0, -c3, c3)
    delta = 2.0 * np.pi * n2 * d * c2 / lam
    e = np.exp(2j * delta)
    out = 0.0
    for r12, r23 in zip(_fresnel_amplitudes(n1, c1, n2, c2), _fresnel_amplitudes(n2, c2, n3, c3)):
        r = (r12 + r23 * e) / (1.0 + r12 * r23 * e)
        out = out + 0.5 * np.abs(r) ** 2
    return out


def _integrate(values, lam):
    """Trapezoid over the last axis."""
    dl = np.diff(lam)
    return np.sum(0.5 * (values[..., 1:] + values[..., :-1]) * dl, axis=-1)


def spectral_F_Iridescence(outside_ior, film_ior, cos_theta1, thickness_nm, base_f0, *, white="balanced"):
    """Reference (b): [...] scalars, base_f0 [..., 3] -> linear Rec. 709 [..., 3] (module doc)."""
    lam = WAVELENGTHS_NM
    cmf = cie_xyz_wyman(lam)                          # [L, 3]
    norm = _integrate(cmf[:, 1], lam)                 # ∫ ȳ (illuminant E)
    n1, n2, c1, d = (np.asarray(_f(x))[..., None] for x in (outside_ior, film_ior, cos_theta1, thickness_nm))
    c1 = np.clip(c1, 0.0, 1.0)
    eta3 = ior_from_f0(np.clip(_f(base_f0), 0.0, MAX_BASE_F0))
    M = _f(XYZ_TO_REC709)
    white_rgb = M @ (_integrate(cmf.T, lam) / norm)
    if white not in ("balanced", "E"):
        raise ValueError(f"white must be 'balanced' or 'E', not {white!r}")

    def rgb_of(eta):
        R = airy_reflectance(n1, n2, eta, c1, d, lam)   # [..., L]
        xyz = np.stack([_integrate(R * cmf[:, k], lam) for k in range(3)], axis=-1) / norm
        rgb = xyz @ M.T
        return rgb / white_rgb if white == "balanced" else rgb

    if np.all(eta3 == eta3[..., :1]):  # grey base: one spectrum serves every channel
        return rgb_of(eta3[..., :1])
    return np.stack([rgb_of(eta3[..., c:c + 1])[..., c] for c in range(3)], axis=-1)
