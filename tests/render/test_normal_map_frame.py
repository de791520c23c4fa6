"""The tiers' normal-map frames (PBR_NORMAL_MAP_FRAME, pbr/shading/dispatch.glsl; the scene
template's pbrlab_tangent_to_world_normal): LOW maps a tangent-space normal through
MikkTSpace's pixel-shader form, the interpolated tangent as it arrives (mikktspace.h:
"bitangent = fSign * cross(vN, tangent); vNout = normalize(vNt.x * tangent + vNt.y * bitangent
+ vNt.z * vN)"), HIGH through the orthonormal frame (Gram-Schmidt).

The check needs no reference of its own: on a flat plane with normal n, a tangent T = T0 + k n
(T0 unit and orthogonal to n) gives MikkTSpace's bitangent w n x T0 (n x n = 0), so the texel
(x, y, z) maps along x T0 + y w (n x T0) + (x k + z) n: the direction the orthonormal frame of T0
gives the texel (x, y, x k + z). So LOW's image of the skewed tangent under texel m equals its
image of the orthonormal tangent T0 under the texel m' = (x, y, x k + z), with k chosen so that
m' is another 8-bit texel exactly; and HIGH, which removes k n, does not (the control)."""

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.foundation import images
from pbrlab.render import tangent_frames
from pbrlab.render.renderer import render_scene
from pbrlab.scene import meshes

from render_scenes import one_sphere

CODE_A = (200, 150, 180)   # the skewed tangent's texel
CODE_B = (200, 150, 230)   # the orthonormal tangent's: the same x and y, z = x k + z_A


def _unpack(code):
    return np.asarray(code, np.float64) / 255.0 * 2.0 - 1.0  # UnpackNormal of an 8-bit texel


def _plane(tmp_path, code, tangent_normal_part: float, quality: str):
    name = f"n{code[2]}.png"
    images.write_png(tmp_path / name, np.full((4, 4, 3), code, np.uint8))
    data = one_sphere({"albedo": [0.8, 0.7, 0.6], "smoothness": 0.5, "metallic": 0.0, "textures": {"normal": name}},
                      [{"type": "directional", "direction": [0.3, -1, -0.2]}], size=(24, 24))
    data["camera"] = {"position": [0, 3, 0.01], "target": [0, 0, 0], "fov_y_deg": 30, "size": [24, 24]}
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 4.0}, "material": "m"}]
    data["render"] = {"quality": quality, "tonemap": "none"}
    scene = parse_scene(data, base=tmp_path)
    obj = scene.objects[0]
    positions, normals, uv, tangents, indices = meshes.mesh_data(obj).arrays[:5]
    assert np.allclose(normals, (0.0, 1.0, 0.0)) and np.allclose(tangents[:, :3], (1.0, 0.0, 0.0))
    tangents = tangents.copy()
    tangents[:, :3] = (1.0, tangent_normal_part, 0.0)  # T0 = +x, plus k n
    obj.geometry = meshes.Geometry(("frame test", code, tangent_normal_part), positions, normals, uv, tangents,
                                   uv, np.ones((len(positions), 4), np.float32), indices)
    obj.mesh_path = obj.primitive = None
    assert not tangent_frames.needs_fallback(scene.objects)  # LOW's frame is compiled, not the fallback
    return scene


@pytest.fixture(scope="module")
def k():
    a, b = _unpack(CODE_A), _unpack(CODE_B)
    return float(np.float32((b[2] - a[2]) / a[0]))  # x k + z_A = z_B


def test_low_maps_through_the_tangent_as_it_arrives(gl_context, tmp_path, k):
    skewed = render_scene(_plane(tmp_path, CODE_A, k, "low"), gl_context).linear.astype(np.float64)
    straight = render_scene(_plane(tmp_path, CODE_B, 0.0, "low"), gl_context).linear.astype(np.float64)
    covered = straight[..., 3] > 0
    assert covered.sum() > 400 and (straight[covered][:, :3] > 0).all()
    # The two normals agree up to k's float32 rounding (2^-24 relative) and the two programs'
    # different roundings of the same sums (a few float32 ulps of |x T + ...| ~ 1.5): the
    # normalised directions within 1e-6, which moves a lit pixel by at most about the
    # lobe's logarithmic slope times that (< 1e3 for roughness 0.5's GGX): 1e-3 relative.
    # Measured: 3.7e-7.
    rel = np.abs(skewed[covered][:, :3] - straight[covered][:, :3]) / straight[covered][:, :3]
    assert rel.max() < 1e-3, rel.max()


def test_high_takes_the_normal_part_out_of_the_tangent(gl_context, tmp_path, k):
    """The control: the orthonormal frame removes k n, so the skewed tangent's image is the
    unskewed one's under the same texel, and not the image of texel B."""
    skewed = render_scene(_plane(tmp_path, CODE_A, k, "high"), gl_context).linear.astype(np.float64)
    unskewed = render_scene(_plane(tmp_path, CODE_A, 0.0, "high"), gl_context).linear.astype(np.float64)
    straight_b = render_scene(_plane(tmp_path, CODE_B, 0.0, "high"), gl_context).linear.astype(np.float64)
    covered = unskewed[..., 3] > 0
    rel = np.abs(skewed[covered][:, :3] - unskewed[covered][:, :3]) / unskewed[covered][:, :3]
    assert rel.max() < 1e-3, rel.max()  # measured: 0 (Gram-Schmidt of +x + k n on n = +y is +x)
    differs = np.abs(skewed[covered][:, :3] - straight_b[covered][:, :3]) / straight_b[covered][:, :3]
    assert np.median(differs) > 1e-2, np.median(differs)  # measured: 0.53
