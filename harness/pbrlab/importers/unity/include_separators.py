"""An ``#include`` written with Windows' path separator (``#include "Assets\\ShaderLibs\\Node.hlsl"``):
Unity, whose asset paths use ``/`` on every platform, reads ``\\`` in an include's name as ``/``
(the project compiles the same on Windows and macOS editors); glslang and pbrlab's expander,
on Linux, would look for one file named with backslashes. A pass program's include names are
respelled with ``/`` (each keeps its line), before their case (include_case) and their folder
(source_text.resolve_included: an ``Assets/`` path from the project's root) are read.

    program = forward_slashed_includes(program)
"""

from __future__ import annotations

from .source_text import INCLUDE, blank_comments


def forward_slashed_includes(program: str) -> str:
    """``program`` with ``\\`` read as ``/`` in each include's name (module docstring)."""
    masked = blank_comments(program)
    out, pos = [], 0
    for m in INCLUDE.finditer(masked):
        if "\\" in m.group(1):
            out += [program[pos:m.start(1)], m.group(1).replace("\\", "/")]
            pos = m.end(1)
    return "".join(out) + program[pos:]
