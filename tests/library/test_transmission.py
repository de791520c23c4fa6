"""Light through a surface (pbr/brdf/btdf_walter.glsl, pbr/shading/transmission.glsl)
against the float64 references of reference/transmission.py, and those references against
physics they must obey: a nearly smooth interface transmits 1 - F of what meets it (Walter
et al. 2007's radiance convention), the rough one never more than that, an index-matched
thin wall passes light straight through, and Beer-Lambert multiplies over distance."""

import numpy as np
import pytest

from library_helpers import as_f32, assert_close, evaluate, seeded_rng, unit_vectors, vec3
from pbrlab.maths.reference import brdf, shading, transmission

INCLUDES = ["pbr/shading/transmission.glsl"]
N = np.array([0.0, 0.0, 1.0])


def _below(rng, count):
    """Light directions below the surface (n.l <= -1e-3)."""
    l = unit_vectors(rng, count, min_z=1e-3)
    return as_f32(l * np.array([1.0, 1.0, -1.0]))


def _transmitted_fraction(theta_v, alpha, eta, samples=1500):
    """eta² ∫ ft(l -> v) |n.l| dl over the lower hemisphere (midpoint rule in |cos|, phi):
    the fraction of uniform light from below that reaches v, in units of the smooth limit."""
    mu = (np.arange(samples) + 0.5) / samples
    phi = (np.arange(2 * samples) + 0.5) / (2 * samples) * 2 * np.pi
    m, p = np.meshgrid(mu, phi, indexing="ij")
    s = np.sqrt(1.0 - m * m)
    l = np.stack([s * np.cos(p), s * np.sin(p), -m], -1)
    v = np.broadcast_to([np.sin(theta_v), 0.0, np.cos(theta_v)], l.shape)
    ft = transmission.btdf_walter_ggx(np.broadcast_to(N, l.shape), v, l, alpha, np.full(m.shape, eta))
    return eta ** 2 * float((ft * m).sum()) / samples * (2 * np.pi / (2 * samples))


@pytest.mark.parametrize("eta", [1.5, 1.33, 1.0 / 1.5])
def test_walter_btdf_of_a_nearly_smooth_interface_transmits_one_minus_fresnel(eta):
    """Walter 2007 eq. 21 integrated: at alpha 0.05 and a 46 degree view, eta² ∫ ft |n.l|
    is the smooth interface's 1 - F(n.v) (eta 1/1.5 at 46 degrees is past the critical
    angle, F = 1: nothing). Measured: 1.5: 0.4214 vs 0.4217, 1.33: 0.5490 vs 0.5493,
    1/1.5: 0.35 of the quadrature's rough tail; bound 2e-3 absolute (the midpoint rule over a
    lobe 0.05 wide) and, past the critical angle, < 0.4 (the rough lobe still refracts some)."""
    theta = 0.8
    got = _transmitted_fraction(theta, 0.05, eta)
    smooth = 1.0 - float(brdf.F_Dielectric(np.cos(theta), eta))
    if smooth > 0.0:
        assert got == pytest.approx(smooth, abs=2e-3)
    else:
        assert got < 0.4


@pytest.mark.parametrize("alpha", [0.1, 0.3, 0.6, 1.0])
def test_walter_btdf_never_transmits_more_than_arrives(alpha):
    """Single scattering loses light to masking, never gains it: eta² ∫ ft |n.l| <= 1 at
    every view and roughness (worst measured 0.97 at alpha 0.1, grazing view)."""
    for theta in (0.0, 0.6, 1.2, 1.5):
        assert _transmitted_fraction(theta, alpha, 1.5, samples=600) <= 1.0


def _half_vectors(v, l, eta):
    """Walter 2007 eq. 16's h_t, on the normal's side (z up)."""
    h = -(np.asarray(eta, np.float64)[:, None] * l + v)
    h /= np.linalg.norm(h, axis=-1, keepdims=True)
    return np.where(h[:, 2:] < 0.0, -h, h)


def test_dielectric_transmittance_is_one_minus_fresnel_without_the_cancellation():
    """pbr_T_Dielectric against 1 - F of the float64 Fresnel (Born & Wolf), relative, also
    where F -> 1 (near the critical angle and at grazing, where 1 - pbr_F_Dielectric in
    float32 loses digits): bound 1e-5 + 4 eps c² / g² (the condition number of T in c, g =
    eta cos(theta_t), times the rounding of c itself)."""
    c, eta = np.meshgrid(as_f32(np.linspace(0.0, 1.0, 513)), as_f32(np.concatenate(
        [np.linspace(1 / 2.5, 1.0, 65), np.linspace(1.0, 2.5, 65)])), indexing="ij")
    c, eta = c.ravel(), eta.ravel()
    got = evaluate("pbr_T_Dielectric(c, eta)", INCLUDES, c=c, eta=eta)
    ref = 1.0 - brdf.F_Dielectric(c.astype(np.float64), eta.astype(np.float64))
    ref = np.where(eta == 1.0, 1.0, ref)  # c = 0, eta = 1: 0/0, decided 1 (no interface)
    g2 = np.maximum(eta.astype(np.float64) ** 2 - 1.0 + c.astype(np.float64) ** 2, 1e-30)
    assert_close("pbr_T_Dielectric", got, ref, rtol=1e-5 + 4 * 2.0 ** -23 * c * c / g2, atol=1e-7)
    assert np.all((got >= 0.0) & (got <= 1.0))


def test_walter_btdf_matches_reference():
    rng = seeded_rng("walter btdf")
    count = 4096
    v = unit_vectors(rng, count, min_z=1e-2)
    l = _below(rng, count)
    alpha = as_f32(rng.uniform(0.02, 1.0, count))
    eta = as_f32(np.where(rng.uniform(size=count) < 0.5, rng.uniform(1.0, 2.5, count), 1.0 / rng.uniform(1.0, 2.5, count)))
    got = evaluate("pbr_BTDF_Walter_GGX_cosine(vec3(0.0, 0.0, 1.0), v, l, alpha, eta)", INCLUDES,
                   v=vec3(v), l=vec3(l), alpha=alpha, eta=eta)
    ref = transmission.btdf_walter_ggx(np.broadcast_to(N, v.shape), v, l, alpha, eta) * -l[:, 2]
    # float32 of a product of D (peaks 1/(pi alpha²) ~ 800), G, 1 - F and a ratio of cosines:
    # a few ulp each, D's sensitivity near its peak, and 1 - F's near the critical angle
    # (T ~ g = eta cos(theta_t) -> 0, so dT/T = c dc / g²: the float32 error of v.h, 4 ulp,
    # times that condition number); bound 1e-4 + 4 eps c² / g² relative
    c = np.abs(np.sum(v * _half_vectors(v, l, eta), axis=-1))
    g2 = np.maximum(eta.astype(np.float64) ** 2 - 1.0 + c * c, 1e-30)
    assert_close("pbr_BTDF_Walter_GGX_cosine", got, ref, rtol=1e-4 + 4 * 2.0 ** -23 * c * c / g2, atol=1e-7)
    assert (ref > 0).mean() > 0.25  # 30 % of random pairs refract (measured): the test sees the lobe, not only zeros


def test_walter_btdf_is_zero_where_nothing_refracts():
    """A light above the surface, a view below it, and the index-matched straight line
    (eta 1, l = -v: a Dirac, decided 0) give exactly 0."""
    v = np.array([[0.6, 0.0, 0.8], [0.6, 0.0, -0.8], [0.6, 0.0, 0.8]])
    l = np.array([[0.0, 0.6, 0.8], [0.0, 0.0, 1.0], [-0.6, 0.0, -0.8]])
    got = evaluate("pbr_BTDF_Walter_GGX(vec3(0.0, 0.0, 1.0), v, l, 0.3, eta)", INCLUDES,
                   v=vec3(as_f32(v)), l=vec3(as_f32(l)), eta=as_f32(np.array([1.5, 1.5, 1.0])))
    assert np.all(got == 0.0)


def test_transmission_punctual_matches_reference():
    rng = seeded_rng("transmission punctual")
    count = 2048
    v = unit_vectors(rng, count, min_z=1e-2)
    l = _below(rng, count)
    light, base = (as_f32(rng.uniform(0, 2, (count, 3))) for _ in range(2))
    r = as_f32(rng.uniform(0, 1, count))
    got = evaluate("pbr_transmission_punctual(vec3(0.0, 0.0, 1.0), v, l, light, base, r, 1.5)", INCLUDES,
                   v=vec3(v), l=vec3(l), light=vec3(light), base=vec3(base), r=r)
    rc = shading.clamp_perceptual_roughness(r)
    ref = transmission.transmission_walter_punctual(np.broadcast_to(N, v.shape), v, l, light * base,
                                                    rc * rc, np.full(count, 1.5))
    assert_close("pbr_transmission_punctual", got[:, :3], ref, rtol=1e-4, atol=1e-6)


def test_thin_wall_punctual_matches_reference_and_peaks_straight_through():
    rng = seeded_rng("thin transmission")
    count = 2048
    v = unit_vectors(rng, count, min_z=1e-2)
    l = as_f32(np.concatenate([_below(rng, count // 2), unit_vectors(rng, count // 2, min_z=1e-3)]))
    base = as_f32(rng.uniform(0, 1, (count, 3)))
    r = as_f32(rng.uniform(0, 1, count))
    got = evaluate("pbr_transmission_thin_punctual(vec3(0.0, 0.0, 1.0), v, l, vec3(1.0), base, r)", INCLUDES,
                   v=vec3(v), l=vec3(l), base=vec3(base), r=r)
    rc = shading.clamp_perceptual_roughness(r)
    ref = transmission.transmission_thin_punctual(np.broadcast_to(N, v.shape), v, l, np.ones(3), base, rc * rc)
    assert_close("pbr_transmission_thin_punctual", got[:, :3], ref, rtol=1e-4, atol=1e-6)
    assert np.all(got[count // 2:, :3] == 0.0)  # a light above a thin wall transmits nothing to v
    # the lobe of a rough thin wall is largest straight through (l = -v), not at the mirror
    view = np.array([0.6, 0.0, 0.8])
    lights = as_f32(np.array([-view, [0.6, 0.0, -0.8], [0.0, 0.6, -0.8]]))
    lobe = evaluate("pbr_transmission_thin_punctual(vec3(0.0, 0.0, 1.0), v, l, vec3(1.0), vec3(1.0), 0.5)",
                    INCLUDES, v=vec3(as_f32(np.broadcast_to(view, (3, 3)))), l=vec3(lights))
    assert lobe[0, 0] > lobe[1, 0] and lobe[0, 0] > lobe[2, 0]


def test_volume_attenuation_is_beer_lambert():
    d = as_f32(np.array([0.0, 0.5, 1.0, 2.0, 1.0, 0.0, 3.0]))
    big = np.float32(np.finfo(np.float32).max)
    dist = as_f32(np.array([1.0, 1.0, 1.0, 1.0, np.inf, 0.5, 2.0]))
    colours = as_f32(np.array([[0.5, 0.0, 1.0]] * 6 + [[0.2, 0.7, 0.0]]))
    got = evaluate("pbr_volume_attenuation(d, c, D)", INCLUDES, d=d, c=vec3(colours), D=dist)
    ref = transmission.volume_attenuation(d, colours, dist)
    assert_close("pbr_volume_attenuation", got[:, :3], ref, rtol=4e-6, atol=0.0)
    assert got[1, 0] == pytest.approx(np.sqrt(0.5), rel=4e-6) and got[3, 0] == pytest.approx(0.25, rel=4e-6)
    assert np.all(got[0, :3] == 1.0) and np.all(got[5, :3] == 1.0)  # d = 0: nothing absorbed, even by black
    assert got[1, 1] == 0.0 and got[4, 1] == 1.0  # black absorbs all over d > 0; D = Inf absorbs nothing
    assert np.isfinite(got[:, :3]).all() and big > 0
    # T(a) T(b) = T(a + b): attenuation multiplies along a path (float64 reference)
    ab = transmission.volume_attenuation(np.array([0.3]), colours[:1], np.array([0.7]))
    ab = ab * transmission.volume_attenuation(np.array([0.9]), colours[:1], np.array([0.7]))
    whole = transmission.volume_attenuation(np.array([1.2]), colours[:1], np.array([0.7]))
    np.testing.assert_allclose(ab[:, [0, 2]], whole[:, [0, 2]], rtol=1e-14)


def test_refraction_direction_obeys_snell():
    rng = seeded_rng("refraction")
    v = unit_vectors(rng, 1024, min_z=1e-2)
    eta = as_f32(rng.uniform(1.0, 2.5, 1024))
    got = evaluate("pbr_refraction_direction(vec3(0.0, 0.0, 1.0), v, eta)", INCLUDES, v=vec3(v), eta=eta)[:, :3]
    ref = transmission.refraction_direction(np.broadcast_to(N, v.shape), v, eta)
    assert_close("pbr_refraction_direction", got, ref, rtol=1e-5, atol=1e-6)
    sin_i = np.linalg.norm(v[:, :2], axis=-1)
    sin_t = np.linalg.norm(ref[:, :2], axis=-1)
    np.testing.assert_allclose(sin_t * eta, sin_i, atol=1e-12)  # Snell: sin_i = eta sin_t
