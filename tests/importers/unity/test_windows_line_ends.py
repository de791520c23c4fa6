"""Unity source files with Windows line ends (CR LF), as Git on Windows checks many out. The Cg
type pass reads a line's end as LF only: a CR left in a parameter list kept the port from
renaming a GLSL-reserved parameter (``InputPatch<Varyings, 3> patch`` in the URP corpus'
Tessellation.hlsl, GeoGrass's GLSL tessellation stage refused). source_text.read_source now reads
CR LF as LF (one line either way, so every file and line a message names is unchanged)."""

from __future__ import annotations

import numpy as np
import pytest

from colour_pass import colour_pass

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.unity import cg_types, port
from pbrlab.importers.unity.source_text import read_source

SHADER = colour_pass("WindowsLineEnds", "tint.cginc", "Tinted(_Color, 0.5)")
# a macro continued over a line end (with CR LF a backslash before CR: what the type pass misread)
# and parameters named as GLSL reserves them (cg_types.RESERVED): the port must rename both
INCLUDE = ("#define HALVED(x) \\\n    ((x) * 0.5)\n"
           "fixed4 Tinted(fixed4 patch,\n              float input)\n{\n    return HALVED(patch) * input;\n}\n")


def _write(folder, end: str):
    folder.mkdir()
    (folder / "tint.shader").write_bytes(SHADER.replace("\n", end).encode("ascii"))
    (folder / "tint.cginc").write_bytes(INCLUDE.replace("\n", end).encode("ascii"))
    return folder / "tint.shader"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_shader_with_windows_line_ends_renders_as_its_lf_twin(tmp_path, language):
    crlf = corpus.run_shader(_write(tmp_path / "crlf", "\r\n"), language)
    lf = corpus.run_shader(_write(tmp_path / "lf", "\n"), language)
    assert crlf.status == "rendered", crlf.message
    assert lf.status == "rendered", lf.message
    assert np.array_equal(crlf.image, lf.image)
    # _Color * 0.5 * 0.5 on every fully covered pixel (short binary fractions: exact)
    covered = crlf.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(crlf.image[covered][:, :3], np.broadcast_to([0.1875, 0.0625, 0.125], (covered.sum(), 3)))


def test_the_reader_gives_lf_and_keeps_the_line_count(tmp_path):
    path = tmp_path / "x.cginc"
    path.write_bytes(INCLUDE.replace("\n", "\r\n").encode("ascii"))
    text = read_source(path)
    assert "\r" not in text and text == INCLUDE and text.count("\n") == INCLUDE.count("\n")


def test_the_port_needs_the_lf_text():
    """Control: the type pass given the CR LF text as it was read before cannot read the function
    after the continued macro (the defect: it is left as written; since session 42 its reserved
    names are renamed even so, cg_types._Parser.rename_reserved), and reads it in LF text."""
    crlf = cg_types.convert_detail(INCLUDE.replace("\n", "\r\n"))
    lf = port.port_text(INCLUDE)
    assert "pbr_unity_patch" in lf and "pbr_unity_input" in lf
    assert cg_types.convert_detail(INCLUDE).skipped == [] and crlf.skipped != []
