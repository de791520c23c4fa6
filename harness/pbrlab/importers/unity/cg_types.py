"""The type pass of ``pbrlab port-unity``: where Cg/HLSL converts a value implicitly and GLSL
330 refuses, spell the conversion out; change nothing else (whitespace, comments and line
breaks stay byte for byte, so the port keeps the original's line numbers).

    text = convert(program_text)       # Cg spellings in, Cg spellings out (port.py renames types)

How: a tokenizer and a recursive-descent parser for the Cg subset surface shaders use
(structs, globals, functions with in/out/inout parameters and semantics; declarations,
assignments, if/else, for/while/do, return, discard; C-precedence expressions, ternaries,
calls, constructors, swizzles, indexing, casts) infer each expression's type against a
symbol table: the program's own structs, globals and functions, and the GLSL library the
harness includes before it (pbr/unity/, unity_compat/, the harness's unity_surface.inc),
whose declarations are read by the same parser (``library()``); the Cg intrinsics have
generic rules (``_INTRINSICS``). The parser records edits (text inserted before or after an
expression, or a token's text replaced); ``convert`` applies them to the original text.
An expression of unknown type is never touched, and a top-level declaration the parser
cannot read keeps its text (``Result.skipped`` names them).

Conversions (HLSL semantics -> GLSL spelling), inserted in Cg spelling (``float3(``):
  * vector op vector of different sizes: the larger truncated (``.xyz``; a swizzle already
    there is shortened: ``c.rgba * v3`` -> ``c.rgb * v3``);
  * assignment, initialisation, return and argument passing: a larger vector truncated to
    the target, a scalar splatted (``float3(x)``), float -> int/uint/bool and bool -> float
    through a constructor (GLSL 330 converts int -> float itself: left alone);
  * Cg intrinsics: the HLSL result size (the smallest vector argument), larger arguments
    truncated, scalars promoted where GLSL has no scalar overload (``max(0, v)``,
    ``step(v, 0.5)``, ``lerp(a3, b3, t4)``);
  * conditions (if, loops, ``?:``, ``!``, ``&&``, ``||``) of a non-bool scalar: ``bool(x)``;
    ``?:`` branches of different sizes brought to HLSL's common type;
  * vector comparisons ``a < b`` -> ``lessThan(a, b)`` (and the other five);
  * float ``%`` -> ``fmod`` (cg_compat.glsl); a float index -> ``int(i)``;
  * swizzles of scalars: ``x.xxx`` -> ``float3(x)``, ``x.x`` -> ``x``;
  * casts ``(float3)x`` -> ``float3(x)``; array initialisers ``{1, 2, 3}`` -> ``float[3](1, 2, 3)``;
  * matrices: ``floatRxC(rows...)`` and an initialiser list ``{rows...}`` ->
    ``transpose(floatCxR(rows...))`` (HLSL's constructor takes rows, GLSL's columns; port.py
    names floatRxC matCxR), ``m[i]`` read as a row -> ``transpose(m)[i]``, written ->
    ``pbr_unity_set_row(m, i, v)`` (cg_compat.glsl), an element ``m[i][j]`` / ``m[i].y``
    written -> ``m[j][i]``, ``m._mRC`` / ``m._RC`` -> ``m[C][R]``; a larger matrix to a smaller
    (assignment, argument, return: FXC keeps the upper-left block) -> ``floatRxC(m)``;
    ``transpose`` / ``determinant`` typed; ``mul`` of a vector longer than the matrix side it
    meets -> the vector's first components (FXC's truncation);
  * arrays of arrays (``float w[2][3]``) kept, with GLSL's nested constructors;
  * for the HLSL as written too (``fxc_conversions``): a vector argument longer than its
    function's parameter -> its first components, as FXC passes it;
  * literal suffixes GLSL lacks (``0.5h``) dropped; ``[unroll]``-style attributes dropped;
  * ``static`` dropped, ``uniform`` added to the other global variables, ``inline`` dropped;
  * identifiers that are GLSL reserved words or the names cg_compat.glsl's macros expand to
    (``input``, ``filter``, ``sample``, ``mix``, ``fract``, ...) -> ``pbr_unity_<name>``.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field
from pathlib import Path

# --- types -------------------------------------------------------------------------------


def written_parameter(text: str, start: int, name_end: int, end: int) -> str:
    """A parameter as written, through its array lengths (``float4 tangentToWorld[3]``): the
    port's shorter overload for a default argument declares it again (end: after the lengths;
    name_end: after its name)."""
    return text[start:end]


@dataclass(frozen=True)
class Type:
    """base: float, int, uint, bool (numeric), a struct name, a sampler name or void; dim:
    1 scalar, 2-4 vector, rows of a matrix (cols > 0), 0 for non-numeric; array: its length
    (-1 unsized), 0 when not an array."""
    base: str
    dim: int = 1
    cols: int = 0
    array: int = 0
    inner: tuple = ()  # an array of arrays' inner lengths (``float w[2][3]``: array 2, inner (3,))

    @property
    def numeric(self):
        return self.base in _BASES and self.dim >= 1 and not self.array

    @property
    def scalar(self):
        return self.numeric and self.dim == 1 and not self.cols

    @property
    def vector(self):
        return self.numeric and self.dim > 1 and not self.cols

    @property
    def matrix(self):
        return self.numeric and self.cols > 0

    def element(self):
        if self.inner:
            return Type(self.base, self.dim, self.cols, self.inner[0], self.inner[1:])
        return Type(self.base, self.dim, self.cols)

    def cg(self) -> str:
        """The Cg spelling (port.py renames it); an array's, GLSL's ``float[3]``."""
        if self.array:
            element = Type(self.base, self.dim, self.cols)
            return element.cg() + "".join(f"[{n}]" for n in (self.array, *self.inner))
        if self.cols:
            return f"{self.base}{self.dim}x{self.cols}"
        if self.base in _BASES:
            return self.base + (str(self.dim) if self.dim > 1 else "")
        return self.base


_BASES = ("float", "int", "uint", "bool")
_CG_BASE = {"float": "float", "half": "float", "fixed": "float", "double": "float",
            "min16float": "float", "min10float": "float", "int": "int", "min16int": "int",
            "uint": "uint", "min16uint": "uint", "dword": "uint", "bool": "bool"}
_CG_TYPE = re.compile(r"(float|half|fixed|double|min16float|min10float|int|min16int|uint|min16uint|dword|bool)"
                      r"(?:([1-4])(?:x([1-4]))?)?")
_GLSL_TYPE = re.compile(r"(?:(vec|ivec|uvec|bvec)([2-4])|mat([2-4])(?:x([2-4]))?)")
_GLSL_VEC_BASE = {"vec": "float", "ivec": "int", "uvec": "uint", "bvec": "bool"}
_OPAQUE = re.compile(r"sampler(?:1D|2D|3D|CUBE|Cube|2DShadow|2D_float|2D_half|CUBE_float|CUBE_half|2DArray|2DMS|2DMSArray)?|"
                     r"Texture[123]D(?:Array)?|TextureCube|SamplerState|SamplerComparisonState")
VOID = Type("void", 0)


def builtin_type(name: str) -> Type | None:
    m = _CG_TYPE.fullmatch(name)
    if m:
        base, n, c = _CG_BASE[m.group(1)], int(m.group(2) or 1), int(m.group(3) or 0)
        return Type(base, n, c) if not (c and base == "bool") else Type(base, n, c)
    m = _GLSL_TYPE.fullmatch(name)
    if m:
        if m.group(1):
            return Type(_GLSL_VEC_BASE[m.group(1)], int(m.group(2)))
        cols = int(m.group(3))
        rows = int(m.group(4) or cols)
        return Type("float", rows, cols)  # GLSL matCxR: C columns, R rows
    if name == "void":
        return VOID
    if _OPAQUE.fullmatch(name):
        return Type(name.replace("Cube", "CUBE"), 0)
    return None


def _splat(t: Type, n: int) -> Type:
    return Type(t.base, n)


# --- tokens ------------------------------------------------------------------------------

@dataclass
class Tok:
    kind: str      # id, num, op, str
    text: str
    s: int
    e: int


_TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<pp>\#(?:[^\n\\]|\\.)*(?:\\\n(?:[^\n\\]|\\.)*)*)
  | (?P<num>0[xX][0-9a-fA-F]+[uUlL]*|(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fFhHlLuU]*)
  | (?P<id>[A-Za-z_]\w*)
  | (?P<str>"(?:[^"\\\n]|\\.)*")
  | (?P<op><<=|>>=|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\+=|-=|\*=|/=|%=|&=|\|=|\^=|->|::|[-+*/%<>=!~&|^?:;,.(){}\[\]])
""", re.S | re.X)


def tokenize(text: str):
    """(tokens, directive spans): comments and whitespace dropped, preprocessor lines apart."""
    toks, directives, pos, line_start = [], [], 0, True
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            raise CgSyntaxError(f"unexpected character {text[pos]!r}", pos)
        kind = m.lastgroup
        if kind == "pp" and not line_start:
            raise CgSyntaxError("'#' inside a line", pos)
        if kind == "pp":
            directives.append((m.start(), m.end()))
        elif kind not in ("ws", "comment"):
            toks.append(Tok(kind, m.group(0), m.start(), m.end()))
        if kind in ("ws", "comment"):
            line_start = line_start or "\n" in m.group(0)
        else:
            line_start = False
        pos = m.end()
    return toks, directives


_CONDITION = re.compile(r"#\s*(if|ifdef|ifndef|elif|else|endif)\b")


def _enclosing_conditions(text: str, directives, pos: int) -> list:
    """The preprocessor lines that put ``pos`` where it is: each open #if (its #elif and
    #else up to the branch ``pos`` lies in), outermost first; an include guard (``#ifndef X``
    then ``#define X``: a file's, or one a program writes around a part of its own, as URP's
    files do) is not one (false where the zero's body goes, at the end), nor is anything closed
    before."""
    stack = []   # per open #if: its lines so far
    spans = [(s, e) for s, e in directives if s < pos]
    guards = set()
    for (s, e), (s2, e2) in zip(directives, directives[1:]):
        m = re.match(r"#\s*ifndef\s+(\w+)", text[s:e])
        if m and re.match(r"#\s*define\s+" + m.group(1) + r"\b", text[s2:e2]):
            guards.add(s)
    for s, e in spans:
        m = _CONDITION.match(text, s)
        if not m:
            continue
        line = text[s:e].strip()
        if m.group(1).startswith("if"):
            stack.append([] if s in guards else [line])  # (a guard's #endif closes it)
        elif m.group(1) == "endif":
            if stack:
                stack.pop()
        elif stack and stack[-1]:
            stack[-1].append(line)
    return [line for block in stack for line in block]


class CgSyntaxError(Exception):
    def __init__(self, message, pos):
        super().__init__(message)
        self.pos = pos


# --- edits -------------------------------------------------------------------------------

# A float literal with a suffix GLSL lacks (``1.0h``, ``0.5H``), in a default argument the port
# copies into an overload (primary() drops the suffix where the literal stands).
_SUFFIXED_FLOAT = re.compile(r"\b((?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?)[hH]\b|(?<![\w.])(\.\d+(?:[eE][+-]?\d+)?)[hH]\b")


def _glsl_literals(text: str) -> str:
    """``text`` with its float literals' ``h`` suffixes dropped (``1.0h`` -> ``1.0``)."""
    return _SUFFIXED_FLOAT.sub(lambda m: m.group(1) or m.group(2), text)


class Edits:
    """Insertions before/after expressions and token replacements, applied in one pass.
    At one position, closing text (after an expression) precedes opening text (before the
    next); nested openings run outer first, nested closings inner first."""

    def __init__(self):
        self.items = {}    # id -> (pos, side, order, text) ; side 0 close, 1 open, 2 replace
        self.seq = 0

    def _add(self, item):
        self.seq += 1
        self.items[self.seq] = item
        return self.seq

    def open(self, pos, text):
        return self._add((pos, 1, -self.seq, text, pos))

    def close(self, pos, text):
        return self._add((pos, 0, self.seq, text, pos))

    def replace(self, s, e, text):
        return self._add((s, 2, 0, text, e))

    def mark(self):
        return self.seq

    def drop_after(self, mark):
        for k in [k for k in self.items if k > mark]:
            del self.items[k]

    def drop(self, ids):
        for k in ids:
            self.items.pop(k, None)

    def apply(self, text: str) -> str:
        items = sorted(self.items.values(), key=lambda it: (it[0], it[1], it[2]))
        out, pos = [], 0
        for p, side, _, t, end in items:
            if p < pos:  # inside a replaced span: cannot happen for well-formed edits
                continue
            out.append(text[pos:p])
            out.append(t)
            pos = end if side == 2 else p
        out.append(text[pos:])
        return "".join(out)


# --- symbols -----------------------------------------------------------------------------

@dataclass
class Param:
    qual: str      # in, out, inout
    type: Type


@dataclass
class Signature:
    ret: Type
    params: list


# `#define one half3(1., 1., 1.)`: a constant of the constructor's type (its whole body one call)
_CONSTRUCTOR_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+([A-Za-z_]\w*)[ \t]*\(([^()\n]*)\)[ \t]*(?://[^\n]*)?$",
                                 re.M)
# `#define real3 float3`, `#define UNITY_MATRIX_M unity_ObjectToWorld`: an object-like alias
_ALIAS_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+(\w+)[ \t]*$", re.M)
# `#define SHADERGRAPH_SAMPLE_SCENE_DEPTH(uv) pbrlab_shadergraph_scene_depth(uv)`: a macro that
# forwards its parameters, in order, to a function is that function's alias (a use has its type:
# FXC's conversions of the value, a scalar's swizzle or splat, are then spelled as for a call)
_FORWARDING_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)\(([\w \t,]*)\)[ \t]+([A-Za-z_]\w*)[ \t]*\(([\w \t,]*)\)"
                                r"[ \t]*(?://[^\n]*)?$", re.M)
# A function-like #define of one expression on its line (``#define SHADOW_ATTENUATION(a) 1.0``):
# a use has the body's type with the arguments' types for its parameters (_Parser.macro_value)
_FUNCTION_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)\(([\w \t,]*)\)[ \t]+([^\s\\#][^\n#]*?)[ \t]*(?://[^\n]*)?$",
                              re.M)
_NUMBER_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+\(?[ \t]*((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?[fFhHuU]?)"
                            r"[ \t]*\)?[ \t]*(?://[^\n]*)?$", re.M)


@dataclass
class Symbols:
    structs: dict = field(default_factory=dict)    # name -> {field: Type}
    functions: dict = field(default_factory=dict)  # name -> [Signature]
    globals: dict = field(default_factory=dict)    # name -> Type
    aliases: dict = field(default_factory=dict)    # object-like #define NAME OTHER
    # structs whose members depend on the preprocessor (an #if among them, or a macro member):
    # their zero is the function pbr_unity_zero_<name>() the port defines (_Parser.struct)
    conditional: set = field(default_factory=set)
    # function-like #defines of one expression: name -> {(parameters, body)}, every definition
    # seen (one under #if, another under #else: typed only where all agree)
    macros: dict = field(default_factory=dict)

    def copy(self):
        return Symbols({k: dict(v) for k, v in self.structs.items()},
                       {k: list(v) for k, v in self.functions.items()},
                       dict(self.globals), dict(self.aliases), set(self.conditional),
                       {k: set(v) for k, v in self.macros.items()})


LIBRARY_FILES = (  # what the harness's GLSL path includes before a port (generate.py)
    "glsl/unity_compat/cg_compat.glsl", "glsl/unity_compat/shader_variables.glsl",
    "glsl/pbr/surface/lighting_standard.glsl", "glsl/pbr/unity/brdf_unity.glsl",
    "glsl/pbr/unity/unity_cg.glsl", "glsl/pbr/unity/surface_standard.glsl",
    "glsl/pbr/unity/lighting_legacy.glsl", "glsl/pbr/unity/global_illumination.glsl",
    "templates/unity_surface.inc")


def library_file(rel: str) -> Path:
    """A file of LIBRARY_FILES where this install keeps it (checkout or package data)."""
    from ...foundation.locations import locate
    if rel.startswith("templates/"):
        return Path(__file__).resolve().parents[2] / rel
    tree, _, rest = rel.partition("/")
    return locate(tree) / rest


@functools.lru_cache(maxsize=1)
def library() -> Symbols:
    """The declarations of the GLSL files the port is compiled after (bodies not read)."""
    symbols = Symbols()
    for rel in LIBRARY_FILES:
        path = library_file(rel)
        if path.is_file():
            text = path.read_text(encoding="utf-8")
            _Parser(text, symbols, declarations_only=True).program()  # its aliases too (_ALIAS_DEFINE)
            defined_values(text, symbols)
    return symbols


# An object-like #define whose body is one expression on its line (``#define UNITY_MATRIX_IT_MV
# transpose(unity_WorldToObject * unity_MatrixInvV)``, ``#define UNITY_LIGHTMODEL_AMBIENT
# Unity_LightmodelAmbient()``); a body ending in ``\`` (continued) or ``;`` (statements) is none.
_EXPRESSION_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+([^\s\\][^\n]*?)[ \t]*(?://[^\n]*)?$", re.M)


def defined_values(text: str, symbols: Symbols) -> None:
    """The names ``text``'s object-like #defines give an expression of a known numeric type,
    declared in ``symbols`` as globals of that type (a use of the name is a use of the
    expression: ``float3 n = mul(UNITY_MATRIX_IT_MV, v)`` is truncated as the matrix's product
    is); a name already known keeps its type."""
    for m in _EXPRESSION_DEFINE.finditer(text):
        name, body = m.groups()
        if name in symbols.globals or name in symbols.aliases or body.endswith((";", "\\")):
            continue
        try:
            parser = _Parser(body, symbols.copy(), declarations_only=True)
            value = parser.expression()
        except CgSyntaxError:
            continue
        if parser.peek().kind == "eof" and value.t is not None and value.t.numeric:
            symbols.globals[name] = value.t


# --- the Cg intrinsics -------------------------------------------------------------------
# name -> (kind, positions where GLSL accepts a scalar beside vectors). Kinds: "same"
# (elementwise: the HLSL result has the smallest vector argument's size), "scalar" (dot,
# length, distance: float), "bool1" (any, all), "cross" (float3), "first" (reflect, refract:
# the first argument's type).
_INTRINSICS = {
    **{n: ("same", ()) for n in (
        "abs", "sign", "floor", "ceil", "round", "trunc", "frac", "exp", "exp2", "log", "log2",
        "sqrt", "rsqrt", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh",
        "saturate", "normalize", "radians", "degrees", "ddx", "ddy", "fwidth", "atan2")},
    "min": ("same", (1,)), "max": ("same", (1,)), "clamp": ("same", (1, 2)),
    "lerp": ("same", (2,)), "step": ("same", (0,)), "smoothstep": ("same", (0, 1)),
    "pow": ("same", (1,)), "fmod": ("same", (1,)),
    "dot": ("scalar", ()), "distance": ("scalar", ()), "length": ("scalar", ()),
    "any": ("bool1", None), "all": ("bool1", None),
    "cross": ("cross", ()), "reflect": ("first", ()), "refract": ("first", (2,)),
    "faceforward": ("first", ()),
}
# The intrinsics GLSL has as built-in functions of the same name. A program's own function of
# such a name (``float cross(float2 p, float2 c, float r, float w, float e)``) overloads the
# intrinsic in HLSL, where a call picks by its arguments; in GLSL a function of the shader's
# hides every built-in of its name (GLSL 3.30 section 6.1.1: "a function declared in a shader
# hides all built-in functions of the same name"), so the port names the program's own
# pbr_own_<name>, with each call that resolves to it; the other calls keep the built-in.
_GLSL_BUILT_IN_INTRINSICS = frozenset({
    "abs", "sign", "floor", "ceil", "round", "trunc", "exp", "exp2", "log", "log2", "sqrt", "sin", "cos",
    "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "normalize", "radians", "degrees", "fwidth",
    "min", "max", "clamp", "step", "smoothstep", "dot", "distance", "length", "any", "all", "cross",
    "reflect", "refract", "faceforward"})
OWN_PREFIX = "pbr_own_"
_KEYWORDS = {"return", "else", "case", "default", "goto", "discard", "break", "continue", "if", "for",
             "while", "do", "switch", "struct", "typedef", "true", "false"}
_COMPARE = {"<": "lessThan", ">": "greaterThan", "<=": "lessThanEqual", ">=": "greaterThanEqual",
            "==": "equal", "!=": "notEqual"}
_NAME = re.compile(r"[A-Za-z_]\w*")
_SWIZZLE = re.compile(r"[xyzw]{1,4}|[rgba]{1,4}")
# HLSL's matrix swizzles: zero-based ``_mRC`` or one-based ``_RC``, up to four in a row
_PLAIN = re.compile(r"[A-Za-z_]\w*(?:\s*\.\s*[A-Za-z_]\w*)*|\d+")  # a name, a member or a literal
_MATRIX_ELEMENTS = re.compile(r"(?:_m[0-3][0-3]){1,4}|(?:_[1-4][1-4]){1,4}")
# Unity's macros that declare a local of their first argument's name (AutoLight.cginc's
# UNITY_LIGHT_ATTENUATION(destName, input, worldPos): ``fixed destName = ...``; the port's
# unity_compat declares it float): the local's type, known to the statements after it.
_DECLARING_MACROS = {"UNITY_LIGHT_ATTENUATION": "float"}
# Unity's statement macros of no arguments that declare locals of fixed names (UnityCG.cginc's
# TANGENT_SPACE_ROTATION: ``float3 binormal = ...; float3x3 rotation = ...``, the port's
# unity_compat the same): their types, known to the statements after it (``mul(rotation,
# v.vertex)`` is cut as FXC does, _Parser.mul_vector_truncated).
_DECLARING_STATEMENTS = {"TANGENT_SPACE_ROTATION": (("binormal", "float3"), ("rotation", "float3x3"))}
_GEOMETRY_PRIMITIVES = {"point", "line", "triangle", "lineadj", "triangleadj"}
_GEOMETRY_STREAMS = {"PointStream", "LineStream", "TriangleStream"}
_QUALIFIERS = {"const", "static", "uniform", "in", "out", "inout", "inline", "extern", "volatile",
               "precise", "nointerpolation", "linear", "centroid", "noperspective", "row_major",
               "column_major", "highp", "mediump", "lowp", "flat", "smooth", "groupshared"}
# GLSL 330's vector and matrix type names (GLSL 3.30 section 3.6, "Keywords"), which HLSL does
# not reserve (Microsoft's HLSL reference, "Keywords" and "Reserved Words"): a program's
# ``float2 vec2 = ...`` is its own variable, renamed in the port (port.py's float2 -> vec2 would
# otherwise meet it). Sampler names are left out: Cg spells its own sampler types so.
GLSL_TYPE_NAMES = frozenset(
    [f"{p}vec{n}" for p in ("", "i", "u", "b") for n in (2, 3, 4)]
    + [f"mat{n}" for n in (2, 3, 4)] + [f"mat{r}x{c}" for r in (2, 3, 4) for c in (2, 3, 4)])
# Names a Cg program may use that GLSL 330 reserves (keywords and reserved words) or that
# cg_compat.glsl's macros expand to (lerp -> mix, ...) or this pass writes into the program's
# own scopes (not() of HLSL's !v, lessThan() of v < w, matrixCompMult() of m * n): renamed
# pbr_unity_<name> wherever the program uses them as names (a local ``bool not`` would hide
# GLSL's function).
RESERVED = frozenset("""
    attribute varying layout centroid flat smooth noperspective patch sample subroutine invariant
    precise common partition active asm class union enum typedef template this packed resource
    goto noinline public external interface long short superp input output filter sizeof cast
    namespace using coherent restrict readonly writeonly buffer shared atomic_uint lowp mediump
    highp precision hvec2 hvec3 hvec4 fvec2 fvec3 fvec4 dvec2 dvec3 dvec4 union image1D image2D
    image3D imageCube mix fract inversesqrt dFdx dFdy samplerCube texture lessThan greaterThan
    lessThanEqual greaterThanEqual equal notEqual not matrixCompMult
""".split()) | GLSL_TYPE_NAMES
RENAME_PREFIX = "pbr_unity_"
# Names glslang's HLSL front end reserves (C++ words) that an HLSL program of Unity's may use as
# its own: ``float char = ...`` compiles in Unity (a shader of the hidden URP sample draws so)
# and glslang answers "'char' : Reserved word"; renamed pbr_unity_<name> in the HLSL as
# written (fxc_conversions), as the GLSL port renames GLSL's reserved words.
# glslang's HLSL front end also takes GLSL's vec2..vec4 and mat2..mat4 for types (its keyword
# table holds them: "';' : Expected" after ``float vec2``), which HLSL does not reserve.
GLSLANG_HLSL_RESERVED = frozenset({"char", "vec2", "vec3", "vec4", "mat2", "mat3", "mat4"})
# A program's function names renamed so in the HLSL as written (only as functions: a member or
# variable ``main`` is left alone): ``main``, the name of pbrlab's HLSL entry point
# (generate.py), for which glslang takes a program's ``float4 main(float2)`` ("No function
# definition (body) found: main(vf2;").
GLSLANG_HLSL_FUNCTION_NAMES = frozenset({"main"})


def renamed_reserved(text: str) -> str:
    """``text`` (a parameter list, a call or a head the type pass writes itself: the default
    argument overloads) with the names GLSL reserves renamed as rename_reserved_name renames them
    where the program writes them, but for a qualifier (a word of _QUALIFIERS followed by a name:
    ``centroid float2 uv``)."""
    def one(m):
        word, after = m.group(1), text[m.end():]
        if not is_reserved(word) or (word in _QUALIFIERS and re.match(r"\s*[A-Za-z_]", after)):
            return word
        return RENAME_PREFIX + word
    return re.sub(r"(?<![\w.])([A-Za-z_]\w*)", one, text)


def is_reserved(name: str) -> bool:
    """Whether GLSL refuses ``name`` as a program's own: a reserved word above, or a name with
    the gl_ prefix or a double underscore (GLSL 3.30 section 3.7, "Identifiers"; HLSL takes
    both, ``float4 gl_Position : SV_POSITION;``), or ``main``: GLSL's entry point, which must
    return void and take nothing (GLSL 3.30 section 6.1), and the port's own stage entry; HLSL
    names its entry points by the pragmas, so ``float4 main(float2 fragCoord)`` is a function
    like any other there (a ShaderToy port's, yunyufeiwei's fog.shader)."""
    return name in RESERVED or name == "main" or name.startswith("gl_") or "__" in name


def ported_function_name(name: str, language: str) -> str:
    """A program's function as the type pass renames it in ``language`` (rename_reserved_name):
    the name an entry point's call uses (``#pragma fragment main``)."""
    if (language == "glsl" and is_reserved(name)) or \
            (language == "hlsl" and (name in GLSLANG_HLSL_RESERVED or name in GLSLANG_HLSL_FUNCTION_NAMES)):
        return RENAME_PREFIX + name
    return name


@dataclass
class E:
    """A typed expression: its text span, type (None: unknown), whether a swizzle can be
    appended without parentheses, and the swizzle it ends with, if any."""
    s: int
    e: int
    t: Type | None
    postfix: bool = True
    swizzle: tuple | None = None     # (start, end, letters) of a trailing vector swizzle
    row_index: tuple = ()            # edit ids of a matrix row read (dropped if written)
    literal: bool = False
    # a matrix row read through ``transpose`` (M[i]): (M, its '[', its ']'), how it is written
    # (_Parser.row_written); an element of one (M[i][j], M[i].y): (that row, the span of its
    # column's '[j]' or '.y', the column's index text)
    row: tuple = ()
    element: tuple = ()


class _Parser:
    EMPTY_MEMBER = "int pbr_unity_empty; "  # an empty struct's stand-in member (struct())

    def __init__(self, text, symbols: Symbols, declarations_only=False, srp=False):
        self.fxc_edits = Edits()  # what the HLSL as written needs too (fxc_conversions)
        self.text = text
        self.toks, self.directives = tokenize(text)
        self.i = 0
        self.sym = symbols
        for m in _NUMBER_DEFINE.finditer(text):  # `#define MAX_STEPS 10`: a constant of the literal's type
            literal = m.group(2)
            base = "float" if re.search(r"[.eEfFhH]", literal) else "uint" if literal[-1] in "uU" else "int"
            symbols.globals.setdefault(m.group(1), Type(base))
        for m in _CONSTRUCTOR_DEFINE.finditer(text):
            constructed = builtin_type(m.group(2))
            if constructed is not None and constructed.numeric:
                symbols.globals.setdefault(m.group(1), constructed)
        for m in _ALIAS_DEFINE.finditer(text):  # `#define real3 float3` (Core RP): a type's or a name's alias
            symbols.aliases.setdefault(m.group(1), m.group(2))
        for m in _FORWARDING_DEFINE.finditer(text):  # a macro that calls a function with its parameters
            params, args = ([w.strip() for w in g.split(",")] for g in (m.group(2), m.group(4)))
            if params == args and m.group(1) != m.group(3):
                symbols.aliases.setdefault(m.group(1), m.group(3))
        for m in _FUNCTION_DEFINE.finditer(text):
            if not m.group(3).endswith((";", "\\")):  # statements, or continued on the next line
                params = tuple(w.strip() for w in m.group(2).split(",") if w.strip())
                symbols.macros.setdefault(m.group(1), set()).add((params, m.group(3)))
        self.edits = Edits()
        self.scopes = []
        self.ret = None
        self.decl_only = declarations_only
        self.srp = srp  # a Scriptable Render Pipeline's program (conditional structs' zeros)
        self.skipped = []
        # the program's own object-like #defines of one expression (``#define _BlurRadius
        # _Params.y``): typed where a use meets them (defined_value), when the globals they
        # name are declared; defined_values types an include's after it is read
        self.own_defines = {m.group(1): m.group(2) for m in _EXPRESSION_DEFINE.finditer(text)
                            if not m.group(2).endswith((";", "\\"))}
        self.define_types = {}
        self.macro_types = {}  # (macro, its arguments' types) -> (type, postfix) (macro_value)

    # token helpers
    def peek(self, k=0):
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else Tok("eof", "", len(self.text), len(self.text))

    def next(self):
        t = self.peek()
        self.i += 1
        return t

    def at(self, text, k=0):
        t = self.peek(k)
        return t.kind in ("op", "id") and t.text == text

    def accept(self, text):
        if self.at(text):
            return self.next()
        return None

    def expect(self, text):
        t = self.next()
        if t.text != text:
            raise CgSyntaxError(f"expected {text!r}, found {t.text!r}", t.s)
        return t

    def fail(self, what):
        raise CgSyntaxError(what, self.peek().s)

    def name(self):
        t = self.next()
        if t.kind != "id":
            raise CgSyntaxError(f"expected a name, found {t.text!r}", t.s)
        self.rename_reserved_name(t)
        return t

    def rename_reserved_name(self, t: Tok):
        """A name of the program's that a compiler reserves, renamed pbr_unity_<name>: in the
        GLSL port where GLSL reserves it (is_reserved), in the HLSL as written where glslang's
        HLSL front end does and Unity's compiler takes it (GLSLANG_HLSL_RESERVED)."""
        if self.decl_only:
            return
        if is_reserved(t.text):
            self.edits.replace(t.s, t.e, RENAME_PREFIX + t.text)
        if t.text in GLSLANG_HLSL_RESERVED:
            self.fxc_edits.replace(t.s, t.e, RENAME_PREFIX + t.text)

    def rename_function_name(self, t: Tok):
        """A function's name where it is declared or called: renamed in the HLSL as written when
        glslang takes it for pbrlab's entry point (GLSLANG_HLSL_FUNCTION_NAMES)."""
        if not self.decl_only and t.text in GLSLANG_HLSL_FUNCTION_NAMES:
            self.fxc_edits.replace(t.s, t.e, RENAME_PREFIX + t.text)

    # symbols
    def resolve_alias(self, name):
        seen = 0
        while name in self.sym.aliases and seen < 8:
            name, seen = self.sym.aliases[name], seen + 1
        return name

    def type_named(self, name):
        t = builtin_type(name)
        if t is not None:
            return t
        name = self.resolve_alias(name)
        t = builtin_type(name)
        if t is not None:
            return t
        if name in self.sym.structs:
            return Type(name, 0)
        return None

    def lookup(self, name):
        for scope in reversed(self.scopes):
            if name in scope:
                return scope[name]
        if name in self.sym.globals:
            return self.sym.globals[name]
        alias = self.resolve_alias(name)
        if alias in self.sym.globals:
            return self.sym.globals[alias]
        return self.defined_value(name)

    def defined_value(self, name):
        """The type of the expression a #define of the program's own names (``#define
        _BlurRadius _Params.y`` after ``half2 _Params;``: half), read against the globals
        declared so far; None where it names a local or is no expression. Ashlining's blurs:
        ``float4 poissonScale = (_BlurRadius * 30) * mask;`` is then splatted as FXC does."""
        body = self.own_defines.get(name)
        if body is None or name in self.define_types:
            return self.define_types.get(name)
        self.define_types[name] = None  # a define naming itself reads as unknown
        sub = _Parser(body, self.sym.copy(), declarations_only=True)
        sub.own_defines, sub.define_types = self.own_defines, self.define_types
        try:
            value = sub.expression()
        except CgSyntaxError:
            return None
        if sub.peek().kind == "eof" and value.t is not None and value.t.numeric:
            self.define_types[name] = value.t
        return self.define_types[name]

    def declare(self, name, t):
        if self.scopes:
            self.scopes[-1][name] = t
        else:
            self.sym.globals[name] = t

    # --- top level
    def program(self):
        while self.peek().kind != "eof":
            start, mark, fxc_mark = self.i, self.edits.mark(), self.fxc_edits.mark()
            try:
                self.external()
            except CgSyntaxError:
                self.edits.drop_after(mark)
                self.fxc_edits.drop_after(fxc_mark)
                self.scopes, self.ret = [], None
                self.i = start
                self.skip_declaration()
                self.skipped.append(self.line(self.toks[start].s))
                self.rename_reserved(start, self.i)
        return self

    def rename_reserved(self, first: int, end: int):
        """A declaration left as written still has its names GLSL reserves renamed (``Attributes
        input`` -> ``pbr_unity_input``, as name() renames them where the pass reads it), but for
        a word followed by a name: a qualifier (HLSL's ``sample``, ``centroid``), not a name."""
        for k in range(first, end):
            if self.toks[k].kind == "id" and self.peek(k + 1 - self.i).kind != "id":
                self.rename_reserved_name(self.toks[k])

    def line(self, pos):
        return self.text.count("\n", 0, pos) + 1

    def skip_declaration(self):
        depth, opened = 0, False
        while self.peek().kind != "eof":
            t = self.next()
            if t.text in "({[" and t.kind == "op":
                depth += 1
                opened = opened or t.text == "{"
            elif t.text in ")}]" and t.kind == "op":
                depth -= 1
                if depth <= 0 and t.text == "}" and opened:
                    self.accept(";")
                    return
            elif t.text == ";" and depth <= 0:
                return

    def geometry_parameter_type(self):
        """A geometry-stage function's parameters (``triangle v2g IN[3]``, ``inout
        TriangleStream<g2f> stream``: Microsoft's HLSL reference, "Geometry-Shader Object"): the
        input primitive's word is consumed, leaving the element type to type_spec (None); a
        stream object's type is read whole, opaque (``Type("stream", 0)``), so that the body is
        read too (its calls converted as FXC does) and not skipped."""
        if self.peek().text in _GEOMETRY_PRIMITIVES and self.peek(1).kind == "id" \
                and self.peek(2).text not in (",", ")", "[", ":"):
            self.next()
            return None
        if self.peek().text in _GEOMETRY_STREAMS and self.peek(1).text == "<":
            self.next()
            self.skip_balanced("<", ">")
            return Type("stream", 0)
        return None

    def qualifiers(self):
        quals = []
        while self.peek().kind == "id" and self.peek().text in _QUALIFIERS and self.type_named(self.peek().text) is None:
            quals.append(self.next())
        return quals

    def external(self):
        if self.accept(";"):
            return
        if self.at("struct"):
            return self.struct()
        if self.at("typedef"):
            self.fail("typedef")
        first = self.peek()
        if first.text == "[":  # [maxvertexcount(3)], [numthreads(...)]: kept as written
            self.skip_balanced("[", "]")
            return
        if first.kind == "id" and self.type_named(first.text) is None and first.text not in _QUALIFIERS \
                and first.text != "struct" and not self.opaque_ahead() and not self.at("(", 1):
            self.next()  # a bare macro at file scope: CBUFFER_END, UNITY_INSTANCING_BUFFER_END
            return
        if first.kind == "id" and self.at("(", 1) and self.type_named(first.text) is None:
            # a macro at file scope: UNITY_INSTANCING_BUFFER_START(Props), UNITY_DECLARE_TEX2D(x);
            self.next()
            self.skip_balanced("(", ")")
            self.accept(";")
            return
        quals = self.qualifiers()
        t = self.type_spec()
        if t is None:
            self.fail("expected a type")
        if self.peek().kind == "id" and self.at("(", 1):
            return self.function(t, quals)
        words = {q.text for q in quals}
        if not self.decl_only:
            for q in quals:  # a global's lone `static` stays for port._globals_uniform: not a uniform
                if q.text == "inline" or (q.text == "static" and "const" in words):
                    self.delete_word(q)
            if not words & {"static", "const", "uniform", "extern"} and t.base != "void":
                self.edits.open(first.s, "uniform ")
        self.declarators(t, is_global=True, const="const" in words)
        self.expect(";")

    def delete_word(self, tok):
        end = tok.e
        while end < len(self.text) and self.text[end] in " \t":
            end += 1
        self.edits.replace(tok.s, end, "")

    def skip_balanced(self, open_, close):
        self.expect(open_)
        depth = 1
        while depth:
            t = self.next()
            if t.kind == "eof":
                self.fail("unbalanced")
            if t.text == open_:
                depth += 1
            elif t.text == close:
                depth -= 1

    def opaque_ahead(self, j=0):
        """An unknown name followed by a name: a type from an include the pass does not read
        (v2f_surf, appdata_t, LeafSurfaceOutput): a declaration of a value of unknown type."""
        t, n = self.peek(j), self.peek(j + 1)
        return t.kind == "id" and n.kind == "id" and self.type_named(t.text) is None \
            and t.text not in _KEYWORDS and t.text not in _QUALIFIERS and n.text not in _KEYWORDS \
            and self.type_named(n.text) is None and n.text not in _QUALIFIERS

    def type_spec(self):
        t = self.peek()
        if t.kind != "id":
            return None
        if self.opaque_ahead():
            self.next()
            return Type(t.text, 0)
        if t.text == "struct":  # struct Name as a type
            self.next()
            return self.type_spec()
        ty = self.type_named(t.text)
        if ty is None:
            return None
        self.next()
        if ty.base == t.text and t.text in self.sym.structs:
            self.rename_reserved_name(t)  # a struct of a name GLSL reserves (``struct output``)
        if ty.base in ("Texture2D",) and self.at("<"):
            self.skip_balanced("<", ">")
        return ty

    def struct(self):
        self.expect("struct")
        name = self.name().text
        fields = {}
        self.sym.structs[name] = fields
        self.sym.conditional.discard(name)
        open_ = self.expect("{")
        members, macro_member = [], False   # (position, name, Type) in declaration order
        while not self.accept("}"):
            if self.accept(";"):
                continue
            self.qualifiers()
            t = None if self._macro_member_ahead() else self.type_spec()
            if t is None:
                # a macro member: INTERNAL_DATA, UNITY_FOG_COORDS(3), UNITY_VERTEX_INPUT_INSTANCE_ID
                tok = self.next()
                if tok.kind != "id":
                    self.fail("struct member")
                if self.at("("):
                    self.skip_balanced("(", ")")
                    macro_member = True
                else:
                    declared = self.own_macro_members(tok.text)
                    if declared is None:
                        macro_member = True
                    for n, ft in declared or ():
                        fields[n] = self.member_type(fields, n, ft)
                        members.append((tok.s, n, ft))
                self.accept(";")
                continue
            while True:
                name_tok = self.name()
                n = name_tok.text
                ft = self.array_suffix(t)
                self.semantic()
                fields[n] = self.member_type(fields, n, ft)
                members.append((name_tok.s, n, ft))
                if not self.accept(","):
                    break
            self.expect(";")
        close = self.toks[self.i - 1]
        inside = [(s, e) for s, e in self.directives if open_.s < s < close.s]
        if not members and not macro_member and not inside and not self.decl_only and self.EMPTY_MEMBER:
            # ``struct Bindings_X { };`` (Shader Graph's subgraph bindings of nothing): FXC takes
            # an empty struct, GLSL's grammar needs a member (GLSL 3.30 section 4.1.8, "a
            # structure must have at least one member declaration"): an unused int stands in
            self.edits.open(close.s, self.EMPTY_MEMBER)
            fields["pbr_unity_empty"] = Type("int")
        if self.peek().kind == "id":
            self.declarators(Type(name, 0), is_global=not self.scopes, const=False)
        end = self.expect(";")
        if (inside or macro_member) and self.srp:
            self.sym.conditional.add(name)
            if not self.decl_only and not self.scopes:
                self._define_conditional_zero(name, open_.s, end.e, members, inside)

    def own_macro_members(self, macro: str):
        """[(name, Type)] of the members an object-like macro of the program's own declares
        (``#define EXTRA float4 e1; float e2;`` written in a struct as ``EXTRA``), in order,
        so a zero of the struct, ``(S)0``, constructs every member (a constructor without them:
        GLSL's "insufficient parameters in constructor"); None where the program does not
        define the macro once, or its body is no list of member declarations."""
        bodies = set()
        for s, e in self.directives:
            m = re.match(r"#\s*define\s+(\w+)(?!\()[ \t]*(.*)", self.text[s:e], re.S)
            if m and m.group(1) == macro:
                bodies.add(m.group(2).replace("\\\n", " ").strip())
        if len(bodies) != 1:
            return None
        sub = _Parser(bodies.pop(), self.sym.copy(), declarations_only=True)
        out = []
        try:
            while sub.peek().kind != "eof":
                sub.qualifiers()
                t = sub.type_spec()
                if t is None:
                    return None
                while True:
                    n = sub.name().text
                    out.append((n, sub.array_suffix(t)))
                    sub.semantic()
                    if not sub.accept(","):
                        break
                sub.expect(";")
        except CgSyntaxError:
            return None
        return out or None

    @staticmethod
    def member_type(fields, name, t):
        """A member declared again of another type (``#if defined(_NORMALMAP) float4 normalWS;
        #else float3 normalWS;``, RyouTomokin's KIIFPBR): the variant compiled holds one of them,
        which this pass cannot know; of unknown type (None), its uses are left as written (FXC
        converts each variant against its own member)."""
        return None if name in fields and fields[name] != t else t

    def _macro_member_ahead(self) -> bool:
        """Whether the struct member ahead is a bare macro (UNITY_VERTEX_INPUT_INSTANCE_ID
        before another member or the closing brace), not ``Type name``: a name after a
        type is followed by ``;``, ``,``, ``:`` or ``[``."""
        first, second = self.peek(), self.peek(1)
        if first.kind != "id" or builtin_type(first.text) is not None or first.text in self.sym.structs:
            return False
        return second.kind == "id" and self.peek(2).text not in (";", ",", ":", "[")

    def _define_conditional_zero(self, name, start, end, members, inside):
        """The zero of a struct whose members depend on the preprocessor: GLSL has no
        ``(Struct)0``, and a constructor would list the members of every #if branch. Its
        prototype goes on the struct's last line (the port keeps its line count); its body at
        the end of the file, each member zeroed under the struct's own #if lines, the whole
        under the #if lines that enclose the struct (their #else and #elif branches kept
        empty) and a guard of its own (an include read twice defines it once). A macro
        member (its name unknown here) is left as GLSL leaves a local: undefined."""
        zero = f"pbr_unity_zero_{name}"
        self.edits.close(end, f" {name} {zero}();")
        body = [(s, self.text[s:e].strip()) for s, e in inside]
        for pos, member, ty in members:
            try:
                body.append((pos, f"    z.{member} = {self.zero_value(ty)};"))
            except CgSyntaxError:
                continue  # a member of a type without a zero here (a sampler): left undefined
        lines = [f"{name} {zero}() {{", f"    {name} z;"] + [t for _, t in sorted(body)] + ["    return z;", "}"]
        guard = f"PBR_UNITY_ZERO_{name}_DEFINED"
        enclosing = _enclosing_conditions(self.text, self.directives, start)
        text = "\n".join([*enclosing, f"#ifndef {guard}", f"#define {guard}", *lines, "#endif",
                          *["#endif"] * sum(1 for c in enclosing if c.startswith("#if"))])
        self.edits.close(len(self.text), "\n" + text + "\n")

    def semantic(self):
        if self.at(":") and self.peek(1).kind == "id":
            self.next()
            self.next()
            if self.at("("):
                self.skip_balanced("(", ")")

    def array_suffix(self, t):
        """``t`` with the array lengths that follow a declared name (``[3]``, ``[]``, ``[2][3]``:
        an array of arrays, which GLSL takes with GL_ARB_arrays_of_arrays, generate.prelude)."""
        t = self.one_array_suffix(t)
        inner = []
        while t.array and self.at("["):
            inner.append(self.one_array_suffix(Type(t.base, t.dim, t.cols)).array)
        return Type(t.base, t.dim, t.cols, t.array, tuple(inner)) if inner else t

    def one_array_suffix(self, t):
        if self.accept("["):
            if self.accept("]"):
                return Type(t.base, t.dim, t.cols, -1)
            tok = self.next()
            n = int(tok.text.rstrip("uU"), 0) if tok.kind == "num" and tok.text.rstrip("uU").isdigit() else -1
            if n == -1:
                depth = 1
                while depth:  # a size from a macro or an expression
                    tk = self.next()
                    if tk.kind == "eof":
                        self.fail("array size")
                    depth += {"[": 1, "]": -1}.get(tk.text, 0)
                return Type(t.base, t.dim, t.cols, -1)
            self.expect("]")
            return Type(t.base, t.dim, t.cols, n)
        return t

    def function(self, ret, quals):
        if not self.decl_only:
            for q in quals:
                if q.text in ("static", "inline"):
                    self.delete_word(q)
        name_tok = self.name()
        self.rename_function_name(name_tok)
        name = written = name_tok.text
        if name in _GLSL_BUILT_IN_INTRINSICS:  # the program's own overload of a built-in's name
            if not self.decl_only:
                self.edits.replace(name_tok.s, name_tok.e, OWN_PREFIX + name)
            name = OWN_PREFIX + name
        self.expect("(")
        params, scope = [], {}
        spelled, defaults = [], []   # each parameter's text, and its default's (HLSL only)
        param_macros = []            # (the number of parameters before it, a parameter-list macro)
        if not self.at(")"):
            while True:
                if self.at("void") and self.at(")", 1):
                    self.next()
                    break
                first = self.peek().s
                pq = self.qualifiers()
                words = [q.text for q in pq]
                if not self.decl_only and "const" in words and any(w in ("in", "out", "inout") for w in words[:words.index("const")]):
                    # HLSL takes ``in const``; GLSL wants const first
                    direction = next(q for q in pq if q.text in ("in", "out", "inout"))
                    self.delete_word(pq[words.index("const")])
                    self.edits.open(direction.s, "const ")
                pt = self.geometry_parameter_type()
                pt = pt if pt is not None else self.type_spec()
                if pt is None:
                    self.fail("parameter type")
                name_tok = self.name()
                pn = name_tok.text
                pt = self.array_suffix(pt)
                written_param = written_parameter(self.text, first, name_tok.e, self.toks[self.i - 1].e)
                self.semantic()
                spelled.append((re.sub(r"\b(in|out|inout)(\s+)const\b", r"const\2\1", written_param), pn))
                default = None
                if self.at("="):
                    eq = self.next()
                    start = self.peek().s
                    value = self.assignment()
                    default = self.text[start:self.toks[self.i - 1].e]
                    if value.t is not None and value.t.scalar and pt.vector:
                        default = f"{pt.cg()}({default})"  # HLSL splats a scalar default; GLSL does not
                    if not self.decl_only:  # GLSL has no default arguments: overloads below
                        self.edits.replace(eq.s, self.toks[self.i - 1].e, "")
                defaults.append(default)
                qual = next((q.text for q in pq if q.text in ("out", "inout")), "in")
                params.append(Param(qual, pt))
                scope[pn] = pt
                # a macro that brings parameters of its own (``, const half4 mask`` or nothing),
                # written after this parameter: kept where it stands
                while self.peek().kind == "id" and self.peek(1).text in (",", ")"):
                    param_macros.append((len(params), self.next().text))
                if not self.accept(","):
                    break
        self.expect(")")
        self.semantic()
        # one entry per signature: a prototype and its definition (or an include's prototype
        # known twice) are one function, not an ambiguous pair of overloads
        # (a parameter-list macro's parameters are unknown here: calls to it are left untyped)
        known = self.sym.functions.setdefault(name, []) if not param_macros else []
        # a call may leave out only a trailing run of defaulted parameters: a default before a
        # parameter without one (HLSL refuses it: "default parameter missing") makes no shorter form
        first_default = len(defaults)
        while first_default > 0 and defaults[first_default - 1] is not None:
            first_default -= 1
        for k in [len(params), *range(first_default, len(params))]:  # f(a, b = 1) may be called as f(a)
            if Signature(ret, params[:k]) not in known:
                known.append(Signature(ret, params[:k]))
        if self.accept(";"):
            return
        if self.another_head_follows(written):
            # #if lines choosing the signature (``#if X`` ``fragOut frag(g2f i)`` ``#else``
            # ``half4 frag(g2f i) : SV_Target`` ``#endif`` ``{``): this head is known as a
            # prototype; the next one reads the body
            return self.external()
        if self.decl_only:
            self.skip_balanced("{", "}")
            return
        self.ret = ret
        self.scopes = [scope]
        self.block(new_scope=False)
        self.scopes, self.ret = [], None
        if first_default < len(params) and param_macros:
            self._macro_default_overloads(ret, name, spelled, defaults, first_default, param_macros)
        elif first_default < len(params):
            # HLSL's default arguments as GLSL overloads, on the closing brace's line (the
            # port keeps its line count): each shorter form calls the full one with the defaults.
            overloads = []
            for k in range(first_default, len(params)):
                args = [n for _, n in spelled[:k]] + [f"({_glsl_literals(d)})" for d in defaults[k:]]
                call = f"{name}({', '.join(args)})"
                body = f"return {call};" if ret.base != "void" else f"{call};"
                overloads.append(f" {ret.cg()} {name}({', '.join(t for t, _ in spelled[:k])}) {{ {body} }}")
            # the overloads' names as the program's are renamed (``float3 input``, a function
            # ``smooth``): written here from the text as written, so renamed here too
            self.edits.close(self.toks[self.i - 1].e, renamed_reserved("".join(overloads)))

    def another_head_follows(self, name: str) -> bool:
        """A preprocessor line before the next token, then another head of the function
        ``name`` (qualifiers, a return type, ``name (``) instead of its body."""
        before = self.toks[self.i - 1].e
        if not any(before <= s and e <= self.peek().s for s, e in self.directives):
            return False
        for k in range(4):
            if self.peek(k).kind == "id" and self.peek(k).text == name and self.peek(k + 1).text == "(":
                return k > 0
        return False

    def _macro_default_overloads(self, ret, name, spelled, defaults, first_default, param_macros):
        """Default arguments of a parameter list that also holds parameter macros
        (``..., inout half3 spec SHADOW_MASK_PARAM, const half3 albedo = half3(1, 1, 1)``): each
        shorter form keeps the macros before its cut in its parameters and forwards what they
        declare through PBR_UNITY_ARGS_<macro>, the names of the parameters each #define of the
        macro in this file brings, defined at the end of the file under that #define's own #if
        lines. The shorter forms' prototypes go on the closing brace's line (lines kept), their
        bodies after those #defines. A macro this file does not define: no shorter forms (the
        compiler names the default argument)."""
        definitions = {}
        for s, e in self.directives:
            m = re.match(r"#\s*define\s+(\w+)(?!\()[ \t]*(.*)", self.text[s:e], re.S)
            if m and m.group(1) in {mac for _, mac in param_macros}:
                definitions.setdefault(m.group(1), []).append((s, m.group(2).replace("\\\n", " ").strip()))
        if any(mac not in definitions for _, mac in param_macros):
            return
        tail = []
        for mac, found in definitions.items():
            for pos, body in found:
                names = [re.findall(r"[A-Za-z_]\w*", piece)[-1] for piece in body.split(",")
                         if re.findall(r"[A-Za-z_]\w*", piece)]
                conditions = _enclosing_conditions(self.text, self.directives, pos)
                args = "".join(f", {n}" for n in names)
                tail += [*conditions, f"#undef PBR_UNITY_ARGS_{mac}", f"#define PBR_UNITY_ARGS_{mac} {args}",
                         *["#endif"] * sum(1 for c in conditions if c.startswith("#if"))]

        def listed(k, spell, spell_macro):
            """The first k parameters (spell: their text or their name), each followed by the
            parameter macros written after it."""
            out = ""
            for i, item in enumerate(spelled[:k]):
                out += (", " if i else "") + spell(item)
                out += "".join(f" {spell_macro(mac)}" for at, mac in param_macros if at == i + 1)
            return out

        prototypes, bodies = [], []
        for k in range(first_default, len(spelled)):
            if any(at > k for at, _ in param_macros):
                return  # a macro after the cut: its parameters have no value in the shorter form
            head = f"{ret.cg()} {name}({listed(k, lambda p: p[0], lambda mac: mac)})"
            args = listed(k, lambda p: p[1], lambda mac: f"PBR_UNITY_ARGS_{mac}")
            args += "".join(f", ({_glsl_literals(d)})" for d in defaults[k:])
            prototypes.append(f" {head};")
            bodies.append(f"{head} {{ {'return ' if ret.base != 'void' else ''}{name}({args}); }}")
        self.edits.close(self.toks[self.i - 1].e, renamed_reserved("".join(prototypes)))
        self.edits.close(len(self.text), "\n" + "\n".join(tail + [renamed_reserved(b) for b in bodies]) + "\n")

    def declarators(self, t, is_global, const, const_word=None):
        """``const_word``: a local's ``const``, dropped where an initialiser is not a constant
        expression (HLSL allows ``const float k = 1.0 / length(n);``, GLSL does not)."""
        while True:
            n = self.name().text
            vt = self.array_suffix(t)
            if is_global:
                self.semantic()
            if self.accept("="):
                if self.at("{"):
                    self.brace_init(vt)
                elif self.decl_only:
                    self.assignment()
                else:
                    init = self.assignment()
                    self.coerce(init, vt)
                    self.bool_of_unknown(init, vt)
                    names = re.findall(r"\b[A-Za-z_]\w*\b", self.text[init.s:init.e])
                    if const_word is not None and any(builtin_type(w) is None for w in names):
                        self.delete_word(const_word)
                        const_word = None
            self.declare(n, vt)
            if not self.accept(","):
                break

    def brace_init(self, t):
        """``{a, b}`` -> ``float[2](a, b)`` (an array) or ``T(a, b)`` (a struct)."""
        open_ = self.expect("{")
        items = []
        while not self.at("}"):
            if self.at("{"):
                if not t.array:
                    self.fail("nested initialiser")
                self.brace_init(t.element())  # an array of vectors or structs: {{0, 1}, {2, 3}}
                items.append(None)
            else:
                items.append(self.assignment())
            comma = self.accept(",")
            if comma is None:
                break
            if self.at("}"):  # HLSL's trailing comma, which a GLSL constructor does not take
                self.edits.replace(comma.s, comma.e, "")
            else:
                self.comma_after_directive(comma)
        close = self.expect("}")
        if t.array:
            size = str(t.array) if t.array > 0 else str(len(items))
            self.edits.replace(open_.s, open_.e, f"{Type(t.base, t.dim, t.cols).cg()}[{size}]"
                                                 + "".join(f"[{n}]" for n in t.inner) + "(")
            for it in items:
                if it is not None:
                    self.coerce(it, t.element())
        elif t.base in self.sym.structs:
            self.edits.replace(open_.s, open_.e, f"{t.base}(")
        elif t.matrix:  # HLSL fills a matrix's initialiser list row by row; GLSL's constructor by columns
            self.edits.replace(open_.s, open_.e, f"transpose({Type(t.base, t.cols, t.dim).cg()}(")
            self.edits.replace(close.s, close.e, "))")
            return
        elif t.numeric:
            self.edits.replace(open_.s, open_.e, f"{t.cg()}(")
        else:
            self.fail("initialiser")
        self.edits.replace(close.s, close.e, ")")

    def comma_after_directive(self, comma):
        """An initialiser's comma before a preprocessor line (TextMesh Pro: ``{a, b,`` then
        ``#if X`` ``c, d,`` ``#endif`` ``};``): where the lines after it are compiled out, HLSL
        reads a trailing comma, which a GLSL constructor refuses. The comma moves to the start
        of the line after the last directive before the next item, so it goes with that item."""
        between = [e for s, e in self.directives if comma.e <= s and e <= self.peek().s]
        if between and self.text.startswith("\n", between[-1]):
            self.edits.replace(comma.s, comma.e, "")
            self.edits.close(between[-1] + 1, ",")

    # --- statements
    def block(self, new_scope=True):
        self.expect("{")
        if new_scope:
            self.scopes.append({})
        while not self.accept("}"):
            if self.peek().kind == "eof":
                self.fail("unterminated block")
            self.statement()
        if new_scope:
            self.scopes.pop()

    def is_declaration(self):
        j = 0
        while self.peek(j).kind == "id" and self.peek(j).text in _QUALIFIERS and self.type_named(self.peek(j).text) is None:
            j += 1
        t = self.peek(j)
        if t.kind != "id":
            return False
        if t.text == "struct":
            return True
        if self.opaque_ahead(j):
            return self.peek(j + 2).text in (";", "=", ",", "[", ":", ")")
        return self.type_named(t.text) is not None and self.peek(j + 1).kind == "id"

    def statement(self):
        t = self.peek()
        if t.text == "{":
            return self.block()
        if t.text == ";":
            self.next()
            return
        if t.text == "[" and self.peek(1).kind == "id":  # [unroll], [loop], [branch(...)]
            start = self.next()
            depth = 1
            while depth:
                tk = self.next()
                if tk.kind == "eof":
                    self.fail("attribute")
                depth += {"[": 1, "]": -1}.get(tk.text, 0)
            self.delete_word(Tok("op", "", start.s, self.toks[self.i - 1].e))
            return self.statement()
        if t.kind == "id":
            if t.text == "if":
                self.next()
                self.expect("(")
                self.condition(self.expression())
                self.expect(")")
                self.statement()
                if self.accept("else"):
                    self.statement()
                return
            if t.text == "while":
                self.next()
                self.expect("(")
                self.condition(self.expression())
                self.expect(")")
                return self.statement()
            if t.text == "do":
                self.next()
                self.statement()
                self.expect("while")
                self.expect("(")
                self.condition(self.expression())
                self.expect(")")
                self.expect(";")
                return
            if t.text == "for":
                self.next()
                self.expect("(")
                self.scopes.append({})
                if not self.accept(";"):
                    self.simple_statement()
                if not self.at(";"):
                    self.condition(self.expression())
                self.expect(";")
                if not self.at(")"):
                    self.expression()
                self.expect(")")
                self.statement()
                self.scopes.pop()
                return
            if t.text == "return":
                self.next()
                if not self.at(";"):
                    e = self.expression()
                    if self.ret is not None:
                        self.coerce(e, self.ret, exact=True)
                self.expect(";")
                return
            if t.text in ("break", "continue", "discard"):
                self.next()
                self.expect(";")
                return
            if t.text == "switch":  # switch (e) { case k: ... default: ... }: its statements typed as any
                self.next()
                self.expect("(")
                self.expression()
                self.expect(")")
                self.expect("{")
                self.scopes.append({})
                while not self.accept("}"):
                    if self.accept("case"):
                        self.expression()
                        self.expect(":")
                    elif self.accept("default"):
                        self.expect(":")
                    elif self.peek().kind == "eof":
                        self.fail("unterminated switch")
                    else:
                        self.statement()
                self.scopes.pop()
                return
            if t.text == "struct":
                self.struct()
                return
            if t.text in _DECLARING_MACROS and self.at("(", 1) and self.peek(2).kind == "id" and self.scopes:
                self.declare(self.peek(2).text, self.type_named(_DECLARING_MACROS[t.text]))
            if t.text in _DECLARING_STATEMENTS and self.scopes:
                for name, type_name in _DECLARING_STATEMENTS[t.text]:
                    self.declare(name, self.type_named(type_name))
        self.simple_statement()

    def local_sampler(self, ty, start) -> bool:
        """``sampler2D ramp = _RampMap;`` in a function: HLSL takes a sampler local that names a
        global one (Amplify Shader Editor's generated code writes them); GLSL declares samplers
        only as uniforms and parameters ("image/sampler variables may only be declared as
        function parameters or uniform-qualified global variables"). The declaration is blanked
        and the local's uses in its scope read the global (sampler_alias)."""
        if ty is None or not ty.base.startswith(("sampler", "Texture")) or ty.numeric:
            return False
        if not (self.peek().kind == "id" and self.at("=", 1) and self.peek(2).kind == "id" and self.at(";", 3)):
            return False
        name, _, value, end = self.next(), self.next(), self.next(), self.next()
        target = self.sampler_alias(value.text) or value.text
        self.scopes[-1][name.text] = ty
        self.scopes[-1][("sampler alias", name.text)] = target
        if not self.decl_only:
            self.edits.replace(start, end.e, "")
        return True

    def sampler_alias(self, name):
        """The global sampler a local sampler names (local_sampler), or None."""
        for scope in reversed(self.scopes):
            if name in scope:
                return scope.get(("sampler alias", name))
        return None

    def simple_statement(self):
        """A declaration or an expression, then ';'."""
        if self.is_declaration():
            quals = self.qualifiers()
            for q in quals:
                if q.text == "static":
                    self.delete_word(q)
            if self.at("struct"):
                self.next()
            start = self.peek().s
            ty = self.type_spec()
            if self.local_sampler(ty, start):
                return
            const = next((q for q in quals if q.text == "const"), None)
            self.declarators(ty, is_global=False, const=False, const_word=const)
        else:
            first = self.peek()
            e = self.expression()
            if e.t is None and not self.at(";") and self.macro_statement(first):
                return  # UNITY_TRANSFER_FOG(o, o.vertex) with no ';' (a macro that brings its own)
        self.expect(";")

    def macro_statement(self, first: Tok) -> bool:
        """The statement began with a name the pass does not know and ends its line or is
        followed by another statement."""
        known = self.lookup(first.text) is not None or first.text in self.sym.functions or first.text in _INTRINSICS
        last = self.toks[self.i - 1]
        # what follows the call: its line's end, or a name or '}' (``M(a) M(b)``: no expression
        # goes on with one)
        ends = "\n" in self.text[last.e:self.peek().s] or self.peek().kind == "id" or self.at("}")
        return first.kind == "id" and not known and ends

    def delete_span(self, s, e):
        self.edits.replace(s, e, "")

    def condition(self, e: E):
        if e.t is not None and e.t.scalar and e.t.base != "bool":
            self.wrap(e, "bool")
        elif e.t is None and not self.decl_only and _NAME.fullmatch(self.text[e.s:e.e]):
            # a bare name of a type this pass cannot know: a keyword the harness defines 1 for
            # the variant (``if (_DEPTHSELECT_RAW)`` under ``#pragma shader_feature_local
            # _DEPTHSELECT_RAW ...``, FractalAsim's DepthVisualizer) or a global of an include
            # not read (a [Toggle] float): FXC converts a scalar condition to bool (nonzero is
            # true; Microsoft's HLSL reference, "if statement"), which bool() spells in GLSL
            self.wrap(e, "bool")

    # --- expressions
    def expression(self):
        e = self.assignment()
        while self.at(","):
            self.next()
            e = self.assignment()
        return e

    def assignment(self):
        lhs = self.ternary()
        t = self.peek()
        if t.kind == "op" and t.text in ("=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="):
            self.next()
            rhs = self.assignment()
            if t.text == "=":
                self.bool_of_unknown(rhs, lhs.t)
            if lhs.t is not None and rhs.t is not None:
                if t.text == "=":
                    self.coerce(rhs, lhs.t)
                elif t.text in ("+=", "-=", "*=", "/=") and lhs.t.numeric and rhs.t.numeric and not lhs.t.cols and not rhs.t.cols:
                    if rhs.t.dim > 1 and rhs.t.dim > lhs.t.dim:
                        self.truncate(rhs, lhs.t.dim)
                    elif rhs.t.base == "bool" and lhs.t.base != "bool":  # x *= a < b: HLSL takes 0 or 1
                        self.coerce(rhs, Type(lhs.t.base, rhs.t.dim))
                if t.text in ("+=", "-=", "*=", "/=") and lhs.t.base in ("int", "uint") and rhs.t.base == "float" \
                        and lhs.t.numeric and not lhs.t.cols and rhs.t.numeric and not rhs.t.cols \
                        and _PLAIN.fullmatch(self.text[lhs.s:lhs.e]) and not self.decl_only:
                    # ``steps *= scale`` (an int and a float): HLSL computes in float and
                    # converts the result back to int (FXC's warning X3205, conversion from a
                    # larger type, truncating toward 0); GLSL refuses the float operand, and
                    # glslang's HLSL converts the operand to int first (5 *= 0.75 gives 0)
                    for edits in (self.edits, self.fxc_edits):
                        edits.replace(t.s, t.e, f"= {lhs.t.cg()}({self.text[lhs.s:lhs.e]} {t.text[0]} (")
                        edits.close(rhs.e, "))")
                    return E(lhs.s, rhs.e, lhs.t, False)
                if t.text != "=" and lhs.t.base == "uint" and rhs.t.base == "int" and rhs.t.numeric:
                    # ``u %= 8`` (a uint2 and an int): HLSL converts the int operand to uint, as
                    # in ``u % 8`` (combine); GLSL 330 takes one signedness only
                    self.wrap(rhs, Type("uint", rhs.t.dim, rhs.t.cols).cg())
            if lhs.element:
                self.edits.drop(lhs.row_index)
                self.element_written(lhs.element)
            elif lhs.row and self.row_written(lhs.row, t, rhs):
                self.edits.drop(lhs.row_index)
            # else a matrix row written another way: the transposed read stays (GLSL refuses it)
            return E(lhs.s, rhs.e, lhs.t, False)
        return lhs

    def ternary(self):
        c = self.binary(0)
        if not self.at("?"):
            return c
        question = self.next()
        a = self.assignment()
        colon = self.expect(":")
        b = self.assignment()
        if c.t is not None and c.t.vector:
            # HLSL selects per component; GLSL's ?: takes one bool: cg_compat's
            # pbr_unity_select(c, a, b) = mix(b, a, c) with both branches at c's size
            if a.t is None or b.t is None or not (a.t.numeric and b.t.numeric) or a.t.cols or b.t.cols:
                return E(c.s, b.e, None, False)
            t = Type(_base(a.t, b.t), c.t.dim)
            if c.t.base != "bool":
                self.wrap(c, Type("bool", c.t.dim).cg())
            for x in (a, b):
                if x.t.dim != t.dim or x.t.base != t.base:
                    self.coerce(x, t)
            self.edits.open(c.s, "pbr_unity_select(")
            self.edits.replace(question.s, question.e, ",")
            self.edits.replace(colon.s, colon.e, ",")
            self.edits.close(b.e, ")")
            return E(c.s, b.e, t, True)
        self.condition(c)
        t = None
        if a.t is not None and b.t is not None:
            t = self.common(a.t, b.t)
            if t is not None:
                for x in (a, b):
                    if x.t.dim != t.dim or (x.t.base != t.base and not (t.base == "float" and x.t.base in ("int", "uint"))):
                        self.coerce(x, t)
        return E(c.s, b.e, t, False)

    def common(self, a: Type, b: Type):
        """HLSL's type of a binary arithmetic result (None: not both numeric, or matrices)."""
        if not (a.numeric and b.numeric):
            return None
        if a.cols or b.cols:
            if a == b:
                return a
            if a.scalar:
                return Type(_base(a, b), b.dim, b.cols)
            if b.scalar:
                return Type(_base(a, b), a.dim, a.cols)
            if a.cols and b.cols:
                # FXC cuts the larger matrix to the smaller's rows and columns (warning X3206:
                # Microsoft's HLSL reference, "Operators", binary casts: "the size of the
                # result is the smaller of the two")
                return Type(_base(a, b), min(a.dim, b.dim), min(a.cols, b.cols))
            return None
        n = b.dim if a.dim == 1 else a.dim if b.dim == 1 else min(a.dim, b.dim)
        return Type(_base(a, b), n)

    _LEVELS = [("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", ">", "<=", ">="),
               ("<<", ">>"), ("+", "-"), ("*", "/", "%")]

    def binary(self, level):
        if level == len(self._LEVELS):
            return self.unary()
        a = self.binary(level + 1)
        while self.peek().kind == "op" and self.peek().text in self._LEVELS[level]:
            op = self.next()
            b = self.binary(level + 1)
            a = self.combine(a, op, b)
        return a

    def combine(self, a: E, op: Tok, b: E) -> E:
        o = op.text
        span = (a.s, b.e)
        if a.t is None or b.t is None:
            return E(*span, None, False)
        if o in ("&&", "||"):
            n = max(a.t.dim, b.t.dim)
            if n > 1 and not a.t.cols and not b.t.cols and a.t.numeric and b.t.numeric and not self.decl_only:
                # HLSL's && and || of vectors are componentwise (Microsoft's HLSL reference,
                # "Operators": "Boolean math operators ... operate on a per-component basis";
                # a scalar operand is replicated): GLSL's take scalars only, so each operand's
                # components as 0 or 1 meet in & or | and the result is compared with 0
                # (Amplify's Preview_NandNode: ``!tex2D(_A, uv) && !tex2D(_B, uv)``)
                for x in (a, b):
                    self.edits.open(x.s, f"uvec{n}(bvec{n}(")
                    self.edits.close(x.e, "))")
                self.edits.open(a.s, "notEqual(")
                self.edits.replace(op.s, op.e, o[0])
                self.edits.close(b.e, f", uvec{n}(0u))")
                return E(*span, Type("bool", n), True)
            for x in (a, b):
                self.condition(x)
            return E(*span, Type("bool"), False)
        if o in ("|", "^", "&") and a.t.base == b.t.base == "bool" and a.t.dim == b.t.dim == 1 \
                and not self.decl_only:
            # HLSL's bitwise operators on bools (abcwangxiaoqi's DepthTroughtWall02: ``if (a < 1.0
            # & b < 1.0)``): FXC takes a bool as an integer 0 or 1 (Microsoft's HLSL reference,
            # "Scalar types"), so a & b, a | b and a ^ b are the logical and, or and xor; GLSL
            # takes integers only, and its &&, || and ^^ are those (both operands evaluated
            # first: a comparison has no side effects to skip)
            self.edits.open(a.s, "(")
            self.edits.replace(op.s, op.e, {"&": "&&", "|": "||", "^": "^^"}[o])
            self.edits.close(b.e, ")")
            return E(*span, Type("bool"), True)
        if o in ("|", "^", "&", "<<", ">>"):
            if o in ("|", "^", "&") and {a.t.base, b.t.base} == {"int", "uint"} and a.t.numeric and b.t.numeric:
                # HLSL converts the int operand to uint; GLSL 330 takes one signedness only
                for x in (a, b):
                    if x.t.base == "int":
                        self.wrap(x, Type("uint", x.t.dim).cg())
                return E(*span, Type("uint", max(a.t.dim, b.t.dim)), False)
            return E(*span, a.t if a.t.numeric else None, False)
        t = self.common(a.t, b.t)
        if t is None:
            return E(*span, None, False)
        if a.t.cols and b.t.cols and o in ("*", "+", "-", "/"):
            return self.matrix_componentwise(a, op, b, t)
        if not t.cols and t.dim > 1:
            for x in (a, b):
                if x.t.dim > t.dim:
                    self.truncate(x, t.dim)
        if t.base == "uint":  # HLSL converts int to uint here; GLSL 330 does not (4.00 does)
            for x in (a, b):
                if x.t.base == "int":
                    self.wrap(x, Type("uint", x.t.dim, x.t.cols).cg())
        if o in _COMPARE:
            if t.dim == 1 or t.cols:
                return E(*span, Type("bool", 1 if not t.cols else t.dim, t.cols), False)
            for x in (a, b):
                if x.t.dim == 1:
                    self.wrap(x, Type(t.base, t.dim).cg())
            self.edits.open(a.s, _COMPARE[o] + "(")
            self.operator_to_comma(a, op)
            self.edits.close(b.e, ")")
            return E(*span, Type("bool", t.dim), True)
        if t.base == "bool" or "bool" in (a.t.base, b.t.base):
            base = "float" if t.base == "bool" else t.base
            for x in (a, b):
                if x.t.base == "bool":
                    self.wrap(x, Type(base, x.t.dim if x.t.dim <= t.dim else t.dim, x.t.cols).cg())
            t = Type(base if t.base == "bool" else t.base, t.dim, t.cols)
        if o == "%" and t.base == "float":
            if b.t.dim == 1 or b.t.dim == t.dim:
                if a.t.dim == 1 and t.dim > 1:
                    self.wrap(a, Type("float", t.dim).cg())
                self.edits.open(a.s, "fmod(")
                self.operator_to_comma(a, op)
                self.edits.close(b.e, ")")
                return E(*span, t, True)
            return E(*span, None, False)
        return E(*span, t, False)

    def matrix_componentwise(self, a: E, op: Tok, b: E, t: Type) -> E:
        """HLSL's arithmetic of two matrices, component by component, each first cut to ``t``
        (the smaller's size, as FXC does: common); GLSL's ``*`` of matrices is their linear
        algebra product, its ``matrixCompMult`` HLSL's ``*`` (GLSL 3.30, section 5.9)."""
        if self.decl_only:
            return E(a.s, b.e, t, False)
        for x in (a, b):
            if (x.t.dim, x.t.cols) != (t.dim, t.cols):
                self.wrap(x, t.cg())       # GLSL's matrix-from-matrix: the upper-left block
                self.fxc_edits.open(x.s, f"(({t.cg()})(")   # glslang's HLSL needs the cast too
                self.fxc_edits.close(x.e, "))")
        if op.text != "*":
            return E(a.s, b.e, t, False)
        # glslang 11's HLSL front end also multiplies two matrices as linear algebra (a 3x3 pair
        # drew the product): the HLSL as written calls unity_hlsl_support.hlsl's componentwise one
        for edits, name in ((self.edits, "matrixCompMult("), (self.fxc_edits, "pbrlab_matrix_comp_mult(")):
            edits.open(a.s, name)
            gap = self.text[a.e:op.s]
            edits.replace(op.s if "\n" in gap else a.e, op.e, ",")
            edits.close(b.e, ")")
        return E(a.s, b.e, t, True)

    def operator_to_comma(self, a: E, op: Tok):
        """``a < b`` -> ``a, b`` inside the call that replaces the operator."""
        gap = self.text[a.e:op.s]
        self.edits.replace(op.s if "\n" in gap else a.e, op.e, ",")

    def unary(self):
        t = self.peek()
        if t.kind == "op" and t.text in ("-", "+", "!", "~", "++", "--"):
            self.next()
            x = self.unary()
            if t.text == "!":
                if x.t is not None and x.t.vector:
                    # HLSL's componentwise not (of a numeric vector: x == 0): GLSL's not()
                    if not self.decl_only:
                        inner = "(" if x.t.base == "bool" else f"(bvec{x.t.dim}("
                        self.edits.replace(t.s, t.e, "not" + inner)
                        self.edits.close(x.e, ")" if x.t.base == "bool" else "))")
                    return E(t.s, x.e, Type("bool", x.t.dim), False)
                self.condition(x)
                return E(t.s, x.e, Type("bool"), False)
            if t.text in ("-", "+", "~"):
                return E(t.s, x.e, self.bool_sign(x), False)
            return E(t.s, x.e, x.t, False)
        if t.text == "(" and self.peek(1).kind == "id" and self.at(")", 2) and self.peek(1).text in self.sym.structs \
                and self.peek(3).text == "0":
            # HLSL's zero cast (Struct)0 -> Struct(every member 0), GLSL having no such cast
            open_, name, _, zero = self.next(), self.next(), self.next(), self.next()
            self.edits.replace(open_.s, zero.e, self.zero_value(Type(name.text)))
            return E(open_.s, zero.e, Type(name.text), False)
        cast = self.type_named(self.peek(1).text) if t.text == "(" and self.peek(1).kind == "id" and self.at(")", 2) else None
        if cast is not None and cast.base in self.sym.structs and not cast.dim and not self.decl_only \
                and (self.peek(3).kind in ("id", "num") or self.at("(", 3)):
            cast_value = self.struct_cast(cast)
            if cast_value is not None:
                return cast_value
        if cast is not None and cast.numeric:
            # a cast (float3)x -> float3(x); of an alias too: (real3x3)m -> float3x3(m)
            open_, name, close = self.next(), self.next(), self.next()
            x = self.unary()
            ty = cast
            if builtin_type(name.text) is None:
                self.edits.replace(name.s, name.e, ty.cg())
            self.edits.replace(open_.s, open_.e, "")
            self.edits.replace(close.s, close.e, "(")
            self.edits.close(x.e, ")")
            return E(open_.s, x.e, ty, True)
        return self.postfix()

    def bool_sign(self, x: E) -> Type | None:
        """The type of ``-x``, ``+x`` or ``~x``. Of a bool: HLSL promotes the operand to int
        first, as C++ does (clang's, DXC's; glslang's HLSL converts a bool operand of arithmetic
        to int, its Test/hlsl.boolConv.vert): -true is -1. GLSL's and glslang's operators refuse
        a bool: the conversion spelled out in both languages."""
        if x.t is None or not x.t.numeric or x.t.base != "bool" or x.t.cols or self.decl_only:
            return x.t
        spelled = "int" + (str(x.t.dim) if x.t.dim > 1 else "")
        for edits in (self.edits, self.fxc_edits):
            edits.open(x.s, spelled + "(")
            edits.close(x.e, ")")
        return Type("int", x.t.dim)

    def struct_cast(self, cast: Type) -> E | None:
        """A cast to a struct, ``(VertexOutput)x``, at '(' (not ``(S)0``: unary): GLSL has no
        casts, and ``(S)`` alone reads as a constructor missing its arguments. Of a value of the
        struct itself, the cast is dropped; of a scalar (a name or a literal), every component
        of every member is the scalar converted (Microsoft's HLSL reference, "Casting and
        conversions": scalar-to-structure, as the port's (S)0); None, nothing read, otherwise
        (left as written)."""
        mark, fxc_mark, at = self.edits.mark(), self.fxc_edits.mark(), self.i
        open_, _, close = self.next(), self.next(), self.next()
        x = self.unary()
        if x.t == cast:
            self.edits.replace(open_.s, close.e, "")
            return E(open_.s, x.e, cast, False)
        written = self.text[x.s:x.e]
        if x.t is not None and x.t.scalar and (_PLAIN.fullmatch(written) or x.literal
                                               or (self.i == at + 4 and self.toks[at + 3].kind == "num")):
            filled = self.filled_value(cast, _glsl_literals(written))
            if filled is not None:
                self.edits.drop_after(mark)
                self.edits.replace(open_.s, x.e, filled)
                return E(open_.s, x.e, cast, True)
        self.edits.drop_after(mark)
        self.fxc_edits.drop_after(fxc_mark)
        self.i = at
        return None

    def filled_value(self, ty: Type, scalar: str) -> str | None:
        """``ty`` with the scalar expression ``scalar`` (a name or a literal) in every
        component, converted to each member's base, in Cg spelling; None for a struct whose
        members depend on #if lines or are of unknown or non-numeric type."""
        if ty.array > 0:
            element = self.filled_value(ty.element(), scalar)
            return None if element is None else f"{ty.cg()}({', '.join([element] * ty.array)})"
        if ty.base in self.sym.structs:
            members = list(self.sym.structs[ty.base].values())
            if ty.base in self.sym.conditional or None in members:
                return None
            values = [self.filled_value(m, scalar) for m in members]
            if None in values:
                return None
            name = RENAME_PREFIX + ty.base if is_reserved(ty.base) else ty.base
            return f"{name}({', '.join(values)})"
        if not ty.numeric or ty.array:
            return None
        if ty.cols:  # every element, not GLSL's diagonal (matrix_of_scalar)
            before, after = matrix_of_scalar(ty)
            return f"{before}{scalar}{after}"
        return f"{ty.cg()}({scalar})"

    def zero_value(self, ty: Type) -> str:
        """``ty``'s zero in Cg spelling: 0 of its base in every component, every member's zero
        for a struct (in declaration order), each element's for an array."""
        if ty.array > 0:
            element = self.zero_value(ty.element())
            return f"{ty.cg()}({', '.join([element] * ty.array)})"
        if ty.base in self.sym.conditional:
            return f"pbr_unity_zero_{ty.base}()"
        if ty.base in self.sym.structs:
            members = self.sym.structs[ty.base].values()
            if None in members:  # a member of two types under #if (member_type): left as written
                self.fail("a zero of a member of unknown type")
            return f"{ty.base}({', '.join(self.zero_value(m) for m in members)})"
        zero = {"float": "0.0", "int": "0", "uint": "0u", "bool": "false"}.get(ty.base)
        if zero is None:
            self.fail("a zero of this type")
        return zero if ty.scalar else f"{ty.cg()}({zero})"

    def postfix(self):
        e = self.primary()
        while True:
            t = self.peek()
            if t.text == "." and t.kind == "op":
                self.next()
                m = self.peek()
                if m.kind != "id":
                    self.fail("member")
                if e.t is not None and e.t.base == "stream" and self.peek(1).text == "(":
                    self.next()  # a stream's method: Append(v), RestartStrip()
                    close = self.arguments()[1]
                    e = E(e.s, close.e, VOID, True)
                    continue
                e = self.member(e, m)
            elif t.text == "[" and t.kind == "op":
                bracket = self.next()
                idx = self.expression()
                close = self.expect("]")
                e = self.index(e, idx, close, bracket)
            elif t.text in ("++", "--") and t.kind == "op":
                self.next()
                e = E(e.s, t.e, e.t, False)
            else:
                return e

    def member(self, obj: E, m: Tok) -> E:
        ot = obj.t
        if ot is not None and ot.base in self.sym.structs and not ot.array:
            self.name()
            return E(obj.s, m.e, self.sym.structs[ot.base].get(m.text))
        if ot is not None and (ot.base in self.sym.aliases) and not ot.array:
            self.name()
            fields = self.sym.structs.get(self.resolve_alias(ot.base), {})
            return E(obj.s, m.e, fields.get(m.text))
        self.next()
        if ot is not None and ot.matrix and _MATRIX_ELEMENTS.fullmatch(m.text):
            return self.matrix_elements(obj, m, ot)
        if ot is not None and ot.numeric and not ot.cols and _SWIZZLE.fullmatch(m.text) and \
                all(_swizzle_index(ch) < ot.dim for ch in m.text):
            n = len(m.text)
            if ot.dim == 1:  # a scalar's swizzle: GLSL 330 has none
                dot = self.toks[self.i - 2]
                if n == 1:
                    self.edits.replace(dot.s, m.e, "")
                    return E(obj.s, m.e, ot, obj.postfix)
                self.edits.open(obj.s, Type(ot.base, n).cg() + "(")
                self.edits.replace(dot.s, m.e, ")")
                return E(obj.s, m.e, Type(ot.base, n), True)
            if obj.row and n == 1:  # M[i].y: an element, written as GLSL's M[1][i]
                dot = self.toks[self.i - 2]
                return E(obj.s, m.e, Type(ot.base), row_index=obj.row_index,
                         element=(obj, (dot.s, m.e), str(_swizzle_index(m.text))))
            return E(obj.s, m.e, Type(ot.base, n), True, (m.s, m.e, m.text))
        return E(obj.s, m.e, None)

    def matrix_elements(self, obj: E, m: Tok, ot: Type) -> E:
        """HLSL's matrix element ``M._m12`` (row 1, column 2, from 0) or ``M._23`` (from 1):
        GLSL's ``M[C][R]`` (columns first). Several in a row (``M._m03_m13_m23``) were spelled
        as a constructor of single ones before (cg_spellings._matrix_swizzles); one left (the
        object an expression): no type, for the compiler to name."""
        picks = [(int(z[-2]), int(z[-1])) if "m" in z else (int(z[-2]) - 1, int(z[-1]) - 1)
                 for z in re.findall(r"_m?\d\d", m.text)]
        if len(picks) > 1:
            return E(obj.s, m.e, None)
        (r, c), = picks
        if r >= ot.dim or c >= ot.cols:
            self.fail("matrix element out of range")
        dot = self.toks[self.i - 2]
        self.edits.replace(dot.s, m.e, f"[{c}][{r}]")
        return E(obj.s, m.e, Type(ot.base), True)

    def index(self, obj: E, idx: E, close: Tok, bracket: Tok) -> E:
        if idx.t is not None and idx.t.scalar and idx.t.base == "float":
            self.wrap(idx, "int")
        ot = obj.t
        if ot is None:
            return E(obj.s, close.e, None)
        if ot.array:
            return E(obj.s, close.e, ot.element())
        if ot.cols:  # HLSL m[i] is row i; GLSL's is column i
            ids = (self.edits.open(obj.s, "transpose("), self.edits.close(obj.e, ")"))
            return E(obj.s, close.e, Type(ot.base, ot.cols), True, row_index=ids, row=(obj, bracket, close))
        if ot.vector:
            if obj.row:  # M[i][j]: HLSL's row i, column j
                return E(obj.s, close.e, Type(ot.base), row_index=obj.row_index,
                         element=(obj, (bracket.s, close.e), self.text[bracket.e:close.s]))
            return E(obj.s, close.e, Type(ot.base))
        return E(obj.s, close.e, None)

    def row_written(self, row, op: Tok, rhs: E) -> bool:
        """``M[i] = v`` (HLSL's row i) as ``pbr_unity_set_row(M, i, v)`` (cg_compat.glsl); a
        compound ``M[i] += v`` as ``pbr_unity_set_row(M, i, transpose(M)[i] + (v))``, where
        ``M`` and ``i`` are names or literals (their text read twice reads the same). False:
        not written here (the transposed read stays, which GLSL refuses as an l-value)."""
        obj, bracket, close = row
        matrix, index = self.text[obj.s:obj.e], self.text[bracket.e:close.s]
        if op.text == "=":
            middle = ", "
        elif op.text in ("+=", "-=", "*=", "/=") and _PLAIN.fullmatch(matrix) and _PLAIN.fullmatch(index.strip()):
            middle = f", transpose({matrix})[{index}] {op.text[0]} ("
        else:
            return False
        self.edits.open(obj.s, "pbr_unity_set_row(")
        self.edits.replace(bracket.s, bracket.e, ", ")
        self.edits.replace(close.s, op.e, middle)
        self.edits.close(rhs.e, ")" if op.text == "=" else "))")
        return True

    def element_written(self, element) -> bool:
        """``M[i][j] = x`` (HLSL: row i, column j) as GLSL's ``M[j][i] = x``; ``M[i].y = x``
        likewise (``element``: E.element)."""
        row, (start, end), column = element
        _, bracket, close = row.row
        self.edits.replace(bracket.s, close.e, f"[{column}]")
        self.edits.replace(start, end, f"[{self.text[bracket.e:close.s]}]")
        return True

    def primary(self) -> E:
        t = self.next()
        if t.kind == "num":
            text = t.text
            is_float = not text.lower().startswith("0x") and bool(re.search(r"[.eE]|[fFhH]$", text))
            base = "float" if is_float else "uint" if text[-1] in "uU" else "int"
            glsl = re.sub(r"[hHlL]+$", "", text) if is_float else re.sub(r"[lL]+$", "", text)
            if is_float and re.fullmatch(r"\d+[fF]", glsl):
                glsl = glsl[:-1] + ".0"
            if glsl != text and not self.decl_only:
                self.edits.replace(t.s, t.e, glsl)
            return E(t.s, t.e, Type(base), False, literal=True)
        if t.kind == "str":
            return E(t.s, t.e, None)
        if t.text == "(":
            x = self.expression()
            close = self.expect(")")
            return E(t.s, close.e, x.t, True, literal=x.literal)
        if t.kind != "id":
            raise CgSyntaxError(f"unexpected {t.text!r}", t.s)
        if t.text in ("true", "false"):
            return E(t.s, t.e, Type("bool"), True)
        if self.at("("):
            return self.call(t)
        self.i -= 1
        self.name()
        alias = self.sampler_alias(t.text) if self.scopes else None
        if alias is not None and not self.decl_only:
            self.edits.replace(t.s, t.e, alias)  # a sampler local: the global it names (local_sampler)
        ty = self.lookup(t.text)
        # a #define's expression (defined_value) takes a swizzle unparenthesised only if plain
        postfix = t.text not in self.define_types or bool(_PLAIN.fullmatch(self.own_defines[t.text].strip()))
        return E(t.s, t.e, ty, postfix)

    def arguments(self):
        self.expect("(")
        args = []
        if not self.at(")"):
            while True:
                args.append(self.assignment())
                # an argument-list macro after it (``d SHADOW_MASK_ARG``: ``, mask`` or nothing),
                # left where it stands
                while self.peek().kind == "id" and self.peek(1).text in (",", ")"):
                    self.next()
                if not self.accept(","):
                    break
        close = self.expect(")")
        return args, close

    def call(self, name: Tok) -> E:
        ctor = builtin_type(name.text)
        if ctor is None and self.type_named(name.text) is not None and self.type_named(name.text).numeric:
            ctor = self.type_named(name.text)
        if ctor is not None:
            args, close = self.arguments()
            if ctor.cols and len(args) > 1 and not self.decl_only:  # rows in HLSL, columns in GLSL
                self.edits.open(name.s, "transpose(")
                if ctor.cols != ctor.dim:
                    self.edits.replace(name.s, name.e, Type(ctor.base, ctor.cols, ctor.dim).cg())
                self.edits.close(close.e, ")")
            return E(name.s, close.e, ctor if ctor.numeric else None, True)
        self.rename_reserved_name(name)
        self.rename_function_name(name)
        args, close = self.arguments()
        span = (name.s, close.e)
        fname = name.text
        own = self.sym.functions.get(OWN_PREFIX + fname) if fname in _GLSL_BUILT_IN_INTRINSICS else None
        if own and self.overload(own, args) is not None:  # the program's own of a built-in's name
            if not self.decl_only:
                self.edits.replace(name.s, name.e, OWN_PREFIX + fname)
            fname = OWN_PREFIX + fname
        elif fname in _INTRINSICS:
            return E(*span, self.intrinsic(fname, args), True)
        if fname == "sincos" and len(args) == 3:
            self.sincos_splat(*args)
            return E(*span, VOID, True)
        if fname == "mul" and len(args) == 2 and all(a.t is not None and a.t.vector for a in args):
            # HLSL's mul of two vectors is their inner product (Microsoft's HLSL reference,
            # "mul": vector x vector -> scalar, "x and y must be the same size"; FXC cuts the
            # longer with warning X3206, as in any binary operation); GLSL's dot spells it
            n = min(a.t.dim for a in args)
            if not self.decl_only:
                self.edits.replace(name.s, name.e, "dot")
                for a in args:
                    if a.t.dim > n:
                        self.truncate(a, n)
            return E(*span, Type("float"), True)
        if fname == "mul" and len(args) == 2 and all(a.t is not None and a.t.numeric for a in args) \
                and any(a.t.scalar for a in args):
            self.mul_by_scalar(name, *args)
            return E(*span, _mul_type(args[0].t, args[1].t), True)
        if fname == "mul" and len(args) == 2:
            self.mul_vector_truncated(*args)
            return E(*span, _mul_type(args[0].t, args[1].t), True)
        if fname == "transpose" and len(args) == 1 and args[0].t is not None and args[0].t.matrix:
            m = args[0].t
            return E(*span, Type(m.base, m.cols, m.dim), True)
        if fname == "determinant" and len(args) == 1 and args[0].t is not None and args[0].t.matrix:
            return E(*span, Type("float"), True)
        sigs = self.sym.functions.get(fname) or self.sym.functions.get(self.resolve_alias(fname))
        if not sigs:
            return E(*span, *self.macro_value(fname, args))
        sig = self.overload(sigs, args)
        if sig is None:
            rets = {s.ret for s in sigs}
            return E(*span, rets.pop() if len(rets) == 1 else None, True)
        for a, p in zip(args, sig.params):
            if p.qual == "in":
                if not self.decl_only:  # the program's own, an include's, or the library's
                    # (Linear01Depth(tex2D(_CameraDepthTexture, uv)): its HLSL twin takes a float too)
                    self.fxc_argument(a, p.type)
                self.coerce(a, p.type)
        return E(*span, sig.ret if sig.ret != VOID else VOID, True)

    def macro_value(self, name: str, args: list) -> tuple:
        """(type, postfix) of a use of a function-like macro of one expression (``float3 shadow
        = SHADOW_ATTENUATION(i);`` with shader_variables.glsl's ``#define SHADOW_ATTENUATION(a)
        1.0``: float, which FXC splats to the float3 it initialises): its body read with each
        parameter of its argument's type and the locals in scope (the text the preprocessor puts
        there); (None, True) where the name is no such macro, its definitions disagree, or a
        body is no expression the pass reads."""
        key = (name, tuple(a.t for a in args))
        if key in self.macro_types:
            return self.macro_types[key]
        self.macro_types[key] = (None, True)  # a macro naming itself reads as unknown
        found, postfix = set(), True
        for params, body in self.sym.macros.get(name, ()):
            if len(params) != len(args):
                return self.macro_types[key]
            # (the symbols shared: a body holds no ``#``, so no #define of it adds any, and an
            # expression read for its type declares nothing)
            sub = _Parser(body, self.sym, declarations_only=True)
            sub.own_defines, sub.define_types, sub.macro_types = self.own_defines, self.define_types, self.macro_types
            sub.scopes = [dict(scope) for scope in self.scopes] + [{p: a.t for p, a in zip(params, args)}]
            try:
                value = sub.expression()
            except CgSyntaxError:
                return self.macro_types[key]
            if sub.peek().kind != "eof" or value.t is None or not value.t.numeric:
                return self.macro_types[key]
            found.add(value.t)
            postfix = postfix and value.postfix
        if len(found) == 1:
            self.macro_types[key] = (found.pop(), postfix)
        return self.macro_types[key]

    def fxc_argument(self, a: E, param: Type):
        """A vector argument longer than the parameter it meets (``UnpackUV(v.texcoord1)``, a
        float2 to a float): FXC passes its first components (warning X3206, implicit truncation
        of a vector type); glslang's HLSL front end finds no overload. Recorded for the HLSL
        text as written (``fxc_conversions``); the GLSL port's coerce truncates it the same."""
        if a.t is None or not (a.t.numeric and param.numeric) or a.t.cols or param.cols \
                or a.t.dim <= param.dim or a.t.dim == 1:
            return
        if a.swizzle is not None:
            s, end, letters = a.swizzle
            self.fxc_edits.replace(s, end, letters[:param.dim])
        elif a.postfix:
            self.fxc_edits.close(a.e, "." + "xyzw"[:param.dim])
        else:
            self.fxc_edits.open(a.s, "(")
            self.fxc_edits.close(a.e, ")." + "xyzw"[:param.dim])

    def sincos_splat(self, x: E, s: E, c: E):
        """``sincos(h, s3, c3)`` of a scalar angle and vector outputs (FractalAsim's HueShift):
        HLSL's sincos is a template whose three arguments share one type (Microsoft's HLSL
        reference, "sincos": s and c "the same type as" x), and FXC promotes the scalar
        argument to the outputs' vector, as any intrinsic's scalar is promoted (the reference's
        "Intrinsic Functions" template types); GLSL's cg_compat sincos assigns sin(x) to the
        vector and glslang's HLSL front end finds the overload ambiguous: both spell the splat."""
        if any(a.t is None or not a.t.numeric or a.t.cols for a in (x, s, c)) or self.decl_only:
            return
        if x.t.dim == 1 and s.t.dim == c.t.dim > 1:
            ctor = Type("float", s.t.dim).cg()
            for edits in (self.edits, self.fxc_edits):
                edits.open(x.s, ctor + "(")
                edits.close(x.e, ")")

    def mul_by_scalar(self, name: Tok, a: E, b: E):
        """HLSL's mul with a scalar operand (``mul(rayDir, distance)``): the componentwise
        product, x * y (Microsoft's HLSL reference, "mul": the first row of its table, "x
        scalar, y vector/matrix: out = x * y", and the scalar-y rows alike); GLSL has no mul,
        and cg_compat.glsl's overloads take matrices only, so the call is spelled as the product
        of its two parenthesised arguments, ``((a) * (b))``."""
        comma = next((t for t in self.toks if t.s >= a.e and t.e <= b.s and t.text == ","), None)
        if self.decl_only or comma is None:
            return
        self.edits.replace(name.s, name.e, "")
        self.edits.open(a.s, "(")
        self.edits.close(a.e, ")")
        self.edits.replace(comma.s, comma.e, " *")
        self.edits.open(b.s, "(")
        self.edits.close(b.e, ")")

    def mul_vector_truncated(self, a: E, b: E):
        """HLSL's mul of a vector longer than the matrix's side it meets (``mul(v4, m3x3)``,
        ``mul(m3x3, v4)``): FXC takes the vector's first components (warning X3206, implicit
        truncation of a vector type; glslang's HLSL front end does the same with a warning,
        "mul() matrix size mismatch"); GLSL has no such overload, so the cut is written out."""
        if a.t is None or b.t is None:
            return
        if a.t.vector and b.t.matrix and a.t.dim > b.t.dim:
            self.truncate(a, b.t.dim)
            a.t = Type(a.t.base, b.t.dim)
        elif a.t.matrix and b.t.vector and b.t.dim > a.t.cols:
            self.truncate(b, a.t.cols)
            b.t = Type(b.t.base, a.t.cols)

    def overload(self, sigs, args):
        sigs = [s for s in sigs if len(s.params) == len(args)]
        if len(sigs) == 1:
            return sigs[0]
        if any(a.t is None for a in args):
            return None
        exact = [s for s in sigs if all(_same_shape(a.t, p.type) for a, p in zip(args, s.params))]
        if len(exact) == 1:
            return exact[0]
        if exact:
            return None
        return _best_converted(sigs, args)

    def intrinsic(self, fname, args):
        kind, scalar_ok = _INTRINSICS[fname]
        if any(a.t is None or not a.t.numeric or a.t.cols for a in args) or not args:
            return None
        if kind == "bool1":
            a = args[0]
            if len(args) == 1 and not self.decl_only and (a.t.dim == 1 or a.t.base != "bool"):
                # HLSL's any/all of a numeric value test its components against 0, and take a
                # scalar; GLSL's take a bool vector only: any(bvecN(x)), of a scalar any(bvec2(x))
                self.wrap(a, f"bvec{max(a.t.dim, 2)}")
            return Type("bool")
        dims = [a.t.dim for a in args if a.t.dim > 1]
        n = min(dims) if dims else 1
        if kind == "cross":
            n = 3
        elif kind == "first":
            n = args[0].t.dim
        base = "float" if any(a.t.base == "float" for a in args) or fname not in ("abs", "min", "max", "clamp", "sign") \
            else args[0].t.base
        if base == "bool":  # HLSL's arithmetic promotes a bool to int (abs(c < 0.5) is 0 or 1)
            base = "int"
        for a in args:  # GLSL's numeric built-ins take no bool: converted as HLSL does
            if a.t.base == "bool":
                self.wrap(a, Type(base, a.t.dim).cg())
                a.t = Type(base, a.t.dim)
        # GLSL's scalar overloads take scalars at all those positions or at none (clamp(vec3,
        # float, float), smoothstep(float, float, vec3)): with a vector at one, HLSL's promoted
        # scalar at another is written out (clamp(v, 0, hi) -> clamp(v, float3(0), hi))
        if any(args[i].t.dim > 1 for i in scalar_ok if i < len(args)):
            scalar_ok = ()
        for i, a in enumerate(args):
            if kind == "first" and i in scalar_ok:
                continue
            if a.t.dim > 1 and a.t.dim > n:
                self.truncate(a, n)
            elif a.t.dim == 1 and n > 1 and i not in scalar_ok:
                self.wrap(a, Type(base, n).cg())
        if kind == "scalar":
            return Type("float")
        return Type(base, n)

    # --- conversions
    def wrap(self, e: E, ctor: str):
        self.edits.open(e.s, ctor + "(")
        self.edits.close(e.e, ")")

    def truncate(self, e: E, n: int):
        """A vector expression cut to its first n components, as HLSL does."""
        if e.swizzle is not None:
            s, end, letters = e.swizzle
            self.edits.replace(s, end, letters[:n])
        elif e.postfix:
            self.edits.close(e.e, "." + "xyzw"[:n])
        else:
            self.edits.open(e.s, "(")
            self.edits.close(e.e, ")." + "xyzw"[:n])

    def coerce(self, e: E, target: Type, exact=False):
        """Spell out HLSL's implicit conversion of ``e`` to ``target``, where GLSL needs it
        (GLSL 330 converts int and uint to float itself, except in ``return``: ``exact``)."""
        src = e.t
        if src is None or target is None or not src.numeric or not target.numeric:
            return
        if target.cols and src.scalar and target.base == "float":
            before, after = matrix_of_scalar(target)
            self.edits.open(e.s, before)
            self.edits.close(e.e, after)
            return
        if target.cols and src.vector and src.dim == target.dim * target.cols and not self.decl_only:
            # a vector to a matrix of as many components fills it row by row (Microsoft's HLSL
            # reference, "Casting and conversions": vector-to-matrix, "the vector must be the
            # same size as the matrix"); GLSL's constructor fills columns: transposed
            self.edits.open(e.s, f"transpose({Type(target.base, target.cols, target.dim).cg()}(")
            self.edits.close(e.e, "))")
            return
        if target.cols or src.cols:
            if target.cols and src.cols and (src.dim, src.cols) != (target.dim, target.cols) \
                    and src.dim >= target.dim and src.cols >= target.cols:
                self.wrap(e, target.cg())
            return
        base_ok = src.base == target.base or (target.base == "float" and src.base in ("int", "uint") and not exact)
        if src.dim == target.dim:
            if not base_ok:
                self.wrap(e, target.cg())
            return
        if src.dim == 1:                 # splat
            self.wrap(e, target.cg())
        elif src.dim > target.dim:       # truncate
            if base_ok:
                self.truncate(e, target.dim)
            else:
                self.wrap(e, target.cg())


    def bool_of_unknown(self, e: E, target: Type | None):
        """A value of a type this pass cannot infer (a global another include declares:
        TextMesh Pro's ``bool raisedBevel = step(1, fmod(_ShaderFlags, 2));``) given to a scalar
        bool: ``bool(e)``, HLSL's conversion (nonzero is true; a vector's first component, as
        HLSL's truncation takes it), which GLSL's constructor spells for a bool, a number or a
        vector alike, so it is right whatever ``e``'s type turns out to be."""
        if e.t is None and target == Type("bool") and not self.decl_only:
            self.wrap(e, "bool")


def matrix_of_scalar(target: Type) -> tuple:
    """(text before, text after) a scalar given to a matrix ``target``: HLSL's scalar-to-matrix
    promotion fills every element with the scalar (Microsoft's HLSL reference, "Type
    conversion": scalar-to-matrix replicates the scalar); GLSL's ``matN(x)`` puts x on the
    diagonal only, but adds a scalar to every element of a matrix (GLSL 3.30, section 5.9):
    ``(floatRxC(0.0) + float(x))``, x read once."""
    return f"({target.cg()}(0.0) + float(", "))"


def _base(a: Type, b: Type) -> str:
    bases = {a.base, b.base}
    if "float" in bases:
        return "float"
    if "uint" in bases:
        return "uint"
    if "int" in bases:
        return "int"
    return "bool"


def _conversion_rank(arg: Type, param: Param):
    """What HLSL's implicit conversion of an argument to a parameter costs, for choosing among
    overloads none of which takes the arguments as they are: 0 the same shape, 1 a scalar
    splatted to a vector or a base converted, 2 a vector truncated (clang's HLSL ranks a vector
    splat and truncation as conversions of their own, truncation the costlier: clang's
    Sema/Overload.h, ICK_HLSL_Vector_Splat / ICK_HLSL_Vector_Truncation); None where HLSL converts no such way (a shorter vector to a
    longer one, a matrix, a struct, or an out parameter of another shape)."""
    target = param.type
    if _same_shape(arg, target):
        return 0
    if param.qual != "in" or not (arg.numeric and target.numeric) or arg.cols or target.cols:
        return None
    if arg.dim == target.dim:
        return 1
    if arg.dim == 1:
        return 1
    if arg.dim > target.dim:
        return 2
    return None


def _best_converted(sigs, args):
    """The one signature whose every argument's conversion costs no more than any other's
    (_conversion_rank), as HLSL chooses ``float3 mod(float3, float3)`` for ``mod(v3, 2.0)``
    over ``float2 mod(float2, float2)``; None where none takes them or two tie."""
    ranked = []
    for sig in sigs:
        ranks = [_conversion_rank(a.t, p) for a, p in zip(args, sig.params)]
        if None not in ranks:
            ranked.append((sig, ranks))
    best = [(sig, ranks) for sig, ranks in ranked
            if all(all(r <= o for r, o in zip(ranks, other)) for _, other in ranked)]
    return best[0][0] if len(best) == 1 else None


def _same_shape(a: Type, b: Type) -> bool:
    return a.dim == b.dim and a.cols == b.cols and (a.base == b.base or not (a.numeric and b.numeric)
                                                    or {a.base, b.base} <= {"float", "int", "uint"})


def _swizzle_index(ch):
    return "xyzw".find(ch) if ch in "xyzw" else "rgba".find(ch)


def _mul_type(a: Type | None, b: Type | None):
    if a is None or b is None or not (a.numeric and b.numeric):
        return None
    if a.scalar:
        return b
    if b.scalar:
        return a
    if a.cols and b.vector and b.dim == a.cols:
        return Type("float", a.dim)
    if a.vector and b.cols and a.dim == b.dim:
        return Type("float", b.cols)
    # a float4x4 times a float3 (either side): the matrix cut to the vector's length, the
    # result the matrix's other size (cg_compat.glsl's mul(mat4, vec3): four components)
    if a.cols and b.vector and b.dim < a.cols:
        return Type("float", a.dim)
    if a.vector and b.cols and a.dim < b.dim:
        return Type("float", b.cols)
    if a.cols and b.cols and a.cols == b.dim:
        return Type("float", a.dim, b.cols)
    return None


@dataclass
class Result:
    text: str
    skipped: list       # first lines of top-level declarations left as written


# The directives that name macros or the program's names: a #define's name and replacement
# text, and the macro a conditional tests or #undef drops. A macro the port renames at its
# #define (``#define __COMMON__``, a double underscore GLSL reserves) is renamed where an include
# guard tests it too (``#ifndef __COMMON__``), else the guard never closes and the file's
# declarations come in twice (yangxuan0261's PostProcessing Common.cginc).
_NAMING_DIRECTIVE = re.compile(r"#\s*(?:define|undef|ifdef|ifndef|if|elif)\s+")
# The preprocessor's own names, which a conditional may test and no program defines (GLSL 3.30
# section 3.3 and HLSL's): never renamed.
_PREDEFINED_MACROS = frozenset({"__LINE__", "__FILE__", "__VERSION__", "__HLSL_VERSION", "defined"})


def _rename_in_directives(text: str, directives) -> list:
    """Edits renaming reserved names in #define lines (the program's macros use its names) and
    in the conditionals and #undef lines that name a macro."""
    out = []
    for s, e in directives:
        line = text[s:e]
        m = _NAMING_DIRECTIVE.match(line)
        if not m:
            continue
        for w in re.finditer(r"\b[A-Za-z_]\w*\b", line[m.end():]):
            if is_reserved(w.group(0)) and w.group(0) not in _PREDEFINED_MACROS:
                out.append((s + m.end() + w.start(), s + m.end() + w.end(), RENAME_PREFIX + w.group(0)))
    return out


def convert_detail(text: str, symbols: Symbols | None = None, srp: bool = False) -> Result:
    """``srp``: a Scriptable Render Pipeline's program, whose structs' members depend on the
    preprocessor (their zeros are functions: _Parser._define_conditional_zero)."""
    symbols = (symbols or library()).copy()
    try:
        parser = _Parser(text, symbols, srp=srp)
    except CgSyntaxError:
        return Result(text, [1])
    parser.program()
    for s, e, t in _rename_in_directives(text, parser.directives):
        parser.edits.replace(s, e, t)
    return Result(parser.edits.apply(text), parser.skipped)


def convert(text: str, symbols: Symbols | None = None, srp: bool = False) -> str:
    return convert_detail(text, symbols, srp).text


def fxc_conversions(text: str, symbols: Symbols | None = None, srp: bool = False) -> str:
    """``text`` (HLSL) with the implicit conversions FXC makes and glslang's HLSL front end
    refuses spelled out (_Parser.fxc_argument), nothing else changed; lines kept."""
    symbols = (symbols or library()).copy()
    try:
        parser = _Parser(text, symbols, srp=srp)
    except CgSyntaxError:
        return text
    parser.program()
    return parser.fxc_edits.apply(text)


def with_declarations(text: str, srp: bool = False) -> Symbols:
    """The library's symbols and the declarations of ``text`` (a program's included files)."""
    symbols = library().copy()
    try:
        _Parser(text, symbols, declarations_only=True, srp=srp).program()
    except CgSyntaxError:
        pass  # an include the parser cannot read adds nothing
    defined_values(text, symbols)
    return symbols
