"""Issue 35: every quality tier keeps the lecture's elements at grazing, through the GLSL
evaluator: "everything has Fresnel" (F rises towards 1 as VdotH -> 0), energy conservation
(the white furnace: directional albedo <= 1) and reciprocity (swapping l and v changes
nothing). The samples are test_grazing_mirrors.py's (NdotL = NdotV from 1e-6 to 0.05 near
the mirror, n = +z) and, for reciprocity, the same turned by random rotations (frames.py).

Tolerances (u = 2^-24):
  * Fresnel: the lobe with F0 = 0.04 over the lobe with F0 = 1 (F = 1 in every form, F90 =
    pbr_f90_from_f0 = 1 for both) is the tier's F, the shared π·D·V cancelling: Schlick's
    F = F0 + (1 - F0)(1 - x)^5 >= 1 - 5x (1 - F0) (Bernoulli), x = VdotH = |l + v| / 2 from
    the same float32 vectors in float64; the quotient's float32 error is at most 16u: F's
    seven roundings, two per lobe for π·D·V·F and the 1/π, and VdotH's rounding moving F by at
    most 5 of its own relative u's. At normal incidence (l = v = n) the same quotient is F0
    within 16u. Fails on the LOW tier before issue 35 (F = F0: the quotient is 0.04 at every
    angle) and on PBR_SPECULAR_F_F0 selected explicitly (the control).
  * White furnace: E(v) = ∫ BRDF (n·l) dl with F = 1 (F0 = 1) and no diffuse, by
    pbrlab.maths.reference.directional_albedo.light_quadrature (adapted to the lobe). Its error
    is taken as the change when every node count doubles, checked <= 1e-9 in each case
    (measured worst 5.3e-10, MEDIUM at its roughness floor; 1e-10 for the exact lobe, the
    quadrature's stated accuracy). The float64 model's E <= 1 + 1e-9. The GLSL runs on the
    nodes rounded to float32 and follows the float64 model at those same vectors within 1e-4
    relative (the frame-exact per-sample bound of test_grazing_mirrors.py, summed with positive
    weights); rounding the nodes itself moves the model's E by d32 (measured in the same run, up
    to 1.8e-3 relative at NdotV = 1e-3 and HIGH's floor, where E = 0.92), so E_GLSL <=
    (1 + 1e-9 + d32)(1 + 1e-4). The control: the lecture's implicit Viz_I = 1 (D alone) reflects
    more than it receives (E = 1.5 at the normal view, roughness 0.5).
  * Reciprocity: exact (bit for bit) where n·l and n·v are both at least PBR_MIN_NDOTV: the
    shading model applies the same float32 operations to l and v (l + v and NdotL + n·v
    commute in IEEE arithmetic, h, LdotH and |n × h|² are symmetric), in any frame. Below
    PBR_MIN_NDOTV the NdotV floor (a guard: pbr/common/guards.glsl) is applied to v only:
    measured up to 0.51 relative apart in HIGH and MEDIUM there, in LOW 0 with n = +z and 0.056
    in rotated frames (its lobe reads n·v as it is; recorded, not asserted). The control: the BRDF times NdotL (the cosine folded
    into the BRDF) is not reciprocal."""

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.checking.hardcases import grazing
from pbrlab.maths.reference import directional_albedo, shading

import frames

TIERS = ("HIGH", "MEDIUM", "LOW")
U = 2.0 ** -24
F0 = 0.04
FRESNEL_ROUNDING = 16 * U
QUADRATURE = 1e-9
FRAME_EXACT_REL = 1e-4
N = np.array([0.0, 0.0, 1.0], np.float32)


def _lobe(defines, sample, f0):
    return evaluate(f"pbr_brdf_standard(n, v, l, vec3(0.0), vec3({f0}), r)", defines=defines,
                    n=vec3(sample["n"]), v=vec3(sample["v"]), l=vec3(sample["l"]), r=sample["r"])[:, 0]


def fresnel_of(defines, sample):
    """The tier's F at each sample: the lobe at F0 = 0.04 over the lobe at F0 = 1."""
    return _lobe(defines, sample, F0).astype(np.float64) / _lobe(defines, sample, 1.0)


def fresnel_rises(defines, sample):
    """Whether F >= 1 - 5 VdotH (1 - F0) - 16u at every sample (module docstring)."""
    half = sample["l"].astype(np.float64) + sample["v"]
    x = 0.5 * np.linalg.norm(half, axis=-1)
    return fresnel_of(defines, sample) >= 1.0 - 5.0 * x * (1.0 - F0) - FRESNEL_ROUNDING


@pytest.fixture(scope="module")
def mirrors():
    sample = grazing.mirror_sample(100_000, seed=35)
    # the lobe at F0 = 1 must not underflow to 0: h below the surface has no lobe (χ+)
    return sample


@pytest.mark.parametrize("quality", TIERS)
def test_fresnel_rises_towards_one_at_grazing_in_tier(quality, mirrors):
    defines = shading.glsl_defines(quality=quality)
    F = fresnel_of(defines, mirrors)
    ok = fresnel_rises(defines, mirrors)
    worst = int(np.argmin(F))
    print(f"{quality}: F at the grazing mirrors from {F.min():.6f} (VdotH {mirrors['l'][worst, 2]:.3g}) to {F.max():.6f}")
    assert ok.all(), f"{quality}: {int((~ok).sum())} of {len(F)} samples with F below Schlick's rise; lowest {F[worst]:.4g}"
    normal = {"n": N[None], "v": N[None], "l": N[None], "r": np.array([0.5], np.float32)}
    assert abs(fresnel_of(defines, normal)[0] - F0) <= FRESNEL_ROUNDING  # and starts from F0


def test_fresnel_rise_check_fails_without_a_fresnel_rise(mirrors):
    """The control: F = F0 (PBR_SPECULAR_F_F0, explicit; LOW's default before issue 35)."""
    defines = shading.glsl_defines(quality="LOW", specular_f="F0")
    F = fresnel_of(defines, mirrors)
    assert np.abs(F - F0).max() <= FRESNEL_ROUNDING and not fresnel_rises(defines, mirrors).any()


VIEW_COSINES = (1e-3, 1e-2, 0.05, 0.3, 1.0)
ROUGHNESSES = (0.0, 0.2, 0.5, 1.0)  # perceptual; 0 is each tier's floor


def _furnace_nodes(mu, alpha, doubled=False):
    l, w = directional_albedo.light_quadrature(mu, alpha, *((64, 96) if doubled else (32, 48)))
    v = np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])
    return v, l, w


def _model_albedo(quality, v, l, w, r):
    model = shading.brdf_standard(N.astype(np.float64), v, l, np.zeros(3), np.ones(3), r, quality=quality)[:, 0]
    return float(np.sum(w * model * l[:, 2]))


def furnace(expression, quality, mu, r):
    """E of the GLSL expression on the float32 nodes, and the float64 model's: (E_GLSL, E of
    the model on the float32 nodes, E of the model on the float64 nodes, the quadrature's
    error: that E's change when the node counts double)."""
    alpha = float(shading.clamp_perceptual_roughness(r, quality)) ** 2
    v, l, w = _furnace_nodes(mu, alpha)
    E64 = _model_albedo(quality, v, l, w, r)
    quadrature = abs(_model_albedo(quality, *_furnace_nodes(mu, alpha, doubled=True), r) - E64)
    v32, l32 = v.astype(np.float32), l.astype(np.float32)
    E32 = _model_albedo(quality, v32.astype(np.float64), l32.astype(np.float64), w, r)
    glsl = evaluate(expression, defines=shading.glsl_defines(quality=quality), n=vec3(N[None]),
                    v=vec3(v32[None]), l=vec3(l32), r=np.float32(r))
    glsl = glsl[:, 0] if glsl.ndim == 2 else glsl
    return float(np.sum(w * glsl * l32[:, 2].astype(np.float64))), E32, E64, quadrature


@pytest.mark.parametrize("quality", TIERS)
def test_white_furnace_directional_albedo_at_most_one_in_tier(quality):
    worst = 0.0
    for mu in VIEW_COSINES:
        for r in ROUGHNESSES:
            E, E32, E64, quadrature = furnace("pbr_brdf_standard(n, v, l, vec3(0.0), vec3(1.0), r)", quality, mu, r)
            worst = max(worst, E)
            assert quadrature <= QUADRATURE, (quality, mu, r, quadrature)
            assert E64 <= 1.0 + QUADRATURE, (quality, mu, r, E64)
            assert abs(E - E32) <= FRAME_EXACT_REL * E32, (quality, mu, r, E, E32)
            d32 = abs(E32 - E64) / E64
            assert E <= (1.0 + QUADRATURE + d32) * (1.0 + FRAME_EXACT_REL), (quality, mu, r, E, d32)
    print(f"{quality}: largest directional albedo {worst:.6f}")


def test_white_furnace_check_fails_on_the_lecture_implicit_visibility():
    """The control: D alone (the lecture's Viz_I = 1) reflects more than it receives."""
    expression = "vec3(pbr_D_GGX(clamp(dot(n, normalize(v + l)), 0.0, 1.0), r * r))"
    E = furnace(expression, "HIGH", 1.0, 0.5)[0]
    assert E > 1.5 * (1.0 + QUADRATURE) * (1.0 + FRAME_EXACT_REL), E


def _swap(defines, sample, expression="pbr_brdf_standard(n, a, b, vec3(0.5, 0.4, 0.3), vec3(0.04, 0.5, 0.9), r)"):
    args = {"n": vec3(sample["n"]), "r": sample["r"]}
    forward = evaluate(expression, defines=defines, a=vec3(sample["v"]), b=vec3(sample["l"]), **args)
    backward = evaluate(expression, defines=defines, a=vec3(sample["l"]), b=vec3(sample["v"]), **args)
    n = sample["n"].astype(np.float64)
    above = ((np.sum(n * sample["l"], -1) >= shading.MIN_NDOTV) & (np.sum(n * sample["v"], -1) >= shading.MIN_NDOTV))
    return forward, backward, above


@pytest.fixture(scope="module")
def rotated_mirrors():
    return frames.rotated_mirror_sample(100_000, seed=36)


@pytest.mark.parametrize("quality", TIERS)
@pytest.mark.parametrize("frame", ["axis", "rotated"])
def test_reciprocity_swapping_l_and_v_at_grazing_in_tier(quality, frame, mirrors, rotated_mirrors):
    sample = mirrors if frame == "axis" else rotated_mirrors
    forward, backward, above = _swap(shading.glsl_defines(quality=quality), sample)
    below = np.abs(forward[~above] / backward[~above] - 1.0).max() if (~above).any() else 0.0
    print(f"{quality}, {frame}: {int(above.sum())} samples above PBR_MIN_NDOTV; below it {below:.3g} apart")
    assert above.sum() > len(above) // 3
    differ = (forward[above] != backward[above]).any(-1)
    assert not differ.any(), f"{quality}, {frame}: {int(differ.sum())} of {int(above.sum())} samples not reciprocal"


def test_reciprocity_check_fails_on_a_brdf_with_the_cosine_folded_in(mirrors):
    expression = "pbr_brdf_standard(n, a, b, vec3(0.5, 0.4, 0.3), vec3(0.04), r) * dot(n, b)"
    forward, backward, above = _swap(shading.glsl_defines(quality="LOW"), mirrors, expression)
    assert (forward[above] != backward[above]).any(-1).mean() > 0.5
