"""KHR_materials_specular mapped by the glTF importer (gltf/materials.py) as the extension
defines it, against reference/specular_extension.py: every material of Khronos' SpecularTest
(corpus/gltf/khronos) and a few written here, dielectric and (partly) metallic."""

import base64
import json
import struct
import zlib
from pathlib import Path

import numpy as np
import pytest

from pbrlab.importers.gltf import load_gltf
from pbrlab.maths.reference import specular_extension as ext

CORPUS = Path(__file__).resolve().parents[3] / "corpus" / "gltf" / "khronos"


def _glb_json(path: Path) -> dict:
    data = path.read_bytes()
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A  # "JSON"
    return json.loads(data[20:20 + length])


def test_specular_tests_materials_map_to_the_extensions_f0_and_f90():
    path = CORPUS / "SpecularTest" / "SpecularTest.glb"
    doc = _glb_json(path)
    result = load_gltf(path, size=(32, 32), emit_warnings=False)
    by_name = {m.name: m for m in result.scene.materials.values()}
    checked = 0
    for spec in doc["materials"]:
        extension = spec.get("extensions", {}).get("KHR_materials_specular")
        if extension is None or spec.get("pbrMetallicRoughness", {}).get("metallicFactor", 1.0) != 0.0:
            continue
        ior = spec.get("extensions", {}).get("KHR_materials_ior", {}).get("ior", 1.5)
        strength = extension.get("specularFactor", 1.0)
        colour = extension.get("specularColorFactor", [1.0, 1.0, 1.0])
        m = by_name[spec["name"]]
        assert m.workflow == "specular"
        np.testing.assert_allclose(m.specular, ext.dielectric_f0(ior, colour, strength), rtol=1e-15, atol=0)
        assert m.specular_f90 == ext.dielectric_f90(strength)
        checked += 1
    assert checked >= 10, checked  # SpecularTest's factor, texture and colour rows


@pytest.mark.parametrize("extensions, f0, f90", [
    ({"KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [50, 0, 0.5]}},
     [0.5, 0.0, 0.01], 0.5),                       # the clamp before the strength
    ({"KHR_materials_specular": {"specularColorFactor": [0, 0, 0]}}, [0, 0, 0], 1.0),  # black, rim-lit
    ({"KHR_materials_ior": {"ior": 1.2}}, [((1.2 - 1) / 2.2) ** 2] * 3, None),  # IOR alone: F90 from F0
])
def test_a_dielectrics_specular_extension_sets_f0_and_f90(tmp_path, extensions, f0, f90):
    material = _material(tmp_path, {"metallicFactor": 0.0}, extensions)
    assert material.workflow == "specular" and material.dielectric_specular is None
    np.testing.assert_allclose(material.specular, f0, rtol=1e-12, atol=1e-15)
    assert material.specular_f90 == f90


@pytest.mark.parametrize("pbr", [{"metallicFactor": 0.5}, {"metallicFactor": 1.0, "metallicRoughnessTexture": {"index": 0}}],
                         ids=["half_metal", "metal_map"])
@pytest.mark.parametrize("extensions, f0, f90", [
    ({"KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [50, 0, 0.5]}},
     [0.5, 0.0, 0.01], 0.5),
    ({"KHR_materials_specular": {"specularColorFactor": [0, 0, 0]}, "KHR_materials_ior": {"ior": 2.0}},
     [0, 0, 0], 1.0),
    ({"KHR_materials_ior": {"ior": 1.2}}, [((1.2 - 1) / 2.2) ** 2] * 3, None),
])
def test_a_partly_metallic_materials_specular_extension_sets_its_dielectric(tmp_path, pbr, extensions, f0, f90):
    """The metallic workflow kept, the dielectric's F0 and F90 as the extension's
    dielectric_f0 and dielectric_f90 (mixed with the base colour by metallic in the shader)."""
    material = _material(tmp_path, pbr, extensions)
    assert material.workflow == "metallic" and material.metallic == pbr["metallicFactor"]
    np.testing.assert_allclose(material.dielectric_specular, f0, rtol=1e-12, atol=1e-15)
    assert material.specular_f90 == f90


def test_a_pure_metals_specular_extension_changes_nothing(tmp_path):
    """metallicFactor 1 without a map: F0 = base colour and F90 = 1 whatever the dielectric."""
    material = _material(tmp_path, {"metallicFactor": 1.0},
                         {"KHR_materials_specular": {"specularFactor": 0.2}, "KHR_materials_ior": {"ior": 2.0}})
    assert material.dielectric_specular is None and material.specular_f90 is None


@pytest.mark.parametrize("layer", [{"KHR_materials_anisotropy": {"anisotropyStrength": 0.6}},
                                   {"KHR_materials_iridescence": {"iridescenceFactor": 1.0}},
                                   {"KHR_materials_transmission": {"transmissionFactor": 0.8}}],
                         ids=["anisotropy", "iridescence", "transmission"])
def test_the_f90_is_kept_beside_the_layers_that_change_the_base(tmp_path, layer):
    """The base's anisotropic lobe, film and transmission read the explicit F90
    (pbr/unity/surface_layers.glsl): the importer keeps it and warns about none of them."""
    extensions = {"KHR_materials_specular": {"specularFactor": 0.5}, **layer}
    material = _material(tmp_path, {"metallicFactor": 0.0}, extensions)
    assert material.specular_f90 == 0.5


def _material(tmp_path, pbr, extensions):
    """The one material of a one-triangle glTF (positions, and UVs for a texture)."""
    data = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32).tobytes() + bytes(24)  # + 3 UVs of 0
    doc = {"asset": {"version": "2.0"}, "materials": [
        {"name": "m", "pbrMetallicRoughness": pbr, "extensions": extensions}],
        "extensionsUsed": list(extensions),
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}
    if "metallicRoughnessTexture" in pbr:  # a 1x1 PNG (the importer reads it)
        doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(_png_1x1()).decode()}]
        doc["textures"] = [{"source": 0}]
    (tmp_path / "m.gltf").write_text(json.dumps(doc))
    result = load_gltf(tmp_path / "m.gltf", size=(8, 8), emit_warnings=False)
    assert not [w for w in result.warnings if "KHR_materials" in w], result.warnings
    return next(iter(result.scene.materials.values()))


def _png_1x1() -> bytes:
    """One RGB texel (0, 128, 255): metallic 1 in B, roughness 0.5 in G."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(b"\x00\x00\x80\xff")) + chunk(b"IEND", b""))
