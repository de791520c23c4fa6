"""Scene-driven shader specialisation: which effects a scene can show, as compile-time
feature sets, and the #defines that select them.

Two kinds of compile-time configuration reach a program:

* settings: choices the scene makes (workflow, alpha mode, BRDF variants, quality tier,
  energy compensation, HDR target). Both the specialised and the full program compile
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
all compiled (its code decides what it writes).
"""

from __future__ import annotations

import json
import warnings
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from . import json_input
from .errors import SceneError
from .reference.shading import glsl_defines

MAX_LIGHTS_PER_TYPE = 8        # capacity of each light type's arrays in the full program
MAX_SPECIALISED_PROGRAMS = 32  # past this many distinct (material x scene) feature sets:
                               # warn and render every material with the full program
LIGHT_TYPES = ("directional", "point", "spot")


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


@dataclass(frozen=True)
class SceneFeatures:
    directional: int
    point: int
    spot: int
    environment: bool          # indirect diffuse (SH9) and specular (prefiltered + DFG)
    energy_compensation: bool
    quality: str
    tonemap: str
    exposure: bool             # exposure != 0 (a multiply in the resolve pass)
    hdr_target: str


def material_features(material) -> MaterialFeatures:
    custom = material.surface is not None
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
    )


def scene_features(scene) -> SceneFeatures:
    counts = {t: sum(1 for light in scene.lights if light.type == t) for t in LIGHT_TYPES}
    return SceneFeatures(
        directional=counts["directional"], point=counts["point"], spot=counts["spot"],
        environment=scene.environment is not None,
        energy_compensation=scene.render.energy_compensation,
        quality=scene.render.quality,
        tonemap=scene.render.tonemap,
        exposure=scene.render.exposure != 0.0,
        hdr_target=scene.render.hdr_target,
    )


def _settings_defines(m: MaterialFeatures, s: SceneFeatures) -> dict:
    defines = dict(glsl_defines(**dict(m.brdf)))
    defines["PBR_ALPHA_MODE"] = f"PBR_ALPHA_MODE_{m.alpha_mode.upper()}"
    defines["PBR_QUALITY"] = f"PBR_QUALITY_{s.quality.upper()}"
    defines["PBR_ENERGY_COMPENSATION"] = int(s.energy_compensation)
    if m.workflow == "specular":
        defines["PBRLAB_WORKFLOW_SPECULAR"] = 1
    if s.hdr_target == "rgba16f":
        defines["PBRLAB_HDR_HALF"] = 1
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
    return defines


FULL_MAP_SLOTS = ("albedo", "emission", "metallic_smoothness", "normal", "occlusion")


def full_defines(m: MaterialFeatures, s: SceneFeatures) -> dict:
    """Defines of the runtime-branching program: every effect compiled in."""
    defines = _settings_defines(m, s)
    defines.update({"PBRLAB_FULL": 1, "PBRLAB_ENV": 1, "PBRLAB_EMISSION": 1,
                    "PBRLAB_OCCLUSION": 1, "PBRLAB_ALPHA": 1,
                    "PBRLAB_DIRECTIONAL_COUNT": MAX_LIGHTS_PER_TYPE,
                    "PBRLAB_POINT_COUNT": MAX_LIGHTS_PER_TYPE, "PBRLAB_SPOT_COUNT": MAX_LIGHTS_PER_TYPE})
    if m.custom_surface is None:
        for slot in FULL_MAP_SLOTS:
            defines[f"PBRLAB_{slot.upper()}_MAP"] = 1
    return defines


@dataclass
class ProgramPlan:
    """What a render compiles: one defines dict per material, and how many distinct."""
    defines: dict            # material name -> defines
    specialised: bool
    distinct: int


def plan_programs(scene, specialise: bool = True, limit: int = MAX_SPECIALISED_PROGRAMS) -> ProgramPlan:
    """Per material, the defines of its program; falls back to the full program for every
    material when specialisation would need more than ``limit`` programs."""
    s = scene_features(scene)
    per_material = {name: material_features(m) for name, m in scene.materials.items()}
    if specialise:
        defines = {name: specialised_defines(m, s) for name, m in per_material.items()}
        distinct = len({tuple(sorted(d.items())) for d in defines.values()})
        if distinct <= limit:
            return ProgramPlan(defines, True, distinct)
        warnings.warn(f"the scene needs {distinct} specialised programs, more than {limit}: "
                      "rendering every material with the full program instead", stacklevel=2)
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


# --- glTF 2.0 -------------------------------------------------------------------------

def _gltf_document(path: Path) -> dict:
    """The JSON of a .gltf, or the JSON chunk of a .glb (glTF 2.0 spec, section 4.4),
    through the same gate as scene files (json_input: duplicate keys, non-finite numbers)."""
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise SceneError(f"{path}: cannot read: {exc.strerror or exc}") from None
    if data[:4] == b"glTF":
        length = int.from_bytes(data[12:16], "little")
        if data[16:20] != b"JSON":
            raise SceneError(f"{path}: the first GLB chunk is not JSON")
        data = data[20:20 + length]
    try:
        text = data.decode("utf-8")
        document = json.loads(text, object_pairs_hook=json_input._pairs_hook,
                              parse_constant=json_input._constant)
    except UnicodeDecodeError:
        raise SceneError(f"{path}: not a readable glTF 2.0 file (its JSON is not UTF-8 text)") from None
    except json.JSONDecodeError as exc:
        raise SceneError(f"{path}: not a readable glTF 2.0 file (invalid JSON at line "
                         f"{exc.lineno}, column {exc.colno}: {exc.msg})") from None
    except RecursionError:
        raise SceneError(f"{path}: not a readable glTF 2.0 file (JSON nested too deeply)") from None
    document = json_input.normalize(document, str(path))
    if not isinstance(document, dict):
        raise SceneError(f"{path}: a glTF document is a JSON object, got {type(document).__name__}")
    return document


def _gltf_field(value, kind, path: Path, where: str, default):
    """``value`` if it has JSON type ``kind`` (absent: ``default``), else SceneError naming it."""
    if value is None:
        return default
    if not isinstance(value, kind) or isinstance(value, bool) and kind is not bool:
        names = {dict: "an object", list: "an array", str: "a string"}
        raise SceneError(f"{path}: {where}: expected {names.get(kind, kind.__name__)}, "
                         f"got {json.dumps(value)[:60]}")
    return value


def gltf_features(path) -> dict:
    """Feature sets of a glTF 2.0 file: materials as trimesh reads them, lights from
    KHR_lights_punctual (which trimesh does not read). glTF's metallic-roughness model maps
    to the metallic workflow; its metallicRoughnessTexture packs roughness in G and
    metallic in B (not Unity's R/A packing), recorded as its channels. Every field read is
    type-checked (SceneError naming its path: ``materials[0].alphaMode``)."""
    import trimesh

    path = Path(path)
    if not path.is_file():
        raise SceneError(f"{path}: no such glTF file")
    document = _gltf_document(path)
    extensions = _gltf_field(document.get("extensions"), dict, path, "extensions", {})
    punctual = _gltf_field(extensions.get("KHR_lights_punctual"), dict, path,
                           "extensions.KHR_lights_punctual", {})
    lights = _gltf_field(punctual.get("lights"), list, path, "extensions.KHR_lights_punctual.lights", [])
    for i, light in enumerate(lights):
        where = f"extensions.KHR_lights_punctual.lights[{i}]"
        _gltf_field(light, dict, path, where, {})
        if light.get("type") not in LIGHT_TYPES:
            raise SceneError(f"{path}: {where}.type: expected one of {', '.join(LIGHT_TYPES)}, "
                             f"got {json.dumps(light.get('type'))}")
    counts = {t: sum(1 for light in lights if light.get("type") == t) for t in LIGHT_TYPES}
    materials = {}
    for index, spec in enumerate(_gltf_field(document.get("materials"), list, path, "materials", [])):
        where = f"materials[{index}]"
        spec = _gltf_field(spec, dict, path, where, {})
        name = _gltf_field(spec.get("name"), str, path, f"{where}.name", f"material_{index}")
        pbr = _gltf_field(spec.get("pbrMetallicRoughness"), dict, path, f"{where}.pbrMetallicRoughness", {})
        maps, channels = [], {}
        if "baseColorTexture" in pbr:
            maps.append("albedo")
            channels["albedo"] = "RGBA, sRGB"
        if "metallicRoughnessTexture" in pbr:
            maps.append("metallic_roughness")
            channels["metallic_roughness"] = "G roughness, B metallic, linear"
        for key, slot, what in (("normalTexture", "normal", "RGB tangent space, linear"),
                                ("occlusionTexture", "occlusion", "R, linear"),
                                ("emissiveTexture", "emission", "RGB, sRGB")):
            if key in spec:
                maps.append(slot)
                channels[slot] = what
        emissive = _gltf_field(spec.get("emissiveFactor"), list, path, f"{where}.emissiveFactor", [0, 0, 0])
        if len(emissive) != 3 or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                         for v in emissive):
            raise SceneError(f"{path}: {where}.emissiveFactor: expected 3 numbers, got {json.dumps(emissive)}")
        modes = {"OPAQUE": "opaque", "MASK": "cutout", "BLEND": "fade"}
        mode = spec.get("alphaMode", "OPAQUE")
        if not isinstance(mode, str) or mode not in modes:
            raise SceneError(f"{path}: {where}.alphaMode: expected one of {', '.join(modes)}, "
                             f"got {json.dumps(mode)}")
        alpha_mode = modes[mode]
        materials[name] = {
            "workflow": "metallic",
            "alpha_mode": alpha_mode,
            "maps": sorted(maps),
            "channels": channels,
            "srgb_maps": sorted(m for m in maps if m in ("albedo", "emission")),
            # glTF multiplies the emissive texture by emissiveFactor (default 0): both needed
            "emission": any(v != 0 for v in emissive),
            "occlusion": "occlusionTexture" in spec,
            "alpha": alpha_mode != "opaque",
        }
    try:
        loaded = trimesh.load(path, force="scene")
    except Exception as exc:  # trimesh raises many types for broken files (a missing .bin: OSError)
        raise SceneError(f"{path}: trimesh cannot read this glTF ({type(exc).__name__}: {exc})") from None
    return {
        "scene": {"directional": counts["directional"], "point": counts["point"], "spot": counts["spot"],
                  "environment": False, "meshes": len(loaded.geometry)},
        "materials": materials,
    }
