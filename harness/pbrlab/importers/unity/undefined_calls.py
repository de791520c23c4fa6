"""A call of a function that nothing defines: the shader's file, the files it includes (its own
and pbrlab's stand-ins for Unity's) and pbrlab's Unity layer hold no function or macro of that
name (``Remap(1, 10, 0, 1, y)`` in a URP shader that defines none, as Unity's URP and Core
ShaderLibrary define none; ``ShadeGI(...)`` after the project renamed its lighting functions).
Unity's compiler refuses such a shader too ("undeclared identifier"), so the refusal says that
the project's own code calls an undefined function, naming the file and line of the call.

    found = undefined_call(message, shader_path, provided)   # (file:line, name) or None
    name = unity_library_function(message, provided)          # a Unity ShaderLibrary function pbrlab lacks, or None
"""

from __future__ import annotations

import re
from pathlib import Path

from .source_text import blank_comments, included_files, read_source
from .unity_library_names import UNITY_LIBRARY_NAMES

# The first error of either compiler when a call's name has no function at all: Mesa's GLSL
# ("FILE:LINE:COL: error: no function with name 'X'") and glslang's HLSL front end
# ("FILE:LINE: error: 'X' : no matching overloaded function found", which it also says for a
# call whose arguments match none of a name's overloads: the definitions are looked for below).
_NO_FUNCTION = re.compile(r"^(?P<file>\S+?):(?P<line>\d+):(?:\d+:)? error: (?:no function with name '(?P<glsl>\w+)'|"
                          r"'(?P<hlsl>\w+)' : no matching overloaded function found)")


def unity_library_function(message: str, provided) -> str | None:
    """The name of the first error's call when it is a function of Unity's URP or Core
    ShaderLibrary (unity_library_names) that pbrlab's layer does not define (not in ``provided``,
    unprovided.provided_names), else None."""
    first = next((line for line in message.splitlines() if "error" in line.lower()), "")
    m = _NO_FUNCTION.match(first.strip())
    name = m and (m.group("glsl") or m.group("hlsl"))
    return name if name and name in UNITY_LIBRARY_NAMES and name not in provided else None


def _defines(text: str, name: str) -> bool:
    """Whether ``text`` (comments blanked) defines or declares a function ``name`` or a macro of it."""
    return re.search(rf"(?:\b\w+\s+{name}\s*\(|^[ \t]*#[ \t]*define[ \t]+{name}\b)", text, re.M) is not None


def undefined_call(message: str, shader, provided) -> tuple[str, str] | None:
    """(``file:line`` of the call, the function's name) when the first error of ``message`` is a
    call of a function that no file the shader reads nor pbrlab's layer (``provided``) defines
    (module docstring), else None."""
    first = next((line for line in message.splitlines() if "error" in line.lower()), "")
    m = _NO_FUNCTION.match(first.strip())
    if m is None:
        return None
    name = m.group("glsl") or m.group("hlsl")
    shader = Path(shader)
    try:
        own = blank_comments(read_source(shader))
    except OSError:
        return None
    files = {shader.resolve(): own, **included_files(own, shader.parent)}
    if name in provided or name in UNITY_LIBRARY_NAMES or any(_defines(text, name) for text in files.values()):
        return None  # (a name of Unity's library pbrlab lacks: unity_library_function)
    return f"{_calling_file(m.group('file'), int(m.group('line')), name, files)}:{m.group('line')}", name


def _calling_file(written: str, line: int, name: str, files: dict):
    """The file an error names: as written when absolute (the GLSL compiler's), else (glslang names
    a file by its base name) the one of ``files`` of that name whose line ``line`` calls ``name``."""
    if Path(written).is_absolute():
        return written
    for path, text in files.items():
        rows = text.splitlines()
        if Path(path).name == Path(written).name and 0 < line <= len(rows) and name in rows[line - 1]:
            return path
    return written
