"""Stand-ins for URP / Core RP include files users' shaders include (issue 34): URP's
Shaders/UnlitInput.hlsl (a copy of URP's Unlit shader includes it for its material inputs,
_BaseMap (white by default) and its _ST, _BaseColor, _Cutoff, _Surface), and Core RP's
Filtering.hlsl (Amplify Shader Editor's URP templates include it without calling it; a call of
one of its filters is refused naming it).

Scene: a unit UV sphere (test_urp_library_round2's) drawn with an unlit pass returning a
constant over the sphere.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.foundation.errors import PbrlabError
from pbrlab.render.renderer import render_scene
from test_urp_library_round2 import render_constant, urp_pass

LANGUAGES = ("glsl", "hlsl")

UNLIT = textwrap.dedent("""
    Shader "t/unlit input" {
        Properties {
            [MainTexture] _BaseMap("Texture", 2D) = "white" {}
            [MainColor] _BaseColor("Color", Color) = (0.25, 0.5, 0.75, 1)
            _Cutoff("AlphaCutout", Range(0.0, 1.0)) = 0.5
        }
        SubShader {
            Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
            Pass {
                HLSLPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "Packages/com.unity.render-pipelines.universal/Shaders/UnlitInput.hlsl"
                struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
                struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
                Varyings vert(Attributes IN) {
                    Varyings OUT;
                    OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                    OUT.uv = TRANSFORM_TEX(IN.uv, _BaseMap);
                    return OUT;
                }
                float4 frag(Varyings IN) : SV_Target {
                    float4 c = SAMPLE_TEXTURE2D(_BaseMap, sampler_BaseMap, float2(0.5, 0.5)) * _BaseColor;
                    AlphaDiscard(c.a, _Cutoff);
                    return float4(c.rgb, 1.0);
                }
                ENDHLSL
            }
        }
    }
    """)
# exact: white (1.0) times constants float32 holds
BOUND = 0.0


def _render(tmp_path, language, properties=None) -> np.ndarray:
    shader = tmp_path / "unlit.shader"
    shader.write_text(UNLIT)
    data = {"camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [32, 32]},
            "materials": {"m": {"surface": str(shader), **({"properties": properties} if properties else {})}},
            "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]}
    image = render_scene(parse_scene(data, origin="unlit input test", base=tmp_path), language=language)
    image = image.linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 100
    return image[covered][:, :3]


@pytest.mark.parametrize("language", LANGUAGES)
def test_unlit_input_declares_the_unlit_material_inputs(tmp_path, language):
    """The pixel is the white base map times _BaseColor's default (0.25, 0.5, 0.75). Control: the
    material's own _BaseColor (0.5, 0.25, 1) reaches the same variable and changes the pixel."""
    pixels = _render(tmp_path, language)
    assert (np.abs(pixels - [0.25, 0.5, 0.75]).max(axis=1) > BOUND).mean() == 0.0
    overridden = _render(tmp_path, language, {"_BaseColor": [0.5, 0.25, 1.0, 1.0]})
    assert (np.abs(overridden - [0.5, 0.25, 1.0]).max(axis=1) > BOUND).mean() == 0.0


FILTERING = '#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Filtering.hlsl"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_filtering_include_alone_draws(tmp_path, language):
    """A program including Filtering.hlsl and calling none of it draws its constant (0.25, 0.5,
    0.75), exactly. Control: one calling SampleTexture2DBicubic is refused naming the function
    and Filtering.hlsl, not drawn."""
    pixels, _ = render_constant(tmp_path, urp_pass("filtering", "return float4(0.25, 0.5, 0.75, 1.0);", FILTERING),
                                language, environment=False)
    assert (np.abs(pixels[:, :3] - [0.25, 0.5, 0.75]).max(axis=1) > BOUND).mean() == 0.0
    body = ("float2 s = float2(1.0, 1.0);\n"
            "                return SampleTexture2DBicubic(TEXTURE2D_ARGS(_T, sampler_T), float2(0.5, 0.5),"
            " float4(s, s), s, 0);")
    text = urp_pass("bicubic", body, FILTERING + "\n            TEXTURE2D(_T); SAMPLER(sampler_T);")
    with pytest.raises(PbrlabError, match="uses SampleTexture2DBicubic, part of Core RP's Filtering.hlsl"):
        render_constant(tmp_path, text, language, environment=False)
