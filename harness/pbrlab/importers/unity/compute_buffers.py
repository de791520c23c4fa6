"""Compute buffers a Unity program reads (``StructuredBuffer<T>``, ``ByteAddressBuffer``, ...):
the application fills them from C# (``Material.SetBuffer``, ``ComputeBuffer.SetData``, or a
compute shader's output) and draws with them; a shader file holds no data for them. The
harness has no such application, and an unbound buffer reads zero (or nothing), so a pass
whose drawn variant reads one is refused naming it, at its declaration's line.

    check_compute_buffers(active_program, path, first_line)   # raises UnityShaderError
    check_included_compute_buffers(active_program, active_included, program, folder)  # the same, its own includes
"""

from __future__ import annotations

import re
from pathlib import Path

from .source_text import CGINC, PACKAGE_STAND_INS, UnityShaderError, included_files, line_of

_BUFFER = re.compile(r"\b((?:RW|Append|Consume)?StructuredBuffer|(?:RW)?ByteAddressBuffer|(?:RW)?Buffer)"
                     r"\s*(?:<[^<>;]*>)?\s+(\w+)\s*(?:\[[^\]]*\])?\s*(?::\s*register\s*\([^)]*\))?\s*;")


def check_compute_buffers(active_program: str, path: Path, first_line: int) -> None:
    """Refuse a program whose drawn variant (comments and undrawn branches blanked) declares a
    compute buffer and reads it."""
    for m in _BUFFER.finditer(active_program):
        rest = active_program[:m.start()] + active_program[m.end():]
        if re.search(rf"\b{re.escape(m.group(2))}\b", rest):
            line = first_line - 1 + line_of(active_program, m.start())
            raise UnityShaderError(
                f"{path}:{line}: reads {m.group(1)} {m.group(2)}, a compute buffer the application fills from C# "
                "(Material.SetBuffer) or a compute shader, which a shader file carries no data for and pbrlab "
                "does not provide")


def check_included_compute_buffers(active_program: str, active_included: str, program: str, folder: Path) -> None:
    """The same for a compute buffer the program's own include files declare (a procedural
    draw's ``StructuredBuffer<DrawTriangle>`` in its .hlsl): refused where the drawn variant
    (``active_program`` and ``active_included``, the text of its includes with undrawn branches
    blanked) reads it, naming the include file and its declaration's line. pbrlab's stand-ins
    for Unity's files are not the project's and are left out."""
    everything = active_program + "\n" + active_included
    for m in _BUFFER.finditer(active_included):
        rest = everything.replace(m.group(0), " ", 1)
        if not re.search(rf"\b{re.escape(m.group(2))}\b", rest):
            continue
        for file, text in included_files(program, folder).items():
            if file.is_relative_to(CGINC.resolve()) or file.is_relative_to(PACKAGE_STAND_INS.resolve()):
                continue
            declared = next((d for d in _BUFFER.finditer(text) if d.group(2) == m.group(2)), None)
            if declared is not None:
                raise UnityShaderError(
                    f"{file}:{line_of(text, declared.start())}: reads {m.group(1)} {m.group(2)}, a compute buffer "
                    "the application fills from C# (Material.SetBuffer) or a compute shader, which a shader file "
                    "carries no data for and pbrlab does not provide")
