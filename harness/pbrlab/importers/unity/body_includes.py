"""An ``#include`` inside a function body, for the GLSL port.

HLSL's preprocessor pastes an included file where its line stands, so a file included inside a
function body (``float4 frag(v2f input) : SV_Target { #include "share/Basics.hlsl" ... }``)
is a file of statements: its ``float3 n = ...;`` are the function's locals, read with the
function's parameters. The GLSL path ports each included file on its own, as declarations (a
global there is a uniform), so such a file is spliced into the including text between two
marker comments before the port (the type pass reads its statements in the function, whose
later statements use its locals) and cut out of the port afterwards into a file of its own,
included at its line, so that errors still name the included file and its lines.

One level: an include inside a spliced file stays an include of a file ported on its own.
"""

from __future__ import annotations

import re
from pathlib import Path

from .source_text import blank_comments

_BEGIN = "/*pbrlab-body-include {}*/"
_END = "/*pbrlab-body-include-end {}*/"
_INCLUDE = re.compile(r'^([ \t]*#[ \t]*include[ \t]*")([^"]+)(")[^\n]*$', re.M)
_INCLUDE_NAME = re.compile(r'(#[ \t]*include[ \t]*")([^"]+)(")')
_SPLICED = re.compile(r"/\*pbrlab-body-include (\d+)\*/\n(.*?)\n?/\*pbrlab-body-include-end \1\*/", re.S)


def _depth_at_lines(masked: str) -> list[int]:
    """The brace depth at the start of each line of ``masked`` (comments blanked); a
    preprocessor line's braces (a macro's body) do not count."""
    depths, depth = [], 0
    for line in masked.split("\n"):
        depths.append(depth)
        if not line.lstrip().startswith("#"):
            depth += line.count("{") - line.count("}")
    return depths


def spliced(text: str, resolve, read) -> tuple[str, list]:
    """(``text`` with each include inside a function body replaced by the included file's text
    between markers, [(the include line, the resolved file)] in marker order). ``resolve(name)``:
    the file an include names, or None (that line is left to the expander's message);
    ``read(path)``: its text."""
    masked = blank_comments(text)
    depths = _depth_at_lines(masked)
    lines, masked_lines, splices = text.split("\n"), masked.split("\n"), []
    for i, (line, seen) in enumerate(zip(lines, masked_lines)):
        m = _INCLUDE.match(seen)
        if m is None or depths[i] <= 0:
            continue
        target = resolve(m.group(2))
        if target is None:
            continue
        body = read(target).rstrip("\n")
        lines[i] = "\n".join((_BEGIN.format(len(splices)), body, _END.format(len(splices))))
        splices.append((line, target))
    return "\n".join(lines), splices


def cut(ported: str, splices: list, name_of) -> tuple[str, dict]:
    """(the port with each spliced file's text replaced by its include line, naming
    ``name_of(index, path)`` now, {that name: (the spliced file's port, its path)})."""
    files = {}

    def back(m):
        index = int(m.group(1))
        line, target = splices[index]
        name = name_of(index, target)
        files[name] = (m.group(2), target)
        return _INCLUDE_NAME.sub(lambda q: q.group(1) + name + q.group(3), line, count=1)
    return _SPLICED.sub(back, ported), files
