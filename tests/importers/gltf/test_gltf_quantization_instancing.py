"""KHR_mesh_quantization (integer attributes, normalized or not) and EXT_mesh_gpu_instancing
(one mesh drawn per instance), each against the same geometry written the plain way."""

from __future__ import annotations

import base64
import copy

import numpy as np
import pytest

from gltf_helpers import quad_document, write
from pbrlab.foundation.errors import SceneError
from pbrlab.importers.gltf import load_gltf
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment

ENV = Environment(color=np.array([0.5, 0.6, 0.7]))
SIZE = (48, 32)


def _strided(values: np.ndarray, stride: int) -> bytes:
    """Elements padded to ``stride`` bytes (KHR_mesh_quantization: attribute strides are
    multiples of 4)."""
    raw = values.reshape(len(values), -1).view(np.uint8)
    out = np.zeros((len(values), stride), np.uint8)
    out[:, :raw.shape[1]] = raw
    return out.tobytes()


def quantized_quad(with_extension: bool = True) -> dict:
    """quad_document's quad with SHORT normalized positions (+-32767 is +-1 exactly), BYTE
    normalized normals (127 is 1) and UNSIGNED_BYTE UVs that are not normalized (0 and 1)."""
    positions = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.int16) * 32767
    normals = np.tile(np.array([0, 0, 127], np.int8), (4, 1))
    uv = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.uint8)
    indices = np.array([0, 1, 2, 0, 2, 3], np.uint16)
    parts = [_strided(positions, 8), _strided(normals, 4), _strided(uv, 4), indices.tobytes()]
    offsets = np.cumsum([0] + [len(p) for p in parts])
    blob = b"".join(parts)
    doc = quad_document()
    doc["buffers"] = [{"byteLength": len(blob),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]
    doc["bufferViews"] = [{"buffer": 0, "byteOffset": int(offsets[i]), "byteLength": len(parts[i]),
                           **({"byteStride": s} if s else {})} for i, s in enumerate((8, 4, 4, 0))]
    doc["accessors"] = [
        {"bufferView": 0, "componentType": 5122, "normalized": True, "count": 4, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5120, "normalized": True, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5121, "count": 4, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
    ]
    if with_extension:
        doc["extensionsUsed"] = doc["extensionsRequired"] = ["KHR_mesh_quantization"]
    return doc


def _load(tmp_path, doc, name="model.gltf"):
    return load_gltf(write(tmp_path, doc, name), environment=ENV, size=SIZE, emit_warnings=False)


def test_a_quantized_quad_is_the_float_quad(tmp_path):
    plain = _load(tmp_path, quad_document(), "plain.gltf")
    quantized = _load(tmp_path, quantized_quad(), "quantized.gltf")
    assert quantized.warnings == []  # the extension is honoured, required or not
    a, b = plain.scene.objects[0].geometry, quantized.scene.objects[0].geometry
    for field in ("positions", "normals", "uv", "tangents", "indices"):
        np.testing.assert_array_equal(getattr(b, field), getattr(a, field), err_msg=field)
    np.testing.assert_array_equal(render_scene(quantized.scene).linear, render_scene(plain.scene).linear)


def test_quantized_types_without_the_extension_are_refused_with_a_hint(tmp_path):
    with pytest.raises(SceneError, match=r"POSITION: accessor 0 has components SHORT normalized, expected "
                                         r"FLOAT \(or, with KHR_mesh_quantization in extensionsUsed, that type\)"):
        _load(tmp_path, quantized_quad(with_extension=False))


def test_normals_must_be_normalized_even_quantized(tmp_path):
    doc = quantized_quad()
    doc["accessors"][1]["normalized"] = False
    with pytest.raises(SceneError, match=r"NORMAL: accessor 1 has components BYTE, expected"):
        _load(tmp_path, doc)


# --- EXT_mesh_gpu_instancing -----------------------------------------------------------

TRANSLATIONS = np.array([[-2.5, 0, 0], [0, 0.5, -1], [2.5, 0, 0]], np.float32)
ROTATIONS = np.array([[0, 0, 0, 1], [0, 0.38268343, 0, 0.9238795], [0.5, 0.5, 0.5, 0.5]], np.float32)
SCALES = np.array([[1, 1, 1], [0.5, 2, 1], [1, -1, 1]], np.float32)  # the last one mirrors


def _instanced(base: dict, attributes=("TRANSLATION", "ROTATION", "SCALE")) -> dict:
    doc = copy.deepcopy(base)
    data = {"TRANSLATION": TRANSLATIONS, "ROTATION": ROTATIONS, "SCALE": SCALES}
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    ext = {}
    for name in attributes:
        doc["bufferViews"].append({"buffer": 0, "byteOffset": len(blob), "byteLength": data[name].nbytes})
        doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5126,
                                 "count": 3, "type": "VEC4" if name == "ROTATION" else "VEC3"})
        ext[name] = len(doc["accessors"]) - 1
        blob += data[name].tobytes()
    doc["buffers"] = [{"byteLength": len(blob),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]
    doc["nodes"] = [{"mesh": 0, "translation": [0, -0.5, 0],
                     "extensions": {"EXT_mesh_gpu_instancing": {"attributes": ext}}}]
    doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
    return doc


def _one_node_each(base: dict) -> dict:
    """The same instances as child nodes with TRS (the node's transform first)."""
    doc = copy.deepcopy(base)
    doc["nodes"] = [{"translation": [0, -0.5, 0], "children": [1, 2, 3]}] + [
        {"mesh": 0, "translation": t.tolist(), "rotation": r.tolist(), "scale": s.tolist()}
        for t, r, s in zip(TRANSLATIONS, ROTATIONS, SCALES)]
    return doc


def test_instances_are_the_nodes_they_stand_for(tmp_path):
    instanced = _load(tmp_path, _instanced(quad_document()), "instanced.gltf")
    nodes = _load(tmp_path, _one_node_each(quad_document()), "nodes.gltf")
    assert instanced.warnings == [] and len(instanced.scene.objects) == 3
    for a, b in zip(instanced.scene.objects, nodes.scene.objects):
        np.testing.assert_allclose(a.transform, b.transform, rtol=0, atol=1e-12)
        np.testing.assert_array_equal(a.geometry.indices, b.geometry.indices)  # the mirror's winding too
    np.testing.assert_array_equal(render_scene(instanced.scene).linear, render_scene(nodes.scene).linear)


def test_instances_without_rotation_and_scale_are_translated(tmp_path):
    result = _load(tmp_path, _instanced(quad_document(), ("TRANSLATION",)))
    got = np.array([o.transform[:3, 3] for o in result.scene.objects])
    np.testing.assert_allclose(got, TRANSLATIONS + [0, -0.5, 0], rtol=0, atol=1e-7)
    assert all(np.array_equal(o.transform[:3, :3], np.eye(3)) for o in result.scene.objects)


def test_instance_attributes_of_different_counts_are_refused(tmp_path):
    doc = _instanced(quad_document())
    doc["accessors"][-1]["count"] = 2  # SCALE
    with pytest.raises(SceneError, match=r"EXT_mesh_gpu_instancing.attributes.SCALE: accessor \d+ has 2 elements, "
                                         r"expected 3"):
        _load(tmp_path, doc)


@pytest.mark.parametrize("unlit", [False, True], ids=["lit_without_light", "KHR_materials_unlit"])
def test_instances_draw_when_the_program_never_reads_the_normal(tmp_path, unlit):
    """A program that reads no normal (a scene without light or environment, an unlit
    material) has no in_normal_matrix attribute. Main: the instanced draw named it anyway,
    a KeyError traceback from moderngl (found rendering 3,000 instances of a file without
    lights, issue 39)."""
    from pbrlab.render.empty_frame import empty_frame_reason

    doc = _instanced(quad_document())
    if unlit:
        doc["materials"][0].setdefault("extensions", {})["KHR_materials_unlit"] = {}
        doc["extensionsUsed"].append("KHR_materials_unlit")
    scene = load_gltf(write(tmp_path, doc), environment=None, size=SIZE, emit_warnings=False).scene
    linear = render_scene(scene).linear
    covered = linear[..., 3] > 0
    assert covered.mean() > 0.05
    if unlit:  # the base colour as it is: (0.8, 0.2, 0.1) in linear
        np.testing.assert_allclose(np.median(linear[..., :3][covered], axis=0), doc["materials"][0][
            "pbrMetallicRoughness"]["baseColorFactor"][:3], rtol=1e-6)
        assert empty_frame_reason(scene, linear) is None
    else:  # no light at all: black, and said so (render.empty_frame)
        assert not np.any(linear[..., :3][covered])
        assert "no light and no environment" in empty_frame_reason(scene, linear)


@pytest.mark.parametrize("component", [{}, [5122], "SHORT", None])
def test_a_component_type_that_is_no_number_is_refused_in_a_quantized_file(tmp_path, component):
    """Main: with KHR_mesh_quantization in extensionsUsed, a componentType of {} or [5122]
    ended in "TypeError: unhashable type" (found by mutating MeshPrimitiveModes.gltf)."""
    doc = quantized_quad()
    doc["accessors"][0]["componentType"] = component
    with pytest.raises(SceneError, match=r"POSITION: accessor 0 has components .*, expected"):
        _load(tmp_path, doc)
