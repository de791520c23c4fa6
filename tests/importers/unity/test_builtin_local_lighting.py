"""Two constructs of a built-in pass that keeps its lighting in a file of its own (issue 34):

* a local include named as one of Unity's (``#include "Lighting.cginc"`` beside the .shader):
  Unity reads the including file's folder first, so the shader's own file, in both languages
  (the HLSL path's include search named pbrlab's stand-in first);
* AutoLight's UNITY_LIGHT_ATTENUATION(name, input, worldPos), which declares the float local
  ``name``: the GLSL port's type pass knows it, so ``float3 c = float4(...) * name;`` is
  truncated as FXC truncates (a warning there).

Both languages, a constant pass checked at every covered pixel against float64.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
COLOUR = (0.25, 0.5, 0.75)

PASS = """
Shader "t/local lighting" {
    SubShader { Pass {
        Tags { "LightMode" = "ForwardBase" }
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        #include "Lighting.cginc"
        ENDCG
    } }
}
"""
# The shader's own Lighting.cginc: the whole program (a pass that includes only its own file).
LOCAL = """#ifndef LOCAL_LIGHTING
#define LOCAL_LIGHTING
#include "AutoLight.cginc"
struct v2f { float4 pos : SV_POSITION; float3 world : TEXCOORD0; };
v2f vert(float4 vertex : POSITION) {
    v2f o; o.pos = UnityObjectToClipPos(vertex); o.world = mul(unity_ObjectToWorld, vertex).xyz; return o; }
float4 frag(v2f i) : SV_Target {
    UNITY_LIGHT_ATTENUATION(attenuation, i, i.world);
    float3 c = float4(%s, 1.0) * attenuation;
    return float4(c, 1);
}
#endif"""
# float32 products of exact binary fractions by an attenuation of 1: exact.
EXACT = 0.0


def _render(tmp_path, language, colour=COLOUR):
    (tmp_path / "Lighting.cginc").write_text(LOCAL % ", ".join(map(str, colour)))
    shader = tmp_path / "t.shader"
    shader.write_text(textwrap.dedent(PASS))
    data = corpus.scene_for(shader)
    data.pop("environment", None)
    data["lights"] = [{"type": "directional", "direction": [0.0, 0.0, -1.0], "color": [1.0, 1.0, 1.0],
                       "intensity": 1.0}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.2
    return image[covered, :3]


@pytest.mark.parametrize("language", LANGUAGES)
def test_the_shaders_own_lighting_cginc_and_its_attenuation_local(tmp_path, language):
    # AutoLight's attenuation of a directional light without shadows: 1 (Unity's manual)
    assert np.abs(_render(tmp_path, language) - np.asarray(COLOUR)).max() <= EXACT
    # control: the local file is the one read (another colour in it, another image)
    assert np.abs(_render(tmp_path, language, (0.5, 0.5, 0.5)) - np.asarray(COLOUR)).max() >= 0.25
