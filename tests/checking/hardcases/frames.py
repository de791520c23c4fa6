"""Randomly rotated shading frames for the hard-case tests (issue 35): the grazing-mirror
sample of pbrlab.checking.hardcases.grazing turned by one uniform random rotation per sample,
so that n is no axis and the GLSL rounds n·l and n·v (with n = +z they are exact)."""

import numpy as np

from pbrlab.checking.hardcases import grazing


def rotations(count: int, rng) -> np.ndarray:
    """(count, 3, 3) uniform random rotations: unit quaternions from four normal deviates
    (Shoemake 1992, "Uniform random rotations", Graphics Gems III)."""
    q = rng.normal(size=(count, 4))
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q.T
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], -1),
                     np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], -1),
                     np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1)], -2)


def rotated_mirror_sample(count: int, seed: int) -> dict:
    """grazing.mirror_sample(count, seed) with n, l, v turned (in float64, then rounded to
    float32) by rotations(count, default_rng(seed)); r as drawn."""
    sample = grazing.mirror_sample(count, seed=seed)
    turn = rotations(count, np.random.default_rng(seed))
    out = {k: np.einsum("nij,nj->ni", turn, sample[k].astype(np.float64)).astype(np.float32) for k in ("n", "l", "v")}
    out["r"] = sample["r"]
    return out
