"""The environment's sun as a shadow-casting light (render.environment_sun):
scene/environment_sun.py finds it and splits it off, render/shadow_map.py shadows it,
pbr/lighting/disc_light.glsl widens the lobes to its disc.

* recovery: a disc of known radiance on a constant sky (float64), its direction, irradiance
  and radius against the continuous disc, within bounds derived from the texel size;
* energy: sun + the sky without it has the environment's flux to rounding, and its
  irradiance on a white Lambertian sphere differs at every normal by at most the cosine's
  spread over the sun's texels (triangle inequality);
* a plane under a box lit by such an environment: the shadow where float64 geometry puts it,
  outside a band as wide as the shadow map's reach (shadow_map.py's module doc);
* what fails: no sun in a constant sky, in a broad glow, in a faint disc; the split that
  forgets to take the sun out; the render without the option; a shadow cast the wrong way.
"""

import math

import numpy as np
import pytest

from pbrlab import evaluate
from pbrlab.foundation import images
from pbrlab.scene import environment_sun as es
from pbrlab.importers.loader import parse_scene
from pbrlab.render import shadow_map
from pbrlab.render.renderer import render_scene
from pbrlab.scene.environment import equirect_directions

SKY = np.array([0.2, 0.3, 0.5])
DISC = np.array([4000.0, 3500.0, 3000.0])
SUN_TO = np.array([0.35, -0.8, -0.3])     # the way the light travels
SUN_TO = SUN_TO / np.linalg.norm(SUN_TO)
RADIUS = math.radians(2.5)  # under SUN_MAX_RADIUS_DEG; 2 g / r = 16 % at 2048 x 1024


def disc_environment(height=1024, width=2048, radius=RADIUS, disc=DISC, sky=SKY, towards=SUN_TO):
    """(image, texel mask) of a disc of radiance ``disc`` around -towards on a constant ``sky``."""
    d, _ = equirect_directions(height, width)
    inside = d @ -towards >= math.cos(radius)
    image = np.broadcast_to(sky, (height, width, 3)).copy()
    image[inside] = disc
    return image, inside


def texel_diagonal(height, width, towards=SUN_TO):
    """The largest angular diagonal of a texel at the disc's latitude (radians)."""
    polar = math.acos(float(-towards[1]))
    return math.hypot(math.pi / height, 2 * math.pi / width * math.sin(polar))


# -- recovery ------------------------------------------------------------------------------

def test_a_disc_on_a_constant_sky_is_found_where_it_is():
    height, width = 1024, 2048
    image, inside = disc_environment(height, width)
    sun = es.find_sun(image)
    assert sun is not None
    # the texels: exactly the disc's (sky 0.5 against a peak of 3.6e3: far under 1 %)
    assert np.array_equal(sun.mask, inside)
    np.testing.assert_allclose(sun.fill, SKY, rtol=1e-12)
    # against the continuous disc: the texels cut by its rim (a band one texel diagonal g wide
    # along the rim 2 pi r) are all the solid angle can be off by: |dOmega| <= 2 pi r g, so
    # |dE| / E <= 2 g / r, |dr| <= g, and the centroid moves by at most r |dOmega| / Omega <= 2 g
    g = texel_diagonal(height, width)
    omega = 2 * math.pi * (1 - math.cos(RADIUS))
    exact = (DISC - SKY) * omega
    assert np.all(np.abs(sun.irradiance - exact) <= exact * 2 * g / RADIUS), (sun.irradiance, exact, g)
    assert abs(sun.angular_radius - RADIUS) <= g, (math.degrees(sun.angular_radius), math.degrees(g))
    angle = math.acos(min(1.0, float(sun.direction @ SUN_TO)))
    assert angle <= 2 * g, (math.degrees(angle), math.degrees(g))
    np.testing.assert_allclose(sun.radiance, sun.irradiance / math.pi)


def test_the_bounds_are_tight_enough_to_fail():
    """A disc 3 texel diagonals off, or 25 % brighter, is outside the bounds above."""
    height, width = 1024, 2048
    g = texel_diagonal(height, width)
    axis = np.cross(SUN_TO, [0.0, 1.0, 0.0])
    axis /= np.linalg.norm(axis)
    moved = SUN_TO * math.cos(3 * g) + np.cross(axis, SUN_TO) * math.sin(3 * g)
    sun = es.find_sun(disc_environment(height, width, towards=moved)[0])
    assert math.acos(min(1.0, float(sun.direction @ SUN_TO))) > 2 * g
    sun = es.find_sun(disc_environment(height, width, disc=DISC * 1.25)[0])
    exact = (DISC - SKY) * 2 * math.pi * (1 - math.cos(RADIUS))
    assert np.any(np.abs(sun.irradiance - exact) > exact * 2 * g / RADIUS)


def test_no_sun_where_there_is_none():
    sky = np.broadcast_to(SKY, (256, 512, 3)).copy()
    assert es.find_sun(sky) is None                                          # constant
    glow, _ = disc_environment(256, 512, radius=math.radians(10), disc=np.full(3, 50.0))
    assert es.find_sun(glow) is None                                         # too wide
    faint, _ = disc_environment(256, 512, radius=math.radians(1.5), disc=np.full(3, 20.0))
    assert es.find_sun(faint) is None                                        # too small a share
    assert es.find_sun(disc_environment(256, 512)[0]) is not None            # the control


def test_blenders_sunrise_has_a_sun_and_its_courtyard_none():
    from pbrlab.checking.fidelity import staging
    sunrise = images.read_image(staging.ENVIRONMENTS_DIR / "sunrise.exr")
    sun = es.find_sun(sunrise)
    assert sun is not None and sun.mask.sum() == 8 and 0.5 < sun.share < 0.6
    assert sun.direction[1] < 0  # the light comes down from above the horizon
    assert es.find_sun(images.read_image(staging.ENVIRONMENTS_DIR / "courtyard.exr")) is None


# -- energy --------------------------------------------------------------------------------

def _split_check(image, sun, remaining):
    """(flux error relative, per-normal irradiance error, its bound) of sun + remaining
    against image, float64, over 400 Fibonacci normals."""
    image, remaining = np.asarray(image, np.float64), np.asarray(remaining, np.float64)
    d, solid = equirect_directions(*image.shape[:2])
    flux = (image * solid[..., None]).sum(axis=(0, 1))
    split_flux = (remaining * solid[..., None]).sum(axis=(0, 1)) + sun.irradiance
    count = 400
    k = np.arange(count) + 0.5
    y = 1 - 2 * k / count
    phi = k * math.pi * (3 - math.sqrt(5))
    normals = np.stack([np.sqrt(1 - y * y) * np.cos(phi), y, np.sqrt(1 - y * y) * np.sin(phi)], axis=1)
    flat_d, flat_w = d.reshape(-1, 3), solid.reshape(-1)
    original, split = np.empty((count, 3)), np.empty((count, 3))
    for start in range(0, count, 20):  # 20 normals at a time: memory
        cos = np.maximum(normals[start:start + 20] @ flat_d.T, 0.0) * flat_w
        original[start:start + 20] = cos @ image.reshape(-1, 3)
        split[start:start + 20] = cos @ remaining.reshape(-1, 3)
    split += np.maximum(normals @ -sun.direction, 0.0)[:, None] * sun.irradiance
    # |max(0, n.w_i) - max(0, n.w_c)| <= |w_i - w_c| for each sun texel, weighted by its excess
    excess = np.abs(image[sun.mask] - sun.fill) * solid[sun.mask, None]
    spread = np.linalg.norm(d[sun.mask] + sun.direction, axis=1)
    bound = (excess * spread[:, None]).sum(axis=0)
    return np.abs(split_flux - flux) / flux, np.abs(split - original), bound


@pytest.mark.parametrize("which", ["disc", "sunrise"])
def test_sun_plus_the_sky_without_it_is_the_environment(which):
    if which == "disc":
        image = disc_environment(256, 512, radius=math.radians(2))[0]
    else:
        from pbrlab.checking.fidelity import staging
        image = images.read_image(staging.ENVIRONMENTS_DIR / "sunrise.exr")[..., :3].astype(np.float64)
    sun = es.find_sun(image)
    remaining = np.asarray(image, np.float64).copy()
    remaining[sun.mask] = sun.fill  # es.sunless, in float64
    np.testing.assert_allclose(es.sunless(image, sun), remaining.astype(np.float32))
    flux_error, irradiance_error, bound = _split_check(image, sun, remaining)
    assert np.all(flux_error < 1e-12), flux_error
    assert np.all(irradiance_error <= bound * (1 + 1e-9) + 1e-12), (irradiance_error.max(axis=0), bound)
    # the bound is small beside the sun's irradiance: the split is a fair stand-in everywhere
    assert np.all(bound <= 0.06 * sun.irradiance), bound / sun.irradiance
    # control: the sun kept in the sky as well is counted twice
    flux_error, irradiance_error, bound = _split_check(image, sun, image)
    assert np.all(flux_error > 0.2) and np.any(irradiance_error.max(axis=0) > bound)


# -- the disc's highlight --------------------------------------------------------------------

def test_a_mirror_reflects_the_disc_at_its_own_size():
    """pbr_disc_light_alpha(0, r) (disc_light.glsl, evaluated on the GPU) gives GGX a half
    maximum at tan(theta_h) = r / 2, i.e. a reflected highlight of half-maximum radius r
    (float64 GGX); at r = 0 the lobe is as it was."""
    r = math.radians(2.0)
    alpha = evaluate("pbr_disc_light_alpha(0.0, x)", includes=("pbr/lighting/disc_light.glsl",), x=r)
    d = lambda t: alpha ** 2 / (math.pi * math.cos(t) ** 4 * (alpha ** 2 + math.tan(t) ** 2) ** 2)  # noqa: E731
    half = math.atan(r / 2)
    # D / D(0) = 1 / (2 cos^4) there (disc_light.glsl matches tan^2 at half maximum, first order in
    # r): within 1 / cos^4 - 1 (4e-4 at r = 2 deg) of 1/2, plus float32's rounding of alpha (1e-6)
    assert abs(d(half) / d(0.0) - 0.5) <= 0.5 * (1 / math.cos(half) ** 4 - 1) + 1e-6
    unchanged = evaluate("pbr_disc_light_alpha(0.5, x)", includes=("pbr/lighting/disc_light.glsl",), x=0.0)
    assert unchanged == pytest.approx(0.5, rel=1e-7)


# -- the shadow --------------------------------------------------------------------------------

PLANE = 4.0
BOX = {"size": 0.6, "centre": np.array([0.0, 0.5, 0.0])}
CAMERA = {"position": [0.0, 6.0, 0.001], "target": [0.0, 0.0, 0.0], "fov_y_deg": 45.0, "size": [192, 192]}


def shadow_scene(environment_path, environment_sun=True):
    return {
        "camera": dict(CAMERA),
        "environment": {"path": str(environment_path)},
        "materials": {"white": {"albedo": [0.8, 0.8, 0.8], "smoothness": 0.0}},
        "objects": [
            {"mesh": {"primitive": "plane", "size": PLANE}, "material": "white"},
            {"mesh": {"primitive": "box", "size": BOX["size"]}, "material": "white",
             "transform": {"translate": BOX["centre"].tolist()}},
        ],
        "render": {"environment_sun": environment_sun},
    }


def _box_hit(origins, directions, lo, hi):
    """Whether rays origin + s d, s > 0, meet the box [lo, hi] (slabs, float64)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t0, t1 = (lo - origins) / directions, (hi - origins) / directions
    near = np.nanmax(np.minimum(t0, t1), axis=-1)
    far = np.nanmin(np.maximum(t0, t1), axis=-1)
    return (far >= np.maximum(near, 0.0))


def expected_shadow(sun_to, size, band):
    """Per pixel: (on the plane and seen, in the box's shadow, within ``band`` of its edge)."""
    from pbrlab.maths.camera import camera_frame, camera_rays

    eye = np.array(CAMERA["position"])
    data = shadow_scene("unused.exr")
    data["camera"]["size"], data["environment"] = list(size), {"color": [0.0, 0.0, 0.0]}
    rays = camera_rays(camera_frame(parse_scene(data, origin="the shadow scene's camera").camera, 1.0))
    s = -eye[1] / rays[..., 1]
    points = eye + s[..., None] * rays
    half = BOX["size"] / 2
    lo, hi = BOX["centre"] - half, BOX["centre"] + half
    on_plane = (np.abs(points[..., 0]) < PLANE / 2) & (np.abs(points[..., 2]) < PLANE / 2)
    seen = on_plane & ~_box_hit(np.broadcast_to(eye, rays.shape), rays, lo, hi)
    to_sun = np.broadcast_to(-sun_to, points.shape)
    shadowed = _box_hit(points, to_sun, lo, hi)
    near_edge = np.zeros_like(shadowed)
    for angle in np.linspace(0, 2 * math.pi, 24, endpoint=False):
        moved = points + band * np.array([math.cos(angle), 0.0, math.sin(angle)])
        near_edge |= _box_hit(moved, to_sun, lo, hi) != shadowed
    return seen, shadowed, near_edge


@pytest.fixture(scope="module")
def sun_environment(tmp_path_factory):
    path = tmp_path_factory.mktemp("sun") / "disc.exr"
    images.write_exr(path, np.ascontiguousarray(disc_environment(256, 512, radius=math.radians(2))[0], np.float32))
    return path


def _classified(linear, sun, sky_irradiance):
    """Lit (True) where a pixel's radiance is above the midpoint of the float64 predictions
    for the plane in the sun and in the shadow (albedo 0.8: 0.8 E / pi, green channel)."""
    cos = max(0.0, -sun.direction[1])
    lit = 0.8 * (sky_irradiance + sun.irradiance[1] * cos) / math.pi
    dark = 0.8 * sky_irradiance / math.pi
    return linear[..., 1] > (lit + dark) / 2


def _shadow_mismatches(linear, sun, sun_to, frame_texel):
    """Pixels of the plane whose lit / shadowed state differs from float64 geometry's, away from
    the band the shadow map may move the edge by: (1 + 1.5 sqrt 2) texels of the filter's reach
    plus the normal offset (shadow_map.py) plus half a pixel's diagonal on the plane."""
    height, width = linear.shape[:2]
    pixel = 2 * 6.0 * math.tan(math.radians(CAMERA["fov_y_deg"]) / 2) / height
    reach = (1 + 1.5 * math.sqrt(2) + shadow_map.NORMAL_OFFSET_TEXELS + shadow_map.DEPTH_BIAS_TEXELS) * frame_texel
    band = reach + pixel * math.sqrt(2) / 2
    seen, shadowed, near_edge = expected_shadow(sun_to, (width, height), band)
    # the sky seen by the plane (upper hemisphere of the constant sky: E = pi L; the box's
    # own shadow on the sky light is the ambient the test does not model: it only lowers dark)
    lit = _classified(linear, sun, float(np.pi * SKY[1]))
    judged = seen & ~near_edge
    return int((lit[judged] == shadowed[judged]).sum()), int(judged.sum()), int((seen & shadowed & ~near_edge).sum())


def _render(scene_dict, folder):
    scene = parse_scene(scene_dict, origin="test_environment_sun", base=folder)
    return np.asarray(render_scene(scene).linear, np.float64), scene


def test_the_shadow_is_where_float64_geometry_puts_it(sun_environment):
    linear, scene = _render(shadow_scene(sun_environment), sun_environment.parent)
    sun = es.find_sun(images.read_image(sun_environment))
    frame = shadow_map.light_frame(scene, sun.direction)
    wrong, judged, in_shadow = _shadow_mismatches(linear, sun, sun.direction, frame.texel)
    assert in_shadow > 300, in_shadow            # the scene has a shadow to judge (423 of 36,864 px)
    assert wrong == 0, f"{wrong} of {judged} pixels lit where float64 says shadow or the reverse"


def test_without_the_option_or_cast_the_wrong_way_the_check_fails(sun_environment):
    sun = es.find_sun(images.read_image(sun_environment))
    linear, scene = _render(shadow_scene(sun_environment, environment_sun=False), sun_environment.parent)
    frame = shadow_map.light_frame(scene, sun.direction)
    wrong, _, in_shadow = _shadow_mismatches(linear, sun, sun.direction, frame.texel)
    assert wrong > 0.9 * in_shadow  # no shadow: every shadowed pixel is lit
    linear, _ = _render(shadow_scene(sun_environment), sun_environment.parent)
    mirrored = sun.direction * np.array([-1.0, 1.0, -1.0])
    wrong, _, _ = _shadow_mismatches(linear, sun, mirrored, frame.texel)
    assert wrong > 500


def test_the_option_changes_nothing_without_a_sun(tmp_path):
    """An environment without a sun (a constant sky) renders bit for bit as without the option."""
    path = tmp_path / "sky.exr"
    images.write_exr(path, np.ascontiguousarray(np.broadcast_to(SKY, (64, 128, 3)), np.float32))
    on, _ = _render(shadow_scene(path, True), tmp_path)
    off, _ = _render(shadow_scene(path, False), tmp_path)
    assert np.array_equal(on, off)


def test_the_lit_plane_is_as_bright_as_with_the_sun_in_the_environment(sun_environment):
    """Where the sun reaches, the split (light E / pi + the sky without it) shades the white
    plane as the whole environment did: the median relative difference of the lit pixels is
    within the float64 split's own bound, the cosine's spread over the sun's texels relative to
    its irradiance (test_sun_plus_the_sky_without_it_is_the_environment; 2 deg disc: 3.5 %;
    measured 1e-4). A sun in the wrong light unit (E, not E / pi) would be 3x too bright."""
    sun = es.find_sun(images.read_image(sun_environment))
    on, _ = _render(shadow_scene(sun_environment, True), sun_environment.parent)
    off, _ = _render(shadow_scene(sun_environment, False), sun_environment.parent)
    d, solid = equirect_directions(*sun.mask.shape)
    image = images.read_image(sun_environment)[..., :3].astype(np.float64)
    excess = np.abs(image[sun.mask] - sun.fill) * solid[sun.mask, None]
    spread = np.linalg.norm(d[sun.mask] + sun.direction, axis=1)
    bound = float(((excess * spread[:, None]).sum(axis=0) / excess.sum(axis=0)).max())
    seen, shadowed, near_edge = expected_shadow(sun.direction, on.shape[1::-1], 0.05)
    lit = seen & ~shadowed & ~near_edge
    relative = np.abs(on[lit][:, :3] - off[lit][:, :3]) / off[lit][:, :3]
    assert np.median(relative) <= bound, (np.median(relative), bound)
    assert np.mean(relative > bound) <= 0.01, np.mean(relative > bound)
