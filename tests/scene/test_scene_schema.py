"""The scene files' JSON Schema (pbrlab.scene.schema, `pbrlab schema`) agrees with the parser
(pbrlab.scene.model): every committed and test scene is valid under both; invalid scenes the
parser refuses are refused by the schema; and over a sample of mutated scenes, the two
disagree only where the parser checks what a schema cannot (scene_schema.PARSER_ONLY_RULES:
files, material names, coinciding camera points, cone order, 512.0 as a size)."""

from __future__ import annotations

import copy
import json
import re
import sys
from pathlib import Path

import jsonschema
import pytest

from pbrlab.commands import cli
from pbrlab.scene import fields as scene_fields
from pbrlab.checking.charts import CHARTS
from pbrlab.foundation.errors import SceneError
from pbrlab.scene import load_scene, parse_scene
from pbrlab.scene.schema import PARSER_ONLY_RULES, scene_schema

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "hostile"))
sys.path.insert(0, str(ROOT / "tests" / "render"))
from hostile_common import base_scene, leaf_paths, replace_at  # noqa: E402
from render_scenes import light_zoo, one_sphere  # noqa: E402
from test_scene_validation import MINIMAL, _with  # noqa: E402

VALIDATOR = jsonschema.Draft202012Validator(scene_schema())
SCENE_FILES = sorted([*(ROOT / "scenes").rglob("*.json"), *(ROOT / "examples").rglob("scene.json")])
# A layered material and a glTF object (which brings the camera): the schema's combinators.
LAYERED = {**copy.deepcopy(MINIMAL), "materials": {"white": {
    "albedo": [1, 1, 1], "clearcoat": 0.5, "sheen_color": [0.1, 0.1, 0.1], "anisotropy_strength": 0.3,
    "iridescence": 0.4, "transmission": 0.5, "thickness": 0.1, "attenuation_distance": 2.0, "ior": 1.4,
    "brdf": {"specular_d": "beckmann", "diffuse": "burley"}}}}
TEST_SCENES = {
    **{name: build for name, build in CHARTS.items()},
    "test_scene_validation.MINIMAL": lambda: copy.deepcopy(MINIMAL),
    "hostile_common.BASE_SCENE": base_scene,
    "render/scenes.light_zoo": light_zoo,
    "render/scenes.one_sphere": lambda: one_sphere({"albedo": [0.5, 0.5, 0.5]}, [], environment={"color": [1, 1, 1]}),
    "layered material": lambda: copy.deepcopy(LAYERED),
}


def _schema_errors(data) -> list[str]:
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message[:200]}" for e in VALIDATOR.iter_errors(data)]


def test_the_schema_is_draft_2020_12():
    jsonschema.Draft202012Validator.check_schema(scene_schema())
    assert scene_schema()["$schema"] == "https://json-schema.org/draft/2020-12/schema"


def test_pbrlab_schema_prints_it(capsys, tmp_path):
    assert cli.main(["schema"]) == 0
    assert json.loads(capsys.readouterr().out) == scene_schema()
    assert cli.main(["schema", "-q", "-o", str(tmp_path / "scene.schema.json")]) == 0
    assert json.loads((tmp_path / "scene.schema.json").read_text(encoding="utf-8")) == scene_schema()


@pytest.mark.parametrize("path", SCENE_FILES, ids=[str(p.relative_to(ROOT)) for p in SCENE_FILES])
def test_every_committed_scene_is_valid(path):
    load_scene(path)  # the parser's verdict
    assert _schema_errors(json.loads(path.read_text(encoding="utf-8"))) == []


@pytest.mark.parametrize("name", TEST_SCENES)
def test_every_test_scene_is_valid(name):
    parse_scene(TEST_SCENES[name]())
    assert _schema_errors(TEST_SCENES[name]()) == []


def test_the_tables_defaults_are_the_parsers():
    """scene_fields' defaults (the schema's) are what the parser fills in."""
    scene = parse_scene(MINIMAL)
    material, render = scene.materials["white"], scene.render
    for table, obj, given in ((scene_fields.MATERIAL, material, {"albedo"}), (scene_fields.RENDER, render, set())):
        for key, spec in table.items():
            if key in given or spec.default is scene_fields.REQUIRED or (spec.only and material.workflow not in spec.only):
                continue
            value = getattr(obj, key)
            assert list(value) == list(spec.default) if isinstance(spec.default, list) else value == spec.default, key


# Invalid scenes with the parser's message (its error paths, unchanged): the schema refuses each.
REFUSED_BY_BOTH = [
    ("materials.white.smoothness", 1.5, r"materials\.white\.smoothness: expected a number in \[0.0, 1.0\], got 1\.5"),
    ("materials.white.albedo", [1, 1], r"materials\.white\.albedo: expected a list of 3 numbers"),
    ("materials.white.albedo", [1, -0.1, 1], r"materials\.white\.albedo: components must lie in \[0, 1\]"),
    ("materials.white.glossiness", 0.3, r"materials\.white: unknown field: glossiness"),
    ("materials.white.specular", [0.04] * 3, r"materials\.white\.specular: specular belongs to the specular workflow"),
    ("materials.white.unlit", 1, r"materials\.white\.unlit: expected true"),
    ("materials.white.thickness", 0.2, r"materials\.white\.thickness: `thickness` belongs to the transmission"),
    ("materials.white.textures", {"glow": "x.png"}, r"materials\.white\.textures\.glow: unknown texture slot"),
    ("materials.white.brdf", {"specular_d": "phong"}, r"materials\.white\.brdf\.specular_d: expected one of ggx"),
    ("materials.white.properties", {}, r"materials\.white\.properties: properties belong to a Unity surface shader"),
    ("lights.0.type", "area", r"lights\[0\]\.type: expected one of directional, point, spot"),
    ("lights.0.intensity", -2, r"lights\[0\]\.intensity: expected a number in \[0.0, inf\]"),
    ("lights.0.direction", [0, 0, 0], r"lights\[0\]\.direction: must not be the zero vector"),
    ("lights.0.position", [0, 0, 0], r"lights\[0\]: unknown field: position"),
    ("lights.0", {"type": "point"}, r"lights\[0\]\.position: is required"),
    ("camera.size", [0, 10], r"camera\.size: expected \[width, height\]"),
    ("camera.fov_y_deg", 180, r"camera\.fov_y_deg: expected a number in \(0.0, 179.0\]"),
    ("camera.position", "here", r"camera\.position: expected a list of 3 numbers"),
    ("objects.0.sphere", {"center": [0, 0, 0], "radius": -1}, r"objects\[0\]\.sphere\.radius"),
    ("objects.0.mesh", {"primitive": "box"}, r"objects\[0\]: give exactly one of sphere or mesh"),
    ("objects.0", {"mesh": {"primitive": "cone"}, "material": "white"}, r"objects\[0\]\.mesh\.primitive: expected one of box"),
    ("objects.0", {"mesh": {"primitive": "icosphere", "subdivisions": 9}, "material": "white"},
     r"objects\[0\]\.mesh\.subdivisions: expected a whole number in \[0, 8\]"),
    ("objects.0", {"mesh": {"primitive": "box", "radius": 1}, "material": "white"},
     r"objects\[0\]\.mesh\.radius: unknown parameter of a box"),
    ("objects.0", {"mesh": {"primitive": "box"}, "material": "white", "transform": {"scale": 0}},
     r"objects\[0\]\.transform\.scale: scale components must be positive"),
    ("objects", [], r"objects: expected a non-empty list of objects"),
    ("render", {"tonemap": "filmic"}, r"render\.tonemap: expected one of none, reinhard"),
    ("render", {"exposure": 65}, r"render\.exposure: expected a number in \[-64.0, 64.0\]"),
    ("render", {"energy_compensation": "yes"}, r"render\.energy_compensation: expected one of true, false"),
    ("environment", {"color": [1, 1, 1], "path": "sky.hdr"}, r"environment: give exactly one of color"),
    ("environment", {"intensity": 2}, r"environment: give exactly one of color"),
    ("extra", 1, r"\(top level\): unknown field: extra"),
]


@pytest.mark.parametrize("path, value, message", REFUSED_BY_BOTH, ids=[f"{p}={json.dumps(v)}" for p, v, _ in REFUSED_BY_BOTH])
def test_what_the_parser_refuses_the_schema_refuses(path, value, message):
    scene = _with(path, value)
    with pytest.raises(SceneError, match=message):
        parse_scene(copy.deepcopy(scene), origin="s.json")
    assert _schema_errors(scene), f"the schema accepts {path} = {value!r}"


def test_the_camera_comes_from_a_gltf_object_or_the_scene():
    no_camera = {k: v for k, v in MINIMAL.items() if k != "camera"}
    with pytest.raises(SceneError, match=r"camera: is required \(or a gltf object with a camera\)"):
        parse_scene(copy.deepcopy(no_camera))
    assert _schema_errors(no_camera)
    assert not _schema_errors({**no_camera, "objects": [{"gltf": "model.glb"}]})


# The parser's refusals a schema cannot make, by their message: one pattern per rule of
# PARSER_ONLY_RULES that the mutations below reach.
PARSER_ONLY_MESSAGES = {
    r"file not found": PARSER_ONLY_RULES[0],
    r"unknown material": PARSER_ONLY_RULES[1],
    r"position and target coincide": PARSER_ONLY_RULES[2],
    r"inner_cone_deg must be smaller than outer_cone_deg": PARSER_ONLY_RULES[3],
    r"camera\.size: expected \[width, height\], integers in 1\.\.16384, got \[[^\]]*\.0": PARSER_ONLY_RULES[7],
}
MUTATIONS = [None, True, False, -1, 0, 0.5, 1, 1.5, 2.0, 90, 16385, 3.5e38, "", "x", "ggx", "point", "specular",
             "box", [], [1, 2, 3], [0, 0, 0], [1, 1], {}, {"x": 1}]
DELETE = object()


def _mutated(base: dict):
    for path in list(leaf_paths(base))[1:]:
        for value in [*MUTATIONS, DELETE]:
            scene = copy.deepcopy(base)
            if value is DELETE:
                node = scene
                for key in path[:-1]:
                    node = node[key]
                del node[path[-1]]
            else:
                replace_at(scene, path, copy.deepcopy(value))
            yield path, value, scene


@pytest.mark.parametrize("base", [base_scene, lambda: copy.deepcopy(LAYERED)], ids=["BASE_SCENE", "layered"])
def test_mutated_scenes_get_the_same_verdict_from_both(base):
    """Every field of a valid scene replaced by each of a set of values (or removed):
    the schema never refuses what the parser accepts, and refuses all the parser refuses
    but for the parser-only rules. About 1,700 scenes for the two bases."""
    disagreements, counted = [], 0
    for path, value, scene in _mutated(base()):
        counted += 1
        try:
            parse_scene(copy.deepcopy(scene), origin="s.json")
            parser = None
        except SceneError as exc:
            parser = str(exc)
        schema = _schema_errors(scene)
        if parser is None and schema:
            disagreements.append(f"{path} = {value!r}: the parser accepts, the schema refuses: {schema[0]}")
        elif parser is not None and not schema and not any(re.search(p, parser) for p in PARSER_ONLY_MESSAGES):
            disagreements.append(f"{path} = {value!r}: the parser refuses ({parser}), the schema accepts")
    assert counted > 500
    assert not disagreements, "\n".join(disagreements)
