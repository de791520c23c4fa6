"""Core RP's `real` types (`real`, `real2..4`: half or float by platform; the stand-in's Core.hlsl
defines them as float) as members of the structure a URP vertex stage passes to its fragment
stage. The varying check knew Cg's names only, so `real4 color : COLOR` was refused ("real4
cannot pass between the stages here"): 6 of 124 shaders of an unseen URP sample (docs/unity.md)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.unity import generate_pass

SHADER = textwrap.dedent("""\
    Shader "Test/RealVaryings"
    {
        Properties { _Tint ("Tint", Color) = (0.75, 0.25, 0.5, 1) }
        SubShader
        {
            Tags { "RenderPipeline" = "UniversalPipeline" }
            Pass
            {
                Tags { "LightMode" = "UniversalForward" }
                HLSLPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
                CBUFFER_START(UnityPerMaterial)
                half4 _Tint;
                CBUFFER_END
                struct Attributes { float4 positionOS : POSITION; };
                struct Varyings { float4 positionCS : SV_POSITION; real4 color : COLOR; real scale : TEXCOORD0; };
                Varyings vert(Attributes i)
                {
                    Varyings o;
                    o.positionCS = TransformObjectToHClip(i.positionOS.xyz);
                    o.color = _Tint;
                    o.scale = 0.5;
                    return o;
                }
                half4 frag(Varyings i) : SV_Target { return half4(i.color.rgb * i.scale, 1); }
                ENDHLSL
            }
        }
    }
    """)


def _shader(tmp_path):
    path = tmp_path / "real_varyings.shader"
    path.write_text(SHADER, encoding="utf-8")
    return path


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_real_members_pass_between_the_stages(tmp_path, language):
    """The colour the program passes, _Tint * 0.5, on every pixel the sphere covers fully: the
    same value at every vertex, so interpolation keeps it (short binary fractions: exact)."""
    outcome = corpus.run_shader(_shader(tmp_path), language)
    assert outcome.status == "rendered", outcome.message
    covered = outcome.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(outcome.image[covered][:, :3], np.broadcast_to([0.375, 0.125, 0.25], (covered.sum(), 3)))


def test_without_the_real_names_the_member_is_refused(tmp_path, monkeypatch):
    """Control: the varying check without Core RP's names refuses the shader as before."""
    known = generate_pass.component_count
    monkeypatch.setattr(generate_pass, "component_count", lambda kind: 0 if kind.startswith("real") else known(kind))
    outcome = corpus.run_shader(_shader(tmp_path), "glsl")
    assert outcome.status == "refused" and "real4 cannot pass between the stages" in outcome.message
