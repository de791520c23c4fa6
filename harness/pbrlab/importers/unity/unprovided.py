"""Unity names pbrlab does not provide on purpose, each with the engine feature behind it: a
compile error that names one becomes a refusal that says what is missing, instead of a
compiler's "undeclared identifier".

    raise_named(exc, shader_path)   # inside ``except PbrlabError``: re-raise, named if one is known
"""

from __future__ import annotations

import functools
import re

from .source_text import UnityShaderError
from .undefined_calls import undefined_call, unity_library_function

# name -> the Unity feature it belongs to (docs/unity.md, "Unity shaders": what is refused and why).
UNPROVIDED = {
    # (the baked lightmap itself, unity_Lightmap/unity_LightmapST/DecodeLightmap, is the one a
    # material supplies, with its direction texture and a white shadow mask: lightmaps.py)
    # (the realtime GI lightmap itself, unity_DynamicLightmap/unity_DynamicLightmapST/
    # DecodeRealtimeLightmap, is the one a material supplies: dynamic_lightmaps.py)
    "unity_DynamicDirectionality": "directional realtime GI lightmaps (the dominant-direction texture beside "
                                   "a realtime lightmap), which a supplied realtime lightmap does not include",
    **dict.fromkeys(("UnityMetaVertexPosition", "UnityMetaFragment", "UnityMetaInput",
                     "unity_MetaVertexControl", "unity_MetaFragmentControl"),
                    "the lightmap-baking meta pass"),
    "unity_VertexLightParams": "Unity's vertex-light parameters of its legacy vertex-lit path (the light count)",
    **dict.fromkeys(("_ShadowMapTexture", "unity_WorldToShadow", "_ShadowCoord", "V2F_SHADOW_CASTER",
                     "TRANSFER_SHADOW_CASTER", "TRANSFER_SHADOW_CASTER_NORMALOFFSET", "SHADOW_CASTER_FRAGMENT",
                     "UnityApplyLinearShadowBias", "UnityClipSpaceShadowCasterPos", "UnitySampleShadowmap",
                     "UnitySampleShadowmap_PCF3x3", "UnitySampleShadowmap_PCF5x5", "UnitySampleShadowmap_PCF7x7",
                     "UnityComputeShadowFade", "UnityComputeShadowFadeDistance", "UnityGetRawBakedOcclusions",
                     "UnitySampleBakedOcclusion", "UnityMixRealtimeAndBakedShadows", "_ShadowMapTexture_TexelSize",
                     "UNITY_DECLARE_SHADOWMAP", "UNITY_SAMPLE_SHADOW", "UNITY_SAMPLE_SHADOW_PROJ",
                     "UNITY_DECLARE_SCREENSPACE_SHADOWMAP", "UNITY_SAMPLE_SCREEN_SHADOW",
                     "UNITY_DECLARE_TEXCUBE_SHADOWMAP", "UNITY_SAMPLE_TEXCUBE_SHADOW"),
                    "shadow maps and shadow-caster passes"),
    **dict.fromkeys(("UNITY_DECLARE_TEXCUBEARRAY", "UNITY_SAMPLE_TEXCUBEARRAY"),
                    "cube-map arrays as Unity declares them"),
    # (probe 0's box, unity_SpecCube0_ProbePosition/_BoxMin/_BoxMax, is the sky's, not box-projected:
    # unity_compat/shader_variables; BoxProjectedCubemapDirection is UnityStandardUtils.cginc's stand-in's)
    "unity_SpecCube1": "blended reflection probes (a second probe)",
    **dict.fromkeys(("unity_ProbeVolumeSH", "unity_ProbeVolumeWorldToObject", "SHEvalLinearL0L1_SampleProbeVolume"),
                    "light probe proxy volumes"),
    **dict.fromkeys(("_CameraDepthNormalsTexture", "DecodeDepthNormal", "_CameraMotionVectorsTexture"),
                    "the camera's depth-normals and motion-vector textures"),
    # the G-buffer's RT0..RT2 and the depth texture are rendered (render/camera_textures.py); RT3
    # (emission and ambient, the light buffer the lights add onto) is not
    "_CameraGBufferTexture3": "the G-buffer's emission and ambient target (RT3), which the harness's G-buffer pre-pass does not make",
    **dict.fromkeys(("BSpline2Left", "BSpline2Middle", "BSpline2Right", "BSpline3Leftmost", "BSpline3MiddleLeft",
                     "BSpline3MiddleRight", "BSpline3Rightmost", "BiquadraticFilter", "BicubicFilter",
                     "SampleTexture2DBicubic", "SampleTexture2DBiquadratic", "SampleTexture2DArrayBicubic",
                     "SampleTexture2DArrayBicubicLOD"),
                    "Core RP's Filtering.hlsl (B-spline bicubic and biquadratic texture filters), whose stand-in "
                    "declares none of them"),
}
_NAME = re.compile(r"\b(" + "|".join(sorted(UNPROVIDED, key=len, reverse=True)) + r")\b")


# Unity's own naming (UnityCG.cginc and friends): an unknown identifier spelled so is a Unity
# name pbrlab lacks, not a mistake of the shader's.
_UNITY_SPELLING = re.compile(r"\b(unity_\w+|UNITY_\w+|Unity[A-Z]\w+|_Camera\w*Texture\w*|SAMPLE_\w*DEPTH\w*|"
                             r"(?:Encode|Decode|Unpack|Pack)(?:DepthNormal|ViewNormalStereo|Float\w*|Heightmap))\b")
# A Unity include file pbrlab has no stand-in for: a built-in .cginc, or a file of one of
# Unity's packages (Packages/com.unity.*/...: the render pipelines' ShaderLibrary, Shader Graph).
_MISSING_INCLUDE = re.compile(r'(?:header name: |cannot find include ")([\w./-]+\.cginc|Packages/com\.unity\.[\w./-]+)')
_AT_LINE = re.compile(r"([^\s:]+\.(?:shader|cginc)):(\d+)")
# Unity's own include files by name: its packages' and the built-in pipeline's CGIncludes (their
# names begin with Unity, or are these); any other missing include is the project's own.
_UNITY_INCLUDES = {"Lighting.cginc", "AutoLight.cginc", "HLSLSupport.cginc", "Tessellation.cginc",
                   "TerrainEngine.cginc", "TerrainSplatmapCommon.cginc", "TerrainPreview.cginc",
                   "TerrainTool.cginc", "GLSLSupport.glslinc"}


def missing_include(name: str, folder=None) -> str:
    """What an unresolved ``#include "name"`` is, in a refusal's words: one of Unity's include
    files pbrlab has no stand-in for, or (any other name) the project's own file that no folder
    holds, which Unity would not find either. With the including file's ``folder``, a file of
    that name elsewhere in its repository is named (elsewhere_in_repository)."""
    base = name.rsplit("/", 1)[-1]
    if name.startswith("Packages/com.unity.") or base.startswith(("Unity", "SpeedTree")) or base in _UNITY_INCLUDES:
        return "one of Unity's include files pbrlab has no stand-in for"
    text = "an include file of the project's that no folder beside the shader or above it holds (Unity would not find it either)"
    elsewhere = elsewhere_in_repository(base, folder) if folder is not None else None
    if elsewhere is not None:
        text += (f"; a file of that name lies at {elsewhere}, where Unity does not look (it reads an include from "
                 "the including file's folder, a project path, or its own CGIncludes folder): copy it beside the shader")
    return text


def elsewhere_in_repository(base: str, folder) -> "Path | None":
    """A file named ``base`` beside the Unity project ``folder`` lies in (the nearest folder above
    it that holds ``Assets/``): in the project's parent folder or two folders below it, other
    Unity projects left out -- where an author keeps a copy of an include Unity found elsewhere
    (a Unity install's own CGIncludes folder, copied into the repository). None outside a Unity
    project, or where none is."""
    from pathlib import Path
    folder = Path(folder).resolve()
    project = next((a for a in [folder, *folder.parents] if (a / "Assets").is_dir()), None)
    if project is None:
        return None
    level = [project.parent]
    for _ in range(3):  # the parent, its folders, theirs
        for here in level:
            if (here / base).is_file():
                return here / base
        level = [sub for here in level for sub in sorted(_folders(here))
                 if sub != project and not (sub / "Assets").is_dir()]
    return None


def _folders(here):
    try:
        return [entry for entry in here.iterdir() if entry.is_dir()]
    except OSError:
        return []


@functools.lru_cache(maxsize=1)
def _provided() -> frozenset:
    """The names pbrlab's Unity layer defines (macros, uniforms, functions, structs)."""
    from .cg_types import LIBRARY_FILES, library_file
    from .source_text import PACKAGE_STAND_INS
    names = set()
    # the library's files, and the stand-ins for Unity's packages' files (URP's, Core RP's)
    paths = [library_file(rel) for rel in LIBRARY_FILES + ("templates/unity_hlsl_support.hlsl",)]
    for path in paths + sorted(PACKAGE_STAND_INS.rglob("*.hlsl")):
        if path.is_file():
            text = path.read_text(encoding="utf-8")
            names.update(re.findall(r"^[ \t]*#[ \t]*define[ \t]+(\w+)", text, re.M))
            names.update(re.findall(r"^\s*(?:uniform\s+|static\s+)?\w+\s+(\w+)\s*[;(]", text, re.M))
            names.update(re.findall(r"\bstruct\s+(\w+)", text))
    # the camera's textures the harness renders and binds to a program that declares them
    # (render/camera_textures.py): _CameraDepthTexture in the built-in pipeline too
    from ...scene.gbuffer_surface import CAMERA_TEXTURES
    names.update(CAMERA_TEXTURES)
    return frozenset(names)


def provided_names() -> frozenset:
    """The names pbrlab's Unity layer defines (_provided)."""
    return _provided()


def _unprovided_spelled(text: str):
    """The first identifier of ``text`` spelled as Unity's that pbrlab does not define."""
    provided = _provided()
    for m in _UNITY_SPELLING.finditer(text):
        if m.group(1) not in provided:
            return m.group(1)
    return None


def named_missing(message: str, shader=None):
    """(name, feature) of the first Unity name pbrlab lacks that an error line points at:
    one of UNPROVIDED, a Unity include without a stand-in, or an identifier spelled as Unity
    spells its own (named by the error, or found on the source line the error is at)."""
    for line in message.splitlines():
        if "error" not in line.lower() and "cannot find include" not in line:
            continue
        m = _NAME.search(line)
        if m:
            return m.group(1), UNPROVIDED[m.group(1)]
        m = _MISSING_INCLUDE.search(line)
        if m:
            return m.group(1), missing_include(m.group(1))
        source = _source_line(line, shader)
        m = _NAME.search(source)  # a syntax error at a line that uses one (a declaring macro)
        if m:
            return m.group(1), UNPROVIDED[m.group(1)]
        name = _unprovided_spelled(line.split("error", 1)[1] if "error" in line else "")
        if name is None:
            name = _unprovided_spelled(source)
        if name is not None:
            return name, "a Unity name pbrlab does not provide"
        break  # the first error decides: later ones follow from it
    return None


def _source_line(error_line: str, shader=None) -> str:
    """The text of the file and line an error names (``X.shader:18: error ...``; a bare
    name is ``shader``'s when it matches), or ''."""
    m = _AT_LINE.search(error_line)
    if not m:
        return ""
    from pathlib import Path
    named = Path(m.group(1))
    if shader is not None and not named.is_file() and named.name == Path(shader).name:
        named = Path(shader)
    for candidate in (named,):
        try:
            lines = candidate.read_text(encoding="utf-8", errors="replace").splitlines()
        except OSError:
            return ""
        n = int(m.group(2))
        return lines[n - 1] if 0 < n <= len(lines) else ""
    return ""


# The first error, a Unity-spelled name declared twice (glslang's HLSL "'x' : redefinition", the
# GLSL compiler's "`x' redeclared"): the shader declares a name Unity's includes declare already.
_REDECLARED = re.compile(r"error: (?:'(\w+)' : redefinition|`(\w+)' redeclared)")


def redeclared(message: str):
    """(name, "file:line" or "") of the Unity name the first error says is declared again, or None."""
    for line in message.splitlines():
        if "error" in line.lower():
            m = _REDECLARED.search(line)
            name = m and (m.group(1) or m.group(2))
            if not name or not _UNITY_SPELLING.fullmatch(name):
                return None
            at = _AT_LINE.search(line)
            return name, (f"{at.group(1).rsplit('/', 1)[-1]}:{at.group(2)}" if at else "")
    return None


def raise_named(exc: Exception, path) -> None:
    """Re-raise ``exc`` as a refusal naming the missing Unity feature when its message names one,
    or the Unity name the shader declares again (redeclared)."""
    again = redeclared(str(exc))
    if again is not None:
        name, at = again
        raise UnityShaderError(
            f"{path}: {at + ': ' if at else ''}declares {name} itself, which Unity's includes declare already (UnityShaderVariables.cginc "
            f"since Unity 5, unity_Lightmap as a Texture2D with its sampler); a shader written for Unity 4, "
            f"which declared it itself: remove the declaration "
            f"(the compiler's words follow)\n{exc}") from None
    found = named_missing(str(exc), path)
    if found is None:
        name = unity_library_function(str(exc), _provided())
        if name is not None:
            raise UnityShaderError(f"{path}: uses {name}, a Unity name pbrlab does not provide (a function of Unity's "
                                   f"URP or Core RP ShaderLibrary); pbrlab does not provide it "
                                   f"(the compiler's words follow)\n{exc}") from None
        call = undefined_call(str(exc), path, _provided())
        if call is not None:
            at, name = call
            raise UnityShaderError(
                f"{at}: calls {name}, a function that neither the shader, the files it includes nor Unity's "
                f"libraries define: the project's own code calls an undefined function, which Unity's compiler "
                f"refuses too (the compiler's words follow)\n{exc}") from None
        raise exc
    name, feature = found
    what = feature if feature.startswith(("a Unity name", "one of Unity's")) else f"part of {feature}"
    raise UnityShaderError(f"{path}: uses {name}, {what}; pbrlab does not provide it "
                           f"(the compiler's words follow)\n{exc}") from None
