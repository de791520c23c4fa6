"""Names a shader defines itself that pbrlab's URP and Core RP stand-ins define too: the
stand-in steps aside, so the shader's own definition is the one used.

Two cases in real shaders:

- a constant macro redefined after Core.hlsl (``#define PI 3.14159265358979323846``). FXC and DXC
  warn ("macro redefinition", X1519 / -Wmacro-redefined) and take the new body from there on;
  glslang and GLSL preprocessors refuse a different body. Here the stand-in leaves the name
  undefined when the shader's program or its own include files ``#define`` it, so the shader's
  body is the one its code reads (the stand-ins never read these names themselves). The one
  difference from FXC: the shader's code between Core.hlsl and its own ``#define`` does not see
  Core's value (no shader we have seen reads one there).
- a struct a later URP version added under a name a shader written for an earlier one uses
  (``struct LightingData``: URP 12's, which the stand-ins follow, where a URP 10 shader declares
  its own). Where the shader's program or its own files declare ``struct <Name>``, the stand-in
  leaves out the struct and the functions that take it (they are URP 12's, which that shader
  does not call), as the URP version the shader was written for had none.

- a global a later Core RP version declares that shaders written for an earlier one declare
  themselves (``float4 _BlitTexture_TexelSize;``: Blit.hlsl's since Unity 6; a Unity 2022 shader
  declares it beside its include). Where the shader's own text declares the global, the stand-in
  leaves its declaration out (two would be a redefinition, an error in FXC as in glslang), as the
  version the shader was written for had none.

- a global pbrlab's Unity prelude declares (unity_compat/shader_variables: ``float4 _SpecColor``,
  Lighting.cginc's BlinnPhong colour, which URP's core does not declare) that the shader's own
  text declares with another type (``half3 _SpecColor;``, inside a CBUFFER or not). In Unity the
  shader's declaration is the only one; glslang crashed (signal 11) on the redeclaration and a
  GLSL compiler refuses it. The prelude declares its own under another name
  (``pbrlab_prelude_SpecColor``, generate.prelude: ``#define`` before the library, ``#undef``
  after), so the program's declaration is the only ``_SpecColor``, and pbrlab's value reaches it
  by name, converted to its type (program._bind_vector: a half3 takes rgb). Same-typed, the
  prelude's declaration serves (the port drops the program's: port._drop_unity_redeclarations).
- a function of an earlier URP that a shader names without defining it (``#pragma vertex
  FullscreenVert``: URP 12's PostProcessing/Common.hlsl's, from Utils/Fullscreen.hlsl, where URP 13
  on has Blit.hlsl's Vert). That is the layout the shader was written for: a
  ``PBRLAB_USER_READS_<name>`` define, which the stand-in tests to give that version's.
- the mesh-drawn layout of URP 10's PostProcessing/Common.hlsl (Attributes { positionOS: POSITION,
  uv: TEXCOORD0 }, Varyings { positionCS, uv }, Vert), told by the shader reading
  ``<param>.positionOS`` of an ``Attributes`` parameter while declaring no ``struct Attributes``
  of its own (Blit.hlsl's, URP 13 on, has only a vertex id): ``PBRLAB_USER_READS_Attributes_positionOS``;
  not where the program includes Blit.hlsl itself (whose Attributes has positionOS on GLES only).

Each other name is a ``PBRLAB_USER_DEFINES_<name>`` define (its leading underscores dropped) of the program; the stand-ins test it
(``#ifndef PBRLAB_USER_DEFINES_PI``).

    defines = program_defines(unity_pass)     # {"PBRLAB_USER_DEFINES_PI": 1, ...}
    defines = text_defines(program, folder)   # the same, of a program's text (parse_pass.py)
"""

from __future__ import annotations

import functools
import hashlib
import re
from pathlib import Path

from ...foundation.file_identity import FileCache, followed_key
from ...foundation.locations import locate
from .source_text import CGINC, INCLUDE, PACKAGE_STAND_INS, blank_comments, included_files

# The stand-ins' constants (Core RP Common.hlsl / Macros.hlsl) that step aside: none is read by a
# stand-in's own code (FLT_MIN, HALF_MIN and HALF_MIN_SQRT are, and are not in this list).
MACROS = ("PI", "TWO_PI", "FOUR_PI", "INV_PI", "INV_TWO_PI", "INV_FOUR_PI", "HALF_PI", "INV_HALF_PI",
          "LOG2_E", "INV_SQRT2", "FLT_EPS", "FLT_MAX", "HALF_MAX", "MAX_VISIBLE_LIGHTS")
# Structs URP 12 added that shaders written for earlier versions declare themselves.
STRUCTS = ("LightingData",)
PREFIX = "PBRLAB_USER_DEFINES_"
# Functions of an earlier URP that tell the layout a shader was written for.
EARLIER_FUNCTIONS = ("FullscreenVert",)
READS_PREFIX = "PBRLAB_USER_READS_"
# URP 10's PostProcessing/Common.hlsl layout (module docstring): a parameter of type Attributes.
EARLIER_ATTRIBUTES = "Attributes_positionOS"
_ATTRIBUTES_PARAMETER = re.compile(r"\bAttributes\s+(\w+)\s*[,)]")
# A program (or its own file) that includes Core RP's Blit.hlsl itself was written for Blit.hlsl's
# Attributes (URP 13 on; Unity never has it beside URP 10's Common.hlsl, each defines Attributes),
# whose positionOS and uv exist only under SHADER_API_GLES (Core RP 14 Blit.hlsl): a read of
# v.positionOS in that branch (X-PostProcessing's VertRay) is Blit's own GLES path, not URP 10's.
_BLIT_INCLUDE = re.compile(r'#[ \t]*include[ \t]*["<][^">]*Runtime/Utilities/Blit\.hlsl[">]')
# Globals Unity 6's Core RP declares that earlier shaders declare themselves.
GLOBALS = ("_BlitTexture_TexelSize",)

# A numeric global's declaration at a line's start (after a one-line CBUFFER_START(...), uniform
# or static): its type and its (first) name.
_NUMERIC_GLOBAL = re.compile(r"^[ \t]*(?:CBUFFER_START[ \t]*\([ \t]*\w+[ \t]*\)[ \t]*)?(?:(?:uniform|static)[ \t]+)?"
                             r"((?:float|half|fixed|real|min16float|int|uint|bool)(?:[1-4](?:x[1-4])?)?)[ \t]+(\w+)[ \t]*[;,]",
                             re.M)
_PRELUDE_UNIFORM = re.compile(r"^uniform[ \t]+(float[1-4]?)[ \t]+(\w+)[ \t]*;", re.M)


@functools.cache
def prelude_globals() -> dict:
    """{name: type} of the vector and scalar uniforms pbrlab's Unity prelude declares (hlsl_ports/
    unity_compat/shader_variables.hlsl, the GLSL twin's HLSL spelling; not its matrices, which the
    generated entry reads, nor its arrays)."""
    text = (locate("hlsl_ports") / "unity_compat" / "shader_variables.hlsl").read_text(encoding="utf-8")
    return {name: kind for kind, name in _PRELUDE_UNIFORM.findall(text)}


def _same_type(written: str, prelude: str) -> bool:
    """Whether a program's type names the prelude's (half, fixed, real: float; float1: float)."""
    written = re.sub(r"^(?:half|fixed|real|min16float)", "float", written)
    return re.sub(r"^float1$", "float", written) == prelude


def retyped_prelude_globals(text: str) -> set:
    """The prelude's globals (prelude_globals) that ``text`` declares with a type of its own."""
    known = prelude_globals()
    return {name for kind, name in _NUMERIC_GLOBAL.findall(text) if name in known and not _same_type(kind, known[name])}


def prelude_renames(defines: dict) -> dict:
    """{name: the prelude's own name for it} of each prelude global ``defines`` say the program
    declares with another type (generate.prelude declares the prelude's under that name)."""
    return {name: "pbrlab_prelude_" + name.lstrip("_") for name in prelude_globals()
            if PREFIX + name.lstrip("_") in defines}


_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)", re.M)
_STRUCT = re.compile(r"\bstruct[ \t\r\n]+(\w+)[ \t\r\n]*\{")
# A global's declaration: a type (uniform, or precision qualifiers before it) then the name, ending
# the declaration or followed by another of a list.
_GLOBAL = re.compile(r"\b(?:float|half|fixed|real|min16float)4[ \t]+(\w+)[ \t]*[;,]")


def user_text(program: str, folder) -> str:
    """The program and the files it includes that are the shader's own (not pbrlab's stand-ins),
    comments blanked."""
    return _user_text(program, included_files(program, folder))


def _user_text(program: str, files: dict) -> str:
    own = [text for path, text in files.items()
           if not path.is_relative_to(PACKAGE_STAND_INS.resolve()) and not path.is_relative_to(CGINC.resolve())]
    return "\n".join([blank_comments(program), *own])


def program_defines(unity_pass) -> dict:
    """{PBRLAB_USER_DEFINES_<name>: 1} for each name of MACROS the pass's own text #defines and
    each of STRUCTS and GLOBALS it declares, {PBRLAB_USER_READS_<name>: 1} for each of
    EARLIER_FUNCTIONS it names and does not define (module docstring); {} for a pass without a
    program."""
    program = getattr(unity_pass, "program", None)
    path = getattr(unity_pass, "path", None)
    if not program or path is None:
        return {}
    return text_defines(program, path.parent)


def text_defines(program: str, folder) -> dict:
    """program_defines of a program's text and the folder its includes are found from (the
    parser's branches are the drawn program's: parse_pass.py). Kept per process for the
    programs seen last (``_TEXT_DEFINES``) and made again when a file it read, or a place an
    include of it could be found, changed: every pass asks twice (parse_pass, the material),
    each time reading every file the program includes (a URP program: ~40 ms)."""
    key = (hashlib.sha256(program.encode("utf-8", "surrogatepass")).digest(), str(folder))

    def build():
        files = included_files(program, Path(folder))
        # a file read as a legacy code page warns at each read (source_text.read_source): not kept
        kept = all(_is_utf8(path) for path in files)
        places = [*files, *_places(program, Path(folder), files)] if kept else None
        return _defines(_user_text(program, files)), places

    return dict(_TEXT_DEFINES.get(key, build))


# text_defines' answers: a few names each.
TEXT_DEFINES_CACHED = 256
_TEXT_DEFINES = FileCache(TEXT_DEFINES_CACHED, identity=followed_key)


def _is_utf8(path: Path) -> bool:
    try:
        Path(path).read_bytes().decode("utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    return True


def _places(program: str, folder: Path, files: dict) -> list[Path]:
    """Every place source_text.resolve_included may look at for an include of ``program``
    (from ``folder``) or of the ``files`` it reached (from theirs): a file created, removed or
    changed at one could change what the program reads (a superset: the including folder,
    pbrlab's stand-ins, each folder above for a project or package path and its package.json)."""
    out = [CGINC, PACKAGE_STAND_INS]
    texts = [(blank_comments(program), folder), *((text, Path(path).parent) for path, text in files.items())]
    for text, where in texts:
        for name in INCLUDE.findall(text):
            name = name.lstrip("/")
            out += [where / name, (where / name).parent, (PACKAGE_STAND_INS / name).parent]
            if name.startswith(("Assets/", "Packages/")):
                rest = name.split("/", 2)[-1]
                for ancestor in [where, *where.parents]:
                    out += [ancestor / name, (ancestor / name).parent, ancestor / "package.json",
                            ancestor / rest, (ancestor / rest).parent]
    return out


def _defines(text: str) -> dict:
    """text_defines of the program's and its own files' text (comments blanked)."""
    names = ({n for n in _DEFINE.findall(text) if n in MACROS} | {n for n in _STRUCT.findall(text) if n in STRUCTS}
             | {n for n in _GLOBAL.findall(text) if n in GLOBALS} | retyped_prelude_globals(text))
    reads = {n for n in EARLIER_FUNCTIONS if re.search(rf"\b{n}\b", text)
             and not re.search(rf"\b\w+\s+{n}\s*\([^()]*\)\s*\{{", text)}
    if not re.search(r"\bstruct\s+Attributes\b", text) and not _BLIT_INCLUDE.search(text) and any(
            re.search(rf"\b{p}\s*\.\s*positionOS\b", text) for p in _ATTRIBUTES_PARAMETER.findall(text)):
        reads.add(EARLIER_ATTRIBUTES)
    # (a name's leading underscores dropped: GLSL reserves the macro names with two in a row)
    return {**{PREFIX + n.lstrip("_"): 1 for n in sorted(names)}, **{READS_PREFIX + n: 1 for n in sorted(reads)}}
