"""A variable declared in a ``for`` statement's initialiser and used after the loop
(``for (int k = 0; k < 4; ++k) {...} ... for (k = 0; k < 4; ++k)``): in HLSL as FXC compiles
it (the language before HLSL 2021), such a variable belongs to the scope that encloses the loop,
so the later ``k`` is the same variable; HLSL 2021 gave it C++'s scope, the loop alone
(DirectXShaderCompiler wiki, "HLSL 2021", "for loop variable scoping"). GLSL (4.60 §6.3) and
glslang's HLSL front end take the loop's scope: both refuse the later ``k`` as undeclared.
Spelled as FXC reads it: the declaration before the loop, the initialiser an assignment
(``int k; for (k = 0; ...``), which both languages take; lines kept. Only a loop whose variable is
used later in the same block, before any declaration of that name there, and that stands as a
statement of its own (after ``;``, ``{`` or ``}``: not the unbraced body of an ``if``).

    text = loop_variables_in_enclosing_scope(text)
"""

from __future__ import annotations

import re

from .source_text import blank_comments, matching_brace, matching_paren

_FOR_DECLARATION = re.compile(r"\bfor\s*\(\s*((?:float|half|fixed|int|uint|min16int|min16uint)[1-4]?)"
                              r"\s+([A-Za-z_]\w*)\s*=")

# A type name just before a name: its declaration (``for (int k = 0`` again, ``float k;``).
_TYPE_BEFORE = re.compile(r"\b(?:float|half|fixed|int|uint|bool|min16float|min16int|min16uint)[1-4]?\s+$")


def _enclosing_open_brace(masked: str, index: int) -> int:
    """The offset of the ``{`` of the block that holds ``index``; -1 at file scope."""
    depth = 0
    for i in range(index - 1, -1, -1):
        if masked[i] == "}":
            depth += 1
        elif masked[i] == "{":
            if depth == 0:
                return i
            depth -= 1
    return -1


def _loop_end(masked: str, close_paren: int) -> int:
    """The offset of the last character of the loop's body: its block's ``}`` or its one
    statement's ``;``; -1 when neither is found."""
    j = close_paren + 1
    while j < len(masked) and masked[j].isspace():
        j += 1
    if j < len(masked) and masked[j] == "{":
        return matching_brace(masked, j)
    return masked.find(";", j)


def loop_variables_in_enclosing_scope(text: str) -> str:
    """``text`` with each for-loop variable that the code after its loop uses declared before
    the loop (module docstring)."""
    masked = blank_comments(text)
    edits = []  # (offset, removed length, inserted)
    for m in _FOR_DECLARATION.finditer(masked):
        kind, name = m.group(1), m.group(2)
        before = masked[:m.start()].rstrip()
        if before and before[-1] not in ";{}":
            continue  # the unbraced body of an if or a loop: a declaration cannot go before it
        close = matching_paren(masked, masked.index("(", m.start()))
        end = _loop_end(masked, close) if close >= 0 else -1
        opening = _enclosing_open_brace(masked, m.start())
        closing = matching_brace(masked, opening) if opening >= 0 else -1
        if end < 0 or closing < 0:
            continue
        after = masked[end + 1:closing]
        use = re.search(rf"(?<![\w.]){re.escape(name)}\b", after)
        if use is None or _TYPE_BEFORE.search(after[:use.start()]):
            continue  # not used after the loop, or its first use there is a declaration of its own
        edits.append((m.start(1), m.end(1) - m.start(1), ""))
        edits.append((m.start(), 0, f"{kind} {name}; "))
    for offset, removed, inserted in sorted(edits, reverse=True):
        text = text[:offset] + inserted + " " * removed + text[offset + removed:]
    return text
