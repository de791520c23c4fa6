"""The scene format's fields, as tables: the one place their types, defaults, bounds and
meanings are written.

``scene.py`` reads every field listed here through ``read_field`` (so a bound changed here
changes what the parser accepts), and ``scene_schema.py`` writes the JSON Schema (and the
docs' scene-file reference) from the same tables. The rules that tie fields together (one
of sphere or mesh, the workflow's own F0 field, ...) are the parser's code and the schema's
combinators; tests/scene/test_scene_schema.py checks the two agree on valid and invalid
scenes.

Kinds: ``Number`` (a float, ``lo``..``hi``, ``lo_open`` for an open lower bound), ``Vector``
(``n`` numbers, each in ``lo``..``hi``), ``Choice`` (one of ``options``, compared by type
and value), ``Flag`` (true or false), ``Integers`` (``n`` whole numbers in ``lo``..``hi``),
``Scale`` (a positive number or three), ``File`` (a path, relative to the scene file's folder). ``REQUIRED`` marks a field without
a default.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

REQUIRED = object()  # a field's default when the scene must give it


@dataclass(frozen=True)
class Number:
    doc: str
    default: object = REQUIRED
    lo: float = -math.inf
    hi: float = math.inf
    lo_open: bool = False
    only: tuple = ()  # the light types (or workflows) the field belongs to; () = all


@dataclass(frozen=True)
class Vector:
    doc: str
    default: object = REQUIRED
    lo: float = -math.inf
    hi: float = math.inf
    n: int = 3
    nonzero: bool = False
    only: tuple = ()


@dataclass(frozen=True)
class Choice:
    doc: str
    options: tuple
    default: object = REQUIRED
    only: tuple = ()


@dataclass(frozen=True)
class Flag:
    doc: str
    default: object = REQUIRED
    only: tuple = ()


@dataclass(frozen=True)
class Integers:
    doc: str
    default: object = REQUIRED
    lo: int = 0
    hi: int = 0
    n: int = 2
    only: tuple = ()


@dataclass(frozen=True)
class Scale:
    """A positive number, or a list of three (per axis)."""
    doc: str
    default: object = REQUIRED
    only: tuple = ()


@dataclass(frozen=True)
class File:
    doc: str
    default: object = REQUIRED
    only: tuple = ()


TONEMAPPERS = ("none", "reinhard", "aces_fitted", "aces_narkowicz", "hable", "khronos_neutral")  # pbr/tonemap/tonemap.glsl
QUALITIES = ("high", "medium", "low")  # PBR_QUALITY_* (pbr/shading/dispatch.glsl)
# render.brdf_model -> PBR_BRDF_MODEL_* (pbr/shading/dispatch.glsl): pbrlab's physical shading,
# or Unity's built-in BRDF1/2/3 by tier (pbr/unity/brdf_unity.glsl)
BRDF_MODELS = ("pbrlab", "unity")
ALPHA_MODES = ("opaque", "cutout", "fade", "transparent")  # Unity's Rendering Mode
HDR_TARGETS = ("rgba32f", "rgba16f")
# render.antialias: samples per pixel, 1 = none. Powers of two, as GL implementations offer
# them (OpenGL 4.5 core, section 9.2.4: an implementation's sample counts); 32 is beyond every
# GL_MAX_SAMPLES known to pbrlab. Which of them this context takes is checked before a render
# (pbrlab.gpu.gl_limits.check_antialias); llvmpipe (Mesa 22) takes 1 and 4.
ANTIALIAS_SAMPLES = (1, 2, 4, 8, 16, 32)
# render.antialias_filter: how a multisampled pixel is resolved (pbrlab.gpu.targets.RESOLVE_FILTERS):
# "box" averages the pixel's own samples (the GL's blit), "blackman_harris" weighs the samples
# within 1.5 px of the centre by the Blackman-Harris window (Cycles' default pixel filter)
ANTIALIAS_FILTERS = ("box", "blackman_harris")
# render.supersample: the image drawn this many times wider and taller, then filtered down
# (antialias_filter) to its size in linear: every pixel shaded at supersample^2 places
SUPERSAMPLES = (1, 2, 3, 4)
LIGHT_TYPES = ("directional", "point", "spot")
WORKFLOWS = ("metallic", "specular")
PRIMITIVES = ("box", "icosphere", "uv_sphere", "cylinder", "plane", "torus")
# The film's IOR: KHR_materials_iridescence's minimum 1; at most pbr_F_Iridescence's domain.
IRIDESCENCE_IOR_RANGE = (1.0, 16.0)
# The volume's index of refraction (KHR_materials_ior's ior as the transmission reads it):
# at least 1 (pbrlab's volumes are denser than the air around them), at most the Walter
# BTDF's domain (pbr/brdf/btdf_walter.glsl: eta in [1/16, 16]).
TRANSMISSION_IOR_RANGE = (1.0, 16.0)
CAMERA_SIZE_RANGE = (1, 16384)  # pixels per side

CAMERA = {
    "position": Vector("The eye, in scene units."),
    "target": Vector("The point looked at (not the eye's position)."),
    "up": Vector("The up direction (not parallel to the view direction).", default=[0, 1, 0], nonzero=True),
    "fov_y_deg": Number("The vertical field of view, in degrees.", default=45.0, lo=0.0, hi=179.0,
                        lo_open=True),
    "size": Integers("The image's [width, height] in pixels.", default=[512, 512],
                     lo=CAMERA_SIZE_RANGE[0], hi=CAMERA_SIZE_RANGE[1]),
}

LIGHT = {
    "type": Choice("directional (direction), point (position, range) or spot (both, and the cones).",
                   LIGHT_TYPES),
    "color": Vector("Linear RGB.", default=[1, 1, 1], lo=0.0),
    "intensity": Number("Multiplies color: irradiance (directional) or intensity (point, spot).",
                        default=1.0, lo=0.0),
    "direction": Vector("The way the light travels (not towards the light).", nonzero=True,
                        only=("directional", "spot")),
    "position": Vector("The light's position, in scene units.", only=("point", "spot")),
    "range": Number("Where the inverse-square falloff's smooth window reaches zero (Karis 2013); "
                    "absent: no window.", default=math.inf, lo=0.0, lo_open=True, only=("point", "spot")),
    "inner_cone_deg": Number("Full intensity inside this angle from the axis, in degrees "
                             "(smaller than outer_cone_deg).", default=0.0, lo=0.0, hi=90.0, only=("spot",)),
    "outer_cone_deg": Number("No light beyond this angle from the axis, in degrees; a smooth ramp between.",
                             default=45.0, lo=0.0, hi=90.0, lo_open=True, only=("spot",)),
}

ENVIRONMENT = {
    "color": Vector("A constant radiance, linear RGB (give this or path).", lo=0.0),
    "path": File("An equirectangular .hdr/.exr (+Y up, the image's centre looks at +Z; give this or color)."),
    "intensity": Number("Multiplies the radiance.", default=1.0, lo=0.0),
}

MATERIAL = {
    "workflow": Choice("metallic (albedo and metallic) or specular (albedo and specular).", WORKFLOWS,
                       default="metallic"),
    "albedo": Vector("The base colour, linear RGB.", default=[0.8, 0.8, 0.8], lo=0.0, hi=1.0),
    "metallic": Number("0 dielectric .. 1 metal (the metallic workflow).", default=0.0, lo=0.0, hi=1.0,
                       only=("metallic",)),
    "specular": Vector("F0, linear RGB (the specular workflow).", default=[0.04, 0.04, 0.04], lo=0.0,
                       hi=1.0, only=("specular",)),
    "specular_f90": Number("F90, the reflectance at grazing incidence (KHR_materials_specular's "
                           "specularFactor), at least every channel of specular (the specular workflow) "
                           "or of dielectric_specular (the metallic one: F90 = mix(specular_f90, 1, metallic)); "
                           "absent: F90 follows F0 (pbr_f90_from_f0).", default=None, lo=0.0, hi=1.0),
    "dielectric_specular": Vector("The metallic workflow's dielectric F0, linear RGB (KHR_materials_specular's "
                                  "dielectric_f0, KHR_materials_ior's F0): F0 = mix(dielectric_specular, "
                                  "albedo, metallic), the diffuse albedo (1 - max(dielectric_specular)) "
                                  "(1 - metallic); absent: 0.04.", default=None, lo=0.0, hi=1.0,
                                  only=("metallic",)),
    "smoothness": Number("1 - perceptual roughness (Unity's).", default=0.5, lo=0.0, hi=1.0),
    "emission": Vector("Linear radiance added to the lit colour.", default=[0, 0, 0], lo=0.0),
    "occlusion": Number("Scales indirect light only.", default=1.0, lo=0.0, hi=1.0),
    "alpha": Number("Opacity (or the cut-out's value).", default=1.0, lo=0.0, hi=1.0),
    "alpha_mode": Choice("Unity's rendering modes.", ALPHA_MODES, default="opaque"),
    "alpha_cutoff": Number("Cut-out threshold (alpha_mode cutout).", default=0.5, lo=0.0, hi=1.0),
    "unlit": Flag("KHR_materials_unlit: the albedo and alpha, no light.", default=False),
    "clearcoat": Number("The clear coat's mask (KHR_materials_clearcoat); 0 = none.", default=0.0,
                        lo=0.0, hi=1.0),
    "clearcoat_smoothness": Number("1 - the coat's perceptual roughness.", default=1.0, lo=0.0, hi=1.0),
    "sheen_color": Vector("The sheen's colour, linear (KHR_materials_sheen); 0 = none.",
                          default=[0.0, 0.0, 0.0], lo=0.0, hi=1.0),
    "sheen_smoothness": Number("1 - the sheen's perceptual roughness.", default=1.0, lo=0.0, hi=1.0),
    "anisotropy_strength": Number("KHR_materials_anisotropy's strength; 0 = none.", default=0.0,
                                  lo=0.0, hi=1.0),
    "anisotropy_rotation": Number("Radians, counter-clockwise from the tangent to the bitangent.",
                                  default=0.0),
    "iridescence": Number("The thin film's mask (KHR_materials_iridescence); 0 = none.", default=0.0,
                          lo=0.0, hi=1.0),
    "iridescence_ior": Number("The film's index of refraction.", default=1.3, lo=IRIDESCENCE_IOR_RANGE[0],
                              hi=IRIDESCENCE_IOR_RANGE[1]),
    "iridescence_thickness_min": Number("The film's thickness where the thickness map is 0, in nm.",
                                        default=100.0, lo=0.0),
    "iridescence_thickness_max": Number("The film's thickness where the map is 1 (or without one), in nm.",
                                        default=400.0, lo=0.0),
    "transmission": Number("KHR_materials_transmission's factor; 0 = none. The non-transmissive objects "
                           "behind and the environment are seen through.", default=0.0, lo=0.0, hi=1.0),
    "thickness": Number("The volume's thickness in scene units (KHR_materials_volume); 0 = thin-walled.",
                        default=0.0, lo=0.0),
    "attenuation_color": Vector("Beer-Lambert: the colour, linear, reached after attenuation_distance.",
                                default=[1.0, 1.0, 1.0], lo=0.0, hi=1.0),
    "attenuation_distance": Number("Scene units; absent: no attenuation (+infinity).", default=math.inf,
                                   lo=0.0, lo_open=True),
    "ior": Number("The volume's index of refraction (refraction only: F0 stays the workflow's).",
                  default=1.5, lo=TRANSMISSION_IOR_RANGE[0], hi=TRANSMISSION_IOR_RANGE[1]),
}
# The material fields a transmission of 0 leaves without meaning (each needs transmission > 0).
TRANSMISSION_KEYS = ("transmission", "thickness", "attenuation_color", "attenuation_distance", "ior")
# The layers only the default surface writes (a surface file writes its own output).
DEFAULT_SURFACE_LAYER_KEYS = ("clearcoat", "clearcoat_smoothness", "sheen_color", "sheen_smoothness",
                              "anisotropy_strength", "anisotropy_rotation", "iridescence",
                              "iridescence_ior", "iridescence_thickness_min",
                              "iridescence_thickness_max", "specular_f90", "dielectric_specular") + TRANSMISSION_KEYS

SPHERE = {
    "center": Vector("The centre, in scene units."),
    "radius": Number("The radius, in scene units.", lo=0.0, lo_open=True),
}

TRANSFORM = {
    "translate": Vector("Applied last.", default=[0, 0, 0]),
    "rotate_deg": Vector("Degrees about X, then Y, then Z.", default=[0, 0, 0]),
    "scale": Scale("A positive number, or three (per axis); applied first.", default=1.0),
}

RENDER = {
    "quality": Choice("The tier (PBR_QUALITY).", QUALITIES, default="high"),
    "tonemap": Choice("The PNG's tone mapper (the EXR holds radiance before exposure).", TONEMAPPERS,
                      default="none"),
    "exposure": Number("EV stops: the PNG's radiance x 2^exposure.", default=0.0, lo=-64.0, hi=64.0),
    "energy_compensation": Flag("Multiple-scattering energy compensation (PBR_ENERGY_COMPENSATION) where the "
                                "quality tier has it (high, medium; low reads single scattering); false: none.",
                                default=True),
    "hdr_target": Choice("The float target; rgba16f clamps at 65504.", HDR_TARGETS, default="rgba32f"),
    "brdf_model": Choice("pbrlab's shading, or Unity's BRDF1/2/3 by tier (PBR_BRDF_MODEL).", BRDF_MODELS,
                         default="pbrlab"),
    "antialias": Choice("Samples per pixel (multisampling, resolved in linear before exposure); 1 = none. "
                        "The GL must take the count (llvmpipe: 1 or 4).", ANTIALIAS_SAMPLES, default=1),
    "antialias_filter": Choice("How the samples are resolved: box (each pixel's own, averaged) or "
                               "blackman_harris (every sample within 1.5 px of the pixel's centre, weighted "
                               "by the Blackman-Harris window: Cycles' pixel filter); needs antialias > 1, "
                               "at most 16.", ANTIALIAS_FILTERS, default="box"),
    "horizon_occlusion": Flag("Take out the share of a normal-mapped surface's environment light that would "
                              "come through the object (below its geometric normal's horizon: "
                              "pbr/ibl/horizon_occlusion.glsl).", default=True),
    "valid_reflection_normal": Flag("Bend a normal-mapped shading normal towards the geometric normal until "
                                    "the view's mirror reflection stays just above the geometric surface "
                                    "(Keller et al. 2017, as Cycles does: "
                                    "pbr/shading/valid_reflection_normal.glsl).", default=False),
    "environment_sun": Flag("Split the environment image's sun (a compact source holding at least a fifth of its "
                            "light: scene/environment_sun.py) off as a directional light that casts shadows "
                            "(render/shadow_map.py); the rest stays the environment. Nothing changes for an "
                            "environment without a sun.", default=False),
    "environment_visibility": Choice("Scale the environment's specular light at each point by the share of the "
                                     "environment the scene's own geometry leaves visible, estimated from this many "
                                     "shadow maps along directions of equal flux (render/environment_visibility.py); "
                                     "0: off.", (0, 16, 32, 64), default=0),
    "environment_visibility_diffuse": Flag("With environment_visibility: scale the environment's diffuse (and sheen) "
                                           "light too. A path tracer fills what is hidden with light bounced off and "
                                           "emitted by the scene, which this does not add (docs/fidelity.md).",
                                           default=False),
    "volume_chord": Flag("A volume's path length (KHR_materials_volume: Beer-Lambert, where the transmitted ray "
                         "leaves it) measured along the view ray through its mesh, from a pass of its back "
                         "faces (render/volume_exit.py), instead of read from its thickness; a thickness of 0 "
                         "stays thin-walled.", default=False),
    "screen_space_reflections": Flag("Where the reflected ray of a lobe smoother than 0.6 meets the frame's own "
                                     "surfaces (searched through a first pass's positions), the first pass's "
                                     "radiance there replaces the environment's specular light, faded with the "
                                     "roughness and at the screen's border (render/screen_space_reflection.py). "
                                     "One more draw of the scene.", default=False),
    "supersample": Choice("Draw the image this many times wider and taller and filter it down (antialias_filter) "
                          "in linear: shading, not only coverage, at supersample^2 places a pixel. Pixel-sized "
                          "effects of a Unity shader (_ScreenParams, a 1-texel offset) see the drawn size.",
                          SUPERSAMPLES, default=1),
}


def read_field(reader, table: dict, key: str):
    """The value of ``key`` read through a scene._Reader with the table's type, default and
    bounds (its messages name the field). Files and whole-number pairs are read by their
    callers, whose messages say what the value means."""
    spec = table[key]
    default = None if spec.default is REQUIRED else spec.default
    if isinstance(spec, Number):
        return reader.number(key, default=default, lo=spec.lo, hi=spec.hi, lo_open=spec.lo_open)
    if isinstance(spec, Vector):
        return reader.vector(key, n=spec.n, default=default, lo=spec.lo, hi=spec.hi, nonzero=spec.nonzero)
    if isinstance(spec, Choice):
        return reader.choice(key, spec.options, default=default)
    if isinstance(spec, Flag):
        return reader.choice(key, (True, False), default=default)
    raise TypeError(f"{key}: a {type(spec).__name__} is read by its caller")
