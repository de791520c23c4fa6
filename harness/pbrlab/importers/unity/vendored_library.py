"""A project's own copy of a file of Unity's render-pipeline ShaderLibrary (Core RP's
``Common.hlsl``, URP's ``Core.hlsl``, ...), vendored under ``Assets/`` and included by a relative
path (``#include "../ShaderLibrary/Core.hlsl"``): pbrlab reads its stand-in for that package file
in its place, as it does for the package's own path (``Packages/com.unity.render-pipelines.*``
always resolves to the stand-ins, even where a project embeds its own copy of the package).

Why: the package's files declare what Unity's engine sets (URP's UnityInput.hlsl: the per-draw
cbuffer, ``unity_SHAr``.., ``_MainLightPosition``; Core's UnityInstancing.hlsl: the
``UNITY_MATRIX_M`` family), which pbrlab's prelude and stand-ins provide and fill from the scene;
compiled as written beside them each is a redeclaration (glslang, GLSL), and the engine's
values would not reach the copy's own declarations. The stand-in is pbrlab's reading of the same
package file.

A copy is recognised by its path below a folder named ``ShaderLibrary`` (``Common.hlsl``) or
``Shaders`` (URP's ``LitInput.hlsl``, ``LitForwardPass.hlsl``), for which a stand-in exists in
Core RP's or URP's package, and by Unity's
include guard for that file (GUARDS: the names Unity's files use, read from Unity-Technologies/
Graphics; a file of the project's own that happens to share a name keeps its own text). A copy's
files that pbrlab has no stand-in for (CommonLighting.hlsl, Sampling/*.hlsl) are compiled as written.

    stand_in = stand_in_for(path, package_stand_ins)   # the stand-in's path, or None
    own_include(stand_in, package_stand_ins)           # the include glslang reads it by
"""

from __future__ import annotations

import re
from pathlib import Path

_PACKAGES = ("com.unity.render-pipelines.core", "com.unity.render-pipelines.universal")
# Unity's include guard of each file pbrlab has a stand-in for, by its path below the package's
# ShaderLibrary/ or Shaders/ (Core RP's and URP's; one folder in a project's merged copy).
_SHADER_LIBRARY = {
    "ACES.hlsl": "__ACES__", "BSDF.hlsl": "UNITY_BSDF_INCLUDED", "Color.hlsl": "UNITY_COLOR_INCLUDED",
    "Common.hlsl": "UNITY_COMMON_INCLUDED", "CommonMaterial.hlsl": "UNITY_COMMON_MATERIAL_INCLUDED",
    "EntityLighting.hlsl": "UNITY_ENTITY_LIGHTING_INCLUDED", "Filtering.hlsl": "UNITY_FILTERING_INCLUDED",
    "ImageBasedLighting.hlsl": "UNITY_IMAGE_BASED_LIGHTING_INCLUDED", "Macros.hlsl": "UNITY_MACROS_INCLUDED",
    "Packing.hlsl": "UNITY_PACKING_INCLUDED", "Random.hlsl": "UNITY_RANDOM_INCLUDED",
    "SpaceTransforms.hlsl": "UNITY_SPACE_TRANSFORMS_INCLUDED", "UnityInstancing.hlsl": "UNITY_INSTANCING_INCLUDED",
    "Core.hlsl": "UNIVERSAL_PIPELINE_CORE_INCLUDED", "Input.hlsl": "UNIVERSAL_INPUT_INCLUDED",
    "UnityInput.hlsl": "UNIVERSAL_SHADER_VARIABLES_INCLUDED", "Lighting.hlsl": "UNIVERSAL_LIGHTING_INCLUDED",
    "Shadows.hlsl": "UNIVERSAL_SHADOWS_INCLUDED", "SurfaceInput.hlsl": "UNIVERSAL_INPUT_SURFACE_INCLUDED",
    "RealtimeLights.hlsl": "UNIVERSAL_REALTIME_LIGHTS_INCLUDED", "BRDF.hlsl": "UNIVERSAL_BRDF_INCLUDED",
    "GlobalIllumination.hlsl": "UNIVERSAL_GLOBAL_ILLUMINATION_INCLUDED",
    "DeclareDepthTexture.hlsl": "UNITY_DECLARE_DEPTH_TEXTURE_INCLUDED",
    "DeclareOpaqueTexture.hlsl": "UNITY_DECLARE_OPAQUE_TEXTURE_INCLUDED",
    "ShaderGraphFunctions.hlsl": "UNITY_GRAPHFUNCTIONS_LW_INCLUDED", "ShaderTypes.cs.hlsl": "SHADERTYPES_CS_HLSL",
}
# URP's Shaders/ folder's include files pbrlab has stand-ins for (Lit's and Unlit's)
_SHADERS = {
    "LitInput.hlsl": "UNIVERSAL_LIT_INPUT_INCLUDED", "LitForwardPass.hlsl": "UNIVERSAL_FORWARD_LIT_PASS_INCLUDED",
    "UnlitInput.hlsl": "UNIVERSAL_UNLIT_INPUT_INCLUDED",
}
# (not PostProcessing/Common.hlsl: the stand-in's is URP 12's, whose Varyings spell the texture
# coordinate ``texcoord`` where an older copy's shaders read ``uv``: the copy is compiled as written)
GUARDS = {**{f"ShaderLibrary/{k}": v for k, v in _SHADER_LIBRARY.items()},
          **{f"Shaders/{k}": v for k, v in _SHADERS.items()}}
_ROOTS = ("ShaderLibrary", "Shaders")  # the packages' two folders of include files
_GUARD = re.compile(r"\A(?:\s|//[^\n]*\n|/\*.*?\*/)*#[ \t]*ifndef[ \t]+(\w+)", re.S)


def _below_root(path: Path) -> str | None:
    """``path``'s path from its nearest folder named ShaderLibrary or Shaders (that folder's name
    first), or None."""
    for i, part in enumerate(reversed(path.parent.parts)):
        if part in _ROOTS:
            return "/".join(path.parts[len(path.parts) - 2 - i:])
    return None


def stand_in_for(path: Path, package_stand_ins: Path) -> Path | None:
    """pbrlab's stand-in read in place of ``path`` when it is a project's copy of a file of Unity's
    render-pipeline ShaderLibrary (module docstring); else None."""
    below = _below_root(Path(path))
    if below not in GUARDS:
        return None
    try:
        head = Path(path).read_text(encoding="utf-8-sig", errors="replace")[:4000]
    except OSError:
        return None
    m = _GUARD.match(head)
    if not m or m.group(1) != GUARDS[below]:
        return None
    for package in _PACKAGES:
        stand_in = Path(package_stand_ins) / "Packages" / package / below
        if stand_in.is_file():
            return stand_in
    return None


def own_include(stand_in: Path, package_stand_ins: Path) -> str:
    """The include name a copy's text is replaced by for glslang (program._vendored_copies):
    the stand-in's path from the stand-ins' folder's parent (``package_stand_ins/Packages/...``,
    read through that parent, the last of the HLSL path's include folders). Not its
    ``Packages/...`` name: glslang looks an include up in the folders of every file on the
    include stack before its -I folders, and where one of them is the project's root (a shader
    or include file beside Assets/ and Packages/) that name is the copy itself, replaced by the
    same include: glslang followed that loop until its time limit (60 s; ChillyHub's
    Unity_URP_NPR_Sample, which embeds URP 14's packages, session 47)."""
    return Path(stand_in).relative_to(Path(package_stand_ins).parent).as_posix()
