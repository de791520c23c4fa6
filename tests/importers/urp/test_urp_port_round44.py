"""URP texture macros given a longer location (issue 34's hidden URP sample, session 44:
yunyufeiwei's ``SAMPLE_TEXTURECUBE_LOD(_Cubemap, sampler_Cubemap, float4(dir, mip), 3)``):
Core RP's macro is ``TextureCube.SampleLevel``, which FXC gives the location's first three
components (warning X3206, implicit truncation of a vector type); the GLSL port packed the
float4 and the level into a five-component float4 and was refused. Both languages now read the
texel the float3 direction reads.

Scene and readback: test_urp_library_round2.render_constant (a unit sphere; covered pixels). The
cube, declared without a property, is the scene's environment (unset_samplers)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from test_urp_library_round2 import render_constant  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")
EXACT = 2.5e-7  # 2 ulp of 1: the same texel read by two programs

CUBE = textwrap.dedent("""
    Shader "t/{name}" {{
        SubShader {{
            Tags {{ "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }}
            Pass {{
                Tags {{ "LightMode" = "UniversalForward" }}
                HLSLPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
                TEXTURECUBE(_Cube); SAMPLER(sampler_Cube);
                struct Attributes {{ float4 positionOS : POSITION; }};
                struct Varyings {{ float4 positionCS : SV_POSITION; }};
                Varyings vert(Attributes IN) {{
                    Varyings OUT; OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz); return OUT;
                }}
                float4 frag(Varyings IN) : SV_Target {{
                    return float4(SAMPLE_TEXTURECUBE_LOD(_Cube, sampler_Cube, {location}, 0).rgb, 1);
                }}
                ENDHLSL
            }}
        }}
    }}
""")


@pytest.mark.parametrize("language", LANGUAGES)
def test_sample_texturecube_lod_of_a_float4_reads_its_xyz(tmp_path, language):
    """float4(0, 1, 0, 7) reads what float3(0, 1, 0) reads on every covered pixel; control: the
    opposite direction (ground for sky) reads another colour."""
    def drawn(name, location):
        pixels, _ = render_constant(tmp_path, CUBE.format(name=name, location=location), language, environment=True)
        return pixels[:, :3].astype(np.float64)

    longer = drawn("cube4", "float4(0, 1, 0, 7)")
    assert np.all(np.isfinite(longer))
    assert np.abs(longer - drawn("cube3", "float3(0, 1, 0)")).max() <= EXACT
    assert np.abs(longer - drawn("cube_down", "float3(0, -1, 0)")).max() > 0.01
