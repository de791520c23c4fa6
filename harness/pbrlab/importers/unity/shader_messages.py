"""HLSL's ``printf`` (a shader message, Direct3D's debug output) dropped from a program, both
languages.

Microsoft's HLSL reference, "printf function": ``void printf(string format, argument ...)``
submits a custom shader message to the information queue, from Shader Model 4 on, and "does
nothing on devices that do not support it"; so FXC compiles it for Unity's Direct3D 11 targets
and the pixels drawn are the same as without it. Neither language here has a place for it:
GLSL has no strings (the port's syntax error), and spirv-cross refuses glslang's debug-printf
SPIR-V outside Vulkan GLSL. Each ``printf(...);`` statement of the program's own text is
blanked (its lines kept), with a warning naming the shader's file and line.

    program, dropped = dropped_printf_calls(program, path, first_line)
"""

from __future__ import annotations

import re
from pathlib import Path

from .source_text import blank_comments, line_of

_PRINTF = re.compile(r"(?<![\w.])printf\s*\(")


def _call_end(text: str, open_paren: int) -> int:
    """The offset after the ``)`` that closes the ``(`` at ``open_paren`` (string literals
    skipped: a format may hold parentheses); -1 when none does."""
    depth, i, quoted = 0, open_paren, False
    while i < len(text):
        c = text[i]
        if quoted:
            if c == "\\":
                i += 1
            elif c == '"':
                quoted = False
        elif c == '"':
            quoted = True
        elif c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return -1


def dropped_printf_calls(program: str, path: Path, first_line: int) -> tuple[str, list]:
    """``program`` with each ``printf(...);`` statement blanked (newlines kept), and a warning
    for each naming its line in ``path`` (the program's first line is ``first_line``)."""
    masked = blank_comments(program)
    out, pos, warnings = [], 0, []
    for m in _PRINTF.finditer(masked):
        if m.start() < pos:
            continue
        end = _call_end(masked, m.end() - 1)
        if end < 0:
            continue
        semicolon = re.match(r"\s*;", masked[end:])
        if semicolon is None:  # printf inside an expression: HLSL's is void, so none is valid
            continue
        end += semicolon.end()
        out += [program[pos:m.start()], re.sub(r"[^\n]", " ", program[m.start():end])]
        pos = end
        warnings.append(f"{path}:{first_line - 1 + line_of(program, m.start())}: printf dropped: Direct3D's "
                        "shader messages (HLSL's printf, which does nothing where a device has no message "
                        "queue) have no place in pbrlab's renders; the pixels are the same without it")
    return "".join(out) + program[pos:], warnings
