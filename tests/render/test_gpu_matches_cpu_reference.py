"""GPU renders (GLSL library, float32) against the independent float64 CPU renderer
(numpy ray-sphere + pbrlab.reference), on analytic scenes."""

from pathlib import Path

import numpy as np
import pytest

from pbrlab.images import read_image
from pbrlab.reference import tonemap as ref_tonemap
from pbrlab.reference.color import linear_to_srgb
from pbrlab.scene import TONEMAPPERS
from pbrlab.charts import CHARTS
from pbrlab.cpu_render import render_scene_cpu
from pbrlab.render import render_scene
from pbrlab.scene import parse_scene

from scenes import light_zoo, one_sphere

# GPU (float32) vs float64 CPU, linear radiance, per channel: |gpu - cpu| <= ATOL +
# rtol * |cpu|. ATOL = 1e-5 is 1/30 of the smallest 8-bit sRGB step (3.04e-4), so it is
# invisible; it covers silhouette pixels (radiance ~1e-4 at grazing angles) where float32
# conditioning gives a few % relative. Measured on Mesa 22.3 llvmpipe: both renderers
# hit exactly the same pixels (same ray algebra); 99.99 % of pixels agree within 1.1e-3
# relative; the worst, 2.4 %, sit in the highlights of smoothness-1 spheres, where
# float32 1 - NdotH^2 cancels against alpha^2 = 4e-6 inside D_GGX (issue 5's
# cancellation-free form removes this). So: rtol 2e-3 for all but 0.05 % of pixels,
# rtol 3e-2 for every pixel, and no coverage difference.
ATOL = 1e-5
RTOL_TYPICAL = 2e-3
RTOL_WORST = 3e-2
FRACTION_OVER_TYPICAL = 5e-4


def _compare(scene_dict, gl_context, gpu=None):
    if gpu is None:
        gpu = render_scene(parse_scene(scene_dict), gl_context).linear
    gpu = gpu.astype(np.float64)
    cpu = render_scene_cpu(parse_scene(scene_dict))
    assert np.isfinite(gpu).all()
    covered_gpu = gpu[..., 3] > 0
    covered_cpu = cpu[..., 3] > 0
    assert np.array_equal(covered_gpu, covered_cpu), (covered_gpu != covered_cpu).sum()
    err = np.abs(gpu - cpu)[..., :3]
    ref = np.abs(cpu)[..., :3]
    assert np.all(err <= ATOL + RTOL_WORST * ref), ((err - ATOL) / ref).max()
    over_typical = (err > ATOL + RTOL_TYPICAL * ref).any(axis=-1)
    assert over_typical.mean() <= FRACTION_OVER_TYPICAL, over_typical.mean()
    return gpu, cpu


@pytest.mark.parametrize("chart", sorted(CHARTS))
def test_chart_matches_float64_cpu_render(chart, gl_context):
    _compare(CHARTS[chart](), gl_context)


@pytest.mark.parametrize("chart", sorted(CHARTS))
def test_chart_golden_file_matches_float64_cpu_render(chart, gl_context):
    # The stored golden itself, not only today's render, must agree with the
    # independent reference: a golden is never just "whatever the shader printed".
    path = Path(__file__).resolve().parents[2] / "goldens" / f"{chart}.exr"
    if not path.exists():
        pytest.fail(f"{path} is missing; create it with make test PYTEST_ARGS=--update-goldens")
    _compare(CHARTS[chart](), gl_context, gpu=read_image(path))


def test_point_and_spot_lights_match_float64_cpu_render(gl_context):
    gpu, cpu = _compare(light_zoo(), gl_context)
    assert cpu[..., :3].max() > 0.1  # the lights do reach the spheres


def test_white_lambert_under_unit_light_along_normal_is_exactly_one(gl_context):
    # The lecture's convention ("lights are pi times too bright"): albedo 1, intensity 1,
    # light along the normal -> 1, and 255 through the sRGB framebuffer. Specular is
    # removed by a zero F0 (specular workflow, specular 0).
    scene = one_sphere({"workflow": "specular", "albedo": [1, 1, 1], "specular": [0, 0, 0],
                        "smoothness": 0.5},
                       [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0}],
                       size=(33, 33))
    rendering = render_scene(parse_scene(scene), gl_context)
    centre = rendering.linear[16, 16, :3]  # the pixel whose ray hits the sphere head-on
    np.testing.assert_allclose(centre, 1.0, rtol=2e-6)
    assert tuple(rendering.srgb8[16, 16, :3]) == (255, 255, 255)


def test_constant_environment_lights_white_lambert_to_its_radiance(gl_context):
    # Uniform radiance L on a white Lambert surface reflects exactly L everywhere
    # (irradiance pi*L times albedo/pi); order-2 SH represents a constant exactly.
    scene = one_sphere({"workflow": "specular", "albedo": [1, 1, 1], "specular": [0, 0, 0]},
                       [], environment={"color": [0.25, 0.5, 0.75]}, size=(32, 32))
    linear = render_scene(parse_scene(scene), gl_context).linear
    shaded = linear[linear[..., 3] > 0, :3]
    assert shaded.shape[0] > 300
    np.testing.assert_allclose(shaded, np.broadcast_to([0.25, 0.5, 0.75], shaded.shape), rtol=1e-5)


@pytest.mark.parametrize("tonemap", TONEMAPPERS)
def test_display_image_is_exposure_tonemap_and_srgb_of_the_linear_render(tonemap, gl_context):
    # The PNG must be exactly the library's display transform of the EXR: exposure,
    # then the tonemapper, then the sRGB encode. Reference: float64 of all three on the
    # GPU's own linear output. Tolerance: the hardware encode picks one of the two codes
    # bracketing the exact value (tests/harness/test_srgb_hardware.py), so 1 code.
    scene = one_sphere({"albedo": [0.9, 0.6, 0.3], "smoothness": 0.8},
                       [{"type": "directional", "direction": [0.3, -0.4, -1], "intensity": 6.0}],
                       size=(48, 48), tonemap=tonemap)
    scene["render"]["exposure"] = 0.5
    rendering = render_scene(parse_scene(scene), gl_context)
    linear = rendering.linear[..., :3].astype(np.float64)
    exposed = ref_tonemap.apply_exposure(linear, 0.5)
    mapped = exposed if tonemap == "none" else ref_tonemap.tonemap(exposed, tonemap.upper())
    expected = linear_to_srgb(np.clip(mapped, 0.0, 1.0)) * 255.0
    got = rendering.srgb8[..., :3].astype(np.float64)
    assert exposed.max() > 1.5  # the input is HDR, so the tonemappers differ from clamping
    assert np.abs(got - expected).max() < 1.0 + 1e-6
