"""A macro a shader ``#define``s again with another body: one Unity's layer defines too
(``#define COMPUTE_DEPTH_01 ...`` beside UnityCG's, ``#define unity_ColorSpaceDouble ...`` beside
Core RP's), or one its own files define twice.

FXC and DXC treat a macro redefinition as a warning (FXC X1519 "macro redefinition", clang's
-Wmacro-redefined) and the later body is the one used from there on. glslang's HLSL
preprocessor and Mesa's GLSL preprocessor refuse a different body ("Macro redefined; different
substitutions", "Redefinition of macro"). Here the shader's own text (the program and its own
include files, not pbrlab's stand-ins) gets ``#undef NAME`` on the line before each such
``#define NAME``, in both languages: the new body wins from its line on, as FXC has it, and the
code before the line still reads the earlier body. A note names each.

Lines are kept: the ``#undef`` takes the place of a blank line directly above the ``#define``
where there is one, else it is inserted and the first blank line below (not inside a
multi-line macro) is dropped, so only the lines between move (by one); a file with no blank
line below ends one line longer.

    program, rewritten, notes = undefined_before_redefinition(program, path, first_line, rewritten)
"""

from __future__ import annotations

import functools
import re
from pathlib import Path

from ...gpu.hlsl import HLSL_ROOT
from ...gpu.shaders import GLSL_ROOT
from .source_text import CGINC, PACKAGE_STAND_INS, _read_include, blank_comments, included_files

_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)", re.M)


@functools.lru_cache(maxsize=1)
def provided_macros() -> dict:
    """{name: the bodies it is given} of the macros pbrlab's Unity layer ``#define``s: the
    built-in stand-ins (cginc/), the URP and Core RP stand-ins (package_stand_ins/), the Unity
    prelude of each language (unity_compat/, pbr/unity/)."""
    files = [*CGINC.rglob("*.cginc"), *CGINC.rglob("*.hlsl"), *PACKAGE_STAND_INS.rglob("*.hlsl"),
             *(GLSL_ROOT / "unity_compat").glob("*.glsl"), *(HLSL_ROOT / "unity_compat").glob("*.hlsl"),
             *(GLSL_ROOT / "pbr" / "unity").glob("*.glsl"), *(HLSL_ROOT / "pbr" / "unity").glob("*.hlsl")]
    names: dict = {}
    for path in files:
        for name, _, body in _bodies(path.read_text(encoding="utf-8", errors="replace")):
            names.setdefault(name, set()).add(body)
    return names


def _bodies(text: str) -> list:
    """(name, line index, the body with its continuation lines, white space collapsed) of each
    #define line of ``text`` (comments blanked)."""
    lines = blank_comments(text).split("\n")
    out, i = [], 0
    while i < len(lines):
        m = _DEFINE.match(lines[i])
        start = i
        while lines[i].rstrip().endswith("\\") and i + 1 < len(lines):
            i += 1
        if m:
            body = " ".join(line.rstrip().rstrip("\\") for line in [lines[start][m.end():], *lines[start + 1:i + 1]])
            out.append((m.group(1), start, " ".join(body.split())))
        i += 1
    return out


def _continued(lines: list, i: int) -> bool:
    return i > 0 and lines[i - 1].rstrip("\r").rstrip().endswith("\\")


def _with_undefs(text: str, starts: list) -> str:
    """``text`` with ``#undef NAME`` before each line index of ``starts`` ((index, name)), lines
    kept as the module docstring says."""
    lines = text.split("\n")
    blank = [not lines[i].strip() and not _continued(lines, i) for i in range(len(lines))]
    for i, name in sorted(starts, reverse=True):  # from the last: an edit moves no earlier line
        if i > 0 and blank[i - 1]:
            lines[i - 1] = f"#undef {name}"
            blank[i - 1] = False
            continue
        lines.insert(i, f"#undef {name}")
        blank.insert(i, False)
        below = next((j for j in range(i + 2, len(lines)) if blank[j]), None)
        if below is not None:
            del lines[below]
            del blank[below]
    return "\n".join(lines)


def undefined_before_redefinition(program: str, path: Path, first_line: int, rewritten: dict) -> tuple:
    """(the program, ``rewritten`` updated with the shader's own include files so changed, notes)
    (module docstring): each ``#define`` of the shader's own text whose name pbrlab's Unity layer
    defines too, or that its own text defines with another body elsewhere, gets an ``#undef``
    before it; ``rewritten``: texts already standing in for files, changed on top."""
    stand_ins = (CGINC.resolve(), PACKAGE_STAND_INS.resolve())
    own = {p: rewritten.get(p) or _read_include(p) for p in included_files(program, path.parent)
           if not any(p.is_relative_to(root) for root in stand_ins)}
    texts = {None: program, **{p: t for p, t in own.items() if t}}
    found = {key: _bodies(text) for key, text in texts.items()}
    bodies = {}
    for defines in found.values():
        for name, _, body in defines:
            bodies.setdefault(name, set()).add(body)
    provided = provided_macros()
    # a body the layer gives the name too is no redefinition (FXC says nothing for an equal body)
    again = {name for name, seen in bodies.items() if len(seen) > 1 or (name in provided and seen - provided[name])}
    if not again:
        return program, rewritten, []
    out, notes = dict(rewritten), []
    for key, defines in found.items():
        starts = [(i, name) for name, i, _ in defines if name in again]
        if not starts:
            continue
        shown, base = (path, first_line) if key is None else (key, 1)
        for i, name in starts:
            whose = ("pbrlab's Unity layer defines with another body" if name in provided
                     else "defined before with another body")
            notes.append(f"{shown}:{base + i}: #define {name} defines a macro {whose}: the shader's body is used "
                         "from this line on (FXC and DXC warn, X1519, and take the later one)")
        changed = _with_undefs(texts[key], starts)
        if key is None:
            program = changed
        else:
            out[key] = changed
    return program, out, notes
