"""What the environment-lobe tests share (test_sheen_environment.py,
test_specular_environment_direction.py): Blender's sunrise box-averaged to 128 x 64, each texel
held constant, as directions, solid angles and radiance; random shading frames; the prefiltered
lobe's read along a direction, and a lobe's luminance integral."""

import numpy as np

from pbrlab.foundation import images
from pbrlab.foundation.locations import locate
from pbrlab.gpu import ibl
from pbrlab.maths.reference import prefilter

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])


def sunrise_texels():
    """(directions N x 3, solid angles N, radiance N x 3) of the box-averaged sunrise."""
    image = images.read_image(locate("scenes") / "assets" / "environments" / "sunrise_256.exr")[..., :3]
    source = ibl.box_average(image.astype(np.float64), 128)
    d, solid = prefilter.equirect_texels(*source.shape[:2])
    return d.reshape(-1, 3), solid.reshape(-1), source.reshape(-1, 3)


def random_views(count: int, seed: int, min_NdotV: float):
    """``count`` random (n, v, n.v): n uniform on the sphere, v at n.v uniform in [min_NdotV, 1]."""
    rng = np.random.default_rng(seed)
    for _ in range(count):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        t = rng.normal(size=3)
        t -= n * (t @ n)
        t /= np.linalg.norm(t)
        mu = rng.uniform(min_NdotV, 1.0)
        yield n, mu * n + np.sqrt(1 - mu * mu) * t, mu


def prefiltered_luminance(d, solid, radiance, direction, alpha):
    """The prefiltered environment's luminance along ``direction``: the GGX lobe of roughness
    alpha (n = v = r) over the texels, as the prefilter sums it (gpu/ibl.py)."""
    lobe = ibl._lobe_weight_unscaled(np.clip(d @ direction, -1, 1)[None], alpha)[0] * solid
    return (lobe @ radiance) / lobe.sum() @ LUMINANCE
