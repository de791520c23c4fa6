"""A local variable named in its own initialiser (``float4 color = c ? color = a : b;``): in C,
and in HLSL as FXC compiles it, a variable's scope begins at its declarator, before its
initialiser (C11 6.2.1 p7), so the name there is the variable being declared, and the
assignment inside sets it before the initialiser's value does. GLSL's scope begins after the
initialiser (GLSL 4.60 §4.2.2) and glslang's HLSL front end reads it so too: both refuse the
name as undeclared. Spelled as a declaration and then an assignment (``float4 color; color =
c ? color = a : b;``), which both languages take and which computes what FXC does; lines kept.
Only a declaration whose initialiser assigns the variable (``color = ...`` inside it: the value is
written before it is read either way) is spelled so -- a variable that only reads its own name
(``float3 n = normalize(n);`` in a block under a parameter ``n``) is left to the compilers, which
read the outer ``n`` -- and only one variable of a scalar, vector or matrix type, with no ``const``
(which cannot be assigned after) and no brace initialiser.

    text = declared_before_initialised(text)
"""

from __future__ import annotations

import re

_DECLARATION = re.compile(r"(?<![\w.])((?:float|half|fixed|int|uint|bool|min16float|real)(?:[1-4](?:x[1-4])?)?)"
                          r"(\s+)([A-Za-z_]\w*)(\s*)=([^;{}]*);")
_CONST = re.compile(r"\bconst\s*$")


def declared_before_initialised(text: str) -> str:
    """``text`` with each declaration whose initialiser names the variable itself split in two
    (module docstring)."""
    def spelled(m: re.Match) -> str:
        kind, gap, name, space, init = m.groups()
        if not re.search(rf"(?<![\w.]){re.escape(name)}\s*=(?!=)", init) or _CONST.search(text[max(0, m.start() - 40):m.start()]):
            return m.group(0)
        return f"{kind}{gap}{name}{space}; {name} ={init};"
    return _DECLARATION.sub(spelled, text)
