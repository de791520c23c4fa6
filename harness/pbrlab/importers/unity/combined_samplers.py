"""A sampler-state declaration that a program samples as a Cg combined sampler, spelled as one
before either language compiles it (lines kept):

    SAMPLER(_CameraColorTexture);              // Core RP's macro: SamplerState _CameraColorTexture
    float4 c = tex2D(_CameraColorTexture, uv); // Cg's intrinsic: a sampler2D's

Unity compiles Direct3D programs with FXC's backwards-compatibility mode, in which the legacy
``sampler`` type (the same type as SamplerState) handed to ``tex2D`` and its kin is a DX9
combined sampler: the compiler gives it a texture register beside its sampler register, and
Unity binds the texture of that name to it (the URP shaders of the development sample that
read the camera's colour and depth through such a declaration draw in Unity so). glslang's HLSL
front end and GLSL have no such type: the declaration is spelled ``sampler2D name`` there, the
form pbrlab's Unity layer already takes in both (a texture and its sampler). Only a name that a
Cg sampling intrinsic takes as its first argument is so spelled; a sampler state used with a
texture object's methods (``t.Sample(name, uv)``) is left as it is.

    text = combined_samplers.spelled(text)   # cg_spellings.respelled, both languages
"""

from __future__ import annotations

import re

# the Cg intrinsics that take a combined sampler first (HLSL's DX9 forms that Unity's Cg uses)
_CG_SAMPLING = re.compile(r"\b(?:tex2D|tex2Dlod|tex2Dbias|tex2Dgrad|tex2Dproj)\s*\(\s*(\w+)\s*,")
# a global sampler-state declaration: Core RP's SAMPLER(name) or HLSL's SamplerState / sampler
_SAMPLER_STATE = re.compile(r"(?<![\w.])(?:SAMPLER\s*\(\s*(\w+)\s*\)|(?:SamplerState|sampler)\s+(\w+)\s*(?=;))")


def spelled(text: str) -> str:
    """``text`` with each sampler-state declaration whose name a Cg sampling intrinsic takes
    written ``sampler2D name``."""
    sampled = set(_CG_SAMPLING.findall(text))
    if not sampled:
        return text

    def spell(m):
        name = m.group(1) or m.group(2)
        if name not in sampled:
            return m.group(0)
        return f"sampler2D {name}"
    return _SAMPLER_STATE.sub(spell, text)
