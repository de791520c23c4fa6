"""The staging check on pbrlab itself (pbrlab.checking.fidelity.check_staging): under a real
environment, its mirror sphere shows the sky the right way round and its rough white sphere at
the right brightness, against what the environment image predicts in float64. The other three
renderers are checked the same way when their references are made (docs/fidelity.md)."""

import numpy as np
import pytest

from pbrlab.checking.fidelity import check_staging, renderers, spheres, staging
from pbrlab.foundation import images

# The mirror's sky turned a quarter, a half or three quarters round +Y, or mirrored: each must
# fit the render worse than pbrlab's own convention by this factor. Any factor above 1 tells
# the orientations apart; the nearest wrong one (the mirrored sky seen from +X, whose mirror
# plane holds the view's own reflection) fits 4.7 times worse, the others 5.3-26 times; 3
# leaves room for a softer mirror level without admitting a wrong sky.
WRONG_ORIENTATION_FACTOR = 3.0
# The rough white sphere is Lambert plus a specular layer of F0 0.04 at roughness 1 whose
# albedo the diffuse gives up (the coupling): its mean is Lambert's within +-0.04 (F0), and the
# irradiance cube's bilinear reconstruction adds at most h^2/8 = 3e-4 (gpu/ibl.py)
EXPOSURE_BOUND = 0.04 + 3e-4


def _variants(radiance):
    w = radiance.shape[1]
    return {"turned 90": np.roll(radiance, w // 4, axis=1), "turned 180": np.roll(radiance, w // 2, axis=1),
            "turned 270": np.roll(radiance, 3 * w // 4, axis=1), "mirrored": radiance[:, ::-1]}


@pytest.fixture(scope="module")
def staged(tmp_path_factory):
    folder = tmp_path_factory.mktemp("staging")
    models = spheres.write_spheres(folder / "models")
    environment = staging.prepare_environment("sunrise", folder / "environments")
    radiance = images.read_image(environment["environment"])[..., :3].astype(np.float64)
    return models, environment, radiance


def _render_sphere(staged, model, view):
    """pbrlab's linear image of a staging sphere from one of check_staging.VIEWS, the
    environment's radiance and the camera (for check_staging.predicted)."""
    models, environment, radiance = staged
    camera = {"eye": check_staging.VIEWS[view], "target": [0.0, 0.0, 0.0], "up": [0.0, 1.0, 0.0],
              "yfov_deg": 45.0, "znear": 0.01, "zfar": 20.0}
    linear, _ = renderers.render("pbrlab", {"gltf": str(models[model]), **environment,
                                            "size": list(check_staging.SIZE), "camera": camera})
    return linear, radiance, camera


@pytest.mark.parametrize("view", sorted(check_staging.VIEWS))
def test_pbrlabs_mirror_shows_the_sky_the_right_way_round(staged, view):
    linear, radiance, camera = _render_sphere(staged, "mirror_sphere", view)
    expected, mask, hit = check_staging.predicted("mirror_sphere", radiance, camera)
    right = check_staging.compare(linear, expected, mask, hit)
    assert right["coverage_mismatch"] <= 0.01 * hit.sum(), right
    for name, sky in _variants(radiance).items():
        wrong = check_staging.compare(linear, check_staging.predicted("mirror_sphere", sky, camera)[0], mask, hit)
        assert wrong["median_err"] >= WRONG_ORIENTATION_FACTOR * right["median_err"], (view, name, right, wrong)


@pytest.mark.parametrize("view", sorted(check_staging.VIEWS))
def test_pbrlabs_rough_white_sphere_has_lamberts_brightness(staged, view):
    linear, radiance, camera = _render_sphere(staged, "diffuse_sphere", view)
    expected, mask, hit = check_staging.predicted("diffuse_sphere", radiance, camera)
    got = check_staging.compare(linear, expected, mask, hit)
    assert abs(got["mean_ratio"] - 1.0) <= EXPOSURE_BOUND, got
