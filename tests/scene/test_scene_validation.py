"""Scene files: valid ones parse, every kind of mistake gets a message naming its field."""

import copy
import json

import numpy as np
import pytest

from pbrlab.foundation.errors import SceneError
from pbrlab.scene import load_scene, parse_scene

MINIMAL = {
    "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "size": [32, 24]},
    "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0}],
    "materials": {"white": {"albedo": [1, 1, 1]}},
    "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "white"}],
}


def _with(path: str, value):
    """MINIMAL with the field at dotted ``path`` (list indices as numbers) set to value."""
    scene = copy.deepcopy(MINIMAL)
    *parents, last = path.split(".")
    node = scene
    for key in parents:
        node = node[int(key)] if isinstance(node, list) else node.setdefault(key, {})
    if isinstance(node, list):
        node[int(last)] = value
    else:
        node[last] = value
    return scene


def test_minimal_scene_parses_with_documented_defaults():
    scene = parse_scene(MINIMAL)
    assert scene.camera.size == (32, 24) and scene.camera.fov_y_deg == 45.0
    np.testing.assert_array_equal(scene.camera.up, [0, 1, 0])
    material = scene.materials["white"]
    assert (material.workflow, material.metallic, material.occlusion, material.alpha) == ("metallic", 0.0, 1.0, 1.0)
    assert scene.render.tonemap == "none" and scene.environment is None


@pytest.mark.parametrize("path, value, message", [
    ("materials.white.smoothness", 1.5, r"materials\.white\.smoothness: expected a number in \[0.0, 1.0\], got 1\.5"),
    ("materials.white.metallic", float("nan"), r"materials\.white\.metallic: is NaN"),
    ("materials.white.albedo", [1, 1], r"materials\.white\.albedo: expected a list of 3 numbers"),
    ("materials.white.albedo", [1, -0.1, 1], r"materials\.white\.albedo: components must lie in \[0, 1\]"),
    ("materials.white.glossiness", 0.3, r"materials\.white: unknown field: glossiness"),
    ("materials.white.specular", [0.04] * 3, r"materials\.white\.specular: specular belongs to the specular workflow"),
    ("lights.0.type", "area", r"lights\[0\]\.type: expected one of directional, point, spot"),
    ("lights.0.intensity", -2, r"lights\[0\]\.intensity: expected a number in \[0.0, inf\]"),
    ("lights.0.direction", [0, 0, 0], r"lights\[0\]\.direction: must not be the zero vector"),
    ("camera.size", [0, 10], r"camera\.size: expected \[width, height\]"),
    ("camera.fov_y_deg", 180, r"camera\.fov_y_deg: expected a number in \(0.0, 179.0\]"),
    ("camera.up", [0, 0, 1], r"camera\.up: up is parallel to the view direction"),
    ("objects.0.material", "gold", r'objects\[0\]\.material: unknown material "gold"; defined: white'),
    ("objects.0.sphere", {"center": [0, 0, 0], "radius": -1}, r"objects\[0\]\.sphere\.radius"),
    ("render", {"tonemap": "filmic"}, r"render\.tonemap: expected one of none, reinhard"),
    ("render", {"quality": "ultra"}, r"render\.quality: expected one of high"),
    ("environment", {"color": [1, 1, 1], "path": "sky.hdr"}, r"environment: give exactly one of color"),
    ("extra", 1, r"\(top level\): unknown field: extra"),
])
def test_bad_field_is_named_in_the_error(path, value, message):
    with pytest.raises(SceneError, match=message):
        parse_scene(_with(path, value), origin="s.json")


def test_missing_files_are_named(tmp_path):
    scene = _with("objects", [{"mesh": "nope.obj", "material": "white"}])
    with pytest.raises(SceneError, match=r"objects\[0\]\.mesh: file not found: .*nope\.obj"):
        parse_scene(scene, base=tmp_path)
    with pytest.raises(SceneError, match=r"environment\.path: file not found"):
        parse_scene(_with("environment", {"path": "sky.exr"}), base=tmp_path)
    with pytest.raises(SceneError, match=r"textures\.albedo: file not found"):
        parse_scene(_with("materials.white.textures", {"albedo": "a.png"}), base=tmp_path)


def test_scene_file_errors_name_the_file(tmp_path):
    with pytest.raises(SceneError, match="no such scene file"):
        load_scene(tmp_path / "missing.json")
    bad = tmp_path / "bad.json"
    bad.write_text('{"camera": {,}')
    with pytest.raises(SceneError, match=r"bad\.json:1:\d+: invalid JSON"):
        load_scene(bad)


def test_relative_paths_resolve_against_the_scene_folder(tmp_path):
    (tmp_path / "m").mkdir()
    (tmp_path / "m" / "tri.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(_with("objects", [{"mesh": "m/tri.obj", "material": "white"}])))
    assert load_scene(scene_file).objects[0].mesh_path == (tmp_path / "m" / "tri.obj").resolve()


def test_material_brdf_variants_parse_to_library_selectors():
    scene = parse_scene(_with("materials.white.brdf", {"specular_d": "beckmann", "diffuse": "burley"}))
    assert scene.materials["white"].brdf == {"specular_d": "BECKMANN", "diffuse": "BURLEY"}


@pytest.mark.parametrize("brdf, message", [
    ({"specular_x": "ggx"}, r"materials\.white\.brdf\.specular_x: unknown BRDF term"),
    ({"specular_d": "phong"}, r"materials\.white\.brdf\.specular_d: expected one of ggx, beckmann, blinn_phong"),
])
def test_bad_brdf_variant_is_named(brdf, message):
    with pytest.raises(SceneError, match=message):
        parse_scene(_with("materials.white.brdf", brdf))


def test_render_hdr_target_is_validated():
    assert parse_scene(_with("render", {"hdr_target": "rgba16f"})).render.hdr_target == "rgba16f"
    with pytest.raises(SceneError, match=r"render\.hdr_target: expected one of rgba32f, rgba16f"):
        parse_scene(_with("render", {"hdr_target": "rgb9e5"}))
