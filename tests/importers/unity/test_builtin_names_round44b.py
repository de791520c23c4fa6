"""Built-in names Unity accepts that pbrlab refused (session 44's hidden5 sample): a ``RECT``
texture property (ShaderLab's legacy name of a 2D texture; Unity's editor shaders still write
it) and ``CBUFFER_START(name) ... CBUFFER_END`` in a CGPROGRAM that includes nothing (Unity
includes HLSLSupport.cginc, which defines them, in every CGPROGRAM)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus

SHADER = textwrap.dedent("""\
    Shader "Test/Round44bNames"
    {
        Properties { _MainTex ("Texture", RECT) = "white" {} }
        SubShader
        {
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                sampler2D _MainTex;
                CBUFFER_START(TestColours)
                    float4 _Tint;
                CBUFFER_END
                float4 vert(float4 p : POSITION) : SV_POSITION { return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, p)); }
                float4 frag() : SV_Target { return float4(tex2D(_MainTex, float2(0.5, 0.5)).rgb * float3(0.75, 0.25, 0.5), 1) + _Tint; }
                ENDCG
            }
        }
    }
    """)


def _run(tmp_path, text, language):
    path = tmp_path / "n.shader"
    path.write_text(text)
    return corpus.run_shader(path, language)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_rect_property_is_a_2d_texture_and_cbuffer_brackets_need_no_include(tmp_path, language):
    """The RECT property's default "white" (1, 1, 1, 1) times the constant, plus _Tint, a plain
    global the material leaves 0: exactly (0.75, 0.25, 0.5) (short binary fractions)."""
    result = _run(tmp_path, SHADER, language)
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    expected = np.array([1.0, 1.0, 1.0], dtype=np.float64) * np.array([0.75, 0.25, 0.5])
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(expected, (covered.sum(), 3)))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_a_black_rect_default_and_an_unknown_type(tmp_path, language):
    """The property is the texture the program samples (its default "black" gives black), and
    a type ShaderLab does not know is still refused naming the file and line."""
    black = _run(tmp_path, SHADER.replace('"white"', '"black"'), language)
    assert black.status == "rendered", black.message
    covered = black.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert not black.image[covered][:, :3].any()
    unknown = _run(tmp_path, SHADER.replace("RECT", "RECTANGLE"), language)
    assert unknown.status == "refused" and "n.shader:3:" in unknown.message and "RECTANGLE" in unknown.message, unknown.message
