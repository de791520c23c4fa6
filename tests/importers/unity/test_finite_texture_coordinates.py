"""A texture lookup at a NaN or infinite coordinate reads a texel, as Direct3D's sampler does
(importers/unity/finite_texture_coordinates.py): Direct3D converts the coordinate to fixed point
before addressing (Direct3D 10/11 "Data Conversion Rules": NaN becomes 0), so a finite texture
samples finite. Mesa's llvmpipe filtered a NaN coordinate into a NaN colour: motion blurs whose
script-set matrix is 0 (worldPos / worldPos.w = 0 / 0 feeds the UV), a wave effect dividing its
UV offset by an unset width, an AO pass dividing its step by an unset downsample factor all
rendered non-finite where Unity draws them.

Each shader below returns ``lookup * _Color`` of a "white" (1, 1, 1, 1) texture: Unity's value
on the sphere is _Color itself, (0.75, 0.25, 0.5), computed below in float64. Controls: a NaN the
shader computes itself (``* (0 / 0)`` on the colour, NaN in Unity as well) stays non-finite, and
without the rewrite of spirv-cross's GLSL the HLSL program is non-finite again (the old
behaviour)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.unity import finite_texture_coordinates

COLOR = np.array([0.75, 0.25, 0.5], np.float64)  # _Color's default; times white (1.0) = itself
# The fragment returns fixed4 (half precision at worst): 0.75, 0.25 and 0.5 are exact in half,
# and the white texel is 255/255 = 1 exactly, so the product is exact; the bound is one half
# ulp in [0.5, 1), 2^-11, the only rounding a half-precision product could add.
BOUND = 2.0 ** -11
# the corpus sphere covers 2624 of the 4096 pixels (corpus scene, 64 x 64); its silhouette ring,
# partly covered, is left out by requiring every channel to match: >= 2000 pixels remain
INTERIOR_PIXELS = 2000

# both pipelines' shaders: a white texture, _Color, and a 0 to divide by
PROPERTIES = """\
    Properties {
        _MainTex ("Texture", 2D) = "white" {}
        _Color ("Color", Color) = (0.75, 0.25, 0.5, 1)
        _Zero ("Zero", Float) = 0
    }
"""

BUILT_IN = """\
Shader "Test/FiniteCoordinate" {
""" + PROPERTIES + """\
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        sampler2D _MainTex;
        fixed4 _Color;
        float _Zero;
        struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }
        fixed4 frag(v2f i) : SV_Target { return %s; }
        ENDCG
    } }
}
"""

URP = """\
Shader "Test/FiniteCoordinateURP" {
""" + PROPERTIES + """\
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            Texture2D _MainTex; SamplerState sampler_MainTex;
            float4 _Color;
            float _Zero;
            struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
            struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.uv = IN.uv;
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target { float2 uv = IN.uv; %s }
            ENDHLSL
        }
    }
}
"""

CASES = {
    # Cg's tex2D at uv + 0/0 (NaN), tex2Dproj with w = 0 (a Projector's unset matrix: inf),
    # tex2Dlod at NaN; URP's SAMPLE_TEXTURE2D and Texture2D.Sample at NaN
    "tex2D_nan": (BUILT_IN, "tex2D(_MainTex, i.uv + _Zero / _Zero) * _Color"),
    "tex2Dproj_w0": (BUILT_IN, "tex2Dproj(_MainTex, float4(i.uv, 0.0, _Zero)) * _Color"),
    "tex2Dlod_nan": (BUILT_IN, "tex2Dlod(_MainTex, float4(i.uv * (_Zero / _Zero), 0.0, 0.0)) * _Color"),
    "sample_macro_nan": (URP, "return SAMPLE_TEXTURE2D(_MainTex, sampler_MainTex, uv + _Zero / _Zero) * _Color;"),
    "sample_method_inf": (URP, "float4 c = _MainTex.Sample(sampler_MainTex, uv / _Zero); return c * _Color;"),
}
FINITE_TWIN = {BUILT_IN: "tex2D(_MainTex, i.uv) * _Color",
               URP: "return SAMPLE_TEXTURE2D(_MainTex, sampler_MainTex, uv) * _Color;"}


def _run(tmp_path, name: str, template: str, returned: str, language: str):
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(template % returned))
    return corpus.run_shader(path, language)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("case", sorted(CASES))
def test_a_lookup_at_a_non_finite_coordinate_reads_the_texel(tmp_path, case, language):
    template, returned = CASES[case]
    outcome = _run(tmp_path, case, template, returned, language)
    assert outcome.status == "rendered", outcome.message
    image = np.asarray(outcome.image, np.float64)[..., :3]
    twin = _run(tmp_path, f"{case}_finite", template, FINITE_TWIN[template], language)
    assert twin.status == "rendered", twin.message
    expected = np.asarray(twin.image, np.float64)[..., :3]
    interior = np.all(np.abs(expected - COLOR) <= BOUND, axis=-1)
    assert interior.sum() >= INTERIOR_PIXELS, interior.sum()
    # every pixel as the finite lookup draws it; on the sphere's interior, _Color (float64)
    over = np.any(np.abs(image - expected) > BOUND, axis=-1)
    assert over.mean() == 0.0, f"{over.sum()} pixels differ from the finite lookup"
    assert np.all(np.abs(image[interior] - COLOR) <= BOUND)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_nan_the_shader_computes_itself_stays_non_finite(tmp_path, language):
    # control: 0 / 0 on the colour is NaN in Unity too (Direct3D 11's float rules: 0/0 = NaN)
    outcome = _run(tmp_path, "own_nan", BUILT_IN, "tex2D(_MainTex, i.uv) * _Color * (_Zero / _Zero)", language)
    assert outcome.status == "non-finite", outcome.message


def test_without_the_rewrite_an_hlsl_lookup_at_nan_is_non_finite(tmp_path, monkeypatch):
    # control: the old behaviour (spirv-cross's GLSL as written) draws NaN on llvmpipe
    monkeypatch.setattr(finite_texture_coordinates, "applied", lambda glsl: glsl)
    outcome = _run(tmp_path, "unrewritten", URP, CASES["sample_method_inf"][1], "hlsl")
    assert outcome.status == "non-finite", outcome.message


def test_the_rewrite_wraps_each_coordinate_and_leaves_texel_fetches():
    glsl = ("#version 330\n#extension GL_ARB_separate_shader_objects : require\nuniform sampler2D t;\n"
            "void main() { vec4 a = textureLod(t, texture(t, vec2(0.5)).xy, 0.0);"
            " vec4 b = texelFetch(t, ivec2(0), 0); }\n")
    out = finite_texture_coordinates.applied(glsl)
    assert ("textureLod(t, pbr_unity_finite_coordinate(texture(t, pbr_unity_finite_coordinate(vec2(0.5))).xy), 0.0)"
            in out)
    assert "texelFetch(t, ivec2(0), 0)" in out
    lines = out.split("\n")
    assert lines[:2] == glsl.split("\n")[:2]  # #version and #extension stay first
    assert out.index("pbr_unity_finite_coordinate(float x)") < out.index("uniform sampler2D t;")
    # a program that samples nothing is returned as it was
    assert finite_texture_coordinates.applied("#version 330\nvoid main() {}\n") == "#version 330\nvoid main() {}\n"
