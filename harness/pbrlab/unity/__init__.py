"""Unity surface shaders in the harness: Unity's surface-shader compiler, for both languages.

    shader = load_shader(Path("rim.shader"))      # parse.py -> model.SurfaceShader
    program = build_program(ctx, shader, "hlsl", "sphere", defines)   # generate.py

Flow (STYLE 10): ``parse`` reads ShaderLab (Properties, Cull/ZWrite/Blend) and the CGPROGRAM
(``#pragma surface``, struct Input, the surface, vertex, final-colour and lighting functions)
into a ``model``; ``properties`` resolves a scene material's values against it; ``generate``
writes the programs; ``program`` compiles and binds them; ``port`` is ``pbrlab port-unity``,
the mechanical GLSL renames. The renderer (render.py) only asks ``program`` to draw.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from .model import SurfaceShader
from .parse import UnityShaderError, is_unity_surface, parse_file
from .properties import resolve as resolve_properties

__all__ = ["SurfaceShader", "UnityShaderError", "UnityShaderWarning", "is_unity_surface",
           "load_shader", "resolve_properties"]


class UnityShaderWarning(UserWarning):
    """Something a surface shader asks for that the harness does not do (named in the text)."""


def load_shader(path: Path) -> SurfaceShader:
    """Parse a surface shader; its warnings are issued as ``UnityShaderWarning``."""
    shader = parse_file(Path(path))
    for message in shader.warnings:
        warnings.warn(message, UnityShaderWarning, stacklevel=2)
    return shader
