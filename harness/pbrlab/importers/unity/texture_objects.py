"""Shader Graph's texture objects spelled out (a URP program's text, both languages).

Shader Graph's generated code reads a texture property through a local struct::

    UnityTexture2D t = UnityBuildTexture2DStructNoScale(_MainTex);
    float4 c = SAMPLE_TEXTURE2D(t.tex, t.samplerstate, t.GetTransformedUV(uv));

A struct that holds a texture and a sampler is what neither GLSL (no samplers in a local
struct) nor spirv-cross (no structs of separate samplers; the HLSL path's cross-compiler) can
carry, so each such local is spelled out where it is read: ``t.tex`` is the texture,
``t.samplerstate`` its sampler (``sampler_MainTex``), ``t.texelSize`` ``_MainTex_TexelSize``,
``t.scaleTranslate`` ``_MainTex_ST`` (NoScale: tiling 1, offset 0) and ``t.GetTransformedUV(uv)``
``uv`` tiled and offset by it (Core RP's Texture.hlsl: ``uv * scaleTranslate.xy +
scaleTranslate.zw``); ``UnitySamplerState s = UnityBuildSamplerStateStruct(x)`` likewise
(``s.samplerstate`` is ``x``). A local used any other way (passed whole to a function) is
left as written, and the compilers name it. Lines are kept.
"""

from __future__ import annotations

import re

from .source_text import blank_comments, matching_brace, matching_paren

_TEXTURE = re.compile(r"\bUnityTexture2D\s+(\w+)\s*=\s*UnityBuildTexture2DStruct(NoScale)?\s*\(\s*(\w+)\s*\)\s*;")
_SAMPLER = re.compile(r"\bUnitySamplerState\s+(\w+)\s*=\s*UnityBuildSamplerStateStruct\s*\(\s*(\w+)\s*\)\s*;")
_NO_SCALE = "float4(1.0, 1.0, 0.0, 0.0)"


def _block_end(masked: str, pos: int) -> int:
    """The end of the brace block that holds ``pos`` (the text's end at depth 0)."""
    depth = 0
    for i in range(pos, -1, -1):
        if masked[i] == "}":
            depth += 1
        elif masked[i] == "{":
            if depth == 0:
                end = matching_brace(masked, i)
                return end if end >= 0 else len(masked)
            depth -= 1
    return len(masked)


def _members(name: str, texture: str | None, scale: str, sampler: str):
    """(member pattern, its spelling) for a texture object ``name`` (``texture`` None: a sampler object)."""
    out = [(re.compile(rf"\b{name}\s*\.\s*samplerstate\b"), sampler)]
    if texture is not None:
        out += [(re.compile(rf"\b{name}\s*\.\s*tex\b"), texture),
                (re.compile(rf"\b{name}\s*\.\s*texelSize\b"), f"{texture}_TexelSize"),
                (re.compile(rf"\b{name}\s*\.\s*scaleTranslate\b"), f"({scale})")]
    return out


def _spell_block(block: str, name: str, texture: str | None, scale: str, sampler: str) -> str | None:
    """``block`` (the text after the declaration) with ``name``'s members spelled out; None when
    ``name`` is also read some other way."""
    if texture is not None:
        out, pos = [], 0
        call = re.compile(rf"\b{name}\s*\.\s*GetTransformedUV\s*\(")
        for m in call.finditer(block):
            if m.start() < pos:
                continue
            end = matching_paren(block, m.end() - 1)
            if end < 0:
                return None
            uv = block[m.end():end]
            out += [block[pos:m.start()], f"(({uv}) * ({scale}).xy + ({scale}).zw)"]
            pos = end + 1
        block = "".join(out) + block[pos:]
    for pattern, spelling in _members(name, texture, scale, sampler):
        block = pattern.sub(spelling, block)
    return None if re.search(rf"\b{name}\b", blank_comments(block)) else block


def spelled_out(text: str) -> str:
    """``text`` with each Shader Graph texture or sampler object spelled out where it is read."""
    while True:
        masked = blank_comments(text)
        found = None
        for m in [*_TEXTURE.finditer(masked), *_SAMPLER.finditer(masked)]:
            if m.re is _TEXTURE:
                name, no_scale, texture = m.group(1), m.group(2), m.group(3)
                scale, sampler = (_NO_SCALE if no_scale else f"{texture}_ST"), f"sampler{texture}"
            else:
                name, texture, scale, sampler = m.group(1), None, "", m.group(2)
            end = _block_end(masked, m.start())
            spelled = _spell_block(text[m.end():end], name, texture, scale, sampler)
            if spelled is not None:
                found = text[:m.start()] + spelled + text[end:]  # the declaration (one line) dropped
                break
        if found is None:
            return text
        text = found
