"""s47-glslinc (issue 34, session 47): two ways a URP program's Cg reached GLSL unported.

1. An include written in a subfolder's file and found only from the shader's own folder
   (lclandrews' URP toon shading: TwoTone/ToonTwoToneVertexPass.hlsl includes
   ``Core/ToonURP.hlsl``, which lies beside the .shader). The HLSL path finds it (the shader's
   folder is one of glslang's include folders: program._include_dirs); the GLSL port resolved
   each include from its including file's folder only, left this one as written, and the GLSL
   expander found it in the same include folder and read it raw, the stand-ins it includes
   with it (SurfaceData.hlsl's ``float3 albedo;``: "syntax error, unexpected NEW_IDENTIFIER").
   The port now resolves it from the shader's folder too (program.included_from).
2. A global texture declared through the program's own macro that wraps Core RP's
   TEXTURE2D_FLOAT (URP 14's Shaders/Utils/CopyDepthPass.hlsl: ``#define DEPTH_TEXTURE(name)
   TEXTURE2D_FLOAT(name)``, ``DEPTH_TEXTURE(_CameraDepthAttachment);``): the port spelled the
   macro's body ``sampler2D name`` and left the use a plain global, which GLSL refuses ("image/
   sampler variables may only be declared as function parameters or uniform-qualified global
   variables"); the use now gets ``uniform`` (port._TEXTURE_DECLARING_DEFINE), as a written
   ``TEXTURE2D_FLOAT(x);`` does.

Minimal shaders of ours under shaders/s47-glslinc/, drawn in both languages.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import port, program
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

SHADERS = Path(__file__).parent / "shaders" / "s47-glslinc"
FOLDER = SHADERS / "shader_folder_include"


def _folder_copy(tmp_path) -> tuple[Path, str]:
    """(a copy of the shader's folder, the shader's text): render_constant writes it there as
    t.shader, beside Sub/ and Common/ (a folder of its own: no compile cached for another test's)."""
    shutil.copytree(FOLDER, tmp_path / "shader")
    return tmp_path / "shader", (FOLDER / "ShaderFolderInclude.shader").read_text()


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_include_found_from_the_shaders_folder_is_ported(tmp_path, language, monkeypatch):
    """_Base (0.25, 0.5, 0.125) through Common/Tone.hlsl: Core RP's Max3 / Min3 (Common.hlsl:
    max(max(a, b), c), min(min(a, b), c)) and 0.75, URP's SurfaceData.albedo returned unlit:
    (0.5, 0.125, 0.75), each a short binary fraction, exact in float32 and in half (bound 0).
    Control (GLSL): the port resolving an include from its including file's folder only (as
    before: program.included_from without its fallback), the expander reads Common/Tone.hlsl
    raw and GLSL refuses the SurfaceData.hlsl stand-in's text."""
    folder, text = _folder_copy(tmp_path)
    pixels, _ = render_constant(folder, text, language, environment=False)
    want = np.array([max(0.25, 0.5, 0.125), min(0.25, 0.5, 0.125), 0.75], dtype=np.float64)
    assert np.array_equal(pixels[:, :3], np.broadcast_to(want, pixels[:, :3].shape)), pixels[0, :3]
    if language == "glsl":
        monkeypatch.setattr(program, "included_from", lambda name, where, shader_folder:
                            program.resolve_included(name, where))
        old, text = _folder_copy(tmp_path / "old")
        with pytest.raises(PbrlabError, match=r"SurfaceData\.hlsl:\d+:\d+: error: syntax error"):
            render_constant(old, text, language, environment=False)


DEPTH = SHADERS / "depth_texture_macro"


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("shader", ["DepthTextureMacro.shader", "DepthTextureMacroIncluded.shader"])
def test_a_global_texture_declared_by_a_programs_macro_is_a_uniform(tmp_path, language, shader, monkeypatch):
    """_Depth's "gray" default (0.5, a float texel) read by SAMPLE_DEPTH_TEXTURE (its .r) and
    _Direct's "white" (1.0): (0.5 * 0.5, 1.0 * 0.25, 0.5 * 1.0) = (0.25, 0.25, 0.5), the first
    keyword of the multi_compile (_DEPTH_NO_MSAA) on; dyadic, exact (bound 0). The macro defined
    in the program, and in a file it includes (DepthMacros.hlsl). Control (GLSL): the macro not
    known as declaring a texture (port._texture_declaring_macros finding none, as before), GLSL
    refuses the plain global sampler."""
    shutil.copy(DEPTH / "DepthMacros.hlsl", tmp_path)
    text = (DEPTH / shader).read_text()
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    want = np.array([0.5 * 0.5, 1.0 * 0.25, 0.5 * 1.0], dtype=np.float64)
    assert np.array_equal(pixels[:, :3], np.broadcast_to(want, pixels[:, :3].shape)), pixels[0, :3]
    if language == "glsl":
        monkeypatch.setattr(port, "_texture_declaring_macros", lambda code: frozenset())
        (tmp_path / "old").mkdir()
        shutil.copy(DEPTH / "DepthMacros.hlsl", tmp_path / "old")
        with pytest.raises(PbrlabError, match="uniform-qualified global variables"):
            render_constant(tmp_path / "old", text, language, environment=False)


def test_the_macro_use_gets_uniform_only_at_file_scope():
    """The port's rule itself: a file-scope statement using a macro whose body is one texture
    declaration of its parameter gets ``uniform``; a use inside a function body (a local GLSL
    would refuse anyway, left for the compiler to name) and a macro declaring something else are
    left as written."""
    code = ("#define DEPTH_TEXTURE(name) sampler2D name\n"
            "#define SCALAR(name) float name\n"
            "DEPTH_TEXTURE(_A);\n"
            "SCALAR(_B);\n"
            "void f() {\n"
            "    DEPTH_TEXTURE(_C);\n"
            "}\n")
    lines = port._globals_uniform(code).split("\n")
    assert lines[2] == "uniform DEPTH_TEXTURE(_A);"
    assert lines[3] == "SCALAR(_B);"
    assert lines[5] == "    DEPTH_TEXTURE(_C);"
