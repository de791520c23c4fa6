"""glTF 2.0 accessors (spec 3.6) read into numpy arrays, each checked against what its
user expects: element type, component type, count, bounds in its buffer view, finite
values. Errors name the user and the accessor, e.g.
``meshes[2].primitives[0].attributes.NORMAL: accessor 7 has 3 elements, expected 24``.
"""

from __future__ import annotations

import json

import numpy as np

from .document import Document

# spec 3.6.2.2 "Accessor Data Types"
COMPONENT_TYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16,
                   5125: np.uint32, 5126: np.float32}
COMPONENT_NAMES = {5120: "BYTE", 5121: "UNSIGNED_BYTE", 5122: "SHORT", 5123: "UNSIGNED_SHORT",
                   5125: "UNSIGNED_INT", 5126: "FLOAT"}
ELEMENT_SIZES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
FLOAT = 5126

# What each use accepts: element types and (component type, normalized) pairs.
# spec 3.7.2.1 "Overview" (attribute table), 3.7.2.2 "Indexed geometry".
_COLOUR_LIKE = {(FLOAT, False), (5121, True), (5123, True)}
USES = {
    "POSITION": (("VEC3",), {(FLOAT, False)}),
    "NORMAL": (("VEC3",), {(FLOAT, False)}),
    "TANGENT": (("VEC4",), {(FLOAT, False)}),
    "TEXCOORD": (("VEC2",), _COLOUR_LIKE),
    "COLOR": (("VEC3", "VEC4"), _COLOUR_LIKE),
    "indices": (("SCALAR",), {(5121, False), (5123, False), (5125, False)}),
}


def _normalised(values: np.ndarray, component: int) -> np.ndarray:
    """Normalised integers to float (spec 3.11 "Animations": the conversion table)."""
    info = np.iinfo(COMPONENT_TYPES[component])
    out = values.astype(np.float64) / info.max
    return np.maximum(out, -1.0) if info.min < 0 else out


def read_accessor(doc: Document, index, where: str, use: str, count: int | None = None) -> np.ndarray:
    """Accessor ``index`` as float64 (count x n) or, for indices, int64 (count,), checked
    for ``use`` (a USES key) and, when given, its element ``count``."""
    accessor = doc.get("accessors", index, where)
    name = f"accessor {index}"
    types, components = USES[use]
    element = accessor.get("type")
    component = accessor.get("componentType")
    normalized = bool(accessor.get("normalized", False))
    if element not in types:
        doc.fail(where, f"{name} has type {json.dumps(element)}, expected {' or '.join(types)}")
    if (component, normalized) not in components:
        allowed = ", ".join(f"{COMPONENT_NAMES[c]}{' normalized' if n else ''}" for c, n in sorted(components))
        got = COMPONENT_NAMES.get(component, json.dumps(component))
        doc.fail(where, f"{name} has components {got}{' normalized' if normalized else ''}, expected {allowed}")
    n = ELEMENT_SIZES[element]
    n_elements = accessor.get("count")
    if isinstance(n_elements, bool) or not isinstance(n_elements, int) or n_elements < 1:
        doc.fail(where, f"{name}: count must be a positive integer, got {json.dumps(n_elements)}")
    if count is not None and n_elements != count:
        doc.fail(where, f"{name} has {n_elements} elements, expected {count}")
    dtype = np.dtype(COMPONENT_TYPES[component]).newbyteorder("<")
    if "bufferView" not in accessor:
        values = np.zeros((n_elements, n), dtype)  # spec 3.6.2.4: no buffer view means zeros
    else:
        values = _from_buffer_view(doc, accessor, name, where, dtype, n, n_elements)
    if "sparse" in accessor:
        values = _apply_sparse(doc, accessor["sparse"], values, f"{where} ({name}.sparse)", dtype, n)
    if use == "indices":
        return values[:, 0].astype(np.int64)
    out = _normalised(values, component) if normalized else values.astype(np.float64)
    if not np.all(np.isfinite(out)):
        bad = int(np.argmax(~np.all(np.isfinite(out), axis=1)))
        doc.fail(where, f"{name} holds a non-finite value (element {bad}: {out[bad].tolist()})")
    return out


def _apply_sparse(doc, sparse, values, where, dtype, n) -> np.ndarray:
    """spec 3.6.2.3 "Sparse Accessors": ``count`` (index, value) pairs replace elements."""
    count = sparse.get("count") if isinstance(sparse, dict) else None
    if isinstance(count, bool) or not isinstance(count, int) or count < 1:
        doc.fail(where, f"count must be a positive integer, got {json.dumps(count)}")
    indices_spec, values_spec = sparse.get("indices", {}), sparse.get("values", {})
    index_type = indices_spec.get("componentType")
    if index_type not in (5121, 5123, 5125):
        doc.fail(f"{where}.indices", f"componentType must be UNSIGNED_BYTE, _SHORT or _INT, got {index_type}")
    index_dtype = np.dtype(COMPONENT_TYPES[index_type]).newbyteorder("<")
    indices = _from_buffer_view(doc, {"bufferView": indices_spec.get("bufferView"),
                                      "byteOffset": indices_spec.get("byteOffset", 0)},
                                "indices", f"{where}.indices", index_dtype, 1, count)[:, 0].astype(np.int64)
    replacements = _from_buffer_view(doc, {"bufferView": values_spec.get("bufferView"),
                                           "byteOffset": values_spec.get("byteOffset", 0)},
                                     "values", f"{where}.values", dtype, n, count)
    if np.any(indices >= len(values)) or np.any(np.diff(indices) <= 0):
        doc.fail(f"{where}.indices", f"must increase strictly and stay below {len(values)}")
    values = values.copy()
    values[indices] = replacements
    return values


def _from_buffer_view(doc, accessor, name, where, dtype, n, n_elements) -> np.ndarray:
    view_index = accessor["bufferView"]
    view = doc.get("bufferViews", view_index, f"{where} ({name})")
    view_where = f"bufferViews[{view_index}]"
    buffer = doc.buffer(view.get("buffer"), view_where)
    view_offset = view.get("byteOffset", 0)
    view_length = view.get("byteLength")
    for key, value in (("byteOffset", view_offset), ("byteLength", view_length)):
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            doc.fail(view_where, f"{key} must be a non-negative integer, got {json.dumps(value)}")
    if view_offset + view_length > len(buffer):
        doc.fail(view_where, f"bytes {view_offset}..{view_offset + view_length} lie outside "
                             f"buffers[{view.get('buffer')}] ({len(buffer)} bytes)")
    element_bytes = dtype.itemsize * n
    stride = view.get("byteStride", element_bytes)
    if isinstance(stride, bool) or not isinstance(stride, int) or stride < element_bytes:
        doc.fail(view_where, f"byteStride {json.dumps(stride)} is smaller than an element ({element_bytes} bytes)")
    offset = accessor.get("byteOffset", 0)
    if isinstance(offset, bool) or not isinstance(offset, int) or offset < 0:
        doc.fail(where, f"{name}: byteOffset must be a non-negative integer, got {json.dumps(offset)}")
    if offset % dtype.itemsize or (view_offset + offset) % dtype.itemsize:
        doc.fail(where, f"{name}: byteOffset {offset} is not aligned to its {dtype.itemsize}-byte components")
    end = offset + stride * (n_elements - 1) + element_bytes
    if end > view_length:
        doc.fail(where, f"{name} needs {end} bytes of bufferViews[{view_index}], which has {view_length}")
    raw = np.ndarray((n_elements, n), dtype=dtype, buffer=buffer, offset=view_offset + offset,
                     strides=(stride, dtype.itemsize))
    return np.array(raw)
