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
from pathlib import Path, PurePosixPath, PureWindowsPath

from ...foundation import json_input, safe_paths
from ...foundation.errors import SceneError
from . import meshopt
from .fields import FieldReader, join, shown

GLB_MAGIC = b"glTF"           # glTF 2.0, 4.4.3 "GLB Header"
GLB_CHUNK_JSON = 0x4E4F534A   # 4.4.3.2 "Chunks": chunkType "JSON"
GLB_CHUNK_BIN = 0x004E4942    # "BIN\0"
GLB_HEADER_BYTES = 12
GLB_CHUNK_HEADER_BYTES = 8


# spec 5.17 "glTF": the top-level arrays, each an array of objects where present.
TOP_LEVEL_ARRAYS = ("accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                    "meshes", "nodes", "samplers", "scenes", "skins", "textures")
LIGHTS = "extensions.KHR_lights_punctual.lights"  # the one collection outside the top level

# What one import may read from the file's accessors, counted as the float64 arrays it makes
# each time a mesh, node, skin or morph target reads one (an accessor named by 1,000 JOINTS_n
# sets, morph targets or skinned nodes is read 1,000 times: a few kilobytes of JSON can
# multiply a buffer that way). Half of a render's memory budget of 2 GiB (disk_cache.py; the
# other half for the GL buffers, textures and the image), and about 3 s of numpy work at
# 1 GB/s. The largest read of the 2023 Khronos sample set: see docs/faults.md.
MAX_READ_BYTES = 1 << 30


@dataclass
class Document:
    path: Path
    json: dict
    glb_bin: bytes | None = None
    allow_outside: bool = False  # read files outside the glTF's folder too (--allow-outside)
    _buffers: dict = field(default_factory=dict)
    _items: dict = field(default_factory=dict)
    _decoded_views: dict = field(default_factory=dict)
    read_bytes: int = 0  # float64 bytes of accessor data read so far (charge_read)

    def __post_init__(self):
        self.root = FieldReader(self.json, "", self)

    def fail(self, where: str, message: str):
        raise SceneError(f"{self.path}: {where}: {message}")

    def charge_read(self, nbytes: int, where: str, what: str) -> None:
        """Count ``nbytes`` of decoded data against MAX_READ_BYTES, refusing the file at
        ``where`` once the import has read more (module doc of MAX_READ_BYTES)."""
        self.read_bytes += int(nbytes)
        if self.read_bytes > MAX_READ_BYTES:
            self.fail(where, f"{what}: the file's accessors, read where its meshes, nodes, skins and morph "
                             f"targets use them, come to over {MAX_READ_BYTES >> 20} MiB as float64 "
                             f"(gltf.document.MAX_READ_BYTES: the import's share of a render's 2 GiB)")

    def items(self, key: str) -> list[FieldReader]:
        """The top-level array ``key`` (or LIGHTS) as readers, checked once."""
        if key not in self._items:
            if key == LIGHTS:
                self._items[key] = self.root.object("extensions").object("KHR_lights_punctual").objects("lights")
            else:
                self._items[key] = self.root.objects(key)
        return self._items[key]

    def check_index(self, key: str, index, where: str) -> int:
        """``index`` as an index into ``key``, refused at ``where`` when it is not one."""
        count = len(self.items(key))
        if isinstance(index, bool) or not isinstance(index, int):
            self.fail(where, f"expected an index into {key}, got {shown(index)}")
        if not 0 <= index < count:
            self.fail(where, f"refers to {key}[{index}], but the file has {count} {key}")
        return index

    def get(self, key: str, index, where: str) -> FieldReader:
        """``key[index]``, refused by name (at ``where``) when the index is not there."""
        return self.items(key)[self.check_index(key, index, where)]

    def buffer(self, index, where: str) -> bytes:
        spec = self.get("buffers", index, where)
        if index not in self._buffers:
            self._buffers[index] = self._load_buffer(spec)
        return self._buffers[index]

    def buffer_view(self, index, where: str) -> tuple[FieldReader, bytes]:
        """Buffer view ``index`` and the bytes of its buffer it spans (spec 3.6.1), or the
        bytes its EXT_meshopt_compression object decodes to (gltf.meshopt), once."""
        view = self.get("bufferViews", index, where)
        extensions = view.object("extensions")
        if extensions.has(meshopt.EXTENSION) and meshopt.available():
            if index not in self._decoded_views:
                self._decoded_views[index] = meshopt.decode_view(self, view, extensions.object(meshopt.EXTENSION))
            return view, self._decoded_views[index]
        buffer_index = view.index("buffer", "buffers", required=True)
        if extensions.has(meshopt.EXTENSION) and self._placeholder(buffer_index):
            view.fail(f"its data is {meshopt.EXTENSION}-compressed and buffers[{buffer_index}] is only a "
                      f"placeholder; install the decoder: {meshopt.INSTALL}")
        buffer = self.buffer(buffer_index, join(view.path, "buffer"))
        offset = view.integer("byteOffset", 0)
        length = view.integer("byteLength", None, lo=1)
        if offset + length > len(buffer):
            view.fail(f"bytes {offset}..{offset + length} lie outside buffers[{buffer_index}] ({len(buffer)} bytes)")
        return view, buffer[offset:offset + length]

    def _placeholder(self, index: int) -> bool:
        """Whether buffer ``index`` holds no data: no uri, and not the GLB's BIN chunk (which
        only buffer 0 may name: glTF 2.0, GLB "Binary buffer")."""
        return not self.items("buffers")[index].has("uri") and (self.glb_bin is None or index != 0)

    def _load_buffer(self, spec: FieldReader) -> bytes:
        length = spec.integer("byteLength", None, lo=1)
        if not spec.has("uri"):
            if self.glb_bin is None:
                spec.fail("has no uri and the file has no GLB binary chunk")
            data = self.glb_bin
        else:
            data = self.uri_bytes(spec.string("uri"), spec.path)
        if len(data) < length:
            spec.fail(f"holds {len(data)} bytes, byteLength says {length}")
        return data[:length]

    def uri_bytes(self, uri, where: str) -> bytes:
        """The bytes of a data: URI or of a file relative to the glTF file."""
        if not isinstance(uri, str) or not uri:
            self.fail(where, f"uri must be a non-empty string, got {shown(uri)}")
        if uri.startswith("data:"):
            header, _, payload = uri.partition(",")
            if not header.endswith(";base64"):
                self.fail(where, "data: URIs must be base64 encoded")
            try:
                return base64.b64decode(payload, validate=True)
            except ValueError:
                self.fail(where, "the data: URI is not valid base64")
        if "\x00" in urllib.parse.unquote(uri):
            self.fail(where, f"uri holds a NUL character: {shown(uri)}")
        file = self.local_file(uri)
        if file is None:
            self.fail(where, f"only files beside the glTF (in its folder or below it) and data: URIs "
                             f"are read, not {uri}"
                             + ("" if "://" in uri else " (pass --allow-outside to read files outside it)"))
        try:
            file = safe_paths.inside(self.path.parent, urllib.parse.unquote(uri), allow=self.allow_outside)
        except safe_paths.OutsideFolderError as exc:
            self.fail(where, exc.reason)
        try:
            if not file.is_file():
                self.fail(where, f"file not found: {file}")
            return file.read_bytes()
        except (OSError, RuntimeError) as exc:  # a symlink loop, a name too long, no permission
            self.fail(where, f"cannot read {file}: {getattr(exc, 'strerror', None) or exc}")

    def local_file(self, uri: str) -> Path | None:
        """The file a uri names when it lies in the glTF's folder or below it: no scheme, no
        absolute path or drive, no ``..``, no NUL; with ``allow_outside``, any local path
        (absolute, or relative to the glTF's folder)."""
        name = urllib.parse.unquote(uri)
        if "://" in uri or uri.startswith("data:") or "\x00" in name:
            return None
        slashed = name.replace("\\", "/")
        outside = slashed.startswith("/") or PureWindowsPath(name).drive or ".." in PurePosixPath(slashed).parts
        if outside and not self.allow_outside:
            return None
        return self.path.parent / name

    def declared_files(self) -> list[tuple[Path, str]]:
        """Every file the buffers and images name, with its role ("images[0] of model.gltf"):
        what an output of a render of this file must not be."""
        found = []
        for key in ("buffers", "images"):
            for i, item in enumerate(self.items(key)):
                uri = item.data.get("uri")
                file = self.local_file(uri) if isinstance(uri, str) else None
                if file is not None:
                    found.append((file, f"{key}[{i}] of {self.path.name}"))
        return found


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
    """The document through the same gate as scene files (pbrlab.foundation.json_input): duplicate
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


def read_document(path, allow_outside: bool = False) -> Document:
    """The document of a .gltf or .glb file (asset.version 2.x). ``allow_outside``: its
    buffers and images may name files outside its folder (refused by default)."""
    path = Path(path)
    allow_outside = allow_outside or safe_paths.outside_allowed()  # the CLI's flag, for a glTF a scene names
    try:
        safe_paths.named_file(path, allow_outside)
    except safe_paths.OutsideFolderError as exc:
        raise SceneError(str(exc)) from None
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
    doc = Document(path, document, binary, allow_outside)
    _check_top_level(doc)
    return doc


def _check_top_level(doc: Document) -> None:
    """The shape of the top level (spec 5.17), before any part is read: the arrays of
    objects, the extension lists and objects, the default scene."""
    for key in TOP_LEVEL_ARRAYS:
        doc.items(key)
    doc.root.object("asset").string("version")
    for key in ("minVersion", "generator", "copyright"):
        if doc.root.object("asset").has(key):
            doc.root.object("asset").string(key)
    doc.root.strings("extensionsUsed")
    doc.root.strings("extensionsRequired")
    doc.root.extensions()
    doc.items(LIGHTS)
    doc.root.index("scene", "scenes")
