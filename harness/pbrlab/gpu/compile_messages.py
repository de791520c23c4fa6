"""A compile failure's text: the compiler's first error first, its follow-ons after.

A compiler that meets one mistake usually reports a cascade after it: an undeclared name
makes the expression it is in ill-typed, then the statement, then the return ("operands to
arithmetic operators must be numeric", "`return' with wrong type error" in Mesa). Those
follow-ons sit on the line already reported (issue 36: they buried the first error). So the
text reads:

    shaders/my/rim.glsl:5:52: error: `undefined_thing' undeclared     <- the first error
    shaders/my/rim.glsl:6:49: error: `y' undeclared                   <- the first on another line
    (fragment shader failed to compile; 2 more lines: follow-ons on the lines above, and warnings)
      shaders/my/rim.glsl:6:9: error: operands to arithmetic operators must be numeric
      ...

Each message is kept (a later one is sometimes the useful one), only moved after the first
of each line; a line the mapping could not place (no ``file:line:``) stays where it was
among the first messages, after the message it continues.
"""

from __future__ import annotations

import re

# "path:line: error: ..." or "path:line:col: error: ..." (shaders.Source.map_messages,
# hlsl.map_messages): the place is path and line, the column left out.
_PLACED = re.compile(r"^(?P<place>.+?:\d+)(?::\d+)?: (?P<kind>error|warning): ")


def compile_failure(what: str, messages: str) -> str:
    """``what`` ("fragment shader failed to compile") and the mapped ``messages`` (one a line),
    ordered: each line's first error, in the compiler's order, then the rest, indented."""
    first, rest = [], []
    seen = set()
    target = first
    for line in messages.splitlines():
        if not line.strip():
            continue
        placed = _PLACED.match(line)
        if placed:
            new_error = placed["kind"] == "error" and placed["place"] not in seen
            seen.add(placed["place"])
            target = first if new_error else rest
        target.append(line)
    if not first:  # nothing but warnings or follow-ons: the first of them leads
        first, rest = rest[:1], rest[1:]
    if not rest:
        return "\n".join(first + [f"({what})"])
    more = f"{len(rest)} more line{'s' if len(rest) != 1 else ''}: follow-ons on the lines above, and warnings"
    return "\n".join(first + [f"({what}; {more})"] + [f"  {line}" for line in rest])
