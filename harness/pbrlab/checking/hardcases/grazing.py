"""Grazing mirrors: the specular lobe at NdotL = NdotV -> 0 near the mirror direction, where
l + v is short but h is well defined and the lobe is at its largest (issue 25).

``mirror_sample`` draws the inputs (float32, deterministic for a seed): n = +z (so that n·l,
n·v and n × (l + v) are exact in float32 and the check isolates the lobe's own arithmetic),
NdotL = c log-uniform in [C_MIN, C_MAX], v the mirror of l about n turned by at most
``TWIST`` in azimuth and elevation (near the peak of every lobe), perceptual roughness
uniform in [0, 1] (each tier clamps it). ``lobe_errors`` compares a tier's GLSL with its
float64 model (reference.shading.brdf_standard) at the same float32 inputs.

The anisotropic lobe (KHR_materials_anisotropy, pbr/shading/anisotropy.glsl) gets the same
sample plus a tangent t at a uniform angle in the surface's plane, b = n × t, and a strength
uniform in [0, 1] (``anisotropic_sample``); ``anisotropic_lobe_errors`` compares
pbr_brdf_anisotropic_specular with reference.anisotropy.brdf_anisotropic_specular."""

from __future__ import annotations

import numpy as np

from ...gpu import evaluator
from ...maths.reference import anisotropy, shading

C_MIN, C_MAX = 1e-6, 0.05     # the cosines of the sample: from 1e-6 up to about 3° above the horizon
TWIST = 2e-3                  # radians off the exact mirror, azimuth and elevation
DIFFUSE, F0 = (0.5, 0.4, 0.3), (0.04, 0.04, 0.04)
EXPRESSION = f"pbr_brdf_standard(n, v, l, vec3{DIFFUSE}, vec3{F0}, r)"
ANISOTROPIC_EXPRESSION = f"pbr_brdf_anisotropic_specular(n, v, l, t, b, vec3{F0}, r, s)"


def mirror_sample(count: int, seed: int) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    c = np.exp(rng.uniform(np.log(C_MIN), np.log(C_MAX), count))
    azimuth = rng.uniform(0.0, 2.0 * np.pi, count)
    elevation_l = np.arcsin(c)
    elevation_v = np.maximum(elevation_l + rng.uniform(-TWIST, TWIST, count) * np.minimum(1.0, c / TWIST), 0.0)
    azimuth_v = azimuth + np.pi + rng.uniform(-TWIST, TWIST, count)

    def direction(elevation, phi):
        return np.stack([np.cos(elevation) * np.cos(phi), np.cos(elevation) * np.sin(phi), np.sin(elevation)], -1)

    n = np.broadcast_to(np.array([0.0, 0.0, 1.0]), (count, 3))
    return {"n": n.astype(np.float32), "l": direction(elevation_l, azimuth).astype(np.float32),
            "v": direction(elevation_v, azimuth_v).astype(np.float32),
            "r": rng.uniform(0.0, 1.0, count).astype(np.float32)}


def lobe_errors(quality: str, sample: dict, evaluate=evaluator.evaluate) -> dict:
    """Per sample: the GLSL value, the float64 model's, and the relative error of the sum of
    the three channels (the specular lobe dominates it near the mirror)."""
    got = np.asarray(evaluate(EXPRESSION, defines={"PBR_QUALITY": f"PBR_QUALITY_{quality}"},
                              n=evaluator.vec3(sample["n"]), v=evaluator.vec3(sample["v"]),
                              l=evaluator.vec3(sample["l"]), r=sample["r"]), np.float64)
    d = {k: v.astype(np.float64) for k, v in sample.items()}
    want = shading.brdf_standard(d["n"], d["v"], d["l"], np.array(DIFFUSE), np.array(F0), d["r"], quality=quality)
    g, w = got.reshape(len(want), -1).sum(-1), want.sum(-1)
    return {"got": g, "want": w, "rel": np.abs(g - w) / np.abs(w), "finite": np.isfinite(g)}


def anisotropic_sample(count: int, seed: int) -> dict[str, np.ndarray]:
    """``mirror_sample`` plus the anisotropic frame: t at a uniform angle in the plane of n = +z,
    b = n × t (both float32, exactly orthogonal to n), strength s uniform in [0, 1]."""
    out = mirror_sample(count, seed)
    rng = np.random.default_rng(seed + 1)
    angle = rng.uniform(0.0, 2.0 * np.pi, count)
    zero = np.zeros(count)
    out["t"] = np.stack([np.cos(angle), np.sin(angle), zero], -1).astype(np.float32)
    out["b"] = np.stack([-np.sin(angle), np.cos(angle), zero], -1).astype(np.float32)
    out["s"] = rng.uniform(0.0, 1.0, count).astype(np.float32)
    return out


def anisotropic_lobe_errors(quality: str, sample: dict, evaluate=evaluator.evaluate) -> dict:
    """As ``lobe_errors`` for the anisotropic specular lobe (no diffuse: the lobe alone)."""
    got = np.asarray(evaluate(ANISOTROPIC_EXPRESSION, includes=("pbr/shading/anisotropy.glsl",),
                              defines={"PBR_QUALITY": f"PBR_QUALITY_{quality}"},
                              **{k: evaluator.vec3(sample[k]) for k in ("n", "v", "l", "t", "b")},
                              r=sample["r"], s=sample["s"]), np.float64)
    d = {k: v.astype(np.float64) for k, v in sample.items()}
    want = anisotropy.brdf_anisotropic_specular(d["n"], d["v"], d["l"], d["t"], d["b"], np.array(F0), d["r"],
                                                d["s"], quality=quality)
    g, w = got.reshape(len(want), -1).sum(-1), want.sum(-1)
    return {"got": g, "want": w, "rel": np.abs(g - w) / np.abs(w), "finite": np.isfinite(g)}
