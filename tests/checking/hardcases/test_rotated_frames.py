"""Issue 35: each tier's stated error bound holds in any shading frame. The grazing-mirror
sample of test_grazing_mirrors.py (10^6 samples, NdotL = NdotV from 1e-6 to 0.05 near the
mirror, perceptual roughness uniform in [0, 1]) turned by a random rotation per sample, so n
is no axis and n·l, n·v are rounded in float32; each tier's GLSL against its own float64
model at the same float32 vectors (pbrlab.checking.hardcases.grazing.lobe_errors).

The bound, per sample, is the tier's frame-exact bound plus what the rounding of the two
cosines propagates (u = 2^-24; the float64 model sees the exact dot products of the same
vectors, the GLSL |fl(n·x) - n·x| <= 3u for unit vectors, Higham's gamma_3):
  * V: each tier's V (0.5 / (NdotL + NdotV) in LOW, the Smith lambdas' sum in HIGH and
    MEDIUM) moves by at most 2 ΔNdotX / NdotX relative per cosine: 6u (1/NdotL + 1/NdotV).
  * D (every tier's |n × h|² form since issue 35): rounding n·(l + v) by e <= 6u moves the
    rejection (l + v) - n n·(l + v) along n only, orthogonal to itself, so |n × h|² / |h|²
    grows by e² / |l + v|² <= 36u² / (NdotL + NdotV)² (|l + v| >= n·(l + v)); the denominator
    alpha² + (1 - alpha²) sin² is >= alpha², so D falls by at most 2 · 36u² / ((NdotL +
    NdotV)² alpha²).
  * F, h's own components and the lobe's arithmetic: the frame-exact bound 1e-4 (n = +z,
    test_grazing_mirrors.py, measured 9.9e-7 in every tier).
So rel <= 1e-4 + 6u (1/NdotL + 1/max(NdotV, PBR_MIN_NDOTV)) + 72u² / ((NdotL + NdotV)² alpha²).
Measured (seed 35): worst rel / bound 0.28 in HIGH and MEDIUM, 0.14 in LOW, none over. The
frame-exact bounds alone do not hold here: HIGH's worst relative error is 0.030, LOW's 0.054,
against 1e-4 (the conditioning of the float32 cosines, shared by every tier; another draw of
rotations gave 0.19 and 0.069, at NdotL = 1.1e-5).

The control: the former LOW lobe (issue 25's cancelling 1 - NdotH² (1 - alpha²), which the
tier used until issue 35: former_low_lobe.glsl) is first-order in the cosines' rounding
(NdotH² off by about 6u / c absolute, over a denominator >= alpha²): the same bound fails on
7.5 % of the samples, worst 304 relative (another draw: 9.3e4); with n = +z it held 4.4e-3.
The test asks for more than 0.1 % over and a worst above 1."""

import numpy as np
import pytest
from pathlib import Path

from pbrlab import evaluate, vec3
from pbrlab.checking.hardcases import grazing
from pbrlab.maths.reference import shading

import frames

SAMPLES = 10 ** 6
U = 2.0 ** -24
FRAME_EXACT_REL = 1e-4  # test_grazing_mirrors.REL: every tier since issue 35


@pytest.fixture(scope="module")
def rotated():
    return frames.rotated_mirror_sample(SAMPLES, seed=35)


def rounding_bound(sample, quality):
    """The per-sample relative bound of the module docstring."""
    n, l, v = (sample[k].astype(np.float64) for k in ("n", "l", "v"))
    NdotL, nDotV = np.sum(n * l, -1), np.sum(n * v, -1)
    alpha = shading.clamp_perceptual_roughness(sample["r"], quality) ** 2
    return (FRAME_EXACT_REL + 6 * U * (1 / NdotL + 1 / np.maximum(nDotV, shading.MIN_NDOTV))
            + 72 * U * U / ((NdotL + nDotV) ** 2 * alpha ** 2))


def test_rotated_sample_turns_the_normal_off_every_axis(rotated):
    n = rotated["n"].astype(np.float64)
    assert np.abs(n).max(-1).min() < 0.6 and (np.abs(n).max(-1) < 0.999).mean() > 0.99
    c = np.sum(n * rotated["l"], -1)
    assert c.min() < 2e-6 and c.max() > 0.04  # still the grazing cosines of the sample


@pytest.mark.parametrize("quality", ["HIGH", "MEDIUM", "LOW"])
def test_tier_follows_its_float64_model_in_rotated_frames(quality, rotated):
    result = grazing.lobe_errors(quality, rotated)
    assert result["finite"].all()
    bound = rounding_bound(rotated, quality)
    ratio = result["rel"] / bound
    worst = int(np.argmax(ratio))
    print(f"{quality}: worst relative error {result['rel'].max():.3g}, worst rel / bound {ratio[worst]:.3g}")
    assert ratio[worst] <= 1.0, (
        f"{quality}: {int((ratio > 1).sum())} of {SAMPLES} over the bound; worst: GLSL {result['got'][worst]:.6g}, "
        f"float64 {result['want'][worst]:.6g} (bound {bound[worst]:.3g}) at n = {rotated['n'][worst].tolist()}, "
        f"l = {rotated['l'][worst].tolist()}, v = {rotated['v'][worst].tolist()}, r = {float(rotated['r'][worst]):.4g}")


def test_former_cancelling_low_lobe_fails_the_rotated_frame_bound(rotated):
    """The control: the bound catches the form issue 35 replaced (module docstring)."""
    got = evaluate("former_low_lobe(n, v, l, r)", includes=("former_low_lobe.glsl",),
                   include_dirs=(Path(__file__).parent,),
                   **{k: vec3(rotated[k]) for k in ("n", "l", "v")}, r=rotated["r"]).astype(np.float64)
    d = {k: rotated[k].astype(np.float64) for k in ("n", "l", "v", "r")}
    want = shading.brdf_standard(d["n"], d["v"], d["l"], np.zeros(3), np.ones(3), d["r"], quality="LOW",
                                 specular_f="NONE")[:, 0]
    rel = np.abs(got - want) / want
    over = rel > rounding_bound(rotated, "LOW")
    print(f"former LOW lobe: worst {rel.max():.3g}, {over.mean():.2%} over the bound")
    assert over.mean() > 1e-3 and rel.max() > 1.0
