"""A program's own structs with texture or sampler members, spelled out (both languages):

    struct TextureInfo { TEXTURE2D(tex); SAMPLER(sampler_tex); float4 st; };
    float4 SampleInfo(TextureInfo info, float2 uv) { return SAMPLE_TEXTURE2D(info.tex, info.sampler_tex, uv); }
    ...
    TextureInfo info; info.tex = _MainTex; info.sampler_tex = sampler_MainTex; info.st = _MainTex_ST;
    return SampleInfo(info, i.uv);

FXC compiles such a struct because it inlines every function and resolves each texture member to
the global assigned to it. GLSL allows no opaque type (sampler) in a struct but a uniform's
(GLSL 3.30 section 4.1.7: samplers "can only be declared as function parameters or uniform
variables"), and spirv-cross refuses a struct of separate samplers (the HLSL path's
cross-compiler: "Attempting to use arrays or structs of separate samplers"). So, as FXC
resolves them:

- the struct keeps its other members; each texture or sampler member is dropped from it;
- a function taking the struct (``TextureInfo info``) takes each dropped member as a parameter
  of its own after it, declared as the member was (``TEXTURE2D(info_tex), SAMPLER(info_sampler_tex)``),
  and its body reads ``info.tex`` as ``info_tex``;
- in a function body, a local of the struct whose members are assigned (``info.tex =
  _MainTex;``) reads each member as the value assigned to it (the assignment is dropped), and a
  call of such a function passes, after the local, the values of its dropped members (or, for a
  parameter of the struct handed on, the parameters it was given).

A texture member read before it is assigned, or assigned twice, is left as written (the compilers
then name it). Lines are kept: a program's errors keep their lines.
"""

from __future__ import annotations

import re

from .source_text import blank_comments, matching_brace, matching_paren
from .texture_objects import _split_arguments

# A texture or sampler member: a Core RP declaration macro (D3D11.hlsl's TEXTURE2D(name) etc.)
# or HLSL's own type.
_MACRO_MEMBER = re.compile(r"\b(TEXTURE2D|TEXTURE2D_ARRAY|TEXTURECUBE|TEXTURECUBE_ARRAY|TEXTURE3D|TEXTURE2D_FLOAT|"
                           r"TEXTURE2D_HALF|TEXTURE2D_SHADOW|TEXTURE2D_ARRAY_SHADOW|TEXTURECUBE_SHADOW|SAMPLER|"
                           r"SAMPLER_CMP)\s*\(\s*(\w+)\s*\)\s*;")
_TYPE_MEMBER = re.compile(r"\b(Texture2D|Texture2DArray|TextureCube|TextureCubeArray|Texture3D|SamplerState|"
                          r"SamplerComparisonState)(\s*<[^;<>]*>)?\s+(\w+)\s*;")
_STRUCT = re.compile(r"\bstruct\s+(\w+)\s*\{")
_FUNCTION = re.compile(r"\b(\w+)\s+(\w+)\s*\(")
_KEYWORDS = {"if", "for", "while", "switch", "return", "else", "do"}


def _blank(text: str) -> str:
    return re.sub(r"[^\n]", " ", text)


def _opaque_structs(text: str) -> tuple[str, dict]:
    """(``text`` with each struct's texture and sampler members blanked, {struct: [(member,
    declaration template)]})."""
    masked = blank_comments(text)
    found, cuts = {}, []
    for m in _STRUCT.finditer(masked):
        end = matching_brace(masked, m.end() - 1)
        if end < 0:
            continue
        members = []
        for d in _MACRO_MEMBER.finditer(masked, m.end(), end):
            members.append((d.start(), d.group(2), d.group(1) + "({})", d.span()))
        for d in _TYPE_MEMBER.finditer(masked, m.end(), end):
            members.append((d.start(), d.group(3), d.group(1) + (d.group(2) or "") + " {}", d.span()))
        if members:
            members.sort()
            found[m.group(1)] = [(name, template) for _, name, template, _ in members]
            cuts += [span for *_, span in members]
    for start, end in sorted(cuts, reverse=True):
        text = text[:start] + _blank(text[start:end]) + text[end:]
    return text, found


def _functions(masked: str):
    """[(name, parameter list's "(" offset, its ")" offset, body "{" offset, body "}" offset)] of
    the functions defined in ``masked``."""
    out, inside = [], -1
    for m in _FUNCTION.finditer(masked):
        if m.start() <= inside:  # (a call in a body read before)
            continue
        if m.group(1) in _KEYWORDS or m.group(2) in _KEYWORDS or m.group(1) == "struct":
            continue
        close = matching_paren(masked, m.end() - 1)
        if close < 0:
            continue
        after = re.match(r"\s*(?::\s*\w+\s*)?\{", masked[close + 1:])
        if after is None:
            continue
        brace = close + after.end()
        end = matching_brace(masked, brace)
        if end >= 0:
            out.append((m.group(2), m.end() - 1, close, brace, end))
            inside = end
    return out


def _struct_parameters(params: str, structs: dict) -> list:
    """[(index, struct, name)] of the parameters of a struct in ``structs``."""
    out = []
    for i, p in enumerate(_split_arguments(params)):
        m = re.fullmatch(r"\s*(?:in\s+)?(\w+)\s+(\w+)\s*", p)
        if m and m.group(1) in structs:
            out.append((i, m.group(1), m.group(2)))
    return out


def _body_spelled(body: str, structs: dict, params: list, callees: dict) -> str:
    """A function's body (between its braces) with its struct parameters' and locals' texture
    members spelled out and its calls of ``callees`` ({function: [(index, struct)]}) given them."""
    values = {}  # a local or parameter of a struct -> {member: value}
    for _, struct, name in params:
        values[name] = {member: f"{name}_{member}" for member, _ in structs[struct]}
    kinds = {name: struct for _, struct, name in params}
    masked = blank_comments(body)
    for m in re.finditer(r"\b(\w+)\s+(\w+)\s*(?:=[^;]*)?;", masked):
        if m.group(1) in structs:
            kinds[m.group(2)] = m.group(1)
            values.setdefault(m.group(2), {})
    for local, struct in kinds.items():
        for member, _ in structs[struct]:
            read = re.compile(rf"\b{local}\s*\.\s*{member}\b")
            if values[local].get(member) is None:  # a local: the value its one assignment gives
                assigned = list(re.finditer(rf"\b{local}\s*\.\s*{member}\s*=\s*([^;=][^;]*);", blank_comments(body)))
                if len(assigned) != 1:
                    continue
                a = assigned[0]
                values[local][member] = a.group(1).strip()
                body = body[:a.start()] + _blank(body[a.start():a.end()]) + body[a.end():]
            body = read.sub(values[local][member], body)
    for function, indices in callees.items():
        out, pos = [], 0
        for m in re.finditer(rf"\b{function}\s*\(", blank_comments(body)):
            end = matching_paren(body, m.end() - 1)
            if end < 0:
                continue
            arguments = _split_arguments(body[m.end():end])
            for i, struct in reversed(indices):
                a = arguments[i].strip() if i < len(arguments) else ""
                given = values.get(a, {})
                if kinds.get(a) == struct and all(member in given for member, _ in structs[struct]):
                    arguments[i] += ", " + ", ".join(given[member] for member, _ in structs[struct])
            out += [body[pos:m.end()], ",".join(arguments)]
            pos = end
        body = "".join(out) + body[pos:]
    return body


def spelled_out(text: str) -> str:
    """``text`` with its structs' texture and sampler members spelled out (module docstring);
    a text without such a struct unchanged."""
    if not (_MACRO_MEMBER.search(text) or _TYPE_MEMBER.search(text)):
        return text
    text, structs = _opaque_structs(text)
    if not structs:
        return text
    masked = blank_comments(text)
    functions = _functions(masked)
    callees = {}
    for name, open_, close, _, _ in functions:
        found = _struct_parameters(masked[open_ + 1:close], structs)
        if found:
            callees[name] = [(i, struct) for i, struct, _ in found]
    # from the last function to the first, so that each one's offsets hold
    for name, open_, close, brace, end in reversed(functions):
        params = _struct_parameters(masked[open_ + 1:close], structs) if name in callees else []
        body = _body_spelled(text[brace + 1:end], structs, params, callees)
        signature = text[open_ + 1:close]
        if params:
            arguments = _split_arguments(signature)
            for i, struct, pname in reversed(params):
                arguments[i] += ", " + ", ".join(template.format(f"{pname}_{member}")
                                                 for member, template in structs[struct])
            signature = ",".join(arguments)
        text = text[:open_ + 1] + signature + text[close:brace + 1] + body + text[end:]
    return text
