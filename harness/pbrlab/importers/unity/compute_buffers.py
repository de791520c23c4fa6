"""Compute buffers a Unity program reads (``StructuredBuffer<T>``, ``ByteAddressBuffer``, ...):
the application fills them from C# (``Material.SetBuffer``, ``ComputeBuffer.SetData``, or a
compute shader's output) and draws with them; a shader file holds no data for them. The
harness has no such application, and an unbound buffer reads zero (or nothing), so a pass
whose drawn variant reads one is refused naming it, at its declaration's line.

    check_compute_buffers(active_program, path, first_line)   # raises UnityShaderError
"""

from __future__ import annotations

import re
from pathlib import Path

from .source_text import UnityShaderError, line_of

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
