"""The sheen's environment term (templates/scene_lighting.inc): the lobe's albedo times the
irradiance / pi at the normal, chosen over the GGX-prefiltered radiance along the mirror
direction because it is the closer approximation of the float64 integral of the Charlie lobe
(maths/reference/sheen.py sheen_lobe) over a real environment with a sun (Blender's sunrise,
box-averaged to 128 x 64: each texel held constant, so both approximations and the integral
use one discretisation). Random normals and views, fixed seed."""

import numpy as np
import pytest

from pbrlab.maths.reference import sheen
from sunrise_lobes import LUMINANCE, prefiltered_luminance, random_views, sunrise_texels


def _errors(perceptual_roughness, count=300, seed=1):
    d, solid, radiance = sunrise_texels()
    irradiance_error, mirror_error = [], []
    for n, v, mu in random_views(count, seed, 0.02):
        NdotL = d @ n
        h = d + v
        h /= np.linalg.norm(h, axis=1, keepdims=True)
        f = sheen.sheen_lobe(np.maximum(NdotL, 1e-9), np.full(len(d), mu), np.clip(h @ n, 0, 1), np.ones(3),
                             perceptual_roughness)[..., 0]
        w = np.where(NdotL > 0, f * NdotL * solid, 0.0)
        exact, albedo = (w @ radiance) @ LUMINANCE, w.sum()
        cosine = np.where(NdotL > 0, NdotL * solid, 0.0)
        irradiance = (cosine @ radiance) / cosine.sum() @ LUMINANCE
        mirror = prefiltered_luminance(d, solid, radiance, 2 * mu * n - v, perceptual_roughness ** 2)
        irradiance_error.append(abs(albedo * irradiance - exact) / exact)
        mirror_error.append(abs(albedo * mirror - exact) / exact)
    return np.array(irradiance_error), np.array(mirror_error)


@pytest.mark.parametrize("perceptual_roughness", [0.5, 0.8, 1.0])
def test_the_irradiance_is_the_closer_sheen_environment(perceptual_roughness):
    irradiance, mirror = _errors(perceptual_roughness)
    assert np.median(irradiance) < 0.5 * np.median(mirror), (np.median(irradiance), np.median(mirror))
    assert np.percentile(irradiance, 90) < np.percentile(mirror, 90)
