"""Scene-driven shader specialisation: which effects a scene can show, as compile-time
feature sets, and the #defines that select them.

Two kinds of compile-time configuration reach a program:

* settings: choices the scene makes (workflow, alpha mode, BRDF variants, quality tier,
  BRDF model, energy compensation, HDR target). Both the specialised and the full program compile
  them; they change the image.
* effects: work a scene may or may not call for: punctual lights of each type, the
  environment (indirect diffuse and specular), emission, occlusion, an alpha value,
  each texture map. The specialised program compiles only the effects the material and
  scene can show: no emission when it is zero everywhere and unmapped, no occlusion when
  it is 1 without a map, no alpha in opaque mode, no loop for a light type the scene
  lacks, nothing of the environment without one. The full program compiles every effect
  and is fed neutral values (emission 0, occlusion 1, alpha 1, white or flat maps, zero
  lights of a type, a black environment); it is the fallback when a scene needs more
  programs than ``MAX_SPECIALISED_PROGRAMS``, and the reference the equivalence tests
  compare against.

A material with its own ``surface`` file is opaque to this analysis: its effects are
all compiled (its code decides what it writes), except the layers beyond the Standard
model, compiled exactly where the surface writes their fields (surface_layers.py).
"""

from __future__ import annotations

import warnings
from dataclasses import asdict, dataclass

import numpy as np

from ..foundation import json_input
from ..scene import surface_layers
from . import texture_slots
from ..foundation.errors import SceneError
from ..maths.reference.shading import glsl_defines

# The checking and production programs (templates/surface_pixel.inc; docs/specialisation.md):
# PBRLAB_CHECKING 1 (the templates' default, `pbrlab render`'s) tests the surface's output for
# NaN and Inf; the production program, compiled with PBRLAB_CHECKING 0, does not.
CHECKING_DEFINE = "PBRLAB_CHECKING"
MAX_LIGHTS_PER_TYPE = 8        # capacity of each light type's arrays in the full program
MAX_SPECIALISED_PROGRAMS = 32  # past this many distinct (material x scene) feature sets:
                               # warn and render every material with the full program
LIGHT_TYPES = ("directional", "point", "spot")
# The layers beyond the Standard model, as MaterialFeatures fields (PBRLAB_<LAYER> defines)
LAYERS = ("clearcoat", "sheen", "anisotropy", "iridescence", "transmission", "specular_f90", "dielectric_specular")


@dataclass(frozen=True)
class MaterialFeatures:
    workflow: str
    alpha_mode: str
    brdf: tuple               # ((term, VARIANT), ...) sorted
    maps: tuple               # default-surface texture slots present, sorted
    srgb_maps: tuple          # those decoded from sRGB by the hardware
    emission: bool
    occlusion: bool
    alpha: bool
    custom_surface: str | None  # a surface file: every effect compiled
    # settings of the default surface (glTF materials: pbrlab/importers/gltf), compiled in both programs
    uv1_maps: tuple = ()        # slots reading the second UV set
    uv_transforms: tuple = ()   # slots with a UV transform
    normal_scale: bool = False  # normal scale != 1
    occlusion_strength: bool = False  # occlusion strength != 1
    vertex_color: bool = False
    double_sided: bool = False
    # the layers (surface_layers.material_layers: from the numbers below, or, for a surface
    # file or Unity shader, from the fields it writes)
    clearcoat: bool = False     # a coat (mask > 0): its lobe and the base's weight
    clearcoat_normal_scale: bool = False
    unlit: bool = False         # KHR_materials_unlit: albedo and alpha only
    sheen: bool = False         # a sheen (colour > 0): its lobe, table and the base's scaling
    anisotropy: bool = False    # an anisotropic base lobe (strength > 0): its mapping, lobe, bent normal
    iridescence: bool = False   # a thin film on the base (mask > 0): pbr_F_Iridescence, the base's F0
    transmission: bool = False  # the diffuse partly replaced by transmission (factor > 0): its lobes,
                                # the environment seen through, the volume's attenuation
    specular_f90: bool = False  # an explicit F90 (KHR_materials_specular's specularFactor), not F90 from F0
    dielectric_specular: bool = False  # the metallic workflow's dielectric F0 is the material's, not 0.04
    shading_normal: bool = False  # a normal map (or a surface that writes one) may tilt n from the geometric normal


@dataclass(frozen=True)
class SceneFeatures:
    directional: int
    point: int
    spot: int
    environment: bool          # indirect diffuse (SH9) and specular (prefiltered + DFG)
    energy_compensation: bool
    horizon_occlusion: bool    # render.horizon_occlusion (compiled where a material's normal can tilt)
    valid_reflection_normal: bool  # render.valid_reflection_normal (likewise)
    quality: str
    brdf_model: str            # "pbrlab" or "unity" (PBR_BRDF_MODEL)
    tonemap: str
    exposure: bool             # exposure != 0 (a multiply in the resolve pass)
    hdr_target: str
    orthographic: bool = False  # parallel projection: one view direction
    sun_shadow: bool = False   # directional light 0 is the environment's sun, shadowed (render.environment_sun)
    sky_visibility: int = 0    # K shadow maps for the environment's visibility (render.environment_visibility)
    sky_visibility_diffuse: bool = False  # ... applied to the diffuse too (render.environment_visibility_diffuse)
    volume_chord: bool = False  # a volume's path length from its back faces (render.volume_chord)
    screen_space_reflections: bool = False  # render.screen_space_reflections (screen_space_reflection.py)


def material_features(material) -> MaterialFeatures:
    custom = material.surface is not None
    layers = surface_layers.material_layers(material)  # from its numbers, or what its surface writes
    maps = tuple(sorted(material.textures)) if not custom else ()
    return MaterialFeatures(
        workflow=material.workflow,
        alpha_mode=material.alpha_mode,
        brdf=tuple(sorted(material.brdf.items())),
        maps=maps,
        srgb_maps=tuple(sorted(m for m in maps if material.texture_srgb.get(m))),
        emission=custom or bool(np.any(np.asarray(material.emission) != 0)) or "emission" in maps,
        occlusion=custom or material.occlusion != 1.0 or "occlusion" in maps,
        alpha=custom or material.alpha_mode != "opaque",
        custom_surface=str(material.surface) if custom else None,
        uv1_maps=tuple(sorted(m for m in maps if material.texture_uv_set.get(m, 0) == 1)),
        uv_transforms=tuple(sorted(m for m in maps if m in material.texture_transform)),
        normal_scale="normal" in maps and material.normal_scale != 1.0,
        occlusion_strength="occlusion" in maps and material.occlusion_strength != 1.0,
        vertex_color=material.vertex_color,
        double_sided=bool(material.double_sided),
        clearcoat="clearcoat" in layers,
        clearcoat_normal_scale="clearcoat_normal" in maps and material.clearcoat_normal_scale != 1.0,
        unlit=not custom and material.unlit,
        sheen="sheen" in layers,
        anisotropy="anisotropy" in layers,
        iridescence="iridescence" in layers,
        transmission="transmission" in layers,
        specular_f90="specular_f90" in layers,
        dielectric_specular="dielectric_specular" in layers,
        shading_normal=surface_layers.tilts_shading_normal(material),
    )


def scene_features(scene) -> SceneFeatures:
    counts = {t: sum(1 for light in scene.lights if light.type == t) for t in LIGHT_TYPES}
    return SceneFeatures(
        directional=counts["directional"], point=counts["point"], spot=counts["spot"],
        environment=scene.environment is not None,
        energy_compensation=scene.render.energy_compensation,
        horizon_occlusion=scene.render.horizon_occlusion,
        valid_reflection_normal=scene.render.valid_reflection_normal,
        sun_shadow=scene.render.environment_sun,
        sky_visibility=scene.render.environment_visibility if scene.environment is not None else 0,
        sky_visibility_diffuse=scene.render.environment_visibility_diffuse,
        volume_chord=scene.render.volume_chord,
        screen_space_reflections=scene.render.screen_space_reflections,
        quality=scene.render.quality,
        brdf_model=scene.render.brdf_model,
        tonemap=scene.render.tonemap,
        exposure=scene.render.exposure != 0.0,
        hdr_target=scene.render.hdr_target,
        orthographic=scene.camera.ortho_half_height is not None,
    )


def _settings_defines(m: MaterialFeatures, s: SceneFeatures) -> dict:
    defines = dict(glsl_defines(**dict(m.brdf)))
    defines["PBR_ALPHA_MODE"] = f"PBR_ALPHA_MODE_{m.alpha_mode.upper()}"
    defines["PBR_QUALITY"] = f"PBR_QUALITY_{s.quality.upper()}"
    defines["PBR_BRDF_MODEL"] = f"PBR_BRDF_MODEL_{s.brdf_model.upper()}"
    if not s.energy_compensation:  # else the tier's choice (pbr/shading/dispatch.glsl: LOW leaves it out)
        defines["PBR_ENERGY_COMPENSATION"] = 0
    if m.workflow == "specular":
        defines["PBRLAB_WORKFLOW_SPECULAR"] = 1
    if s.hdr_target == "rgba16f":
        defines["PBRLAB_HDR_HALF"] = 1
    if s.orthographic:
        defines["PBRLAB_ORTHOGRAPHIC"] = 1
    if s.sun_shadow and not m.unlit:
        defines["PBRLAB_SUN_SHADOW"] = 1
    if s.sky_visibility and s.environment and not m.unlit:
        defines["PBRLAB_SKY_VISIBILITY"] = s.sky_visibility
        if s.sky_visibility_diffuse:
            defines["PBRLAB_SKY_VISIBILITY_DIFFUSE"] = 1
    if s.volume_chord and m.transmission:  # render/volume_exit.py
        defines["PBRLAB_VOLUME_CHORD"] = 1
    if s.screen_space_reflections and s.environment and not m.unlit:  # render/screen_space_reflection.py
        defines["PBRLAB_SCREEN_SPACE_REFLECTION"] = 1
    for flag, on in (("NORMAL_SCALE", m.normal_scale), ("OCCLUSION_STRENGTH", m.occlusion_strength),
                     ("VERTEX_COLOR", m.vertex_color), ("DOUBLE_SIDED", m.double_sided),
                     ("CLEARCOAT", m.clearcoat), ("CLEARCOAT_NORMAL_SCALE", m.clearcoat_normal_scale),
                     ("UNLIT", m.unlit), ("SHEEN", m.sheen),
                     ("ANISOTROPY", m.anisotropy), ("IRIDESCENCE", m.iridescence),
                     ("TRANSMISSION", m.transmission), ("SPECULAR_F90", m.specular_f90),
                     ("DIELECTRIC_SPECULAR", m.dielectric_specular),
                     ("HORIZON_OCCLUSION", m.shading_normal and s.horizon_occlusion),
                     ("VALID_REFLECTION_NORMAL", m.shading_normal and s.valid_reflection_normal)):
        if on:
            defines[f"PBRLAB_{flag}"] = 1
    # A map without an exactly neutral texel (1 - (1 - s) * 1 need not equal s in float32)
    # is compiled only where the material has it, in both programs.
    for slot in m.maps:
        if slot not in FULL_MAP_SLOTS:
            defines[f"PBRLAB_{slot.upper()}_MAP"] = 1
    return defines


def specialised_defines(m: MaterialFeatures, s: SceneFeatures) -> dict:
    """Defines of the program that computes exactly this material in this scene."""
    defines = _settings_defines(m, s)
    defines.update({"PBRLAB_DIRECTIONAL_COUNT": s.directional, "PBRLAB_POINT_COUNT": s.point,
                    "PBRLAB_SPOT_COUNT": s.spot})
    if s.environment:
        defines["PBRLAB_ENV"] = 1
    for flag, on in (("EMISSION", m.emission), ("OCCLUSION", m.occlusion), ("ALPHA", m.alpha)):
        if on:
            defines[f"PBRLAB_{flag}"] = 1
    for slot in m.maps:
        defines[f"PBRLAB_{slot.upper()}_MAP"] = 1
    defines.update(_slot_code(m, m.maps))
    return defines


def _slot_code(m: MaterialFeatures, slots) -> dict:
    """The sampling and declarations of the default surface's compiled ``slots`` (texture_slots.py)."""
    return texture_slots.slot_defines(slots, m.uv1_maps, m.uv_transforms,
                                      [layer for layer in LAYERS if getattr(m, layer)])


FULL_MAP_SLOTS = ("albedo", "emission", "metallic_smoothness", "normal", "occlusion")
# Two packings of metallic and smoothness: a material has at most one (scene validation),
# and the full program of a glTF material leaves Unity's out (its neutral multiply after
# glTF's 1 - (1 - s) g lets the compiler contract differently: 1e-6 relative, measured).
FULL_MAP_EXCLUDED_BY = {"metallic_smoothness": "metallic_roughness"}


def full_defines(m: MaterialFeatures, s: SceneFeatures) -> dict:
    """Defines of the runtime-branching program: every effect compiled in."""
    defines = _settings_defines(m, s)
    defines.update({"PBRLAB_FULL": 1, "PBRLAB_ENV": 1, "PBRLAB_EMISSION": 1,
                    "PBRLAB_OCCLUSION": 1, "PBRLAB_ALPHA": 1,
                    "PBRLAB_DIRECTIONAL_COUNT": MAX_LIGHTS_PER_TYPE,
                    "PBRLAB_POINT_COUNT": MAX_LIGHTS_PER_TYPE, "PBRLAB_SPOT_COUNT": MAX_LIGHTS_PER_TYPE})
    if m.custom_surface is None:
        full_slots = [slot for slot in FULL_MAP_SLOTS if FULL_MAP_EXCLUDED_BY.get(slot) not in m.maps]
        for slot in full_slots:
            defines[f"PBRLAB_{slot.upper()}_MAP"] = 1
        defines.update(_slot_code(m, set(m.maps) | set(full_slots)))
    return defines


@dataclass
class ProgramPlan:
    """What a render compiles: one defines dict per material, and how many distinct."""
    defines: dict            # material name -> defines
    specialised: bool
    distinct: int
    checking: bool = True    # the checking programs (else the production ones: CHECKING_DEFINE)


def plan_programs(scene, specialise: bool = True, limit: int = MAX_SPECIALISED_PROGRAMS,
                  checking: bool = True) -> ProgramPlan:
    """Per material, the defines of its program; falls back to the full program for every
    material when specialisation would need more than ``limit`` programs. ``checking=False``:
    the production programs (``CHECKING_DEFINE`` 0; the checking ones leave it to the
    templates' default, 1)."""
    plan = _plan_programs(scene, specialise, limit)
    if not checking:
        plan.defines = {name: {**d, CHECKING_DEFINE: 0} for name, d in plan.defines.items()}
        plan.checking = False
    return plan


def _plan_programs(scene, specialise: bool, limit: int) -> ProgramPlan:
    s = scene_features(scene)
    per_material = {name: material_features(m) for name, m in scene.materials.items()}
    if specialise:
        defines = {name: specialised_defines(m, s) for name, m in per_material.items()}
        distinct = len({tuple(sorted(d.items())) for d in defines.values()})
        if distinct <= limit:
            return ProgramPlan(defines, True, distinct)
        warnings.warn(f"the scene needs {distinct} specialised programs, more than {limit}: "
                      "rendering every material with the full program instead", stacklevel=3)
    for light_type in LIGHT_TYPES:
        if getattr(s, light_type) > MAX_LIGHTS_PER_TYPE:
            raise SceneError(f"the full program holds at most {MAX_LIGHTS_PER_TYPE} {light_type} "
                             f"lights; the scene has {getattr(s, light_type)}")
    defines = {name: full_defines(m, s) for name, m in per_material.items()}
    return ProgramPlan(defines, False, len({tuple(sorted(d.items())) for d in defines.values()}))


def features_report(scene) -> dict:
    """The JSON `pbrlab features` prints: scene features, per-material features, and the
    programs specialisation would compile."""
    plan = plan_programs(scene)
    return {
        "scene": asdict(scene_features(scene)),
        "materials": {name: asdict(material_features(m)) for name, m in scene.materials.items()},
        "programs": {"specialised": plan.specialised, "distinct": plan.distinct,
                     "limit": MAX_SPECIALISED_PROGRAMS},
    }
