"""Morph targets (gltf/morph.py) and the choice of scene, on scenes/gltf/morph_scenes.gltf
(make_delivered_assets.py): a 9x9 grid with a bump target (POSITION and NORMAL deltas)
and a shear target (POSITION), mesh.weights [0.5, 0]; scene 0 draws node 0 (the mesh's
weights) at x = -1.1, scene 1 node 1 (weights [1, 1] of its own) at x = +1.1. The target
deltas the tests expect are read from the file's buffer here with numpy, not through the
importer's accessor reader."""

from __future__ import annotations

import base64
import copy
import json

import numpy as np
import pytest

from gltf_helpers import blob, quad_document, set_blob, write
from pbrlab.commands import cli
from pbrlab.foundation.errors import SceneError
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import load_gltf
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment

ENV = Environment(color=np.array([0.3, 0.3, 0.35]))
SIZE = (96, 64)
MORPH = GLTF_DIR / "morph_scenes.gltf"
DOC = json.loads(MORPH.read_text())
# Geometry is stored in float32: sums of values up to 1.6 round within 2^-23 x 2 each
FLOAT32_SUM = 4 * float(np.finfo(np.float32).eps)


def _raw(doc, accessor: int) -> np.ndarray:
    """An accessor's float32 VEC3 values straight from the data: URI (tightly packed)."""
    data = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    acc = doc["accessors"][accessor]
    view = doc["bufferViews"][acc["bufferView"]]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    return np.frombuffer(data, np.float32, acc["count"] * 3, start).reshape(-1, 3).astype(np.float64)


def _geometry(**kw):
    return load_gltf(MORPH, size=SIZE, environment=ENV, emit_warnings=False, **kw).scene.objects[0].geometry


TARGETS = DOC["meshes"][0]["primitives"][0]["targets"]
BASE = _raw(DOC, DOC["meshes"][0]["primitives"][0]["attributes"]["POSITION"])
BUMP, SHEAR = _raw(DOC, TARGETS[0]["POSITION"]), _raw(DOC, TARGETS[1]["POSITION"])
BUMP_NORMAL = _raw(DOC, TARGETS[0]["NORMAL"])


def test_a_weight_of_one_half_moves_the_vertices_halfway():
    base, half, full = (_geometry(weights=(w, 0.0)) for w in (0.0, 0.5, 1.0))
    assert np.abs(BUMP).max() > 0.5  # the bump rises 0.6 at its centre
    np.testing.assert_allclose(base.positions, BASE, rtol=0, atol=FLOAT32_SUM)
    np.testing.assert_allclose(half.positions, BASE + 0.5 * BUMP, rtol=0, atol=FLOAT32_SUM)
    np.testing.assert_allclose(full.positions, BASE + BUMP, rtol=0, atol=FLOAT32_SUM)
    np.testing.assert_allclose(half.positions, (base.positions + full.positions) / 2, rtol=0, atol=FLOAT32_SUM)
    # normals: base + w x delta, renormalised
    for geometry, w in ((half, 0.5), (full, 1.0)):
        n = np.array([0.0, 0.0, 1.0]) + w * BUMP_NORMAL
        np.testing.assert_allclose(geometry.normals, n / np.linalg.norm(n, axis=1, keepdims=True),
                                   rtol=0, atol=FLOAT32_SUM)


def test_two_targets_add():
    both = _geometry(weights=(0.25, -0.5))
    np.testing.assert_allclose(both.positions, BASE + 0.25 * BUMP - 0.5 * SHEAR, rtol=0, atol=FLOAT32_SUM)


def test_the_mesh_weights_are_the_default_and_node_weights_override_them():
    scene0 = load_gltf(MORPH, size=SIZE, environment=ENV, emit_warnings=False)
    assert scene0.warnings == []
    np.testing.assert_allclose(scene0.scene.objects[0].geometry.positions, BASE + 0.5 * BUMP,
                               rtol=0, atol=FLOAT32_SUM)  # mesh.weights [0.5, 0]
    np.testing.assert_allclose(_geometry(scene=1).positions, BASE + BUMP + SHEAR,
                               rtol=0, atol=FLOAT32_SUM)  # node 1's weights [1, 1]


def test_a_scene_index_picks_the_other_scene():
    default, first, second = (load_gltf(MORPH, size=SIZE, environment=ENV, emit_warnings=False, scene=s).scene
                              for s in (None, 0, 1))
    assert [o.transform[0, 3] for o in default.objects] == [o.transform[0, 3] for o in first.objects] == [-1.1]
    assert [o.transform[0, 3] for o in second.objects] == [1.1]
    assert len(second.lights) == 1
    images = [render_scene(s).linear[..., 3] > 0 for s in (first, second)]
    half = SIZE[0] // 2
    # the camera looks down the middle: scene 0's grid on the left, scene 1's on the right
    assert images[0][:, :half].sum() > 10 * images[0][:, half:].sum()
    assert images[1][:, half:].sum() > 10 * images[1][:, :half].sum()


@pytest.mark.parametrize("scene", [2, -1])
def test_an_out_of_range_scene_is_refused_naming_the_count(scene):
    with pytest.raises(SceneError, match=rf"morph_scenes.gltf: scenes: --scene {scene}: the file has 2 scenes "
                                         r"\(0 to 1\)$"):
        load_gltf(MORPH, scene=scene, emit_warnings=False)


def test_a_scene_of_a_file_without_scenes_is_refused(tmp_path):
    doc = quad_document()
    del doc["scenes"], doc["scene"]
    load_gltf(write(tmp_path, doc), emit_warnings=False)  # scene-less files draw their root nodes
    with pytest.raises(SceneError, match=r"scenes: --scene 0: the file has 0 scenes$"):
        load_gltf(write(tmp_path, doc), scene=0, emit_warnings=False)


def test_scene_and_weights_on_the_command_line(tmp_path, capsys):
    outputs = {}
    for name, options in (("default", []), ("half", ["--weights", "0.5,0"]), ("flat", ["--weights", "0,0"]),
                          ("scene1", ["--scene", "1"]), ("scene1_half", ["--scene", "1", "--weights", "0.5,0"])):
        out = tmp_path / f"{name}.png"
        assert cli.main(["render", str(MORPH), "-o", str(out), "--size", "48x32", *options]) == 0, name
        outputs[name] = out.read_bytes()
    assert outputs["half"] == outputs["default"]  # the mesh's weights are [0.5, 0]
    assert outputs["flat"] != outputs["default"]
    assert outputs["scene1"] != outputs["scene1_half"] != outputs["default"]


@pytest.mark.parametrize("options, message", [
    (["--weights", "1,2,3"], "meshes[0]: --weights gives 3 weights; mesh 0 has 2 morph targets"),
    (["--weights", "a,b"], "--weights a,b: expected finite numbers separated by commas"),
    (["--weights", "nan,0"], "--weights nan,0: expected finite numbers"),
    (["--scene", "5"], "--scene 5: the file has 2 scenes (0 to 1)"),
])
def test_bad_scene_and_weights_options_are_named(tmp_path, capsys, options, message):
    assert cli.main(["render", str(MORPH), "-o", str(tmp_path / "out.png"), *options]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err, err


def test_weights_for_a_file_without_morph_targets_are_refused(tmp_path, capsys):
    path = write(tmp_path, quad_document())
    assert cli.main(["render", str(path), "-o", str(tmp_path / "out.png"), "--weights", "1"]) == 2
    assert "meshes: --weights: the file has no morph targets" in capsys.readouterr().err


def _morph_doc(edit) -> dict:
    doc = copy.deepcopy(DOC)
    edit(doc)
    return doc


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["nodes"][0].update(weights=[1.0]), "nodes[0]: weights must be 2 numbers, got [1.0]"),
    (lambda d: d["meshes"][0].update(weights=[0.5, 0, 1]), "meshes[0]: weights must be 2 numbers"),
    (lambda d: d["meshes"][0]["primitives"].append(
        {k: v for k, v in d["meshes"][0]["primitives"][0].items() if k != "targets"}),
     "meshes[0]: its primitives have different numbers of morph targets ([2, 0])"),
    (lambda d: d["accessors"][TARGETS[1]["POSITION"]].update(count=80),
     f"targets[1].POSITION: accessor {TARGETS[1]['POSITION']} has 80 elements, expected 81"),
], ids=["node-weights-length", "mesh-weights-length", "primitives-disagree", "target-count"])
def test_a_broken_morph_is_named(tmp_path, edit, message):
    with pytest.raises(SceneError) as caught:
        load_gltf(write(tmp_path, _morph_doc(edit)), emit_warnings=False)
    assert message in str(caught.value)


def test_a_morph_target_of_another_attribute_is_named_in_a_warning(tmp_path):
    doc = _morph_doc(lambda d: d["meshes"][0]["primitives"][0]["targets"][1].update(
        COLOR_0=d["meshes"][0]["primitives"][0]["targets"][1]["POSITION"]))
    result = load_gltf(write(tmp_path, doc), emit_warnings=False)
    assert result.warnings == ["morph target attribute COLOR_0 ignored in mesh 0 primitive 0"]


def test_tangents_are_displaced_and_keep_their_handedness(tmp_path):
    doc = quad_document()
    tangents = np.tile(np.array([1, 0, 0, -1], np.float32), (4, 1))  # w = -1: a mirrored frame
    delta = np.tile(np.array([0, 1, 0], np.float32), (4, 1))
    data = blob(doc)
    start = len(data)
    set_blob(doc, data + tangents.tobytes() + delta.tobytes())
    doc["buffers"][0]["byteLength"] = start + 64 + 48
    doc["bufferViews"] += [{"buffer": 0, "byteOffset": start, "byteLength": 64},
                           {"buffer": 0, "byteOffset": start + 64, "byteLength": 48}]
    doc["accessors"] += [{"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC4"},
                         {"bufferView": 5, "componentType": 5126, "count": 4, "type": "VEC3"}]
    primitive = doc["meshes"][0]["primitives"][0]
    primitive["attributes"]["TANGENT"] = 4
    primitive["targets"] = [{"TANGENT": 5}]
    doc["meshes"][0]["weights"] = [1.0]
    geometry = load_gltf(write(tmp_path, doc), emit_warnings=False).scene.objects[0].geometry
    s = 1 / np.sqrt(2)  # (1, 0, 0) + 1 x (0, 1, 0), renormalised
    np.testing.assert_allclose(geometry.tangents, np.tile([s, s, 0, -1], (4, 1)), rtol=0, atol=FLOAT32_SUM)
