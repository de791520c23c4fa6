"""A global texture that HLSL samples with a comparison sampler only inside a function it is
passed to, typed as a comparison sampler in the GLSL spirv-cross writes.

glslang's ``--auto-sampled-textures`` combines each ``Texture2D`` global with its sampler as a
plain ``sampler2D`` unless the global itself is read by ``SampleCmp``; a function whose
parameter is so read gets a ``sampler2DShadow`` parameter. A call passing the global then has no
matching overload in GLSL (``F(sampler2D)`` against ``F(sampler2DShadow)``), though the HLSL is
valid (Microsoft's HLSL reference: a texture object may be passed to a function and sampled
there with a SamplerComparisonState). Such a global is declared here with the parameter's
comparison type, as if the global were read directly: a texture also read without comparison
then fails to compile in GLSL, naming the read.

    stages = same_shadow_globals({stage: typed_shadow_globals(glsl) ...})   # one type per global

A stage that does not read such a global still declares it (glslang keeps every global at -Od),
as a plain sampler: GLSL's linker refuses one uniform of two types, so each stage's declaration
takes the comparison type another stage's has.
"""

from __future__ import annotations

import re

from .source_text import call_arguments

_SHADOW = {"sampler2D": "sampler2DShadow", "sampler2DArray": "sampler2DArrayShadow", "samplerCube": "samplerCubeShadow"}
_GLOBAL = re.compile(r"^(.*\buniform\s+)(sampler2D|sampler2DArray|samplerCube)(\s+)(\w+)(\s*;)", re.M)
_DEFINITION = re.compile(r"^\w+\s+(\w+)\s*\(([^()]*)\)\s*$", re.M)
_SHADOW_PARAMETER = re.compile(r"^\s*(?:(?:in|const|highp|mediump|lowp)\s+)*(sampler2DShadow|sampler2DArrayShadow|samplerCubeShadow)\s+\w+\s*$")


def typed_shadow_globals(glsl: str) -> str:
    """``glsl`` with each plain sampler global passed where a function takes a comparison sampler
    declared with that comparison type."""
    shadow_parameters = {}  # function name -> {index: comparison type}
    for m in _DEFINITION.finditer(glsl):
        indices = {i: p.group(1) for i, parameter in enumerate(m.group(2).split(","))
                   if (p := _SHADOW_PARAMETER.match(parameter))}
        if indices:
            shadow_parameters.setdefault(m.group(1), {}).update(indices)
    if not shadow_parameters:
        return glsl
    plain = {m.group(4): m.group(2) for m in _GLOBAL.finditer(glsl)}
    compared = {}
    calls = re.compile(r"\b(" + "|".join(map(re.escape, shadow_parameters)) + r")\s*\(")
    for m in calls.finditer(glsl):
        found = call_arguments(glsl, m.end() - 1)
        args = found[0] if found else None
        for index, kind in shadow_parameters[m.group(1)].items():
            if args is not None and index < len(args) and plain.get(args[index]) and _SHADOW[plain[args[index]]] == kind:
                compared[args[index]] = kind
    return _retyped(glsl, compared)


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
