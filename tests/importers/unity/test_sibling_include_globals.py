"""A global one include declares and a sibling include reads (``float _Glow;`` in a.cginc, then
``if (_Glow)`` in b.cginc, both included by the program): the GLSL port types each include on
its own, and knew only an SRP program's sibling declarations, so the float condition went
unconverted and glslang refused "if-statement condition must be scalar boolean" (FXC tests a
float condition against 0). Now a built-in program's includes know them too."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus

SHADER = textwrap.dedent("""\
    Shader "Test/SiblingIncludes"
    {
        Properties { _Glow ("Glow", Float) = GLOW }
        SubShader
        {
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                #include "a.cginc"
                #include "b.cginc"
                ENDCG
            }
        }
    }
    """)
A = "float _Glow;\n"
B = textwrap.dedent("""\
    float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
    float4 frag() : SV_Target
    {
        if (_Glow) { return float4(0.75, 0.25, 0.5, 1); }
        return float4(0.25, 0.5, 0.125, 1);
    }
    """)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("glow,expected", [("1", (0.75, 0.25, 0.5)), ("0", (0.25, 0.5, 0.125))])
def test_a_float_condition_on_a_sibling_includes_global(tmp_path, glow, expected, language):
    """_Glow != 0 takes the first colour, 0 the second (the control: the condition is read)."""
    (tmp_path / "a.cginc").write_text(A)
    (tmp_path / "b.cginc").write_text(B)
    path = tmp_path / "s.shader"
    path.write_text(SHADER.replace("GLOW", glow))
    result = corpus.run_shader(path, language)
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(np.array(expected, dtype=np.float64), (covered.sum(), 3)))
