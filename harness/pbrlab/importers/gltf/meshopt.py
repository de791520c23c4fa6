"""EXT_meshopt_compression: a buffer view whose bytes are decoded from a compressed range
of another buffer through the ``meshoptimizer`` bindings (zeux's meshoptimizer codecs).

The extension's README, "JSON schema updates": the view's extension object gives the
compressed ``buffer``, ``byteOffset``, ``byteLength``, and the layout of the decoded
data, ``count`` elements of ``byteStride`` bytes; ``mode`` picks the codec (ATTRIBUTES:
meshopt_decodeVertexBuffer, TRIANGLES: meshopt_decodeIndexBuffer, INDICES:
meshopt_decodeIndexSequence) and ``filter`` the transform applied after it (Appendix B:
OCTAHEDRAL, QUATERNION, EXPONENTIAL). The decoded bytes are the view's bytes; the view's
own ``buffer`` is then a fallback (often a placeholder without data) and is not read.
Its validity rules (byteLength = byteStride x count, the strides each mode and filter
allow) are checked here, each refused by its field.
"""

from __future__ import annotations

import importlib.util

import numpy as np

from .fields import FieldReader, join

EXTENSION = "EXT_meshopt_compression"
PACKAGE = "meshoptimizer"
INSTALL = "pip install meshoptimizer==0.2.30a0"
MODES = ("ATTRIBUTES", "TRIANGLES", "INDICES")
FILTERS = ("NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL")
MAX_ATTRIBUTE_STRIDE = 256  # README: "byteStride must be divisible by 4 and must be <= 256"
FILTER_STRIDES = {"OCTAHEDRAL": (4, 8), "QUATERNION": (8,)}  # EXPONENTIAL: any multiple of 4


def available() -> bool:
    return importlib.util.find_spec(PACKAGE) is not None


def decode_view(doc, view: FieldReader, spec: FieldReader) -> bytes:
    """The decoded bytes of buffer view ``view`` from its extension object ``spec``."""
    import meshoptimizer

    buffer_index = spec.index("buffer", "buffers", required=True)
    buffer = doc.buffer(buffer_index, join(spec.path, "buffer"))
    offset = spec.integer("byteOffset", 0)
    length = spec.integer("byteLength", None, lo=1)
    stride = spec.integer("byteStride", None, lo=1)
    count = spec.integer("count", None, lo=1)
    mode = spec.enum("mode", MODES)
    filter_ = spec.enum("filter", FILTERS, "NONE")
    if offset + length > len(buffer):
        spec.fail(f"bytes {offset}..{offset + length} lie outside buffers[{buffer_index}] ({len(buffer)} bytes)")
    if view.has("byteStride") and view.integer("byteStride", None, lo=4) != stride:
        spec.fail(f"byteStride {stride} differs from the buffer view's {view.data['byteStride']}")
    view_length = view.integer("byteLength", None, lo=1)
    if view_length != stride * count:
        spec.fail(f"the buffer view's byteLength {view_length} is not byteStride x count = {stride * count}")
    if mode == "ATTRIBUTES" and (stride % 4 or stride > MAX_ATTRIBUTE_STRIDE):
        spec.fail(f"byteStride {stride}: ATTRIBUTES needs a multiple of 4 up to {MAX_ATTRIBUTE_STRIDE}")
    if mode != "ATTRIBUTES" and stride not in (2, 4):
        spec.fail(f"byteStride {stride}: {mode} needs 2 or 4 (16- or 32-bit indices)")
    if mode == "TRIANGLES" and count % 3:
        spec.fail(f"count {count}: TRIANGLES needs a multiple of 3")
    if filter_ != "NONE" and mode != "ATTRIBUTES":
        spec.fail(f"filter {filter_} applies to ATTRIBUTES only, not {mode}")
    if filter_ in FILTER_STRIDES and stride not in FILTER_STRIDES[filter_]:
        spec.fail(f"byteStride {stride}: filter {filter_} needs {' or '.join(map(str, FILTER_STRIDES[filter_]))}")
    data = bytes(buffer[offset:offset + length])
    try:
        if mode == "ATTRIBUTES":
            raw = np.ascontiguousarray(meshoptimizer.decode_vertex_buffer(count, stride, data)).view(np.uint8)
            if filter_ == "OCTAHEDRAL":
                raw = meshoptimizer.decode_filter_oct(raw, count, stride)
            elif filter_ == "QUATERNION":
                raw = meshoptimizer.decode_filter_quat(raw, count, stride)
            elif filter_ == "EXPONENTIAL":
                raw = meshoptimizer.decode_filter_exp(raw, count, stride)
            return raw.tobytes()
        # decoded as 32-bit indices, then stored at the view's width
        decoder = meshoptimizer.decode_index_buffer if mode == "TRIANGLES" else meshoptimizer.decode_index_sequence
        indices = np.asarray(decoder(count, 4, data), np.uint32)
    except (ValueError, RuntimeError) as exc:
        spec.fail(f"the {mode} data does not decode ({exc})")
    if stride == 2 and len(indices) and int(indices.max()) > np.iinfo(np.uint16).max:
        spec.fail(f"decodes index {int(indices.max())}, more than 16 bits hold (byteStride 2)")
    return indices.astype("<u2" if stride == 2 else "<u4").tobytes()
