"""Texture lookups at a coordinate that is not finite, as Direct3D (Unity's default API) draws them.

Direct3D addresses texels after converting the coordinate to fixed point, and that conversion
turns NaN into 0 (Direct3D 10/11 "Data Conversion Rules", float to fixed point), so sampling a
finite texture never gives NaN. Mesa's llvmpipe filters with float weights: a NaN or infinite
coordinate gives a NaN colour. Unity shaders meet such coordinates where a value their C# script
sets is 0 without it: ``worldPos / worldPos.w`` with an unset inverse view-projection matrix
(0 / 0), a UV offset divided by an unset ``_waveWidth`` or ``_Downsample``, ``tex2Dproj`` of a
Projector's unset matrix (w = 0). In Unity they draw the texel; pbrlab drew NaN.

Both languages route each lookup's coordinate through ``pbr_unity_finite_coordinate``
(glsl/unity_compat/finite_texture_coordinate.glsl: NaN and infinite components -> 0):

* the GLSL port: cg_compat.glsl's tex2D family calls it (every port lookup is one of those);
* an HLSL program: the GLSL that spirv-cross writes is rewritten here (``applied``): the
  coordinate argument of each texture / textureLod / textureGrad / ...Offset / textureGather
  call is wrapped, and the function's definition put before the first declaration.
"""

from __future__ import annotations

import re

from ...gpu.shaders import GLSL_ROOT

FUNCTION = "pbr_unity_finite_coordinate"
HELPER = GLSL_ROOT / "unity_compat" / "finite_texture_coordinate.glsl"
# GLSL 4.60 8.9.2, "Texture Lookup Functions": those whose second argument is a float coordinate
# (texelFetch's is an integer texel address: no conversion to wrap)
_LOOKUP = re.compile(r"\b(?:texture|textureLod|textureGrad|textureOffset|textureLodOffset|"
                     r"textureGradOffset|textureGather|textureGatherOffset)\s*\(")


def _argument_spans(text: str, opening: int) -> tuple:
    """([(start, end)] of the top-level arguments of the call whose '(' is at ``opening``, the
    index of its ')')."""
    spans, depth, start = [], 0, opening + 1
    for i in range(opening, len(text)):
        c = text[i]
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
            if depth == 0:
                spans.append((start, i))
                return spans, i
        elif c == "," and depth == 1:
            spans.append((start, i))
            start = i + 1
    raise ValueError("unbalanced parentheses in a texture lookup")  # spirv-cross writes none


def wrapped(glsl: str) -> str:
    """``glsl`` with the coordinate (second argument) of each texture lookup passed through
    ``pbr_unity_finite_coordinate``; lookups nested in an argument are wrapped too."""
    out, pos = [], 0
    for m in _LOOKUP.finditer(glsl):
        if m.start() < pos:
            continue  # inside a lookup already rewritten (its arguments were recursed into)
        spans, close = _argument_spans(glsl, m.end() - 1)
        args = [wrapped(glsl[a:b]) for a, b in spans]
        if len(args) >= 2:
            args[1] = f" {FUNCTION}({args[1].strip()})"
        out += [glsl[pos:m.end()], ",".join(args), ")"]
        pos = close + 1
    out.append(glsl[pos:])
    return "".join(out)


def applied(glsl: str) -> str:
    """The GLSL spirv-cross wrote for an HLSL stage, each lookup's coordinate made finite as
    Direct3D's addressing makes it; unchanged if it samples nothing."""
    if _LOOKUP.search(glsl) is None:
        return glsl
    lines = wrapped(glsl).split("\n")
    # after the leading preprocessor lines (#version, #extension and their #ifdef guards)
    first = next((i for i, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")),
                 len(lines))
    return "\n".join(lines[:first] + [HELPER.read_text(encoding="utf-8")] + lines[first:])
