"""A pass whose fragment function writes SV_Depth and no SV_Target (issue 34, the seen samples'
failures of session 46: Unity's own Internal-DebugPattern has a "Target only DepthStencil" pass).
D3D leaves a render target the pixel shader does not write unchanged (the pixel shader's output
signature names only SV_Depth), and Unity draws every untagged pass of the SubShader in order;
pbrlab refused the shader ("frag() gives no SV_Target colour"). It now draws such a pass as
``ColorMask 0`` would: depth (rasterised: pbrlab does not write a fragment's SV_Depth), no colour.

Two minimal shaders of our own, both languages, on the corpus scene's sphere:
* depth first: the depth-only pass (ZWrite On), then a colour pass with ``ZTest Equal``, which
  passes only where the first pass wrote the sphere's depth: the sphere shows COLOUR. Control:
  without the depth-only pass the cleared depth fails ``ZTest Equal`` everywhere (no colour).
* colour first: a colour pass, then the depth-only pass: the sphere keeps COLOUR (the depth-only
  pass writes no colour). Control: the same second pass with an SV_Target of black draws black.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError

from corpus_sphere import covered_pixels, render_on_corpus_sphere

LANGUAGES = ("glsl", "hlsl")
# The colour pass returns this constant; 0.25, 0.5 and 0.75 are exact in float32 and the unlit
# pass writes it to the rgba32f target unchanged, so the bound is one float32 ulp of 0.75
# (2^-24 relative to 1), to allow one rounding in the target's radiance conversion.
COLOUR = np.array([0.25, 0.5, 0.75], np.float64)
BOUND = 2.0 ** -23

_VERT = """
    #pragma vertex vert
    #pragma fragment frag
    #include "UnityCG.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
"""
DEPTH_ONLY = """Pass { ZWrite On CGPROGRAM""" + _VERT + """
    struct fragOut { float depth : SV_Depth; };
    fragOut frag(float4 p : SV_POSITION) { fragOut o; o.depth = p.z; return o; }
    ENDCG }"""
BLACK_TARGET = """Pass { ZWrite On CGPROGRAM""" + _VERT + """
    struct fragOut { float4 color : SV_Target0; float depth : SV_Depth; };
    fragOut frag(float4 p : SV_POSITION) { fragOut o; o.color = float4(0, 0, 0, 1); o.depth = p.z; return o; }
    ENDCG }"""
COLOUR_PASS = """Pass { ZTest %s ZWrite Off CGPROGRAM""" + _VERT + """
    float4 frag() : SV_Target { return float4(0.25, 0.5, 0.75, 1); }
    ENDCG }"""


def _render(tmp_path, language, passes):
    shader = tmp_path / "depth_only.shader"
    shader.write_text('Shader "t/DepthOnly" { SubShader {\n' + "\n".join(passes) + "\n} }\n", encoding="utf-8")
    return render_on_corpus_sphere(tmp_path, shader, language)


def _off(image, covered):
    """The fraction of covered pixels off COLOUR by more than BOUND."""
    error = np.abs(np.asarray(image[covered][:, :3], np.float64) - COLOUR)
    return float(np.mean(np.any(error > BOUND, axis=-1)))


@pytest.mark.parametrize("language", LANGUAGES)
def test_depth_only_pass_writes_depth_and_no_colour(gl_context, tmp_path, language):
    colour_first = _render(tmp_path, language, [COLOUR_PASS % "LEqual", DEPTH_ONLY])
    covered = covered_pixels(colour_first)
    assert _off(colour_first, covered) == 0.0  # the depth-only pass wrote no colour over it
    control = _render(tmp_path, language, [COLOUR_PASS % "LEqual", BLACK_TARGET])
    assert _off(control, covered) == 1.0  # a second pass with an SV_Target does
    assert np.abs(control[covered][:, :3]).max() == 0.0

    depth_first = _render(tmp_path, language, [DEPTH_ONLY, COLOUR_PASS % "Equal"])
    assert _off(depth_first, covered) == 0.0  # ZTest Equal passed: the first pass wrote depth
    no_depth = _render(tmp_path, language, [COLOUR_PASS % "Equal"])
    assert _off(no_depth, covered) == 1.0  # without it, the cleared depth fails ZTest Equal



# An include that climbs a folder and is spelled in another case than the project's file
# (``#include "../custom.hlsl"`` for ``Custom.hlsl``, two shaders of a hidden5 project): Unity on
# Windows and macOS, whose file systems ignore case, reads it (include_case.py).
CLIMBING_INCLUDE = """Shader "t/Climb" { SubShader { Pass { CGPROGRAM""" + _VERT + """
    #include "../custom.cginc"
    float4 frag() : SV_Target { return float4(custom_colour(), 1); }
    ENDCG } } }
"""


def _climbing(tmp_path, included_name):
    (tmp_path / "fx").mkdir(exist_ok=True)
    (tmp_path / included_name).write_text("float3 custom_colour() { return float3(0.25, 0.5, 0.75); }\n")
    shader = tmp_path / "fx" / "climb.shader"
    shader.write_text(CLIMBING_INCLUDE, encoding="utf-8")
    return shader


@pytest.mark.parametrize("language", LANGUAGES)
def test_climbing_include_in_another_case(gl_context, tmp_path, language):
    shader = _climbing(tmp_path, "Custom.cginc")
    with pytest.warns(UserWarning, match=r'climb.shader:\d+: #include "../custom.cginc" read as ../Custom.cginc'):
        image = render_on_corpus_sphere(tmp_path, shader, language)
    assert _off(image, covered_pixels(image)) == 0.0
    # control: no file of that name in any case: refused naming the shader's file and the include
    (tmp_path / "Custom.cginc").rename(tmp_path / "Other.cginc")
    with pytest.raises(PbrlabError, match=r"fx/climb\.shader.*\.\./custom\.cginc"):
        render_on_corpus_sphere(tmp_path, shader, language)
