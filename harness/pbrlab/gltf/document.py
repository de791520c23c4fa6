"""Reading a glTF 2.0 file: the JSON (from a .gltf, or the JSON chunk of a .glb), its
buffers (files beside it, data: URIs, the GLB's BIN chunk) and its images' bytes.

Every problem is a SceneError naming the file and the object (``buffers[1]: file not
found: model.bin``); nothing here raises anything else for a bad file.
"""

from __future__ import annotations

import base64
import json
import struct
import urllib.parse
from dataclasses import dataclass, field
from pathlib import Path

from .. import json_input
from ..errors import SceneError

GLB_MAGIC = b"glTF"           # glTF 2.0, 4.4.3 "GLB Header"
GLB_CHUNK_JSON = 0x4E4F534A   # 4.4.3.2 "Chunks": chunkType "JSON"
GLB_CHUNK_BIN = 0x004E4942    # "BIN\0"
GLB_HEADER_BYTES = 12
GLB_CHUNK_HEADER_BYTES = 8


@dataclass
class Document:
    path: Path
    json: dict
    glb_bin: bytes | None = None
    _buffers: dict = field(default_factory=dict)

    def fail(self, where: str, message: str):
        raise SceneError(f"{self.path}: {where}: {message}")

    def items(self, key: str) -> list:
        value = self.json.get(key, [])
        if not isinstance(value, list):
            self.fail(key, f"expected a list, got {type(value).__name__}")
        for i, item in enumerate(value):
            if not isinstance(item, dict):
                self.fail(f"{key}[{i}]", f"expected an object, got {json.dumps(item)[:40]}")
        return value

    def get(self, key: str, index, where: str) -> dict:
        """``json[key][index]``, refused by name when the index is not there."""
        items = self.items(key)
        if isinstance(index, bool) or not isinstance(index, int) or not 0 <= index < len(items):
            self.fail(where, f"refers to {key}[{index}], but the file has {len(items)} {key}")
        return items[index]

    def buffer(self, index: int, where: str) -> bytes:
        if index not in self._buffers:
            spec = self.get("buffers", index, where)
            self._buffers[index] = self._load_buffer(spec, f"buffers[{index}]")
        return self._buffers[index]

    def _load_buffer(self, spec: dict, where: str) -> bytes:
        length = spec.get("byteLength")
        if isinstance(length, bool) or not isinstance(length, int) or length < 1:
            self.fail(where, f"byteLength must be a positive integer, got {json.dumps(length)}")
        uri = spec.get("uri")
        if uri is None:
            if self.glb_bin is None:
                self.fail(where, "has no uri and the file has no GLB binary chunk")
            data = self.glb_bin
        else:
            data = self.uri_bytes(uri, where)
        if len(data) < length:
            self.fail(where, f"holds {len(data)} bytes, byteLength says {length}")
        return data[:length]

    def uri_bytes(self, uri, where: str) -> bytes:
        """The bytes of a data: URI or of a file relative to the glTF file."""
        if not isinstance(uri, str) or not uri:
            self.fail(where, f"uri must be a non-empty string, got {json.dumps(uri)}")
        if uri.startswith("data:"):
            header, _, payload = uri.partition(",")
            if not header.endswith(";base64"):
                self.fail(where, "data: URIs must be base64 encoded")
            try:
                return base64.b64decode(payload, validate=True)
            except ValueError:
                self.fail(where, "the data: URI is not valid base64")
        if "://" in uri:
            self.fail(where, f"only files beside the glTF and data: URIs are read, not {uri}")
        file = (self.path.parent / urllib.parse.unquote(uri)).resolve()
        if not file.is_file():
            self.fail(where, f"file not found: {file}")
        return file.read_bytes()


def _parse_glb(path: Path, data: bytes) -> tuple[dict, bytes | None]:
    """glTF 2.0, 4.4 "Binary glTF Layout": header, a JSON chunk, an optional BIN chunk."""
    if len(data) < GLB_HEADER_BYTES + GLB_CHUNK_HEADER_BYTES:
        raise SceneError(f"{path}: a GLB file needs at least 20 bytes, this one has {len(data)}")
    _, version, length = struct.unpack_from("<4sII", data, 0)
    if version != 2:
        raise SceneError(f"{path}: GLB version {version}; only glTF 2.0 is read")
    if length > len(data):
        raise SceneError(f"{path}: the GLB header says {length} bytes, the file has {len(data)}")
    chunks, offset = [], GLB_HEADER_BYTES
    while offset + GLB_CHUNK_HEADER_BYTES <= length:
        size, kind = struct.unpack_from("<II", data, offset)
        start = offset + GLB_CHUNK_HEADER_BYTES
        if start + size > length:
            raise SceneError(f"{path}: GLB chunk {len(chunks)} runs past the end of the file")
        chunks.append((kind, data[start:start + size]))
        offset = start + size
    if not chunks or chunks[0][0] != GLB_CHUNK_JSON:
        raise SceneError(f"{path}: the first GLB chunk is not JSON")
    binary = chunks[1][1] if len(chunks) > 1 and chunks[1][0] == GLB_CHUNK_BIN else None
    return _parse_json(path, chunks[0][1]), binary


def _parse_json(path: Path, data: bytes) -> dict:
    """The document through the same gate as scene files (pbrlab.json_input): duplicate
    keys, NaN / Infinity / numbers beyond float32 and over-deep nesting are refused by path."""
    try:
        document = json.loads(data.decode("utf-8"), object_pairs_hook=json_input.pairs_hook,
                              parse_constant=json_input.parse_constant)
    except UnicodeDecodeError:
        raise SceneError(f"{path}: not a readable glTF 2.0 file (the JSON is not UTF-8)") from None
    except json.JSONDecodeError as exc:
        raise SceneError(f"{path}: not a readable glTF 2.0 file (invalid JSON at line {exc.lineno} "
                         f"column {exc.colno}: {exc.msg})") from None
    except RecursionError:
        raise SceneError(f"{path}: not a readable glTF 2.0 file (JSON nested too deeply)") from None
    document = json_input.normalize(document, str(path))
    if not isinstance(document, dict):
        raise SceneError(f"{path}: not a readable glTF 2.0 file (the JSON is not an object)")
    return document


def read_document(path) -> Document:
    """The document of a .gltf or .glb file (asset.version 2.x)."""
    path = Path(path)
    if not path.is_file():
        raise SceneError(f"{path}: no such glTF file")
    data = path.read_bytes()
    if data[:4] == GLB_MAGIC:
        document, binary = _parse_glb(path, data)
    else:
        document, binary = _parse_json(path, data), None
    asset = document.get("asset")
    version = asset.get("version") if isinstance(asset, dict) else None
    if not isinstance(version, str) or not version.startswith("2."):
        raise SceneError(f"{path}: not a readable glTF 2.0 file (asset.version is {json.dumps(version)}, "
                         "expected \"2.0\")")
    return Document(path, document, binary)
