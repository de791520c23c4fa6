"""A URP shader's material (``scene.material_passes.MaterialSource``), and how the loader
recognises and reads one.

URP draws a forward pass once with every light: the main light (the scene's first
directional light) and the additional lights (every other one) are read by the program itself
(``GetMainLight``, ``GetAdditionalLight``: the stand-in Lighting.hlsl) from the scene's light
uniforms the renderer binds for every program, so a pass draws once, with no per-light
repetition (unlike the built-in pipeline's ForwardAdd). URP's pipeline keywords are set as
its default renderer sets them: ``_ADDITIONAL_LIGHTS`` (per-pixel additional lights), where
the shader declares it; no shadow, lightmap or fog keyword (there are none of those here).
"""

from __future__ import annotations

import re
from pathlib import Path

from ...scene.gbuffer_surface import WORLD_NORMALS
from ..unity import URP
from ..unity import material as unity_material
from ..unity.render_objects import BUILTIN_LIGHT_MODES
from ..unity.source_text import blank_comments

# The keywords URP's default renderer enables globally, where a shader declares them (the
# reader reads the programs' structs with them on: parse.URP.keywords).
PIPELINE_KEYWORDS = URP.keywords
_URP_TAG = re.compile(r'"RenderPipeline"\s*=\s*"Universal(?:Render)?Pipeline"')
_URP_INCLUDE = re.compile(r'#\s*include\s+"Packages/com\.unity\.render-pipelines\.universal/')


class URPSource(unity_material.UnitySource):
    """The Unity source, drawn as URP draws: its forward passes once each (its passes'
    LightMode is UniversalForward, UniversalForwardOnly or SRPDefaultUnlit, which
    unity_material.light_programs draws once), with URP's pipeline keywords. Its programs'
    _CameraNormalsTexture is URP's DepthNormals texture (world normals, DeclareNormalsTexture.hlsl)."""
    camera_normals = WORLD_NORMALS

    def defines(self, material) -> dict:
        declared = self.shader.keywords
        return {**{k: 1 for k in PIPELINE_KEYWORDS if k in declared}, **super().defines(material)}


# A Scriptable Render Pipeline's shader that names no pipeline: HLSLPROGRAM blocks only, no
# built-in .cginc included, no pass of the built-in pipeline's LightModes (render_objects'
# BUILTIN_LIGHT_MODES), as Unity's manual's custom-SRP example ("LightMode" = "ExampleLightModeTag").
_CG_BLOCK = re.compile(r"\bCG(?:PROGRAM|INCLUDE)\b")
_HLSL_BLOCK = re.compile(r"\bHLSLPROGRAM\b")
_CGINC = re.compile(r'#\s*include\s*[<"][^>"]*\.cginc[>"]')
_LIGHT_MODE = re.compile(r'"LightMode"\s*=\s*"(\w*)"', re.I)


def _srp_only(text: str) -> bool:
    return bool(_HLSL_BLOCK.search(text) and not _CG_BLOCK.search(text) and not _CGINC.search(text)
                and not any(m.lower() in BUILTIN_LIGHT_MODES for m in _LIGHT_MODE.findall(text)))


# URP's forward renderer's own LightModes (URP's manual, "ShaderLab Pass tags in URP": LightMode
# UniversalForward, UniversalForwardOnly), which the built-in pipeline never draws
_URP_FORWARD_LIGHT_MODES = frozenset(("universalforward", "universalforwardonly"))


def _urp_forward_passes(text: str) -> bool:
    """A shader naming no pipeline (or naming it otherwise than _URP_TAG reads) whose passes are
    tagged for URP's forward renderer, and none for the built-in pipeline: whatever its programs'
    language (a CGPROGRAM with UnityCG.cginc included), only URP draws it."""
    modes = {m.lower() for m in _LIGHT_MODE.findall(text)}
    return bool(modes & _URP_FORWARD_LIGHT_MODES) and not modes & BUILTIN_LIGHT_MODES


def reads(path: Path) -> bool:
    """Whether ``path`` is a URP shader: a SubShader tagged for URP, a program that includes
    URP's ShaderLibrary, a Scriptable Render Pipeline's shader naming no pipeline (_srp_only:
    URP is the SRP pbrlab draws), or a shader whose passes are tagged for URP's forward renderer
    (_urp_forward_passes)."""
    try:
        text = blank_comments(Path(path).read_text(encoding="utf-8", errors="replace"))
    except OSError:
        return False
    return bool(_URP_TAG.search(text) or _URP_INCLUDE.search(text) or _srp_only(text) or _urp_forward_passes(text))


def read_material(r, m, base: Path) -> None:
    """Fill ``m`` from a material whose surface is a URP shader (unity_material.read_material,
    for URP)."""
    unity_material.read_material(r, m, base, pipeline=URP, source_type=URPSource)
