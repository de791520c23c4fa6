"""Issue 26 (round two), silent wrong results from placements: a glTF node matrix that is
not affine, a world scale of 1e60 (finite in float64, not in float32: nested glTF node
scales, or a JSON mesh of size 1e30 scaled by 1e30), and a sphere at 1e30 (the shaders
square its distance in float32) rendered empty or black. Each is refused by name; a
sphere as far as float32 allows renders as the same scene scaled down."""

import json

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.commands import cli
from pbrlab.foundation.errors import SceneError
from pbrlab.importers.gltf import load_gltf
from pbrlab.render.renderer import render_scene
from pbrlab.scene import load_scene, parse_scene

# One triangle (positions in a data: URI buffer) on node 1, a child of node 0.
_POSITIONS = "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"


def _gltf(tmp_path, parent: dict, child: dict):
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"children": [1], **parent}, {"mesh": 0, **child}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
           "buffers": [{"byteLength": 36, "uri": _POSITIONS}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                          "min": [0, 0, 0], "max": [1, 1, 0]}]}
    path = tmp_path / "x.gltf"
    path.write_text(json.dumps(doc))
    return path


def _column_major(m: np.ndarray) -> list:
    return [float(v) for v in m.T.reshape(-1)]


def test_a_node_matrix_that_is_not_affine_is_refused_by_name(tmp_path, census):
    m = np.eye(4)
    m[3] = [0, 0, 1, 1]  # a projective last row: no translation x rotation x scale gives it
    path = _gltf(tmp_path, {}, {"matrix": _column_major(m)})
    with pytest.raises(SceneError, match=rf"^{path}: nodes\[1\]: matrix is not affine: its last row "
                                         r"is \[0, 0, 1, 1\], glTF requires \[0, 0, 0, 1\]"):
        load_gltf(path, emit_warnings=False)
    census["glTF node", "refused cleanly"] += 1


def test_an_affine_node_matrix_places_the_mesh(tmp_path, census):
    m = np.eye(4)
    m[:3, 3] = [1, 2, 3]
    path = _gltf(tmp_path, {}, {"matrix": _column_major(m)})
    (obj,) = load_gltf(path, emit_warnings=False).scene.objects
    np.testing.assert_array_equal(obj.transform, m)
    assert obj.where == f"{path}: nodes[1] (mesh 0, primitive 0)"
    census["glTF node", "handled"] += 1


def test_nested_node_scales_beyond_float32_are_refused_by_name(tmp_path, census):
    """1e30 x 1e30: every scale is a float32, the world matrix's 1e60 is not."""
    path = _gltf(tmp_path, {"scale": [1e30, 1e30, 1e30]}, {"scale": [1e30, 1e30, 1e30]})
    with pytest.raises(SceneError, match=rf"^{path}: nodes\[1\]: its world matrix has an entry of "
                                         r"1e\+60: finite in float64, not in float32"):
        load_gltf(path, emit_warnings=False)
    census["glTF node", "refused cleanly"] += 1


def test_a_json_mesh_scaled_beyond_float32_is_refused_by_name(tmp_path, capsys, census):
    scene = base_scene()
    scene["objects"][1]["mesh"] = {"primitive": "box", "size": 1e30}
    scene["objects"][1]["transform"] = {"scale": 1e30}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    out = tmp_path / "out.png"
    assert cli.main(["render", str(tmp_path / "scene.json"), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and not out.exists()
    assert (f"{tmp_path / 'scene.json'}: objects[1]: its world-space bounds reach 5e+59: finite in "
            "float64, not in float32") in err, err
    census["object placement", "refused cleanly"] += 1


def _far_sphere(distance: float) -> dict:
    """The sphere and the camera's distance to it both scaled by ``distance``; a directional
    light and a constant environment, which no scale changes."""
    scene = base_scene()
    scene["camera"].update(position=[0, 0, 6 * distance], target=[0, 0, 0], size=[32, 24])
    scene["lights"] = scene["lights"][:1]
    scene["objects"] = [{"sphere": {"center": [0, 0, 0], "radius": distance}, "material": "m"}]
    return scene


def test_a_sphere_too_far_for_float32_squares_is_refused_by_name(tmp_path, gl_context, census):
    (tmp_path / "scene.json").write_text(json.dumps(_far_sphere(1e30)))
    scene = load_scene(tmp_path / "scene.json")
    with pytest.raises(SceneError, match=rf"^{tmp_path / 'scene.json'}: objects\[0\]: reaches 7.14e\+30 "
                                         r"from the camera; the shaders square distances in float32"):
        render_scene(scene, gl_context)
    census["object placement", "refused cleanly"] += 1


def test_a_sphere_as_far_as_float32_allows_renders_as_the_scene_scaled_down(gl_context, census):
    near = render_scene(parse_scene(_far_sphere(1.0)), gl_context).linear
    far = render_scene(parse_scene(_far_sphere(2e18)), gl_context).linear  # reaches 1.5e19
    np.testing.assert_array_equal(far[..., 3] > 0, near[..., 3] > 0)
    np.testing.assert_allclose(far, near, rtol=0, atol=1e-3)  # float32 rounding of a 1e18 scale
    census["object placement", "handled"] += 1
