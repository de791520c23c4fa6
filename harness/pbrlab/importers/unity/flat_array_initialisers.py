"""An array of vectors initialised from a flat list of numbers (``float2 axis[4] = { -1, 1,
1, 1, -1, 0, 0, 1 };``): HLSL fills an aggregate's components in order from a flat initialiser
list (Microsoft's HLSL reference, "Variable Syntax": an initialiser list "can contain ...
scalars ... flattened"), FXC takes it; glslang and GLSL ask one element per vector. Spelled with
one constructor per element (``{ float2(-1, 1), float2(1, 1), ... }``), line breaks kept.
Only a list of exactly elements x components scalars is spelled so; anything else is left to
the compilers.

    text = grouped_flat_initialisers(text)
"""

from __future__ import annotations

import re

from .source_text import matching_brace

_DECLARATION = re.compile(r"\b((?:float|half|fixed|int|uint|min16float)([234]))\s+\w+\s*\[\s*(\d+)\s*\]\s*=\s*\{")
_SCALAR = re.compile(r"[-+]?\s*(?:[A-Za-z_]\w*(?:\.\w+)*|\d+\.?\d*(?:[eE][-+]?\d+)?[fFhH]?|\.\d+(?:[eE][-+]?\d+)?[fFhH]?)")


def _items(body: str):
    """The list's items split at top-level commas (None where a bracket nests: not a flat list)."""
    if re.search(r"[({\[]", body):
        return None
    parts = body.split(",")
    if parts and not parts[-1].strip():
        parts = parts[:-1]  # a trailing comma
    return parts


def grouped_flat_initialisers(text: str) -> str:
    out, pos = [], 0
    for m in _DECLARATION.finditer(text):
        if m.start() < pos:
            continue
        close = matching_brace(text, m.end() - 1, "{", "}")
        if close < 0:
            continue
        items = _items(text[m.end():close])
        size, count = int(m.group(2)), int(m.group(3))
        if items is None or len(items) != size * count or not all(_SCALAR.fullmatch(i.strip()) for i in items):
            continue
        groups = [items[k:k + size] for k in range(0, len(items), size)]
        body = ",".join(f"{m.group(1)}({','.join(g)})" for g in groups)
        out += [text[pos:m.end()], body]
        pos = close
    return "".join(out) + text[pos:]
