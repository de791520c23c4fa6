"""A URP pass whose fragment function writes SV_Depth and no SV_Target (issue 34, session 46's
reruns of the seen samples; the built-in twin and its depth checks are in
tests/importers/unity/test_unity_older_s46.py). D3D leaves a render target the pixel shader
does not write unchanged, so the pass draws no colour: pbrlab draws it as ``ColorMask 0`` with
a note, and the corpus report lists the shader as drawing no colour by its fragment function
(checking/unity_corpus.no_colour_reason), not as a silently black image. Before, it was refused
("frag() gives no SV_Target colour").

Control: the same pass with an SV_Target member returning COLOUR draws COLOUR on the sphere.
"""

from __future__ import annotations

import numpy as np

from pbrlab.checking import unity_corpus as corpus

LANGUAGES = ("glsl", "hlsl")
# 0.25, 0.5 and 0.75 are exact in float32 and the unlit pass writes them to the rgba32f target;
# one float32 ulp (2^-23 relative to 1) allows one rounding in the target's radiance conversion.
COLOUR = np.array([0.25, 0.5, 0.75], np.float64)
BOUND = 2.0 ** -23

SHADER = """Shader "t/UrpDepthOnly" {
    SubShader { Tags { "RenderPipeline" = "UniversalPipeline" }
    Pass { Tags { "LightMode" = "UniversalForward" } ZWrite On
    HLSLPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
    float4 vert(float4 v : POSITION) : SV_POSITION { return TransformObjectToHClip(v.xyz); }
    struct FragOut { %s float depth : SV_Depth; };
    FragOut frag(float4 p : SV_POSITION) { FragOut o; %s o.depth = p.z; return o; }
    ENDHLSL } } }
"""
TARGET = ("float4 color : SV_Target;", "o.color = float4(0.25, 0.5, 0.75, 1);")


def _outcomes(tmp_path, member, write):
    shader = tmp_path / "depth_only.shader"
    shader.write_text(SHADER % (member, write), encoding="utf-8")
    return {language: corpus.run_shader(shader, language) for language in LANGUAGES}


def test_depth_only_urp_pass_draws_no_colour(gl_context, tmp_path):
    outcomes = _outcomes(tmp_path, "", "")
    assert [o.status for o in outcomes.values()] == ["rendered", "rendered"]
    for o in outcomes.values():
        assert np.abs(np.asarray(o.image, np.float64)[..., :3]).max() == 0.0
    assert "draws no colour by its fragment function" in corpus.no_colour_reason(outcomes)
    # control: an SV_Target member draws its colour on the sphere's pixels (alpha 1)
    control = _outcomes(tmp_path, *TARGET)
    assert corpus.no_colour_reason(control) is None
    for o in control.values():
        image = np.asarray(o.image, np.float64)
        covered = image[..., 3] == 1.0
        assert covered.mean() > 0.3
        assert np.all(np.abs(image[covered][:, :3] - COLOUR) <= BOUND)
