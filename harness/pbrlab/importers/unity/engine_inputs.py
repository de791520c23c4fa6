"""Globals a Unity shader declares itself but only one of Unity's engine subsystems sets (a
G-buffer of the deferred path, the previous frame's matrices of motion vectors, the terrain's
tree-imposter lights): the harness has none of those subsystems, so such a global would stay
zero and draw a picture Unity never shows. A vertex/fragment pass whose drawn variant reads one
is refused naming it, at its line, before anything is compiled (a compiler would accept the
shader's own declaration).

    check_engine_inputs(active_program, path, first_line)   # raises UnityShaderError
"""

from __future__ import annotations

import re
from pathlib import Path

from . import multisampled_textures
from .source_text import UnityShaderError, line_of

_DEFERRED = "the deferred path's G-buffer, which the harness does not render (it shades forward)"
_MOTION = ("motion vectors: the previous frame's camera and object matrices, which a single still "
           "frame does not have")
_TREE_IMPOSTER = ("the lights Unity's terrain sets when it renders a tree into its billboard "
                  "imposter texture (the harness has no terrain)")

# name -> the engine feature that sets it (docs/unity.md, "Unity names set by an engine subsystem").
ENGINE_FED = {
    "_CameraNormalsTexture": _DEFERRED,        # the deferred normals buffer (RT2) a depth-normals combine reads
    "_NonJitteredVP": _MOTION, "_PreviousVP": _MOTION, "_PreviousM": _MOTION,
    "_StereoNonJitteredVP": _MOTION, "_StereoPreviousVP": _MOTION,
    "_TerrainTreeLightDirections": _TREE_IMPOSTER, "_TerrainTreeLightColors": _TREE_IMPOSTER,
}
_NAME = re.compile(r"\b(" + "|".join(sorted(ENGINE_FED, key=len, reverse=True)) + r")\b")
# a declaration's own line does not read it: ``float4x4 _PreviousVP;`` alone draws nothing
_DECLARATION = re.compile(r"^\s*(?:uniform\s+)?\w+\s+\w+\s*(?:\[[^\]]*\])?\s*;\s*$")


def engine_input_read(active_program: str):
    """(name, offset) of the first use of an ENGINE_FED name in ``active_program`` (comments
    blanked, branches not drawn blanked) other than a declaration; None when there is none."""
    for m in _NAME.finditer(active_program):
        start = active_program.rfind("\n", 0, m.start()) + 1
        end = active_program.find("\n", m.end())
        line = active_program[start:end if end >= 0 else len(active_program)]
        if not _DECLARATION.match(line):
            return m.group(1), m.start()
    return None


# Direct3D 10's multisampled texture objects declared outright (``Texture2DMSArray<float> t;``):
# a declaration alone is kept (GLSL's sampler2DMS / sampler2DMSArray: multisampled_textures.py);
# a read of one in the drawn variant needs a multisampled texture bound, which a material cannot
# give (its textures are single-sampled 2D).
MULTISAMPLED_FEATURE = ("multisampled textures (Direct3D's Texture2DMS objects): reading one needs a "
                        "multisampled texture, which a material cannot bind (its textures are single-sampled 2D)")


def check_engine_inputs(active_program: str, path: Path, first_line: int) -> None:
    """Refuse a program whose drawn variant reads a global only an engine subsystem sets, or
    reads a multisampled texture object."""
    found = engine_input_read(active_program)
    feature = ENGINE_FED[found[0]] if found else None
    read = multisampled_textures.first_read(active_program)
    if read and (found is None or read[1] < found[1]):
        found, feature = read, MULTISAMPLED_FEATURE
    if found is None:
        return
    name, offset = found
    line = first_line - 1 + line_of(active_program, offset)
    raise UnityShaderError(f"{path}:{line}: uses {name}, part of {feature}; pbrlab does not provide it")
