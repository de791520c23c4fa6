"""KHR_draco_mesh_compression: a primitive's attributes and indices decoded from a Draco
buffer view through DracoPy (Google's Draco decoder, bitstream 2.2).

The extension's README, "Conformance": the loader decodes the extension's ``bufferView``
first; each attribute it lists (glTF semantic -> Draco attribute unique id) takes its
values from the decoded geometry instead of its accessor's ``bufferView``, ``byteOffset``
(and ``sparse``, which only an uncompressed fallback may carry); the accessors still
give the count, type and componentType the decoded data must match; attributes the
extension does not list are read as usual. Draco returns quantised attributes already
dequantised (float32) and its faces as a triangle list ("Restrictions on geometry type":
TRIANGLES or TRIANGLE_STRIP, "decoded accordingly": Draco stores triangles either way).
"""

from __future__ import annotations

import importlib.util
from dataclasses import dataclass

import numpy as np

from .fields import FieldReader

EXTENSION = "KHR_draco_mesh_compression"
PACKAGE = "DracoPy"
INSTALL = "pip install DracoPy==2.2.0"


def available() -> bool:
    return importlib.util.find_spec(PACKAGE) is not None


@dataclass
class DracoGeometry:
    attributes: dict  # glTF semantic -> decoded values (points x components), Draco's dtype
    indices: np.ndarray  # (faces * 3,) int64: the triangle list


def decode(doc, spec: FieldReader, attributes: FieldReader) -> DracoGeometry:
    """The decoded geometry of one primitive's extension object ``spec``; ``attributes``:
    the primitive's own attributes (the extension's must be a subset of them)."""
    import DracoPy

    view_index = spec.index("bufferView", "bufferViews", required=True)
    _, data = doc.buffer_view(view_index, f"{spec.path}.bufferView")
    ids = spec.object("attributes")
    if not ids.data:
        ids.fail("names no attribute (expected glTF semantics mapped to Draco attribute ids)")
    try:
        mesh = DracoPy.decode(bytes(data))
    except (DracoPy.FileTypeException, ValueError, RuntimeError) as exc:
        spec.fail(f"bufferViews[{view_index}] is not a Draco mesh DracoPy decodes ({exc})")
    if not isinstance(mesh, DracoPy.DracoMesh) or mesh.faces is None or len(mesh.faces) == 0:
        spec.fail(f"bufferViews[{view_index}] decodes to a Draco point cloud, not a triangle mesh")
    decoded = {}
    for semantic in ids.data:
        unique_id = ids.integer(semantic)
        if not attributes.has(semantic):
            ids.fail(f"{semantic} is not one of the primitive's attributes "
                     f"({', '.join(sorted(attributes.data))})")
        attribute = mesh.get_attribute_by_unique_id(unique_id)
        if attribute is None:
            present = sorted(a["unique_id"] for a in mesh.attributes)
            ids.fail(f"{semantic}: attribute id {unique_id} is not in the Draco data (ids: {present})")
        values = np.asarray(attribute["data"])
        decoded[semantic] = values.reshape(len(values), -1)
    return DracoGeometry(decoded, np.asarray(mesh.faces, np.int64).reshape(-1))
