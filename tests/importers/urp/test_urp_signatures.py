"""How the reader reads a URP pass's vertex and fragment signatures (issue 34): ``#if`` lines
inside a parameter list (URP 14's ``, out half4 outColor : SV_Target0 #ifdef
_WRITE_RENDERING_LAYERS , out float4 outRenderingLayers : SV_Target1 #endif``) read as the drawn
variant's parameters; a struct the signatures name that only an include pbrlab lacks defines is
refused naming that include (URP's 2D shadow shaders), not as a signature without semantics."""

from __future__ import annotations

import pytest

from pbrlab.foundation.errors import PbrlabError
from test_urp_library_round2 import urp_pass  # pytest puts this folder on sys.path
from test_urp_passes import COLOUR, LANGUAGES, _sphere

# URP 14's fragment signature (its Lit pass's): the scene-texture tests' pass with that frag.
LAYERED_OUTPUT = urp_pass("layered output", "").replace("float4 frag(Varyings IN) : SV_Target {", """void frag(
    Varyings input
    , out half4 outColor : SV_Target0
#ifdef _WRITE_RENDERING_LAYERS
    , out float4 outRenderingLayers : SV_Target1
#endif
)
{
    outColor = half4(0.25, 0.5, 0.75, 1.0);
#ifdef _WRITE_RENDERING_LAYERS
    outRenderingLayers = 0;
#endif""")


@pytest.mark.parametrize("language", LANGUAGES)
def test_if_lines_in_a_parameter_list_read_as_the_drawn_variant(tmp_path, language):
    """_WRITE_RENDERING_LAYERS is off (no keyword sets it here): one output, the centre pixel
    its colour. Control: the same lines with '#' removed are no directive, and the parameter
    text is refused as before."""
    assert "SV_Target1" in LAYERED_OUTPUT
    image = _sphere(tmp_path, language, LAYERED_OUTPUT)
    assert image[24, 24, :3].tolist() == list(COLOUR)
    broken = LAYERED_OUTPUT.replace("#ifdef _WRITE_RENDERING_LAYERS\n    , out", "ifdef _WRITE_RENDERING_LAYERS\n    , out")
    assert broken != LAYERED_OUTPUT
    with pytest.raises(PbrlabError, match="cannot read the parameter"):
        _sphere(tmp_path, language, broken)


SHADOW_INCLUDE = "Packages/com.unity.render-pipelines.universal/Shaders/2D/Include/ShadowProjectVertex.hlsl"
PROJECTED = """
Shader "t/projected shadow" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "%s"
            Varyings vert(Attributes v) { return ProjectShadow(v); }
            half4 frag(Varyings i) : SV_Target { return half4(0.25, 0.5, 0.75, 1.0); }
            ENDHLSL
        }
    }
}
""" % SHADOW_INCLUDE


def test_a_struct_only_a_missing_include_defines_is_refused_naming_the_include(tmp_path):
    """Control: with the include's structs and function written in the shader instead, it
    renders its colour."""
    with pytest.raises(PbrlabError, match=r"uses " + SHADOW_INCLUDE.replace(".", r"\.") +
                       r", one of Unity's include files pbrlab has no stand-in for.*vert\(\) takes or gives "
                       r"Varyings, a type none of the rest defines"):
        _sphere(tmp_path, "glsl", PROJECTED)
    own = urp_pass("own projection", "return float4(0.25, 0.5, 0.75, 1.0);")
    image = _sphere(tmp_path, "glsl", own)
    assert image[24, 24, :3].tolist() == list(COLOUR)
