"""A volume's path length from its geometry (render.volume_chord: harness/pbrlab/render/volume_exit.py,
templates/transmission_scene.inc pbrlab_volume_path_length), against the float64 chord of the
pixel's ray through the body (pbrlab.maths.reference.volume_chord), per pixel.

The chord is read back from the image: clear glass of IOR 1 (the transmitted ray goes on
unbent) before an emissive wall, no light and no environment, so a pixel of the glass shows
only the wall through it, weighted by the transmission and by Beer-Lambert over the path
length d: against the same glass with a white attenuation colour the ratio is c^(d / D), and
d = D ln(ratio) / ln(c). The control is the renderer without the option: every pixel then
shows the material's thickness, not the chord, and the same check rejects it.
"""

import copy

import numpy as np
import pytest
from scipy import ndimage

from pbrlab.maths.reference import volume_chord
from pbrlab.maths.reference import transmission as ref_transmission
from pbrlab.render import volume_exit
from pbrlab.render.depth_range import scene_frame
from pbrlab.render.renderer import render_scene
from pbrlab.scene import meshes, parse_scene

SIZE = (64, 64)
# the red channel: the smallest colour, the best-conditioned logarithm
ATTENUATION_COLOR = [0.5, 0.6, 0.7]
ATTENUATION_DISTANCE = 1.0
THICKNESS = 0.3  # the material's: none of the bodies' chords is this along most pixels
GLASS = {"albedo": [1, 1, 1], "smoothness": 1.0, "transmission": 1.0, "ior": 1.0, "thickness": THICKNESS,
         "attenuation_color": ATTENUATION_COLOR, "attenuation_distance": ATTENUATION_DISTANCE}
WALL = {"workflow": "specular", "albedo": [0, 0, 0], "specular": [0, 0, 0], "smoothness": 0.0,
        "emission": [1.0, 1.0, 1.0]}
SLAB = {"mesh": {"primitive": "box", "size": 1.0}, "transform": {"scale": [1.6, 1.2, 0.5], "rotate_deg": [25, 35, 0]}}
SPHERE = {"mesh": {"primitive": "icosphere", "radius": 1.0, "subdivisions": 3}}

# Per-pixel bound on |d - chord|, scene units, from what can move either:
# * the rasteriser snaps vertices to a grid of 1/256 pixel (llvmpipe's FIXED_ORDER 8, as the GL
#   spec's subpixel precision lets it): each corner moves up to sqrt(2)/512 px, which moves the
#   chord at a pixel by at most that times the chord's gradient across the image (the largest
#   over the pixel's 3 x 3 neighbourhood, from the float64 reference itself);
SNAP_PX = np.sqrt(2.0) / 512.0
# * the search along the ray (volume_exit.py): a convex body's crossing within reach / 512,
#   reach the largest world bounding-box diagonal of the material's objects (recomputed here
#   from the transformed corners of the mesh's box);
SEARCH_FRACTION = 1.0 / (volume_exit.CHORD_STEPS * 2 ** volume_exit.CHORD_REFINE)
# * float32: positions of size <= 5 hold 5 x 2^-24 = 3e-7 each, |exit - p| and the projection a
#   few of those; the two renders' radiance (rgba32f, a product of ~10 float32 factors) 1e-6
#   relative each, so ln(ratio) 2e-6 and d = D ln(ratio) / ln(0.5) 3e-6: 1e-5 holds the sum.
FLOAT_ATOL = 1e-5
# Pixels allowed over the bound: none in the interior (the silhouette's band of one pixel,
# where a pixel's centre and its neighbours see different faces, is left out).


def _scene(body, glass=GLASS, volume_chord=True):
    return {
        "camera": {"position": [0.3, 0.4, 4.0], "target": [0, 0, 0], "size": list(SIZE)},
        "lights": [],
        "environment": None,
        "materials": {"wall": dict(WALL), "glass": dict(glass)},
        "objects": [{"mesh": {"primitive": "plane", "size": 30.0},
                     "transform": {"rotate_deg": [90, 0, 0], "translate": [0, 0, -3.0]},
                     "material": "wall"},
                    {**copy.deepcopy(body), "material": "glass"}],
        "render": {"volume_chord": volume_chord},
    }


def _pixel_rays(scene):
    """World origins and unit directions of the rays through the pixels' centres (top row first)."""
    frame = scene_frame(parse_scene(scene))
    inverse = np.linalg.inv(np.asarray(frame.view_proj, np.float64))
    w, h = SIZE
    x = (np.arange(w) + 0.5) / w * 2.0 - 1.0
    y = 1.0 - (np.arange(h) + 0.5) / h * 2.0
    ndc = np.stack(np.broadcast_arrays(x[None, :], y[:, None]), axis=-1)

    def unproject(z):
        p = np.concatenate([ndc, np.full(ndc.shape[:2] + (1,), z), np.ones(ndc.shape[:2] + (1,))], axis=-1)
        q = p @ inverse.T
        return q[..., :3] / q[..., 3:]

    near, far = unproject(-1.0), unproject(1.0)
    d = far - near
    return near, d / np.linalg.norm(d, axis=-1, keepdims=True)


def _measured_chord(scene, gl_context, language="glsl"):
    """d per pixel from the ratio of the tinted glass to the clear one (module doc)."""
    clear = copy.deepcopy(scene)
    clear["materials"]["glass"]["attenuation_color"] = [1.0, 1.0, 1.0]
    tinted = render_scene(parse_scene(scene), gl_context, language=language).linear.astype(np.float64)
    white = render_scene(parse_scene(clear), gl_context, language=language).linear.astype(np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = tinted[..., 0] / white[..., 0]
    return ATTENUATION_DISTANCE * np.log(ratio) / np.log(ATTENUATION_COLOR[0])


def _reach(scene):
    """The world bounding box's diagonal of the glass object (its mesh's box, transformed)."""
    obj = parse_scene(scene).objects[1]
    positions = np.asarray(meshes.load_mesh(obj).positions, np.float64)
    lo, hi = positions.min(axis=0), positions.max(axis=0)
    corners = lo + np.array([[(k >> 2) & 1, (k >> 1) & 1, k & 1] for k in range(8)]) * (hi - lo)
    world = corners @ obj.transform[:3, :3].T + obj.transform[:3, 3]
    return float(np.linalg.norm(world.max(axis=0) - world.min(axis=0)))


def _bound(chord, interior, reach):
    gy, gx = np.gradient(chord)
    steepest = ndimage.maximum_filter(np.hypot(gx, gy), size=3)
    return np.where(interior, SNAP_PX * steepest + SEARCH_FRACTION * reach + FLOAT_ATOL, np.inf)


def _slab_chord(scene, ior=1.0):
    """The float64 path through the slab along each pixel's ray refracted at its entry face."""
    origin, direction = _pixel_rays(scene)
    model = parse_scene(scene).objects[1].transform
    t_enter, t_exit = volume_chord.ray_box_interval(origin, direction, model)
    if ior == 1.0:
        return np.where(t_exit > t_enter, t_exit - t_enter, 0.0)
    n = volume_chord.ray_box_entry_normal(origin, direction, model)
    refracted = ref_transmission.refraction_direction(n, -direction, np.full(n.shape[:-1], ior))
    entry = origin + t_enter[..., None] * direction
    chord = volume_chord.ray_box_chord(entry, refracted, model)
    return np.where(t_exit > t_enter, chord, 0.0)


def _interior(chord):
    return ndimage.binary_erosion(chord > 0.0, np.ones((3, 3), bool))


@pytest.mark.parametrize("volume_chord_on", [True, False], ids=["volume_chord", "control: thickness"])
def test_a_slab_transmits_over_the_float64_chord_of_each_pixels_ray(volume_chord_on, gl_context):
    """A rotated slab (1.6 x 1.2 x 0.5, seen at a slant: chords from near 0 at its edges to 0.76): every interior
    pixel's path length within its bound of the float64 slab-method chord. The control (the
    option off) shows the thickness 0.3 and fails on most pixels."""
    scene = _scene(SLAB, volume_chord=volume_chord_on)
    chord = _slab_chord(scene)
    interior = _interior(chord)
    assert interior.sum() > 400 and chord[interior].max() > 0.7
    measured = _measured_chord(scene, gl_context)
    over = np.abs(measured - chord) > _bound(chord, interior, _reach(scene))
    if volume_chord_on:
        assert not over[interior].any(), (over[interior].mean(), np.nanmax(np.abs(measured - chord)[interior]))
    else:
        assert np.allclose(measured[interior], THICKNESS, atol=FLOAT_ATOL)
        assert over[interior].mean() > 0.9


@pytest.mark.parametrize("volume_chord_on", [True, False], ids=["volume_chord", "control: thickness"])
def test_a_sphere_transmits_between_the_chords_of_its_inscribed_and_circumscribed_balls(volume_chord_on,
                                                                                      gl_context):
    """An icosphere (3 subdivisions) is a convex polyhedron between the balls of its faces'
    least distance from the centre and of its vertices' radius, so each ray's chord through it
    lies between the float64 chords through the two (plus the bound of the slab's test):
    every interior pixel. The control (the option off) fails on most pixels."""
    scene = _scene(SPHERE, volume_chord=volume_chord_on)
    obj = parse_scene(scene).objects[1]
    mesh = meshes.load_mesh(obj)  # a primitives.Primitive: float64 positions, triangles
    positions = np.asarray(mesh.positions, np.float64)
    corners = positions[np.asarray(mesh.faces)]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    inner = float(np.min(np.abs(np.sum(normals * corners[:, 0], axis=-1)) / np.linalg.norm(normals, axis=-1)))
    outer = float(np.linalg.norm(positions, axis=-1).max())
    assert 0.98 < inner < outer <= 1.0 + 1e-12
    origin, direction = _pixel_rays(scene)
    low = volume_chord.ray_sphere_chord(origin, direction, (0, 0, 0), inner)
    high = volume_chord.ray_sphere_chord(origin, direction, (0, 0, 0), outer)
    interior = _interior(low)
    assert interior.sum() > 800
    measured = _measured_chord(scene, gl_context)
    reach = _reach(scene)
    bound = np.maximum(_bound(low, interior, reach), _bound(high, interior, reach))
    over = (measured < low - bound) | (measured > high + bound)
    if volume_chord_on:
        assert not over[interior].any(), over[interior].mean()
    else:
        assert over[interior].mean() > 0.95


@pytest.mark.parametrize("ior", [1.5, 1.0], ids=["refracted", "control: the unbent chord"])
def test_a_refracting_slab_transmits_over_the_float64_chord_of_the_refracted_ray(ior, gl_context):
    """Glass of IOR 1.5: the path is the refracted ray's, from the face each pixel's ray
    enters (float64: the slab method's entering face, Snell's direction, the chord from the entry
    point), within the bound on every interior pixel but those whose refracted ray leaves through
    a face turned towards the camera (where the pass's nearest back face is not the exit:
    volume_exit.py). The control compares the same render with the chord of the unbent ray,
    which differs by more than the bound on most pixels."""
    scene = _scene(SLAB, {**GLASS, "ior": 1.5})
    refracted = _slab_chord(scene, 1.5)
    expected = _slab_chord(scene, ior)
    interior = _interior(refracted)
    origin, direction = _pixel_rays(scene)
    model = parse_scene(scene).objects[1].transform
    n = volume_chord.ray_box_entry_normal(origin, direction, model)
    d = ref_transmission.refraction_direction(n, -direction, np.full(n.shape[:-1], 1.5))
    t_enter, _ = volume_chord.ray_box_interval(origin, direction, model)
    exit_point = origin + t_enter[..., None] * direction + refracted[..., None] * d
    exit_normal = volume_chord.ray_box_entry_normal(exit_point + 4.0 * d, -d, model)
    eye = np.array(scene["camera"]["position"], np.float64)
    leaves_away = np.sum(exit_normal * (exit_point - eye), axis=-1) > 0.0
    checked = interior & leaves_away
    assert checked.sum() > 0.8 * interior.sum() > 300
    # a refracted ray crosses into other pixels, and the pass holds one back face per pixel: the
    # crossing is found against the back face at the centre of q's pixel, up to half a pixel's
    # diagonal from q's own projection. That moves the face along the view ray by up to that
    # times its distance's change per pixel (|grad t_exit|, float64, over the 3 x 3
    # neighbourhood), and the crossing along d by that times |n.view| / |n.d| (n the exit face's)
    _, t_exit = volume_chord.ray_box_interval(origin, direction, model)
    gy, gx = np.gradient(np.where(interior, t_exit, 0.0))
    per_pixel = ndimage.maximum_filter(np.hypot(gx, gy), size=3)
    with np.errstate(divide="ignore", invalid="ignore"):
        slant = np.abs(np.sum(exit_normal * direction, axis=-1)) / np.abs(np.sum(exit_normal * d, axis=-1))
    texel = np.sqrt(0.5) * per_pixel * slant
    measured = _measured_chord(scene, gl_context)
    over = np.abs(measured - expected) > _bound(expected, checked, _reach(scene)) + np.where(checked, texel, 0.0)
    if ior == 1.5:
        assert not over[checked].any(), (over[checked].mean(), np.abs(measured - expected)[checked].max())
    else:
        assert over[checked].mean() > 0.5


def test_the_path_agrees_in_glsl_and_hlsl(gl_context):
    """The refracting slab's path in the HLSL port of the search (the shared template through
    glslang and spirv-cross) against GLSL's: every covered pixel within the search's own
    resolution (reach / 512: a step decided the other way by float32 rounding at the crossing
    moves the result by at most the final interval) plus the float32 bound."""
    scene = _scene(SLAB, {**GLASS, "ior": 1.5})
    glsl = _measured_chord(scene, gl_context)
    hlsl = _measured_chord(scene, gl_context, "hlsl")
    seen = np.isfinite(glsl) & (glsl > 0.01)
    assert seen.sum() > 500
    assert np.all(np.abs(hlsl - glsl)[seen] <= SEARCH_FRACTION * _reach(scene) + FLOAT_ATOL)


def test_the_shaders_search_is_the_one_the_bound_is_derived_for():
    """The template's step and bisection counts are volume_exit.py's (the tests' bound uses those)."""
    from pbrlab.gpu.programs import TEMPLATES
    text = (TEMPLATES / "transmission_scene.inc").read_text(encoding="utf-8")
    assert f"#define PBRLAB_VOLUME_CHORD_STEPS {volume_exit.CHORD_STEPS}\n" in text
    assert f"#define PBRLAB_VOLUME_CHORD_REFINE {volume_exit.CHORD_REFINE}\n" in text


def test_a_thin_wall_is_drawn_as_without_the_option(gl_context):
    """Thickness 0 (thin-walled, as KHR_materials_volume defines it) is not made a volume by
    the option: the image is bit for bit the one without it."""
    thin = {**GLASS, "thickness": 0.0, "attenuation_color": [1, 1, 1]}
    del thin["attenuation_distance"]
    on = render_scene(parse_scene(_scene(SLAB, thin, volume_chord=True)), gl_context).linear
    off = render_scene(parse_scene(_scene(SLAB, thin, volume_chord=False)), gl_context).linear
    assert np.array_equal(on, off)


def test_the_float64_chords_match_a_hand_computed_case():
    """The references on rays whose chords are known: through a unit sphere's centre (2), at
    half its radius off centre (sqrt 3), missing it (0); along a box's axis and its diagonal of
    a face (its edge; the edge x sqrt 2), a ray starting inside (the rest of it)."""
    o = np.array([[0.0, 0.0, -5.0], [0.0, 0.5, -5.0], [0.0, 1.5, -5.0]])
    d = np.array([0.0, 0.0, 1.0])
    assert np.allclose(volume_chord.ray_sphere_chord(o, d, (0, 0, 0), 1.0), [2.0, np.sqrt(3.0), 0.0])
    model = np.diag([2.0, 2.0, 2.0, 1.0])
    assert np.isclose(volume_chord.ray_box_chord([0.0, 0.0, -5.0], d, model), 2.0)
    diagonal = np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)
    assert np.isclose(volume_chord.ray_box_chord([-3.0, -3.0, 0.0], diagonal, model), 2.0 * np.sqrt(2.0))
    assert np.isclose(volume_chord.ray_box_chord([0.0, 0.0, 0.5], d, model), 0.5)
