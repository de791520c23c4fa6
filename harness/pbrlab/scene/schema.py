"""The JSON Schema (draft 2020-12) of scene files, written from the parser's own tables.

``scene_schema()`` builds it from scene_fields.py (every field's type, default, bounds and
meaning) and the parser's other tables (texture slots, BRDF selectors, mesh primitives'
parameters); ``pbrlab schema`` prints it and the docs' scene-file reference is rendered
from it (scripts/mkdocs_hooks.py). Editors that read JSON Schema validate and complete a
scene with it. The parser (scene.py) stays the authority and names the field in its
messages; what it checks beyond the schema is ``PARSER_ONLY_RULES``.
tests/scene/test_scene_schema.py checks that both accept every committed scene and refuse
the same invalid ones.
"""

from __future__ import annotations

import math

from ..foundation.version import __version__
from ..foundation.json_input import FLOAT32_MAX
from .fields import (CAMERA, DEFAULT_SURFACE_LAYER_KEYS, ENVIRONMENT, LIGHT, LIGHT_TYPES, MATERIAL, RENDER, REQUIRED, SPHERE, TRANSFORM, TRANSMISSION_KEYS, Choice, File, Flag, Integers, Number, Scale, Vector)

DIALECT = "https://json-schema.org/draft/2020-12/schema"

# What scene.py refuses that a JSON Schema cannot say (or says only at great length): the
# docs list these under the schema's tables.
PARSER_ONLY_RULES = (
    "Files (`environment.path`, `surface`, `textures`, `mesh`, `gltf`) must exist and be readable; "
    "relative paths resolve against the scene file's folder.",
    "An object's `material` must name one of `materials` (or a glTF object's own).",
    "The camera's `position` and `target` differ, and `up` is not parallel to the view direction.",
    "A spot light's `inner_cone_deg` is smaller than its `outer_cone_deg`.",
    "A material whose `surface` is a Unity surface shader (`.shader`, or text with "
    "`#pragma surface`) takes `properties` and `keywords` (the shader's own) and none of the "
    "default surface's fields; a GLSL surface file's own textures are `{\"path\", \"srgb\"}` objects.",
    "A layer's texture needs its layer: the transmission and thickness maps a `transmission` "
    "(and `thickness`) above 0, the iridescence maps an `iridescence` above 0, the anisotropy map an "
    "`anisotropy_strength` above 0; one of the `metallic_smoothness` and `metallic_roughness` packings.",
    "`render.brdf_model` `unity` takes no anisotropic, iridescent or transmissive material, and none with "
    "`specular_f90` or `dielectric_specular`.",
    "`specular_f90` is at least every channel of the dielectric's F0: `specular` (the specular workflow) or "
    "`dielectric_specular` (the metallic workflow; absent: 0.04).",
    "`camera.size` takes whole numbers written without a fraction (JSON Schema's integer admits `512.0`).",
    "`render.antialias` is written without a fraction (a JSON Schema enum admits `4.0` for `4`); a count "
    "the scene admits but the GL does not take (llvmpipe: 1 or 4) is refused before rendering.",
    "No key twice in one object, no nesting deeper than 32 levels (pbrlab.foundation.json_input).",
)


def _bounded(lo: float, hi: float, lo_open: bool = False) -> dict:
    """A number's bounds; beyond float32 (the GPU's) nothing is admitted (pbrlab.foundation.json_input)."""
    out = {"type": "number"}
    out["exclusiveMinimum" if lo_open else "minimum"] = lo if math.isfinite(lo) else -FLOAT32_MAX
    out["maximum"] = hi if math.isfinite(hi) else FLOAT32_MAX
    return out


def _with_default(schema: dict, spec) -> dict:
    default = spec.default
    if default is not REQUIRED and default is not None and not (isinstance(default, float) and math.isinf(default)):
        schema["default"] = default  # +inf (no range, no attenuation) and None (F90 from F0) are JSON's absence
    return {"description": spec.doc, **schema}


def field_schema(spec) -> dict:
    """One field of scene_fields' tables as a JSON Schema."""
    if isinstance(spec, Number):
        return _with_default(_bounded(spec.lo, spec.hi, spec.lo_open), spec)
    if isinstance(spec, Vector):
        schema = {"type": "array", "items": _bounded(spec.lo, spec.hi), "minItems": spec.n, "maxItems": spec.n}
        if spec.nonzero:
            schema["not"] = {"items": {"const": 0}}  # not every component 0
        return _with_default(schema, spec)
    if isinstance(spec, Choice):
        return _with_default({"enum": list(spec.options)}, spec)
    if isinstance(spec, Flag):
        return _with_default({"type": "boolean"}, spec)
    if isinstance(spec, Integers):
        return _with_default({"type": "array", "items": {"type": "integer", "minimum": spec.lo, "maximum": spec.hi},
                              "minItems": spec.n, "maxItems": spec.n}, spec)
    if isinstance(spec, Scale):
        positive = {"type": "number", "exclusiveMinimum": 0, "maximum": FLOAT32_MAX}
        return _with_default({"oneOf": [positive, {"type": "array", "items": positive, "minItems": 3,
                                                   "maxItems": 3}]}, spec)
    if isinstance(spec, File):
        return _with_default({"type": "string", "minLength": 1}, spec)
    raise TypeError(f"no schema for {spec!r}")


def _object(table: dict, required=None, **extra) -> dict:
    required = [k for k, s in table.items() if s.default is REQUIRED and not s.only] if required is None else required
    out = {"type": "object", "properties": {k: field_schema(s) for k, s in table.items()},
           "additionalProperties": False}
    if required:
        out["required"] = required
    out.update(extra)
    return out


def _light() -> dict:
    """Per type: its own fields required where they have no default, the others' refused."""
    rules = []
    for kind in LIGHT_TYPES:
        own = [k for k, s in LIGHT.items() if s.only and kind in s.only]
        others = [k for k, s in LIGHT.items() if s.only and kind not in s.only]
        then = {"required": [k for k in own if LIGHT[k].default is REQUIRED]}
        if others:
            then["properties"] = {k: False for k in others}
        rules.append({"if": {"properties": {"type": {"const": kind}}}, "then": then})
    return _object(LIGHT, allOf=rules)


def _environment() -> dict:
    return {"oneOf": [{"type": "null"},
                      _object(ENVIRONMENT, required=[], oneOf=[{"required": ["color"]}, {"required": ["path"]}])]}


def _material(texture_slots, brdf_terms) -> dict:
    material = _object(MATERIAL)
    material["properties"].update({
        "surface": {"description": "A GLSL file with a Unity-style surf(Input, inout SurfaceOutputStandard) "
                                   "(with a third parameter, inout SurfaceOutputStandardLayers, to write the layers), "
                                   "or a Unity surface shader (.shader, or text with #pragma surface).",
                    "type": "string", "minLength": 1},
        "textures": {"description": "Slot -> image file, or -> {\"path\", \"srgb\"} (any sampler a surface "
                                    "file declares). The default surface's slots, sRGB colour or linear data: "
                                    + ", ".join(f"{slot} ({'sRGB' if kind == 'srgb' else 'linear'})"
                                                for slot, kind in texture_slots.items()) + ".",
                     "type": "object",
                     "additionalProperties": {"oneOf": [
                         {"type": "string", "minLength": 1},
                         {"type": "object", "properties": {"path": {"type": "string", "minLength": 1},
                                                           "srgb": {"type": "boolean"}},
                          "required": ["path", "srgb"], "additionalProperties": False}]}},
        "brdf": {"description": "Per-term variants (the library's PBR_SPECULAR_* / PBR_DIFFUSE_* selectors, lower "
                                "case): " + "; ".join(f"{term}: {', '.join(v.lower() for v in options)}"
                                                       for term, options in brdf_terms.items()) + ".",
                 "type": "object", "additionalProperties": False,
                 "properties": {term: {"enum": [v.lower() for v in options]}
                                for term, options in brdf_terms.items()}},
        "properties": {"description": "A Unity surface shader's Properties, overridden by name.",
                       "type": "object"},
        "keywords": {"description": "The Unity shader keywords to enable (its multi_compile / shader_feature).",
                     "type": "array", "items": {"type": "string"}},
        "lightmap": {"description": "A Unity shader's baked lightmap, supplied (the harness bakes none): the image "
                                    "(unity_Lightmap), scale_offset (unity_LightmapST: scale xy, offset zw of the "
                                    "mesh's second UV set) and encoding (full_hdr: default for .exr/.hdr; rgbm: "
                                    "default for others; dldr). Sets LIGHTMAP_ON where a pass declares it.",
                     "type": "object", "additionalProperties": False, "required": ["path"],
                     "properties": {"path": {"type": "string", "minLength": 1},
                                    "scale_offset": {"type": "array", "items": {"type": "number"},
                                                     "minItems": 4, "maxItems": 4},
                                    "encoding": {"enum": ["full_hdr", "rgbm", "dldr"]}}},
        "dynamic_lightmap": {"description": "A Unity shader's realtime GI (Enlighten) lightmap, supplied (the harness "
                                            "runs no Enlighten): an HDR image (.exr/.hdr: Unity's RGB9E5 output, "
                                            "unity_DynamicLightmap) and scale_offset (unity_DynamicLightmapST: "
                                            "scale xy, offset zw of the realtime lightmap UVs, TEXCOORD2: the mesh's "
                                            "lightmap UVs, its second UV set). Sets DYNAMICLIGHTMAP_ON where a pass "
                                            "declares it.",
                             "type": "object", "additionalProperties": False, "required": ["path"],
                             "properties": {"path": {"type": "string", "minLength": 1},
                                            "scale_offset": {"type": "array", "items": {"type": "number"},
                                                             "minItems": 4, "maxItems": 4}}},
    })
    material["allOf"] = [
        # the workflow's own F0 field: metallic or specular, not the other's
        {"if": {"properties": {"workflow": {"const": "specular"}}, "required": ["workflow"]},
         "then": {"properties": {"metallic": False, "dielectric_specular": False}},
         "else": {"properties": {"specular": False}}},
        # the default surface's slots only, unless a surface file declares its own samplers
        {"if": {"not": {"required": ["surface"]}},
         "then": {"properties": {"textures": {"propertyNames": {"enum": list(texture_slots)}}}}},
        # the layers belong to the default surface
        {"if": {"required": ["surface"]},
         "then": {"properties": {k: False for k in DEFAULT_SURFACE_LAYER_KEYS}}},
    ]
    # the volume's fields mean something only with a transmission above 0
    material["dependentSchemas"] = {k: {"required": ["transmission"],
                                        "properties": {"transmission": {"exclusiveMinimum": 0}}}
                                    for k in TRANSMISSION_KEYS[1:]}
    material["dependentRequired"] = {"properties": ["surface"], "keywords": ["surface"], "lightmap": ["surface"],
                                    "dynamic_lightmap": ["surface"]}
    return material


def _primitive(parameters: dict, integer_parameters: dict) -> dict:
    kinds = []
    for kind, defaults in parameters.items():
        props = {"primitive": {"const": kind}}
        for name, default in defaults.items():
            if name in integer_parameters:
                lo, hi = integer_parameters[name]
                props[name] = {"type": "integer", "minimum": lo, "maximum": hi, "default": default}
            else:
                props[name] = {"type": "number", "exclusiveMinimum": 0, "maximum": FLOAT32_MAX, "default": default}
        kinds.append({"type": "object", "properties": props, "required": ["primitive"],
                      "additionalProperties": False})
    return {"description": "A generated mesh: the primitive and its sizes.", "oneOf": kinds}


def _objects() -> dict:
    material = {"description": "The name of one of `materials`.", "type": "string"}
    transform = {"$ref": "#/$defs/transform"}
    return {
        "sphere_object": {"description": "An analytic sphere, ray-traced per pixel.", "type": "object",
                          "properties": {"sphere": {"$ref": "#/$defs/sphere"}, "material": material},
                          "required": ["sphere", "material"], "additionalProperties": False},
        "mesh_object": {"description": "A rasterised mesh: a file trimesh reads, or a primitive.",
                        "type": "object",
                        "properties": {"mesh": {"oneOf": [{"description": "A mesh file (.obj, .ply, .stl, ...).",
                                                           "type": "string", "minLength": 1},
                                                          {"$ref": "#/$defs/primitive"}]},
                                       "material": material, "transform": transform},
                        "required": ["mesh", "material"], "additionalProperties": False},
        "gltf_object": {"description": "A whole glTF scene (nodes, materials, lights, camera), placed by "
                                       "the transform; its camera serves when the scene has none.",
                        "type": "object",
                        "properties": {"gltf": {"description": "A .gltf or .glb file.", "type": "string",
                                                "minLength": 1},
                                       "transform": transform,
                                       "time": {"description": "Sample an animation at this time in seconds "
                                                               "(default: the nodes as written).",
                                                "type": "number"},
                                       "animation": {"description": "The animation sampled: an index, a name, or "
                                                                    "\"all\" for every one together (default: "
                                                                    "the first).",
                                                     "oneOf": [{"type": "integer", "minimum": 0},
                                                               {"type": "string", "minLength": 1}]}},
                        "required": ["gltf"], "additionalProperties": False},
    }


def scene_schema() -> dict:
    """The scene format as a JSON Schema (draft 2020-12)."""
    from .meshes import INTEGER_PARAMETERS, PRIMITIVE_PARAMETERS
    from .model import BRDF_TERMS, TEXTURE_SLOTS

    defs = {
        "camera": _object(CAMERA, description="The view; may be left out when a gltf object brings a camera."),
        "light": _light(),
        "environment": _environment(),
        "material": _material(TEXTURE_SLOTS, BRDF_TERMS),
        "sphere": _object(SPHERE, description="Its centre and radius."),
        "primitive": _primitive(PRIMITIVE_PARAMETERS, INTEGER_PARAMETERS),
        "transform": _object(TRANSFORM, description="Scale, then rotate (X, Y, Z), then translate."),
        **_objects(),
        "render": _object(RENDER),
    }
    defs["light"]["description"] = "A punctual light (KHR_lights_punctual's three kinds)."
    defs["environment"]["description"] = "Image-based light: none, a constant radiance or an equirectangular image."
    defs["material"]["description"] = "The default surface's fields, a surface file, or a Unity surface shader."
    defs["render"]["description"] = "How the image is rendered and written."
    return {
        "$schema": DIALECT,
        "title": "pbrlab scene",
        "description": f"A pbrlab scene file (pbrlab {__version__}). Relative paths resolve against the "
                       "scene file's folder.",
        "type": "object",
        "properties": {
            "camera": {"description": "The view (required unless a gltf object brings a camera).",
                       "$ref": "#/$defs/camera"},
            "lights": {"description": "Punctual lights; none by default.", "type": "array",
                       "items": {"$ref": "#/$defs/light"}},
            "environment": {"description": "Image-based light; none by default (a black background either way).",
                            "$ref": "#/$defs/environment"},
            "materials": {"description": "Materials by name.", "type": "object",
                          "additionalProperties": {"$ref": "#/$defs/material"}},
            "objects": {"description": "Spheres, meshes and glTF scenes: at least one.", "type": "array",
                        "minItems": 1,
                        "items": {"oneOf": [{"$ref": "#/$defs/sphere_object"}, {"$ref": "#/$defs/mesh_object"},
                                            {"$ref": "#/$defs/gltf_object"}]}},
            "render": {"description": "Tier, tone mapping, exposure.", "$ref": "#/$defs/render"},
        },
        "required": ["objects"],
        "additionalProperties": False,
        # the camera may come from a glTF object instead
        "if": {"not": {"properties": {"objects": {"contains": {"required": ["gltf"]}}}}},
        "then": {"required": ["camera"]},
        "$defs": defs,
    }
