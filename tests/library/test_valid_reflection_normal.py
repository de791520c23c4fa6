"""pbr/shading/valid_reflection_normal.glsl against its float64 reference
(harness/pbrlab/maths/reference/valid_reflection_normal.py: Keller et al. 2017, Cycles'
ensure_valid_specular_reflection), over random and grazing views and normal-map tilts to 85°;
the reference's closed form against its bisection; the unbent normal as the control.
"""

import numpy as np

from library_helpers import F32_EPS, as_f32, evaluate, seeded_rng, unit_vectors, vec3
from pbrlab.maths.reference import valid_reflection_normal as ref

INCLUDE = ("pbr/shading/valid_reflection_normal.glsl",)
COUNT = 4000


def _perpendicular(a):
    helper = np.where(np.abs(a[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    t = np.cross(helper, a)
    return t / np.linalg.norm(t, axis=-1, keepdims=True)


def _cases(purpose: str):
    """(n, ng, v) float32: random geometric normals; views at random elevations (half of them
    grazing, v.ng from 1e-5 to 0.1); shading normals tilted up to 85° from ng."""
    rng = seeded_rng(purpose)
    ng = unit_vectors(rng, COUNT).astype(np.float64)
    t1 = _perpendicular(ng)
    t2 = np.cross(ng, t1)
    mu = np.concatenate([rng.uniform(0.0, 1.0, COUNT // 2), 10.0 ** rng.uniform(-5, -1, COUNT - COUNT // 2)])
    phi = rng.uniform(0.0, 2.0 * np.pi, COUNT)
    v = np.sqrt(1 - mu * mu)[:, None] * (np.cos(phi)[:, None] * t1 + np.sin(phi)[:, None] * t2) + mu[:, None] * ng
    tilt = rng.uniform(0.0, np.radians(85.0), COUNT)
    psi = rng.uniform(0.0, 2.0 * np.pi, COUNT)
    n = np.sin(tilt)[:, None] * (np.cos(psi)[:, None] * t1 + np.sin(psi)[:, None] * t2) + np.cos(tilt)[:, None] * ng
    return as_f32(n), as_f32(ng), as_f32(v)


def _sensitivity(n, ng, v, h=1e-7):
    """|dn'/ds| of the float64 reference for a change s of the view's components along ng and
    along n's tangent direction (the two scalars v.ng and v.x the solve starts from): central
    and one-sided differences, the largest (n' has a kink where it starts to bend)."""
    x = ref._frame(n, ng)
    base = ref.valid_reflection_normal(n, ng, v)
    worst = np.zeros(len(n))
    for axis in (ng, x):
        for step in (h, -h):
            moved = ref.valid_reflection_normal(n, ng, v + step * axis)
            worst = np.maximum(worst, np.linalg.norm(moved - base, axis=-1) / h)
    return worst


def _discriminant_error(n, ng, v, eps):
    """|n' error| from the discriminant's rounding, in a precision of unit roundoff eps.
    b^2 - 4ac cancels as the two roots meet (v.x -> 0, where they are equal): computed, it is
    off by up to 4 eps b^2 absolute (each square and the product rounded, then the
    difference), so its square root by min(4 eps b^2 / (2 root), sqrt(4 eps b^2)), which
    moves w and u and through them n' = sqrt(u) x + sqrt(w) ng (the derivatives of the forms
    the GLSL uses: vx < 0: dw = droot / 4a, du = -u droot / (B + root); else dw = -w droot /
    (b + root), du = droot / 4a; d sqrt(w) = dw / 2 sqrt(w))."""
    x = ref._frame(n, ng)
    vz = np.maximum(np.sum(v * ng, -1), 0.0)
    vx = np.sum(v * x, -1)
    t = ref.threshold(vz)
    a = vx * vx + vz * vz
    b = 2.0 * (a + vz * t)
    big_b = 2.0 * (a - vz * t)
    root = np.sqrt(np.maximum(b * b - 4.0 * a * (vz + t) ** 2, 0.0))
    d_disc = 4.0 * eps * b * b
    d_root = np.minimum(d_disc / np.maximum(2.0 * root, 1e-300), np.sqrt(d_disc))
    w = np.where(vx < 0, (b + root) / (4.0 * a), (vz + t) ** 2 / (b + root))
    u = np.where(vx < 0, (vz - t) ** 2 / (big_b + root), (big_b + root) / (4.0 * a))
    dw = np.where(vx < 0, 1.0 / (4.0 * a), w / (b + root)) * d_root
    du = np.where(vx < 0, u / (big_b + root), 1.0 / (4.0 * a)) * d_root
    return np.hypot(dw / (2.0 * np.sqrt(np.maximum(w, 1e-300))), du / (2.0 * np.sqrt(np.maximum(u, 1e-300))))


def test_matches_reference_over_random_and_grazing_views():
    n, ng, v = _cases("valid reflection normal")
    n64, ng64, v64 = (a.astype(np.float64) for a in (n, ng, v))
    got = evaluate("pbr_valid_reflection_normal(n, ng, v)", INCLUDE, n=vec3(n), ng=vec3(ng), v=vec3(v))
    want = ref.valid_reflection_normal(n64, ng64, v64)
    assert np.isfinite(got).all()
    bent = np.linalg.norm(want - n64, axis=-1) > 0
    assert 0.3 < bent.mean() < 0.7  # both sides of the condition are exercised
    # Derived bound (float32 conditioning). The solve starts from the dot products v.ng and
    # v.x: each a sum of three products of float32 components with |v| = |ng| = 1 (to the
    # inputs' own rounding), off by at most 3 eps absolute, x by a normalisation's 2 eps more:
    # 8 eps on the two scalars, amplified by the reference's sensitivity to them (measured per
    # sample in float64, _sensitivity). The rest of the chain (a, b, c, the discriminant, the
    # two roots, no subtraction of close values but the discriminant's, whose rounding the
    # sensitivity to the inputs
    # does not carry (_discriminant_error: up to sqrt(eps) where the roots meet), two square
    # roots and the sum of two scaled vectors) is about 24 roundings of well-conditioned
    # values: 24 eps. Where n is returned the result is n exactly.
    bound = (8 * F32_EPS * _sensitivity(n64, ng64, v64) + _discriminant_error(n64, ng64, v64, F32_EPS)
             + 24 * F32_EPS)
    err = np.linalg.norm(got - want, axis=-1)
    over = err > bound
    assert over.mean() == 0.0, (over.sum(), (err / F32_EPS)[over][:5], (bound / F32_EPS)[over][:5])
    assert (got[~bent] == n[~bent]).all()
    # what the bend is for: the reflection about n' stays at the threshold above ng (to the
    # same bound, scaled by the height's Lipschitz constant 4 in n')
    height = ref.reflection_height(got.astype(np.float64), ng64, v64)
    threshold = ref.threshold(np.sum(v64 * ng64, -1))
    assert (height[bent] >= threshold[bent] - 4 * bound[bent]).all()
    # control: the unbent normal is rejected by the same check wherever the bend matters
    unbent_err = np.linalg.norm(n64 - want, axis=-1)
    assert (unbent_err[bent] > bound[bent]).mean() > 0.99
    assert (ref.reflection_height(n64, ng64, v64)[bent] < threshold[bent]).all()


def test_reference_closed_form_matches_bisection():
    # unit to float64 precision (the float32 cases are unit only to ~1e-7, which moves the
    # closed form's frame and the bisection's height apart by as much)
    n, ng, v = (a / np.linalg.norm(a, axis=-1, keepdims=True)
                for a in (b.astype(np.float64) for b in _cases("valid reflection normal, bisection")))
    closed = ref.valid_reflection_normal(n, ng, v)
    # the closed form's float64 discriminant (up to sqrt(eps) where the roots meet) and a few
    # hundred roundings elsewhere; the bisection: 80 halvings of an angle under pi/2 (1e-24 rad)
    # and the height compared to the threshold in float64 (the same floor: 256 eps)
    eps64 = 2.0 ** -53
    bound = _discriminant_error(n, ng, v, eps64) + 256 * eps64 * (1.0 + _sensitivity(n, ng, v, h=1e-6))
    for i in range(0, COUNT, 8):
        solved = ref.valid_reflection_normal_bisection(n[i], ng[i], v[i])
        assert np.linalg.norm(closed[i] - solved) <= bound[i], (i, np.linalg.norm(closed[i] - solved), bound[i])


def test_unchanged_without_normal_map_and_constants_shared():
    rng = seeded_rng("valid reflection normal, flat")
    ng = unit_vectors(rng, 500)
    v = unit_vectors(rng, 500)
    v = np.where(np.sum(v * ng, -1, keepdims=True) < 0, -v, v).astype(np.float32)
    got = evaluate("pbr_valid_reflection_normal(ng, ng, v)", INCLUDE, ng=vec3(ng), v=vec3(v))
    assert (got == ng).all()
    zero = as_f32([0.0])
    for name, value in (("PBR_VALID_REFLECTION_VIEW_SCALE", ref.THRESHOLD_SCALE),
                        ("PBR_VALID_REFLECTION_MAX_HEIGHT", ref.THRESHOLD_MAX)):
        assert evaluate(f"{name} + z", INCLUDE, z=zero)[0] == np.float32(value), name
