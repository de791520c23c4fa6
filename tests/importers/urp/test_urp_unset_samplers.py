"""A texture a URP program declares with no Properties line and no engine input behind it
(``TEXTURE2D(_X)``, ``TEXTURECUBE(_X)``: often a misspelt property, as WaterWave's ``_Cubemap``
for its property ``_CubeMap``) gets pbrlab's default for an undeclared sampler, as a Cg
``sampler2D`` / ``samplerCUBE`` does (parse._implicit_texture_properties): white for a 2D
texture, the scene's environment for a cube (importers/unity/unset_samplers.py). Before, both
stayed on texture unit 0: the 2D one read the renderer's DFG table, and with the cube beside it
the draw was invalid (two sampler types on one unit) and the object vanished (issue 34).

Scene: the corpus camera looking at a unit UV sphere; the pass returns the 2D texture's red,
a constant and a step of the cube's green (1 for any finite sample), so every covered pixel is
exact.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.importers.unity import unset_samplers
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

UNSET = """
Shader "t/unset samplers" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            TEXTURE2D(_NoSuchMap); SAMPLER(sampler_NoSuchMap);
            TEXTURECUBE(_NoSuchCube); SAMPLER(sampler_NoSuchCube);
            struct Attributes { float4 positionOS : POSITION; float3 normalOS : NORMAL; float2 uv : TEXCOORD0; };
            struct Varyings { float4 positionCS : SV_POSITION; float3 normal : TEXCOORD0; float2 uv : TEXCOORD1; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.normal = IN.normalOS;
                OUT.uv = IN.uv;
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target {
                float4 map = SAMPLE_TEXTURE2D(_NoSuchMap, sampler_NoSuchMap, IN.uv);
                float4 cube = SAMPLE_TEXTURECUBE(_NoSuchCube, sampler_NoSuchCube, IN.normal);
                return float4(map.r, 0.5, step(-1.0, cube.g), 1.0);
            }
            ENDHLSL
        }
    }
}
"""
EXPECTED = np.array([1.0, 0.5, 1.0, 1.0])  # white's red; the constant; a finite cube sample


@pytest.mark.parametrize("language", LANGUAGES)
def test_unset_samplers_read_the_undeclared_default(tmp_path, language):
    pixels, _ = render_constant(tmp_path, UNSET, language)
    assert np.all(np.abs(pixels - EXPECTED) <= 2.0 ** -24), np.unique(pixels.round(5), axis=0)[:4]


def test_left_on_unit_zero_the_sphere_vanished(tmp_path, monkeypatch):
    """Control: without the binding, the draw fails and no pixel is covered."""
    monkeypatch.setattr(unset_samplers, "bind_unset", lambda *a: 0)
    with pytest.raises(AssertionError, match=r"assert np.int64\(0\) > 200"):
        render_constant(tmp_path, UNSET, "glsl")  # covers no pixel
