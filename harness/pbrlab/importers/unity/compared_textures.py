"""Which textures a Unity program reads through a comparison sampler, and which it reads plainly,
by name: the one decision both languages type their shadow textures by.

HLSL types a comparison per read, not per texture: Core RP's ``TEXTURE2D_SHADOW(t)`` is a plain
``Texture2D`` on Direct3D 11 (Core RP's API/D3D11.hlsl), which ``SAMPLE_TEXTURE2D_SHADOW(t, s,
coord3)`` reads with a ``SamplerComparisonState`` and ``SAMPLE_TEXTURE2D(t, s2, uv)`` with a
``SamplerState``; a ``Texture2D`` may be read both ways (Microsoft's HLSL reference,
"Texture2D": any sampler object with any method). GLSL types the sampler: ``sampler2DShadow``
compares and only compares (no ``texture(sampler2DShadow, vec2)``, no ``texelFetch``), so each
texture is typed by its own reads:

* compared only: a comparison sampler (``sampler2DShadow``; shadow_maps.py binds its depths);
* read plainly only (also one declared ``TEXTURE2D_SHADOW``): a plain sampler;
* both: two views of the one texture, the plain sampler under the texture's name and a
  comparison sampler named ``compared_view(name)``, which the comparisons read; pbrlab binds the
  property's texture to the first and its depths (a depth texture, comparison on) to the second.

A read through a function the texture is passed to counts as the function's parameter's reads
(``float F(TEXTURE2D_SHADOW_PARAM(map, s), ...)`` that compares ``map`` makes a texture passed
by ``F(TEXTURE2D_SHADOW_ARGS(_M, s_M), ...)`` or ``F(_M, s_M, ...)`` compared), through any
depth of calls. Names are not scoped: a parameter name's reads are its reads in every function
that has the parameter.

    reads = texture_reads(program + "\\n" + included)   # comments may be in; blanked here
    reads.compared, reads.plain, reads.both
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .source_text import blank_comments, call_arguments, matching_brace, matching_paren


def compared_view(name: str) -> str:
    """The comparison sampler's name of a texture that is also read plainly (the plain sampler
    keeps the texture's name, which the material's property binds)."""
    return f"{name}_pbrlab_compared"


# A comparison read: Core RP's SAMPLE_*_SHADOW (the texture first), a texture object's
# SampleCmp / SampleCmpLevelZero.
_COMPARED_MACRO = re.compile(r"\bSAMPLE_(?:TEXTURE2D|TEXTURE2D_ARRAY|TEXTURECUBE)_SHADOW\s*\(\s*(\w+)\s*,")
_COMPARED_METHOD = re.compile(r"\b(\w+)\s*\.\s*SampleCmp(?:LevelZero)?\s*\(")
# A plain read: Core RP's sampling and load macros, Cg's functions, a texture object's other
# methods (the texture first or the object before the dot).
_PLAIN_MACRO = re.compile(
    r"\b(?:SAMPLE_TEXTURE2D(?:_X)?(?:_LOD|_BIAS|_GRAD)?|SAMPLE_DEPTH_TEXTURE(?:_LOD)?|LOAD_TEXTURE2D(?:_X)?(?:_LOD)?|"
    r"SAMPLE_TEXTURE2D_ARRAY(?:_LOD)?|tex2D(?:lod|bias|grad|proj)?|UNITY_SAMPLE_TEX2D(?:_SAMPLER)?(?:_LOD)?)\s*\(\s*(\w+)\s*,")
_PLAIN_METHOD = re.compile(r"\b(\w+)\s*\.\s*(?:Sample|SampleLevel|SampleBias|SampleGrad|Load|Gather(?!Cmp)\w*)\s*\(")
# The stand-ins' (or a program's copy of Core RP's) definitions of the API's macros: not reads.
_API_DEFINITION = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(?:SAMPLE_TEXTURE\w*|SAMPLE_DEPTH_TEXTURE\w*|LOAD_TEXTURE\w*|"
                             r"TEXTURE(?:2D|CUBE|3D)\w*|SAMPLER|SAMPLER_CMP|tex2D\w*|UNITY_SAMPLE_\w*|UNITY_DECLARE_\w*)\b"
                             r"(?:[^\n]*\\\n)*[^\n]*", re.M)
# A function's definition: its name and the '(' of its parameters (a ')' and '{' follow).
_DEFINITION = re.compile(r"\b\w+\s+(\w+)\s*\(")
# Core RP's parameter and argument macros, a texture and its sampler: two of a function's
# parameters or a call's arguments
_PAIR = re.compile(r"^\w+_(?:PARAM|ARGS)\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)$")
_KEYWORDS = {"if", "for", "while", "switch", "return", "else", "do"}


@dataclass(frozen=True)
class TextureReads:
    compared: frozenset
    plain: frozenset

    @property
    def both(self) -> frozenset:
        return self.compared & self.plain

    def only_compared(self, name: str) -> bool:
        return name in self.compared and name not in self.plain


def _names(items: list) -> list:
    """A parameter or argument list's names, one a slot (a PARAM/ARGS macro two; an expression
    that is not a name: None)."""
    out = []
    for item in items:
        pair = _PAIR.match(item)
        if pair:
            out += [pair.group(1), pair.group(2)]
        else:
            last = re.search(r"(\w+)\s*$", item)
            out.append(last.group(1) if last else None)
    return out


def _functions(code: str) -> list:
    """(name, [parameter names], the name's offset) of each function ``code`` defines."""
    found = []
    for m in _DEFINITION.finditer(code):
        if m.group(1) in _KEYWORDS:
            continue
        close = matching_paren(code, m.end() - 1)
        if close < 0:
            continue
        after = re.match(r"\s*(?::\s*\w+\s*)?\{", code[close + 1:])  # (a semantic before the body)
        if not after:
            continue
        open_ = close + after.end()
        end = matching_brace(code, open_)
        if end < 0:
            continue
        params = call_arguments(code, m.end() - 1)
        found.append((m.group(1), _names(params[0]) if params else [], m.start(1)))
    return found


def texture_reads(text: str) -> TextureReads:
    """The names ``text`` (a program with the files it includes) reads through a comparison and
    plainly, also through the functions it passes them to."""
    code = _API_DEFINITION.sub(lambda d: " " * len(d.group(0)), blank_comments(text))
    compared = set(_COMPARED_MACRO.findall(code)) | set(_COMPARED_METHOD.findall(code))
    plain = set(_PLAIN_MACRO.findall(code)) | set(_PLAIN_METHOD.findall(code))
    functions = _functions(code)
    parameters = {}  # function name -> its parameter lists (overloads: each)
    for name, params, _ in functions:
        parameters.setdefault(name, []).append(params)
    defined_at = {at for _, _, at in functions}
    calls = []  # (callee, [argument names])
    if parameters:
        call = re.compile(r"\b(" + "|".join(map(re.escape, parameters)) + r")\s*\(")
        for m in call.finditer(code):
            found = call_arguments(code, m.end() - 1)
            if found is not None and m.start() not in defined_at:
                calls.append((m.group(1), _names(found[0])))
    changed = True
    while changed:  # a texture passed where a parameter is read takes the parameter's reads
        changed = False
        for callee, args in calls:
            for params in parameters[callee]:
                if len(params) != len(args):
                    continue
                for param, arg in zip(params, args):
                    for reads in (compared, plain):
                        if arg and param in reads and arg not in reads:
                            reads.add(arg)
                            changed = True
    return TextureReads(frozenset(compared), frozenset(plain))


# GLSL (the port's, spirv-cross's): a function definition's name and parameter list, and a
# comparison sampler parameter in it
_GLSL_DEFINITION = re.compile(r"\b\w+\s+(\w+)\s*\(([^()]*)\)\s*\{")
_GLSL_SHADOW_PARAMETER = re.compile(r"^\s*(?:(?:in|const|highp|mediump|lowp)\s+)*"
                                    r"(sampler2DShadow|sampler2DArrayShadow|samplerCubeShadow)\s+\w+\s*$")


def passed_views(glsl: str, both) -> str:
    """``glsl`` with each texture of ``both`` (read plainly and compared) passed as its
    comparison view where a function takes a comparison sampler."""
    if not both:
        return glsl
    shadow_parameters = {}  # function name -> indices of its comparison sampler parameters
    for m in _GLSL_DEFINITION.finditer(glsl):
        indices = {i for i, p in enumerate(m.group(2).split(",")) if _GLSL_SHADOW_PARAMETER.match(p)}
        if indices:
            shadow_parameters.setdefault(m.group(1), set()).update(indices)
    if not shadow_parameters:
        return glsl
    call = re.compile(r"\b(" + "|".join(map(re.escape, shadow_parameters)) + r")\s*\(")
    out, pos = [], 0
    for m in call.finditer(glsl):
        found = call_arguments(glsl, m.end() - 1)
        if m.start() < pos or found is None:
            continue
        args, end = found
        if not any(i < len(args) and args[i] in both for i in shadow_parameters[m.group(1)]):
            continue
        args = [compared_view(a) if i in shadow_parameters[m.group(1)] and a in both else a for i, a in enumerate(args)]
        spelled = f"{m.group(1)}(" + ", ".join(args) + ")"
        spelled += "\n" * (glsl.count("\n", m.start(), end) - spelled.count("\n"))
        out += [glsl[pos:m.start()], spelled]
        pos = end
    return "".join(out) + glsl[pos:]
