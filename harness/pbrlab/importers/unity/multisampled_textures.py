"""Direct3D 10's multisampled texture objects in a Cg/HLSL program (``Texture2DMS<T> t;``,
``Texture2DMSArray<T> t;``): desktop OpenGL has them too (GLSL 1.50's ``sampler2DMS`` and
``sampler2DMSArray``, read one sample at a time by ``texelFetch(s, coord, sample)``, as
``t.Load(coord, sample)`` reads in HLSL), so the declaration is ported as such:

    code = declarations_ported(code)     # port.py, the GLSL port of a program's text
    read = first_read(active_program)    # engine_inputs: (name, offset) of a read in the drawn variant

What the harness cannot do is bind one: a material's textures are single-sampled 2D images, and
a multisampled texture holds what a multisampled render wrote (Unity binds its MSAA depth or
colour target). A program whose drawn variant reads one is refused by name (engine_inputs); one
that only declares it (Unity's own blits read theirs under ``SHADER_API_D3D11`` only, which the
harness, compiling as Unity's other platforms do, leaves undefined) runs, and the sampler, never
read, is compiled out.
"""

from __future__ import annotations

import re

_DECLARATION = re.compile(r"\b(Texture2DMS(?:Array)?)\s*<\s*\w+\s*(?:,\s*\d+\s*)?>\s*(\w+)\s*;")
_TRANSFORM_TEX = re.compile(r"\bTRANSFORM_TEX\s*\([^;()]*(?:\([^;()]*\)[^;()]*)*,\s*\w+\s*\)")
# HLSL object -> GLSL sampler type (GLSL 4.60 4.1.7, "Opaque Types": the float forms; the
# element type float/float4 is the same sampler type in GLSL, which reads a vec4)
GLSL_SAMPLER = {"Texture2DMS": "sampler2DMS", "Texture2DMSArray": "sampler2DMSArray"}


def declared(program: str) -> dict:
    """{name: HLSL object type} of the multisampled textures ``program`` declares."""
    return {m.group(2): m.group(1) for m in _DECLARATION.finditer(program)}


def first_read(active_program: str):
    """(name, offset) of the first use of a declared multisampled texture other than its
    declaration in ``active_program`` (comments and branches not drawn blanked); None if none."""
    # TRANSFORM_TEX(uv, name) reads name_ST (a token paste), not the texture
    spans = [(m.start(), m.end()) for m in _DECLARATION.finditer(active_program)]
    spans += [(m.start(), m.end()) for m in _TRANSFORM_TEX.finditer(active_program)]
    names = declared(active_program)
    if not names:
        return None
    pattern = re.compile(r"\b(" + "|".join(map(re.escape, names)) + r")\b")
    for m in pattern.finditer(active_program):
        if not any(a <= m.start() < b for a, b in spans):
            return m.group(1), m.start()
    return None


def declarations_ported(code: str) -> str:
    """``code`` with each multisampled texture declaration spelled as GLSL's sampler (uniform)."""
    return _DECLARATION.sub(lambda m: f"uniform {GLSL_SAMPLER[m.group(1)]} {m.group(2)};", code)
