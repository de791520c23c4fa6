"""Luminance in a URP program is Core RP's (Color.hlsl): Rec. 709 relative luminance of a linear
colour, weights (0.2126729, 0.7151522, 0.0721750) summing to 1 (ITU-R BT.709; IEC 61966-2-1's
sRGB primaries). Before, URP programs called the Unity prelude's built-in-pipeline Luminance
(unity_ColorSpaceLuminance's linear weights, summing to 0.504): every URP shader's luminance was
about half, with no message. The built-in pipeline keeps its own (control)."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus

COLOR = np.array([0.75, 0.25, 0.5])
REC709 = np.array([0.2126729, 0.7151522, 0.0721750])
BUILT_IN = np.array([0.0396819152, 0.458021790, 0.00609653955])  # UnityCG.cginc, linear space

URP = """Shader "Test/UrpLuminance"
{
    Properties { _Color ("Color", Color) = (0.75, 0.25, 0.5, 1) }
    SubShader
    {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass
        {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            CBUFFER_START(UnityPerMaterial)
            half4 _Color;
            CBUFFER_END
            float4 vert(float4 p : POSITION) : SV_POSITION { return TransformObjectToHClip(p.xyz); }
            half4 frag() : SV_Target { return half4(Luminance(_Color.rgb).xxx, 1); }
            ENDHLSL
        }
    }
}
"""

BUILT_IN_SHADER = """Shader "Test/BuiltInLuminance"
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
            fixed4 _Color;
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            fixed4 frag() : SV_Target { return fixed4(Luminance(_Color.rgb).xxx, 1); }
            ENDCG
        }
    }
}
"""


def _red_on_covered_pixels(tmp_path, text: str, language: str) -> np.ndarray:
    path = tmp_path / "luminance.shader"
    path.write_text(text)
    outcome = corpus.run_shader(path, language)
    assert outcome.status == "rendered", outcome.message
    image = np.asarray(outcome.image, np.float64)
    return image[image[..., 3] == 1.0][:, 0]


# float32: a dot product of three terms of magnitude < 1 rounds within 3 ulps of 1 (2^-22);
# the colour (0.75, 0.25, 0.5) is exact, the weights' own rounding to float32 adds 2^-24 each
@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_urp_program_calls_core_rps_rec709_luminance(tmp_path, language):
    red = _red_on_covered_pixels(tmp_path, URP, language)
    assert red.size > 0
    assert np.abs(red - COLOR @ REC709).max() <= 2.0 ** -21
    assert np.abs(red - COLOR @ BUILT_IN).min() > 0.2  # the old, built-in weights are rejected


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_built_in_program_keeps_unitycgs_luminance(tmp_path, language):
    red = _red_on_covered_pixels(tmp_path, BUILT_IN_SHADER, language)
    assert red.size > 0
    assert np.abs(red - COLOR @ BUILT_IN).max() <= 2.0 ** -21
