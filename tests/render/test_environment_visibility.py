"""The sky's own shadowing (render.environment_visibility: render/environment_visibility.py).

A plane under a box under a constant sky: at each judged pixel of the plane the ratio of the
render with the option to the render without it is the visibility V the shader applied (a
black, rough dielectric: only the environment's specular, which the option scales by
max(V, f(V)), Jimenez et al.'s multi-bounce fit at F0 0.04, applied here to the float64 V too).

* the float64 estimator with exact ray casting (the same K directions and fluxes) against the
  true cosine-weighted visible fraction (1/pi) int vis cos, by float64 ray casting over
  256^2 cosine-weighted cells (their error: the share of cells the box's outline crosses): both
  are weighted means of region visibilities in [0, 1], so |V_K - V| <= TV(p, q) + sum_k q_k |x_k - y_k|, with p the
  estimator's weights (F_k cos l_k), q the regions' true cosine weights, x_k the visibility
  along l_k and y_k the cosine-weighted seen share of region k's texels (zero but where a
  region straddles the box's outline; per point, float64);
* the GPU's V against that float64 estimator: a direction whose ray passes within the shadow
  map's reach of the box's edge ((1 + 1.5 sqrt 2 + normal offset + depth bias) texels,
  shadow_map.py) may go either way; the sum of those directions' weights is the bound (per
  pixel), plus float32 rounding (1e-4: the ratio of two renders of radiance ~0.05);
* controls: without the option the same check fails on the box's shadow; an unoccluded mesh
  sphere is unchanged (V = 1 to rounding: the ratio estimator is exact where nothing occludes).
"""

import math

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.render import environment_visibility as ev
from pbrlab.render import shadow_map
from pbrlab.render.renderer import render_scene
from pbrlab.scene.environment import equirect_directions

SKY = [0.6, 0.6, 0.6]
K = 32
PLANE = 4.0
BOX_SIZE, BOX_CENTRE = 0.6, np.array([0.0, 0.5, 0.0])
CAMERA = {"position": [0.0, 6.0, 0.001], "target": [0.0, 0.0, 0.0], "fov_y_deg": 30.0, "size": [96, 96]}
F0 = 0.04
# float32 rounding of the shader's V (two sums of K = 32 terms, each within K 2^-24 = 1.9e-6
# relative, their ratio within 4e-6) and of the ratio of two renders' radiance (2^-24 each):
# under 1e-5 (measured: 1.4e-7 at the 571 pixels no direction's shadow edge comes near)
ROUNDING = 1e-5


def multi_bounce(v, albedo=F0):
    """Jimenez et al. 2016's fit, as scene_lighting.inc applies it."""
    a, b, c = 2.0404 * albedo - 0.3324, -4.7951 * albedo + 0.6417, 2.7552 * albedo + 0.6903
    return np.maximum(v, ((v * a + b) * v + c) * v)


# the fit's steepest slope over [0, 1] (float64, 1e5 points: 1.04 near V = 0.8): an error e in V
# moves max(V, f(V)) by at most LIPSCHITZ e
LIPSCHITZ = float(np.max(np.abs(np.diff(multi_bounce(np.linspace(0, 1, 100001))))) * 100000)


def scene(visibility, box=True, sphere=False, albedo=0.0, diffuse=False):
    objects = [{"mesh": {"primitive": "plane", "size": PLANE}, "material": "black"}]
    if box:
        objects.append({"mesh": {"primitive": "box", "size": BOX_SIZE}, "material": "black",
                        "transform": {"translate": BOX_CENTRE.tolist()}})
    if sphere:
        objects = [{"mesh": {"primitive": "icosphere", "radius": 1.0, "subdivisions": 4}, "material": "black"}]
    return parse_scene({
        "camera": dict(CAMERA), "environment": {"color": SKY},
        "materials": {"black": {"albedo": [albedo] * 3, "smoothness": 0.0}},
        "objects": objects,
        "render": {"environment_visibility": visibility, "environment_visibility_diffuse": diffuse}},
        origin="test_environment_visibility")


def _box_hit(origins, directions):
    lo, hi = BOX_CENTRE - BOX_SIZE / 2, BOX_CENTRE + BOX_SIZE / 2
    with np.errstate(divide="ignore", invalid="ignore"):
        t0, t1 = (lo - origins) / directions, (hi - origins) / directions
    near = np.nanmax(np.minimum(t0, t1), axis=-1)
    far = np.nanmin(np.maximum(t0, t1), axis=-1)
    return far >= np.maximum(near, 0.0)


def plane_points():
    """Per pixel centre: the point on the plane (y = 0) and whether the camera sees it there."""
    from pbrlab.maths.camera import camera_frame, camera_rays

    eye = np.array(CAMERA["position"])
    rays = camera_rays(camera_frame(scene(0).camera, 1.0))  # the renderers' own rays
    points = eye + (-eye[1] / rays[..., 1])[..., None] * rays
    seen = ~_box_hit(np.broadcast_to(eye, rays.shape), rays)
    return points, seen


def _malley(u, v):
    """Cosine-weighted directions about +Y from the unit square (Malley: the disc lifted)."""
    r, phi = np.sqrt(u), 2 * np.pi * v
    x, z = r * np.cos(phi), r * np.sin(phi)
    return np.stack([x, np.sqrt(np.maximum(0.0, 1 - x * x - z * z)), z], axis=-1)


def true_visibility(p, n=256):
    """(1/pi) int vis cos over the hemisphere at p by n^2 equal-weight cells of the square mapped
    to cosine-weighted directions, each counted by its centre; and its error bound: the share
    of cells whose corners do not all agree (only those can hold the outline)."""
    centres = (np.arange(n) + 0.5) / n
    u, v = np.meshgrid(centres, centres, indexing="ij")
    d = _malley(u, v).reshape(-1, 3)
    seen = 1.0 - float(_box_hit(np.broadcast_to(p, d.shape), d).mean())
    corners = np.linspace(0.0, 1.0, n + 1)
    u, v = np.meshgrid(corners, corners, indexing="ij")
    c = _malley(u, v)
    hit = _box_hit(np.broadcast_to(p, c.shape), c)
    mixed = (hit[:-1, :-1] != hit[1:, :-1]) | (hit[:-1, :-1] != hit[:-1, 1:]) | (hit[:-1, :-1] != hit[1:, 1:])
    return seen, float(mixed.mean())


@pytest.fixture(scope="module")
def lights():
    return ev.median_cut(np.broadcast_to(np.asarray(SKY, np.float32), (4, 8, 3)), K)


@pytest.fixture(scope="module")
def regions(lights):
    """Per region: its texels' directions and cosine weights about +Y (the image median_cut cut)."""
    d, omega = equirect_directions(ev.MIN_ROWS, 2 * ev.MIN_ROWS)
    return [(d[r0:r1, c0:c1].reshape(-1, 3), (omega[r0:r1, c0:c1] * np.maximum(d[r0:r1, c0:c1, 1], 0)).ravel())
            for r0, r1, c0, c1 in lights.regions]


def estimator_and_bound(lights, regions, p):
    """(V_K with exact visibility, |V_K - V| bound, weights p_k) at point p (module doc)."""
    cos = np.maximum(lights.directions[:, 1], 0.0)
    p_k = lights.flux[:, 1] * cos
    p_k = p_k / p_k.sum()
    vis = ~_box_hit(np.broadcast_to(p, lights.directions.shape), lights.directions)
    q_k, seen = [], []
    for dirs, weight in regions:
        q_k.append(weight.sum())
        hit = _box_hit(np.broadcast_to(p, dirs.shape), dirs)
        seen.append(float(weight[~hit].sum() / weight.sum()) if weight.sum() > 0 else 1.0)
    q_k = np.array(q_k) / sum(q_k)
    # each region's own error (its centroid's 0 or 1 against its texels' seen share), plus the
    # weights' total variation (triangle inequality)
    bound = 0.5 * np.abs(p_k - q_k).sum() + q_k @ np.abs(vis - np.array(seen))
    return float(p_k @ vis), float(bound), p_k


def uncertain(lights, p, band, angles=64):
    """Directions whose ray from p passes within ``band`` of the box's edge, across the ray (the
    map's taps and offsets move the ray sideways in the light's frame): a ring of ``angles``
    sideways displacements changes whether it meets the box. The box's outline across a ray
    is a convex polygon at least BOX_SIZE wide, so the ring (radius under a tenth of that)
    crosses it wherever a displacement of at most ``band`` does."""
    out = np.zeros(len(lights.directions), bool)
    for k, d in enumerate(lights.directions):
        e1 = np.cross(d, [0.0, 1.0, 0.0] if abs(d[1]) < 0.9 else [1.0, 0.0, 0.0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(d, e1)
        a = np.linspace(0, 2 * np.pi, angles, endpoint=False)[:, None]
        origins = p + band * (np.cos(a) * e1 + np.sin(a) * e2)
        hits = _box_hit(np.vstack([p[None], origins]), np.broadcast_to(d, (angles + 1, 3)))
        out[k] = hits.any() and not hits.all()
    return out


def ratio(on, off):
    return on[..., 1] / off[..., 1]


@pytest.fixture(scope="module")
def renders():
    on = np.asarray(render_scene(scene(K)).linear, np.float64)
    off = np.asarray(render_scene(scene(0)).linear, np.float64)
    return on, off


def judged_pixels(step=3):
    points, seen = plane_points()
    near = (np.abs(points[..., 0]) < 1.2) & (np.abs(points[..., 2]) < 1.2) & seen
    rows, cols = np.nonzero(near)
    return [(r, c, points[r, c]) for r, c in zip(rows[::step], cols[::step])]


def test_the_estimator_is_within_its_quadrature_bound_of_the_true_visible_fraction(lights, regions):
    """120 points of the plane around the box, 0.02 to 0.6 from its side (measured: error median
    0.045, largest 0.18; bound median 0.107, smallest margin 0.014). Control: the sky taken as
    unoccluded (V = 1) is over the bound at 96 of them."""
    errors, bounds, unoccluded = [], [], []
    ring = [np.array([r * math.cos(a), 0.0, r * math.sin(a)]) / max(abs(math.cos(a)), abs(math.sin(a)))
            for r in (0.32, 0.4, 0.5, 0.7, 0.9) for a in np.linspace(0, 2 * np.pi, 24, endpoint=False)]
    for p in ring:
        v_k, bound, _ = estimator_and_bound(lights, regions, p)
        truth, truth_error = true_visibility(p)
        errors.append(abs(v_k - truth))
        unoccluded.append(1.0 - truth)
        bounds.append(bound + truth_error)
    errors, bounds, unoccluded = np.array(errors), np.array(bounds), np.array(unoccluded)
    assert len(errors) == 120
    assert (errors <= bounds).all(), (errors.max(), bounds[errors.argmax()])
    assert (unoccluded > bounds).sum() > 60


def _gpu_check(on, off, lights, regions, want):
    frame = shadow_map.light_frame(scene(K), -lights.directions[0], ev.TILE)
    reach = (1 + 1.5 * math.sqrt(2) + shadow_map.NORMAL_OFFSET_TEXELS + shadow_map.DEPTH_BIAS_TEXELS)
    texel = max(shadow_map.light_frame(scene(K), -d, ev.TILE).texel for d in lights.directions)
    assert frame.texel <= texel
    over, occluded = 0, 0
    r = ratio(on, off)
    for row, col, p in judged_pixels():
        v_k, _, p_k = estimator_and_bound(lights, regions, p)
        bound = LIPSCHITZ * p_k[uncertain(lights, p, reach * texel)].sum() + ROUNDING
        occluded += multi_bounce(v_k) < 1 - bound
        over += abs(r[row, col] - multi_bounce(v_k)) > bound
    return over, occluded


def test_the_shaders_visibility_is_the_estimators_within_the_shadow_maps_reach(renders, lights, regions):
    on, off = renders
    over, occluded = _gpu_check(on, off, lights, regions, True)
    assert occluded > 100   # the box's shadow on the sky has pixels to judge
    assert over == 0, f"{over} pixels off the float64 estimator by more than their bound"


def test_without_the_option_the_check_fails(renders, lights, regions):
    _, off = renders
    over, occluded = _gpu_check(off, off, lights, regions, False)
    assert over >= occluded > 100


def test_an_unoccluded_sphere_is_unchanged():
    on = np.asarray(render_scene(scene(K, box=False, sphere=True)).linear, np.float64)
    off = np.asarray(render_scene(scene(0, box=False, sphere=True)).linear, np.float64)
    covered = off[..., 3] > 0
    assert covered.sum() > 1000
    relative = np.abs(on[..., 1] - off[..., 1])[covered] / off[..., 1][covered]
    assert (relative > ROUNDING).sum() == 0, relative.max()


def test_the_median_cut_splits_the_flux_evenly_and_keeps_it(lights):
    flux = lights.flux[:, 1]
    # the flux of the image cut: its texels' solid angles times the sky (float32 0.6: 2e-8 relative)
    omega = equirect_directions(ev.MIN_ROWS, 2 * ev.MIN_ROWS)[1].sum()
    np.testing.assert_allclose(flux.sum(), omega * SKY[1], rtol=1e-7)
    assert flux.max() / flux.min() < 1.15  # a constant sky: regions of (nearly) equal solid angle


def test_the_diffuse_is_scaled_only_with_its_flag(renders):
    """The diffuse light of a white plane (white minus black render: the specular is the same)
    is the option-off's to rounding without the flag; with it, its ratio to the option-off's is
    the fit at the albedo 0.8 of the V the black plane's specular ratio shows (that ratio is
    max(V, f(V)) at F0 0.04, which exceeds V by at most EXCESS: V lies within EXCESS below it;
    the fit at 0.8 has slope at most its LIPSCHITZ there)."""
    on_black, off_black = renders
    off = np.asarray(render_scene(scene(0, albedo=0.8)).linear, np.float64)[..., 1] - off_black[..., 1]
    on = np.asarray(render_scene(scene(K, albedo=0.8)).linear, np.float64)[..., 1] - on_black[..., 1]
    flagged = np.asarray(render_scene(scene(K, albedo=0.8, diffuse=True)).linear, np.float64)[..., 1]
    flagged = flagged - on_black[..., 1]
    points, seen = plane_points()
    assert (np.abs(on - off)[seen] > ROUNDING * np.abs(off)[seen]).sum() == 0
    v = np.linspace(0, 1, 100001)
    excess = float(np.max(multi_bounce(v) - v))                        # 0.002 near V = 0.9
    slope = float(np.max(np.abs(np.diff(multi_bounce(v, 0.8)))) * 100000)
    specular = ratio(on_black, off_black)
    expected = multi_bounce(specular, 0.8)
    bound = slope * excess + 4 * ROUNDING   # four renders' rounding in the two ratios
    shadowed = seen & (specular < 0.9)
    assert shadowed.sum() > 100
    assert (np.abs(flagged / off - expected)[shadowed] > bound).sum() == 0
    assert (flagged[shadowed] < off[shadowed]).all()   # darker in the box's shadow: the flag acts
