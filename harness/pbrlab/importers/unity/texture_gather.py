"""The GLSL extensions a ported Unity program's gathers need (Core RP's ``GATHER_TEXTURE2D``,
``GATHER_RED_TEXTURE2D`` .. ``GATHER_ALPHA_TEXTURE2D`` and their ``_X`` forms, which port.py
spells as GLSL's ``textureGather(t, uv, channel)``).

Why: pbrlab's GLSL is ``#version 330 core``; ``textureGather`` is GLSL 4.00's, which 3.30 takes
with ``GL_ARB_texture_gather``, and its channel argument with ``GL_ARB_gpu_shader5`` (the
extensions' specifications: texture_gather adds the function reading the first channel,
gpu_shader5 the ``comp`` argument). Mesa's drivers (llvmpipe included) have both. They are
enabled only in a stage that calls ``textureGather``: gpu_shader5 also adds implicit
conversions (int to uint) that would change other programs' overload choices.

    source = with_gather_extensions(source)   # a shaders.Source, its text after #version

In HLSL as written, glslang writes ``OpImageGather`` and spirv-cross writes GLSL 3.30 with
``GL_ARB_texture_gather`` for a gather of the first channel; one of another channel it refuses
below GLSL 4.00 ("textureGather with component requires GLSL 400"): that stage is written as
GLSL 4.00 (Mesa links it with the other stage's 3.30, as any two desktop GLSL versions).

    glsl = crossed_glsl(spirv)                   # hlsl.cross_to_glsl, 4.00 where a gather needs it
"""

from __future__ import annotations

import re

from ...gpu import hlsl
from ...gpu.hlsl import ShaderCompileError

_GATHER = re.compile(r"\btextureGather\s*\(")
_VERSION = re.compile(r"^#version[^\n]*\n", re.M)
EXTENSIONS = "#extension GL_ARB_texture_gather : enable\n#extension GL_ARB_gpu_shader5 : enable\n"


def with_gather_extensions(source):
    """``source`` (an expanded GLSL stage) with the gather extensions after its ``#version`` line
    where its text calls textureGather; else unchanged."""
    if not _GATHER.search(source.text):
        return source
    m = _VERSION.search(source.text)
    if m is None:
        return source
    source.text = source.text[:m.end()] + EXTENSIONS + source.text[m.end():]
    return source


_NEEDS_400 = "textureGather with component requires GLSL 400"


def crossed_glsl(spirv: bytes) -> str:
    """The GLSL of an HLSL stage's SPIR-V (hlsl.cross_to_glsl, plain uniforms): GLSL 3.30, or 4.00
    where spirv-cross needs it for a gather's channel (module docstring)."""
    try:
        return hlsl.cross_to_glsl(spirv, plain_uniforms=True)
    except ShaderCompileError as e:
        if _NEEDS_400 not in str(e):
            raise
    return hlsl.cross_to_glsl(spirv, 400, plain_uniforms=True)
