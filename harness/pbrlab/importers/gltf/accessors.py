"""glTF 2.0 accessors (spec 3.6) read into numpy arrays, each checked against what its
user expects: element type, component type, count, bounds in its buffer view, finite
values. Errors name the user and the accessor, e.g.
``meshes[2].primitives[0].attributes.NORMAL: accessor 7 has 3 elements, expected 24``.
"""

from __future__ import annotations

import numpy as np

from ...foundation import disk_cache
from .document import Document
from .fields import FieldReader, shown

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
    # EXT_mesh_gpu_instancing's per-instance attributes (its README, "Extending Nodes")
    "INSTANCE_TRANSLATION": (("VEC3",), {(FLOAT, False)}),
    "INSTANCE_ROTATION": (("VEC4",), {(FLOAT, False), (5120, True), (5122, True)}),
    "INSTANCE_SCALE": (("VEC3",), {(FLOAT, False)}),
    # morph target displacements (spec 3.7.2.2 "Morph Targets": POSITION, NORMAL, TANGENT
    # deltas, all VEC3 FLOAT; a TANGENT delta has no handedness)
    "TARGET_POSITION": (("VEC3",), {(FLOAT, False)}),
    "TARGET_NORMAL": (("VEC3",), {(FLOAT, False)}),
    "TARGET_TANGENT": (("VEC3",), {(FLOAT, False)}),
    # skins (spec 3.7.3 "Skins"; 3.7.2.1's attribute table: JOINTS_n unsigned byte or short,
    # WEIGHTS_n float or normalized unsigned byte or short; inverseBindMatrices MAT4 float)
    "JOINTS": (("VEC4",), {(5121, False), (5123, False)}),
    "WEIGHTS": (("VEC4",), _COLOUR_LIKE),
    "INVERSE_BIND_MATRICES": (("MAT4",), {(FLOAT, False)}),
    # animation samplers (spec 3.11, its table of output types: rotations and weights may be
    # normalized integers, times and translations and scales are float)
    "ANIMATION_INPUT": (("SCALAR",), {(FLOAT, False)}),
    "ANIMATION_TRANSLATION": (("VEC3",), {(FLOAT, False)}),
    "ANIMATION_ROTATION": (("VEC4",), {(FLOAT, False), (5120, True), (5121, True), (5122, True), (5123, True)}),
    "ANIMATION_SCALE": (("VEC3",), {(FLOAT, False)}),
    "ANIMATION_WEIGHTS": (("SCALAR",), {(FLOAT, False), (5120, True), (5121, True), (5122, True), (5123, True)}),
}
# KHR_mesh_quantization (its README, "Extending Mesh Attributes"): the integer types each
# attribute also takes when the file uses the extension; normalized or not, as the
# accessor's ``normalized`` flag says (not normalized: the integers themselves).
QUANTIZATION = "KHR_mesh_quantization"
_INTEGERS = {(c, n) for c in (5120, 5121, 5122, 5123) for n in (False, True)}
QUANTIZED_USES = {"POSITION": _INTEGERS, "NORMAL": {(5120, True), (5122, True)},
                  "TANGENT": {(5120, True), (5122, True)}, "TEXCOORD": _INTEGERS,
                  "INSTANCE_TRANSLATION": _INTEGERS, "INSTANCE_SCALE": _INTEGERS,
                  "INSTANCE_ROTATION": {(5120, True), (5122, True)},
                  # "Extending Morph Target Attributes": signed deltas only
                  "TARGET_POSITION": {(c, n) for c in (5120, 5122) for n in (False, True)},
                  "TARGET_NORMAL": {(5120, True), (5122, True)}, "TARGET_TANGENT": {(5120, True), (5122, True)}}


# An accessor without a bufferView is zeros made from nothing (a few bytes of JSON can ask for
# billions): its float64 array is bounded by the share of one array in the 2 GiB memory budget
# of a render, the disk cache's per-entry limit (foundation/disk_cache.py: 256 MiB, a mesh of 4.4
# million vertices). An accessor read from a buffer is bounded by the file itself.
MAX_UNBACKED_BYTES = disk_cache.MAX_ENTRY_BYTES

def uses_quantization(doc: Document) -> bool:
    return QUANTIZATION in doc.root.strings("extensionsUsed")


def _normalised(values: np.ndarray, component: int) -> np.ndarray:
    """Normalised integers to float (spec 3.11 "Animations": the conversion table)."""
    info = np.iinfo(COMPONENT_TYPES[component])
    out = values.astype(np.float64) / info.max
    return np.maximum(out, -1.0) if info.min < 0 else out


def read_accessor(doc: Document, index, where: str, use: str, count: int | None = None,
                  decoded: np.ndarray | None = None) -> np.ndarray:
    """Accessor ``index`` as float64 (count x n) or, for indices, int64 (count,), checked
    for ``use`` (a USES key) and, when given, its element ``count``. ``decoded``: the
    accessor's values decoded elsewhere (KHR_draco_mesh_compression), which replace its
    bufferView, byteOffset and sparse; the accessor still gives their count and type."""
    accessor = doc.get("accessors", index, where)
    name = f"accessor {index}"
    types, components = USES[use]
    quantized = QUANTIZED_USES.get(use, set())
    if quantized and uses_quantization(doc):
        components, quantized = components | quantized, set()
    element = accessor.data.get("type")
    component = accessor.data.get("componentType")
    normalized = accessor.boolean("normalized", False)
    if element not in types:
        doc.fail(where, f"{name} has type {shown(element)}, expected {' or '.join(types)}")
    if (type(component) is not int or (component, normalized) not in components):
        allowed = ", ".join(f"{COMPONENT_NAMES[c]}{' normalized' if n else ''}" for c, n in sorted(components))
        got = COMPONENT_NAMES.get(component, shown(component)) if type(component) is int else shown(component)
        hint = (f" (or, with {QUANTIZATION} in extensionsUsed, that type)"
                if type(component) is int and (component, normalized) in quantized else "")
        doc.fail(where, f"{name} has components {got}{' normalized' if normalized else ''}, expected {allowed}{hint}")
    n = ELEMENT_SIZES[element]
    n_elements = accessor.integer("count", None, lo=1)
    if count is not None and n_elements != count:
        doc.fail(where, f"{name} has {n_elements} elements, expected {count}")
    dtype = np.dtype(COMPONENT_TYPES[component]).newbyteorder("<")
    view_index = accessor.index("bufferView", "bufferViews")
    if decoded is None and view_index is None and n_elements * n * 8 > MAX_UNBACKED_BYTES:
        doc.fail(where, f"{name} has no bufferView and {n_elements} elements: {n_elements * n * 8 >> 20} MiB "
                        f"of zeros as float64, over the limit of {MAX_UNBACKED_BYTES >> 20} MiB "
                        "(accessors.MAX_UNBACKED_BYTES)")
    doc.charge_read(n_elements * n * 8, where, name)  # the float64 (indices: int64) array, before it is made
    if decoded is not None:
        values = _decoded_values(doc, decoded, where, name, use, component, n, n_elements)
    elif view_index is None:  # spec 3.6.2.4: no buffer view means zeros, which the file does not hold
        values = np.zeros((n_elements, n), dtype)
    else:
        offset = accessor.integer("byteOffset", 0)
        values = _from_buffer_view(doc, view_index, offset, name, where, dtype, n, n_elements, strided=True)
    if accessor.has("sparse") and decoded is None:
        values = _apply_sparse(doc, accessor.object("sparse"), values, dtype, n)
    if use == "indices":
        return values[:, 0].astype(np.int64)
    out = _normalised(values, component) if normalized else values.astype(np.float64)
    if not np.all(np.isfinite(out)):
        bad = int(np.argmax(~np.all(np.isfinite(out), axis=1)))
        doc.fail(where, f"{name} holds a non-finite value (element {bad}: {out[bad].tolist()})")
    return out


def _decoded_values(doc, decoded: np.ndarray, where, name, use, component, n, n_elements) -> np.ndarray:
    """Decoded values checked against their accessor: the same element count and size,
    and the accessor's component type (a float accessor takes float data; an integer one,
    normalized or not, integers in its component type's range: Draco data may store them
    wider, as Khronos' Draco BrainStem does its UNSIGNED_SHORT JOINTS_0 in uint32). Indices
    take any integers."""
    if decoded.shape != (n_elements, n):
        doc.fail(where, f"the compressed data decodes {decoded.shape[0]} elements of {decoded.shape[1]} "
                        f"components; {name} says {n_elements} of {n}")
    if use == "indices":
        return decoded.astype(np.int64)
    expected = np.dtype(COMPONENT_TYPES[component])
    if decoded.dtype.kind == "f" and component == FLOAT or decoded.dtype == expected:
        return decoded
    if decoded.dtype.kind in "iu" and expected.kind in "iu":  # stored wider than the accessor says
        info = np.iinfo(expected)
        if decoded.size == 0 or (decoded.min() >= info.min and decoded.max() <= info.max):
            return decoded.astype(expected)
        doc.fail(where, f"the compressed data decodes integers from {int(decoded.min())} to {int(decoded.max())}; "
                        f"{name} has components {COMPONENT_NAMES[component]} ({info.min} to {info.max})")
    doc.fail(where, f"the compressed data decodes {decoded.dtype} values; {name} has components "
                    f"{COMPONENT_NAMES[component]}")


def _apply_sparse(doc: Document, sparse: FieldReader, values, dtype, n) -> np.ndarray:
    """spec 3.6.2.3 "Sparse Accessors": ``count`` (index, value) pairs replace elements."""
    count = sparse.integer("count", None, lo=1)
    if count > len(values):
        sparse.fail(f"count {count} exceeds the accessor's {len(values)} elements")
    indices_spec, values_spec = sparse.object("indices"), sparse.object("values")
    index_type = indices_spec.enum("componentType", (5121, 5123, 5125), None, COMPONENT_NAMES)
    index_dtype = np.dtype(COMPONENT_TYPES[index_type]).newbyteorder("<")
    indices = _from_buffer_view(doc, indices_spec.index("bufferView", "bufferViews", required=True),
                                indices_spec.integer("byteOffset", 0), "indices", indices_spec.path,
                                index_dtype, 1, count)[:, 0].astype(np.int64)
    replacements = _from_buffer_view(doc, values_spec.index("bufferView", "bufferViews", required=True),
                                     values_spec.integer("byteOffset", 0), "values", values_spec.path,
                                     dtype, n, count)
    if np.any(indices >= len(values)) or np.any(np.diff(indices) <= 0):
        indices_spec.fail(f"must increase strictly and stay below {len(values)}")
    values = values.copy()
    values[indices] = replacements
    return values


def _from_buffer_view(doc, view_index: int, offset: int, name, where, dtype, n, n_elements,
                      strided: bool = False) -> np.ndarray:
    """``n_elements`` elements of ``n`` components from a buffer view, ``offset`` bytes in
    (byteStride honoured where ``strided``: spec 3.6.2.4, sparse data is tightly packed)."""
    view, data = doc.buffer_view(view_index, f"{where} ({name})")
    view_offset = view.integer("byteOffset", 0)
    element_bytes = dtype.itemsize * n
    stride = element_bytes
    if strided and view.has("byteStride"):
        stride = view.integer("byteStride", None, lo=4, hi=252)  # spec 5.11: 4..252
        if stride < element_bytes:
            view.fail(f"byteStride {stride} is smaller than an element ({element_bytes} bytes)")
    if offset % dtype.itemsize or (view_offset + offset) % dtype.itemsize:
        doc.fail(where, f"{name}: byteOffset {offset} is not aligned to its {dtype.itemsize}-byte components")
    end = offset + stride * (n_elements - 1) + element_bytes
    if end > len(data):
        doc.fail(where, f"{name} needs {end} bytes of bufferViews[{view_index}], which has {len(data)}")
    raw = np.ndarray((n_elements, n), dtype=dtype, buffer=data, offset=offset, strides=(stride, dtype.itemsize))
    return np.array(raw)
