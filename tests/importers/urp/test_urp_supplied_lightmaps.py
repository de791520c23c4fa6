"""URP takes a supplied baked lightmap as the built-in pipeline does (issue 34;
importers/unity/lightmaps.py, the URP stand-ins' Lighting.hlsl): the material's ``lightmap`` sets
LIGHTMAP_ON where a pass declares it, and SAMPLE_GI / SampleLightmap then read ``unity_Lightmap``
at the mesh's TEXCOORD1 scaled and offset by ``unity_LightmapST`` (OUTPUT_LIGHTMAP_UV), decoded as
Core's DecodeLightmap does in linear colour space (URP's SampleSingleLightmap with
LIGHTMAP_HDR_MULTIPLIER / _EXPONENT: RGBM 34.49 a^2.2 rgb, dLDR 4.59 rgb, full HDR rgb).

Checked per pixel against the same float64 decode of the texel each pixel reads as the built-in
pipeline's test (tests/importers/unity/test_supplied_lightmaps.py: its scene, lightmap, compared
pixels and bound, derived there), in both languages. Control: without a lightmap the same shader
draws URP's SH ambient (SampleSH of the normal), as before.
"""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "unity"))
from pbrlab.checking import unity_corpus as corpus  # noqa: E402
from test_supplied_lightmaps import SCALE_OFFSET, _lightmap, _render, expected, over_bound  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore::pbrlab.importers.unity.UnityShaderNote")

LANGUAGES = ("glsl", "hlsl")

# SAMPLE_GI as URP's Lit/SimpleLit forward passes call it, or SampleLightmap directly (Unlit's
# baked GI), Core's DecodeLightmap, or SampleSH itself (the control's expectation).
GI = {
    "sample_gi": "SAMPLE_GI(IN.staticLightmapUV, IN.vertexSH, normalize(IN.normalWS))",
    "sample_lightmap": "SampleLightmap(IN.staticLightmapUV, normalize(IN.normalWS))",
    "sample_sh": "SampleSH(normalize(IN.normalWS))",
    # Core's DecodeLightmap with URP's decode instructions, as a project's unlit pass reads it
    "decode_lightmap": "DecodeLightmap(SAMPLE_TEXTURE2D(unity_Lightmap, samplerunity_Lightmap, IN.staticLightmapUV), "
                       "float4(LIGHTMAP_HDR_MULTIPLIER, LIGHTMAP_HDR_EXPONENT, 0.0h, 0.0h))",
}


def _shader(tmp_path, gi: str):
    text = f"""
    Shader "t/urp lightmap {gi}" {{
        SubShader {{
            Tags {{ "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }}
            Pass {{
                Tags {{ "LightMode" = "UniversalForward" }}
                HLSLPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #pragma multi_compile _ LIGHTMAP_ON
                #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"
                struct Attributes {{ float4 positionOS : POSITION; float3 normalOS : NORMAL;
                                     float2 staticLightmapUV : TEXCOORD1; }};
                struct Varyings {{ float4 positionCS : SV_POSITION; float3 normalWS : TEXCOORD0;
                                   DECLARE_LIGHTMAP_OR_SH(staticLightmapUV, vertexSH, 1); }};
                Varyings vert(Attributes IN) {{
                    Varyings OUT;
                    OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                    OUT.normalWS = TransformObjectToWorldNormal(IN.normalOS);
                    OUTPUT_LIGHTMAP_UV(IN.staticLightmapUV, unity_LightmapST, OUT.staticLightmapUV);
                    OUTPUT_SH(OUT.normalWS, OUT.vertexSH);
                    return OUT;
                }}
                float4 frag(Varyings IN) : SV_Target {{
                    return float4({GI[gi]}, 1.0);
                }}
                ENDHLSL
            }}
        }}
    }}
    """
    path = tmp_path / f"urp_lightmap_{gi}.shader"
    path.write_text(textwrap.dedent(text))
    return path


@pytest.mark.parametrize("encoding", ["rgbm", "dldr", "full_hdr"])
@pytest.mark.parametrize("gi", ["sample_gi", "sample_lightmap", "decode_lightmap"])
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_urp_pass_decodes_a_supplied_lightmap_per_pixel(tmp_path, language, gi, encoding):
    path, texels = _lightmap(tmp_path, encoding)
    lightmap = {"path": str(path), "encoding": encoding, "scale_offset": list(SCALE_OFFSET)}
    image = _render(tmp_path, _shader(tmp_path, gi), language, lightmap)
    expectation, compared = expected(image.shape[:2], texels, encoding)
    assert compared.mean() > 0.05
    assert over_bound(image, expectation, compared) == 0.0
    if encoding != "full_hdr":  # control: the expectation without unity_LightmapST fails
        unscaled, compared = expected(image.shape[:2], texels, encoding, scale_offset=(1, 1, 0, 0))
        assert over_bound(image, unscaled, compared) > 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_without_a_lightmap_sample_gi_is_the_sh_as_before(tmp_path, language):
    """No lightmap: LIGHTMAP_ON is off, SAMPLE_GI is SampleSH of the normal (the same program text
    as a pass calling SampleSH itself: equal to float32 rounding, 4 ulp of values below 4), and
    the lightmap's float64 expectation fails on it (the control of the test above)."""
    path, texels = _lightmap(tmp_path, "rgbm")
    gi = _render(tmp_path, _shader(tmp_path, "sample_gi"), language)
    sh = _render(tmp_path, _shader(tmp_path, "sample_sh"), language)
    covered = sh[..., 3] > 0
    assert covered.mean() > 0.3 and (sh[..., :3][covered] > 0).all()
    assert (np.abs(gi - sh)[covered] <= 4 * 2.0 ** -24 * 4).all()
    expectation, compared = expected(gi.shape[:2], texels, "rgbm")
    assert over_bound(gi, expectation, compared) > 0.9


def test_the_corpus_lightmaps_a_urp_shader_that_reads_the_lightmap_unconditionally(tmp_path):
    """unity_corpus gives the sphere a lightmap for a URP pass that reads unity_Lightmap outside
    LIGHTMAP_ON (URP's stand-ins declare it only there); not for one that reads only
    unity_LightmapST (defined for every object: the identity) or SAMPLE_GI (control)."""
    reading = _shader(tmp_path, "sample_gi").read_text().replace(
        "return float4(SAMPLE_GI", "return SAMPLE_TEXTURE2D(unity_Lightmap, samplerunity_Lightmap, 0.5) + float4(SAMPLE_GI")
    path = tmp_path / "reads.shader"
    path.write_text(reading.replace('"t/urp lightmap sample_gi"', '"t/reads"'))
    assert corpus._reads_lightmap(corpus._read(path))
    assert not corpus._reads_lightmap(corpus._read(_shader(tmp_path, "sample_gi")))
