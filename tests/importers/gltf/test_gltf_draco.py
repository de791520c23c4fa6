"""KHR_draco_mesh_compression (gltf/draco.py, DracoPy): scenes/gltf/make_delivered_assets.py
encodes an icosphere with DracoPy (positions 14 bits, normals 10, UVs 12) into
draco_sphere.glb (compressed only) and draco_sphere_fallback.glb (the same Draco data and
an uncompressed fallback holding what it decodes to); sphere_source.glb is the source."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from gltf_helpers import read_glb, write_glb
from pbrlab.checking.compare import Tolerance, diff
from pbrlab.foundation.errors import SceneError
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import draco, load_gltf
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment
from test_gltf_errors import _refused

ENV = Environment(color=np.array([0.3, 0.3, 0.35]))
SIZE = (96, 64)
COMPRESSED, FALLBACK, SOURCE = (GLTF_DIR / n for n in ("draco_sphere.glb", "draco_sphere_fallback.glb",
                                                       "sphere_source.glb"))
# Draco's quantisation (draco::AttributeQuantizationTransform): a step of range / (2^bits - 1)
# over the attribute's largest extent, values rounded to the nearest step.
POSITION_BITS, UV_BITS, SPHERE_EXTENT, UV_EXTENT = 14, 12, 2.0, 1.0
FLOAT32_AT_ONE = float(np.finfo(np.float32).eps)  # the importer stores float32 (and flips v in float64)
# 10-bit octahedral normals: measured 0.216 degrees worst on this sphere; 0.3 allows another
# Draco build's rounding and no mapping error (a normal read from the UVs is tens of degrees off)
NORMAL_DEGREES = 0.3
RENDER = Tolerance(1, 0.005, "8-bit codes: the 14-bit positions and 10-bit normals move shading by 1 code at "
                             "4.3 % of pixels and 2 codes at 0.08 % (5 of 6144, silhouette), measured")


def _load(path, **kw):
    return load_gltf(path, size=SIZE, environment=ENV, emit_warnings=False, **kw)


def _without_dracopy(monkeypatch):
    monkeypatch.setattr(draco, "available", lambda: False)


def test_the_draco_sphere_renders_as_the_data_it_decodes_to(monkeypatch):
    compressed = _load(COMPRESSED)
    assert compressed.warnings == []
    with_draco = render_scene(_load(FALLBACK).scene).linear  # the fallback is ignored when decoding
    _without_dracopy(monkeypatch)
    fallback = _load(FALLBACK)
    assert fallback.warnings == ["KHR_draco_mesh_compression ignored in mesh 0 primitive 0 (DracoPy is not "
                                 "installed: pip install DracoPy==2.2.0; the uncompressed fallback is drawn)"]
    expected = render_scene(fallback.scene).linear
    obtained = render_scene(compressed.scene).linear
    assert (expected[..., 3] > 0).mean() > 0.15  # the sphere fills its part of the frame
    np.testing.assert_array_equal(obtained, expected)
    np.testing.assert_array_equal(with_draco, expected)


def test_the_draco_sphere_is_its_source_within_the_quantisation():
    decoded = _load(COMPRESSED).scene.objects[0].geometry
    source = _load(SOURCE).scene.objects[0].geometry
    # Draco reorders vertices: each decoded vertex against its nearest source vertex
    _, nearest = cKDTree(source.positions.astype(np.float64)).query(decoded.positions.astype(np.float64))
    assert len(decoded.positions) == len(source.positions) == len(set(nearest.tolist()))  # one to one
    assert len(decoded.indices) == len(source.indices)
    position_step = SPHERE_EXTENT / (2 ** POSITION_BITS - 1)
    assert np.abs(decoded.positions - source.positions[nearest]).max() <= position_step / 2 + FLOAT32_AT_ONE
    uv_step = UV_EXTENT / (2 ** UV_BITS - 1)
    assert np.abs(decoded.uv - source.uv[nearest]).max() <= uv_step / 2 + 2 * FLOAT32_AT_ONE
    cosines = np.clip((decoded.normals * source.normals[nearest]).sum(axis=1), -1, 1)
    assert np.degrees(np.arccos(cosines)).max() <= NORMAL_DEGREES
    # the same triangles, by their source vertices (Draco may rotate a triangle's corners)
    def triangles(indices, remap):
        corners = np.sort(remap[indices.reshape(-1, 3)], axis=1)
        return corners[np.lexsort(corners.T[::-1])]
    np.testing.assert_array_equal(triangles(decoded.indices, nearest),
                                  triangles(source.indices, np.arange(len(source.positions))))


def test_the_draco_sphere_renders_as_its_source_within_the_quantisation():
    obtained = render_scene(_load(COMPRESSED).scene).srgb8
    expected = render_scene(_load(SOURCE).scene).srgb8
    result = diff(expected, obtained, RENDER)
    assert result.passed, result.summary()
    assert result.max_abs <= 3, result.summary()  # measured 2


def test_required_draco_without_dracopy_names_the_extension_and_the_install(tmp_path, capsys, monkeypatch):
    _without_dracopy(monkeypatch)
    _refused(tmp_path, capsys, COMPRESSED, "extensionsRequired: KHR_draco_mesh_compression is required by the "
                                           "file and its decoder is not installed (pip install DracoPy==2.2.0)")


def _edited(tmp_path, edit):
    doc, binary = read_glb(COMPRESSED)
    edit(doc)
    return write_glb(tmp_path, doc, binary)


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]
     .update(NORMAL=7), r"attributes: NORMAL: attribute id 7 is not in the Draco data \(ids: \[0, 1, 2\]\)"),
    (lambda d: d["accessors"][0].update(count=600),
     r"attributes.POSITION: the compressed data decodes 642 elements of 3 components; accessor 0 says 600 of 3"),
    (lambda d: d["accessors"][3].update(count=30),
     r"indices: the compressed data decodes 3840 elements of 1 components; accessor 3 says 30 of 1"),
    (lambda d: d["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]
     .update(TEXCOORD_1=2), r"TEXCOORD_1 is not one of the primitive's attributes"),
    (lambda d: d["bufferViews"][d["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
     ["bufferView"]].update(byteOffset=0),
     r"KHR_draco_mesh_compression: bufferViews\[\d+\] is not a Draco mesh DracoPy decodes"),
    (lambda d: d["meshes"][0]["primitives"][0].update(mode=6),
     r"mode TRIANGLE_FAN: KHR_draco_mesh_compression holds TRIANGLES or TRIANGLE_STRIP only"),
], ids=["unknown-attribute-id", "position-count", "index-count", "attribute-not-in-primitive",
        "not-draco-data", "fan-mode"])
def test_a_draco_primitive_that_disagrees_with_its_data_is_named(tmp_path, edit, message):
    with pytest.raises(SceneError, match=message):
        _load(_edited(tmp_path, edit))
