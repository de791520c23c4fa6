"""URP and Core RP names real URP shaders read that pbrlab refused (issue 34, session 45c): Core's
DebugMipmapStreamingMacros.hlsl (Unity 6), whose macros declare the mipmap-streaming debug
constants inside a material's UnityPerMaterial. Rendered in both languages from a minimal shader
of our own, compared with the float64 value of Unity's documented meaning, with a control.
"""

from __future__ import annotations

import numpy as np
import pytest

from test_urp_library_round2 import LANGUAGES, render_constant
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24

MIPMAP_GLOBALS = """
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/DebugMipmapStreamingMacros.hlsl"
CBUFFER_START(UnityPerMaterial)
    UNITY_TEXTURE_STREAMING_DEBUG_VARS
    float4 _Tint;
    UNITY_TEXTURE_STREAMING_DEBUG_VARS_FOR_TEX(_Splat0)
    float _Gain;
CBUFFER_END
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_mipmap_streaming_debug_vars_keep_the_material_constants(tmp_path, language):
    """The macros declare float4 members (the debug texture's and _Splat0's mip and stream
    information) between a material's own constants; those still read their property values
    (_Tint (0.2, 0.4, 0.6), _Gain 0.5) and the debug constants, which nothing sets without
    Unity's rendering debugger, read 0. Expected: tint * gain + the debug values' sum (0).
    Bound: two float32 roundings of values below 1, 2 * 2^-24. Control: the tint without the
    gain, which the bound rejects."""
    text = NAMES44_SHADER % {
        "properties": '_Tint ("t", Color) = (0.2, 0.4, 0.6, 1) _Gain ("g", Float) = 0.5',
        "includes": "", "globals": MIPMAP_GLOBALS,
        "body": "float d = dot(_Splat0_MipInfo + _Splat0_StreamInfo + unity_MipmapStreaming_DebugTex_MipInfo"
                " + unity_MipmapStreaming_DebugTex_StreamInfo + unity_MipmapStreaming_DebugTex_ST"
                " + unity_MipmapStreaming_DebugTex_TexelSize, float4(1, 1, 1, 1));"
                " return float4(_Tint.rgb * _Gain + d, 1.0);"}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    tint = np.array([0.2, 0.4, 0.6])
    expected = tint * 0.5
    bound = 2 * EPS
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    assert (np.abs(tint - expected) > 100 * bound).all()
