"""The sheen's environment term (templates/scene_lighting.inc): the lobe's albedo times the
irradiance / pi at the normal, chosen over the GGX-prefiltered radiance along the mirror
direction because it is the closer approximation of the float64 integral of the Charlie lobe
(maths/reference/sheen.py sheen_lobe) over a real environment with a sun (Blender's sunrise,
box-averaged to 128 x 64: each texel held constant, so both approximations and the integral
use one discretisation). Random normals and views, fixed seed."""

import numpy as np
import pytest

from pbrlab.foundation import images
from pbrlab.foundation.locations import locate
from pbrlab.gpu import ibl
from pbrlab.maths.reference import prefilter, sheen

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])


def _errors(perceptual_roughness, count=300, seed=1):
    image = images.read_image(locate("scenes") / "assets" / "environments" / "sunrise_256.exr")[..., :3]
    source = ibl.box_average(image.astype(np.float64), 128)
    d, solid = prefilter.equirect_texels(*source.shape[:2])
    d, solid, radiance = d.reshape(-1, 3), solid.reshape(-1), source.reshape(-1, 3)
    rng = np.random.default_rng(seed)
    irradiance_error, mirror_error = [], []
    for _ in range(count):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        t = rng.normal(size=3)
        t -= n * (t @ n)
        t /= np.linalg.norm(t)
        mu = rng.uniform(0.02, 1.0)
        v = mu * n + np.sqrt(1 - mu * mu) * t
        NdotL = d @ n
        h = d + v
        h /= np.linalg.norm(h, axis=1, keepdims=True)
        f = sheen.sheen_lobe(np.maximum(NdotL, 1e-9), np.full(len(d), mu), np.clip(h @ n, 0, 1), np.ones(3),
                             perceptual_roughness)[..., 0]
        w = np.where(NdotL > 0, f * NdotL * solid, 0.0)
        exact, albedo = (w @ radiance) @ LUMINANCE, w.sum()
        cosine = np.where(NdotL > 0, NdotL * solid, 0.0)
        irradiance = (cosine @ radiance) / cosine.sum() @ LUMINANCE
        r = 2 * mu * n - v
        lobe = ibl._lobe_weight_unscaled(np.clip(d @ r, -1, 1)[None], perceptual_roughness ** 2)[0] * solid
        mirror = (lobe @ radiance) / lobe.sum() @ LUMINANCE
        irradiance_error.append(abs(albedo * irradiance - exact) / exact)
        mirror_error.append(abs(albedo * mirror - exact) / exact)
    return np.array(irradiance_error), np.array(mirror_error)


@pytest.mark.parametrize("perceptual_roughness", [0.5, 0.8, 1.0])
def test_the_irradiance_is_the_closer_sheen_environment(perceptual_roughness):
    irradiance, mirror = _errors(perceptual_roughness)
    assert np.median(irradiance) < 0.5 * np.median(mirror), (np.median(irradiance), np.median(mirror))
    assert np.percentile(irradiance, 90) < np.percentile(mirror, 90)
