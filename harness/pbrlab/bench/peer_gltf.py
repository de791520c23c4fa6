"""One small glTF file per material class (issue 35's whole-program comparison): the same UV
sphere (positions, normals, tangents, texture coordinates), the same three 64 x 64 textures
and the same KHR_lights_punctual directional lights in every file; only the material's
extension differs. pbrlab, three.js and the Khronos Sample Viewer load the same bytes, so the
fragment programs they build differ only by what each renderer makes of the class.

The files are deterministic (no timestamps, fixed procedural textures): ``sha256`` of a file
written now equals the one recorded beside the captured peer programs
(benchmarks/peer_programs/manifest.json), which is how the bench knows its captures are of
these files.

Textures (procedural, smooth, so no class folds to a constant): base colour (sRGB) a warm
gradient with stripes; metallic-roughness (linear: G roughness 0.25..0.85, B metallic 0..1);
a tangent-space normal map of gentle bumps. The specular-glossiness class reads the base
colour image as its diffuse texture and a specular-glossiness image made from the same
pattern; the unlit class reads the base colour alone (the extension ignores the rest).
"""

from __future__ import annotations

import hashlib
import io
import json
import math
import struct
from pathlib import Path

import numpy as np
from PIL import Image

SEGMENTS = (32, 16)        # UV sphere: longitude x latitude quads
TEXTURE_SIZE = 64
LIGHT_DIRECTION = (0.4, -0.8, -0.5)   # where the lights shine (world; benchmarks/tier_program_cost.py's light)
LIGHT_INTENSITY_LUX = 3.0   # split evenly over the lights (the count, not the value, enters a program)
LIGHT_COUNTS = (0, 1, 4)

# class -> the material's extensions beyond the shared core (base colour, metallic-roughness and
# normal textures; specular-glossiness reads images 0 and 3, unlit only the base colour)
CLASSES = {
    "metallic-roughness": {},
    "specular-glossiness": {"KHR_materials_pbrSpecularGlossiness": {
        "diffuseFactor": [1, 1, 1, 1], "specularFactor": [1, 1, 1], "glossinessFactor": 1.0,
        "diffuseTexture": {"index": 0}, "specularGlossinessTexture": {"index": 3}}},
    "clear-coat": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.1}},
    "sheen": {"KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.6, 0.7], "sheenRoughnessFactor": 0.5}},
    "transmission": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                     "KHR_materials_volume": {"thicknessFactor": 0.3, "attenuationDistance": 0.5,
                                              "attenuationColor": [0.9, 0.5, 0.4]}},
    "iridescence": {"KHR_materials_iridescence": {"iridescenceFactor": 1.0, "iridescenceIor": 1.3,
                                                  "iridescenceThicknessMinimum": 100.0,
                                                  "iridescenceThicknessMaximum": 400.0}},
    "anisotropy": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.6, "anisotropyRotation": 0.4}},
    "unlit": {"KHR_materials_unlit": {}},
}


def _png(pixels: np.ndarray) -> bytes:
    buffer = io.BytesIO()
    Image.fromarray(pixels, "RGBA" if pixels.shape[2] == 4 else "RGB").save(buffer, "PNG", optimize=False)
    return buffer.getvalue()


def textures() -> dict:
    """{name: PNG bytes}: base colour, metallic-roughness, normal, specular-glossiness."""
    n = TEXTURE_SIZE
    u, v = np.meshgrid((np.arange(n) + 0.5) / n, (np.arange(n) + 0.5) / n)
    stripes = 0.5 + 0.5 * np.sin(2 * math.pi * 4 * u)
    base = np.stack([0.55 + 0.4 * u, 0.25 + 0.3 * stripes, 0.15 + 0.2 * v], -1)
    rough = 0.25 + 0.6 * v
    metal = stripes
    mr = np.stack([np.ones_like(u), rough, metal], -1)
    # normal map: the gradient of h = 0.04 sin(2 pi 3u) sin(2 pi 3v) in tangent space
    du = 0.04 * 2 * math.pi * 3 * np.cos(2 * math.pi * 3 * u) * np.sin(2 * math.pi * 3 * v)
    dv = 0.04 * 2 * math.pi * 3 * np.sin(2 * math.pi * 3 * u) * np.cos(2 * math.pi * 3 * v)
    normal = np.stack([-du, -dv, np.ones_like(u)], -1)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    spec_gloss = np.concatenate([np.repeat((0.04 + 0.9 * metal)[..., None], 3, -1), (1 - rough)[..., None]], -1)
    to8 = lambda a: np.round(np.clip(a, 0, 1) * 255).astype(np.uint8)
    return {"base_colour": _png(to8(base)), "metallic_roughness": _png(to8(mr)),
            "normal": _png(to8(normal * 0.5 + 0.5)), "specular_glossiness": _png(to8(spec_gloss))}


def sphere(radius: float = 1.0):
    """(positions, normals, tangents (xyz, w = +1), uvs, uint16 indices) of the UV sphere."""
    nu, nv = SEGMENTS
    rows = []
    for j in range(nv + 1):
        theta = math.pi * j / nv
        for i in range(nu + 1):
            phi = 2 * math.pi * i / nu
            n = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            t = (math.cos(phi), 0.0, -math.sin(phi))   # d/dphi: along +u
            rows.append((n, t, (i / nu, j / nv)))
    normals = np.array([r[0] for r in rows], np.float32)
    tangents = np.array([(*r[1], 1.0) for r in rows], np.float32)
    uvs = np.array([r[2] for r in rows], np.float32)
    indices = []
    for j in range(nv):
        for i in range(nu):
            a, b = j * (nu + 1) + i, (j + 1) * (nu + 1) + i
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return normals * radius, normals, tangents, uvs, np.array(indices, np.uint16)


def _light_nodes(count: int) -> tuple[list, list]:
    """(lights, nodes): ``count`` directional lights, all shining along LIGHT_DIRECTION (a node's
    rotation turns the light's -Z onto it), their intensities summing to one light's."""
    d = np.array(LIGHT_DIRECTION, float)
    d /= np.linalg.norm(d)
    # quaternion rotating (0, 0, -1) onto d: axis (0,0,-1) x d, angle acos(-d_z)
    axis = np.cross([0.0, 0.0, -1.0], d)
    s = np.linalg.norm(axis)
    angle = math.acos(max(-1.0, min(1.0, -d[2])))
    axis = axis / s if s > 0 else np.array([1.0, 0.0, 0.0])
    q = [*(axis * math.sin(angle / 2)), math.cos(angle / 2)]
    lights = [{"type": "directional", "color": [1.0, 1.0, 1.0], "intensity": LIGHT_INTENSITY_LUX / count}
              for _ in range(count)]
    nodes = [{"name": f"light{k}", "rotation": [round(float(x), 9) for x in q],
              "extensions": {"KHR_lights_punctual": {"light": k}}} for k in range(count)]
    return lights, nodes


def gltf_bytes(material_class: str, lights: int) -> bytes:
    """The .glb of ``material_class`` (CLASSES) with ``lights`` directional lights."""
    if material_class not in CLASSES:
        raise KeyError(f"unknown material class {material_class!r} (known: {', '.join(CLASSES)})")
    positions, normals, tangents, uvs, indices = sphere()
    images = textures()
    blobs, views = [], []

    def add(data: bytes, target=None):
        offset = sum(len(b) for b in blobs)
        blobs.append(data + b"\0" * (-len(data) % 4))
        view = {"buffer": 0, "byteOffset": offset, "byteLength": len(data)}
        if target:
            view["target"] = target
        views.append(view)
        return len(views) - 1

    accessors = []
    for array, kind in ((positions, "VEC3"), (normals, "VEC3"), (tangents, "VEC4"), (uvs, "VEC2")):
        accessor = {"bufferView": add(array.tobytes(), 34962), "componentType": 5126, "count": len(array),
                    "type": kind}
        if array is positions:
            accessor.update(min=[float(x) for x in array.min(0)], max=[float(x) for x in array.max(0)])
        accessors.append(accessor)
    accessors.append({"bufferView": add(indices.tobytes(), 34963), "componentType": 5123,
                      "count": len(indices), "type": "SCALAR"})
    image_names = ("base_colour", "metallic_roughness", "normal", "specular_glossiness")
    gltf_images = [{"bufferView": add(images[name]), "mimeType": "image/png", "name": name} for name in image_names]
    extensions = CLASSES[material_class]
    material = {"name": material_class,
                "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1},
                                         "baseColorFactor": [1, 1, 1, 1], "metallicFactor": 1.0,
                                         "roughnessFactor": 1.0},
                "normalTexture": {"index": 2}}
    if extensions:
        material["extensions"] = json.loads(json.dumps(extensions))
    light_list, light_nodes = _light_nodes(lights)
    used = sorted(set(extensions) | ({"KHR_lights_punctual"} if lights else set()))
    document = {
        "asset": {"version": "2.0", "generator": "pbrlab.bench.peer_gltf"},
        "scene": 0, "scenes": [{"nodes": list(range(1 + len(light_nodes)))}],
        "nodes": [{"name": "sphere", "mesh": 0}, *light_nodes],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3},
                                    "indices": 4, "material": 0}]}],
        "materials": [material],
        "textures": [{"source": k, "sampler": 0} for k in range(len(gltf_images))],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "images": gltf_images, "accessors": accessors, "bufferViews": views,
        "buffers": [{"byteLength": sum(len(b) for b in blobs)}],
    }
    if used:
        document["extensionsUsed"] = used
    if light_list:
        document["extensions"] = {"KHR_lights_punctual": {"lights": light_list}}
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary = b"".join(blobs)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(text), 0x4E4F534A) + text
            + struct.pack("<II", len(binary), 0x004E4942) + binary)


def file_name(material_class: str, lights: int) -> str:
    return f"{material_class}-{lights}light.glb"


def write(folder, material_class: str, lights: int) -> tuple[Path, str]:
    """(path, sha256) of the class's file written into ``folder``."""
    data = gltf_bytes(material_class, lights)
    path = Path(folder) / file_name(material_class, lights)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    return path, hashlib.sha256(data).hexdigest()
