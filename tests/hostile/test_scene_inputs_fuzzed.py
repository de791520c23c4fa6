"""Property-based scenes: every field of a valid scene replaced by hostile values (wrong
types, NaN, Inf, 1e400, huge integers, numpy values, nested junk), and scene files
damaged at the byte level. Each must give a clean refusal naming the file, or a Scene
whose every number is finite and whose booleans are booleans; the caller's data and
files are never changed."""

import dataclasses
import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hostile_common import FAST, SLOW, assert_clean_refusal, base_scene, leaf_paths, replace_at
from pbrlab.foundation.errors import PbrlabError
from pbrlab.scene import Scene, load_scene, parse_scene

PATHS = list(leaf_paths(base_scene()))

scalars = st.one_of(
    st.none(), st.booleans(),
    st.integers(min_value=-2 ** 70, max_value=2 ** 70),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, 1, -1, 0.0, 1.5, 1e-45, 3.5e38, -3.5e38, 1e308, 16384, 16385, 0.5]),
    st.text(max_size=6),
    st.sampled_from(["yes", "", "ggx", "high", "m", "s", "box", "point", "\x00", "../x.png"]),
    st.builds(np.float32, st.floats(width=32, allow_nan=True, allow_infinity=True)),
    st.builds(np.int64, st.integers(min_value=-2 ** 63, max_value=2 ** 63 - 1)),
    st.builds(np.bool_, st.booleans()),
    st.builds(complex, st.floats(allow_nan=False), st.floats(allow_nan=False)),
)
hostile = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.tuples(inner, inner, inner),
    st.dictionaries(st.text(max_size=4), inner, max_size=3),
    st.builds(lambda xs: np.array(xs, dtype=np.float64), st.lists(st.floats(), min_size=3, max_size=3)),
), max_leaves=6)


def _finite_scene(scene: Scene) -> None:
    """Every number the renderer will read is finite; booleans are real booleans."""
    def walk(value, where):
        if dataclasses.is_dataclass(value):
            for f in dataclasses.fields(value):
                walk(getattr(value, f.name), f"{where}.{f.name}")
        elif isinstance(value, dict):
            for k, v in value.items():
                walk(v, f"{where}.{k}")
        elif isinstance(value, (list, tuple)):
            for i, v in enumerate(value):
                walk(v, f"{where}[{i}]")
        elif isinstance(value, np.ndarray):
            assert np.all(np.isfinite(value)), where
        elif isinstance(value, float) and not where.endswith(".range"):  # range: inf = unbounded
            # attenuation_distance: +inf is KHR_materials_volume's default (nothing absorbed;
            # a JSON scene cannot write it, the reader refuses non-finite numbers)
            assert math.isfinite(value) or (where.endswith(".attenuation_distance") and value == math.inf), where
    walk(scene, "scene")
    assert type(scene.render.energy_compensation) is bool


@FAST
@given(index=st.integers(min_value=0, max_value=len(PATHS) - 1), value=hostile)
def test_a_hostile_field_is_refused_by_name_or_parsed_finite(index, value, census):
    data = replace_at(base_scene(), PATHS[index], value)
    before = repr(data)
    try:
        scene = parse_scene(data, origin="hostile.json")
    except Exception as exc:  # noqa: BLE001 - the point: any other type is a failure below
        assert_clean_refusal(exc, origin="hostile.json")
        census["scene field", "refused cleanly"] += 1
    else:
        _finite_scene(scene)
        census["scene field", "handled"] += 1
    assert repr(data) == before, "parse_scene changed the caller's data"


DAMAGES = {
    "duplicate key": lambda t: t.replace('"smoothness": 0.6', '"smoothness": 0.6, "smoothness": 0.1'),
    "Infinity": lambda t: t.replace('"intensity": 2.0', '"intensity": Infinity'),
    "-Infinity": lambda t: t.replace('"exposure": 0.0', '"exposure": -Infinity'),
    "NaN": lambda t: t.replace('"radius": 1.0', '"radius": NaN'),
    "1e400": lambda t: t.replace('"intensity": 5.0', '"intensity": 1e400'),
    "beyond float32": lambda t: t.replace('"intensity": 5.0', '"intensity": 1e39'),
    "bool as 0": lambda t: t.replace('"energy_compensation": true', '"energy_compensation": 0'),
    "bool as string": lambda t: t.replace('"energy_compensation": true', '"energy_compensation": "yes"'),
    "list as material": lambda t: t.replace('"material": "m"', '"material": ["m"]'),
    "dict as material": lambda t: t.replace('"material": "m"', '"material": {"m": 1}'),
    "deep nesting": lambda t: t.replace('"lights": [', '"junk": ' + "[" * 100000 + "]" * 100000 + ', "lights": ['),
    "truncated": lambda t: t[: len(t) // 2],
    "empty": lambda t: "",
    "not an object": lambda t: "[1, 2, 3]",
    "size too big": lambda t: t.replace('"size": [8, 6]', '"size": [16385, 6]'),
    "size zero": lambda t: t.replace('"size": [8, 6]', '"size": [0, 6]'),
    "size float": lambda t: t.replace('"size": [8, 6]', '"size": [8.5, 6]'),
}


@pytest.mark.parametrize("damage", sorted(DAMAGES))
def test_a_damaged_scene_file_is_refused_by_name_and_left_as_it_was(tmp_path, damage, census):
    path = tmp_path / "scene.json"
    text = DAMAGES[damage](json.dumps(base_scene()))
    assert text != json.dumps(base_scene()) or damage == "empty"
    path.write_text(text, encoding="utf-8")
    raw = path.read_bytes()
    with pytest.raises(PbrlabError) as info:
        load_scene(path)
    assert_clean_refusal(info.value, origin=str(path))
    assert path.read_bytes() == raw
    census["scene file", "refused cleanly"] += 1


@pytest.mark.parametrize("name, data", [
    ("not UTF-8", b'{"camera": "\xff\xfe"}'),
    ("UTF-16", json.dumps({"a": 1}).encode("utf-16")),
])
def test_undecodable_scene_files_are_refused_by_name(tmp_path, name, data, census):
    path = tmp_path / "scene.json"
    path.write_bytes(data)
    with pytest.raises(PbrlabError, match="not a UTF-8 text file"):
        load_scene(path)
    census["scene file", "refused cleanly"] += 1


def test_a_symlink_loop_texture_and_a_directory_scene_are_refused_by_name(tmp_path, census):
    (tmp_path / "a.png").symlink_to(tmp_path / "b.png")
    (tmp_path / "b.png").symlink_to(tmp_path / "a.png")
    data = base_scene()
    data["materials"]["m"]["textures"] = {"albedo": "a.png"}
    with pytest.raises(PbrlabError, match=r"materials\.m\.textures\.albedo: cannot open .*a\.png"):
        parse_scene(data, "loop.json", tmp_path)
    with pytest.raises(PbrlabError, match="is a directory"):
        load_scene(tmp_path)
    census["scene file", "refused cleanly"] += 2


def test_numpy_values_are_accepted_as_json_values(census):
    data = base_scene()
    data["camera"]["position"] = np.array([0.0, 0.0, 6.0])
    data["camera"]["size"] = [np.int64(8), np.int32(6)]
    data["materials"]["m"]["smoothness"] = np.float32(0.25)
    data["render"]["energy_compensation"] = np.bool_(False)
    scene = parse_scene(data, "numpy.json")
    assert scene.camera.size == (8, 6) and scene.materials["m"].smoothness == 0.25
    assert scene.render.energy_compensation is False
    census["scene field", "handled"] += 1


@SLOW
@given(index=st.integers(min_value=0, max_value=len(PATHS) - 1), value=hostile,
       size=st.one_of(st.none(), st.tuples(st.integers(-2, 20), st.integers(-2, 20)),
                      st.just((np.int64(5), np.int64(3))), st.just("8x8"), st.just((8.0, 8))))
def test_a_parsed_hostile_scene_renders_finite_or_is_refused(gl_context, index, value, size, census):
    from pbrlab.render.renderer import render_scene
    data = replace_at(base_scene(), PATHS[index], value)
    try:
        scene = parse_scene(data, origin="hostile.json")
    except PbrlabError:
        scene = parse_scene(base_scene(), origin="hostile.json")
    camera_before = repr(scene.camera)
    try:
        rendering = render_scene(scene, gl_context, size=size)
    except Exception as exc:  # noqa: BLE001
        assert_clean_refusal(exc)
        census["render", "refused cleanly"] += 1
    else:
        assert np.isfinite(rendering.linear).all()
        expected = tuple(size) if size is not None else scene.camera.size
        assert rendering.linear.shape[:2] == (expected[1], expected[0])
        census["render", "handled"] += 1
    assert repr(scene.camera) == camera_before, "render_scene changed the caller's Scene"


def test_a_radiance_past_float32_is_refused_by_name(gl_context, census):
    from pbrlab.render.renderer import render_scene
    data = base_scene()
    data["lights"][0].update(color=[3e38, 1, 1], intensity=10)
    with pytest.raises(PbrlabError, match=r"lights\[0\]: color x intensity = 3e\+39 is beyond the float32"):
        render_scene(parse_scene(data, "bright.json"), gl_context)
    census["render", "refused cleanly"] += 1


@pytest.mark.parametrize("scene", ["scenes/x.json", 42, {"camera": {}}, None])
def test_render_scene_refuses_what_is_not_a_scene(gl_context, scene, census):
    from pbrlab.render.renderer import render_scene
    with pytest.raises(PbrlabError, match="render_scene takes a Scene"):
        render_scene(scene, gl_context)
    census["render", "refused cleanly"] += 1
