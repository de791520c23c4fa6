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

Each name is a ``PBRLAB_USER_DEFINES_<name>`` define of the program; the stand-ins test it
(``#ifndef PBRLAB_USER_DEFINES_PI``).

    defines = program_defines(unity_pass)     # {"PBRLAB_USER_DEFINES_PI": 1, ...}
"""

from __future__ import annotations

import re

from .source_text import CGINC, PACKAGE_STAND_INS, blank_comments, included_files

# The stand-ins' constants (Core RP Common.hlsl / Macros.hlsl) that step aside: none is read by a
# stand-in's own code (FLT_MIN, HALF_MIN and HALF_MIN_SQRT are, and are not in this list).
MACROS = ("PI", "TWO_PI", "FOUR_PI", "INV_PI", "INV_TWO_PI", "INV_FOUR_PI", "HALF_PI", "INV_HALF_PI",
          "LOG2_E", "INV_SQRT2", "FLT_EPS", "FLT_MAX", "HALF_MAX")
# Structs URP 12 added that shaders written for earlier versions declare themselves.
STRUCTS = ("LightingData",)
PREFIX = "PBRLAB_USER_DEFINES_"
# Globals Unity 6's Core RP declares that earlier shaders declare themselves.
GLOBALS = ("_BlitTexture_TexelSize",)

_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)", re.M)
_STRUCT = re.compile(r"\bstruct[ \t\r\n]+(\w+)[ \t\r\n]*\{")
# A global's declaration: a type (uniform, or precision qualifiers before it) then the name, ending
# the declaration or followed by another of a list.
_GLOBAL = re.compile(r"\b(?:float|half|fixed|real|min16float)4[ \t]+(\w+)[ \t]*[;,]")


def user_text(program: str, folder) -> str:
    """The program and the files it includes that are the shader's own (not pbrlab's stand-ins),
    comments blanked."""
    own = [text for path, text in included_files(program, folder).items()
           if not path.is_relative_to(PACKAGE_STAND_INS.resolve()) and not path.is_relative_to(CGINC.resolve())]
    return "\n".join([blank_comments(program), *own])


def program_defines(unity_pass) -> dict:
    """{PBRLAB_USER_DEFINES_<name>: 1} for each name of MACROS the pass's own text #defines and
    each of STRUCTS and GLOBALS it declares (module docstring); {} for a pass without a program."""
    program = getattr(unity_pass, "program", None)
    path = getattr(unity_pass, "path", None)
    if not program or path is None:
        return {}
    text = user_text(program, path.parent)
    names = ({n for n in _DEFINE.findall(text) if n in MACROS} | {n for n in _STRUCT.findall(text) if n in STRUCTS}
             | {n for n in _GLOBAL.findall(text) if n in GLOBALS})
    return {PREFIX + n: 1 for n in sorted(names)}
