"""EXT_meshopt_compression (gltf/meshopt.py, the meshoptimizer bindings): make_delivered_assets.py
compresses every buffer view of meshopt_instances.glb (all three modes, all three filters:
sphere positions, OCTAHEDRAL BYTE normals, EXPONENTIAL UVs, TRIANGLES indices, a strip's
INDICES, instance TRANSLATION and QUATERNION SHORT rotations; a placeholder fallback
buffer). meshopt_instances_plain.glb stores the same views uncompressed, the filtered ones
as the extension's Appendix B decodes them, computed in the generator in numpy: the decoder
here (meshoptimizer's C++) and that one are independent."""

from __future__ import annotations

import numpy as np
import pytest

from gltf_helpers import read_glb, write_glb
from pbrlab.foundation.errors import SceneError
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import load_gltf, meshopt
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment
from test_gltf_errors import _refused

ENV = Environment(color=np.array([0.3, 0.3, 0.35]))
SIZE = (96, 64)
COMPRESSED, PLAIN = GLTF_DIR / "meshopt_instances.glb", GLTF_DIR / "meshopt_instances_plain.glb"
# Appendix B: "decoding may produce results within 1 ULP", one unit of the normalized
# integer: 1/127 for the BYTE normals, 1/32767 for the SHORT rotations (float64 here).
BYTE_ULP, SHORT_ULP = 1 / 127, 1 / 32767


def _load(path):
    return load_gltf(path, size=SIZE, environment=ENV, emit_warnings=False)


def test_the_compressed_views_decode_to_the_plain_twin():
    compressed, plain = _load(COMPRESSED), _load(PLAIN)
    assert compressed.warnings == [] and len(compressed.scene.objects) == 4  # three instances and the floor
    for a, b in zip(compressed.scene.objects, plain.scene.objects):
        # lossless codecs: positions, UVs (EXPONENTIAL: 2^e x m is exact in float32), indices
        for field in ("positions", "uv"):
            np.testing.assert_array_equal(getattr(a.geometry, field), getattr(b.geometry, field), err_msg=field)
        # the TRIANGLES codec keeps the triangles and their order but may rotate a triangle's
        # corners (meshoptimizer's README: "preserving winding")
        np.testing.assert_array_equal(_rotated_to_smallest(a.geometry.indices), _rotated_to_smallest(b.geometry.indices))
        np.testing.assert_allclose(a.geometry.normals, b.geometry.normals, rtol=0, atol=BYTE_ULP)
        # QUATERNION rotations: a rotation matrix's entries move by at most 2 x 1 ULP per component
        np.testing.assert_allclose(a.transform, b.transform, rtol=0, atol=4 * SHORT_ULP)


def _rotated_to_smallest(indices: np.ndarray) -> np.ndarray:
    """Each triangle's corners rotated (winding kept) to start at its smallest index."""
    triangles = indices.reshape(-1, 3)
    shift = np.argmin(triangles, axis=1)
    return np.stack([triangles[np.arange(len(triangles)), (shift + k) % 3] for k in range(3)], axis=1)


def test_the_compressed_file_renders_as_its_plain_twin():
    compressed, plain = render_scene(_load(COMPRESSED).scene), render_scene(_load(PLAIN).scene)
    assert (plain.linear[..., 3] > 0).mean() > 0.3
    np.testing.assert_array_equal(compressed.srgb8, plain.srgb8)  # measured: the same 8-bit codes
    # linear: a rotated triangle interpolates its attributes in another order; float32
    # rounding of the barycentric sums, measured 6.6e-6 worst (481 of 24 576 values)
    np.testing.assert_allclose(compressed.linear, plain.linear, rtol=0, atol=2e-5)


def test_required_meshopt_without_the_bindings_names_the_extension_and_the_install(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(meshopt, "available", lambda: False)
    _refused(tmp_path, capsys, COMPRESSED, "extensionsRequired: EXT_meshopt_compression is required by the file "
                                           "and its decoder is not installed (pip install meshoptimizer==0.2.30a0)")


def _view(doc, accessor: int) -> dict:
    return doc["bufferViews"][doc["accessors"][accessor]["bufferView"]]


def _ext(doc, accessor: int) -> dict:
    return _view(doc, accessor)["extensions"]["EXT_meshopt_compression"]


@pytest.mark.parametrize("edit, message", [
    (lambda d: _view(d, 0).update(byteLength=_view(d, 0)["byteLength"] + 4),
     r"the buffer view's byteLength 1948 is not byteStride x count = 1944"),
    (lambda d: _ext(d, 0).update(byteStride=16),
     r"byteStride 16 differs from the buffer view's 12"),
    (lambda d: _ext(d, 3).update(filter="OCTAHEDRAL"),
     r"filter OCTAHEDRAL applies to ATTRIBUTES only, not TRIANGLES"),
    (lambda d: _ext(d, 1).update(filter="QUATERNION"),
     r"byteStride 4: filter QUATERNION needs 8"),
    (lambda d: _ext(d, 0).update(byteLength=_ext(d, 0)["byteLength"] - 40),
     r"the ATTRIBUTES data does not decode"),
    (lambda d: _ext(d, 3).update(byteLength=_ext(d, 3)["byteLength"] - 8),
     r"the TRIANGLES data does not decode"),
    (lambda d: _ext(d, 0).update(mode="VERTICES"),
     r"mode must be one of ATTRIBUTES, TRIANGLES, INDICES"),
], ids=["view-length", "stride-mismatch", "filter-on-indices", "quaternion-stride",
        "truncated-attributes", "truncated-triangles", "unknown-mode"])
def test_a_compressed_view_that_breaks_the_rules_is_named(tmp_path, edit, message):
    doc, binary = read_glb(COMPRESSED)
    edit(doc)
    with pytest.raises(SceneError, match=message):
        _load(write_glb(tmp_path, doc, binary))


def test_an_optional_meshopt_view_without_the_bindings_names_the_install(tmp_path, monkeypatch):
    doc, binary = read_glb(COMPRESSED)
    doc["extensionsRequired"].remove("EXT_meshopt_compression")  # used, not required
    monkeypatch.setattr(meshopt, "available", lambda: False)
    with pytest.raises(SceneError, match=r"bufferViews\[\d+\]: its data is EXT_meshopt_compression-compressed and "
                                         r"buffers\[1\] is only a placeholder; install the decoder: "
                                         r"pip install meshoptimizer==0.2.30a0"):
        _load(write_glb(tmp_path, doc, binary))
