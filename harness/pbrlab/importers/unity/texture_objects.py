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
scaleTranslate.zw``); a cube, 2D-array or 3D texture object (``UnityTextureCube c =
UnityBuildTextureCubeStruct(_Cube)``, ``UnityTexture2DArray``, ``UnityTexture3D``), which holds
its texture and its sampler alone, likewise (``c.tex``, ``c.samplerstate``);
``UnitySamplerState s = UnityBuildSamplerStateStruct(x)`` likewise (``s.samplerstate`` is ``x``). A local used any other way (passed whole to a function) is
left as written, and the compilers name it. Lines are kept.

A Shader Graph sub-graph's function that takes a UnityTexture2D (``void SG_F(UnityTexture2D t,
...)``) is spelled out the same way first: the parameter becomes the texture, its sampler, its
texel size and its tiling (``TEXTURE2D_PARAM(t_tex, samplert_tex), float4 t_tex_TexelSize,
float4 t_tex_ST``), each call passes the object's four members in its place (which the rule
above then spells), and in the body ``t`` and each copy of it (``UnityTexture2D u = t;``) read
those parameters.
"""

from __future__ import annotations

import re

from .source_text import blank_comments, matching_brace, matching_paren

_TEXTURE = re.compile(r"\bUnityTexture2D\s+(\w+)\s*=\s*UnityBuildTexture2DStruct(NoScale)?\s*\(\s*(\w+)\s*\)\s*;")
# The texture objects without a texel size or tiling: a cube, a 2D array, a 3D texture.
_PLAIN_TEXTURE = re.compile(r"\bUnityTexture(?:Cube|2DArray|3D)\s+(\w+)\s*=\s*"
                            r"UnityBuildTexture(?:Cube|2DArray|3D)Struct\s*\(\s*(\w+)\s*\)\s*;")
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
    """(member pattern, its spelling) for a texture object ``name`` (``texture`` None: a sampler
    object; ``scale`` None: a texture object without texel size or tiling)."""
    out = [(re.compile(rf"\b{name}\s*\.\s*samplerstate\b"), sampler)]
    if texture is not None:
        out.append((re.compile(rf"\b{name}\s*\.\s*tex\b"), texture))
    if texture is not None and scale is not None:
        out += [(re.compile(rf"\b{name}\s*\.\s*texelSize\b"), f"{texture}_TexelSize"),
                (re.compile(rf"\b{name}\s*\.\s*scaleTranslate\b"), f"({scale})")]
    return out


def _spell_block(block: str, name: str, texture: str | None, scale: str, sampler: str) -> str | None:
    """``block`` (the text after the declaration) with ``name``'s members spelled out; None when
    ``name`` is also read some other way."""
    if texture is not None and scale is not None:
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


_VOID_FUNCTION = re.compile(r"\bvoid\s+(\w+)\s*\(")
_TEXTURE_PARAMETER = re.compile(r"^\s*UnityTexture2D\s+(\w+)\s*$")


def _split_arguments(text: str) -> list:
    """``text`` (between a call's or a signature's parentheses) split at its top-level commas."""
    out, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == "," and depth == 0:
            out.append(text[start:i])
            start = i + 1
    return [*out, text[start:]]


def _texture_parameter_functions(masked: str) -> dict:
    """{function: [index of each UnityTexture2D parameter]} of the void functions defined in ``masked``."""
    found = {}
    for m in _VOID_FUNCTION.finditer(masked):
        end = matching_paren(masked, m.end() - 1)
        if end < 0 or not masked[end + 1:].lstrip().startswith("{"):
            continue
        indices = [i for i, p in enumerate(_split_arguments(masked[m.end():end])) if _TEXTURE_PARAMETER.match(p)]
        if indices:
            found[m.group(1)] = indices
    return found


def _calls_spelled_out(text: str, functions: dict) -> str:
    """Each call of ``functions`` with its texture-object arguments (locals) passed as their four members."""
    for name, indices in functions.items():
        out, pos = [], 0
        for m in re.finditer(rf"\b{name}\s*\(", blank_comments(text)):
            if re.search(r"\bvoid\s*$", text[:m.start()]):
                continue  # the definition
            end = matching_paren(text, m.end() - 1)
            if end < 0:
                continue
            arguments = _split_arguments(text[m.end():end])
            for i in indices:
                a = arguments[i].strip() if i < len(arguments) else ""
                if re.fullmatch(r"\w+", a):
                    arguments[i] = arguments[i].replace(a, f"{a}.tex, {a}.samplerstate, {a}.texelSize, {a}.scaleTranslate")
            out += [text[pos:m.end()], ",".join(arguments)]
            pos = end
        text = "".join(out) + text[pos:]
    return text


def _parameters_spelled_out(text: str) -> str:
    """``text`` with each sub-graph function's UnityTexture2D parameters spelled out (module doc)."""
    functions = _texture_parameter_functions(blank_comments(text))
    if not functions:
        return text
    text = _calls_spelled_out(text, functions)
    for name, indices in functions.items():
        masked = blank_comments(text)
        m = re.search(rf"\bvoid\s+{name}\s*\(", masked)
        end = matching_paren(masked, m.end() - 1)
        parameters = _split_arguments(text[m.end():end])
        objects = []
        for i in indices:
            p = _TEXTURE_PARAMETER.match(parameters[i]).group(1)
            objects.append(p)
            parameters[i] = (f" TEXTURE2D_PARAM({p}_tex, sampler{p}_tex), float4 {p}_tex_TexelSize,"
                             f" float4 {p}_tex_ST")
        head = text[:m.end()] + ",".join(parameters) + ")"
        open_brace = masked.index("{", end)
        close = matching_brace(masked, open_brace)
        body = text[end + 1:close]
        for p in objects:
            for alias in re.finditer(rf"\bUnityTexture2D\s+(\w+)\s*=\s*{p}\s*;", blank_comments(body)):
                rest = _spell_block(body[alias.end():], alias.group(1), f"{p}_tex", f"{p}_tex_ST", f"sampler{p}_tex")
                if rest is not None:
                    body = body[:alias.start()] + " " * (alias.end() - alias.start()) + rest
            spelled = _spell_block(body, p, f"{p}_tex", f"{p}_tex_ST", f"sampler{p}_tex")
            body = body if spelled is None else spelled
        text = head + body + text[close:]
    return text


# A texture object's member read straight off its builder's call, with no local between
# (``UnityBuildTexture2DStructNoScale(_MainTex).tex``, as Shader Graph's Sample Texture 2D node
# writes it for a texture its graph does not name): the same members, spelled the same way.
_BUILT_MEMBER = re.compile(r"\bUnityBuildTexture2DStruct(NoScale)?\s*\(\s*(\w+)\s*\)\s*\.\s*"
                           r"(?=(?:tex|samplerstate|texelSize|scaleTranslate|GetTransformedUV)\b)")


def _built_members_spelled_out(text: str) -> str:
    """``text`` with each member read off a UnityBuildTexture2DStruct call spelled out."""
    while True:
        m = _BUILT_MEMBER.search(blank_comments(text))
        if m is None:
            return text
        texture = m.group(2)
        scale = _NO_SCALE if m.group(1) else f"{texture}_ST"
        # The call stands for a local of that name for one member read, which _spell_block spells.
        name = "pbrlab_built_texture_object"
        tail = text[m.end():]
        member = re.match(r"GetTransformedUV\s*\(", tail)
        end = matching_paren(tail, member.end() - 1) + 1 if member else re.match(r"\w+", tail).end()
        spelled = _spell_block(f"{name}.{tail[:end]}", name, texture, scale, f"sampler{texture}")
        text = text[:m.start()] + spelled + tail[end:]


def spelled_out(text: str) -> str:
    """``text`` with each Shader Graph texture or sampler object spelled out where it is read."""
    text = _built_members_spelled_out(_parameters_spelled_out(text))
    while True:
        masked = blank_comments(text)
        found = None
        for m in [*_TEXTURE.finditer(masked), *_PLAIN_TEXTURE.finditer(masked), *_SAMPLER.finditer(masked)]:
            if m.re is _TEXTURE:
                name, no_scale, texture = m.group(1), m.group(2), m.group(3)
                scale, sampler = (_NO_SCALE if no_scale else f"{texture}_ST"), f"sampler{texture}"
            elif m.re is _PLAIN_TEXTURE:
                name, texture, scale = m.group(1), m.group(2), None
                sampler = f"sampler{texture}"
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
