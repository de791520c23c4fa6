"""A project's own function-like macro that declares struct members with their semantics
(``#define MY_COORDS(i) half3 sh : TEXCOORD##i;``, used as ``MY_COORDS(5)`` in a vertex
output struct), expanded where the pass model reads the struct, so the member is a varying as
it is in Unity (the compiler sees the expansion: the member, its pasted semantic TEXCOORD5).

    body = expanded_member_macros(struct_body, text)

``text`` is the program and its includes with comments blanked and the drawn variant's
branches kept (conditionals.active_text): a macro defined under a branch not taken is not
seen, and an empty one (defined to nothing in that branch) declares nothing. Only macros whose
replacement declares a member with a semantic are expanded; any other call is left to the
caller (Unity's own LIGHTING_COORDS and the like, which the harness provides apart).
"""

from __future__ import annotations

import re

from .source_text import call_arguments

# ``#define NAME(a, b) replacement`` (continued lines joined by the caller's text: a backslash
# and the line break are read as one space)
_FUNCTION_MACRO = re.compile(r"^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)\(([^()]*)\)((?:[^\n\\]|\\\n|\\(?!\n))*)$", re.M)
# a member with a semantic (the semantic's index may be pasted from a parameter), its ``;`` in
# the replacement or left to the call (URP's DECLARE_LIGHTMAP_OR_SH(lm, sh, 1); ends at the semantic)
_SEMANTIC_MEMBER = re.compile(r"[A-Za-z_]\w*\s+[A-Za-z_]\w*(?:\s*\[\s*\w+\s*\])?\s*:\s*[A-Za-z_]\w*(?:\s*##\s*\w+)*\s*(?:;|$)")


def _member_macros(text: str) -> dict:
    """{name: (parameters, replacement)} of the function-like macros that declare members."""
    out = {}
    for m in _FUNCTION_MACRO.finditer(text):
        replacement = m.group(3).replace("\\\n", " ")
        if _SEMANTIC_MEMBER.search(replacement):
            out[m.group(1)] = ([p.strip() for p in m.group(2).split(",") if p.strip()], replacement.strip())
    return out


def _expansion(params: list, replacement: str, args: list) -> str:
    """The replacement with each parameter replaced by its argument, then ``##`` pasting (C's
    order: the operands of ``##`` are the arguments as written)."""
    values = dict(zip(params, (a.strip() for a in args)))
    spelled = re.sub(r"\b[A-Za-z_]\w*\b", lambda m: values.get(m.group(0), m.group(0)), replacement)
    return re.sub(r"\s*##\s*", "", spelled)


def expanded_member_macros(body: str, text: str) -> str:
    """``body`` (a struct's) with each call of a member-declaring macro of ``text`` expanded."""
    macros = _member_macros(text)
    if not macros:
        return body
    call = re.compile(r"\b(" + "|".join(map(re.escape, macros)) + r")\s*\(")
    out, pos = [], 0
    for m in call.finditer(body):
        if m.start() < pos:
            continue
        found = call_arguments(body, m.end() - 1)
        if found is None:
            continue
        args, end = found
        params, replacement = macros[m.group(1)]
        if len(args) != len(params) and not (not params and args == [""]):
            continue  # not the macro's form: left as written
        out += [body[pos:m.start()], _expansion(params, replacement, args)]
        pos = end
    return "".join(out) + body[pos:]
