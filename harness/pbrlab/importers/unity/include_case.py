"""``#include "Packages/..."`` written in another letter case than the package file's
(``.../ShaderLibrary/lighting.hlsl`` for ``Lighting.hlsl``): Unity on Windows and macOS, whose
file systems ignore case, reads the file; a case-sensitive one (Linux, where pbrlab runs) would
not. A pass program's include of a Unity package path that no file matches exactly but exactly one
of pbrlab's stand-ins matches ignoring case is respelled as the stand-in (the line keeps its
length and place) with a warning naming the file and line; two or more matches are refused
naming them. The program's own include files are read as written.

    program = respell_package_includes(program, path, first_line, warnings)
"""

from __future__ import annotations

import functools
from pathlib import Path

from .source_text import INCLUDE, PACKAGE_STAND_INS, UnityShaderError, blank_comments, line_of, resolve_included


@functools.lru_cache(maxsize=1)
def _stand_ins_by_lower_case() -> dict:
    """{package path in lower case: [the stand-ins' package paths spelled so]}."""
    out: dict = {}
    for path in sorted(PACKAGE_STAND_INS.rglob("*")):
        if path.is_file():
            rel = path.relative_to(PACKAGE_STAND_INS).as_posix()
            out.setdefault(rel.lower(), []).append(rel)
    return out


def respell_package_includes(program: str, path: Path, first_line: int, warnings: list) -> str:
    """``program`` with each unresolved ``Packages/`` include that one stand-in matches ignoring
    case spelled as that stand-in (module docstring); ``warnings`` gets one line each."""
    masked = blank_comments(program)
    out, pos = [], 0
    for m in INCLUDE.finditer(masked):
        name = m.group(1)
        if not name.startswith("Packages/") or resolve_included(name, path.parent) is not None:
            continue
        matches = _stand_ins_by_lower_case().get(name.lower(), [])
        where = f"{path}:{first_line - 1 + line_of(program, m.start(1))}"
        if len(matches) > 1:
            raise UnityShaderError(f'{where}: #include "{name}" matches {" and ".join(matches)} ignoring case; '
                                   "write the one meant in its own case")
        if not matches:
            continue  # the include's refusal names it
        warnings.append(f'{where}: #include "{name}" read as {matches[0]}: the file is spelled so (Unity on '
                        "Windows and macOS ignores the case of a file name; a case-sensitive file system does not)")
        out += [program[pos:m.start(1)], matches[0]]
        pos = m.end(1)
    return "".join(out) + program[pos:]
