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
  it (it did not: the literals of such a function kept their ``h`` suffixes in GLSL);
- a program's own macro whose whole body is such attributes (URP's SMAA include:
  ``#define SMAA_FLATTEN [flatten]``, then ``SMAA_FLATTEN if (...)``): blanked in the
  definition, as Unity's own hints are (GLSL has no attribute syntax: the port refused
  ``unexpected '['`` where the macro was used);
- Unity 5.3's names of the object matrices, ``_Object2World`` and ``_World2Object``: Unity 5.4
  renamed them ``unity_ObjectToWorld`` / ``unity_WorldToObject`` and its shader upgrader rewrites
  a program that still spells them so (Unity 5.4 release notes, "Shaders: ... automatically
  upgraded"); the same rewrite here;
- HLSL's multi-element matrix swizzle ``M._m03_m13_m23``: glslang reads one component; spelled
  ``float3(M._m03, M._m13, M._m23)`` (``_MATRIX_SWIZZLE``);
- Cg's four-argument ``tex2D(s, uv, dx, dy)``: ``tex2Dgrad``, the same lookup (``_TEX2D``);
- HLSL's template spellings of the vector and matrix types, ``vector<bool, 3>`` and
  ``matrix<float, 4, 4>``: the short names, ``bool3`` and ``float4x4`` (the same types);
- an OpenGL extension's macro tested by a conditional (``#ifdef GL_ARB_gpu_shader5``, NVIDIA's
  FXAA 3.11 in Unity's PostProcessing): Unity preprocesses a Cg program as HLSL, where no GL_
  macro is defined, whatever the target; Mesa and glslang predefine the extensions they
  support, which turned FXAA's gather path on (a function only its GLSL 1.30 and HLSL 5
  branches define). Spelled ``PBRLAB_UNITY_NO_GL_...``, a name nothing defines (``_GL_TESTED``);
- a variable a for statement declares, used after the loop: FXC's scope, the enclosing block
  (loop_scope);
- UnityCG.cginc's legacy depth macros on a code line: ``UNITY_OUTPUT_DEPTH(i)`` as ``return 0``
  and ``UNITY_TRANSFER_DEPTH(o)`` as nothing, Unity's definitions (UnityCGPacking.cginc's
  stand-in defines them so too), written out before the GLSL port's type pass so that it
  converts the 0 to the fragment's return type (``return vec4(0)``), as HLSL converts a scalar;
- a function the program defines under the name of one of UnityCG.cginc's (or another include's
  pbrlab always compiles: ``ComputeScreenPos`` written out in a program that includes nothing):
  Unity compiles only the includes a program names, so there it is the program's own function;
  pbrlab's program always holds its Unity layer, so the program's function and its calls are
  renamed ``pbrlab_program_<name>`` (a program that includes UnityCG.cginc and defines the same
  overload again is refused by Unity's compiler too: a redefinition).

    text = respelled(cg_text)
"""

from __future__ import annotations

import functools
import re

from . import combined_samplers
from .flat_array_initialisers import grouped_flat_initialisers
from .loop_scope import loop_variables_in_enclosing_scope
from .sample_offsets import specialised_offsets
from .self_initialisers import declared_before_initialised
from .source_text import call_arguments, matching_paren

_CONST_STATIC = re.compile(r"\bconst(\s+)static\b")
_SWITCH = re.compile(r"\bswitch\s*\(")
_UPGRADED_NAMES = {"_Object2World": "unity_ObjectToWorld", "_World2Object": "unity_WorldToObject"}
_UPGRADED = re.compile(r"\b(" + "|".join(_UPGRADED_NAMES) + r")\b")
_TEMPLATE_TYPE = re.compile(r"\b(?:vector\s*<\s*(\w+)\s*,\s*([1-4])\s*>|matrix\s*<\s*(\w+)\s*,\s*([1-4])\s*,\s*([1-4])\s*>)")
# a conditional's test of an OpenGL macro (GL_ES, GL_ARB_..., GL_NV_...), not its #define
_GL_TESTED = re.compile(r"^([ \t]*#[ \t]*(?:if|ifdef|ifndef|elif)\b[^\n]*)", re.M)
# (a code line's use, not the stand-in's #define of the name)
_LEGACY_DEPTH = re.compile(r"^(?![ \t]*#)([^\n]*?)\b(UNITY_OUTPUT_DEPTH|UNITY_TRANSFER_DEPTH)\s*\((?:[^()\n]|\([^()\n]*\))*\)", re.M)
# HLSL's flow-control attributes (Microsoft's HLSL reference, "if Statement", "for Statement",
# "switch Statement": branch, flatten, unroll(n), loop, fastopt, allow_uav_condition, forcecase,
# call), as the whole body of an object-like #define: the body (group 1) is blanked.
_ATTRIBUTE_MACRO = re.compile(r"^[ \t]*#[ \t]*define[ \t]+[A-Za-z_]\w*[ \t]+((?:\[[ \t]*(?:branch|flatten|unroll|loop|fastopt|"
                              r"allow_uav_condition|forcecase|call)[ \t]*(?:\([^()\n]*\))?[ \t]*\][ \t]*)+)$", re.M | re.I)
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


_DEFINITION = re.compile(r"^[ \t]*(?:inline[ \t]+)?[A-Za-z_]\w*[ \t]+([A-Za-z_]\w*)[ \t]*\(([^;{}()]*)\)"
                         r"(?:\s*:\s*\w+)?\s*\{", re.M)
_PARAM_WORDS = {"in", "out", "inout", "uniform", "const"}
# Core RP's precision type ``real`` (real2..real4, real3x3...): its Common.hlsl defines it as
# float unless REAL_IS_HALF, which only a mobile platform's half-precision hint sets (not GLCore:
# graphics_api), so a project's own copy of Common.hlsl defines Unity's functions on floats
_REAL = re.compile(r"^real(?=\d|$)")


@functools.lru_cache(maxsize=1)
def _library_functions() -> dict:
    """name -> the parameter types of each overload the Unity layer every pbrlab program of a
    Unity shader holds defines."""
    from .cg_types import library
    return {name: {tuple(p.type for p in sig.params) for sig in sigs} for name, sigs in library().functions.items()}


def _parameter_types(params: str):
    """The types of a definition's parameters (Cg spellings), None where one is not a built-in type."""
    from .cg_types import builtin_type
    out = []
    for param in filter(None, (p.strip() for p in params.split(","))):
        words = [w for w in re.findall(r"[A-Za-z_]\w*", param.split(":")[0]) if w not in _PARAM_WORDS]
        t = builtin_type(_REAL.sub("float", words[0])) if len(words) == 2 else None
        if t is None:
            return None
        out.append(t)
    return tuple(out)


def library_overloads_defined(text: str) -> set:
    """The names of the Unity layer's overloads ``text`` defines again (the same name and
    parameter types, Cg's half and fixed read as float, as glslang and GLSL read them)."""
    library = _library_functions()
    return {m.group(1) for m in _DEFINITION.finditer(text)
            if m.group(1) in library and _parameter_types(m.group(2)) in library[m.group(1)]}


def renamed_calls(text: str, names) -> str:
    """``text`` with each definition of and call to a function of ``names`` as
    ``pbrlab_program_<name>``."""
    if not names:
        return text
    return re.sub(r"\b(" + "|".join(sorted(names)) + r")\b(?=\s*\()", r"pbrlab_program_\1", text)


def _rename_own_library_functions(text: str) -> str:
    """A definition of one of the Unity layer's overloads (the same name and parameter types)
    renamed with its calls (a different overload of the name is a legitimate HLSL overload:
    left alone)."""
    return renamed_calls(text, library_overloads_defined(text))


# HLSL's multi-element matrix swizzle on a name or member (``M._m03_m13_m23``, ``M._11_22``):
# glslang's HLSL front end reads it wrong (one component: measured, session 41), GLSL has none.
# Spelled as a constructor of the single elements (``float3(M._m03, M._m13, M._m23)``), which
# both take (the type pass names GLSL's element); the object's text is read again per element,
# so only where it is a name or a member chain.
_MATRIX_SWIZZLE = re.compile(r"(?<![\w.])([A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*)\.((?:_m[0-3][0-3]){2,4}|(?:_[1-4][1-4]){2,4})\b")


# The same swizzle assigned to, in a statement of its own (``M._m00_m10_m20 = v;``; glslang
# refuses it: "';' : Expected"): one assignment an element, on the statement's line
# (``{ float3 pbrlab_swizzled = v; M._m00 = pbrlab_swizzled[0]; ... }``).
_ASSIGNED_MATRIX_SWIZZLE = re.compile(r"(^|[;{}]|\n)([ \t]*)([A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*)\."
                                      r"((?:_m[0-3][0-3]){2,4}|(?:_[1-4][1-4]){2,4})\s*=(?!=)([^;{}]*);")


def _matrix_swizzles(text: str) -> str:
    def assigned(m):
        lead, indent, target, swizzle, value = m.groups()
        elements = re.findall(r"_m?\d\d", swizzle)
        stores = " ".join(f"{target}.{e} = pbrlab_swizzled[{k}];" for k, e in enumerate(elements))
        return (f"{lead}{indent}{{ float{len(elements)} pbrlab_swizzled = {value.strip()}; {stores} }}"
                + "\n" * value.count("\n"))  # the lines kept
    text = _ASSIGNED_MATRIX_SWIZZLE.sub(assigned, text)

    def spelled(m):
        elements = re.findall(r"_m?\d\d", m.group(2))
        return f"float{len(elements)}({', '.join(f'{m.group(1)}.{e}' for e in elements)})"
    return _MATRIX_SWIZZLE.sub(spelled, text)


# Cg's tex2D(s, uv, dx, dy), the lookup with explicit derivatives, is tex2Dgrad(s, uv, dx, dy)
# (Microsoft's HLSL reference, tex2D(s, t, ddx, ddy)); the harness's HLSL tex2D is a macro of two
# arguments (unity_hlsl_support.hlsl), so the four-argument form is spelled tex2Dgrad in both.
_TEX2D = re.compile(r"\btex2D\s*\(")


def _tex2d_with_derivatives(text: str) -> str:
    out, pos = [], 0
    for m in _TEX2D.finditer(text):
        found = call_arguments(text, m.end() - 1)
        if m.start() < pos or found is None or len(found[0]) != 4:
            continue
        out += [text[pos:m.start()], "tex2Dgrad", text[m.start() + len("tex2D"):m.end()]]
        pos = m.end()
    return "".join(out) + text[pos:]


# URP's OUTPUT_SH4 by its arity: Unity 6.0 (URP 17.0) introduced it with four arguments (position,
# normal, view direction, the SH output), Unity 6.1 (URP 17.1) added a fifth (the probe occlusion
# output); a shader is written for one. Neither glslang's preprocessor nor GLSL's has variadic or
# overloaded macros, so the stand-in Lighting.hlsl defines the five-argument name and
# OUTPUT_SH4_FOUR_ARGUMENTS; a four-argument call is spelled so (not where the text defines a
# function-like OUTPUT_SH4 itself: its own macro, read as written).
_OUTPUT_SH4 = re.compile(r"\bOUTPUT_SH4\s*\(")
_OWN_OUTPUT_SH4 = re.compile(r"^[ \t]*#[ \t]*define[ \t]+OUTPUT_SH4\(", re.M)
OUTPUT_SH4_FOUR = "OUTPUT_SH4_FOUR_ARGUMENTS"


def _output_sh4_by_arity(text: str) -> str:
    if "OUTPUT_SH4" not in text or _OWN_OUTPUT_SH4.search(text):
        return text
    out, pos = [], 0
    for m in _OUTPUT_SH4.finditer(text):
        found = call_arguments(text, m.end() - 1)
        if m.start() < pos or found is None or len(found[0]) != 4:
            continue
        out += [text[pos:m.start()], OUTPUT_SH4_FOUR, text[m.start() + len("OUTPUT_SH4"):m.end()]]
        pos = m.end()
    return "".join(out) + text[pos:]


# A directive that names a hint itself (a project's copy of Core's API/GLCore.hlsl defines them,
# its Validate.hlsl tests them: ``#ifndef UNITY_BRANCH``): the name is kept there.
_NAMING_DIRECTIVE = re.compile(r"^[ \t]*#[ \t]*(?:define|undef|ifdef|ifndef)[ \t]+$|\bdefined[ \t]*\(?[ \t]*$", re.M)


def _blank_flow_hint(m) -> str:
    """A flow-control hint blanked, unless a directive names it (_NAMING_DIRECTIVE)."""
    line = m.string[m.string.rfind("\n", 0, m.start()) + 1:m.start()]
    return m.group(0) if _NAMING_DIRECTIVE.search(line) else " " * len(m.group(0))


# A parameter's ``in out`` (prprprprprppr's ParallaxHeightWithSoftShadow: ``void
# ParallaxFunc(in out float2 uv, ...)``): HLSL takes both words as ``inout`` (Microsoft's HLSL
# reference, "Function parameters": "inout ... same as in out"); GLSL refuses two ("duplicate
# in/out/inout qualifier"): one word, blanks keep the columns.
_IN_OUT = re.compile(r"\bin([ \t]+)out\b")
# A half literal (``0.001h``, URP's terrain passes): Direct3D 10 and later targets map every half
# to float (Microsoft's HLSL reference, "Scalar Types": "half ... provided only for language
# compatibility. Direct3D 10 shader targets map all half data types to float data types"), so
# FXC reads a float. glslang's HLSL front end makes a 16-bit constant, which turns on SPIR-V's
# Float16 and spirv-cross's GLSL then asks for an extension ("#error No extension available for
# FP16"): spelled with ``f`` (the same width: columns kept), which both languages read as float.
# A hexadecimal integer literal wider than 32 bits (``0x1376312589U``, a hash constant in
# TxN's Kuwahara): Unity's Direct3D targets have no 64-bit integers; DXC, whose literal
# handling followed FXC's, kept an unsuffixed hex literal's low 32 bits (DirectXShaderCompiler
# issue 1973, "Unsuffixed 64-bit hex literals get silently truncated to 32-bits"), and in the
# uint arithmetic such a constant feeds (``n * k + 0x1376312589U`` into a uint) the result is
# the same modulo 2^32 whether or not the literal is truncated first. glslang and GLSL refuse it
# ("hexadecimal literal too big", "out of range"): its low 32 bits, zero-padded to the same width.
_WIDE_HEX = re.compile(r"(?<![\w.])0[xX]([0-9a-fA-F]{9,})(?=[uU]?\b)")


def _low_32_bits(m) -> str:
    digits = m.group(1)
    if int(digits, 16) < 1 << 32:
        return m.group(0)  # leading zeros: already 32 bits
    return m.group(0)[:2] + format(int(digits, 16) & 0xFFFFFFFF, "x").rjust(len(digits), "0")


_HALF_LITERAL = re.compile(r"(?<![\w.])((?:\d+\.\d*|\.\d+)(?:[eE][-+]?\d+)?|\d+[eE][-+]?\d+)[hH]\b")


def respelled(text: str) -> str:
    """``text`` with ``const static`` as ``static const``, each ``switch`` selector cast to int,
    a procedural-instancing setup function's body, Unity's flow-control hints and a macro of
    HLSL flow attributes blanked,
    UnityCG's legacy depth macros written out, a conditional's OpenGL macros undefined,
    Unity 5.3's matrix names upgraded, vector<T, N> as TN, the program's own functions of Unity's names renamed,
    a sampler state that tex2D samples declared as a sampler2D (combined_samplers), a multi-element
    matrix swizzle as a constructor of its elements, a four-argument tex2D as tex2Dgrad, a four-argument
    OUTPUT_SH4 (Unity 6.0's) as OUTPUT_SH4_FOUR_ARGUMENTS, a flat
    initialiser list of an array of vectors grouped per element, a for-loop variable used after its
    loop declared before it (loop_scope), a parameter's ``in out`` as ``inout``, a half literal
    ``0.5h`` as ``0.5f``, a function whose texture lookup's offset is its parameter specialised per
    constant its calls pass (sample_offsets), a hex literal wider than 32 bits as its low 32 bits."""
    text = _IN_OUT.sub(lambda m: "inout" + m.group(1), text)
    text = _HALF_LITERAL.sub(lambda m: m.group(1) + "f", text)
    text = _WIDE_HEX.sub(_low_32_bits, text)
    text = _blank_procedural_setup(_CONST_STATIC.sub(lambda m: f"static{m.group(1)}const", text))
    text = _FLOW_HINT.sub(_blank_flow_hint, text)
    text = _ATTRIBUTE_MACRO.sub(lambda m: m.group(0)[:m.start(1) - m.start()] + " " * len(m.group(1)), text)
    text = _GL_TESTED.sub(lambda m: re.sub(r"\bGL_(?=\w)", "PBRLAB_UNITY_NO_GL_", m.group(1)), text)
    text = _LEGACY_DEPTH.sub(lambda m: m.group(1) + ("return 0" if m.group(2) == "UNITY_OUTPUT_DEPTH" else ""), text)
    text = _UPGRADED.sub(lambda m: _UPGRADED_NAMES[m.group(1)], text)
    text = _rename_own_library_functions(text)
    text = combined_samplers.spelled(text)  # SAMPLER(x) read by tex2D(x, uv): a sampler2D
    text = _matrix_swizzles(_tex2d_with_derivatives(_output_sh4_by_arity(text)))
    text = grouped_flat_initialisers(text)  # float2 a[4] = { 8 numbers }: one constructor per element
    text = declared_before_initialised(text)  # float4 c = ... c ...: C's scope, as FXC reads it
    text = loop_variables_in_enclosing_scope(text)  # for (int k ...) {} ... k: FXC's scope
    text = specialised_offsets(text)  # t.Sample(s, uv, parameter): FXC inlines, then it is constant
    text = _TEMPLATE_TYPE.sub(lambda m: f"{m.group(1)}{m.group(2)}" if m.group(1) else
                              f"{m.group(3)}{m.group(4)}x{m.group(5)}", text)
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
