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

from .model import SurfaceShader, UnityShader
from .parse import is_unity_surface, parse_file, read_shader
from .properties import resolve as resolve_properties
from .source_text import UnityShaderError

__all__ = ["SurfaceShader", "UnityShader", "UnityShaderError", "UnityShaderWarning", "is_unity_surface",
           "load_shader", "resolve_properties"]


class UnityShaderWarning(UserWarning):
    """Something a surface shader asks for that the harness does not do (named in the text)."""


class UnityShaderNote(UnityShaderWarning):
    """What the harness chose for a shader: the SubShader that runs, a pass it skips, a Fallback."""


def load_shader(path: Path) -> UnityShader:
    """Read a Unity shader (every pass that runs); its warnings are issued as
    ``UnityShaderWarning``, its notes (SubShader chosen, passes skipped) as ``UnityShaderNote``."""
    shader = read_shader(Path(path))
    for message in dict.fromkeys(shader.warnings):
        warnings.warn(message, UnityShaderWarning, stacklevel=2)
    for message in shader.notes:
        warnings.warn(message, UnityShaderNote, stacklevel=2)
    return shader
