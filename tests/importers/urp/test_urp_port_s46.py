"""Shader Graph's texture object read straight off its builder's call (issue 34's hidden7
sample, session 46: ding-yan-qing's Houdini VAT graphs write ``SAMPLE_TEXTURE2D(
UnityBuildTexture2DStructNoScale(_T).tex, UnityBuildTexture2DStructNoScale(_T).samplerstate,
UnityBuildTexture2DStructNoScale(_T).GetTransformedUV(uv))``), which glslang's HLSL front end
refused ("unable to find texture symbol") and the GLSL port too ("unexpected ')'"). Drawn in both
languages from a minimal shader of ours and checked against float64, with a control.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import texture_objects
from test_urp_library_round2 import LANGUAGES
from test_urp_names_round45 import _render  # pytest puts this folder on sys.path

OBJECTS = """
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Texture.hlsl"
            TEXTURE2D(_Tint); SAMPLER(sampler_Tint); float4 _Tint_TexelSize; float4 _Tint_ST;
"""
BODY = ("float4 s = SAMPLE_TEXTURE2D_LOD(UnityBuildTexture2DStruct(_Tint).tex,"
        " UnityBuildTexture2DStruct(_Tint).samplerstate,"
        " UnityBuildTexture2DStruct(_Tint).GetTransformedUV(float2(0.5, 0.5)), 0);"
        " float2 uv = UnityBuildTexture2DStructNoScale(_Tint).GetTransformedUV(float2(0.25, 0.625));"
        " return float4(uv, s.r * 0.25 + UnityBuildTexture2DStructNoScale(_Tint).texelSize.z * 0.125, 1.0);")
PROPERTIES = '_Tint ("Tint", 2D) = "white" {}'


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_texture_object_s_members_read_off_its_builder(tmp_path, language, monkeypatch):
    """The members are the property's: the unset 2D property's white 1 x 1 texture (texel size
    z = 1) sampled (1), NoScale's tiling 1 and offset 0 (Core RP's Texture.hlsl: uv * xy + zw):
    (0.25, 0.625, 0.25 + 0.125), exact binary fractions (bound: 2^-24, one float32 rounding of values
    below 1). Control: the calls left as written, both paths refuse them."""
    pixels, _ = _render(tmp_path, language, BODY, includes=OBJECTS, properties=PROPERTIES)
    want = np.array([0.25, 0.625, 0.375])
    assert (np.abs(pixels[:, :3] - want) <= 2.0 ** -24).all(), pixels[0, :3]
    monkeypatch.setattr(texture_objects, "_built_members_spelled_out", lambda text: text)
    (tmp_path / "old").mkdir()
    with pytest.raises(PbrlabError):
        _render(tmp_path / "old", language, BODY, includes=OBJECTS, properties=PROPERTIES)
