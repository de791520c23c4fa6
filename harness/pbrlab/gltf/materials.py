"""glTF 2.0's metallic-roughness material mapped into pbrlab's surface API: the one
mapping (README, "glTF 2.0 files"). The default surface (templates/default_surface.inc)
reads what this module writes into a scene Material:

    glTF                                     pbrlab Material / default surface
    baseColorFactor.rgb x baseColorTexture   albedo x albedo map (sRGB, decoded on sampling)
      x COLOR_0                                x IN.color (PBRLAB_VERTEX_COLOR)
    baseColorFactor.a x texture.a x COLOR_0.a  alpha (MASK: cutout at alphaCutoff; BLEND: fade)
    metallicFactor x metallicRoughness.B     metallic x metallic_roughness map .b
    roughnessFactor x metallicRoughness.G    smoothness = 1 - perceptual roughness
                                             (u_smoothness = 1 - roughnessFactor)
    normalTexture, scale                     normal map (tangent space), xy x normal_scale
    occlusionTexture.R, strength             occlusion = 1 + strength (R - 1): indirect light only
    emissiveFactor x emissiveTexture         emission x emission map (sRGB)
      x KHR_materials_emissive_strength
    doubleSided                              no culling; back faces lit with the normal reversed
    KHR_materials_ior, KHR_materials_specular
      (dielectric: metallicFactor 0)         the specular workflow, F0 = ((ior - 1) / (ior + 1))^2
                                             x specularColorFactor x specularFactor (max 1)
    textureInfo.texCoord, KHR_texture_transform, samplers   per-slot UV set, UV transform, sampler

Everything else a material carries is named in one warning each.
"""

from __future__ import annotations

import io
import json
import math

import numpy as np

from ..scene import Material
from .document import Document

# glTF sampler enums (spec 3.8.4 "Samplers") -> moderngl: repeat flags and filters.
REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT = 10497, 33071, 33648
MAG_FILTERS = {9728, 9729}                                # NEAREST, LINEAR
MIN_FILTERS = {9728, 9729, 9984, 9985, 9986, 9987}        # ... and the four mipmap modes
DEFAULT_MIN_FILTER, DEFAULT_MAG_FILTER = 9987, 9729       # LINEAR_MIPMAP_LINEAR, LINEAR: pbrlab's default
DEFAULT_IOR = 1.5                                         # KHR_materials_ior: glTF's dielectric (F0 = 0.04)

HONOURED_MATERIAL_EXTENSIONS = ("KHR_materials_emissive_strength", "KHR_materials_ior",
                                "KHR_materials_specular")
HONOURED_TEXTURE_EXTENSIONS = ("KHR_texture_transform",)
# (glTF key, pbrlab slot, decode sRGB)
TEXTURE_KEYS = (("baseColorTexture", "albedo", True), ("metallicRoughnessTexture", "metallic_roughness", False),
                ("normalTexture", "normal", False), ("occlusionTexture", "occlusion", False),
                ("emissiveTexture", "emission", True))
# glTF's UVs have v down the image (origin top left, spec 3.8.4.1); pbrlab's texture upload
# puts the image's last row at v = 0 (OpenGL). v_gl = 1 - v_glTF: this matrix, its own inverse.
FLIP_V = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 1.0], [0.0, 0.0, 1.0]])


class GltfImage:
    """A glTF image decoded to a top-row-first uint8 array (what resource_cache uploads),
    optionally doubled with its mirror image along x and/or y for MIRRORED_REPEAT (a
    repeating texture of twice the size, sampled at half the UVs, is mirrored repeat)."""

    def __init__(self, key: tuple, pixels: np.ndarray, mirror: tuple[bool, bool] = (False, False)):
        self.key = (*key, mirror)
        image = pixels
        if mirror[0]:
            image = np.concatenate([image, image[:, ::-1]], axis=1)
        if mirror[1]:  # rows top first: GL's v = 0 is the last row, so the mirror goes on top
            image = np.concatenate([image[::-1], image], axis=0)
        self._pixels = image

    def pixels(self) -> np.ndarray:
        return self._pixels


class MaterialReader:
    """Turns glTF materials into pbrlab Materials, decoding each image once."""

    def __init__(self, doc: Document, file_key: tuple, warn):
        self.doc, self.file_key, self.warn = doc, file_key, warn
        self._images: dict[int, np.ndarray] = {}

    # --- numbers ----------------------------------------------------------------------
    def _number(self, spec, key, where, default, lo=0.0, hi=math.inf):
        value = spec.get(key, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not lo <= value <= hi:
            self.doc.fail(where, f"{key} must be a number in [{lo:g}, {hi:g}], got {json.dumps(value)}")
        return float(value)

    def _vector(self, spec, key, where, default, n, lo=0.0, hi=1.0):
        value = spec.get(key, default)
        if (not isinstance(value, list) or len(value) != n
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)
                or not all(lo <= v <= hi for v in value)):
            self.doc.fail(where, f"{key} must be {n} numbers in [{lo:g}, {hi:g}], got {json.dumps(value)}")
        return np.array(value, np.float64)

    # --- images and textures ----------------------------------------------------------
    def image(self, index: int, where: str) -> np.ndarray:
        if index not in self._images:
            spec = self.doc.get("images", index, where)
            image_where = f"images[{index}]"
            if "uri" in spec:
                data = self.doc.uri_bytes(spec["uri"], image_where)
            elif "bufferView" in spec:
                view = self.doc.get("bufferViews", spec["bufferView"], image_where)
                buffer = self.doc.buffer(view.get("buffer"), f"bufferViews[{spec['bufferView']}]")
                start = view.get("byteOffset", 0)
                data = buffer[start:start + view.get("byteLength", 0)]
            else:
                self.doc.fail(image_where, "has neither uri nor bufferView")
            self._images[index] = _decode_image(self.doc, data, image_where)
        return self._images[index]

    def texture(self, info, where: str, material: Material, slot: str, srgb: bool, name: str):
        """Fill ``material``'s ``slot`` from a glTF textureInfo."""
        if not isinstance(info, dict):
            self.doc.fail(where, f"expected a textureInfo object, got {json.dumps(info)[:40]}")
        texture_index = info.get("index")
        texture = self.doc.get("textures", texture_index, f"{where}.index")
        texture_where = f"textures[{texture_index}]"
        for ext in texture.get("extensions", {}):
            self.warn(f"{ext} ignored in texture {texture_index} (material \"{name}\")")
        if "source" not in texture:
            self.doc.fail(texture_where, "has no source image")
        pixels = self.image(texture.get("source"), f"{texture_where}.source")
        sampler = {}
        if "sampler" in texture:
            sampler = self.doc.get("samplers", texture["sampler"], f"{texture_where}.sampler")
        wrap = []
        for key in ("wrapS", "wrapT"):
            mode = sampler.get(key, REPEAT)
            if mode not in (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT):
                self.doc.fail(f"samplers[{texture.get('sampler')}]", f"{key} {json.dumps(mode)} is not a glTF wrap mode")
            wrap.append(mode)
        min_filter = sampler.get("minFilter", DEFAULT_MIN_FILTER)
        mag_filter = sampler.get("magFilter", DEFAULT_MAG_FILTER)
        if min_filter not in MIN_FILTERS or mag_filter not in MAG_FILTERS:
            self.doc.fail(f"samplers[{texture.get('sampler')}]",
                          f"filters {min_filter}/{mag_filter} are not glTF filter modes")
        mirror = (wrap[0] == MIRRORED_REPEAT, wrap[1] == MIRRORED_REPEAT)
        key = (*self.file_key, texture.get("source"))
        material.textures[slot] = GltfImage(key, pixels, mirror)
        material.texture_srgb[slot] = srgb
        material.texture_sampler[slot] = (wrap[0] != CLAMP_TO_EDGE, wrap[1] != CLAMP_TO_EDGE,
                                          min_filter, mag_filter)
        uv_set = info.get("texCoord", 0)
        transform = None
        for ext, spec in info.get("extensions", {}).items():
            if ext == "KHR_texture_transform":
                transform = self._uv_transform(spec, f"{where}.extensions.KHR_texture_transform")
                uv_set = spec.get("texCoord", uv_set)
            else:
                self.warn(f"{ext} ignored in {slot} texture of material \"{name}\"")
        if uv_set not in (0, 1):
            self.warn(f"TEXCOORD_{uv_set} ignored in material \"{name}\" ({slot} texture reads TEXCOORD_0)")
            uv_set = 0
        material.texture_uv_set[slot] = uv_set
        # glTF-space transform -> GL-space (v flipped), then halve for mirrored repeat
        gl = np.eye(3) if transform is None else FLIP_V @ transform @ FLIP_V
        if any(mirror):
            gl = np.diag([0.5 if mirror[0] else 1.0, 0.5 if mirror[1] else 1.0, 1.0]) @ gl
        if transform is not None or any(mirror):
            material.texture_transform[slot] = gl[:2]

    def _uv_transform(self, spec, where) -> np.ndarray:
        """KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv (the extension's
        README, "Overview"), rotation counter-clockwise in UV space (v down)."""
        offset = self._vector(spec, "offset", where, [0.0, 0.0], 2, -math.inf, math.inf)
        scale = self._vector(spec, "scale", where, [1.0, 1.0], 2, -math.inf, math.inf)
        rotation = self._number(spec, "rotation", where, 0.0, -math.inf, math.inf)
        c, s = math.cos(rotation), math.sin(rotation)
        translation = np.array([[1, 0, offset[0]], [0, 1, offset[1]], [0, 0, 1]], np.float64)
        rotate = np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]], np.float64)
        return translation @ rotate @ np.diag([scale[0], scale[1], 1.0])

    # --- the material -----------------------------------------------------------------
    def material(self, index: int | None, vertex_color: bool) -> Material:
        """Material ``index`` (None: glTF's default material, spec 3.9.6)."""
        spec = {} if index is None else self.doc.get("materials", index, "material")
        where = "default material" if index is None else f"materials[{index}]"
        name = spec.get("name") or ("default" if index is None else f"material_{index}")
        m = Material(name=name)
        pbr = spec.get("pbrMetallicRoughness", {})
        base = self._vector(pbr, "baseColorFactor", f"{where}.pbrMetallicRoughness", [1, 1, 1, 1], 4)
        m.albedo, m.alpha = base[:3], float(base[3])
        m.metallic = self._number(pbr, "metallicFactor", f"{where}.pbrMetallicRoughness", 1.0, 0.0, 1.0)
        m.smoothness = 1.0 - self._number(pbr, "roughnessFactor", f"{where}.pbrMetallicRoughness", 1.0, 0.0, 1.0)
        mode = spec.get("alphaMode", "OPAQUE")
        modes = {"OPAQUE": "opaque", "MASK": "cutout", "BLEND": "fade"}
        if mode not in modes:
            self.doc.fail(where, f"alphaMode must be OPAQUE, MASK or BLEND, got {json.dumps(mode)}")
        m.alpha_mode = modes[mode]
        m.alpha_cutoff = self._number(spec, "alphaCutoff", where, 0.5, 0.0, 1.0)
        m.double_sided = bool(spec.get("doubleSided", False))
        m.vertex_color = vertex_color
        for key, slot, srgb in TEXTURE_KEYS:
            holder, holder_where = (pbr, f"{where}.pbrMetallicRoughness") if key in pbr else (spec, where)
            if key in holder:
                self.texture(holder[key], f"{holder_where}.{key}", m, slot, srgb, name)
        if "normalTexture" in spec:
            m.normal_scale = self._number(spec["normalTexture"], "scale", f"{where}.normalTexture", 1.0,
                                          -math.inf, math.inf)
        if "occlusionTexture" in spec:
            m.occlusion_strength = self._number(spec["occlusionTexture"], "strength",
                                                f"{where}.occlusionTexture", 1.0, 0.0, 1.0)
        emissive = self._vector(spec, "emissiveFactor", where, [0, 0, 0], 3)
        extensions = spec.get("extensions", {})
        strength = 1.0
        if "KHR_materials_emissive_strength" in extensions:
            strength = self._number(extensions["KHR_materials_emissive_strength"], "emissiveStrength",
                                    f"{where}.extensions.KHR_materials_emissive_strength", 1.0)
        m.emission = emissive * strength
        self._specular(m, extensions, where, name, "metallicRoughnessTexture" in pbr)
        for ext in extensions:
            if ext not in HONOURED_MATERIAL_EXTENSIONS:
                self.warn(f"{ext} ignored in material \"{name}\"")
        return m

    def _specular(self, m: Material, extensions: dict, where: str, name: str, metallic_map: bool):
        """KHR_materials_ior / _specular on a dielectric: the specular workflow with F0 from
        the IOR (Fresnel at normal incidence) times the specular colour and factor."""
        ior_ext = extensions.get("KHR_materials_ior", {})
        spec_ext = extensions.get("KHR_materials_specular", {})
        if "KHR_materials_ior" not in extensions and "KHR_materials_specular" not in extensions:
            return
        ior = self._number(ior_ext, "ior", f"{where}.extensions.KHR_materials_ior", DEFAULT_IOR, 1.0)
        factor = self._number(spec_ext, "specularFactor", f"{where}.extensions.KHR_materials_specular", 1.0, 0.0, 1.0)
        colour = self._vector(spec_ext, "specularColorFactor", f"{where}.extensions.KHR_materials_specular",
                              [1, 1, 1], 3, 0.0, math.inf)
        for key in ("specularTexture", "specularColorTexture"):
            if key in spec_ext:
                self.warn(f"KHR_materials_specular.{key} ignored in material \"{name}\"")
        if m.metallic != 0.0:
            if m.metallic < 1.0 or metallic_map:
                self.warn(f"KHR_materials_ior/KHR_materials_specular ignored in material \"{name}\" "
                          "(metallic > 0: the specular workflow holds dielectrics only)")
            return  # a pure metal's F0 is its base colour: the IOR does not enter
        f0_ior = ((ior - 1.0) / (ior + 1.0)) ** 2  # Fresnel at normal incidence, air to ior
        m.workflow = "specular"
        m.specular = np.minimum(f0_ior * colour * factor, 1.0)


def _decode_image(doc: Document, data: bytes, where: str) -> np.ndarray:
    """PNG or JPEG bytes -> top-row-first uint8 (h, w, 3 or 4)."""
    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(io.BytesIO(data)) as image:
            if image.format not in ("PNG", "JPEG"):
                doc.fail(where, f"is {image.format}; glTF images are PNG or JPEG")
            # grey images as RGB(A): a channel is read as R, G or B by the slot (spec 3.8.3)
            image = image.convert("RGBA" if "A" in image.getbands() else "RGB")
            return np.asarray(image, np.uint8)
    except (UnidentifiedImageError, OSError, ValueError) as exc:
        doc.fail(where, f"is not a readable PNG or JPEG image ({exc})")
