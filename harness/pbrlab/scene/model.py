"""The JSON scene format, parsed into plain dataclasses with every field validated.

A bad field raises SceneError naming its path, e.g.
``scenes/x.json: materials.gold.smoothness: expected a number in [0, 1], got 1.5``.
Every document first passes json_input (duplicate keys, non-finite or beyond-float32
numbers, numpy values, nesting depth), so each field parser sees plain JSON types.
Unknown fields are errors too (a typo must not be silently ignored). Relative file
paths (meshes, textures, environments) are resolved against the scene file's folder.

Every field's type, default, bounds and meaning: scene_fields.py, from which scene_schema.py
writes the JSON Schema (`pbrlab schema`) and the docs' tables. Format (docs/scenes.md)::

    camera      {position, target, up=[0,1,0], fov_y_deg=45, size=[512, 512]}
                (may be left out when a gltf object brings a camera)
    lights      [{type: directional, direction (the way light travels), color, intensity}
                 {type: point, position, color, intensity, range}
                 {type: spot, position, direction, color, intensity, range,
                  inner_cone_deg, outer_cone_deg}]
    environment null | {color: [r,g,b]} | {path: "sky.hdr", intensity: 1}
    materials   {name: {workflow: metallic|specular, albedo, metallic, specular,
                        smoothness, emission, occlusion, alpha, textures: {albedo, ...},
                        brdf: {specular_d, specular_v, specular_f, diffuse}}}
    objects     [{sphere: {center, radius}, material}
                 {mesh: "file.obj" | {primitive: box|icosphere|cylinder|plane|torus, ...},
                  material, transform: {translate, rotate_deg, scale}}
                 {gltf: "model.glb", transform}]  (a whole glTF scene: pbrlab.importers.gltf)
    render      {quality: high, brdf_model: pbrlab|unity,
                 tonemap: none|reinhard|aces_fitted|aces_narkowicz|hable|khronos_neutral,
                 exposure: 0 (EV stops, multiplier 2^exposure), antialias: 1 (samples per pixel)}
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..foundation import json_input, safe_paths
from . import meshes, surface_layers
from ..foundation.errors import SceneError
from ..maths.reference import shading as _shading
from ..maths.reference.material import DIELECTRIC_F0 as _DIELECTRIC_F0
from .fields import (ALPHA_MODES, BRDF_MODELS, CAMERA, DEFAULT_SURFACE_LAYER_KEYS, ENVIRONMENT, IRIDESCENCE_IOR_RANGE, LIGHT, MATERIAL, PRIMITIVES, QUALITIES, RENDER, SPHERE, TONEMAPPERS, TRANSFORM, TRANSMISSION_IOR_RANGE, TRANSMISSION_KEYS, read_field)
from .fields import HDR_TARGETS as _HDR_TARGET_NAMES

# Per-material BRDF variants: scene key -> the library's selector values (lower case in
# scenes; the same names as pbrlab.maths.reference.shading and the PBR_SPECULAR_* defines).
BRDF_TERMS = {"specular_d": _shading.SPECULAR_D, "specular_v": _shading.SPECULAR_V,
              "specular_f": _shading.SPECULAR_F, "diffuse": _shading.DIFFUSE}

# The fields' types, defaults and bounds: scene_fields.py (the JSON Schema's source too).
HDR_TARGETS = dict(zip(_HDR_TARGET_NAMES, ("f32", "f16")))  # render.hdr_target -> targets.Target kind
TEXTURE_SLOTS = {  # default surface's slot -> colour (sRGB-decoded on sampling) or linear data
    "albedo": "srgb",
    "metallic_smoothness": "linear",  # Unity's packing: R = metallic, A = smoothness
    "metallic_roughness": "linear",   # glTF's packing: G = perceptual roughness, B = metallic
    "normal": "linear",               # tangent space, RGB = xyz * 0.5 + 0.5
    "emission": "srgb",
    "occlusion": "linear",
    "specular_glossiness": "srgb",    # RGB = specular colour (sRGB), A = glossiness (linear): glTF's
                                      # KHR_materials_pbrSpecularGlossiness, specular workflow
    "specular_color": "srgb",         # RGB x the specular colour (KHR_materials_specularColorTexture)
    "specular_strength": "linear",    # A x the specular colour (KHR_materials_specular's specularTexture)
    "clearcoat": "linear",            # R = the coat's mask (glTF clearcoatTexture)
    "clearcoat_roughness": "linear",  # G = the coat's perceptual roughness (glTF clearcoatRoughnessTexture)
    "clearcoat_normal": "linear",     # the coat's tangent-space normal (glTF clearcoatNormalTexture)
}
CLEARCOAT_SLOTS = ("clearcoat", "clearcoat_roughness", "clearcoat_normal")
# The sheen's maps (KHR_materials_sheen): sheen_color (sRGB, RGB x the colour), sheen_roughness
# (linear, A = the sheen's perceptual roughness: glTF sheenRoughnessTexture).
TEXTURE_SLOTS.update({"sheen_color": "srgb", "sheen_roughness": "linear"})
SHEEN_SLOTS = ("sheen_color", "sheen_roughness")
# The anisotropy's map (KHR_materials_anisotropy's anisotropyTexture, linear): RG = the
# direction in tangent space (x 2 - 1), B = the strength's factor.
TEXTURE_SLOTS.update({"anisotropy": "linear"})
ANISOTROPY_SLOTS = ("anisotropy",)
# The thin film's maps (KHR_materials_iridescence, linear): iridescence (R x the mask),
# iridescence_thickness (G: between the minimum and maximum thickness).
TEXTURE_SLOTS.update({"iridescence": "linear", "iridescence_thickness": "linear"})
IRIDESCENCE_SLOTS = ("iridescence", "iridescence_thickness")
# Transmission's maps (KHR_materials_transmission / KHR_materials_volume, linear):
# transmission (R x the factor), thickness (G x the thickness).
TEXTURE_SLOTS.update({"transmission": "linear", "thickness": "linear"})
TRANSMISSION_SLOTS = ("transmission", "thickness")


@dataclass
class Camera:
    position: np.ndarray
    target: np.ndarray
    up: np.ndarray
    fov_y_deg: float
    size: tuple[int, int]
    ortho_half_height: float | None = None  # orthographic (glTF ymag): half the view's height


@dataclass
class Light:
    type: str
    color: np.ndarray
    intensity: float
    direction: np.ndarray | None = None  # the way light travels (directional, spot)
    position: np.ndarray | None = None
    range: float = math.inf
    inner_cone_deg: float = 0.0
    outer_cone_deg: float = 45.0


@dataclass
class Environment:
    color: np.ndarray | None = None  # constant radiance
    path: Path | None = None  # equirectangular image
    intensity: float = 1.0


@dataclass
class Material:
    name: str
    workflow: str = "metallic"
    albedo: np.ndarray = field(default_factory=lambda: np.array([0.8, 0.8, 0.8]))
    metallic: float = 0.0
    specular: np.ndarray = field(default_factory=lambda: np.array([0.04, 0.04, 0.04]))
    smoothness: float = 0.5
    emission: np.ndarray = field(default_factory=lambda: np.zeros(3))
    occlusion: float = 1.0
    alpha: float = 1.0
    textures: dict[str, Path] = field(default_factory=dict)
    texture_srgb: dict[str, bool] = field(default_factory=dict)  # per texture: decode sRGB?
    brdf: dict[str, str] = field(default_factory=dict)  # e.g. {"specular_d": "BECKMANN"}
    alpha_mode: str = "opaque"
    alpha_cutoff: float = 0.5
    surface: Path | None = None  # a GLSL file defining surf(Input, inout SurfaceOutput...)
    # Per texture slot, set by the glTF importer (pbrlab/importers/gltf): UV set 0 or 1, a 2x3 UV
    # transform, a sampler (wrap_s, wrap_t, min_filter, mag_filter as GL enums).
    texture_uv_set: dict[str, int] = field(default_factory=dict)
    texture_transform: dict[str, np.ndarray] = field(default_factory=dict)
    texture_sampler: dict[str, tuple] = field(default_factory=dict)
    normal_scale: float = 1.0
    occlusion_strength: float = 1.0
    # The clear coat (KHR_materials_clearcoat; pbr/unity/surface_layers.glsl): mask 0 is none
    clearcoat: float = 0.0
    clearcoat_smoothness: float = 1.0  # 1 - the coat's perceptual roughness
    clearcoat_normal_scale: float = 1.0
    unlit: bool = False  # KHR_materials_unlit: the surface's albedo and alpha, no light
    # The sheen (KHR_materials_sheen; pbr/unity/surface_layers.glsl): colour 0 is none
    sheen_color: tuple = (0.0, 0.0, 0.0)  # linear
    sheen_smoothness: float = 1.0          # 1 - the sheen's perceptual roughness
    # The anisotropy (KHR_materials_anisotropy; pbr/unity/surface_layers.glsl): strength 0 is
    # none (x the map's B); rotation in radians, counter-clockwise from the tangent to the bitangent
    anisotropy_strength: float = 0.0
    anisotropy_rotation: float = 0.0
    # The thin film (KHR_materials_iridescence; pbr/unity/surface_layers.glsl): mask 0 is none
    # (x the map's R); thickness in nanometres, the maximum without the thickness map (G)
    iridescence: float = 0.0
    iridescence_ior: float = 1.3
    iridescence_thickness_min: float = 100.0
    iridescence_thickness_max: float = 400.0
    # Transmission (KHR_materials_transmission, KHR_materials_volume; pbr/surface/
    # lighting_transmission.glsl): 0 is none (x the map's R); thickness in scene units (x the
    # map's G), 0 = thin-walled; Beer-Lambert attenuation colour (linear) reached after
    # attenuation_distance (+inf: none); ior the volume's (refraction only: F0 stays the
    # workflow's)
    transmission: float = 0.0
    thickness: float = 0.0
    attenuation_color: tuple = (1.0, 1.0, 1.0)
    attenuation_distance: float = math.inf
    ior: float = 1.5
    # An explicit F90 (KHR_materials_specular's specularFactor; pbr/unity/surface_layers.glsl's
    # SpecularF90; the metallic workflow blends it towards 1 by metallic): None is F90 from F0
    # (pbr_f90_from_f0)
    specular_f90: float | None = None
    # The metallic workflow's dielectric F0 (KHR_materials_ior / _specular on a metallic
    # material; pbr/unity/surface_layers.glsl's DielectricSpecular), linear RGB: None is 0.04
    dielectric_specular: np.ndarray | None = None
    vertex_color: bool = False
    double_sided: bool | None = None  # None: cull back faces unless blended (JSON scenes)
    # How the renderer draws it (scene.material_passes.MaterialSource): None for pbrlab's own
    # material (scene.standard_material); an importer's source when `surface` is another
    # engine's shader (importers/unity/material.py: a .shader, or text with #pragma surface)
    source: object = None
    properties: dict = field(default_factory=dict)  # the shader's Properties' values, by name
    keywords: tuple = ()         # the shader keywords it enables (Unity's Material.EnableKeyword)


@dataclass
class SceneObject:
    material: str
    sphere: tuple[np.ndarray, float] | None = None  # (center, radius)
    mesh_path: Path | None = None
    primitive: dict | None = None
    transform: np.ndarray = field(default_factory=lambda: np.eye(4))
    geometry: object = None  # meshes.Geometry: vertex data held in memory (glTF primitives)
    where: str = ""  # the object's name in messages: "scene.json: objects[1]", "x.gltf: nodes[3] (...)"
    # Objects with the same instance_group, geometry and material are instances of one mesh
    # (glTF EXT_mesh_gpu_instancing): the renderer may draw them in one instanced call.
    instance_group: object = None


@dataclass
class RenderSettings:
    quality: str = "high"
    tonemap: str = "none"
    exposure: float = 0.0
    energy_compensation: bool = True  # PBR_ENERGY_COMPENSATION
    hdr_target: str = "rgba32f"  # the float target: rgba32f, or rgba16f (values clamped to 65504)
    brdf_model: str = "pbrlab"  # PBR_BRDF_MODEL: "pbrlab" or "unity" (Unity's BRDF1/2/3 by tier)
    # exposure metered from the rendered image, added to ``exposure`` (pbrlab.maths.exposure):
    # what `pbrlab render` chooses for a glTF file in physical light units left unset
    exposure_metered: bool = False
    # samples per pixel (1: no antialiasing): multisampled targets resolved in linear before
    # exposure, spheres covering their samples analytically (pbrlab.render.renderer, docs/rendering.md)
    antialias: int = 1
    # how the samples are resolved: "box" (each pixel's own) or "blackman_harris" (gpu/targets.py)
    antialias_filter: str = "box"
    # the image drawn supersample times wider and taller, filtered down in linear (gpu/targets.py)
    supersample: int = 1
    # a normal-mapped surface's environment light below its geometric horizon taken out
    # (PBRLAB_HORIZON_OCCLUSION: pbr/ibl/horizon_occlusion.glsl)
    horizon_occlusion: bool = True
    # a normal-mapped shading normal bent towards the geometric one until the view's mirror
    # reflection stays above the geometric surface (PBRLAB_VALID_REFLECTION_NORMAL:
    # pbr/shading/valid_reflection_normal.glsl, as Cycles does)
    valid_reflection_normal: bool = False
    # the environment's sun (a compact source holding a large share of its light: scene/environment_sun.py)
    # drawn as a directional light with a shadow map (render/shadow_map.py) and taken out of the environment
    environment_sun: bool = False
    # the environment's light scaled by the share the scene's own geometry leaves visible, from
    # this many shadow maps (0: off; render/environment_visibility.py)
    environment_visibility: int = 0
    # ... applied to the environment's diffuse (and sheen) light too, not only its specular
    environment_visibility_diffuse: bool = False
    # a volume's path length (KHR_materials_volume) measured along the view ray through its
    # geometry instead of read from its thickness (render/volume_exit.py)
    volume_chord: bool = False
    # the environment's specular read replaced where its ray meets the frame's own surfaces, from a
    # first pass of the frame (render/screen_space_reflection.py)
    screen_space_reflections: bool = False


@dataclass
class Scene:
    camera: Camera
    lights: list[Light]
    environment: Environment | None
    materials: dict[str, Material]
    objects: list[SceneObject]
    render: RenderSettings
    source: str = "<scene>"
    # files read besides the scene file and its materials' and objects' own (a glTF's file,
    # buffers and images), with their roles: what an output must not be (render.input_files)
    read_files: list = field(default_factory=list)

    @property
    def spheres(self):
        return [o for o in self.objects if o.sphere is not None]

    @property
    def meshes(self):
        return [o for o in self.objects if o.sphere is None]


class _Reader:
    """Typed access to one JSON object, with error messages that carry the field path."""

    def __init__(self, data, path: str, origin: str):
        self.path, self.origin = path, origin
        if not isinstance(data, dict):
            self.fail(f"expected an object, got {type(data).__name__}")
        self.data = dict(data)
        self.used: set[str] = set()

    def fail(self, message: str, key: str | None = None):
        where = f"{self.path}.{key}" if key else self.path
        raise SceneError(f"{self.origin}: {where.lstrip('.') or '(top level)'}: {message}")

    def has(self, key):
        return key in self.data

    def raw(self, key, default=None):
        self.used.add(key)
        return self.data.get(key, default)

    def child(self, key, default=None):
        value = self.raw(key, default)
        return _Reader(value, f"{self.path}.{key}", self.origin)

    def number(self, key, default=None, lo=-math.inf, hi=math.inf, lo_open=False):
        value = self.raw(key, default)
        if value is None:
            self.fail("is required", key)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(f"expected a number, got {json.dumps(value)}", key)
        value = float(value)
        if math.isnan(value):
            self.fail("is NaN", key)
        if not (lo < value if lo_open else lo <= value) or value > hi:
            bound = f"({lo}, {hi}]" if lo_open else f"[{lo}, {hi}]"
            self.fail(f"expected a number in {bound}, got {value:g}", key)
        return value

    def vector(self, key, n=3, default=None, lo=-math.inf, hi=math.inf, nonzero=False):
        value = self.raw(key, default)
        if value is None:
            self.fail("is required", key)
        if (not isinstance(value, (list, tuple)) or len(value) != n
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)):
            self.fail(f"expected a list of {n} numbers, got {json.dumps(value)}", key)
        arr = np.array(value, dtype=np.float64)
        if not np.all(np.isfinite(arr)):
            self.fail(f"has a non-finite component: {json.dumps(value)}", key)
        if np.any(arr < lo) or np.any(arr > hi):
            self.fail(f"components must lie in [{lo:g}, {hi:g}], got {json.dumps(value)}", key)
        if nonzero and not np.any(arr):
            self.fail("must not be the zero vector", key)
        return arr

    def choice(self, key, options, default=None):
        value = self.raw(key, default)
        # same type and value: 0 is not False, 1.0 is not True, a list is no option at all
        if not any(type(value) is type(o) and value == o for o in options):
            shown = ", ".join(o if isinstance(o, str) else json.dumps(o) for o in options)
            self.fail(f"expected one of {shown}, got {json.dumps(value)}", key)
        return value

    def file(self, key, base: Path, value=None):
        value = self.raw(key) if value is None else value
        if not isinstance(value, str) or not value or "\x00" in value:
            self.fail(f"expected a file path, got {json.dumps(value)}", key)
        try:  # the folder rule first: a link out of the folder is refused, not followed (safe_paths)
            safe_paths.inside(base, value, climb=True)
        except safe_paths.OutsideFolderError as exc:
            self.fail(exc.reason, key)
        try:
            path = (base / value).resolve(strict=True)
        except FileNotFoundError:
            self.fail(f"file not found: {base / value}", key)
        except (OSError, RuntimeError) as exc:  # a symlink loop, a component that is a file
            self.fail(f"cannot open {base / value}: {getattr(exc, 'strerror', None) or exc}", key)
        if not path.is_file():
            self.fail(f"not a file: {path}", key)
        try:
            with open(path, "rb"):
                pass
        except OSError as exc:
            self.fail(f"cannot read {path}: {exc.strerror or exc}", key)
        return path

    def finish(self):
        unknown = sorted(set(self.data) - self.used)
        if unknown:
            self.fail(f"unknown field{'s' if len(unknown) > 1 else ''}: {', '.join(unknown)}")


def _camera(r: _Reader) -> Camera:
    position = read_field(r, CAMERA, "position")
    target = read_field(r, CAMERA, "target")
    if np.allclose(position, target):
        r.fail("position and target coincide")
    up = read_field(r, CAMERA, "up")
    forward = target - position
    if np.linalg.norm(np.cross(forward, up)) < 1e-9 * np.linalg.norm(forward) * np.linalg.norm(up):
        r.fail("up is parallel to the view direction", "up")
    fov = read_field(r, CAMERA, "fov_y_deg")
    size_field = CAMERA["size"]
    size = r.raw("size", size_field.default)
    if (not isinstance(size, list) or len(size) != size_field.n
            or not all(isinstance(s, int) and not isinstance(s, bool) and size_field.lo <= s <= size_field.hi
                       for s in size)):
        r.fail(f"expected [width, height], integers in {size_field.lo}..{size_field.hi}, got {json.dumps(size)}",
               "size")
    r.finish()
    return Camera(position, target, up, fov, (size[0], size[1]))


def _light(r: _Reader) -> Light:
    kind = read_field(r, LIGHT, "type")
    light = Light(type=kind, color=read_field(r, LIGHT, "color"), intensity=read_field(r, LIGHT, "intensity"))
    for key in ("direction", "position", "range", "inner_cone_deg", "outer_cone_deg"):
        if kind in LIGHT[key].only:  # a field of another type is left unread: finish() names it
            setattr(light, key, read_field(r, LIGHT, key))
    if light.direction is not None:
        light.direction = unit_direction(light.direction)
    if kind == "spot":
        if light.inner_cone_deg >= light.outer_cone_deg:
            r.fail("inner_cone_deg must be smaller than outer_cone_deg", "inner_cone_deg")
    r.finish()
    return light


def _environment(r: _Reader, base: Path) -> Environment:
    env = Environment(intensity=read_field(r, ENVIRONMENT, "intensity"))
    if r.has("color") == r.has("path"):
        r.fail("give exactly one of color (constant radiance) or path (equirectangular image)")
    if r.has("color"):
        env.color = read_field(r, ENVIRONMENT, "color")
    else:
        env.path = r.file("path", base)
    r.finish()
    return env


def unit_direction(v) -> np.ndarray:
    """v / |v| for any finite non-zero v: scaled by its largest component first, so a
    direction such as [1e-200, 1e-200, 0] (whose |v|² underflows to 0) is still a direction."""
    v = np.asarray(v, np.float64)
    v = v / np.max(np.abs(v))
    return v / np.linalg.norm(v)


def _material(r: _Reader, name: str, base: Path, shaders=None) -> Material:
    m = Material(name=name)
    m.workflow = read_field(r, MATERIAL, "workflow")
    m.albedo = read_field(r, MATERIAL, "albedo")
    setattr(m, m.workflow, read_field(r, MATERIAL, m.workflow))  # metallic or specular: F0's field
    other = "specular" if m.workflow == "metallic" else "metallic"
    if r.has(other):
        r.fail(f"{other} belongs to the {other} workflow; use {m.workflow} here", other)
    for key in ("smoothness", "emission", "occlusion", "alpha", "alpha_mode", "alpha_cutoff"):
        setattr(m, key, read_field(r, MATERIAL, key))
    m.unlit = r.raw("unlit", MATERIAL["unlit"].default)
    if not isinstance(m.unlit, bool):
        r.fail("expected true (KHR_materials_unlit: the albedo, no light) or false", "unlit")
    for key in DEFAULT_SURFACE_LAYER_KEYS:  # numbers; colours as tuples; None where absent means "not given"
        if MATERIAL[key].default is None and not r.has(key):
            continue
        value = read_field(r, MATERIAL, key)
        setattr(m, key, tuple(value) if isinstance(value, np.ndarray) else value)
    if r.has("surface"):
        m.surface = r.file("surface", base)
    if m.surface is not None and shaders is not None and shaders.reads(m.surface):
        shaders.read_material(r, m, base)  # a shader of another engine's (the loader's importers)
        return m
    if r.has("properties"):
        r.fail("properties belong to a Unity surface shader (a .shader file or text with "
               "#pragma surface) named by `surface`", "properties")
    textures = r.child("textures", {})
    for name in list(textures.data):
        value = textures.data[name]
        if m.surface is None and name not in TEXTURE_SLOTS:
            textures.fail(f"unknown texture slot; use one of {', '.join(TEXTURE_SLOTS)} "
                          "(or give the material a surface file declaring its own samplers)", name)
        if isinstance(value, dict):  # {"path": ..., "srgb": true|false}
            t = textures.child(name)
            m.textures[name] = t.file("path", base)
            srgb = t.raw("srgb")
            if not isinstance(srgb, bool):
                t.fail("expected true (colour, sRGB-encoded) or false (linear data)", "srgb")
            m.texture_srgb[name] = srgb
            t.finish()
        elif name in TEXTURE_SLOTS:
            m.textures[name] = textures.file(name, base)
            m.texture_srgb[name] = TEXTURE_SLOTS[name] == "srgb"
        else:
            textures.fail('a surface file\'s texture needs {"path": ..., "srgb": true|false}', name)
    textures.finish()
    if m.surface is not None and (r.has("clearcoat") or r.has("clearcoat_smoothness")):
        r.fail("the clear coat belongs to the default surface; a surface file writes its own "
               "output (remove `clearcoat`, `clearcoat_smoothness`)", "clearcoat" if r.has("clearcoat") else
               "clearcoat_smoothness")
    if m.surface is not None and (r.has("sheen_color") or r.has("sheen_smoothness")):
        r.fail("the sheen belongs to the default surface; a surface file writes its own output "
               "(remove `sheen_color`, `sheen_smoothness`)", "sheen_color" if r.has("sheen_color") else
               "sheen_smoothness")
    if m.surface is not None and (r.has("anisotropy_strength") or r.has("anisotropy_rotation")):
        r.fail("the anisotropy belongs to the default surface; a surface file writes its own output "
               "(remove `anisotropy_strength`, `anisotropy_rotation`)",
               "anisotropy_strength" if r.has("anisotropy_strength") else "anisotropy_rotation")
    film_keys = [k for k in ("iridescence", "iridescence_ior", "iridescence_thickness_min",
                             "iridescence_thickness_max") if r.has(k)]
    if m.surface is not None and film_keys:
        r.fail("the iridescence belongs to the default surface; a surface file writes its own output "
               f"(remove `{'`, `'.join(film_keys)}`)", film_keys[0])
    if m.surface is not None and r.has("specular_f90"):
        r.fail("the explicit F90 belongs to the default surface; a surface file writes its own output "
               "(SurfaceOutputStandardLayers.SpecularF90; remove `specular_f90`)", "specular_f90")
    if r.has("dielectric_specular"):
        if m.surface is not None:
            r.fail("the dielectric F0 belongs to the default surface; a surface file writes its own output "
                   "(SurfaceOutputStandardLayers.DielectricSpecular; remove `dielectric_specular`)",
                   "dielectric_specular")
        if m.workflow != "metallic":
            r.fail("belongs to the metallic workflow (the F0 of its dielectric share); the specular workflow's "
                   "F0 is `specular`", "dielectric_specular")
        m.dielectric_specular = np.asarray(m.dielectric_specular, np.float64)
    if m.specular_f90 is not None:
        # the dielectric's F0 that F90 bounds: the specular workflow's F0, the metallic one's dielectric share
        f0_name, f0 = (("specular", m.specular) if m.workflow == "specular" else
                       ("dielectric_specular", m.dielectric_specular if m.dielectric_specular is not None
                        else np.full(3, _DIELECTRIC_F0)))
        if m.specular_f90 < float(np.max(f0)):
            r.fail(f"F90 {m.specular_f90:g} is below the F0 `{f0_name}` {float(np.max(f0)):g}: F90 is at "
                   "least every channel of F0 (KHR_materials_specular: F0 = min(F0_ior x colour, 1) x F90)",
                   "specular_f90")
    transmission_keys = [k for k in TRANSMISSION_KEYS if r.has(k)]
    if m.surface is not None and transmission_keys:
        r.fail("the transmission belongs to the default surface; a surface file writes its own output "
               f"(remove `{'`, `'.join(transmission_keys)}`)", transmission_keys[0])
    if m.transmission == 0.0:
        for key in TRANSMISSION_KEYS[1:]:
            if r.has(key):
                r.fail(f"`{key}` belongs to the transmission, which is 0 here: give the material a "
                       "transmission in (0, 1]", key)
    for slot in TRANSMISSION_SLOTS:
        if slot in m.textures and m.transmission == 0.0:
            textures.fail(f"the {slot} map belongs to the transmission, which is 0 here: give the "
                          "material a transmission in (0, 1]", slot)
    if "thickness" in m.textures and m.thickness == 0.0:
        textures.fail("the thickness map scales `thickness`, which is 0 (thin-walled) here: give the "
                      "material a thickness > 0", "thickness")
    for slot in IRIDESCENCE_SLOTS:
        if slot in m.textures and m.iridescence == 0.0:
            textures.fail(f"the {slot} map belongs to the thin film, whose mask `iridescence` is 0 here: "
                          "give the material an iridescence in (0, 1]", slot)
    if "anisotropy" in m.textures and m.anisotropy_strength == 0.0:
        textures.fail("the anisotropy map scales anisotropy_strength, which is 0 here: give the "
                      "material an anisotropy_strength in (0, 1]", "anisotropy")
    if "metallic_smoothness" in m.textures and "metallic_roughness" in m.textures:
        textures.fail("give one packing: metallic_smoothness (Unity: R metallic, A smoothness) or "
                      "metallic_roughness (glTF: B metallic, G roughness), not both")
    brdf = r.child("brdf", {})
    for term in list(brdf.data):
        if term not in BRDF_TERMS:
            brdf.fail(f"unknown BRDF term; use one of {', '.join(BRDF_TERMS)}", term)
        options = tuple(v.lower() for v in BRDF_TERMS[term])
        m.brdf[term] = brdf.choice(term, options).upper()
    brdf.finish()
    r.finish()
    return m


def _transform(r: _Reader) -> np.ndarray:
    translate = read_field(r, TRANSFORM, "translate")
    rx, ry, rz = np.radians(read_field(r, TRANSFORM, "rotate_deg"))
    scale = r.raw("scale", TRANSFORM["scale"].default)
    if isinstance(scale, (int, float)) and not isinstance(scale, bool):
        scale = [scale] * 3
    r.data["scale"] = scale
    scale = r.vector("scale", lo=0.0)
    if np.any(scale == 0):
        r.fail("scale components must be positive", "scale")
    r.finish()
    cx, sx, cy, sy, cz, sz = np.cos(rx), np.sin(rx), np.cos(ry), np.sin(ry), np.cos(rz), np.sin(rz)
    rot_x = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    rot_y = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rot_z = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    m = np.eye(4)
    m[:3, :3] = rot_z @ rot_y @ rot_x @ np.diag(scale)  # scale, then X, Y, Z rotations
    m[:3, 3] = translate
    return m


def _object(r: _Reader, materials: dict, base: Path) -> SceneObject:
    material = r.raw("material")
    if not isinstance(material, str) or material not in materials:
        r.fail(f"unknown material {json.dumps(material)}; defined: {', '.join(materials) or 'none'}",
               "material")
    obj = SceneObject(material=material, where=f"{r.origin}: {r.path}")
    if r.has("sphere") == r.has("mesh"):
        r.fail("give exactly one of sphere or mesh")
    if r.has("sphere"):
        s = r.child("sphere")
        obj.sphere = (read_field(s, SPHERE, "center"), read_field(s, SPHERE, "radius"))
        s.finish()
        if r.has("transform"):
            r.fail("spheres are placed by center and radius, not transform", "transform")
    else:
        mesh = r.raw("mesh")
        if isinstance(mesh, str):
            obj.mesh_path = r.file("mesh", base)
        else:
            p = r.child("mesh")
            kind = p.choice("primitive", PRIMITIVES)
            obj.primitive = {"primitive": kind}
            allowed = meshes.PRIMITIVE_PARAMETERS[kind]
            for key in list(p.data):
                if key == "primitive":
                    continue
                if key not in allowed:
                    p.fail(f"unknown parameter of a {kind}; use {', '.join(allowed) or 'none'}", key)
                if key in meshes.INTEGER_PARAMETERS:
                    lo, hi = meshes.INTEGER_PARAMETERS[key]
                    value = p.raw(key)
                    if isinstance(value, bool) or not isinstance(value, (int, float)) or value != int(value) \
                            or not lo <= value <= hi:
                        p.fail(f"expected a whole number in [{lo}, {hi}], got {value!r}", key)
                    obj.primitive[key] = int(value)
                else:
                    obj.primitive[key] = p.number(key, lo=0.0, lo_open=True)
            p.finish()
        obj.transform = _transform(r.child("transform", {}))
    r.finish()
    return obj


def _gltf_subscene(r: _Reader, base: Path, read_gltf):
    """An object ``{"gltf": "model.glb", "transform": {...}}``: the file's whole scene
    (nodes, materials, lights, camera) placed by the transform; ``"time"`` and ``"animation"``
    pose it as ``pbrlab render --time --animation`` do (gltf.animation). Its materials are named
    "<file name>/<material>"; its camera serves when the scene gives none. ``read_gltf(path)``
    reads the file (``gltf.load_gltf``): the scene model sits below the importers and is
    handed their reader (scene_files), never imports it (docs/layers.md)."""
    if read_gltf is None:
        r.fail("a glTF object needs the glTF reader: read this scene with pbrlab.importers.loader "
               "(load_scene or parse_scene), as pbrlab render does", "gltf")
    path = r.file("gltf", base)
    transform = _transform(r.child("transform", {}))
    options = {}  # the glTF animation: "time" in seconds, "animation" an index, a name or "all"
    if r.has("time"):
        options["time"] = r.number("time", lo=-1e30, hi=1e30)
    if r.has("animation"):
        animation = r.raw("animation")
        if isinstance(animation, bool) or not isinstance(animation, (int, str)) or animation == "":
            r.fail(f"expected an animation index, name or \"all\", got {json.dumps(animation)}", "animation")
        options["animation"] = str(animation)
    r.finish()
    sub = read_gltf(path, **options)
    prefix = f"{path.name}/"
    materials = {}
    for name, material in sub.scene.materials.items():
        material.name = prefix + name
        materials[material.name] = material
    objects = []
    for obj in sub.scene.objects:
        obj.material = prefix + obj.material
        obj.transform = transform @ obj.transform
        objects.append(obj)
    for light in sub.scene.lights:
        if light.position is not None:
            light.position = transform[:3, :3] @ light.position + transform[:3, 3]
        if light.direction is not None:
            d = transform[:3, :3] @ light.direction
            light.direction = unit_direction(d)
    camera = None
    if sub.cameras:
        camera = sub.scene.camera
        camera.position = transform[:3, :3] @ camera.position + transform[:3, 3]
        camera.target = transform[:3, :3] @ camera.target + transform[:3, 3]
        camera.up = transform[:3, :3] @ camera.up
    return objects, materials, sub.scene.lights, camera, [(path, f"{r.path}'s glTF file"), *sub.scene.read_files]


# The layers Unity's BRDFs cannot draw: (layer, why, what the material is, the remedy), refused
# by name when render.brdf_model is "unity".
_UNITY_REFUSED_LAYERS = (
    ("anisotropy", "Unity's BRDFs have no anisotropic lobe", "is anisotropic",
     "use brdf_model pbrlab, or anisotropy_strength 0"),
    ("iridescence", "Unity's BRDFs have no F0 a thin film could replace", "is iridescent",
     "use brdf_model pbrlab, or iridescence 0"),
    ("transmission", "Unity's BRDFs have no transmission", "is transmissive",
     "use brdf_model pbrlab, or transmission 0"),
    ("specular_f90", "Unity's BRDFs take F90 from F0", "has an explicit F90",
     "KHR_materials_specular; use brdf_model pbrlab, or remove specular_f90"),
    ("dielectric_specular", "Unity's metallic setup has the dielectric F0 0.04", "has its own",
     "KHR_materials_ior / _specular; use brdf_model pbrlab, or remove dielectric_specular"),
)


def parse_scene(data, origin: str = "<scene>", base: Path | None = None, read_gltf=None,
                shaders=None) -> Scene:
    """Validate a scene given as parsed JSON; ``base`` resolves relative file paths.
    ``read_gltf``: the reader of ``{"gltf": ...}`` objects; ``shaders``: the reader of
    materials whose ``surface`` is another engine's shader (``reads(path)``,
    ``read_material(reader, material, base)``, ``check_objects(objects, materials, origin)``).
    pbrlab.importers.loader passes both; without them a glTF object is refused and every
    surface file is read as a GLSL/HLSL surface."""
    base = Path(base or ".")
    data = json_input.normalize(data, origin)  # a checked copy: the caller's data is never changed
    top = _Reader(data, "", origin)
    camera = _camera(top.child("camera")) if top.has("camera") else None
    lights_raw = top.raw("lights", [])
    if not isinstance(lights_raw, list):
        top.fail("expected a list of lights", "lights")
    lights = [_light(_Reader(l, f"lights[{i}]", origin)) for i, l in enumerate(lights_raw)]
    env_raw = top.raw("environment")
    environment = None if env_raw is None else _environment(top.child("environment"), base)
    mats = top.child("materials", {})
    materials = {name: _material(mats.child(name), name, base, shaders) for name in list(mats.data)}
    mats.finish()
    objects_raw = top.raw("objects", [])
    if not isinstance(objects_raw, list) or not objects_raw:
        top.fail("expected a non-empty list of objects", "objects")
    objects, read_files = [], []
    for i, o in enumerate(objects_raw):
        if isinstance(o, dict) and "gltf" in o:
            sub_objects, sub_materials, sub_lights, sub_camera, sub_files = _gltf_subscene(
                _Reader(o, f"objects[{i}]", origin), base, read_gltf)
            read_files += sub_files
            objects += sub_objects
            materials.update(sub_materials)
            lights += sub_lights
            camera = camera or sub_camera
        else:
            objects.append(_object(_Reader(o, f"objects[{i}]", origin), materials, base))
    if camera is None:
        top.fail("is required (or a gltf object with a camera)", "camera")
    if shaders is not None:
        shaders.check_objects(objects, materials, origin)
    rs = top.child("render", {})
    render = RenderSettings(**{key: read_field(rs, RENDER, key) for key in RENDER})
    rs.finish()
    if render.antialias_filter != "box" and not (1 < render.antialias <= 16 or render.supersample > 1):
        rs.fail(f"{render.antialias_filter} filters a pixel's samples: it needs an antialias of 2 to 16 or a "
                f"supersample above 1, got antialias {render.antialias}", "antialias_filter")
    if render.brdf_model == "unity":
        # the layers from the material's numbers, or from what its surface writes
        layers = {name: surface_layers.material_layers(m) for name, m in materials.items()}
        for layer, what, has, remedy in _UNITY_REFUSED_LAYERS:
            using = sorted(name for name in materials if layer in layers[name])
            if using:
                rs.fail(f"{what}; material {using[0]!r} {has} ({remedy})", "brdf_model")
    top.finish()
    return Scene(camera, lights, environment, materials, objects, render, origin, read_files)


def load_scene(path, read_gltf=None, shaders=None) -> Scene:
    """Read and validate a JSON scene file (``read_gltf``, ``shaders``: see parse_scene; a scene
    file of either format, with its importers: pbrlab.importers.loader.load_scene)."""
    path = Path(path)
    return parse_scene(json_input.read_json_file(path), str(path), path.parent, read_gltf, shaders)
