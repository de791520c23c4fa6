"""The rasterised mesh path: tessellated spheres approach the analytic one, textures
follow the sRGB/linear rule, tangents are orthonormal."""

import numpy as np
import pytest

from pbrlab.foundation import images
from pbrlab.scene import meshes
from pbrlab.maths.reference.color import srgb_to_linear
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from render_scenes import one_sphere

KEY = [{"type": "directional", "direction": [0.3, -0.3, -1], "intensity": 1.5}]


def test_tessellated_sphere_converges_to_the_ray_traced_one(gl_context):
    material = {"albedo": [0.7, 0.7, 0.7], "smoothness": 0.3}
    analytic = one_sphere(material, KEY, size=(96, 96))
    mesh = one_sphere(material, KEY, size=(96, 96))
    mesh["objects"] = [{"mesh": {"primitive": "icosphere", "subdivisions": 5, "radius": 1.0},
                        "material": "m"}]
    a_rgba = render_scene(parse_scene(analytic), gl_context).linear
    m_rgba = render_scene(parse_scene(mesh), gl_context).linear
    a, m = a_rgba[..., :3], m_rgba[..., :3]
    covered_a, covered_m = a_rgba[..., 3] > 0, m_rgba[..., 3] > 0
    # Measured (96x96, 20480 triangles): both cover the same 2848 pixels. Inside (two
    # pixels away from the silhouette, where grazing angles amplify the polygonal
    # deviation), interpolated normals stay within a fraction of a degree of the exact
    # ones: relative radiance difference median 1.2e-4, max 5.1e-3. A mesh path with
    # flat normals or a wrong normal matrix differs by > 10 %.
    assert np.array_equal(covered_a, covered_m)
    inner = covered_a.copy()
    for dy in range(-2, 3):
        for dx in range(-2, 3):
            inner &= np.roll(np.roll(covered_a, dy, 0), dx, 1)
    rel = np.abs(a - m)[inner] / (1e-3 + a[inner])
    assert np.median(rel) < 5e-4 and rel.max() < 1e-2


def test_albedo_texture_is_decoded_from_srgb(gl_context, tmp_path):
    code = 188  # sRGB code of linear ~0.5
    texture = np.full((8, 8, 4), code, np.uint8)
    images.write_png(tmp_path / "albedo.png", texture)
    light = [{"type": "directional", "direction": [0, -1, 0]}]
    plane = {"mesh": {"primitive": "plane", "size": 4.0}, "material": "m"}
    base = one_sphere({"workflow": "specular", "specular": [0, 0, 0], "albedo": [1, 1, 1]}, light, size=(16, 16))
    base["camera"] = {"position": [0, 3, 0.01], "target": [0, 0, 0], "fov_y_deg": 30, "size": [16, 16]}
    base["objects"] = [plane]
    textured = parse_scene(dict(base, materials={"m": {"workflow": "specular", "specular": [0, 0, 0],
                                                       "albedo": [1, 1, 1], "textures": {"albedo": "albedo.png"}}}),
                           base=tmp_path)
    out = render_scene(textured, gl_context).linear[8, 8, :3]
    expected = srgb_to_linear(code / 255.0)
    # llvmpipe's sRGB decode is an approximation (see tests/gpu/test_srgb_hardware.py):
    # measured within 1.2e-3 of the exact curve. Sampling the texture as linear data
    # would give 188/255 = 0.737 instead of 0.503.
    np.testing.assert_allclose(out, expected, atol=2e-3)


def test_tangents_are_unit_orthogonal_to_normals_and_follow_u():
    mesh = meshes.load_mesh(parse_scene({
        "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
        "materials": {"m": {}},
        "objects": [{"mesh": {"primitive": "plane"}, "material": "m"}]}).objects[0])
    positions, normals, uv, tangents, _ = meshes.vertex_arrays(mesh)
    np.testing.assert_allclose(np.linalg.norm(tangents[:, :3], axis=1), 1, rtol=1e-6)
    np.testing.assert_allclose(np.sum(tangents[:, :3] * normals, axis=1), 0, atol=1e-6)
    # the plane's u grows along +x, v along -z: tangent +x, right-handed bitangent
    np.testing.assert_allclose(tangents[:, :3], np.tile([1, 0, 0], (4, 1)), atol=1e-6)
    assert set(tangents[:, 3]) == {1.0}
