"""A URP construct the GLSL port refused where HLSL rendered (issue 34's hidden URP sample,
session 43: w963963555577/Funcy_URP-Shader's Lit shaders, measured not committed): a struct
whose members depend on the preprocessor, zeroed with ``(Varyings)0``, declared inside an
include guard the program writes around part of itself (``#ifndef X`` / ``#define X``, as URP's
own pass files do). The port defines the struct's zero at the end of the text under the
conditions around the struct; the guard's condition is false there, so the zero was declared and
never defined ("unresolved reference to function pbr_unity_zero_Varyings").

Scene and readback: test_urp_library_round2.render_constant (a unit sphere; covered pixels)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.importers.unity import cg_types
from test_urp_library_round2 import render_constant  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")

GUARDED = textwrap.dedent("""
    Shader "t/guarded" {
        SubShader {
            Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
            Pass {
                Tags { "LightMode" = "UniversalForward" }
                Cull Back
                HLSLPROGRAM
                #pragma vertex vert
                #pragma shader_feature _MY_TINT
                #pragma fragment frag
                #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
                #ifndef MY_FORWARD_PASS_INCLUDED
                    #define MY_FORWARD_PASS_INCLUDED
                    struct Attributes { float4 positionOS : POSITION; };
                    struct Varyings {
                        float4 positionCS : SV_POSITION;
                        float3 base : TEXCOORD0;
                    #ifdef _MY_TINT
                        float3 tint : TEXCOORD1;
                    #endif
                    };
                    Varyings vert(Attributes IN) {
                        Varyings OUT = (Varyings)0;
                        OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                        OUT.base = float3(0.375, 0.25, 0.125);
                        return OUT;
                    }
                    float4 frag(Varyings IN) : SV_Target { return float4(IN.base + 0.5 * IN.base, 1); }
                #endif
                ENDHLSL
            }
        }
    }
""")


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_conditional_structs_zero_inside_a_programs_own_include_guard(tmp_path, language):
    """The fragment's 1.5 x the vertex stage's (0.375, 0.25, 0.125) on every covered pixel
    (float32: exact in binary); the GLSL port failed to link before."""
    pixels, _ = render_constant(tmp_path, GUARDED, language, environment=False)
    assert np.abs(pixels[:, :3].astype(np.float64) - 1.5 * np.array([0.375, 0.25, 0.125])).max() <= 2.5e-7


def test_only_an_include_guard_is_left_out_of_the_zeros_conditions():
    """The conditions around a position: a guard (#ifndef X then #define X) is none, its #endif
    closing it; control: an #ifndef not followed by its #define stays a condition."""
    guarded = "#ifndef G\n#define G\n#ifdef A\n#endif\nHERE\n#endif\n"
    plain = "#ifndef G\n#define H\nHERE\n#endif\n"
    for text, want in ((guarded, []), (plain, ["#ifndef G"])):
        _, directives = cg_types.tokenize(text)
        assert cg_types._enclosing_conditions(text, directives, text.index("HERE")) == want
