"""The comparison samplers of the GLSL spirv-cross writes from a Unity program's HLSL, typed per
texture as the GLSL port types them: by compared_textures.texture_reads of the program.

glslang's ``--auto-sampled-textures`` combines each ``Texture2D`` global with its sampler as a
plain ``sampler2D`` unless the global itself is read by ``SampleCmp``; a function whose
parameter is so read gets a ``sampler2DShadow`` parameter. A call passing the global then has no
matching overload in GLSL (``F(sampler2D)`` against ``F(sampler2DShadow)``), though the HLSL is
valid (Microsoft's HLSL reference: a texture object may be passed to a function and sampled
there with a SamplerComparisonState). And a global read both ways is two combined samplers,
``sampler2D t`` and ``sampler2DShadow t_1`` (or the other way round: spirv-cross numbers the
second it meets), a name no property binds. So:

* a global the program only compares is declared with the comparison type;
* a global it compares and reads plainly keeps its name as the plain sampler, and its comparison
  sampler is named compared_textures.compared_view(name), also where it is passed to a
  function's comparison sampler parameter (compared_textures.passed_views); shadow_maps.py
  binds the property's depths to it.

    stages = same_shadow_globals({stage: typed_shadow_globals(glsl, reads) ...})   # one type per global

A stage that does not read such a global still declares it (glslang keeps every global at -Od),
as a plain sampler: GLSL's linker refuses one uniform of two types, so each stage's declaration
takes the comparison type another stage's has.
"""

from __future__ import annotations

import re

from .compared_textures import TextureReads, compared_view, passed_views

_SHADOW = {"sampler2D": "sampler2DShadow", "sampler2DArray": "sampler2DArrayShadow", "samplerCube": "samplerCubeShadow"}
_PLAIN = {shadow: plain for plain, shadow in _SHADOW.items()}
_GLOBAL = re.compile(r"^(.*\buniform\s+)(sampler2D|sampler2DArray|samplerCube)(\s+)(\w+)(\s*;)", re.M)
_ANY_GLOBAL = re.compile(r"^(.*\buniform\s+)(sampler2D|sampler2DArray|samplerCube|sampler2DShadow|sampler2DArrayShadow|"
                         r"samplerCubeShadow)(\s+)(\w+)(\s*;)[^\n]*$", re.M)


def typed_shadow_globals(glsl: str, reads: TextureReads) -> str:
    """``glsl`` with each sampler global the program only compares (``reads``) declared with the
    comparison type, and each it also reads plainly split into its plain sampler and its
    comparison view."""
    glsl = passed_views(_split(glsl, reads.both), reads.both)
    compared = {m.group(4): _SHADOW[m.group(2)] for m in _GLOBAL.finditer(glsl) if reads.only_compared(m.group(4))}
    return _retyped(glsl, compared)


def _split(glsl: str, both) -> str:
    """Each global of ``both`` as its plain sampler under its name and its comparison view."""
    for name in sorted(both):
        found = [m for m in _ANY_GLOBAL.finditer(glsl) if re.fullmatch(re.escape(name) + r"(?:_\d+)?", m.group(4))]
        plain = next((m for m in found if m.group(2) in _SHADOW), None)
        shadow = next((m for m in found if m.group(2) in _PLAIN), None)
        if plain is None and shadow is None:
            continue  # the stage does not declare it
        renames = {}
        if plain is not None:
            renames[plain.group(4)] = name
        if shadow is not None:
            renames[shadow.group(4)] = compared_view(name)
        glsl = re.sub(r"\b(" + "|".join(map(re.escape, renames)) + r")\b", lambda r: renames[r.group(1)], glsl)
        if plain is None or shadow is None:  # the other one, declared beside it
            m = next(m for m in _ANY_GLOBAL.finditer(glsl) if m.group(4) in (name, compared_view(name)))
            other = (f"{m.group(1)}{_SHADOW[m.group(2)]}{m.group(3)}{compared_view(name)}{m.group(5)}" if shadow is None
                     else f"{m.group(1)}{_PLAIN[m.group(2)]}{m.group(3)}{name}{m.group(5)}")
            glsl = glsl[:m.end()] + "\n" + other + glsl[m.end():]
    return glsl


def _retyped(glsl: str, compared: dict) -> str:
    if not compared:
        return glsl
    return _GLOBAL.sub(lambda g: (f"{g.group(1)}{compared[g.group(4)]}{g.group(3)}{g.group(4)}{g.group(5)}"
                                  if compared.get(g.group(4)) == _SHADOW[g.group(2)] else g.group(0)), glsl)


_COMPARED_GLOBAL = re.compile(r"^.*\buniform\s+(sampler2DShadow|sampler2DArrayShadow|samplerCubeShadow)\s+(\w+)\s*;", re.M)


def same_shadow_globals(stages: dict) -> dict:
    """{stage: glsl} with every global that some stage declares as a comparison sampler declared
    so in each stage."""
    compared = {m.group(2): m.group(1) for glsl in stages.values() for m in _COMPARED_GLOBAL.finditer(glsl)}
    return {stage: _retyped(glsl, compared) for stage, glsl in stages.items()}
