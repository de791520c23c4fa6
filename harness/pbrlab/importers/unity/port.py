"""``pbrlab port-unity``: the mechanical renames that turn a surface shader's CGPROGRAM into
GLSL the harness's GLSL path compiles (types, constructors, global uniforms, scalar-to-vector
assignments); the Cg intrinsics (saturate, lerp, tex2D, ...) are not renamed, they come from
``unity_compat/cg_compat.glsl``.

    text = port_program(shader)        # from a parsed model.SurfaceShader

Two passes, applied to code only (comments and strings untouched, line breaks kept, so the
port stays line for line with the original and compile errors map back by line):

  A. The type pass (cg_types.py): a parser and type inference for the Cg the program is
     written in, which spells out where HLSL converts implicitly and GLSL refuses (vector
     truncation, scalar splats, float -> int, conditions, scalar swizzles, casts, matrix
     constructors and rows, array initialisers, reserved words, ``static``/``uniform``).
     It works on the Cg text and inserts Cg spellings (``float3(``), which B renames.
  B. Renames, by rule:
     1. Types: (float|half|fixed|min16float)N -> vecN, ...RxC -> matCxR (GLSL names columns
        first: HLSL's float3x4 has 3 rows, GLSL's mat4x3 too), scalar half/fixed -> float,
        intN -> ivecN, boolN -> bvecN, uintN -> uvecN.
     2. HLSL-only words: ``inline`` and ``static`` (before const) dropped; ``uniform`` added to
        the shader's global variable declarations (Unity's globals are uniforms). The type pass
        does both where it reads the declaration; these rules catch the ones it cannot read.
     3. Casts ``(float3)x`` -> ``vec3(x)`` (likewise a fallback: the type pass does casts).
     4. HLSL semantics after a member or parameter (``float4 color : COLOR;``) dropped.
     5. ``pow`` -> ``pbr_unity_pow`` (cg_compat.glsl: HLSL's pow(float3, 2.2) promotes the
        scalar; GLSL neither has that overload nor lets a shader overload a built-in).
     6. ``discard`` -> ``PBR_UNITY_DISCARD`` (cg_compat.glsl: nothing in a vertex stage, where
        GLSL refuses the word even in a function that stage never calls).
     7. A matrix element ``M._mRC`` (HLSL: row R, column C) -> ``M[C][R]`` (GLSL names columns
        first).
"""

from __future__ import annotations

import functools
import hashlib
import re
from pathlib import Path

from ...foundation.file_identity import FileCache
from . import cg_spellings, cg_types, multisampled_textures, user_definitions
from . import model as M
from .geometry_syntax import spell_for_glsl
from .tessellation_syntax import spell_for_glsl as spell_tessellation
from .output_struct import layered_struct
from .source_text import PORT_MARKER, call_arguments, included_text
from .compared_textures import TextureReads, compared_view, passed_views, texture_reads
from .texture_methods import spelled_texture_methods, texture_kinds

_TYPE = re.compile(r"\b(?:float|half|fixed|min16float)([234])(?:x([234]))?\b")
_SCALAR = re.compile(r"\b(?:half|fixed|min16float)\b")
_INT = re.compile(r"\b(int|bool|uint)([234])\b")
# Comments and strings are placeholders (_placeholder) while the rules run: those between a
# semantic and what ends its declaration, or between a signature and its body.
_KEPT = r"(?:\x01\d+\x02\s*)*"
# HLSL semantics (rule 5): the D3D9/10 names a surface shader's structs and parameters carry
# (before the ; , or ) that ends the declaration, or before a preprocessor line: a parameter
# list whose last parameters are under an #if). In a macro's body the index may be pasted from a
# parameter (``#define MY_COORDS(i) float3 v : TEXCOORD##i;``): the port strips semantics from the
# macro's text, so its expansion carries none. A comment between the semantic and what ends the
# declaration (``float4 p : SV_POSITION // clip space`` before ``)``) is a placeholder here
# (port_text: _placeholder).
_SEMANTIC = re.compile(r"([\w\]])\s*:\s*(?:POSITION|NORMAL|TANGENT|BINORMAL|COLOR|TEXCOORD|BLENDWEIGHT|"
                       r"BLENDINDICES|PSIZE|FOG|DEPTH|VFACE|VPOS|SV_\w+?|FRONT_FACE_SEMANTIC)\d*(?:\s*##\s*\w+)*\s*(?=" + _KEPT + r"[;,)]|\n[ \t]*#)", re.I)  # Unity: any case
# Any other identifier is a semantic too in HLSL (a custom varying: ``float fog : FOG_FACTOR;``):
# dropped where it follows a declaration, a type and a name (``type name : SEMANTIC`` before
# ``;``, ``,`` or ``)``), which no expression spells (a ternary's ``:`` follows an operand;
# ``case X : return;`` is not a declaration); an array member too (``float3 v[4] : TANUCORNER;``).
_DECLARED_SEMANTIC = re.compile(r"\b((?!case\b)[A-Za-z_]\w*\s+[A-Za-z_]\w*(?:\s*\[\s*\w+\s*\])?)\s*:\s*"
                                r"(?!(?:return|break|continue|discard)\b)[A-Za-z_]\w*\s*(?=" + _KEPT + r"[;,)])")
_COMMENT_OR_STRING = re.compile(r'//[^\n]*|/\*.*?\*/|"[^"\n]*"', re.S)


def _rename_types(code: str) -> str:
    code = _TYPE.sub(lambda m: f"mat{m.group(2)}" + (f"x{m.group(1)}" if m.group(2) != m.group(1) else "")
                     if m.group(2) else f"vec{m.group(1)}", code)
    code = _SCALAR.sub("float", code)
    return _INT.sub(lambda m: {"int": "ivec", "bool": "bvec", "uint": "uvec"}[m.group(1)] + m.group(2), code)


def _code_segments(text: str):
    """[(is_code, text)] alternating code and comments/strings."""
    out, last = [], 0
    for m in _COMMENT_OR_STRING.finditer(text):
        out.append((True, text[last:m.start()]))
        out.append((False, m.group(0)))
        last = m.end()
    out.append((True, text[last:]))
    return out


# HLSL's ``static`` global (a variable of the stage's own, not a uniform; the type pass keeps the
# word on one that is not const): GLSL's plain global, the word dropped (GLSL reserves it). HLSL
# zero-initialises a static without an initialiser; GLSL leaves a global undefined, so one of a
# numeric type gets the zero written out.
_STATIC_GLOBAL = re.compile(r"^(\s*)static\s+")
_STATIC_UNINITIALISED = re.compile(r"^(\s*)static\s+((?:[biu]?vec[234]|mat[234](?:x[234])?|float|int|uint|bool))\s+"
                                   r"(\w+)\s*(?:\[\s*(\d+)\s*\])?\s*;")


def _static_global(line: str) -> str:
    """A depth-0 line that declares a ``static`` global, as GLSL's plain global (above)."""
    m = _STATIC_UNINITIALISED.match(line)
    if m is None:
        return _STATIC_GLOBAL.sub(r"\1", line)
    indent, kind, name, count = m.groups()
    zero = f"{kind}(0)"
    if count:
        size = f"[{count}]"
        value = f"{kind}{size}({', '.join([zero] * int(count))})"
    else:
        size, value = "", zero
    return f"{indent}{kind} {name}{size} = {value};{line[m.end():]}"


# A global of HLSL's without ``static`` is a uniform, and an initialiser of one is not its value
# in Unity: the material sets every uniform, to 0 where neither a property nor a global sets it
# (Unity's manual, "Accessing shader properties in Cg/HLSL": a value defined nowhere is 0; glslang
# reads such a global as a uniform as well). GLSL would keep the initialiser as a plain global's
# value, so the port declares the uniform alone.
_INITIALISED_GLOBAL = re.compile(r"^(\s*)(?:uniform\s+)?((?:[biu]?vec[234]|mat[234](?:x[234])?|float|int|uint)"
                                 r"\s+\w+)\s*=[^;{}]*;")


# A #define whose body declares a texture (ylvgn's ``#define MY_TEXTURE2D(T) TEXTURE2D(T); float4
# T##_ST; SAMPLER(sampler##T);``, used at file scope): FXC compiles the expansion where it is used,
# a global's declaration, and a global without ``static`` is a uniform (Microsoft's HLSL reference,
# "Variable syntax"); GLSL takes a sampler only as a uniform or a parameter, and a plain global
# there would not be the material's value. A texture declared by a statement of the body (ending
# in ``;``: no parameter) makes the macro a globals' declaration: each declaration statement of
# its body (names may be pasted, ``T##_ST``) gets ``uniform``, as _globals_uniform gives code's.
_GLOBAL_TYPES = (r"(?:[biu]?vec[234]|mat[234]|float|int|uint|sampler2DArrayShadow|sampler2DShadow|samplerCubeShadow|"
                 r"sampler2DArray|sampler2D|samplerCUBE|samplerCube|sampler3D)")
_DEFINE_HEAD = re.compile(r"#[ \t]*define[ \t]+\w+(?:\([^()]*\))?")
_BODY_DECLARATION = r"(^|;|\\\n)(\s*)(%s\s+[\w#]+\s*(?:\[\s*\w+\s*\])?\s*;)"
_BODY_SAMPLER = re.compile(_BODY_DECLARATION % r"sampler\w+")
_BODY_GLOBAL = re.compile(_BODY_DECLARATION % _GLOBAL_TYPES)


def _uniforms_in_declaring_defines(code: str) -> str:
    def define(d):
        text = d.group(0)
        head = _DEFINE_HEAD.match(text.lstrip())
        if head is None:
            return text
        cut = len(text) - len(text.lstrip()) + head.end()
        body = text[cut:]
        if not _BODY_SAMPLER.search(body):
            return text
        return text[:cut] + _BODY_GLOBAL.sub(lambda m: f"{m.group(1)}{m.group(2)}uniform {m.group(3)}", body)
    return _DEFINE_LINES.sub(define, code)


# A function-like #define whose body is one texture declaration of its parameter, without its
# ``;`` (URP 14's CopyDepthPass.hlsl: ``#define DEPTH_TEXTURE(name) TEXTURE2D_FLOAT(name)``,
# spelled ``sampler2D name`` by _expand_srp_texture_macros): a use of it as a statement at file
# scope (``DEPTH_TEXTURE(_CameraDepthAttachment);``) declares a global, which FXC makes a uniform
# (Microsoft's HLSL reference, "Variable syntax": a global without ``static`` is uniform) and GLSL
# takes only as one; the use gets ``uniform``, as a written ``TEXTURE2D_FLOAT(x);`` does (the
# body is left alone: the macro may declare a parameter too).
_TEXTURE_DECLARING_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)\([ \t]*(\w+)[ \t]*\)[ \t]*"
                                       r"(?:sampler2DArrayShadow|sampler2DShadow|samplerCubeShadow|sampler2DArray|"
                                       r"sampler2D|samplerCUBE|samplerCube|sampler3D)[ \t]+\2[ \t]*$", re.M)


def _texture_declaring_macros(code: str) -> frozenset:
    return frozenset(m.group(1) for m in _TEXTURE_DECLARING_DEFINE.finditer(code))


def _globals_uniform(code: str, declaring: frozenset = frozenset()) -> str:
    """``uniform`` before global variable declarations (brace depth 0, not functions/structs, not
    a line of a multi-line #define: a texture-declaring #define's in _uniforms_in_declaring_defines),
    and before a file-scope use of a macro that declares a texture (_TEXTURE_DECLARING_DEFINE: the
    code's own, and ``declaring``, those of the files it includes); ``static`` dropped before one
    (_STATIC_GLOBAL)."""
    code = _uniforms_in_declaring_defines(code)
    declaring = _texture_declaring_macros(code) | declaring
    declared_by_macro = (re.compile(r"^(\s*)((?:%s)\s*\(\s*\w+\s*\)\s*;)" % "|".join(sorted(declaring)))
                         if declaring else None)
    lines, depth, out = code.split("\n"), 0, []
    decl = re.compile(r"^(\s*)((?:vec[234]|mat[234]|float|int|sampler2DArrayShadow|sampler2DShadow|samplerCubeShadow|"
                      r"sampler2DArray|sampler2D|samplerCUBE|samplerCube|sampler3D)\s+\w+\s*(?:\[\s*\d+\s*\])?\s*;)")
    continued = False  # the line continues a preprocessor directive (a macro's body, after a backslash)
    for line in lines:
        directive = continued or line.lstrip().startswith("#")
        continued = directive and line.rstrip().endswith("\\")
        if depth == 0 and not directive:
            m = decl.match(line)
            initialised = _INITIALISED_GLOBAL.match(line)
            by_macro = declared_by_macro.match(line) if declared_by_macro else None
            if m:
                line = f"{m.group(1)}uniform {m.group(2)}{line[m.end():]}"
            elif by_macro:
                line = f"{by_macro.group(1)}uniform {by_macro.group(2)}{line[by_macro.end():]}"
            elif initialised:  # a uniform's initialiser Unity ignores (_INITIALISED_GLOBAL)
                line = f"{initialised.group(1)}uniform {initialised.group(2)};{line[initialised.end():]}"
            else:
                line = _static_global(line)
        depth += line.count("{") - line.count("}")
        out.append(line)
    return "\n".join(out)


def port_code_types(code: str) -> str:
    """Rule 1 alone (a type name, e.g. an Input member's)."""
    return _rename_types(code)


def _in_ternary(code: str, pos: int) -> bool:
    """Whether the ``:`` after ``pos`` closes a ``?`` of the statement it stands in (``d < v ?
    color01 : color02;``, wrc1028's WaterPass: an operand whose name reads as a semantic, COLOR
    in any case and a number, is no semantic: a declaration has no ``?``)."""
    start = max(code.rfind(c, 0, pos) for c in ";{}") + 1
    head = code[start:pos + 1]
    return head.count("?") > head.count(":")


def port_code(code: str, declaring: frozenset = frozenset()) -> str:
    """Pass B on code without comments or strings (``declaring``: the texture-declaring macros
    its includes define, _globals_uniform)."""
    code = _rename_types(code)
    code = _SEMANTIC.sub(lambda m: m.group(0) if _in_ternary(code, m.start()) else m.group(1), code)
    code = _DECLARED_SEMANTIC.sub(r"\1", code)
    # a function's return semantic (comments between it and the body: placeholders here; #if
    # lines there too: `half4 frag(g2f i) : SV_Target` / `#endif` / `{`, the other branch's
    # signature above)
    code = re.sub(r"\)(\s*):\s*[A-Za-z_]\w*(\s*)(?=(?:" + _KEPT + r"#[^\n]*\n\s*)*" + _KEPT + r"\{)", r")\1\2", code)
    code = re.sub(r"\binline\s+", "", code)
    code = re.sub(r"\bpow\s*\(", "pbr_unity_pow(", code)
    code = re.sub(r"\bstatic\s+(?=const\b)", "", code)
    code = re.sub(r"\bdiscard\b", "PBR_UNITY_DISCARD", code)  # GLSL refuses discard in a vertex stage
    # HLSL's matrix element M._mRC (row R, column C, from 0) is GLSL's M[C][R] (columns first)
    code = re.sub(r"\._m([0-3])([0-3])\b", r"[\2][\1]", code)
    code = re.sub(r"\(\s*(vec[234]|float)\s*\)\s*(\w+(?:\.\w+)*)", r"\1(\2)", code)
    return _globals_uniform(code, declaring)


def _unity_globals() -> dict:
    """{name: GLSL type} of the globals unity_compat/shader_variables.glsl declares (Unity's
    UnityShaderVariables / UnityLightingCommon names: _LightColor0, _Time, ...)."""
    text = cg_types.library_file("glsl/unity_compat/shader_variables.glsl").read_text(encoding="utf-8")
    return {name: kind for kind, name in re.findall(r"^(?:uniform\s+)?(vec[234]|mat[234]|float)\s+(\w+)\s*;", text, re.M)}


@functools.cache
def _uniform_declaring_macros() -> frozenset:
    """The Unity prelude's macros whose GLSL spelling declares a uniform itself
    (``#define UNITY_DECLARE_TEX2DARRAY(tex) uniform sampler2DArray tex``)."""
    text = cg_types.library_file("glsl/unity_compat/shader_variables.glsl").read_text(encoding="utf-8")
    return frozenset(re.findall(r"^[ \t]*#[ \t]*define[ \t]+(\w+)\([^()]*\)[ \t]*uniform\b", text, re.M))


def _drop_uniform_before_declaring_macro(code: str) -> str:
    """``uniform UNITY_DECLARE_TEX2DARRAY(_MainTex);`` (Amplify Shader Editor's previews): FXC
    takes the storage class a global has anyway (Microsoft's HLSL reference, "Variable syntax":
    a global is uniform by default), so ``uniform Texture2DArray _MainTex`` compiles; the GLSL
    macro writes its own ``uniform`` and GLSL refuses two (duplicate storage qualifier): the
    written word is blanked (columns kept), as for ``uniform SAMPLER(s)``."""
    names = _uniform_declaring_macros()
    return re.sub(r"\buniform(?=\s+(\w+)\s*\()",
                  lambda m: " " * len("uniform") if m.group(1) in names else m.group(0), code)


_GLOBAL_DECLARATION = re.compile(r"^([ \t]*)(uniform\s+(vec[234]|mat[234]|float)\s+(\w+(?:\s*,\s*\w+)*)\s*;)", re.M)


def _drop_unity_redeclarations(code: str) -> str:
    """A program's own declaration of a global Unity declares for it (``fixed4 _LightColor0;``,
    written where Lighting.cginc is not included) is one GLSL refuses as a redeclaration: it is
    kept as a comment, on its line; from a list (``float4 _LightColor0, _MainTex_ST;``) only
    Unity's names are taken out. One declared with a type of its own (``half3 _SpecColor;``) is
    kept: it is the only one, the prelude's renamed (user_definitions.prelude_renames)."""
    types = _unity_globals()
    names = set(types)
    renamed = user_definitions.prelude_globals()  # (the uniforms the prelude renames for a program's own type)

    def drop(m):
        declared = [n.strip() for n in m.group(4).split(",")]
        kept = [n for n in declared if n not in names or (types[n] != m.group(3) and n in renamed)]
        if len(kept) == len(declared):
            return m.group(0)
        newlines = "\n" * m.group(2).count("\n")  # the port stays line for line
        ours = ", ".join(n for n in declared if n not in kept)
        if not kept:
            return f"{m.group(1)}/* uniform {m.group(3)} {ours}; (declared by UnityShaderVariables) */{newlines}"
        return (f"{m.group(1)}uniform {m.group(3)} {', '.join(kept)}; "
                f"/* {ours}: declared by UnityShaderVariables */{newlines}")
    return _GLOBAL_DECLARATION.sub(drop, code)


def port_program(shader: M.SurfaceShader, program: str | None = None, reads: TextureReads | None = None) -> str:
    """The shader's CGPROGRAM (or ``program``, its text with edits) ported, line for line
    (comments kept); a layered model's output struct (generated before the program:
    output_struct.layered_struct) is known to the type pass. ``reads``: port_text's."""
    return port_text(shader.program if program is None else program, shader.path.parent, "\n".join(layered_struct(shader)),
                     srp=getattr(shader, "srp", False), reads=reads)


# The Scriptable Render Pipelines' texture API (Core RP's ShaderLibrary macros, which the
# Universal Render Pipeline's shaders use): in HLSL the stand-ins define them as Unity does;
# for GLSL each use is spelled in Cg's forms before the two passes, which port those (URP's
# reflection probe unity_SpecCube0, read by its mip in Unity's steps: _SKY_CUBES).
# The reflection probe, and URP's sky reflection cube (Input.hlsl), the same probe (the stand-in
# Core.hlsl): read through the harness's pbrlab_unity_reflection_probe (templates/unity_surface.inc,
# in every Unity program; the stand-in Lighting.hlsl's pbrlab_urp_reflection_probe is the same read).
_SKY_CUBES = ("unity_SpecCube0", "_GlossyEnvironmentCubeMap")
_SRP_TEXTURE_MACROS = {
    "TEXTURE2D": lambda a: f"sampler2D {a[0]}",
    "TEXTURECUBE": lambda a: f"samplerCUBE {a[0]}",
    "SAMPLER": lambda a: f"static const int {a[0]} = 0",
    "TEXTURE2D_PARAM": lambda a: f"sampler2D {a[0]}, int {a[1]}",
    "TEXTURECUBE_PARAM": lambda a: f"samplerCUBE {a[0]}, int {a[1]}",
    "TEXTURE2D_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "TEXTURECUBE_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "TEXTURE3D": lambda a: f"sampler3D {a[0]}",
    "TEXTURE3D_PARAM": lambda a: f"sampler3D {a[0]}, int {a[1]}",
    "TEXTURE3D_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "SAMPLE_TEXTURE3D": lambda a: f"tex3D({a[0]}, {a[2]})",
    "SAMPLE_TEXTURE3D_LOD": lambda a: f"tex3Dlod({a[0]}, float4(({a[2]}).xyz, {a[3]}))",
    # (a *_LOD / *_BIAS location packed with its level is cut to the texture's dimension
    # first: FXC's SampleLevel passes a longer location's first components, warning X3206)
    # the _X forms: an XR eye's texture array in URP, one 2D texture without XR (as here)
    "TEXTURE2D_X": lambda a: f"sampler2D {a[0]}",
    "TEXTURE2D_X_FLOAT": lambda a: f"sampler2D {a[0]}",
    "SAMPLE_TEXTURE2D_X": lambda a: f"tex2D({a[0]}, {a[2]})",
    "SAMPLE_TEXTURE2D_X_LOD": lambda a: f"tex2Dlod({a[0]}, float4(({a[2]}).xy, 0.0, {a[3]}))",
    # 2D texture arrays (the Unity prelude's UNITY_ .._TEX2DARRAY forms: the layer index as the
    # coordinate's z; texture_arrays binds the array) and shadow-map textures passed on with their
    # comparison sampler (a GL texture's own sampler: an unused int, as SAMPLER's)
    "TEXTURE2D_ARRAY": lambda a: f"sampler2DArray {a[0]}",
    "TEXTURE2D_ARRAY_PARAM": lambda a: f"sampler2DArray {a[0]}, int {a[1]}",
    "TEXTURE2D_ARRAY_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "SAMPLE_TEXTURE2D_ARRAY": lambda a: f"UNITY_SAMPLE_TEX2DARRAY({a[0]}, float3({a[2]}, {a[3]}))",
    "SAMPLE_TEXTURE2D_ARRAY_LOD": lambda a: f"UNITY_SAMPLE_TEX2DARRAY_LOD({a[0]}, float3({a[2]}, {a[3]}), {a[4]})",
    # shadow maps: GLSL's comparison samplers (a depth texture with its comparison on:
    # shadow_maps.py binds it), read by cg_compat's pbr_unity_sample_cmp, Core RP's
    # SAMPLE_TEXTURE2D_SHADOW (coord3.xy the location, coord3.z the reference; a longer coordinate's
    # first three, as D3D11.hlsl's (coord3).xy / (coord3).z take them), its array's (the layer
    # after the coordinate) and cube's (coord4.xyz the direction, coord4.w the reference)
    "TEXTURE2D_SHADOW": lambda a: f"sampler2DShadow {a[0]}",
    "SAMPLER_CMP": lambda a: f"static const int {a[0]} = 0",
    "TEXTURE2D_SHADOW_PARAM": lambda a: f"sampler2DShadow {a[0]}, int {a[1]}",
    "TEXTURE2D_SHADOW_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "SAMPLE_TEXTURE2D_SHADOW": lambda a: f"pbr_unity_sample_cmp({a[0]}, ({a[2]}).xyz)",
    "TEXTURE2D_ARRAY_SHADOW": lambda a: f"sampler2DArrayShadow {a[0]}",
    "TEXTURE2D_ARRAY_SHADOW_PARAM": lambda a: f"sampler2DArrayShadow {a[0]}, int {a[1]}",
    "TEXTURE2D_ARRAY_SHADOW_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "SAMPLE_TEXTURE2D_ARRAY_SHADOW": lambda a: f"pbr_unity_sample_cmp({a[0]}, float4(({a[2]}).xy, {a[3]}, ({a[2]}).z))",
    "TEXTURECUBE_SHADOW": lambda a: f"samplerCubeShadow {a[0]}",
    "TEXTURECUBE_SHADOW_PARAM": lambda a: f"samplerCubeShadow {a[0]}, int {a[1]}",
    "TEXTURECUBE_SHADOW_ARGS": lambda a: f"{a[0]}, {a[1]}",
    "SAMPLE_TEXTURECUBE_SHADOW": lambda a: f"pbr_unity_sample_cmp({a[0]}, float4(({a[2]}).xyz, ({a[2]}).w))",
    # Core RP's texel loads (Texture2D.Load(int3(coord, mip))): the port's Load (texture_methods)
    "LOAD_TEXTURE2D": lambda a: f"pbr_unity_load({a[0]}, int3({a[1]}, 0))",
    "LOAD_TEXTURE2D_LOD": lambda a: f"pbr_unity_load({a[0]}, int3({a[1]}, {a[2]}))",
    "LOAD_TEXTURE2D_X": lambda a: f"pbr_unity_load({a[0]}, int3({a[1]}, 0))",
    "LOAD_TEXTURE2D_X_LOD": lambda a: f"pbr_unity_load({a[0]}, int3({a[1]}, {a[2]}))",
    "SAMPLE_TEXTURE2D": lambda a: f"tex2D({a[0]}, {a[2]})",
    "SAMPLE_TEXTURE2D_LOD": lambda a: f"tex2Dlod({a[0]}, float4(({a[2]}).xy, 0.0, {a[3]}))",
    "SAMPLE_TEXTURE2D_BIAS": lambda a: f"tex2Dbias({a[0]}, float4(({a[2]}).xy, 0.0, {a[3]}))",
    "SAMPLE_TEXTURE2D_GRAD": lambda a: f"tex2Dgrad({a[0]}, {a[2]}, {a[3]}, {a[4]})",
    # Core RP's depth reads (three and four arguments; the built-in's two-argument forms are
    # not these, and are left to the Unity prelude's macros by the argument count below)
    "SAMPLE_DEPTH_TEXTURE": lambda a: f"tex2D({a[0]}, {a[2]}).r",
    "SAMPLE_DEPTH_TEXTURE_LOD": lambda a: f"tex2Dlod({a[0]}, float4(({a[2]}).xy, 0.0, {a[3]})).r",
    # Core RP's gathers (Texture2D.Gather / GatherRed .. GatherAlpha: one channel of the four
    # texels a bilinear read of the location weighs): GLSL's textureGather with that channel's
    # index, under the extensions texture_gather.py enables for GLSL 3.30 (in a float4 constructor,
    # so the type pass knows the lookup's type, as texture_methods' offset reads)
    **{f"GATHER_{channel}TEXTURE2D{x}": (lambda index: lambda a: f"float4(textureGather({a[0]}, ({a[2]}).xy, {index}))")(index)
       for channel, index in (("", 0), ("RED_", 0), ("GREEN_", 1), ("BLUE_", 2), ("ALPHA_", 3))
       for x in ("", "_X") if not (channel == "ALPHA_" and x)},  # (Core RP has no GATHER_ALPHA_TEXTURE2D_X)
    "SAMPLE_TEXTURECUBE": lambda a: (f"pbrlab_unity_reflection_probe({a[2]}, 0.0)" if a[0] in _SKY_CUBES
                                     else f"texCUBE({a[0]}, {a[2]})"),
    "SAMPLE_TEXTURECUBE_LOD": lambda a: (f"pbrlab_unity_reflection_probe({a[2]}, {a[3]})" if a[0] in _SKY_CUBES
                                         else f"texCUBElod({a[0]}, float4(({a[2]}).xyz, {a[3]}))"),
}
# Core RP's API headers' precision forms of the declarations (API/GLCore.hlsl's TEXTURE2D_FLOAT,
# TEXTURE2D_HALF, ...): the same texture types (float32 throughout here)
_PRECISION_FORMS = {base + precision: base for base in ("TEXTURE2D", "TEXTURECUBE", "TEXTURE3D", "TEXTURE2D_ARRAY")
                    for precision in ("_FLOAT", "_HALF")}
_SRP_TEXTURE_MACROS.update({form: _SRP_TEXTURE_MACROS[base] for form, base in _PRECISION_FORMS.items()})
_SRP_MACRO = re.compile(r"\b(" + "|".join(sorted(_SRP_TEXTURE_MACROS, key=len, reverse=True)) + r")\s*\(")


_TRAILING_UNIFORM = re.compile(r"\buniform(?=[ \t]+$)")

# The start of a #define line up to its replacement text (``#define NAME(a, b) ``): a use of
# the texture API after it is the shader's own macro's (``#define SAMPLE_MASK(uv)
# SAMPLE_TEXTURE2D(_Mask, sampler_Mask, uv)``), spelled in Cg like any other.
_DEFINE_BODY = re.compile(r"#\s*define\s+\w+(?:\([^()]*\))?\s")


# Core RP's shadow texture declared (and passed) by what the program does with it
# (compared_textures.texture_reads): a comparison sampler where it is only compared; a plain
# texture where it is only read plainly (GLSL reads a comparison sampler only through a
# comparison, no texelFetch; Core RP's TEXTURE2D_SHADOW is a Texture2D on Direct3D 11 that
# LOAD_TEXTURE2D reads as its depth: test_urp_names_round44); both, where it is read both ways
# (its comparisons read the comparison view, compared_textures.compared_view).
def _shadow_declaration(name: str, reads) -> str:
    if name in reads.both:
        return f"sampler2D {name}; sampler2DShadow {compared_view(name)}"
    return f"{'sampler2DShadow' if reads.only_compared(name) else 'sampler2D'} {name}"


_SHADOW_BY_READS = {
    "TEXTURE2D_SHADOW": lambda a, reads: _shadow_declaration(a[0], reads),
    "TEXTURE2D_SHADOW_PARAM": lambda a, reads: f"{'sampler2DShadow' if a[0] in reads.compared else 'sampler2D'} {a[0]}, int {a[1]}",
    "SAMPLE_TEXTURE2D_SHADOW": lambda a, reads: (f"pbr_unity_sample_cmp({compared_view(a[0]) if a[0] in reads.both else a[0]},"
                                                 f" ({a[2]}).xyz)"),
}


def _expand_srp_texture_macros(code: str, reads: TextureReads | None = None) -> str:
    """Each use of the SRP texture API on a code line spelled in Cg (``SAMPLE_TEXTURE2D(t, s, uv)``
    -> ``tex2D(t, uv)``; the sampler, a GL texture's own, is an unused int), also in a #define's
    replacement text; other preprocessor lines and the name a #define defines (the stand-ins'
    own definitions) are left alone; lines are kept. Shadow textures are declared and compared
    by the program's ``reads`` (_SHADOW_BY_READS; by default ``code``'s own)."""
    reads = reads if reads is not None else texture_reads(code)
    out, pos = [], 0
    for m in _SRP_MACRO.finditer(code):
        if m.start() < pos:
            continue
        line_start = code.rfind("\n", 0, m.start()) + 1
        head = code[line_start:m.start()].lstrip()
        if head.startswith("#") and not _DEFINE_BODY.match(head):
            continue  # a directive, or the name a #define defines: the stand-ins' own definitions
        found = call_arguments(code, m.end() - 1)
        if found is None:
            continue
        args, end = found
        need = {"TEXTURE2D": 1, "TEXTURE2D_X": 1, "TEXTURE2D_X_FLOAT": 1, "TEXTURECUBE": 1, "TEXTURE3D": 1,
                "TEXTURE2D_ARRAY": 1, "TEXTURE2D_SHADOW": 1, "SAMPLER": 1, "SAMPLER_CMP": 1,
                "TEXTURE2D_ARRAY_SHADOW": 1, "TEXTURECUBE_SHADOW": 1,
                **dict.fromkeys(_PRECISION_FORMS, 1)}.get(m.group(1), 2)
        if m.group(1).startswith("SAMPLE_"):
            need = 4 if m.group(1).endswith(("_LOD", "_BIAS")) else 5 if m.group(1).endswith("_GRAD") else 3
            need += m.group(1).startswith("SAMPLE_TEXTURE2D_ARRAY")  # the layer index
        if m.group(1).startswith("LOAD_"):
            need = 3 if m.group(1).endswith("_LOD") else 2
        if m.group(1).startswith("GATHER_"):
            need = 3
        if len(args) != need:
            continue  # not the API's form: left for the compiler to name
        by_reads = _SHADOW_BY_READS.get(m.group(1))
        spelled = by_reads(args, reads) if by_reads else _SRP_TEXTURE_MACROS[m.group(1)](args)
        # the lines a call spans are kept (an argument dropped takes its line breaks with it)
        spelled += "\n" * (code.count("\n", m.start(), end) - spelled.count("\n"))
        before = code[pos:m.start()]
        if spelled.startswith("static const"):
            # ``uniform SAMPLER(s);`` (hadashiA's ScreenSpaceFluid): FXC takes the storage class
            # a global has anyway (Microsoft's HLSL reference, "Variable syntax": a global is
            # uniform by default); the GL sampler's stand-in is a constant, and GLSL refuses
            # ``uniform const`` (duplicate storage qualifier): the word goes, blanks keep columns
            before = _TRAILING_UNIFORM.sub(lambda u: " " * len(u.group(0)), before)
        out += [before, spelled]
        pos = end
    return "".join(out) + code[pos:]


# Core RP's ZERO_INITIALIZE(type, name) on a code line: ``name = (type)0``, which the type pass
# ports (a macro would bring the cast in only after the port).
_ZERO_INITIALIZE = re.compile(r"^(?![ \t]*#)(.*?)\bZERO_INITIALIZE\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.M)


def _spell_zero_initialize(code: str) -> str:
    return _ZERO_INITIALIZE.sub(lambda m: f"{m.group(1)}{m.group(3)} = ({m.group(2)})0", code)


_STRUCT_OPEN = re.compile(r"\bstruct\s+\w+\s*\{")
_MEMBER_INTERPOLATION = re.compile(r"\b(?:nointerpolation|linear|centroid|noperspective|sample)\s+(?=[A-Za-z_])")


def _drop_member_interpolation(text: str) -> str:
    """HLSL's interpolation modifiers on struct members (``nointerpolation float4 p : TEXCOORD0;``)
    taken out of the structs (GLSL takes none inside a struct); the harness's varyings carry
    ``nointerpolation`` as ``flat`` (generate_pass), blanks keep the offsets."""
    out, pos = [], 0
    for m in _STRUCT_OPEN.finditer(text):
        if m.start() < pos:
            continue
        end = text.find("}", m.end())
        if end < 0:
            break
        body = _MEMBER_INTERPOLATION.sub(lambda q: " " * len(q.group(0)), text[m.end():end])
        out += [text[pos:m.end()], body]
        pos = end
    return "".join(out) + text[pos:]


# HLSL's matrix element (``M._m12``, zero-based row and column; ``M._23``, one-based) in a
# #define's body (its continued lines too), after a name, ``)`` or ``]``: the type pass reads
# code, not a macro's text, so it is spelled here as GLSL's ``M[column][row]`` (the port's
# matrices are GLSL's, columns first: _Parser.matrix_elements spells code's the same).
# Several in a row were a constructor of single ones before (cg_spellings._matrix_swizzles).
_DEFINE_LINES = re.compile(r"^[ \t]*#[ \t]*define\b(?:[^\n]*\\\n)*[^\n]*", re.M)
_DEFINE_MATRIX_ELEMENT = re.compile(r"(?<=[\w)\]])([ \t]*\.[ \t]*)_(m?)([0-4])([0-4])\b")


def _matrix_elements_in_defines(text: str) -> str:
    def element(m):
        first = 0 if m.group(2) else 1
        row, column = int(m.group(3)) - first, int(m.group(4)) - first
        if not (0 <= row < 4 and 0 <= column < 4):
            return m.group(0)  # not an element's name: left for the compiler to name
        return f"[{column}][{row}]"
    return _DEFINE_LINES.sub(lambda d: _DEFINE_MATRIX_ELEMENT.sub(element, d.group(0)), text)


def port_text(program: str, folder: Path | None = None, declarations: str = "", srp: bool = False,
              reads: TextureReads | None = None) -> str:
    """A Cg program's text ported (passes A and B); with ``folder`` (where it lies), the
    declarations of the files it includes are known to the type pass too, as are
    ``declarations`` (what the harness puts before the program). ``srp``: a Scriptable Render
    Pipeline's program, whose texture API macros are spelled in Cg first. ``reads``: which
    textures the whole program compares and reads plainly (compared_textures.texture_reads), for
    an included file whose declarations the program's reads type; by default the text's own."""
    included = declarations
    if folder is not None:
        included += "\n" + included_text(program, folder)
    reads = reads if reads is not None else texture_reads(program + "\n" + included)
    names = set(re.findall(r"\w+", program))  # (only the text's own names: one port of an include for every program)
    reads = TextureReads(reads.compared & names, reads.plain & names)
    # a port is a function of these texts alone: kept for the texts seen last (each pass of a
    # shader ports the same include files again: a 256-pass Amplify preview, 6 a pass)
    key = (hashlib.sha256("\0".join((program, included)).encode("utf-8", "surrogatepass")).digest(), srp, reads)
    return _PORTED.get(key, lambda: (_ported_text(program, included, srp, reads), []))


# port_text's answers (strings of a file's size) under a digest of what they are made from.
PORTED_CACHED = 256
_PORTED = FileCache(PORTED_CACHED)


def _ported_text(program: str, included: str, srp: bool, reads: TextureReads) -> str:
    """port_text of ``program`` with the text of the declarations and files it includes."""
    textures = texture_kinds(included)  # the includes' (and sibling includes') texture objects

    def respelled(text):  # Cg spellings glslang and GLSL do not take, then the geometry and tessellation syntax
        text = multisampled_textures.declarations_ported(text)  # Texture2DMS(Array)<T> t: GLSL's sampler
        text = _matrix_elements_in_defines(cg_spellings.respelled(text))
        return _drop_member_interpolation(spelled_texture_methods(spell_tessellation(spell_for_glsl(text)), textures, reads))
    spell = (lambda text: _expand_srp_texture_macros(_spell_zero_initialize(respelled(text)), reads)) if srp else respelled
    spelled_included = spell(included) if included.strip() else ""
    symbols = cg_types.with_declarations(spelled_included, srp) if spelled_included else None
    segments = _code_segments(cg_types.convert(spell(program), symbols, srp))
    code = "".join(t if is_code else _placeholder(i) for i, (is_code, t) in enumerate(segments))
    code = _drop_unity_redeclarations(port_code(_drop_uniform_before_declaring_macro(code),
                                                 _texture_declaring_macros(spelled_included)))
    for i, (is_code, t) in enumerate(segments):
        if not is_code:
            code = code.replace(_placeholder(i), t, 1)
    return passed_views(code, reads.both)  # a texture read both ways passed on as its comparison view


def _property_line(prop: M.Property) -> str:
    attrs = "".join(f"[{a}] " for a in prop.attributes)
    kind = f"Range({prop.range[0]:g}, {prop.range[1]:g})" if prop.kind == "Range" else prop.kind
    if prop.is_texture:
        default = f'"{prop.default}" {{}}'
    elif isinstance(prop.default, tuple):
        default = "(" + ", ".join(f"{x:g}" for x in prop.default) + ")"
    else:
        default = f"{prop.default:g}"
    return f'//@property {attrs}{prop.name} ("{prop.display}", {kind}) = {default}'


def port_file(shader: M.SurfaceShader) -> str:
    """The text ``pbrlab port-unity`` writes: a header, the Properties and pass state as
    ``//@property`` / ``//@state`` lines (the front end reads them back), and the renamed
    program. A material's ``surface`` may name it for the GLSL path."""
    lines = [f"{PORT_MARKER} GLSL port of {shader.path.name} (\"{shader.name}\"); regenerate with",
             f"//   pbrlab port-unity {shader.path.name} -o {shader.path.stem}.glsl",
             "// Needs unity_compat/cg_compat.glsl and the pbr/unity/ includes (the harness adds them).",
             *(_property_line(p) for p in shader.properties.values() if "implicit" not in p.attributes)]
    if shader.state.cull != "back":
        lines.append(f"//@state Cull {shader.state.cull.capitalize()}")
    if shader.state.zwrite is not None:
        lines.append(f"//@state ZWrite {'On' if shader.state.zwrite else 'Off'}")
    return "\n".join(lines) + "\n" + port_program(shader).strip("\n") + "\n"


def _placeholder(i: int) -> str:
    return f"\x01{i}\x02"  # (no word characters: a name after a comment still starts a word)
