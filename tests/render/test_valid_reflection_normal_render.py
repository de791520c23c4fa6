"""render.valid_reflection_normal through the renderer: a white mirror-like metal plane whose
normal map tilts every normal 25° away from a camera 30° above it, so the mirror reflection of
the view points 9-30° below the plane, in a uniform white environment.

In a uniform white environment a white metal (F0 = F90 = 1) with the multiple-scattering
compensation reflects exactly 1 (the split sum's E times 1 / E; tests/render/test_white_furnace.py),
so every pixel is the horizon occlusion's factor alone (render.horizon_occlusion, on by
default): pbr_specular_horizon_occlusion(r.Ng, n.v, alpha). With the option the normal is
first bent (pbr/shading/valid_reflection_normal.glsl) and r.Ng is the threshold
min(0.9 v.Ng, 0.01): the expected value per pixel is the float64 occlusion at the float64
bent normal (harness/pbrlab/maths/reference/valid_reflection_normal.py) for that pixel's
view ray. The control: without the option the reflection stays below the plane and the
same check rejects every pixel.
"""

import numpy as np

from pbrlab.foundation import images
from pbrlab.maths.camera import camera_frame, camera_rays
from pbrlab.maths.reference import horizon_occlusion as ref_horizon
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import valid_reflection_normal as ref
from pbrlab.render.renderer import render_scene, scene_radius
from pbrlab.scene import meshes, parse_scene

TILT_CODE = (74, 128, 243)    # tangent-space (-0.42, 0.004, 0.91): 25° away from the camera (-x)
SMOOTHNESS = 0.9
SIZE = (32, 24)


def _scene(tmp_path, valid_reflection_normal: bool):
    images.write_png(tmp_path / "tilt.png", np.full((4, 4, 3), TILT_CODE, np.uint8))
    data = {
        # the camera on +x, 30° above the plane: the normal tilted away from it mirrors the view below
        "camera": {"position": [1.73, 1.0, 0.0], "target": [0, 0, 0], "fov_y_deg": 20, "size": list(SIZE)},
        "lights": [], "environment": {"color": [1, 1, 1]},
        "materials": {"m": {"albedo": [1, 1, 1], "metallic": 1.0, "smoothness": SMOOTHNESS,
                            "textures": {"normal": "tilt.png"}}},
        "objects": [{"mesh": {"primitive": "plane", "size": 8.0}, "material": "m"}],
        "render": {"tonemap": "none", "valid_reflection_normal": valid_reflection_normal},
    }
    return parse_scene(data, base=tmp_path)


def _expected(scene):
    """Per pixel: the float64 horizon occlusion at the float64 bent normal, for the pixel's ray."""
    obj = scene.objects[0]
    normals, tangents = (meshes.mesh_data(obj).arrays[i] for i in (1, 3))
    ng = np.asarray(normals[0], np.float64)
    t = np.asarray(tangents[0, :3], np.float64)
    b = tangents[0, 3] * np.cross(ng, t)
    texel = np.asarray(TILT_CODE, np.float64) / 255.0 * 2.0 - 1.0
    n = texel[0] * t + texel[1] * b + texel[2] * ng
    n /= np.linalg.norm(n)
    v = -camera_rays(camera_frame(scene.camera, scene_radius(scene)))
    bent = ref.valid_reflection_normal(n, ng, v)
    r = 2.0 * np.sum(bent * v, -1, keepdims=True) * bent - v
    alpha = max(1.0 - SMOOTHNESS, ref_shading.MIN_PERCEPTUAL_ROUGHNESS) ** 2
    return ref_horizon.specular_horizon_occlusion(r @ ng, np.maximum(np.sum(bent * v, -1), 1e-4), alpha), n, ng, v


# The bound: the shader's view direction is the interpolated world position's, off from the
# float64 ray by float32 rounding (relative 1e-6 on positions of size ~2, normalised); r.Ng
# then moves by at most ~4e-6, and the occlusion's slope in r.Ng is at most
# 1 / (4 alpha) = 25 at alpha 0.01 (d/dc of 1/2 (1 + c / sqrt(4 alpha^2 + c^2)), c = 0):
# 1e-4; the white metal's compensated albedo is 1 to float32 rounding (the white furnace).
BOUND = 1e-3


def test_bent_normal_reflection_stays_above_the_plane(gl_context, tmp_path):
    scene = _scene(tmp_path, True)
    want, n, ng, v = _expected(scene)
    r_unbent = 2.0 * np.sum(n * v, -1, keepdims=True) * n - v
    assert (r_unbent @ ng < -0.15).all()  # the case the option is for: every reflection dips (9° at least)
    got = render_scene(scene).linear[..., 0].astype(np.float64)
    assert (np.abs(got - want) > BOUND).mean() == 0.0, np.abs(got - want).max()
    assert want.min() > 0.5  # lit, not taken out
    # control: without the option the horizon occlusion takes the dipping reflection out
    off = render_scene(_scene(tmp_path, False)).linear[..., 0].astype(np.float64)
    assert (np.abs(off - want) > BOUND).mean() == 1.0
