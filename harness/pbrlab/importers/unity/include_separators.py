"""An ``#include`` written with Windows' path separator (``#include "Assets\\ShaderLibs\\Node.hlsl"``):
Unity, whose asset paths use ``/`` on every platform, reads ``\\`` in an include's name as ``/``
(the project compiles the same on Windows and macOS editors); glslang and pbrlab's expander,
on Linux, would look for one file named with backslashes. A pass program's include names are
respelled with ``/`` (each keeps its line), before their case (include_case) and their folder
(source_text.resolve_included: an ``Assets/`` path from the project's root) are read.

An include's name that starts with ``/`` (``#include "/API/GLCore.hlsl"`` in a project's own copy
of Core's Common.hlsl, ``#include "/Utils/Universal2D.hlsl"`` beside it) is read from the including
file's folder, as Unity reads it (the including folder joined with the name: such a project
compiles in Unity with its ``API/`` beside its Common.hlsl), where glslang would look from the
file system's root. Its name is respelled without the ``/``, in the program and in the project's
own include files it reads (program.hlsl_includes; resolve_included reads it so for the port).

    program = forward_slashed_includes(program)
"""

from __future__ import annotations

from .source_text import INCLUDE, blank_comments


def forward_slashed_includes(program: str) -> str:
    """``program`` with ``\\`` read as ``/`` and a leading ``/`` dropped in each include's name
    (module docstring)."""
    masked = blank_comments(program)
    out, pos = [], 0
    for m in INCLUDE.finditer(masked):
        name = m.group(1).replace("\\", "/")
        if name != m.group(1) or name.startswith("/"):
            out += [program[pos:m.start(1)], name.lstrip("/")]
            pos = m.end(1)
    return "".join(out) + program[pos:]
