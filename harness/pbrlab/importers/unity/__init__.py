"""Unity surface shaders in the harness: Unity's surface-shader compiler, for both languages.

    shader = load_shader(Path("rim.shader"))      # parse.py -> model.UnityShader
    program = build_program(ctx, shader, "hlsl", "sphere", defines)   # program.py

A pipeline (STYLE 10) of five stages; each module imports only the modules listed before it,
in its own stage or an earlier one (tests/foundation/test_layers.py finds any circle):

1. ShaderLab reading, the text before any model: ``source_text`` (comments blanked with line
   numbers kept, braces, identifiers, a type name's component count, ``#include`` resolved
   against the shader's folder and pbrlab's stand-ins in ``cginc/``, what a stand-in refuses,
   the keywords a program declares, the port marker, ``UnityShaderError``); ``conditionals``
   (the ``#if`` branches of the default variant); ``shaderlab`` (the file's structure:
   Properties, SubShaders, passes, program blocks, Fallback).
2. Model: ``model`` (what a shader says, as data); ``output_struct`` (a layered lighting
   model's output struct written from it as code); ``parse_pass`` (a vertex/fragment pass
   into the model); ``parse`` (a ShaderLab file or bare CGPROGRAM into the model: Properties,
   render state, ``#pragma surface`` and its functions, UsePass, Fallback); ``properties``
   (a scene material's values resolved against the model's Properties).
3. Cg/HLSL typing and porting: ``cg_types`` (the type pass: Cg's implicit conversions spelled
   out); ``port`` (``pbrlab port-unity``: the mechanical GLSL renames).
4. Program generation: ``generate_pass`` (a vertex/fragment pass's two stages, and the
   semantics and mesh attributes both kinds of program use); ``generate`` (a surface
   program's fragment and vertex stages).
5. GL program: ``unprovided`` (a compile error naming a Unity feature pbrlab leaves out);
   ``program`` (compile and bind a surface program); ``program_pass`` (a pass's);
   ``tessellate`` (the mesh a sphere becomes for a ``vertex:`` function).

The renderer (render/renderer.py) only asks ``program`` and ``program_pass`` to draw, and
``tessellate`` for a sphere's mesh.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from .model import SurfaceShader, UnityShader
from .parse import BUILTIN, URP, Pipeline, is_unity_surface, parse_file, read_shader
from .properties import resolve as resolve_properties
from .source_text import UnityShaderError, UnityShaderNote, UnityShaderWarning

__all__ = ["BUILTIN", "URP", "Pipeline", "SurfaceShader", "UnityShader", "UnityShaderError", "UnityShaderWarning",
           "is_unity_surface", "load_shader", "resolve_properties"]


def load_shader(path: Path, pipeline: Pipeline = BUILTIN) -> UnityShader:
    """Read a Unity shader (every pass that runs in ``pipeline``); its warnings are issued as
    ``UnityShaderWarning``, its notes (SubShader chosen, passes skipped) as ``UnityShaderNote``."""
    shader = read_shader(Path(path), pipeline)
    for message in dict.fromkeys(shader.warnings):
        warnings.warn(message, UnityShaderWarning, stacklevel=2)
    for message in shader.notes:
        warnings.warn(message, UnityShaderNote, stacklevel=2)
    return shader
