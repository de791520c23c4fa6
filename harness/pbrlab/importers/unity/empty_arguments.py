"""A call of a one-parameter macro with nothing between its parentheses (``TRANSFER_SHADOW();``
where AutoLight.cginc defines ``TRANSFER_SHADOW(a)``): in C one empty argument (C99 6.10.3,
"arguments consisting of no preprocessing tokens"), which FXC's preprocessor takes; glslang's
HLSL front end counts none ("Too few args in Macro"). Spelled for the HLSL as written with
an argument that expands to nothing (``PBRLAB_EMPTY_ARGUMENT``, unity_hlsl_support.hlsl), so the
expansion is the one an empty argument gives. The GLSL path's preprocessor takes ``M()``.

    text = empty_arguments_spelled(text, included)
"""

from __future__ import annotations

import functools
import re

from ...gpu.hlsl import HLSL_ROOT
from pathlib import Path

_ONE_PARAMETER = re.compile(r"^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)\([ \t]*[A-Za-z_]\w*[ \t]*\)", re.M)
EMPTY_ARGUMENT = "PBRLAB_EMPTY_ARGUMENT"


@functools.lru_cache(maxsize=1)
def _layer_macros() -> frozenset:
    """The one-parameter macros of the harness's HLSL Unity layer (the stand-in of Unity's
    UnityCG/AutoLight names, hlsl_ports/unity_compat) and its HLSL support file."""
    names = set()
    for path in [*sorted((HLSL_ROOT / "unity_compat").glob("*.hlsl")),
                 Path(__file__).resolve().parents[2] / "templates" / "unity_hlsl_support.hlsl"]:
        if path.is_file():
            names |= set(_ONE_PARAMETER.findall(path.read_text(encoding="utf-8")))
    return frozenset(names)


def empty_arguments_spelled(text: str, included: str = "") -> str:
    """``text`` with ``NAME()`` as ``NAME(PBRLAB_EMPTY_ARGUMENT)`` where NAME is a one-parameter
    macro of the Unity layer, the program or the files it includes."""
    names = _layer_macros() | set(_ONE_PARAMETER.findall(text)) | set(_ONE_PARAMETER.findall(included))
    if not names:
        return text
    call = re.compile(r"\b(" + "|".join(sorted(map(re.escape, names))) + r")\s*\(\s*\)")
    return call.sub(lambda m: f"{m.group(1)}({EMPTY_ARGUMENT})", text)
