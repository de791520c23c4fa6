"""A Unity source file saved in a legacy code page: Unity's editor writes UTF-8, but shaders whose
comments were typed in Korean (CP949), Chinese (GBK) or Windows-1252 compile in Unity, whose
compilers read bytes. pbrlab read every file as UTF-8 and refused such a shader ("cannot read:
'utf-8' codec can't decode byte 0xc0"): 22 of 124 shaders of an unseen URP sample
(docs/unity.md). Now a file that is not UTF-8 is read byte for byte (source_text.read_source),
with a note naming its file and line, and renders as its UTF-8 twin does, bit for bit."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus

# "빨강" (red) in CP949, in a comment of the program and of its include file
KOREAN_CP949 = "빨강".encode("cp949")

SHADER = textwrap.dedent("""\
    Shader "Test/LegacyCodePage"
    {
        Properties { _Color ("Color", Color) = (0.75, 0.25, 0.5, 1) }
        SubShader
        {
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                #include "legacy.cginc"
                fixed4 _Color; // COMMENT
                float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
                fixed4 frag() : SV_Target { return Tinted(_Color); }
                ENDCG
            }
        }
    }
    """)
INCLUDE = "// COMMENT\nfixed4 Tinted(fixed4 c) { return c * 0.5; } // COMMENT\n"


def _write(folder, comment: bytes):
    folder.mkdir()
    (folder / "legacy.shader").write_bytes(SHADER.encode("ascii").replace(b"COMMENT", comment))
    (folder / "legacy.cginc").write_bytes(INCLUDE.encode("ascii").replace(b"COMMENT", comment))
    return folder / "legacy.shader"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_shader_in_a_legacy_code_page_renders_as_its_utf8_twin(tmp_path, language):
    legacy = corpus.run_shader(_write(tmp_path / "cp949", KOREAN_CP949), language)
    utf8 = corpus.run_shader(_write(tmp_path / "utf8", "빨강".encode("utf-8")), language)
    assert legacy.status == "rendered", legacy.message
    assert utf8.status == "rendered", utf8.message
    assert np.array_equal(legacy.image, utf8.image)
    # the colour the program computes, _Color * 0.5, on every pixel the sphere covers fully (the
    # corpus scene's colour space passes the property as written; short binary fractions: exact)
    covered = legacy.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(legacy.image[covered][:, :3], np.broadcast_to([0.375, 0.125, 0.25], (covered.sum(), 3)))
    notes = [w for w in legacy.warnings if "not UTF-8" in w]
    assert any("legacy.shader:" in w for w in notes) and any("legacy.cginc:1:" in w for w in notes), notes
    assert not any("not UTF-8" in w for w in utf8.warnings)


def test_the_note_names_the_line_of_the_first_byte_that_is_not_utf8(tmp_path):
    """Control of the reader: a UTF-8 file is read as UTF-8 (no note), a CP949 one byte for byte."""
    from pbrlab.importers.unity.source_text import read_source
    path = tmp_path / "x.cginc"
    path.write_bytes(b"\xef\xbb\xbfline one\nline two " + KOREAN_CP949 + b"\n")
    with pytest.warns(Warning, match=r"x\.cginc:2: not UTF-8"):
        text = read_source(path)
    assert text.splitlines()[1].startswith("line two ") and len(text.splitlines()[1]) == 9 + len(KOREAN_CP949)
    path.write_bytes("line two 빨강\n".encode("utf-8"))
    assert read_source(path) == "line two 빨강\n"
