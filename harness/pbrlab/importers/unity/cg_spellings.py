"""Two forms of Cg that Unity's compiler (FXC, with its backwards-compatibility mode) takes and
glslang's HLSL front end and GLSL do not, spelled as both take them before either compiles a
program (offsets and lines kept):

- ``const static T x = ...;``: the qualifiers in the other order, ``static const``; glslang does
  not take the first as a constant expression (an array sized by it is refused);
- ``switch (e)`` on a float ``e``: HLSL converts the selector to int (truncation toward zero,
  FXC's float-to-int), GLSL and glslang require an integer: ``switch (int(e))``, which is the
  same selector for an int ``e`` (a constructor cast: both languages take ``int(e)``);
- ``#pragma instancing_options procedural:setup``: Unity calls ``setup()`` only in the
  procedural-instancing variant (``UNITY_PROCEDURAL_INSTANCING_ENABLED``, drawn by
  DrawMeshInstancedIndirect), where it may assign the per-instance matrices to
  ``unity_ObjectToWorld`` (FXC's compatibility mode lets a program write a global; glslang and
  GLSL refuse a write to a uniform). The harness draws the default variant, which never calls
  it: its body is blanked (lines kept), leaving an empty function;
- HLSLSupport.cginc's flow-control hints (``UNITY_UNROLL for (...)``, ``UNITY_BRANCH if``,
  ``UNITY_UNROLLX(4)``, ...): attributes on Direct3D, nothing on Unity's GLSL targets; blanked
  (a hint, never a change of what is computed), so the Cg type pass reads the statement after
  it (it did not: the literals of such a function kept their ``h`` suffixes in GLSL).

    text = respelled(cg_text)
"""

from __future__ import annotations

import re

from .source_text import matching_paren

_CONST_STATIC = re.compile(r"\bconst(\s+)static\b")
_SWITCH = re.compile(r"\bswitch\s*\(")
_FLOW_HINT = re.compile(r"\bUNITY_(?:BRANCH|FLATTEN|UNROLL|LOOP|FASTOPT)\b|\bUNITY_UNROLLX\s*\(\s*\w+\s*\)")


_PROCEDURAL = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+instancing_options\b[^\n]*\bprocedural:(\w+)", re.M)


def _blank_procedural_setup(text: str) -> str:
    """The body of the procedural-instancing setup function ``#pragma instancing_options``
    names, blanked (its braces and line breaks kept)."""
    m = _PROCEDURAL.search(text)
    if m is None:
        return text
    fn = re.search(r"\bvoid\s+" + re.escape(m.group(1)) + r"\s*\(\s*\)\s*\{", text)
    if fn is None:
        return text
    depth, start = 0, fn.end() - 1
    for i in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            body = re.sub(r"[^\n]", " ", text[start + 1:i])
            return text[:start + 1] + body + text[i:]
    return text


def respelled(text: str) -> str:
    """``text`` with ``const static`` as ``static const``, each ``switch`` selector cast to int,
    a procedural-instancing setup function's body and Unity's flow-control hints blanked."""
    text = _blank_procedural_setup(_CONST_STATIC.sub(lambda m: f"static{m.group(1)}const", text))
    text = _FLOW_HINT.sub(lambda m: " " * len(m.group(0)), text)
    out, pos = [], 0
    for m in _SWITCH.finditer(text):
        if m.start() < pos:
            continue
        close = matching_paren(text, m.end() - 1)
        if close < 0:
            continue
        selector = text[m.end():close]
        if re.fullmatch(r"\s*int\s*\(.*\)\s*", selector, re.S):
            continue  # already an int
        out += [text[pos:m.end()], f"int({selector})"]
        pos = close
    return "".join(out) + text[pos:]
