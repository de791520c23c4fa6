"""A function of Unity's layer that a shader defines again in one of its own include files
(``float Luminance(in float3 c)`` in a project's Tools.cginc, beside UnityCG.cginc's
``half Luminance(half3 rgb)``).

Unity compiles Direct3D programs with FXC, whose ``half`` is a type of its own for overloading:
the two are overloads there, and a call with a float3 takes the project's. glslang and GLSL read
``half`` as ``float``: the same signature twice, "function already has a body". A definition in
the program itself was renamed in the program's text (``cg_spellings.respelled``); one in an
include was renamed in the include only in the GLSL port (each file is ported alone), so the
program's calls still went to Unity's function, and glslang compiled the include as written.

Here the names the shader's own include files define again are renamed, definitions and calls,
``pbrlab_program_<name>``, in the program and in every own file, in both languages (the files
as rewritten texts: hlsl.compile_spirv's ``replaced``, program.program_include for the port).
Every call in the shader's own code then reaches its own function, as FXC's overload resolution
gives a call with float arguments (a call with half arguments, which FXC would give Unity's, is
not told apart). Lines are kept.

    program, rewritten = renamed_in_own_files(program, folder, rewritten)
"""

from __future__ import annotations

from pathlib import Path

from .cg_spellings import library_overloads_defined, renamed_calls
from .source_text import CGINC, PACKAGE_STAND_INS, _read_include, included_files


def renamed_in_own_files(program: str, folder: Path, rewritten: dict) -> tuple[str, dict]:
    """(the program, {path: text} of the own include files, ``rewritten`` updated) with the
    Unity-layer functions those files define again renamed (module docstring); ``rewritten``:
    texts already standing in for files (written_globals.copied_in_includes), renamed on top."""
    stand_ins = (CGINC.resolve(), PACKAGE_STAND_INS.resolve())
    own = {path: rewritten.get(path) or _read_include(path)
           for path in included_files(program, folder)
           if not any(path.is_relative_to(root) for root in stand_ins)}
    names = set()
    for path, text in own.items():
        if text:
            names |= library_overloads_defined(text)
    if not names:
        return program, rewritten
    out = dict(rewritten)
    for path, text in own.items():
        if text and renamed_calls(text, names) != text:
            out[path] = renamed_calls(text, names)
    return renamed_calls(program, names), out
