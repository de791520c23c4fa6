"""Which layers beyond the Standard model a material has: the layers its program compiles.

One rule per kind of material, one answer (a set of ``LAYER_FIELDS`` keys, the
``features.MaterialFeatures`` fields of the same names):

* a JSON or glTF material (the default surface): the layers its numbers turn on (a coat's
  mask, a sheen's colour, an anisotropy's strength, a film's mask, a transmission above 0;
  glTF multiplies each by its texture, so 0 is none);
* a material with a ``surface`` file, or a Unity surface shader (``#pragma surface surf
  StandardLayered``): the layers whose ``SurfaceOutputStandardLayers`` fields the surface
  **writes** (assigns with ``=``, ``+=``, ... , or assigns a swizzle of) anywhere in its text
  or the files it includes from its own folder (not the library's, whose helpers copy every
  field), comments removed. A layer compiled in is one the surface writes;
  a surface that writes none compiles none of the layer code. The field names are URP's and
  pbrlab's own, so a write is found by name whatever the struct variable is called.

A surface file that writes layers fills them in a second parameter of its surface function,
``void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers layers)``
(docs/shading.md); the two mismatches (layers written with no such parameter, the parameter
with no layer written) are refused by name, as is an HLSL twin that writes other layers
than the GLSL file the scene names.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..foundation.errors import SceneError
from ..gpu.surface_bindings import surface_sources

# SurfaceOutputStandardLayers' fields (glsl/pbr/unity/surface_layers.glsl), by the layer they feed
LAYER_FIELDS = {
    "clearcoat": ("ClearCoatMask", "ClearCoatSmoothness", "ClearCoatNormal"),
    "sheen": ("SheenColor", "SheenSmoothness"),
    "anisotropy": ("Anisotropy", "AnisotropyDirection"),
    "iridescence": ("IridescenceMask", "IridescenceIor", "IridescenceThickness"),
    "transmission": ("Transmission", "Thickness", "AttenuationColor", "AttenuationDistance", "TransmissionIor"),
    "specular_f90": ("SpecularF90",),
    "dielectric_specular": ("DielectricSpecular",),
}
LAYER_OF_FIELD = {f: layer for layer, fields in LAYER_FIELDS.items() for f in fields}
FIELD_SIZES = {f: 3 if f in ("ClearCoatNormal", "SheenColor", "AnisotropyDirection", "AttenuationColor",
                              "DielectricSpecular") else 1
               for f in LAYER_OF_FIELD}  # components: vec3 or float
# `.Field =`, `.Field *=`, `.Field.rgb =` ... but not `.Field ==`
_WRITE = re.compile(r"\.\s*(" + "|".join(sorted(LAYER_OF_FIELD, key=len, reverse=True)) +
                    r")\b(?:\s*\.\s*[xyzwrgba]{1,4}\b)?\s*[-+*/]?=(?!=)")
_SURF = re.compile(r"\bvoid\s+surf\s*\(([^)]*)\)")
# a write of a shading normal: `.Normal =`, `.ClearCoatNormal.xy +=` ... (not `.worldNormal =`)
_NORMAL_WRITE = re.compile(r"\.\s*(?:Normal|ClearCoatNormal)\b(?:\s*\.\s*[xyzwrgba]{1,4}\b)?\s*[-+*/]?=(?!=)")
LAYERS_PARAMETER = "inout SurfaceOutputStandardLayers layers"


def written_layers(text: str) -> frozenset:
    """The layers whose fields ``text`` (comments removed) assigns."""
    return frozenset(LAYER_OF_FIELD[m.group(1)] for m in _WRITE.finditer(text))


def json_layers(material) -> frozenset:
    """The layers a default-surface material's numbers turn on."""
    on = {"clearcoat": material.clearcoat > 0.0, "sheen": max(material.sheen_color) > 0.0,
          "anisotropy": material.anisotropy_strength > 0.0, "iridescence": material.iridescence > 0.0,
          "transmission": material.transmission > 0.0, "specular_f90": material.specular_f90 is not None,
          "dielectric_specular": material.dielectric_specular is not None}
    return frozenset(layer for layer, yes in on.items() if yes)


def surface_file_layers(surface: Path) -> frozenset:
    """The layers a surface file writes; SceneError when its surf function's parameters and
    its writes disagree."""
    texts = surface_sources(surface)
    layers = frozenset().union(*(written_layers(t) for t in texts))
    signature = next((m for t in texts for m in _SURF.finditer(t)), None)
    takes = signature is not None and "SurfaceOutputStandardLayers" in signature.group(1)
    if layers and not takes:
        fields = sorted({m.group(1) for t in texts for m in _WRITE.finditer(t)})
        raise SceneError(f"{surface}: writes {', '.join(fields)} (layers beyond SurfaceOutputStandard), "
                         "so its surface function takes them as a third parameter: "
                         f"void surf(Input IN, inout SurfaceOutputStandard o, {LAYERS_PARAMETER})")
    if takes and not layers:
        raise SceneError(f"{surface}: surf takes SurfaceOutputStandardLayers but writes none of its fields "
                         f"({', '.join(LAYER_OF_FIELD)}); remove the parameter, or write the layer it is for")
    return layers


def material_layers(material) -> frozenset:
    """The layers ``material``'s program compiles (module doc)."""
    if material.surface is None:
        return json_layers(material)
    own = material.source.layers(material) if material.source is not None else None
    if own is not None:  # a shader of its own (scene.material_passes): the layers it compiles
        return own
    return surface_file_layers(material.surface)


def tilts_shading_normal(material) -> bool:
    """Whether ``material``'s shading normal may leave its geometric normal (the horizon
    occlusion of scene_lighting.inc is compiled in then): a default-surface material with a
    normal or coat-normal map, a surface file that writes Normal or ClearCoatNormal, and a
    shader of its own (a Unity surface shader: its surf may)."""
    if material.surface is None:
        return bool({"normal", "clearcoat_normal"} & set(material.textures))
    if material.source is not None and material.source.layers(material) is not None:
        return True
    return any(_NORMAL_WRITE.search(t) for t in surface_sources(material.surface))


def check_twins(scene, surfaces: dict) -> None:
    """SceneError when a surface file's twin in the render's language (``surfaces``: material
    name -> file) writes other layers than the file the scene names: the program's layers
    are the named file's."""
    for name, material in scene.materials.items():
        twin = surfaces.get(name)
        if twin is None or material.source is not None or twin == material.surface:
            continue
        named, other = surface_file_layers(material.surface), surface_file_layers(twin)
        if named != other:
            raise SceneError(f"{scene.source}: materials.{name}: {twin.name} writes the layers "
                             f"{sorted(other) or 'none'}, {material.surface.name} writes {sorted(named) or 'none'}; "
                             "a surface's twins write the same layers")
