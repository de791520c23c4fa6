"""A small valid glTF document built in memory (one indexed quad with normals and UVs,
one material), for tests that break one thing at a time."""

import base64
import json

import numpy as np


def quad_document() -> dict:
    positions = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float32)
    normals = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
    uv = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3], np.uint16)
    blob = positions.tobytes() + normals.tobytes() + uv.tobytes() + indices.tobytes()
    views = [(0, 48), (48, 48), (96, 32), (128, 12)]
    return {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
        "materials": [{"name": "paint", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1],
                                                                 "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }


def write(tmp_path, doc: dict, name: str = "model.gltf"):
    path = tmp_path / name
    path.write_text(json.dumps(doc), encoding="utf-8")
    return path


def blob(doc: dict) -> bytes:
    return base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])


def set_blob(doc: dict, data: bytes) -> None:
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()


def read_glb(path) -> tuple[dict, bytes]:
    """The JSON and BIN chunks of a GLB file (glTF 2.0, 4.4: header, JSON chunk, BIN chunk)."""
    import struct
    data = path.read_bytes()
    json_length = struct.unpack_from("<I", data, 12)[0]
    document = json.loads(data[20:20 + json_length])
    start = 20 + json_length
    bin_length = struct.unpack_from("<I", data, start)[0] if start < len(data) else 0
    return document, data[start + 8:start + 8 + bin_length]


def write_glb(tmp_path, doc: dict, binary: bytes, name: str = "model.glb"):
    import struct
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    path = tmp_path / name
    path.write_bytes(struct.pack("<4sII", b"glTF", 2, 28 + len(text) + len(binary))
                     + struct.pack("<II", len(text), 0x4E4F534A) + text
                     + struct.pack("<II", len(binary), 0x004E4942) + binary)
    return path
