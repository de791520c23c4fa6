"""A vertex input wider than the mesh's stream (issue 34, the all-black "rendered" shaders): the
input assembler fills the missing components with (0, 0, 0, 1) (Direct3D 11's documented
default for a missing component, 0 except w = 1; OpenGL 3.3 core, section 2.8, fills a
2-component array the same way). Unity's UVs are 2-component, so a ``float4 texcoord :
TEXCOORD0`` reads (u, v, 0, 1), and a float3 normal read as float4 has w = 1.

Before: pbrlab padded w with 0, which put a cloud billboard's vertices (its UVs' w carried
through the view matrix's translation, WoBok's Cloud demos) behind the camera: black.

Scene: the corpus camera looking at a unit UV sphere; the pass returns the padded components,
which are exact constants (0 and 1), so every covered pixel is compared with no tolerance.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.importers.unity import generate_pass
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

FETCH_SHADER = """
Shader "t/vertex fetch" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            struct Attributes { float4 positionOS : POSITION; float4 normalOS : NORMAL;
                                float4 uv0 : TEXCOORD0; float4 uv1 : TEXCOORD1; };
            struct Varyings { float4 positionCS : SV_POSITION; float4 fetched : TEXCOORD0; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.fetched = float4(IN.uv0.z, IN.uv0.w, IN.uv1.w, IN.normalOS.w);
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target {
                return float4(IN.fetched.x + 0.25, IN.fetched.y * 0.5, IN.fetched.z * 0.75,
                              0.5 + 0.5 * IN.fetched.w);
            }
            ENDHLSL
        }
    }
}
"""

# (uv0.z + 0.25, uv0.w * 0.5, uv1.w * 0.75, 0.5 + 0.5 * normal.w) with (z, w) = (0, 1): sums and
# products of dyadic constants, exact in float32; interpolating a constant varying rounds once
# at most (barycentric weights summing to 1 within float32's 2^-24 each): 2^-22 bounds it.
EXPECTED = np.array([0.25, 0.5, 0.75, 1.0])
BOUND = 2.0 ** -22


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_wider_vertex_input_reads_w_one(tmp_path, language):
    pixels, _ = render_constant(tmp_path, FETCH_SHADER, language, environment=False)
    assert np.all(np.abs(pixels - EXPECTED) <= BOUND), np.unique(pixels.round(6), axis=0)[:4]


def test_the_old_w_zero_is_rejected(tmp_path, monkeypatch):
    """Control: with the old pad (w = 0) the same pixels fail the check above."""
    old = {k: (expr, n, w if k in ("POSITION", "SV_POSITION") else 0.0)
           for k, (expr, n, w) in generate_pass._ATTRIBUTES.items()}
    monkeypatch.setattr(generate_pass, "_ATTRIBUTES", old)
    pixels, _ = render_constant(tmp_path, FETCH_SHADER, "glsl", environment=False)
    assert not np.all(np.abs(pixels - EXPECTED) <= BOUND)
