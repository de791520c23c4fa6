"""Malformed glTF files are refused with one message naming the object, exit status 2,
no traceback (pbrlab render and pbrlab features alike)."""

import struct

import pytest

from pbrlab.commands import cli

from gltf_helpers import blob, quad_document, set_blob, write


def _refused(tmp_path, capsys, doc_or_path, *expected, command="render"):
    path = doc_or_path if not isinstance(doc_or_path, dict) else write(tmp_path, doc_or_path)
    args = [command, str(path)] + (["-o", str(tmp_path / "out.png")] if command == "render" else [])
    assert cli.main(args) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    for text in expected:
        assert text in err, err
    return err


def test_the_valid_quad_renders(tmp_path, capsys):
    path = write(tmp_path, quad_document())
    assert cli.main(["render", str(path), "-o", str(tmp_path / "out.png"), "--size", "32x32"]) == 0


def test_missing_buffer_file_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["buffers"][0]["uri"] = "missing.bin"
    _refused(tmp_path, capsys, doc, "buffers[0]: file not found", "missing.bin")


def test_accessor_count_mismatch_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["accessors"][1]["count"] = 3
    doc["bufferViews"][1]["byteLength"] = 36
    _refused(tmp_path, capsys, doc,
             "meshes[0].primitives[0].attributes.NORMAL: accessor 1 has 3 elements, expected 4")


def test_wrong_accessor_type_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2  # a VEC2 accessor
    _refused(tmp_path, capsys, doc, "attributes.NORMAL: accessor 2 has type \"VEC2\", expected VEC3")


def test_wrong_component_type_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["accessors"][3]["componentType"] = 5126
    _refused(tmp_path, capsys, doc, "meshes[0].primitives[0].indices: accessor 3 has components FLOAT")


def test_out_of_range_index_is_named(tmp_path, capsys):
    doc = quad_document()
    data = bytearray(blob(doc))
    data[128 + 4:128 + 6] = struct.pack("<H", 9)  # the third index
    set_blob(doc, bytes(data))
    _refused(tmp_path, capsys, doc, "meshes[0].primitives[0].indices: index 9 at position 2 is out of range",
             "4 vertices")


def test_non_finite_position_is_named(tmp_path, capsys):
    doc = quad_document()
    data = bytearray(blob(doc))
    data[12:16] = struct.pack("<f", float("nan"))
    set_blob(doc, bytes(data))
    _refused(tmp_path, capsys, doc, "attributes.POSITION: accessor 0 holds a non-finite value (element 1")


def test_accessor_past_its_buffer_view_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["accessors"][0]["count"] = 4
    doc["accessors"][0]["byteOffset"] = 12
    _refused(tmp_path, capsys, doc, "accessor 0 needs 60 bytes of bufferViews[0], which has 48")


def test_buffer_view_past_its_buffer_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["bufferViews"][3]["byteLength"] = 400
    _refused(tmp_path, capsys, doc, "bufferViews[3]: bytes 128..528 lie outside buffers[0]")


def test_unknown_required_extension_is_refused(tmp_path, capsys):
    doc = quad_document()
    doc["extensionsRequired"] = ["EXT_lights_image_based"]
    doc["extensionsUsed"] = ["EXT_lights_image_based"]
    _refused(tmp_path, capsys, doc, "extensionsRequired: EXT_lights_image_based is required")
    _refused(tmp_path, capsys, doc, "EXT_lights_image_based", command="features")


def test_dangling_references_are_named(tmp_path, capsys):
    doc = quad_document()
    doc["nodes"][0]["mesh"] = 5
    _refused(tmp_path, capsys, doc, "nodes[0].mesh: refers to meshes[5], but the file has 1 meshes")
    doc = quad_document()
    doc["meshes"][0]["primitives"][0]["material"] = 3
    _refused(tmp_path, capsys, doc, "meshes[0].primitives[0].material: refers to materials[3]")


def test_node_cycle_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["nodes"].append({"children": [0]})
    doc["nodes"][0]["children"] = [1]
    _refused(tmp_path, capsys, doc, "appears twice in the hierarchy")


def test_material_factor_out_of_range_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 1.5
    _refused(tmp_path, capsys, doc, "materials[0].pbrMetallicRoughness: roughnessFactor must be a number in [0, 1]")


def test_missing_texture_image_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["images"] = [{"uri": "nowhere.png"}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    _refused(tmp_path, capsys, doc, "images[0]: file not found", "nowhere.png")


def test_unreadable_image_is_named(tmp_path, capsys):
    doc = quad_document()
    (tmp_path / "junk.png").write_bytes(b"not a png")
    doc["images"] = [{"uri": "junk.png"}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["normalTexture"] = {"index": 0}
    _refused(tmp_path, capsys, doc, "images[0]: is not a readable PNG, JPEG or WebP image")


def test_bad_light_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "spot", "spot": {
        "innerConeAngle": 0.6, "outerConeAngle": 0.5}}]}}
    doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc["scenes"][0]["nodes"].append(1)
    _refused(tmp_path, capsys, doc, "extensions.KHR_lights_punctual.lights[0].spot: innerConeAngle (0.6) "
                                    "must be smaller than outerConeAngle (0.5)")


def test_camera_index_not_placed_is_named(tmp_path, capsys):
    path = write(tmp_path, quad_document())
    assert cli.main(["render", str(path), "-o", str(tmp_path / "o.png"), "--camera", "2"]) == 2
    assert "--camera 2: no node places camera 2" in capsys.readouterr().err


@pytest.mark.parametrize("content, message", [
    (b"{not json", "not a readable glTF 2.0 file (invalid JSON"),
    (b'{"asset": {"version": "1.0"}}', "asset.version is \"1.0\""),
    (b"glTF" + struct.pack("<II", 2, 400) + b"\0" * 12, "the GLB header says 400 bytes"),
    (b"glTF" + struct.pack("<II", 2, 28) + struct.pack("<II", 8, 0x004E4942) + b"\0" * 8,
     "the first GLB chunk is not JSON"),
])
def test_unreadable_files_are_named(tmp_path, capsys, content, message):
    path = tmp_path / ("model.glb" if content.startswith(b"glTF") else "model.gltf")
    path.write_bytes(content)
    _refused(tmp_path, capsys, path, message)
    _refused(tmp_path, capsys, path, message, command="features")


def test_texture_reading_a_missing_uv_set_is_named(tmp_path, capsys):
    doc = quad_document()
    doc["images"] = [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGP4z8AAAAMBAQDJ/pLvAAAAAElFTkSuQmCC"}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["occlusionTexture"] = {"index": 0, "texCoord": 1}
    _refused(tmp_path, capsys, doc, 'meshes[0].primitives[0]: material "paint" reads TEXCOORD_1 '
                                    "(occlusion texture), which the primitive lacks")


@pytest.mark.parametrize("path, value, message", [
    (("materials",), "gold", "materials: expected an array, got \"gold\""),
    (("nodes", 0), 3, "nodes[0]: expected an object, got 3"),
    (("nodes", 0, "mesh"), "a", "nodes[0].mesh: expected an index into meshes, got \"a\""),
    (("nodes", 0, "mesh"), 0.0, "nodes[0].mesh: expected an index into meshes, got 0.0"),
    (("accessors", 0, "count"), True, "accessors[0]: count must be a positive integer, got true"),
    (("meshes", 0, "primitives", 0, "mode"), 4.0, "meshes[0].primitives[0]: mode must be one of 0 (POINTS)"),
    (("materials", 0, "doubleSided"), "yes", "materials[0]: doubleSided must be true or false, got \"yes\""),
    (("materials", 0, "name"), 5, "materials[0]: name must be a string, got 5"),
    (("materials", 0, "alphaMode"), "opaque", "materials[0]: alphaMode must be one of OPAQUE, MASK, BLEND"),
    (("materials", 0, "emissiveFactor"), [0, 0], "materials[0]: emissiveFactor must be 3 numbers in [0, 1]"),
    (("bufferViews", 0, "byteStride"), 2, "bufferViews[0]: byteStride must be an integer in [4, 252], got 2"),
    (("nodes", 0, "rotation"), [0, 0, 0, 2], "nodes[0]: rotation must be 4 numbers in [-1, 1]"),
    (("scenes", 0, "nodes"), [0, 0], "scenes[0].nodes: names an index twice"),
    (("extensionsUsed",), [1], "extensionsUsed[0]: expected a string, got 1"),
    (("meshes", 0, "primitives", 0, "attributes"), [], "meshes[0].primitives[0].attributes: expected an object"),
])
def test_a_field_of_the_wrong_type_or_range_is_named_by_path(tmp_path, capsys, path, value, message):
    """The schema's types and ranges (spec section 5), read through gltf/fields.py: no
    Python exception escapes, the message names the field's path."""
    doc = quad_document()
    node = doc
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    _refused(tmp_path, capsys, doc, message)
