"""ShaderLab as Unity accepts it but pbrlab refused (issue 34, session 44's hidden5 sample):
keywords in lower case (``shader "n" { subshader { pass {``: ShaderLab's keywords are
case-insensitive), a ``#warning Upgrade NOTE: ...`` line above ``Shader`` (Unity's shader upgrader
writes it; Unity imports the file), and entry points whose outputs are ``out`` parameters
(``void frag(in v2f i, out float4 c : COLOR)``). 14 shaders of one repository were refused as
"a file without a Shader block" or "got '#'"; each now renders the colour its program computes."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus

PROGRAM = """
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            fixed4 _Color;
            struct appdata { float4 vertex : POSITION; };
            struct v2f { float4 pos : SV_POSITION; };
            void vert(in appdata input, out v2f output) { output.pos = UnityObjectToClipPos(input.vertex); }
            void frag(in v2f input, out float4 c : Color) { c = _Color * 0.5; }
            ENDCG
"""
LOWER_CASE = ('shader "Test/LowerCase"\n{\n    properties { _Color ("Color", color) = (0.75, 0.25, 0.5, 1) }\n'
              '    subshader\n    {\n        tags { "RenderType"="Opaque" }\n        pass\n        {' + PROGRAM +
              '        }\n    }\n    fallback off\n}\n')
UPGRADE_NOTE = "\ufeff#warning Upgrade NOTE: unity_Scale shader variable was removed\n\n" + LOWER_CASE


def _run(tmp_path, text, language, name="s.shader"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return corpus.run_shader(path, language)


def _assert_half_colour(result):
    """The program's colour, _Color * 0.5, on every pixel the sphere covers whole (the corpus
    scene passes the property as written; short binary fractions: exact in float32)."""
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    expected = np.array([0.75, 0.25, 0.5], dtype=np.float64) * 0.5
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(expected, (covered.sum(), 3)))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("text", [LOWER_CASE, UPGRADE_NOTE], ids=["lower-case", "upgrade-note"])
def test_lower_case_shaderlab_and_the_upgraders_note_render_the_programs_colour(tmp_path, text, language):
    _assert_half_colour(_run(tmp_path, text, language))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_controls_a_misspelt_keyword_and_another_directive_are_still_refused(tmp_path, language):
    misspelt = _run(tmp_path, LOWER_CASE.replace("shader ", "shadr ", 1), language, "a.shader")
    assert misspelt.status == "refused" and "a.shader:1:" in misspelt.message, misspelt.message
    directive = _run(tmp_path, UPGRADE_NOTE.replace("#warning", "#pragma"), language, "b.shader")
    assert directive.status == "refused" and "b.shader:1:" in directive.message, directive.message
