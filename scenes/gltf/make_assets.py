"""Generates the glTF 2.0 test assets (committed next to this script; run it again to
rebuild them byte for byte): geometry from trimesh.creation, textures drawn with numpy,
and the glTF JSON written by hand, so each file shows exactly the feature it tests.

    hierarchy_lights.glb     a node hierarchy (TRS and matrix), one mesh of three primitives
                             with three materials, a floor, directional + point + spot
                             lights, a perspective camera
    textured.gltf (+ .bin, PNGs)   baseColor (sRGB), metallicRoughness, normal and emissive
                             textures on quads lit by a directional and a point light
    texture_transform.gltf   KHR_texture_transform on a base colour texture (rotation,
                             scale, offset), MIRRORED_REPEAT / CLAMP_TO_EDGE samplers
    texture_transform.pyrender.gltf  the same with the transform applied to the UVs here,
                             in float64 from the extension's README (pyrender has no reader
                             for the extension): what the pyrender cross-check renders
    alpha_modes.glb          MASK (alphaCutoff over a textured alpha) and BLEND quads
                             before an opaque backdrop
    features.gltf            orthographic camera, COLOR_0, TEXCOORD_1 (occlusion with
                             strength), normal scale, non-indexed flat-shaded box (no
                             NORMAL), doubleSided quad seen from behind, KHR_materials_ior +
                             _specular, _emissive_strength, and KHR_materials_dispersion
                             (not honoured: named in a warning); data: URIs only
    sheen.gltf               KHR_materials_sheen on four quads: none, a white sheen, a sheen
                             with colour (sRGB RGB) and roughness (A) textures, a sheen under a coat
    anisotropy.gltf          KHR_materials_anisotropy on four metal quads (no TANGENT: MikkTSpace):
                             none, strength 0.8 along the tangent, the same turned a quarter
                             (anisotropyRotation pi/2), and a swirl map (RG direction around the
                             centre, B strength rising outwards) under a KHR_texture_transform
    iridescence.gltf         KHR_materials_iridescence on four dark quads: none, a 400 nm film of
                             IOR 1.3 (the defaults but the factor), a film whose thickness runs
                             100 -> 800 nm across a thickness texture (G) under a mask texture (R),
                             a film under a coat on an anisotropic metal
    transmission.gltf        KHR_materials_transmission and KHR_materials_volume on four white
                             spheres: none, a smooth thin wall (transmissionFactor 1), a rough thin
                             wall whose transmission a texture (R) stripes, a tinted volume of IOR
                             1.33 (thicknessFactor 0.4 x a thickness texture's G, attenuation colour
                             and distance) on a node scaled 0.8 (the thickness scales with it)
    specular_layers.gltf     KHR_materials_specular (specularFactor 0.4: F90 0.4) on four dark
                             dielectric spheres: alone, with KHR_materials_anisotropy (0.8), with
                             KHR_materials_iridescence (a 400 nm film), with a thin
                             KHR_materials_transmission wall: the explicit F90 through each layer
    transmission_slab.gltf   three glass slabs half over an emissive backdrop (no light, no
                             environment: all they show is what lies behind them): a smooth thin
                             wall of IOR 1, one of IOR 1.5, and a smooth tinted volume (IOR 1.5,
                             thicknessFactor 0.3, attenuation colour and distance) that the
                             transmission copy test checks against the float64 fraction
    specular_metal.gltf      KHR_materials_ior / KHR_materials_specular on (partly) metallic quads:
                             rows metallicFactor 0, 0.5 and 1 x a metallicRoughness texture (B:
                             metallic rising 0 -> 1 left to right); columns none, ior 1.8 alone,
                             specularFactor 0.6 with specularColorFactor (2.5, 1, 0.25) at ior 1.5,
                             and colour (5, 5, 5) x a specularColorTexture (sRGB) x a specularTexture
                             (A); one orange base colour, roughness 0.35
    clearcoat.gltf           KHR_materials_clearcoat on four quads: none, a smooth full coat,
                             a rough coat masked by a texture (clearcoatTexture.r x factor,
                             clearcoatRoughnessTexture.g), a coat with its own normal map
                             over a flat base; data: URIs only

    .venv/bin/python scenes/gltf/make_assets.py
"""

from __future__ import annotations

import base64
import io
import json
import math
import struct
from pathlib import Path

import numpy as np
import trimesh
from PIL import Image

HERE = Path(__file__).resolve().parent
TEX = 64  # texture size in pixels


# ----------------------------------------------------------------------------- writer

class Builder:
    """Accumulates one binary buffer, its views and accessors, and the glTF JSON."""

    def __init__(self):
        self.blob = bytearray()
        self.json = {"asset": {"version": "2.0", "generator": "pbrlab scenes/gltf/make_assets.py"},
                     "accessors": [], "bufferViews": [], "meshes": [], "materials": [], "nodes": []}

    def view(self, data: bytes, target: int | None = None) -> int:
        while len(self.blob) % 4:
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.blob.extend(data)
        self.json["bufferViews"].append(view)
        return len(self.json["bufferViews"]) - 1

    def accessor(self, array, kind: str, component: int = 5126, bounds: bool = False) -> int:
        dtype = {5126: np.float32, 5125: np.uint32, 5123: np.uint16, 5121: np.uint8}[component]
        array = np.ascontiguousarray(array, dtype)
        target = 34963 if kind == "SCALAR" and component != 5126 else 34962
        acc = {"bufferView": self.view(array.tobytes(), target), "componentType": component,
               "count": len(array), "type": kind}
        if bounds:
            acc["min"] = array.min(axis=0).tolist()
            acc["max"] = array.max(axis=0).tolist()
        self.json["accessors"].append(acc)
        return len(self.json["accessors"]) - 1

    def primitive(self, positions, normals=None, uv=None, indices=None, material=None, **extra) -> dict:
        attributes = {"POSITION": self.accessor(positions, "VEC3", bounds=True)}
        if normals is not None:
            attributes["NORMAL"] = self.accessor(normals, "VEC3")
        if uv is not None:
            attributes["TEXCOORD_0"] = self.accessor(uv, "VEC2")
        for name, (array, kind) in extra.items():
            attributes[name] = self.accessor(array, kind)
        prim = {"attributes": attributes}
        if indices is not None:
            prim["indices"] = self.accessor(np.asarray(indices).reshape(-1), "SCALAR", 5123)
        if material is not None:
            prim["material"] = material
        return prim

    def add(self, key: str, item: dict) -> int:
        self.json.setdefault(key, []).append(item)
        return len(self.json[key]) - 1

    def image(self, pixels: np.ndarray, embed: bool, name: str | None = None) -> int:
        png = _png(pixels)
        if embed:
            return self.add("images", {"bufferView": self.view(png), "mimeType": "image/png"})
        (HERE / name).write_bytes(png)
        return self.add("images", {"uri": name})

    def texture(self, image: int, sampler: dict | None = None) -> int:
        tex = {"source": image}
        if sampler is not None:
            tex["sampler"] = self.add("samplers", sampler)
        return self.add("textures", tex)

    def write_glb(self, path: Path, extra_buffers: list | None = None):
        """``extra_buffers``: buffer objects after the GLB chunk's (EXT_meshopt_compression's fallback)."""
        self.json["buffers"] = [{"byteLength": len(self.blob)}] + (extra_buffers or [])
        text = json.dumps(self.json, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        blob = bytes(self.blob) + b"\0" * (-len(self.blob) % 4)
        total = 12 + 8 + len(text) + 8 + len(blob)
        path.write_bytes(struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<II", len(text), 0x4E4F534A)
                         + text + struct.pack("<II", len(blob), 0x004E4942) + blob)

    def write_gltf(self, path: Path, external_bin: bool):
        if external_bin:
            (path.with_suffix(".bin")).write_bytes(bytes(self.blob))
            uri = path.with_suffix(".bin").name
        else:
            uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()
        self.json["buffers"] = [{"byteLength": len(self.blob), "uri": uri}]
        path.write_text(json.dumps(self.json, indent=1) + "\n", encoding="utf-8")


def _png(pixels: np.ndarray) -> bytes:
    out = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(pixels)).save(out, format="PNG", optimize=False, compress_level=9)
    return out.getvalue()


def _srgb8(linear) -> np.ndarray:
    """Linear [0, 1] -> sRGB code values (IEC 61966-2-1)."""
    c = np.clip(np.asarray(linear, np.float64), 0, 1)
    encoded = np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)
    return np.round(encoded * 255).astype(np.uint8)


def _grid():
    """Texel-centre coordinates (u right, v down the image) in [0, 1]."""
    v, u = np.meshgrid((np.arange(TEX) + 0.5) / TEX, (np.arange(TEX) + 0.5) / TEX, indexing="ij")
    return u, v


def _rgba8(*rgba) -> list:
    """A baseColorFactor on the 8-bit grid: trimesh's glTF reader stores the factor as
    8-bit RGBA, so pyrender would otherwise shade a colour up to half a code away."""
    return [round(c * 255) / 255 for c in rgba]


def _quaternion(axis, angle) -> list:
    axis = np.asarray(axis, np.float64) / np.linalg.norm(axis)
    return [*(axis * math.sin(angle / 2)).tolist(), math.cos(angle / 2)]


def _look_rotation(direction) -> list:
    """A quaternion turning -Z onto ``direction`` (lights and cameras look down -Z)."""
    d = np.asarray(direction, np.float64) / np.linalg.norm(direction)
    z = -d
    x = np.cross([0.0, 1.0, 0.0], z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.stack([x, y, z], axis=1)
    w = math.sqrt(max(0.0, 1 + m[0, 0] + m[1, 1] + m[2, 2])) / 2
    return [(m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w), w]


def _quad(size=2.0):
    """A square in the XY plane facing +Z, UVs with v down (glTF): (0,0) at the top left."""
    s = size / 2
    positions = np.array([[-s, -s, 0], [s, -s, 0], [s, s, 0], [-s, s, 0]], np.float64)
    normals = np.tile([0.0, 0.0, 1.0], (4, 1))
    uv = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float64)
    return positions, normals, uv, np.array([0, 1, 2, 0, 2, 3])


# _quad's tangent frame: u grows along +X, v (glTF, down) along -Y, so the bitangent
# cross(n, t) * w = +Y points to decreasing v: MikkTSpace's w = 1 for glTF's flipped v.
_QUAD_TANGENTS = np.tile([1.0, 0.0, 0.0, 1.0], (4, 1))


def _sphere(subdivisions=3, radius=1.0, offset=(0, 0, 0)):
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=radius)
    positions = np.asarray(mesh.vertices) + np.asarray(offset)
    return positions, np.asarray(mesh.vertex_normals), np.asarray(mesh.faces)


# ----------------------------------------------------------------------------- textures

def checker(colours=((0.8, 0.75, 0.7), (0.1, 0.25, 0.6)), cells=4, alpha=None) -> np.ndarray:
    u, v = _grid()
    odd = ((np.floor(u * cells) + np.floor(v * cells)) % 2).astype(bool)
    rgb = np.where(odd[..., None], colours[1], colours[0])
    # a marker in the top-left cell shows orientation and mirroring
    rgb = np.where(((u < 0.5 / cells) & (v < 0.5 / cells))[..., None], (0.9, 0.1, 0.05), rgb)
    out = _srgb8(rgb)
    if alpha is not None:
        out = np.concatenate([out, np.round(np.clip(alpha, 0, 1) * 255).astype(np.uint8)[..., None]], axis=2)
    return out


def metallic_roughness() -> np.ndarray:
    """G roughness rising left to right 0.15 -> 0.9, B metallic: 1 in the top half."""
    u, v = _grid()
    mr = np.zeros((TEX, TEX, 3), np.uint8)
    mr[..., 1] = np.round((0.15 + 0.75 * u) * 255).astype(np.uint8)
    mr[..., 2] = np.where(v < 0.5, 255, 0).astype(np.uint8)
    return mr


def bumps() -> np.ndarray:
    """Tangent-space normals of a 3x3 grid of domes (+X right, +Y up the image)."""
    u, v = _grid()
    cu, cv = (u * 3) % 1 - 0.5, (v * 3) % 1 - 0.5
    r2 = cu * cu + cv * cv
    inside = r2 < 0.16
    # dome height h = sqrt(0.16 - r^2): slopes dh/du, dh/dv; image v runs down, so +Y = -v
    h = np.sqrt(np.maximum(0.16 - r2, 1e-4))
    nx = np.where(inside, cu / h, 0.0) * 0.6
    ny = np.where(inside, -cv / h, 0.0) * 0.6
    n = np.stack([nx, ny, np.ones_like(nx)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return np.round((n * 0.5 + 0.5) * 255).astype(np.uint8)


def glow() -> np.ndarray:
    u, v = _grid()
    ring = np.abs(np.hypot(u - 0.5, v - 0.5) - 0.3) < 0.06
    return _srgb8(np.where(ring[..., None], (1.0, 0.55, 0.15), (0.0, 0.0, 0.0)))


def disc_alpha() -> np.ndarray:
    """Alpha 1 inside a disc, 0.2 outside: a MASK at 0.45 keeps the disc only."""
    u, v = _grid()
    return np.where(np.hypot(u - 0.5, v - 0.5) < 0.42, 1.0, 0.2)


def occlusion() -> np.ndarray:
    u, v = _grid()
    ao = 0.25 + 0.75 * np.clip(np.hypot(u - 0.5, v - 0.5) * 2, 0, 1)
    return np.round(np.repeat(ao[..., None], 3, axis=2) * 255).astype(np.uint8)


# ----------------------------------------------------------------------------- assets

def hierarchy_lights():
    b = Builder()
    materials = [
        {"name": "red_dielectric", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.8, 0.1, 0.08, 1),
                                                            "metallicFactor": 0.0, "roughnessFactor": 0.45}},
        {"name": "gold_metal", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(1.0, 0.766, 0.336, 1),
                                                        "metallicFactor": 1.0, "roughnessFactor": 0.3}},
        {"name": "blue_half_metal", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.15, 0.3, 0.8, 1),
                                                             "metallicFactor": 0.5, "roughnessFactor": 0.7}},
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.6, 0.6, 0.6, 1),
                                                   "metallicFactor": 0.0, "roughnessFactor": 0.8}},
    ]
    b.json["materials"] = materials
    prims = []
    for i, x in enumerate((-2.3, 0.0, 2.3)):
        p, n, f = _sphere(3, 1.0, (x, 0, 0))
        prims.append(b.primitive(p, n, indices=f, material=i))
    b.json["meshes"].append({"name": "trio", "primitives": prims})
    floor = trimesh.creation.box(extents=[9, 0.2, 5])
    b.json["meshes"].append({"name": "floor", "primitives": [
        b.primitive(np.asarray(floor.vertices)[floor.faces.reshape(-1)], None, material=3)]})  # no NORMAL: flat
    b.json["extensionsUsed"] = ["KHR_lights_punctual"]
    b.json["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "color": [1.0, 0.95, 0.9], "intensity": 2.5},
        {"name": "bulb", "type": "point", "color": [1.0, 0.8, 0.6], "intensity": 12.0},
        {"name": "spot", "type": "spot", "color": [0.6, 0.8, 1.0], "intensity": 40.0,
         "spot": {"innerConeAngle": 0.15, "outerConeAngle": 0.4}},
    ]}}
    nodes = b.json["nodes"]
    nodes.append({"name": "stage", "children": [1, 2], "rotation": _quaternion([0, 1, 0], 0.25),
                  "scale": [0.9, 0.9, 0.9]})
    nodes.append({"name": "row", "mesh": 0, "translation": [0, 1.1, 0]})
    m = np.eye(4)
    m[:3, 3] = [0, -0.1, 0]
    nodes.append({"name": "floor", "mesh": 1, "matrix": m.T.reshape(-1).tolist()})
    nodes.append({"name": "sun", "rotation": _look_rotation([0.4, -0.7, -0.6]),
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"name": "bulb", "translation": [-1.5, 2.6, 2.2], "extensions": {"KHR_lights_punctual": {"light": 1}}})
    spot_at = np.array([2.3, 1.0, 0.0])
    spot_from = np.array([3.5, 4.0, 3.0])
    nodes.append({"name": "spot", "translation": spot_from.tolist(), "rotation": _look_rotation(spot_at - spot_from),
                  "extensions": {"KHR_lights_punctual": {"light": 2}}})
    cam_from, cam_at = np.array([0.0, 2.6, 8.5]), np.array([0.0, 0.8, 0.0])
    b.json["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.55, "aspectRatio": 2.0,
                                                                 "znear": 0.1, "zfar": 50}}]
    nodes.append({"name": "camera", "camera": 0, "translation": cam_from.tolist(),
                  "rotation": _look_rotation(cam_at - cam_from)})
    b.json["scenes"] = [{"nodes": [0, 3, 4, 5, 6]}]
    b.json["scene"] = 0
    b.write_glb(HERE / "hierarchy_lights.glb")


def _lit_quads_scene(b: Builder, quads: list[tuple[int, tuple]], camera_y=0.0, distance=6.0, yfov=0.6,
                     aspect=2.0, lights=None):
    """Nodes for quads (mesh index, translation), a directional and a point light, a camera."""
    nodes = b.json["nodes"]
    for mesh, translation in quads:
        nodes.append({"mesh": mesh, "translation": list(translation)})
    b.json["extensionsUsed"] = sorted(set(b.json.get("extensionsUsed", [])) | {"KHR_lights_punctual"})
    b.json.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": lights or [
        {"type": "directional", "intensity": 2.0}, {"type": "point", "intensity": 6.0, "color": [1, 0.9, 0.8]}]}
    nodes.append({"rotation": _look_rotation([0.3, -0.35, -1.0]), "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"translation": [1.0, 1.2, 2.5], "extensions": {"KHR_lights_punctual": {"light": 1}}})
    b.json["cameras"] = [{"type": "perspective", "perspective": {"yfov": yfov, "aspectRatio": aspect, "znear": 0.1}}]
    nodes.append({"camera": 0, "translation": [0.0, camera_y, distance]})
    b.json["scenes"] = [{"nodes": list(range(len(nodes)))}]
    b.json["scene"] = 0


def textured():
    b = Builder()
    images = {name: b.image(pixels, embed=False, name=f"textured_{name}.png")
              for name, pixels in (("base", checker()), ("mr", metallic_roughness()),
                                   ("normal", bumps()), ("glow", glow()))}
    tex = {name: b.texture(index) for name, index in images.items()}
    b.json["materials"] = [
        {"name": "checker_mr", "pbrMetallicRoughness": {"baseColorTexture": {"index": tex["base"]},
                                                        "metallicRoughnessTexture": {"index": tex["mr"]},
                                                        "metallicFactor": 1.0, "roughnessFactor": 1.0}},
        {"name": "bumpy", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.7, 0.7, 0.72, 1), "metallicFactor": 0.0,
                                                   "roughnessFactor": 0.35},
         "normalTexture": {"index": tex["normal"]}},
        {"name": "glowing", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.2, 0.2, 0.2, 1), "metallicFactor": 0.0,
                                                     "roughnessFactor": 0.6},
         "emissiveTexture": {"index": tex["glow"]}, "emissiveFactor": [1.0, 1.0, 1.0]},
    ]
    p, n, uv, f = _quad(1.8)
    for material in range(3):
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material)]})
    _lit_quads_scene(b, [(0, (-2.0, 0, 0)), (1, (0, 0, 0)), (2, (2.0, 0, 0))], yfov=0.5, aspect=3.0, distance=5.5)
    b.write_gltf(HERE / "textured.gltf", external_bin=True)


def _khr_texture_transform(uv: np.ndarray, offset, rotation, scale) -> np.ndarray:
    """The extension's README ("Overview"): uv' = T R S uv, with
    R = [[cos, sin], [-sin, cos]] (a rotation counter-clockwise in UV space, v down)."""
    c, s = math.cos(rotation), math.sin(rotation)
    scaled = uv * np.asarray(scale, np.float64)
    rotated = np.stack([c * scaled[:, 0] + s * scaled[:, 1], -s * scaled[:, 0] + c * scaled[:, 1]], axis=1)
    return rotated + np.asarray(offset, np.float64)


TRANSFORM = {"offset": [0.25, -0.1], "rotation": 0.4, "scale": [1.6, 1.3]}


def texture_transform():
    for pyrender in (False, True):
        b = Builder()
        base = b.image(checker(cells=4), embed=False, name="texture_transform_checker.png")
        wraps = [{"wrapS": 10497, "wrapT": 10497}, {"wrapS": 33648, "wrapT": 33648},
                 {"wrapS": 33071, "wrapT": 33071, "magFilter": 9728, "minFilter": 9728}]
        names = ("repeat", "mirrored_repeat", "clamp_nearest")
        p, n, uv, f = _quad(1.8)
        for i, (sampler, name) in enumerate(zip(wraps, names)):
            # pyrender samples with its default sampler: repeat only (the others are pbrlab-only)
            t = b.texture(base, None if pyrender else sampler)
            info = {"index": t}
            quad_uv = uv
            if i == 0 and pyrender:
                quad_uv = _khr_texture_transform(uv, **TRANSFORM)
            elif i == 0:
                info["extensions"] = {"KHR_texture_transform": dict(TRANSFORM)}
            else:
                quad_uv = uv * 2.2 - 0.6  # past [0, 1]: the wrap mode shows
            b.json["materials"].append({"name": name, "pbrMetallicRoughness": {
                "baseColorTexture": info, "metallicFactor": 0.0, "roughnessFactor": 0.6}})
            b.json["meshes"].append({"primitives": [b.primitive(p, n, quad_uv, f, i)]})
            if pyrender:
                break
        if not pyrender:
            b.json["extensionsUsed"] = ["KHR_texture_transform"]
        quads = [(0, (-2.0, 0, 0))] + ([] if pyrender else [(1, (0, 0, 0)), (2, (2.0, 0, 0))])
        _lit_quads_scene(b, quads, yfov=0.5, aspect=3.0, distance=5.5)
        b.write_gltf(HERE / ("texture_transform.pyrender.gltf" if pyrender else "texture_transform.gltf"),
                     external_bin=False)


def alpha_modes():
    b = Builder()
    disc = b.texture(b.image(checker(colours=((0.2, 0.7, 0.2), (0.9, 0.85, 0.2)), alpha=disc_alpha()), embed=True))
    b.json["materials"] = [
        {"name": "backdrop", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.55, 0.5, 0.45, 1), "metallicFactor": 0.0,
                                                      "roughnessFactor": 0.8}},
        {"name": "mask", "alphaMode": "MASK", "alphaCutoff": 0.45,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": disc}, "metallicFactor": 0.0, "roughnessFactor": 0.5}},
        {"name": "blend", "alphaMode": "BLEND",
         "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.1, 0.3, 0.9, 0.5), "metallicFactor": 0.0,
                                  "roughnessFactor": 0.4}},
    ]
    p, n, uv, f = _quad(1.8)
    backdrop_p = p * [1.0, 1.0, 1.0]
    b.json["meshes"].append({"primitives": [b.primitive(backdrop_p, n, uv, f, 0)]})
    b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, 1)]})
    b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, 2)]})
    _lit_quads_scene(b, [(1, (-1.1, 0, 0)), (0, (1.1, 0, -0.6)), (2, (1.1, 0, 0.4))], yfov=0.5, aspect=2.0,
                     distance=5.5)
    b.write_glb(HERE / "alpha_modes.glb")


def features():
    b = Builder()
    base = b.texture(b.image(checker(), embed=True))
    ao = b.texture(b.image(occlusion(), embed=True))
    normal = b.texture(b.image(bumps(), embed=True))
    b.json["materials"] = [
        {"name": "vertex_coloured", "pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 0.5}},
        {"name": "glass_like", "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.2, 0.25, 0.3, 1), "metallicFactor": 0.0,
                                                        "roughnessFactor": 0.15},
         "extensions": {"KHR_materials_ior": {"ior": 1.8},
                        "KHR_materials_specular": {"specularFactor": 0.9, "specularColorFactor": [1.0, 0.9, 0.8]},
                        "KHR_materials_dispersion": {"dispersion": 0.5}}},
        {"name": "occluded_bumps", "pbrMetallicRoughness": {"baseColorTexture": {"index": base},
                                                            "metallicFactor": 0.0, "roughnessFactor": 0.5},
         "occlusionTexture": {"index": ao, "texCoord": 1, "strength": 0.7},
         "normalTexture": {"index": normal, "scale": 0.5}},
        {"name": "two_sided_glow", "doubleSided": True, "emissiveFactor": [0.15, 0.3, 0.5],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2.0}},
         "pbrMetallicRoughness": {"baseColorFactor": _rgba8(0.1, 0.1, 0.1, 1), "metallicFactor": 0.0,
                                  "roughnessFactor": 0.5}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_ior", "KHR_materials_specular", "KHR_materials_dispersion",
                                "KHR_materials_emissive_strength"]
    box = trimesh.creation.box(extents=[1.2, 1.2, 1.2])
    corners = np.asarray(box.vertices)[box.faces.reshape(-1)]  # non-indexed, no NORMAL: flat
    colours = (corners - corners.min(0)) / np.ptp(corners, axis=0)  # RGB from position
    b.json["meshes"].append({"primitives": [b.primitive(corners, None, None, None, 0,
                                                        COLOR_0=(np.c_[colours, np.ones(len(colours))], "VEC4"))]})
    p, n, f = _sphere(3, 0.75)
    b.json["meshes"].append({"primitives": [b.primitive(p, n, None, f, 1)]})
    qp, qn, quv, qf = _quad(1.4)
    b.json["meshes"].append({"primitives": [b.primitive(qp, qn, quv, qf, 2, TEXCOORD_1=(quv * 0.5 + 0.25, "VEC2"))]})
    b.json["meshes"].append({"primitives": [b.primitive(qp, qn, quv, qf, 3)]})
    nodes = b.json["nodes"]
    nodes.append({"mesh": 0, "translation": [-2.4, 0, 0], "rotation": _quaternion([1, 1, 0], 0.6)})
    nodes.append({"mesh": 1, "translation": [-0.8, 0, 0]})
    nodes.append({"mesh": 2, "translation": [0.8, 0, 0]})
    nodes.append({"mesh": 3, "translation": [2.4, 0, 0], "rotation": _quaternion([0, 1, 0], math.pi * 0.8)})
    b.json["extensionsUsed"].append("KHR_lights_punctual")
    b.json["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0},
                                                               {"type": "spot", "intensity": 20.0, "range": 9.0,
                                                                "spot": {}}]}}  # the cone's defaults
    nodes.append({"rotation": _look_rotation([0.2, -0.4, -1.0]), "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"translation": [0.8, 1.5, 2.5], "rotation": _look_rotation([0.0, -1.5, -2.5]),
                  "extensions": {"KHR_lights_punctual": {"light": 1}}})
    b.json["cameras"] = [{"type": "orthographic", "orthographic": {"xmag": 3.4, "ymag": 1.7, "znear": 0.1,
                                                                   "zfar": 20}},
                         {"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}]
    nodes.append({"camera": 0, "translation": [0, 0.5, 6], "rotation": _quaternion([1, 0, 0], -0.08)})
    nodes.append({"camera": 1, "translation": [0, 1.5, 6], "rotation": _look_rotation([0, -1.5, -6])})
    b.json["scenes"] = [{"nodes": list(range(len(nodes)))}]
    b.json["scene"] = 0
    b.write_gltf(HERE / "features.gltf", external_bin=False)


def clearcoat():
    b = Builder()
    mask = b.texture(b.image(np.repeat(np.round(disc_alpha() * 255).astype(np.uint8)[..., None], 3, axis=2), embed=True))
    rough = b.texture(b.image(metallic_roughness(), embed=True))
    normal = b.texture(b.image(bumps(), embed=True))
    red = {"baseColorFactor": _rgba8(0.6, 0.08, 0.05, 1), "metallicFactor": 0.0, "roughnessFactor": 0.5}
    b.json["materials"] = [
        {"name": "uncoated", "pbrMetallicRoughness": red},
        {"name": "smooth_coat", "pbrMetallicRoughness": red,
         "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.05}}},
        {"name": "masked_rough_coat", "pbrMetallicRoughness": red,
         "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.9, "clearcoatTexture": {"index": mask},
                                                    "clearcoatRoughnessFactor": 0.7,
                                                    "clearcoatRoughnessTexture": {"index": rough}}}},
        {"name": "bumpy_coat", "pbrMetallicRoughness": red,
         "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.1,
                                                    "clearcoatNormalTexture": {"index": normal, "scale": 0.8}}}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_clearcoat"]
    p, n, uv, f = _quad(1.5)
    for material in range(4):  # TANGENT: the layer needs a tangent space (the glTF validator's rule)
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material, TANGENT=(_QUAD_TANGENTS, "VEC4"))]})
    _lit_quads_scene(b, [(m, (-2.4 + 1.6 * m, 0, 0)) for m in range(4)], yfov=0.45, aspect=4.0, distance=6.5)
    b.write_gltf(HERE / "clearcoat.gltf", external_bin=False)


def sheen():
    b = Builder()
    colour = b.texture(b.image(checker(((0.9, 0.8, 0.7), (0.3, 0.5, 0.9))), embed=True))
    alpha = np.round(disc_alpha() * 255).astype(np.uint8)[..., None]
    rough = b.texture(b.image(np.concatenate([np.repeat(alpha, 3, axis=2), alpha], axis=2), embed=True))
    base = {"baseColorFactor": _rgba8(0.15, 0.05, 0.2, 1), "metallicFactor": 0.0, "roughnessFactor": 0.8}
    b.json["materials"] = [
        {"name": "no_sheen", "pbrMetallicRoughness": base},
        {"name": "white_sheen", "pbrMetallicRoughness": base,
         "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [1.0, 1.0, 1.0], "sheenRoughnessFactor": 0.3}}},
        {"name": "mapped_sheen", "pbrMetallicRoughness": base,
         "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.7, 1.0],
                                                "sheenColorTexture": {"index": colour},
                                                "sheenRoughnessFactor": 0.8,
                                                "sheenRoughnessTexture": {"index": rough}}}},
        {"name": "coated_sheen", "pbrMetallicRoughness": base,
         "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.6, 0.9, 0.6], "sheenRoughnessFactor": 0.5},
                        "KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.1}}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_clearcoat", "KHR_materials_sheen"]
    p, n, uv, f = _quad(1.5)
    for material in range(4):
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material)]})
    _lit_quads_scene(b, [(m, (-2.4 + 1.6 * m, 0, 0)) for m in range(4)], yfov=0.45, aspect=4.0, distance=6.5)
    b.write_gltf(HERE / "sheen.gltf", external_bin=False)


def swirl() -> np.ndarray:
    """KHR_materials_anisotropy's texture: RG = the direction (x 2 - 1) in tangent space (+X
    right, +Y up the image), along circles around the centre; B = the strength's factor, 0.25
    at the centre rising to 1 at the rim."""
    u, v = _grid()
    x, y = u - 0.5, 0.5 - v  # y up the image
    r = np.hypot(x, y)
    d = np.stack([-y, x], axis=-1) / np.maximum(r, 1e-6)[..., None]
    d = np.where((r > 1e-6)[..., None], d, [1.0, 0.0])
    strength = 0.25 + 0.75 * np.clip(r / 0.5, 0.0, 1.0)
    rgb = np.concatenate([d * 0.5 + 0.5, strength[..., None]], axis=-1)
    return np.round(rgb * 255).astype(np.uint8)


def anisotropy():
    b = Builder()
    swirl_map = b.texture(b.image(swirl(), embed=True))
    base = {"baseColorFactor": _rgba8(0.95, 0.93, 0.88, 1), "metallicFactor": 1.0, "roughnessFactor": 0.35}
    b.json["materials"] = [
        {"name": "isotropic", "pbrMetallicRoughness": base},
        {"name": "along_tangent", "pbrMetallicRoughness": base,
         "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.8}}},
        {"name": "quarter_turn", "pbrMetallicRoughness": base,
         "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.8, "anisotropyRotation": math.pi / 2}}},
        {"name": "swirl", "pbrMetallicRoughness": base,
         "extensions": {"KHR_materials_anisotropy": {
             "anisotropyStrength": 1.0, "anisotropyRotation": 0.3,
             "anisotropyTexture": {"index": swirl_map, "texCoord": 0, "extensions": {
                 "KHR_texture_transform": {"offset": [0.1, -0.05], "rotation": 0.2, "scale": [1.1, 1.1]}}}}}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_anisotropy", "KHR_texture_transform"]
    p, n, uv, f = _quad(1.5)
    for material in range(4):  # TANGENT: the layer needs a tangent space (the glTF validator's rule)
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material, TANGENT=(_QUAD_TANGENTS, "VEC4"))]})
    _lit_quads_scene(b, [(m, (-2.4 + 1.6 * m, 0, 0)) for m in range(4)], yfov=0.45, aspect=4.0, distance=6.5)
    b.write_gltf(HERE / "anisotropy.gltf", external_bin=False)


def film_thickness() -> np.ndarray:
    """KHR_materials_iridescence's thickness texture: G rising left to right (0 -> 1); R a
    mask, 1 except a vertical band in the middle at 0.3 (the iridescence texture's channel)."""
    u, v = _grid()
    out = np.zeros((TEX, TEX, 3), np.uint8)
    out[..., 0] = np.round(np.where(np.abs(u - 0.5) < 0.1, 0.3, 1.0) * 255).astype(np.uint8)
    out[..., 1] = np.round(u * 255).astype(np.uint8)
    return out


def iridescence():
    b = Builder()
    film_map = b.texture(b.image(film_thickness(), embed=True))
    dark = {"baseColorFactor": _rgba8(0.04, 0.04, 0.05, 1), "metallicFactor": 0.0, "roughnessFactor": 0.3}
    metal = {"baseColorFactor": _rgba8(0.9, 0.9, 0.92, 1), "metallicFactor": 1.0, "roughnessFactor": 0.4}
    b.json["materials"] = [
        {"name": "no_film", "pbrMetallicRoughness": dark},
        {"name": "default_film", "pbrMetallicRoughness": dark,
         "extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 1.0}}},
        {"name": "mapped_film", "pbrMetallicRoughness": dark,
         "extensions": {"KHR_materials_iridescence": {
             "iridescenceFactor": 1.0, "iridescenceTexture": {"index": film_map},
             "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 100.0, "iridescenceThicknessMaximum": 800.0,
             "iridescenceThicknessTexture": {"index": film_map}}}},
        {"name": "coated_brushed_film", "pbrMetallicRoughness": metal,
         "extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 0.8, "iridescenceThicknessMaximum": 550.0},
                        "KHR_materials_anisotropy": {"anisotropyStrength": 0.6},
                        "KHR_materials_clearcoat": {"clearcoatFactor": 1.0, "clearcoatRoughnessFactor": 0.05}}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_anisotropy", "KHR_materials_clearcoat", "KHR_materials_iridescence"]
    p, n, uv, f = _quad(1.5)
    for material in range(4):
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material)]})
    _lit_quads_scene(b, [(m, (-2.4 + 1.6 * m, 0, 0)) for m in range(4)], yfov=0.45, aspect=4.0, distance=6.5)
    b.write_gltf(HERE / "iridescence.gltf", external_bin=False)


def stripes() -> np.ndarray:
    """KHR_materials_transmission's texture: R in horizontal stripes 1 / 0.25 (eight of them);
    G 0.75 (the thickness texture's channel)."""
    u, v = _grid()
    out = np.zeros((TEX, TEX, 3), np.uint8)
    out[..., 0] = np.round(np.where(np.floor(v * 8) % 2 == 0, 1.0, 0.25) * 255).astype(np.uint8)
    out[..., 1] = round(0.75 * 255)
    return out


def _uv_sphere_coordinates(normals) -> np.ndarray:
    """Equirectangular UVs of a sphere's normals (u around +Y, v down from the top)."""
    u = 0.5 + np.arctan2(normals[:, 0], normals[:, 2]) / (2 * math.pi)
    v = np.arccos(np.clip(normals[:, 1], -1.0, 1.0)) / math.pi
    return np.stack([u, v], axis=-1)


def transmission():
    b = Builder()
    stripe_map = b.texture(b.image(stripes(), embed=True))
    white = {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.1}
    b.json["materials"] = [
        {"name": "opaque", "pbrMetallicRoughness": white},
        {"name": "thin", "pbrMetallicRoughness": white,
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}},
        {"name": "rough_striped", "pbrMetallicRoughness": {**white, "roughnessFactor": 0.45},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 0.9,
                                                       "transmissionTexture": {"index": stripe_map}}}},
        {"name": "tinted_volume", "pbrMetallicRoughness": white,
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                        "KHR_materials_ior": {"ior": 1.33},
                        "KHR_materials_volume": {"thicknessFactor": 0.4, "thicknessTexture": {"index": stripe_map},
                                                 "attenuationColor": [0.9, 0.5, 0.2], "attenuationDistance": 0.25}}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_volume"]
    p, n, f = _sphere(subdivisions=3, radius=0.6)
    uv = _uv_sphere_coordinates(n)
    for material in range(4):
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material)]})
    _lit_quads_scene(b, [(m, (-2.4 + 1.6 * m, 0, 0)) for m in range(4)], yfov=0.45, aspect=4.0, distance=6.5)
    b.json["nodes"][3]["scale"] = [0.8, 0.8, 0.8]  # the volume: thickness x 0.8 in the world
    b.write_gltf(HERE / "transmission.gltf", external_bin=False)


def specular_layers():
    b = Builder()
    dark = {"baseColorFactor": [0.05, 0.06, 0.08, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.3}
    specular = {"KHR_materials_specular": {"specularFactor": 0.4, "specularColorFactor": [1.0, 0.8, 0.6]}}
    b.json["materials"] = [
        {"name": "specular", "pbrMetallicRoughness": dark, "extensions": specular},
        {"name": "specular_anisotropic", "pbrMetallicRoughness": dark,
         "extensions": {**specular, "KHR_materials_anisotropy": {"anisotropyStrength": 0.8}}},
        {"name": "specular_film", "pbrMetallicRoughness": dark,
         "extensions": {**specular, "KHR_materials_iridescence": {"iridescenceFactor": 1.0}}},
        {"name": "specular_thin_wall", "pbrMetallicRoughness": dark,
         "extensions": {**specular, "KHR_materials_transmission": {"transmissionFactor": 1.0}}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_specular",
                                "KHR_materials_transmission"]
    p, n, f = _sphere(subdivisions=3, radius=0.6)
    uv = _uv_sphere_coordinates(n)
    tangents = _uv_sphere_tangents(n)  # the anisotropy's tangent space (the glTF validator's rule)
    for material in range(4):
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material, TANGENT=(tangents, "VEC4"))]})
    _lit_quads_scene(b, [(m, (-2.4 + 1.6 * m, 0, 0)) for m in range(4)], yfov=0.45, aspect=4.0, distance=6.5)
    b.write_gltf(HERE / "specular_layers.gltf", external_bin=False)


def _uv_sphere_tangents(normals) -> np.ndarray:
    """_uv_sphere_coordinates' tangent frame: u = 0.5 + atan2(x, z) / 2 pi grows along
    (z, 0, -x) / |(x, z)| (+X at the front, any direction of the plane at the poles: +X), and
    cross(n, t) points up, to decreasing v (glTF's v down): w = 1, as _QUAD_TANGENTS."""
    t = np.stack([normals[:, 2], np.zeros(len(normals)), -normals[:, 0]], axis=-1)
    length = np.linalg.norm(t, axis=-1, keepdims=True)
    t = np.where(length > 1e-6, t / np.maximum(length, 1e-12), np.array([1.0, 0.0, 0.0]))
    return np.concatenate([t, np.ones((len(normals), 1))], axis=-1)


SLAB_BACKDROP_EMISSION = [0.9, 0.4, 0.15]
SLAB_VOLUME = {"thicknessFactor": 0.3, "attenuationColor": [0.4, 0.7, 0.9], "attenuationDistance": 0.5}


def transmission_slab():
    b = Builder()
    glass = {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.0}
    b.json["materials"] = [
        {"name": "backdrop", "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0],
                                                      "metallicFactor": 0.0, "roughnessFactor": 1.0},
         "emissiveFactor": SLAB_BACKDROP_EMISSION},
        {"name": "thin_ior_1", "pbrMetallicRoughness": glass,
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}, "KHR_materials_ior": {"ior": 1.0}}},
        {"name": "thin_ior_1_5", "pbrMetallicRoughness": glass,
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}},
        {"name": "tinted_volume", "pbrMetallicRoughness": glass,
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                        "KHR_materials_volume": dict(SLAB_VOLUME)}},
    ]
    b.json["extensionsUsed"] = ["KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_volume"]
    p, n, uv, f = _quad(1.0)
    b.json["meshes"].append({"primitives": [b.primitive(p * [4.4, 1.2, 1.0], n, uv, f, 0)]})
    for material in (1, 2, 3):
        b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, material)]})
    nodes = b.json["nodes"]
    nodes.append({"name": "backdrop", "mesh": 0, "translation": [0.0, 0.35, -1.0]})
    for mesh, x in ((1, -1.5), (2, 0.0), (3, 1.5)):
        nodes.append({"name": b.json["materials"][mesh]["name"], "mesh": mesh, "translation": [x, 0.0, 0.0]})
    b.json["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.45, "aspectRatio": 2.0, "znear": 0.1}}]
    nodes.append({"camera": 0, "translation": [0.0, 0.0, 6.0]})
    b.json["scenes"] = [{"nodes": list(range(len(nodes)))}]
    b.json["scene"] = 0
    b.write_gltf(HERE / "transmission_slab.gltf", external_bin=False)


def metal_ramp() -> np.ndarray:
    """glTF metallicRoughness texture: B (metallic) rising left to right 0 -> 1, G (roughness) 1."""
    u, _ = _grid()
    out = np.zeros((TEX, TEX, 3), np.uint8)
    out[..., 1] = 255
    out[..., 2] = np.round(u * 255).astype(np.uint8)
    return out


def specular_colour() -> np.ndarray:
    """KHR_materials_specular's colour texture (sRGB codes): R rising left to right, G down,
    B falling left to right: smooth ramps, no texel edges to tell mip chains apart."""
    u, v = _grid()
    return np.round(np.stack([u, v, 1.0 - u], -1) * 255).astype(np.uint8)


def specular_strength() -> np.ndarray:
    """KHR_materials_specular's strength texture: A rising from 0.2 (top) to 1 (bottom), RGB white."""
    _, v = _grid()
    out = np.full((TEX, TEX, 4), 255, np.uint8)
    out[..., 3] = np.round((0.2 + 0.8 * v) * 255).astype(np.uint8)
    return out


def specular_metal():
    b = Builder()
    ramp = b.texture(b.image(metal_ramp(), embed=True))
    colour = b.texture(b.image(specular_colour(), embed=True))
    strength = b.texture(b.image(specular_strength(), embed=True))
    rows = {"dielectric": {"metallicFactor": 0.0}, "half_metal": {"metallicFactor": 0.5},
            "metal_ramp": {"metallicFactor": 1.0, "metallicRoughnessTexture": {"index": ramp}}}
    columns = {"plain": {},
               "ior": {"KHR_materials_ior": {"ior": 1.8}},
               "specular": {"KHR_materials_specular": {"specularFactor": 0.6,
                                                       "specularColorFactor": [2.5, 1.0, 0.25]}},
               "specular_maps": {"KHR_materials_specular": {"specularColorFactor": [5.0, 5.0, 5.0],
                                                            "specularColorTexture": {"index": colour},
                                                            "specularTexture": {"index": strength}}}}
    p, n, uv, f = _quad(1.3)
    quads = []
    for i, (row, pbr) in enumerate(rows.items()):
        for j, (column, extensions) in enumerate(columns.items()):
            material = {"name": f"{row}_{column}", "pbrMetallicRoughness": {
                "baseColorFactor": _rgba8(0.9, 0.5, 0.15, 1), "roughnessFactor": 0.35, **pbr}}
            if extensions:
                material["extensions"] = extensions
            b.json["materials"].append(material)
            b.json["meshes"].append({"primitives": [b.primitive(p, n, uv, f, len(b.json["materials"]) - 1)]})
            quads.append((len(b.json["meshes"]) - 1, (-2.25 + 1.5 * j, 1.5 - 1.5 * i, 0.0)))
    b.json["extensionsUsed"] = ["KHR_materials_ior", "KHR_materials_specular"]
    _lit_quads_scene(b, quads, yfov=0.72, aspect=2.0, distance=6.5)
    b.write_gltf(HERE / "specular_metal.gltf", external_bin=False)


def main():
    hierarchy_lights()
    textured()
    texture_transform()
    alpha_modes()
    features()
    clearcoat()
    sheen()
    anisotropy()
    iridescence()
    transmission()
    transmission_slab()
    specular_metal()
    specular_layers()


if __name__ == "__main__":
    main()
