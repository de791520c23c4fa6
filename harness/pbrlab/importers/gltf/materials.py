"""glTF 2.0's metallic-roughness material mapped into pbrlab's surface API: the one
mapping (docs/gltf.md, "glTF 2.0 files"). The default surface (templates/default_surface.inc)
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
    KHR_materials_clearcoat                  clearcoat = clearcoatFactor x texture.r, clearcoat_smoothness
                                             = 1 - clearcoatRoughnessFactor (x texture.g), the coat's
                                             normal map and scale (else the geometric normal)
    KHR_materials_unlit                      albedo and alpha, no light (PBRLAB_UNLIT)
    KHR_materials_pbrSpecularGlossiness      the specular workflow: diffuseFactor x diffuseTexture =
                                             albedo, specularFactor x texture.rgb = specular,
                                             glossinessFactor x texture.a = smoothness
    KHR_materials_sheen                      sheen_color = sheenColorFactor x sheenColorTexture.rgb (sRGB),
                                             sheen_smoothness = 1 - sheenRoughnessFactor (x texture.a)
    KHR_materials_anisotropy                 anisotropy_strength = anisotropyStrength (x texture.b),
                                             anisotropy_rotation = anisotropyRotation, the anisotropy map
                                             (RG: direction); MikkTSpace tangents where TANGENT is absent
    KHR_materials_iridescence                iridescence = iridescenceFactor (x texture.r), iridescence_ior,
                                             iridescence_thickness_min / _max (nm; texture.g between them)
    KHR_materials_transmission               transmission = transmissionFactor (x transmissionTexture.r)
    KHR_materials_volume                     thickness = thicknessFactor (x thicknessTexture.g) x the node's
                                             world scale (|det|^(1/3)), attenuation_color, attenuation_distance
                                             (absent: +inf); ior = KHR_materials_ior's (refraction)
    KHR_materials_ior, KHR_materials_specular
      (dielectric: metallicFactor 0)         the specular workflow, F0 = min(((ior - 1) / (ior + 1))^2
                                             x specularColorFactor x texture.rgb, 1) x specularFactor
                                             x texture.a; with KHR_materials_specular, specular_f90 =
                                             specularFactor (x texture.a): F90 as the extension sets it
      (partly metallic: 0 < metallicFactor   the metallic workflow with dielectric_specular = that F0
       < 1 or a metallicRoughness texture)   (and specular_f90): F0 = mix(it, base colour, metallic),
                                             F90 = mix(specular_f90, 1, metallic) per pixel
    textureInfo.texCoord, KHR_texture_transform, samplers   per-slot UV set, UV transform, sampler

Everything else a material carries is named in one warning each.
"""

from __future__ import annotations

import math

import numpy as np

from ...scene.model import IRIDESCENCE_IOR_RANGE, TRANSMISSION_IOR_RANGE, Material
from . import images
from .document import Document
from .fields import FieldReader, join
from .texture_source import texture_source

# glTF sampler enums (spec 3.8.4 "Samplers") -> moderngl: repeat flags and filters.
REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT = 10497, 33071, 33648
WRAP_MODES = (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT)
WRAP_NAMES = {REPEAT: "REPEAT", CLAMP_TO_EDGE: "CLAMP_TO_EDGE", MIRRORED_REPEAT: "MIRRORED_REPEAT"}
MAG_FILTERS = (9728, 9729)                                # NEAREST, LINEAR
MIN_FILTERS = (9728, 9729, 9984, 9985, 9986, 9987)        # ... and the four mipmap modes
FILTER_NAMES = {9728: "NEAREST", 9729: "LINEAR", 9984: "NEAREST_MIPMAP_NEAREST", 9985: "LINEAR_MIPMAP_NEAREST",
                9986: "NEAREST_MIPMAP_LINEAR", 9987: "LINEAR_MIPMAP_LINEAR"}
ALPHA_MODES = {"OPAQUE": "opaque", "MASK": "cutout", "BLEND": "fade"}  # glTF alphaMode -> Unity's modes
DEFAULT_MIN_FILTER, DEFAULT_MAG_FILTER = 9987, 9729       # LINEAR_MIPMAP_LINEAR, LINEAR: pbrlab's default
DEFAULT_IOR = 1.5                                         # KHR_materials_ior: glTF's dielectric (F0 = 0.04)

HONOURED_MATERIAL_EXTENSIONS = ("KHR_materials_clearcoat", "KHR_materials_emissive_strength", "KHR_materials_ior",
                                "KHR_materials_specular", "KHR_materials_unlit", "KHR_materials_pbrSpecularGlossiness",
                                "KHR_materials_sheen", "KHR_materials_anisotropy", "KHR_materials_iridescence",
                                "KHR_materials_transmission", "KHR_materials_volume")
# KHR_materials_iridescence's textures: (key, pbrlab slot); linear data (R mask, G thickness)
IRIDESCENCE_TEXTURES = (("iridescenceTexture", "iridescence"), ("iridescenceThicknessTexture", "iridescence_thickness"))
# KHR_materials_sheen's textures: (key, pbrlab slot, decode sRGB)
SHEEN_TEXTURES = (("sheenColorTexture", "sheen_color", True), ("sheenRoughnessTexture", "sheen_roughness", False))
# KHR_materials_clearcoat's textures: (key, pbrlab slot); all linear data
CLEARCOAT_TEXTURES = (("clearcoatTexture", "clearcoat"), ("clearcoatRoughnessTexture", "clearcoat_roughness"),
                      ("clearcoatNormalTexture", "clearcoat_normal"))
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
        self._extension_format: dict[int, str | None] = {}  # image -> the extension its bytes need

    # --- images and textures ----------------------------------------------------------
    def image(self, index: int) -> np.ndarray:
        """Image ``index`` (checked by the caller) decoded, once per file."""
        if index not in self._images:
            spec = self.doc.items("images")[index]
            images.check_mime_type(spec)
            if spec.has("uri"):
                data = self.doc.uri_bytes(spec.string("uri"), spec.path)
            elif spec.has("bufferView"):
                _, data = self.doc.buffer_view(spec.index("bufferView", "bufferViews"), join(spec.path, "bufferView"))
            else:
                spec.fail("has neither uri nor bufferView")
            self._images[index] = images.decode_image(self.doc, data, spec)
            self._extension_format[index] = images.extension_of_bytes(data)
        return self._images[index]

    def texture(self, info: FieldReader, material: Material, slot: str, srgb: bool, name: str):
        """Fill ``material``'s ``slot`` from a glTF textureInfo."""
        texture_index = info.index("index", "textures", required=True)
        texture = self.doc.items("textures")[texture_index]
        source = texture_source(texture, texture_index,
                                lambda message: self.warn(f"{message} (material \"{name}\")"))
        pixels = self.image(source)
        needed = self._extension_format[source]
        if needed and needed not in dict(texture.extensions()):
            self.warn(f"texture {texture_index}'s core source images[{source}] is {images.FORMAT_NAMES[needed]}, "
                      f"not valid glTF without {needed} on the texture (core images are PNG or JPEG); drawn as "
                      f"{images.FORMAT_NAMES[needed]}, which viewers that follow the extension's rule, as three.js "
                      f"r187, do not (material \"{name}\")")
        sampler_index = texture.index("sampler", "samplers")
        sampler = (FieldReader({}, "default sampler", self.doc) if sampler_index is None
                   else self.doc.items("samplers")[sampler_index])
        wrap = [sampler.enum(key, WRAP_MODES, REPEAT, WRAP_NAMES) for key in ("wrapS", "wrapT")]
        min_filter = sampler.enum("minFilter", MIN_FILTERS, DEFAULT_MIN_FILTER, FILTER_NAMES)
        mag_filter = sampler.enum("magFilter", MAG_FILTERS, DEFAULT_MAG_FILTER, FILTER_NAMES)
        mirror = (wrap[0] == MIRRORED_REPEAT, wrap[1] == MIRRORED_REPEAT)
        key = (*self.file_key, source)
        material.textures[slot] = GltfImage(key, pixels, mirror)
        material.texture_srgb[slot] = srgb
        material.texture_sampler[slot] = (wrap[0] != CLAMP_TO_EDGE, wrap[1] != CLAMP_TO_EDGE,
                                          min_filter, mag_filter)
        uv_set = info.integer("texCoord", 0)
        transform = None
        for ext, spec in info.extensions():
            if ext == "KHR_texture_transform":
                transform = self._uv_transform(spec, spec.path)
                uv_set = spec.integer("texCoord", uv_set)
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
        if not isinstance(spec, FieldReader):
            spec = FieldReader(spec, where, self.doc)
        offset = spec.numbers("offset", 2, [0.0, 0.0])
        scale = spec.numbers("scale", 2, [1.0, 1.0])
        rotation = spec.number("rotation", 0.0)
        c, s = math.cos(rotation), math.sin(rotation)
        translation = np.array([[1, 0, offset[0]], [0, 1, offset[1]], [0, 0, 1]], np.float64)
        rotate = np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]], np.float64)
        return translation @ rotate @ np.diag([scale[0], scale[1], 1.0])

    # --- the material -----------------------------------------------------------------
    def material(self, index: int | None, vertex_color: bool) -> Material:
        """Material ``index`` (checked by the caller; None: glTF's default material, spec 3.9.6)."""
        spec = FieldReader({}, "default material", self.doc) if index is None else self.doc.items("materials")[index]
        name = spec.string("name", "") or ("default" if index is None else f"material_{index}")
        m = Material(name=name)
        pbr = spec.object("pbrMetallicRoughness")
        base = pbr.numbers("baseColorFactor", 4, [1, 1, 1, 1], 0.0, 1.0)
        m.albedo, m.alpha = base[:3], float(base[3])
        m.metallic = pbr.number("metallicFactor", 1.0, 0.0, 1.0)
        m.smoothness = 1.0 - pbr.number("roughnessFactor", 1.0, 0.0, 1.0)
        m.alpha_mode = ALPHA_MODES[spec.enum("alphaMode", tuple(ALPHA_MODES), "OPAQUE")]
        m.alpha_cutoff = spec.number("alphaCutoff", 0.5, 0.0, 1.0)
        m.double_sided = spec.boolean("doubleSided", False)
        m.vertex_color = vertex_color
        for key, slot, srgb in TEXTURE_KEYS:
            holder = pbr if pbr.has(key) else spec
            if holder.has(key):
                self.texture(holder.object(key), m, slot, srgb, name)
        if spec.has("normalTexture"):
            m.normal_scale = spec.object("normalTexture").number("scale", 1.0)
        if spec.has("occlusionTexture"):
            m.occlusion_strength = spec.object("occlusionTexture").number("strength", 1.0, 0.0, 1.0)
        emissive = spec.numbers("emissiveFactor", 3, [0, 0, 0], 0.0, 1.0)
        extensions = dict(spec.extensions())
        strength = 1.0
        if "KHR_materials_emissive_strength" in extensions:
            strength = extensions["KHR_materials_emissive_strength"].number("emissiveStrength", 1.0, 0.0)
        m.emission = emissive * strength
        if "KHR_materials_pbrSpecularGlossiness" in extensions:
            self._specular_glossiness(m, extensions["KHR_materials_pbrSpecularGlossiness"], name)
        else:
            self._specular(m, extensions, spec.path, name, pbr.has("metallicRoughnessTexture"))
        m.unlit = "KHR_materials_unlit" in extensions  # its object is empty (the README: "no properties")
        if "KHR_materials_clearcoat" in extensions:
            self._clearcoat(m, extensions["KHR_materials_clearcoat"], name)
        if "KHR_materials_sheen" in extensions:
            self._sheen(m, extensions["KHR_materials_sheen"], name)
        if "KHR_materials_anisotropy" in extensions:
            self._anisotropy(m, extensions["KHR_materials_anisotropy"], name)
        if "KHR_materials_iridescence" in extensions:
            self._iridescence(m, extensions["KHR_materials_iridescence"], name)
        if "KHR_materials_transmission" in extensions:
            self._transmission(m, extensions, name)
        elif "KHR_materials_volume" in extensions:
            self.warn(f"KHR_materials_volume ignored in material \"{name}\" (without KHR_materials_transmission "
                      "there is no light through the surface to attenuate)")
        for ext in extensions:
            if ext not in HONOURED_MATERIAL_EXTENSIONS:
                self.warn(f"{ext} ignored in material \"{name}\"")
        return m

    def _specular_glossiness(self, m: Material, sg: FieldReader, name: str):
        """KHR_materials_pbrSpecularGlossiness (archived; the extension's README): the
        specular workflow, its diffuse taken as Unity's albedo (the README's
        c_diff = diffuse (1 - max(specular)) is Unity's energy conservation)."""
        diffuse = sg.numbers("diffuseFactor", 4, [1, 1, 1, 1], 0.0, 1.0)
        m.workflow = "specular"
        m.albedo, m.alpha = diffuse[:3], float(diffuse[3])
        m.metallic = 0.0
        m.specular = sg.numbers("specularFactor", 3, [1, 1, 1], 0.0, 1.0)
        m.smoothness = sg.number("glossinessFactor", 1.0, 0.0, 1.0)
        for slot in ("albedo", "metallic_roughness"):  # the core model's maps do not apply
            for table in (m.textures, m.texture_srgb, m.texture_sampler, m.texture_uv_set, m.texture_transform):
                table.pop(slot, None)
        if sg.has("diffuseTexture"):
            self.texture(sg.object("diffuseTexture"), m, "albedo", True, name)
        if sg.has("specularGlossinessTexture"):
            self.texture(sg.object("specularGlossinessTexture"), m, "specular_glossiness", True, name)

    def _clearcoat(self, m: Material, coat: FieldReader, name: str):
        """KHR_materials_clearcoat (the extension's README, "Properties")."""
        m.clearcoat = coat.number("clearcoatFactor", 0.0, 0.0, 1.0)
        m.clearcoat_smoothness = 1.0 - coat.number("clearcoatRoughnessFactor", 0.0, 0.0, 1.0)
        for key, slot in CLEARCOAT_TEXTURES:
            if coat.has(key):
                self.texture(coat.object(key), m, slot, False, name)
        if coat.has("clearcoatNormalTexture"):
            m.clearcoat_normal_scale = coat.object("clearcoatNormalTexture").number("scale", 1.0)

    def _sheen(self, m: Material, sheen: FieldReader, name: str):
        """KHR_materials_sheen (the extension's README, "Properties"): colour factor x texture
        RGB (sRGB), roughness factor x texture A."""
        m.sheen_color = tuple(float(c) for c in sheen.numbers("sheenColorFactor", 3, [0, 0, 0], 0.0, 1.0))
        m.sheen_smoothness = 1.0 - sheen.number("sheenRoughnessFactor", 0.0, 0.0, 1.0)
        for key, slot, srgb in SHEEN_TEXTURES:
            if sheen.has(key):
                self.texture(sheen.object(key), m, slot, srgb, name)

    def _anisotropy(self, m: Material, anisotropy: FieldReader, name: str):
        """KHR_materials_anisotropy (the extension's README, "Properties"): strength =
        anisotropyStrength x texture.b, direction = texture.rg x 2 - 1 rotated by
        anisotropyRotation (radians, counter-clockwise in tangent space). A strength of 0 is no
        anisotropy, mapped or not (0 x the texture), so its texture is not read then."""
        m.anisotropy_strength = anisotropy.number("anisotropyStrength", 0.0, 0.0, 1.0)
        m.anisotropy_rotation = anisotropy.number("anisotropyRotation", 0.0)
        if anisotropy.has("anisotropyTexture") and m.anisotropy_strength > 0.0:
            self.texture(anisotropy.object("anisotropyTexture"), m, "anisotropy", False, name)

    def _iridescence(self, m: Material, film: FieldReader, name: str):
        """KHR_materials_iridescence (the extension's README, "Properties"): mask =
        iridescenceFactor x iridescenceTexture.r, the film's IOR, thickness (nm) =
        mix(iridescenceThicknessMinimum, iridescenceThicknessMaximum, thickness texture.g), the
        maximum without that texture. Defaults 0, 1.3, 100, 400. A factor of 0 is no film, so
        its textures are not read then. The IOR's upper limit is pbr_F_Iridescence's domain."""
        m.iridescence = film.number("iridescenceFactor", 0.0, 0.0, 1.0)
        m.iridescence_ior = film.number("iridescenceIor", 1.3, *IRIDESCENCE_IOR_RANGE)
        m.iridescence_thickness_min = film.number("iridescenceThicknessMinimum", 100.0, 0.0)
        m.iridescence_thickness_max = film.number("iridescenceThicknessMaximum", 400.0, 0.0)
        if m.iridescence > 0.0:
            for key, slot in IRIDESCENCE_TEXTURES:
                if film.has(key):
                    self.texture(film.object(key), m, slot, False, name)

    def _transmission(self, m: Material, extensions: dict, name: str):
        """KHR_materials_transmission (the extension's README, "Properties"): transmission =
        transmissionFactor x transmissionTexture.r (default 0). KHR_materials_volume ("Properties"):
        thickness = thicknessFactor x thicknessTexture.g (default 0: thin-walled) in the mesh's
        space (the importer scales it by the node's world scale), attenuationColor (default 1),
        attenuationDistance (default +infinity); its refraction reads KHR_materials_ior's ior
        (default 1.5). A factor of 0 is no transmission, so its textures are not read then."""
        transmission = extensions["KHR_materials_transmission"]
        m.transmission = transmission.number("transmissionFactor", 0.0, 0.0, 1.0)
        if m.transmission > 0.0 and transmission.has("transmissionTexture"):
            self.texture(transmission.object("transmissionTexture"), m, "transmission", False, name)
        if "KHR_materials_ior" in extensions:
            m.ior = extensions["KHR_materials_ior"].number("ior", DEFAULT_IOR, *TRANSMISSION_IOR_RANGE)
        if "KHR_materials_volume" not in extensions:
            return
        volume = extensions["KHR_materials_volume"]
        m.thickness = volume.number("thicknessFactor", 0.0, 0.0)
        m.attenuation_color = tuple(float(c) for c in volume.numbers("attenuationColor", 3, [1, 1, 1], 0.0, 1.0))
        if volume.has("attenuationDistance"):
            m.attenuation_distance = volume.number("attenuationDistance", None, 0.0, lo_open=True)
        if m.transmission > 0.0 and m.thickness > 0.0 and volume.has("thicknessTexture"):
            self.texture(volume.object("thicknessTexture"), m, "thickness", False, name)

    def _specular(self, m: Material, extensions: dict, where: str, name: str, metallic_map: bool):
        """KHR_materials_ior / _specular: the dielectric's F0 from the IOR (Fresnel at normal
        incidence) times the specular colour and factor, its F90 the factor. A dielectric
        (metallicFactor 0) takes the specular workflow with that F0; a partly metallic material
        (0 < metallicFactor < 1, or a metallicRoughness texture) keeps the metallic workflow
        with that dielectric F0 (dielectric_specular), mixed with the base colour by metallic
        per pixel; a pure metal's F0 is its base colour and its F90 1, so neither enters."""
        if "KHR_materials_ior" not in extensions and "KHR_materials_specular" not in extensions:
            return
        absent = {key: FieldReader({}, f"{where}.extensions.{key}", self.doc)
                  for key in ("KHR_materials_ior", "KHR_materials_specular")}
        ior_ext = extensions.get("KHR_materials_ior", absent["KHR_materials_ior"])
        spec_ext = extensions.get("KHR_materials_specular", absent["KHR_materials_specular"])
        ior = ior_ext.number("ior", DEFAULT_IOR, 1.0)
        factor = spec_ext.number("specularFactor", 1.0, 0.0, 1.0)
        colour = spec_ext.numbers("specularColorFactor", 3, [1, 1, 1], 0.0)
        if m.metallic == 1.0 and not metallic_map:
            return  # a pure metal: F0 = base colour, F90 = 1, no diffuse; the dielectric does not enter
        f0_ior = ((ior - 1.0) / (ior + 1.0)) ** 2  # Fresnel at normal incidence, air to ior
        # the README's "Implementation": dielectric_f0 = min(f0_ior x specularColor, 1) x specular,
        # dielectric_f90 = specular (KHR_materials_ior alone keeps F90 from F0: the extension's 1
        # for every ior >= 1.331, where pbr_f90_from_f0 reaches 1); F0 = lerp(dielectric_f0,
        # baseColor, metallic) and F90 = lerp(dielectric_f90, 1, metallic) in the shader
        dielectric_f0 = np.minimum(f0_ior * colour, 1.0) * factor
        if m.metallic == 0.0:
            m.workflow = "specular"
            m.specular = dielectric_f0
        else:
            m.dielectric_specular = dielectric_f0
        if "KHR_materials_specular" in extensions:
            m.specular_f90 = factor
        for key, slot, srgb in (("specularColorTexture", "specular_color", True),
                                ("specularTexture", "specular_strength", False)):
            if spec_ext.has(key):
                self.texture(spec_ext.object(key), m, slot, srgb, name)
