"""Generates the glTF test assets of glTF "as it is delivered" (issue 24): compressed
geometry, morph targets, several scenes. Committed next to this script; run it again to
rebuild them byte for byte (DracoPy 2.2.0 and meshoptimizer 0.2.30a0 encode).

    sphere_source.glb         an icosphere (NORMAL, TEXCOORD_0, a checker texture) under a
                              directional light, stored plainly: the twin of the Draco files
    draco_sphere.glb          the same sphere KHR_draco_mesh_compression only (required):
                              positions quantised to 14 bits, normals 10, UVs 12
    draco_sphere_fallback.glb the same Draco data, the extension used but not required, and
                              an uncompressed fallback holding what the Draco data decodes to
                              (the extension's "Implementation note")
    draco_skinned_strip.glb   skinned_strip.gltf's two-joint strip, its POSITION, NORMAL,
                              JOINTS_0 (UNSIGNED_BYTE) and WEIGHTS_0 in Draco data only
                              (required); joint 1 is written rotated 60 degrees about +Z, so
                              the pose depends on every vertex's joints and weights
    draco_skinned_strip_fallback.glb  the same Draco data, not required, and an uncompressed
                              fallback holding what it decodes to
    meshopt_instances.glb     EXT_meshopt_compression only (a placeholder fallback buffer):
                              the sphere's positions (ATTRIBUTES), BYTE normals (OCTAHEDRAL),
                              UVs (EXPONENTIAL), indices (TRIANGLES); a floor strip's indices
                              (INDICES); three EXT_mesh_gpu_instancing instances whose
                              TRANSLATION (ATTRIBUTES) and SHORT ROTATION (QUATERNION) are
                              compressed too
    meshopt_instances_plain.glb  its twin: the same buffer views uncompressed, the filtered
                              values decoded here by the extension's Appendix B in numpy
    morph_scenes.gltf         a grid with two morph targets (a bump with its normal deltas,
                              a shear), mesh.weights [0.5, 0]; scene 0 draws it with the mesh's
                              weights, scene 1 a second node overriding them with [1, 1]

    .venv/bin/python scenes/gltf/make_delivered_assets.py
"""

from __future__ import annotations

import math

import DracoPy
import meshoptimizer
import numpy as np

from make_animated_assets import _data, strip
from make_assets import HERE, Builder, _look_rotation, _quaternion, checker

DRACO_BITS = {"position": 14, "normal": 10, "tex_coord": 12}
DRACO_LEVEL = 7  # DracoPy's compression_level (0..10)
DRACO_TYPE = {0: "POSITION", 1: "NORMAL", 3: "TEXCOORD_0"}  # draco::GeometryAttribute::Type
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
SQRT2 = math.sqrt(2.0)


# ----------------------------------------------------------------------------- geometry

def sphere(subdivisions=3):
    """A unit icosphere, its exact normals, spherical UVs (v down from the north pole)."""
    import trimesh
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=1.0)
    p = np.asarray(mesh.vertices, np.float64)
    n = p / np.linalg.norm(p, axis=1, keepdims=True)
    uv = np.stack([np.arctan2(n[:, 0], n[:, 2]) / (2 * math.pi) + 0.5, np.arccos(np.clip(n[:, 1], -1, 1)) / math.pi],
                  axis=1)
    return p, n, uv, np.asarray(mesh.faces, np.int64)


def _lit(b: Builder, nodes: list[int], camera_at=(0.0, 0.4, 4.0)):
    """A directional light, a camera looking at the origin and scene 0 of ``nodes``."""
    b.json["extensionsUsed"] = sorted(set(b.json.get("extensionsUsed", [])) | {"KHR_lights_punctual"})
    b.json.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": [{"type": "directional", "intensity": 3.0}]}
    light = b.add("nodes", {"rotation": _look_rotation([0.4, -0.5, -1.0]), "extensions": {"KHR_lights_punctual": {"light": 0}}})
    b.json["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}}]
    camera = b.add("nodes", {"camera": 0, "translation": list(camera_at),
                             "rotation": _look_rotation(-np.asarray(camera_at))})
    b.json["scenes"] = [{"nodes": nodes + [light, camera]}]
    b.json["scene"] = 0


def _textured_material(b: Builder) -> int:
    texture = b.texture(b.image(checker(cells=8), embed=True))
    return b.add("materials", {"name": "checker", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": texture}, "metallicFactor": 0.0, "roughnessFactor": 0.45}})


# ----------------------------------------------------------------------------- Draco

def _accessor_without_view(b: Builder, count: int, kind: str, component: int = 5126, values=None) -> int:
    acc = {"componentType": component, "count": count, "type": kind}
    if values is not None:  # POSITION's bounds (spec 3.7.2.1: required)
        acc["min"], acc["max"] = values.min(axis=0).tolist(), values.max(axis=0).tolist()
    return b.add("accessors", acc)


def draco_spheres():
    p, n, uv, faces = sphere()
    b = Builder()
    material = _textured_material(b)
    b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, faces, material)]})
    _lit(b, [b.add("nodes", {"mesh": 0})])
    b.write_glb(HERE / "sphere_source.glb")

    encoded = DracoPy.encode(p.astype(np.float32), faces.astype(np.uint32), normals=n.astype(np.float64),
                             tex_coord=uv.astype(np.float64), quantization_bits=DRACO_BITS["position"],
                             normal_quantization_bits=DRACO_BITS["normal"],
                             tex_coord_quantization_bits=DRACO_BITS["tex_coord"], compression_level=DRACO_LEVEL)
    decoded = DracoPy.decode(encoded)
    ids = {DRACO_TYPE[a["attribute_type"]]: a["unique_id"] for a in decoded.attributes}
    values = {DRACO_TYPE[a["attribute_type"]]: np.asarray(a["data"], np.float32) for a in decoded.attributes}
    count, corners = len(values["POSITION"]), np.asarray(decoded.faces, np.uint16).reshape(-1)
    kinds = {"POSITION": "VEC3", "NORMAL": "VEC3", "TEXCOORD_0": "VEC2"}
    for fallback in (False, True):
        b = Builder()
        material = _textured_material(b)
        if fallback:  # the uncompressed accessors hold the decoded data
            attributes = {k: b.accessor(values[k], kind, bounds=k == "POSITION") for k, kind in kinds.items()}
            indices = b.accessor(corners, "SCALAR", 5123)
        else:
            attributes = {k: _accessor_without_view(b, count, kind, values=values[k] if k == "POSITION" else None)
                          for k, kind in kinds.items()}
            indices = _accessor_without_view(b, len(corners), "SCALAR", 5123)
        view = b.view(encoded)
        b.json["meshes"].append({"primitives": [{
            "attributes": attributes, "indices": indices, "material": material, "mode": 4,
            "extensions": {"KHR_draco_mesh_compression": {"bufferView": view, "attributes": ids}}}]})
        _lit(b, [b.add("nodes", {"mesh": 0})])
        b.json["extensionsUsed"] = sorted(b.json["extensionsUsed"] + ["KHR_draco_mesh_compression"])
        if not fallback:
            b.json["extensionsRequired"] = ["KHR_draco_mesh_compression"]
        b.write_glb(HERE / ("draco_sphere_fallback.glb" if fallback else "draco_sphere.glb"))


SKINNED_DRACO_IDS = {"JOINTS_0": 5, "WEIGHTS_0": 6}  # Draco generic attributes' unique ids (any unused id)
WRITTEN_BEND_DEGREES = 60.0


def draco_skinned_strips():
    positions, normals, faces, joints, weights = strip()
    encoded = DracoPy.encode(positions.astype(np.float32), faces.astype(np.uint32), normals=normals,
                             quantization_bits=DRACO_BITS["position"],
                             normal_quantization_bits=DRACO_BITS["normal"], compression_level=DRACO_LEVEL,
                             generic_attributes={SKINNED_DRACO_IDS["JOINTS_0"]: joints.astype(np.uint8),
                                                 SKINNED_DRACO_IDS["WEIGHTS_0"]: weights.astype(np.float32)})
    decoded = DracoPy.decode(encoded)
    ids = {DRACO_TYPE[a["attribute_type"]]: a["unique_id"] for a in decoded.attributes if a["attribute_type"] != 4}
    ids.update(SKINNED_DRACO_IDS)
    values = {k: np.asarray(decoded.get_attribute_by_unique_id(i)["data"]) for k, i in ids.items()}
    count, corners = len(values["POSITION"]), np.asarray(decoded.faces, np.uint16).reshape(-1)
    kinds = {"POSITION": ("VEC3", 5126), "NORMAL": ("VEC3", 5126), "JOINTS_0": ("VEC4", 5121),
             "WEIGHTS_0": ("VEC4", 5126)}
    for fallback in (False, True):
        b = Builder()
        clay = b.add("materials", {"name": "clay", "pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.5, 0.3, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6}})
        if fallback:
            attributes = {k: b.accessor(values[k].astype(np.uint8 if c == 5121 else np.float32), kind, c,
                                        bounds=k == "POSITION") for k, (kind, c) in kinds.items()}
            indices = b.accessor(corners, "SCALAR", 5123)
        else:
            attributes = {k: _accessor_without_view(b, count, kind, c, values[k] if k == "POSITION" else None)
                          for k, (kind, c) in kinds.items()}
            indices = _accessor_without_view(b, len(corners), "SCALAR", 5123)
        view = b.view(encoded)
        b.json["meshes"].append({"primitives": [{
            "attributes": attributes, "indices": indices, "material": clay, "mode": 4,
            "extensions": {"KHR_draco_mesh_compression": {"bufferView": view, "attributes": ids}}}]})
        root = b.add("nodes", {"name": "joint 0", "children": [1]})
        b.add("nodes", {"name": "joint 1", "translation": [0.0, 1.0, 0.0],
                        "rotation": _quaternion([0, 0, 1], math.radians(WRITTEN_BEND_DEGREES))})
        inverse_bind = np.stack([np.eye(4), np.array([[1, 0, 0, 0], [0, 1, 0, -1.0], [0, 0, 1, 0], [0, 0, 0, 1]])])
        b.add("skins", {"joints": [0, 1], "skeleton": 0,
                        "inverseBindMatrices": _data(b, inverse_bind.transpose(0, 2, 1).reshape(-1, 16), "MAT4")})
        skinned = b.add("nodes", {"name": "strip", "mesh": 0, "skin": 0})
        _lit(b, [root, skinned], camera_at=(0.0, 1.0, 5.0))
        b.json["extensionsUsed"] = sorted(b.json["extensionsUsed"] + ["KHR_draco_mesh_compression"])
        if not fallback:
            b.json["extensionsRequired"] = ["KHR_draco_mesh_compression"]
        b.write_glb(HERE / ("draco_skinned_strip_fallback.glb" if fallback else "draco_skinned_strip.glb"))


# ----------------------------------------------------------------------------- meshopt filters
# Encoders written from the decoders of EXT_meshopt_compression's Appendix B, and those
# decoders in float32 numpy, which give the plain twin its values.

def octahedral_encode(normals: np.ndarray) -> np.ndarray:
    """Unit vectors to four int8 (K = 8): octahedral x, y; 127 (1.0); 0."""
    n = normals / np.abs(normals).sum(axis=1, keepdims=True)
    x, y, z = n[:, 0], n[:, 1], n[:, 2]
    fold = z < 0  # the lower hemisphere folded over the diagonals
    x, y = (np.where(fold, (1 - np.abs(y)) * np.sign(x + (x == 0)), x),
            np.where(fold, (1 - np.abs(x)) * np.sign(y + (y == 0)), y))
    out = np.zeros((len(n), 4), np.int8)
    out[:, 0], out[:, 1], out[:, 2] = np.round(x * 127), np.round(y * 127), 127
    return out


def octahedral_decode(encoded: np.ndarray) -> np.ndarray:
    one = encoded[:, 2].astype(np.float32)
    x, y = encoded[:, 0] / one, encoded[:, 1] / one
    z = np.float32(1) - np.abs(x) - np.abs(y)
    t = np.minimum(z, np.float32(0))
    x, y = x - np.copysign(t, x), y - np.copysign(t, y)
    length = np.sqrt(x * x + y * y + z * z)
    out = encoded.copy()
    for i, c in enumerate((x, y, z)):
        out[:, i] = np.round(c / length * 127)
    return out


def quaternion_encode(q: np.ndarray) -> np.ndarray:
    """Unit quaternions to four int16 (K = 16): the three smallest components x sqrt(2) in
    cyclic order after the largest, then 1.0 with the largest's index in the low 2 bits."""
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    largest = np.argmax(np.abs(q), axis=1)
    q = q * np.where(q[np.arange(len(q)), largest] < 0, -1, 1)[:, None]
    out = np.zeros((len(q), 4), np.int16)
    for i in range(len(q)):
        m = largest[i]
        out[i, :3] = np.round([q[i, (m + k) % 4] * SQRT2 * 32767 for k in (1, 2, 3)])
        out[i, 3] = (32767 & ~3) | m
    return out


def quaternion_decode(encoded: np.ndarray) -> np.ndarray:
    rng = np.float32(1 / SQRT2)
    one = (encoded[:, 3] | 3).astype(np.float32)
    xyz = encoded[:, :3] / one[:, None] * rng
    w = np.sqrt(np.maximum(np.float32(0), 1 - (xyz * xyz).sum(axis=1)))
    out = np.zeros_like(encoded)
    for i in range(len(encoded)):
        m = int(encoded[i, 3] & 3)
        for k in (1, 2, 3):
            out[i, (m + k) % 4] = np.round(xyz[i, k - 1] * 32767)
        out[i, m] = np.round(w[i] * 32767)
    return out


def exponential_encode(values: np.ndarray) -> np.ndarray:
    """float32 values to int32 (8-bit exponent, 24-bit signed mantissa): v ~ m x 2^e."""
    _, exponent = np.frexp(values.astype(np.float64))
    e = np.where(values == 0, 0, exponent - 22).astype(np.int64)  # |m| < 2^22: rounding stays in 24 bits
    m = np.round(values / np.exp2(e)).astype(np.int64)
    return ((e << 24) | (m & 0xFFFFFF)).astype(np.int32)


def exponential_decode(encoded: np.ndarray) -> np.ndarray:
    e = encoded >> 24
    m = (encoded << 8) >> 8
    return (np.exp2(e.astype(np.float64)) * m).astype(np.float32)


# ----------------------------------------------------------------------------- meshopt

def meshopt_instances():
    p, n, uv, faces = sphere(subdivisions=2)
    p, uv = (0.45 * p).astype(np.float32), uv.astype(np.float32)
    normals8 = octahedral_encode(n)
    uv_exp = exponential_encode(uv)
    floor = np.array([[-3, -0.5, 2], [3, -0.5, 2], [-3, -0.5, -2], [3, -0.5, -2]], np.float32)
    floor_n = np.tile(np.array([0, 127, 0, 0], np.int8), (4, 1))  # as BYTE normalized, no filter
    strip = np.array([0, 1, 2, 3], np.uint16)
    translations = np.array([[-1.2, 0, 0], [0, 0.1, -0.4], [1.2, 0, 0]], np.float32)
    axis = np.array([0.3, 1.0, 0.2]) / np.linalg.norm([0.3, 1.0, 0.2])
    rotations = quaternion_encode(np.array([[*(axis * math.sin(a / 2)), math.cos(a / 2)] for a in (0.0, 1.3, -2.2)]))
    # (name, raw bytes, stride, count, mode, filter, decoded bytes, target)
    views = [
        ("POSITION", p.tobytes(), 12, len(p), "ATTRIBUTES", "NONE", p.tobytes(), ARRAY_BUFFER),
        ("NORMAL", normals8.tobytes(), 4, len(p), "ATTRIBUTES", "OCTAHEDRAL", octahedral_decode(normals8).tobytes(),
         ARRAY_BUFFER),
        ("TEXCOORD_0", uv_exp.tobytes(), 8, len(p), "ATTRIBUTES", "EXPONENTIAL",
         exponential_decode(uv_exp).tobytes(), ARRAY_BUFFER),
        ("indices", faces.astype(np.uint16).tobytes(), 2, faces.size, "TRIANGLES", "NONE",
         faces.astype(np.uint16).tobytes(), ELEMENT_ARRAY_BUFFER),
        ("floor POSITION", floor.tobytes(), 12, 4, "ATTRIBUTES", "NONE", floor.tobytes(), ARRAY_BUFFER),
        ("floor NORMAL", floor_n.tobytes(), 4, 4, "ATTRIBUTES", "NONE", floor_n.tobytes(), ARRAY_BUFFER),
        ("floor indices", strip.tobytes(), 2, 4, "INDICES", "NONE", strip.tobytes(), ELEMENT_ARRAY_BUFFER),
        ("TRANSLATION", translations.tobytes(), 12, 3, "ATTRIBUTES", "NONE", translations.tobytes(), None),
        ("ROTATION", rotations.tobytes(), 8, 3, "ATTRIBUTES", "QUATERNION", quaternion_decode(rotations).tobytes(),
         None),
    ]
    accessors = {  # name -> (type, componentType, normalized)
        "POSITION": ("VEC3", 5126, False), "NORMAL": ("VEC3", 5120, True), "TEXCOORD_0": ("VEC2", 5126, False),
        "indices": ("SCALAR", 5123, False), "floor POSITION": ("VEC3", 5126, False),
        "floor NORMAL": ("VEC3", 5120, True), "floor indices": ("SCALAR", 5123, False),
        "TRANSLATION": ("VEC3", 5126, False), "ROTATION": ("VEC4", 5122, True)}
    meshoptimizer.encode_vertex_version(0)  # the extension's bitstream: header 0xa0
    for compressed in (True, False):
        b = Builder()
        index = {}
        fallback_length = 0
        for name, raw, stride, count, mode, filter_, decoded, target in views:
            if compressed:
                if mode == "ATTRIBUTES":
                    data = meshoptimizer.encode_vertex_buffer(np.frombuffer(raw, np.uint8).reshape(count, stride),
                                                              count, stride)
                elif mode == "TRIANGLES":
                    data = meshoptimizer.encode_index_buffer(np.frombuffer(raw, np.uint16), count, len(p))
                else:
                    data = meshoptimizer.encode_index_sequence(np.frombuffer(raw, np.uint16), count, 4)
                v = b.json["bufferViews"][b.view(data)]
                ext = {"buffer": 0, "byteOffset": v["byteOffset"], "byteLength": v["byteLength"],
                       "byteStride": stride, "count": count, "mode": mode}
                if filter_ != "NONE":
                    ext["filter"] = filter_
                fallback_length += -fallback_length % 4
                v.update({"buffer": 1, "byteOffset": fallback_length, "byteLength": stride * count,
                          "extensions": {"EXT_meshopt_compression": ext}})
                fallback_length += stride * count
            else:
                v = b.json["bufferViews"][b.view(decoded)]
            if mode == "ATTRIBUTES" and target == ARRAY_BUFFER:
                v["byteStride"] = stride
            if target:
                v["target"] = target
            kind, component, normalized = accessors[name]
            acc = {"bufferView": len(b.json["bufferViews"]) - 1, "componentType": component, "count": count,
                   "type": kind}
            if normalized:
                acc["normalized"] = True
            if name.endswith("POSITION"):
                values = np.frombuffer(raw, np.float32).reshape(count, 3)
                acc["min"], acc["max"] = values.min(axis=0).tolist(), values.max(axis=0).tolist()
            index[name] = b.add("accessors", acc)
        material = _textured_material(b)
        grey = b.add("materials", {"name": "floor", "pbrMetallicRoughness": {
            "baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0.0, "roughnessFactor": 0.8}})
        b.json["meshes"] = [
            {"primitives": [{"attributes": {k: index[k] for k in ("POSITION", "NORMAL", "TEXCOORD_0")},
                             "indices": index["indices"], "material": material}]},
            {"primitives": [{"attributes": {"POSITION": index["floor POSITION"], "NORMAL": index["floor NORMAL"]},
                             "indices": index["floor indices"], "material": grey, "mode": 5}]}]
        spheres = b.add("nodes", {"mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": {
            "TRANSLATION": index["TRANSLATION"], "ROTATION": index["ROTATION"]}}}})
        _lit(b, [spheres, b.add("nodes", {"mesh": 1})], camera_at=(0.0, 1.2, 4.5))
        used = ["EXT_mesh_gpu_instancing", "KHR_mesh_quantization"]
        b.json["extensionsUsed"] = sorted(b.json["extensionsUsed"] + used
                                          + (["EXT_meshopt_compression"] if compressed else []))
        b.json["extensionsRequired"] = sorted(["KHR_mesh_quantization"]
                                              + (["EXT_meshopt_compression"] if compressed else []))
        if compressed:  # buffer 0 is the GLB chunk; buffer 1 the placeholder the views' fallback names
            b.write_glb(HERE / "meshopt_instances.glb",
                        extra_buffers=[{"byteLength": fallback_length,
                                        "extensions": {"EXT_meshopt_compression": {"fallback": True}}}])
        else:
            b.write_glb(HERE / "meshopt_instances_plain.glb")


# ----------------------------------------------------------------------------- morph targets

def morph_scenes():
    k = 9  # vertices along each side of the grid
    s = np.linspace(-1, 1, k)
    x, y = np.meshgrid(s, s)
    base = np.stack([x.ravel(), y.ravel(), np.zeros(k * k)], axis=1)
    normals = np.tile([0.0, 0.0, 1.0], (k * k, 1))
    r2 = base[:, 0] ** 2 + base[:, 1] ** 2
    bump = 0.6 * np.exp(-2 * r2)  # z of the bump target
    gx, gy = -4 * base[:, 0] * bump, -4 * base[:, 1] * bump  # its gradient
    bump_normals = np.stack([-gx, -gy, np.ones_like(gx)], axis=1)
    bump_normals /= np.linalg.norm(bump_normals, axis=1, keepdims=True)
    bump_delta = np.stack([np.zeros_like(bump), np.zeros_like(bump), bump], axis=1)
    shear_delta = np.stack([0.3 * base[:, 1], np.zeros(k * k), np.zeros(k * k)], axis=1)
    cells = [(i * k + j, i * k + j + 1, (i + 1) * k + j + 1, (i + 1) * k + j) for i in range(k - 1) for j in range(k - 1)]
    faces = np.array([[a, b, c] for a, b, c, d in cells] + [[a, c, d] for a, b, c, d in cells])
    b = Builder()
    material = b.add("materials", {"name": "clay", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.5, 0.3, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6}})
    primitive = b.primitive(base, normals, None, faces, material)
    primitive["targets"] = [
        {"POSITION": b.accessor(bump_delta, "VEC3", bounds=True),
         "NORMAL": b.accessor(bump_normals - normals, "VEC3")},
        {"POSITION": b.accessor(shear_delta, "VEC3", bounds=True)}]
    b.json["meshes"].append({"primitives": [primitive], "weights": [0.5, 0.0]})
    mesh_weights = b.add("nodes", {"mesh": 0, "translation": [-1.1, 0, 0]})
    node_weights = b.add("nodes", {"mesh": 0, "translation": [1.1, 0, 0], "weights": [1.0, 1.0]})
    _lit(b, [mesh_weights], camera_at=(0.0, -1.5, 5.0))
    b.json["scenes"].append({"nodes": [node_weights] + b.json["scenes"][0]["nodes"][1:]})
    b.write_gltf(HERE / "morph_scenes.gltf", external_bin=False)


def main():
    draco_spheres()
    draco_skinned_strips()
    meshopt_instances()
    morph_scenes()


if __name__ == "__main__":
    main()
