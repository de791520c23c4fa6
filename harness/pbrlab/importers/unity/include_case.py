"""An ``#include`` written in another letter case than the file's (``"unityCG.cginc"`` for
``UnityCG.cginc``, ``.../ShaderLibrary/lighting.hlsl`` for ``Lighting.hlsl``, ``"noise.CGINC"``
for the project's ``Noise.cginc``): Unity on Windows and macOS, whose file systems ignore case,
reads the file; a case-sensitive one (Linux, where pbrlab runs) would not. A pass program's
include that no file matches exactly but exactly one file matches ignoring case -- one of
pbrlab's stand-ins for Unity's include files (``cginc/``, by the name's last part, as
``resolve_included`` reads them), for Unity's packages' files (``Packages/...``), or the
project's own file beside the shader or reached by ``..`` -- is respelled as that file (the
line keeps its place) with a warning naming the file and line; two or more matches are refused
naming them. The includes inside the project's include files are read as written.

    program = respell_package_includes(program, path, first_line, warnings)
"""

from __future__ import annotations

import functools
from pathlib import Path

from .source_text import (CGINC, INCLUDE, PACKAGE_STAND_INS, UnityShaderError, blank_comments, line_of,
                          resolve_included)


@functools.lru_cache(maxsize=2)
def _files_by_lower_case(root: Path, below: bool) -> dict:
    """{path relative to ``root`` in lower case: [the files' paths spelled so]}, of the files in
    ``root`` (and in its folders below, when ``below``)."""
    out: dict = {}
    for path in sorted(root.rglob("*") if below else root.iterdir()):
        if path.is_file():
            rel = path.relative_to(root).as_posix()
            out.setdefault(rel.lower(), []).append(rel)
    return out


def _stand_ins_by_lower_case() -> dict:
    """{package path in lower case: [the stand-ins' package paths spelled so]}."""
    return _files_by_lower_case(PACKAGE_STAND_INS, True)


def _unity_includes_by_lower_case() -> dict:
    """{file name in lower case: [pbrlab's stand-ins for Unity's include files spelled so]}."""
    return _files_by_lower_case(CGINC, False)


def _project_spellings(name: str, folder: Path) -> list:
    """The spellings of ``name`` (a path relative to ``folder``) that name a file there when
    each part is compared ignoring case; a ``..`` part climbs to the folder above, as written
    (``#include "../custom.hlsl"`` for the project's ``Custom.hlsl`` one folder up); [] for an
    absolute path or an empty part."""
    parts = name.split("/")
    if name.startswith("/") or any(part in ("", ".") for part in parts) or parts[-1] == "..":
        return []
    found = [("", folder)]
    for i, part in enumerate(parts):
        last, step = i == len(parts) - 1, []
        if part == "..":
            found = [(f"{spelled}/.." if spelled else "..", here.parent) for spelled, here in found]
            continue
        for spelled, here in found:
            try:
                entries = sorted(here.iterdir())
            except OSError:
                continue
            for entry in entries:
                if entry.name.lower() == part.lower() and (entry.is_file() if last else entry.is_dir()):
                    step.append((f"{spelled}/{entry.name}" if spelled else entry.name, entry))
        found = step
    return [spelled for spelled, _ in found]


def _spellings(name: str, folder: Path) -> list:
    """The files ``#include "name"`` names ignoring case (module docstring), as include names."""
    if name.startswith("Packages/"):
        return _stand_ins_by_lower_case().get(name.lower(), [])
    own = _project_spellings(name, folder)
    if own:
        return own
    head, _, base = name.rpartition("/")
    return [f"{head}/{b}" if head else b for b in _unity_includes_by_lower_case().get(base.lower(), [])]


def respell_package_includes(program: str, path: Path, first_line: int, warnings: list) -> str:
    """``program`` with each unresolved include that one file matches ignoring case spelled as
    that file (module docstring); ``warnings`` gets one line each."""
    masked = blank_comments(program)
    out, pos = [], 0
    for m in INCLUDE.finditer(masked):
        name = m.group(1)
        if resolve_included(name, path.parent) is not None:
            continue
        matches = _spellings(name, path.parent)
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
