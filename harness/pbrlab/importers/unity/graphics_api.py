"""The graphics API a Unity program is compiled for here: desktop OpenGL (Unity's ``glcore``).

Unity compiles every program once per target graphics API and defines exactly one platform
macro for it (Unity manual, "Built-in shader macros" / "Targeting graphics APIs":
``SHADER_API_D3D11``, ``SHADER_API_GLCORE``, ``SHADER_API_VULKAN``, ...). Core RP's
``Common.hlsl`` picks its ``API/<platform>.hlsl`` header (the texture and sampler macros, the
clip-space constants) by that macro and stops at ``#error unsupported shader api`` without one,
so a project that vendors Core's ShaderLibrary under ``Assets/`` needs it.

pbrlab draws with OpenGL and already follows its conventions everywhere: ``UNITY_UV_STARTS_AT_TOP``
and ``UNITY_REVERSED_Z`` undefined, clip-space z in [-1, 1] (the stand-ins' ComputeScreenPos,
ComputeNormalizedDeviceCoordinates, the depth texture cleared to 1), and a ``GLSLPROGRAM`` is
compiled with ``SHADER_API_GLCORE`` (glslprogram.api_macro). So the platform is ``glcore`` in
both languages and both pipelines: a program's ``#if defined(SHADER_API_D3D11)`` branch is the
one Unity skips on OpenGL. (A GLSLPROGRAM keeps its own macro: an OpenGL ES-only one is
compiled with ``SHADER_API_GLES3`` as on that renderer.)

    defines = program_defines(unity_pass)     # {"SHADER_API_GLCORE": 1}
"""

from __future__ import annotations

API_MACRO = "SHADER_API_GLCORE"
# The model's language of a GLSLPROGRAM pass (glslprogram.LANGUAGE): it defines its own macro.
GLSLPROGRAM_LANGUAGE = "unity-glsl"


def program_defines(unity_pass) -> dict:
    """The platform macro of a CGPROGRAM / HLSLPROGRAM pass or a surface program; none for a
    GLSLPROGRAM, whose own renderer macro glslprogram.stage_text defines."""
    if getattr(unity_pass, "language", None) == GLSLPROGRAM_LANGUAGE:
        return {}
    return {API_MACRO: 1}
