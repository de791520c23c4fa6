"""render.screen_space_reflections (harness/pbrlab/render/screen_space_reflection.py,
templates/screen_space_reflection.inc) against a float64 scene: a white mirror-like metal plane
(y = 0) reflecting an emissive box that stands on it, under a uniform sky E, no lights. Standing,
the box's faces that the plane reflects towards the camera are faces the camera sees: what a
screen-space search can find (a floating box's underside, seen only in the mirror, is not in the
frame: with the box floating 0.65 above the plane, seen from higher up, a quarter of its
reflection's pixels kept the sky).

In a uniform sky a white metal (F0 = F90 = 1) with the multiple-scattering compensation reflects
exactly what reaches it (the split sum's E times 1 / E: tests/render/test_white_furnace.py), so
the plane's Fresnel is 1 and each of its pixels is the radiance along its read direction: the
box's emission C where that ray meets the box (float64: pbrlab.maths.reference.
screen_space_reflection, the slab method along the dominant direction), the sky E elsewhere.
The box (albedo and specular 0) shows C itself. The control: the option off shows the sky on
every plane pixel, and the same check rejects the box's reflection.
"""

import numpy as np
import pytest
from scipy import ndimage

from pbrlab.maths.camera import camera_rays
from pbrlab.maths.reference import screen_space_reflection as ref
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import volume_chord
from pbrlab.render import screen_space_reflection
from pbrlab.render.depth_range import scene_frame
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

SIZE = (96, 72)
SKY = (0.2, 0.3, 0.4)
BOX_COLOUR = (1.3, 0.7, 0.45)   # not representable in half floats: the storage's rounding is seen
PLANE = 6.0
BOX = {"mesh": {"primitive": "box", "size": 1.0},
       "transform": {"scale": [0.8, 0.5, 0.6], "rotate_deg": [0, 30, 0], "translate": [0.1, 0.25, -0.6]}}


def _scene(on: bool, hdr_target: str = "rgba16f"):
    return parse_scene({
        "camera": {"position": [0.0, 0.7, 4.0], "target": [0.0, 0.1, -0.3], "fov_y_deg": 40, "size": list(SIZE)},
        "lights": [], "environment": {"color": list(SKY)},
        "materials": {"mirror": {"albedo": [1, 1, 1], "metallic": 1.0, "smoothness": 1.0},
                      "box": {"workflow": "specular", "albedo": [0, 0, 0], "specular": [0, 0, 0],
                              "smoothness": 0.0, "emission": list(BOX_COLOUR)}},
        "objects": [{"mesh": {"primitive": "plane", "size": PLANE}, "material": "mirror"},
                    {**BOX, "material": "box"}],
        "render": {"tonemap": "none", "screen_space_reflections": on, "hdr_target": hdr_target},
    })


def _expected(scene):
    """Per pixel: (plane, box's reflection with weight 1, within a pixel of the reflection's edge)."""
    frame = scene_frame(scene)
    rays = camera_rays(frame)
    origin = np.broadcast_to(np.asarray(scene.camera.position, np.float64), rays.shape)
    alpha = ref_shading.MIN_PERCEPTUAL_ROUGHNESS ** 2   # smoothness 1: the clamped roughness
    box_model = scene.objects[1].transform
    on_plane, p, d, hits_box, q = ref.mirror_plane_reflection(origin, rays, 0.0, box_model, alpha)
    t_enter, t_exit = volume_chord.ray_box_interval(origin, rays, box_model)
    on_plane &= ~(t_exit > t_enter)   # the plane where the box does not stand before it
    on_plane &= (np.abs(p[..., 0]) < PLANE / 2) & (np.abs(p[..., 2]) < PLANE / 2)   # and within its edges
    clip = np.concatenate([q, np.ones(q.shape[:-1] + (1,))], axis=-1) @ np.asarray(frame.view_proj, np.float64).T
    uv = clip[..., :2] / clip[..., 3:] * 0.5 + 0.5
    weight = ref.hit_weight(uv, ref_shading.MIN_PERCEPTUAL_ROUGHNESS)
    return on_plane, hits_box & (weight == 1.0), hits_box


# Pixels next to the box's reflected outline are left out (a band of EDGE_PX): the search finds the
# crossing to within reach / (32 x 2^6) in world units (screen_space_reflection.py), here
# reach = 8.5 (the plane's diagonal): 0.004, under a tenth of a pixel where the box's faces lie
# (a pixel is ~0.045 world units at their depth); the first pass's position and colour are the
# texel's centre's (half a pixel) and the rasteriser's edge sampling of the box and of the plane
# another half pixel each: within 2 px of the outline a pixel's hit may land on either side.
EDGE_PX = 2
# The value's bound: C and E pass through half floats twice (the first pass's target, then the
# frame's: 2^-11 relative each), times float32 arithmetic of a few operations (1e-6 relative):
# 2 x 2^-11 + 1e-5 relative.
RELATIVE = 2 * 2.0 ** -11 + 1e-5


def _checked_pixels(scene):
    """(the plane's pixels that reflect the box, those that reflect the sky), both EDGE_PX away from
    the box's reflected outline and from the plane's own outline."""
    on_plane, reflects, hits_box = _expected(scene)
    near_edge = ndimage.binary_dilation(hits_box, iterations=EDGE_PX) & ~ndimage.binary_erosion(hits_box, iterations=EDGE_PX)
    plane_pixels = ndimage.binary_erosion(on_plane, iterations=EDGE_PX)
    return reflects & plane_pixels & ~near_edge, plane_pixels & ~hits_box & ~near_edge


@pytest.mark.parametrize("on", [True, False], ids=["screen_space_reflections", "control: the sky"])
def test_a_mirror_plane_reflects_the_emissive_box_where_float64_geometry_puts_it(on, gl_context):
    scene = _scene(on)
    inside, outside = _checked_pixels(scene)
    assert inside.sum() > 100 and outside.sum() > 1000
    got = render_scene(scene, gl_context).linear[..., :3].astype(np.float64)
    box = np.asarray(BOX_COLOUR)
    sky = np.asarray(SKY)
    # the sky is kept wherever the read direction meets no box (the option or not)
    assert (np.abs(got[outside] - sky) > RELATIVE * sky).mean() == 0.0, np.abs(got[outside] - sky).max()
    over = np.abs(got[inside] - box) > RELATIVE * box
    if on:
        assert over.mean() == 0.0, (over.any(axis=-1).mean(), np.abs(got[inside] - box).max())
    else:  # control: the sky where the box should be seen
        assert over.all(axis=-1).mean() == 1.0
        assert np.allclose(got[inside], sky, rtol=RELATIVE)


def test_the_search_reach_and_step_are_the_documented_ones(gl_context):
    """The reach the bound above uses: the drawn objects' bounding diagonal (the plane's, 8.5)."""
    scene = _scene(True)
    reach = screen_space_reflection.reach(screen_space_reflection.reflected_objects(scene))
    assert abs(reach - np.hypot(6.0, 6.0)) < 0.1  # the plane's diagonal; the box lies above it
    assert reach / (screen_space_reflection.SSR_STEPS * 2 ** (screen_space_reflection.SSR_REFINE + 1)) < 0.0045


def test_off_by_default():
    from pbrlab.scene.model import RenderSettings
    assert RenderSettings().screen_space_reflections is False


def test_the_hlsl_harness_reflects_as_the_glsl_one(gl_context):
    """The search and the hit in the HLSL programs (templates shared by both languages): the same
    image within float32 rounding of the shading (1e-6 relative), the box's reflection in it."""
    scene = _scene(True)
    glsl = render_scene(scene, gl_context).linear[..., :3].astype(np.float64)
    hlsl = render_scene(scene, gl_context, language="hlsl").linear[..., :3].astype(np.float64)
    assert np.allclose(hlsl, glsl, rtol=1e-6, atol=1e-7)
    inside, _ = _checked_pixels(scene)
    assert np.allclose(hlsl[inside], BOX_COLOUR, rtol=RELATIVE)
