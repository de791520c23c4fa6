"""The preprocessor's conditionals, as the compiler will take them, for the model of a
program: which struct members, which function bodies exist in the variant that runs.

    text = active_text(masked, defines_of(masked, pragma_target))

Lines in a branch not taken are blanked (offsets and line numbers kept). Conditions are
evaluated with the program's own object-like ``#define``s, Unity's predefined macros
(``UNITY_VERSION`` 2019.4, ``SHADER_TARGET`` from ``#pragma target``, the platform's
``SHADER_API_GLCORE``: graphics_api.py) and no keyword (Unity's
default variant; the material's keywords are added by the caller). A condition this reader
cannot evaluate counts as true, as the reader did before it knew conditionals.
"""

from __future__ import annotations

import re

from .graphics_api import API_MACRO

_DIRECTIVE = re.compile(r"^[ \t]*#[ \t]*(if|ifdef|ifndef|elif|else|endif|define|undef)\b([^\n]*)$", re.M)
UNITY_PREDEFINED = {"UNITY_VERSION": 201940, "SHADER_TARGET": 25, API_MACRO: 1}
# The UNITY_VERSION a Universal Render Pipeline program is compiled with (Unity defines it for
# every program, the version's digits: 2021.3 -> 202130, as 2019.4 -> 201940; Unity's manual,
# "Built-in shader macros"): the Unity of URP 12.1,
# the version pbrlab's URP stand-ins follow (Core.hlsl's SHADER_LIBRARY_VERSION), so a program's
# ``#if UNITY_VERSION >= 202120`` takes the branch written for URP 12's functions, as in that
# Unity. (The built-in pipeline's programs are read with UNITY_PREDEFINED's 2019.4.)
URP_UNITY_VERSION = 202130


def defines_of(text: str, keywords=(), srp: bool = False) -> dict:
    """Unity's predefined macros for ``text`` (its #pragma target) and ``keywords``, with
    URP_UNITY_VERSION for a Scriptable Render Pipeline program (``srp``); the text's own
    #defines take effect where ``active_text`` meets them, in order."""
    out = dict(UNITY_PREDEFINED)
    if srp:
        out["UNITY_VERSION"] = URP_UNITY_VERSION
    m = re.search(r"^[ \t]*#[ \t]*pragma[ \t]+target[ \t]+(\d+)(?:\.(\d))?", text, re.M)
    if m:
        out["SHADER_TARGET"] = int(m.group(1)) * 10 + int(m.group(2) or 0)
    out.update({k: 1 for k in keywords})
    return out


def _evaluate(condition: str, defines: dict):
    """True/False, or None when the condition is beyond this reader."""
    expr = re.sub(r"//.*", "", condition).strip()
    expr = re.sub(r"\bdefined\s*\(\s*(\w+)\s*\)|\bdefined\s+(\w+)",
                  lambda m: "1" if (m.group(1) or m.group(2)) in defines else "0", expr)
    expr = re.sub(r"\b[A-Za-z_]\w*\b", lambda m: str(defines.get(m.group(0), 0)), expr)
    expr = expr.replace("&&", " and ").replace("||", " or ")
    # C's bitwise | & ^ (TextMesh Pro's ``#if (UNDERLAY_ON | UNDERLAY_INNER)``): Python takes
    # them as C does beside and/or, but binds them tighter than a comparison and looser than a
    # unary ``not`` (C: the other way round both), so with either of those beside them the
    # condition is beyond this reader
    bitwise = re.search(r"[|&^]", expr)
    if bitwise and re.search(r"[<>=]|!(?!=)", expr):
        return None
    expr = re.sub(r"!(?!=)", " not ", expr)
    if not re.fullmatch(r"[\d\s()<>=!+\-*/|&^andort]*", expr):
        return None
    try:
        return bool(eval(expr, {"__builtins__": {}}, {}))  # digits, comparisons, and/or/not only
    except Exception:
        return None


def _define_value(value: str, defines: dict) -> int:
    """The number an object-like ``#define`` stands for in a later ``#if``: its integer, the
    value of the macro it names (``#define SKYBOX_SUNDISK SKYBOX_SUNDISK_HQ``), the value of a
    condition it spells (``#define USING_FOG (defined(FOG_LINEAR) || defined(FOG_EXP))``, taken
    with the macros defined where it is defined), else 1."""
    if re.fullmatch(r"-?\d+", value):
        return int(value)
    if re.fullmatch(r"[A-Za-z_]\w*", value) and value in defines:
        return defines[value]
    if re.search(r"\bdefined\b", value):
        condition = _evaluate(value, defines)
        if condition is not None:
            return int(condition)
    return 1


def active_text(text: str, defines: dict) -> str:
    """``text`` with the lines of branches not taken blanked (their #define and #undef lines too)."""
    out, pos = [], 0
    defines = dict(defines)
    stack = []   # [(this branch taken, some branch taken, parent active)]
    active = True
    for m in _DIRECTIVE.finditer(text):
        chunk = text[pos:m.start()]
        out.append(chunk if active else re.sub(r"[^\n]", " ", chunk))
        kind, rest = m.group(1), m.group(2)
        if kind in ("define", "undef"):
            d = re.match(r"[ \t]+(\w+)(\()?[ \t]*(.*)", rest)
            if active and d:
                if kind == "undef":
                    defines.pop(d.group(1), None)
                else:
                    value = "" if d.group(2) else re.sub(r"//.*", "", d.group(3)).strip()
                    defines[d.group(1)] = _define_value(value, defines)
        elif kind in ("if", "ifdef", "ifndef"):
            if kind == "if":
                value = _evaluate(rest, defines)
            else:
                name = rest.split()[0] if rest.split() else ""
                value = (name in defines) == (kind == "ifdef")
            taken = True if value is None else value
            stack.append((taken, taken, active))
            active = active and taken
        elif kind == "elif" and stack:
            _, any_taken, parent = stack[-1]
            value = _evaluate(rest, defines)
            taken = not any_taken and (True if value is None else value)
            stack[-1] = (taken, any_taken or taken, parent)
            active = parent and taken
        elif kind == "else" and stack:
            _, any_taken, parent = stack[-1]
            stack[-1] = (not any_taken, True, parent)
            active = parent and not any_taken
        elif kind == "endif" and stack:
            _, _, parent = stack.pop()
            active = parent
        # a #define or #undef in a branch not taken is blanked too (a macro defined in each
        # branch: a reader of the text sees the drawn variant's definition alone)
        out.append(re.sub(r"[^\n]", " ", m.group(0)) if kind in ("define", "undef") and not active else m.group(0))
        pos = m.end()
    tail = text[pos:]
    out.append(tail if active else re.sub(r"[^\n]", " ", tail))
    return "".join(out)
