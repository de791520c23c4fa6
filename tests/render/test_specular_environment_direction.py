"""The direction the specular environment is read along (templates/scene_lighting.inc,
pbr/ibl/dominant_direction.glsl): the split sum's prefiltered radiance along the lobe's
dominant direction, chosen over the mirror direction because it is the closer approximation
of the float64 integral of the GGX lobe (D, height-correlated G2, n.l) over a real environment
with a sun (Blender's sunrise, box-averaged to 128 x 64: each texel held constant, so both
approximations and the integral use one discretisation). Both approximations take the same
directional albedo (the integral's own), so only the direction differs. Random normals and
views, fixed seed; roughness from 0.5, where the lobe spans several texels. Measured (median /
90th percentile relative error, dominant against mirror): roughness 0.5 18 / 66 % against
26 / 103 %; 0.7 15 / 57 % against 36 / 186 %; 1.0 8.6 / 29 % against 50 / 354 %."""

import numpy as np
import pytest

from pbrlab.maths.reference import brdf, dominant_direction
from sunrise_lobes import LUMINANCE, prefiltered_luminance, random_views, sunrise_texels


def _errors(perceptual_roughness, count=300, seed=2):
    d, solid, radiance = sunrise_texels()
    alpha = perceptual_roughness ** 2
    dominant_error, mirror_error = [], []
    for n, v, mu in random_views(count, seed, 0.05):
        NdotL = d @ n
        h = d + v
        h /= np.linalg.norm(h, axis=1, keepdims=True)
        f = brdf.D_GGX(np.clip(h @ n, 0, 1), alpha) * brdf.G2_SmithGGXCorrelated(np.maximum(NdotL, 1e-9), mu, alpha) \
            / (4 * np.maximum(NdotL, 1e-9) * mu)
        w = np.where(NdotL > 0, f * NdotL * solid, 0.0)
        exact, albedo = (w @ radiance) @ LUMINANCE, w.sum()
        r = 2 * mu * n - v
        dominant = dominant_direction.specular_dominant_direction(n, r, alpha)
        dominant_error.append(abs(albedo * prefiltered_luminance(d, solid, radiance, dominant, alpha) - exact) / exact)
        mirror_error.append(abs(albedo * prefiltered_luminance(d, solid, radiance, r, alpha) - exact) / exact)
    return np.array(dominant_error), np.array(mirror_error)


@pytest.mark.parametrize("perceptual_roughness", [0.5, 0.7, 1.0])
def test_the_dominant_direction_is_the_closer_read(perceptual_roughness):
    dominant, mirror = _errors(perceptual_roughness)
    assert np.median(dominant) < np.median(mirror)
    assert np.percentile(dominant, 90) < np.percentile(mirror, 90)
