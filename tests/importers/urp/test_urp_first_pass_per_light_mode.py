"""URP draws one pass of each LightMode of a SubShader: its DrawObjectsPass draws the first pass
tagged SRPDefaultUnlit, UniversalForward and UniversalForwardOnly (an untagged pass is
SRPDefaultUnlit: URP's ShaderLab Pass tags page), so a second untagged pass is not drawn (the
sources: importers/unity/parse.first_of_light_mode's docstring). pbrlab drew
every untagged pass, so an image-effect shader of three untagged passes (a bloom's threshold,
blur and combine steps, which a C# script chains) showed its last pass, black by its unset
script inputs, instead of its first (issue 34).

Scene: the corpus camera looking at a unit UV sphere; the first pass returns a constant colour,
the second black, both at the sphere's depth (the default ZTest LEqual passes the second where
it is drawn), so every covered pixel is exactly one pass's constant.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.importers.unity import parse
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

PASS = """
        Pass {
            %(tag)s
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            float4 vert(float4 positionOS : POSITION) : SV_POSITION { return TransformObjectToHClip(positionOS.xyz); }
            float4 frag() : SV_Target { return float4(%(colour)s); }
            ENDHLSL
        }
"""
FIRST = (0.25, 0.5, 0.75, 1.0)   # the first pass's colour: what URP shows
SECOND = (0.0, 0.0, 0.0, 1.0)    # the second's, black, as the bloom's last step with its inputs unset


def shader(second_tag: str = "") -> str:
    passes = (PASS % {"tag": "", "colour": ", ".join(map(str, FIRST))}
              + PASS % {"tag": second_tag, "colour": ", ".join(map(str, SECOND))})
    return ('Shader "t/two passes" {\n    SubShader {\n'
            '        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }\n'
            + passes + "    }\n}\n")


def _all(pixels, colour) -> bool:
    # constants written as float32 and passed through unchanged: one float32 ulp below 1 bounds them
    return bool(np.all(np.abs(pixels - np.array(colour, np.float64)) <= 2.0 ** -24))


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_second_untagged_pass_is_not_drawn(tmp_path, language):
    with pytest.warns(UserWarning, match=r"draws the first pass of each LightMode"):
        pixels, _ = render_constant(tmp_path, shader(), language)
    assert _all(pixels, FIRST), np.unique(pixels.round(5), axis=0)[:4]


def test_passes_of_different_light_modes_are_both_drawn(tmp_path):
    """Control: the second pass tagged UniversalForward is the first of its LightMode: drawn,
    over the first (equal depth, LEqual), so every pixel is its black."""
    pixels, _ = render_constant(tmp_path, shader('Tags { "LightMode" = "UniversalForward" }'), "glsl")
    assert _all(pixels, SECOND), np.unique(pixels.round(5), axis=0)[:4]


def test_drawing_every_untagged_pass_showed_the_last(tmp_path, monkeypatch):
    """Control: the old rule (every untagged pass drawn) shows the second pass's black."""
    monkeypatch.setattr(parse, "first_of_light_mode", lambda *a: True)
    pixels, _ = render_constant(tmp_path, shader(), "glsl")
    assert _all(pixels, SECOND), np.unique(pixels.round(5), axis=0)[:4]
