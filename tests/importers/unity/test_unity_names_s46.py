"""Built-in pipeline include and name gaps real shaders met (issue 34, session 46): Unity's own
include files named in angle brackets (``#include <UnityInstancing.cginc>`` in a project's
include file, as washble's animation-instancing shaders write it), and the legacy lighting
pre-pass's unity_LightmapFade (Internal-PrePassLighting). Each drawn in both languages on the
corpus scene's sphere (test_unity_names_round7's pass), against a float64 value, with a control.
"""

from __future__ import annotations

import pytest

from corpus_sphere import render_on_corpus_sphere
from pbrlab.foundation.errors import PbrlabError
from test_unity_names_round7 import FLOAT32_FEW_OPS, LANGUAGES, _assert_colour, _shader

# A project's include (beside the shader) that reads Unity's include files in angle brackets and
# declares a per-instance property through UnityInstancing.cginc's macros.
INSTANCED = """\
#include <UnityCG.cginc>
#include <UnityInstancing.cginc>
UNITY_INSTANCING_BUFFER_START(Props)
    UNITY_DEFINE_INSTANCED_PROP(float4, _Tint)
UNITY_INSTANCING_BUFFER_END(Props)
float4 InstanceTint() { return UNITY_ACCESS_INSTANCED_PROP(Props, _Tint) * UNITY_PI / 4.0; }
"""
TINT_PASS = """
Shader "t/{name}" {{
    Properties {{ _Tint ("tint", Color) = (0.2, 0.4, 0.6, 1) }}
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include <UnityCG.cginc>
        {include}
        struct v2f {{ float4 pos : SV_POSITION; }};
        v2f vert(appdata_base v) {{ v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }}
        float4 frag(v2f i) : SV_Target {{ return float4(InstanceTint().rgb, 1); }}
        ENDCG
    }} }}
}}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_unitys_includes_in_angle_brackets(tmp_path, language):
    """``#include <UnityCG.cginc>`` in the program and ``#include <UnityInstancing.cginc>`` in the
    project's include (itself included in angle brackets): Unity reads them as quoted names, from
    its CGIncludes. The per-instance property reads its material value (0.2, 0.4, 0.6) times
    UNITY_PI / 4 (UnityCG.cginc's pi). Bound: FLOAT32_FEW_OPS. Control: an angle-bracket include
    no folder holds is refused naming it."""
    (tmp_path / "instanced.cginc").write_text(INSTANCED)
    text = TINT_PASS.format(name="angle", include="#include <instanced.cginc>")
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "angle", "", text=text), language)
    pi = 3.14159265358979
    _assert_colour(image, [0.2 * pi / 4, 0.4 * pi / 4, 0.6 * pi / 4])
    text = TINT_PASS.format(name="absent", include="#include <absent_instanced.cginc>")
    with pytest.raises(PbrlabError, match="absent_instanced.cginc"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "absent", "", text=text), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_lightmap_fade_is_zero_no_fade(tmp_path, language):
    """UnityDeferredLibrary.cginc's unity_LightmapFade, the legacy pre-pass's fade of realtime
    light into Unity 4's dual lightmaps (fade = distance * z + w; the light times saturate(1 -
    fade)): Unity 5 removed dual lightmaps, so no fade is active and the global is zero, the
    light unfaded. The pixel: (0.25 + x, 0.5 + y, saturate(1 - (3 z + w))) = (0.25, 0.5, 1).
    Control: without that include the name is undeclared, refused naming it."""
    body = ("            float fade = 3.0 * unity_LightmapFade.z + unity_LightmapFade.w;\n"
            "            return float4(0.25 + unity_LightmapFade.x, 0.5 + unity_LightmapFade.y, saturate(1.0 - fade), 1);")
    image = render_on_corpus_sphere(tmp_path, _shader(tmp_path, "fade", body, includes='#include "UnityDeferredLibrary.cginc"'),
                                    language)
    _assert_colour(image, [0.25, 0.5, 1.0], FLOAT32_FEW_OPS)
    with pytest.raises(PbrlabError, match="unity_LightmapFade"):
        render_on_corpus_sphere(tmp_path, _shader(tmp_path, "no_fade", body), language)
