"""ShaderLab-level readings real shaders needed (issue 34, session 45's long tail): a stage
``#pragma`` whose function name ends with a semicolon (``#pragma fragment frag;``, two sampled
projects) names that function, in URP's HLSLPROGRAM and the built-in pipeline's CGPROGRAM; a
SubShader whose RenderPipeline tag matches no pipeline (``"UniversalPipelien"``, three sampled
shaders) is skipped as Unity skips it, and when nothing else runs the refusal names the shader's
file, the tag's line and the likely spelling. Each in both languages, a pixel against its exact
value (the passes return constants that float32 holds exactly), with a control.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

FRAG = (0.25, 0.5, 0.125)          # frag's constant
OTHER = (0.75, 0.375, 0.0625)      # frag_other's

_URP = """Shader "t/pragmas_and_tags" {
    SubShader {
        Tags { "RenderType" = "Opaque"
               "RenderPipeline" = "%(tag)s" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert%(end)s
            #pragma fragment %(fragment)s%(end)s
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; };
            Varyings vert(Attributes IN) { Varyings OUT; OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz); return OUT; }
            float4 frag(Varyings IN) : SV_Target { return float4(0.25, 0.5, 0.125, 1.0); }
            float4 frag_other(Varyings IN) : SV_Target { return float4(0.75, 0.375, 0.0625, 1.0); }
            ENDHLSL
        }
    }%(second)s
    FallBack Off
}
"""

# an untagged SubShader after the first: every pipeline's
_SECOND = """
    SubShader {
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            float4 vert(float4 positionOS : POSITION) : SV_POSITION { return TransformObjectToHClip(positionOS.xyz); }
            float4 frag() : SV_Target { return float4(0.75, 0.375, 0.0625, 1.0); }
            ENDHLSL
        }
    }"""

_BUILTIN = """Shader "t/pragmas_builtin" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert;
            #pragma fragment %(fragment)s;
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target { return float4(0.25, 0.5, 0.125, 1.0); }
            float4 frag_other() : SV_Target { return float4(0.75, 0.375, 0.0625, 1.0); }
            ENDCG
        }
    }
}
"""


def _urp(tmp_path, language, *, tag="UniversalPipeline", fragment="frag", end="", second=""):
    text = _URP % {"tag": tag, "fragment": fragment, "end": end, "second": second}
    return render_constant(tmp_path, text, language, environment=False)


def _drew(pixels, colour) -> bool:
    return bool(np.all(pixels[:, :3] == np.array(colour, np.float32)))


# --- #pragma fragment name; ----------------------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_semicolon_after_a_stage_functions_name_in_urp(tmp_path, language):
    """``#pragma vertex vert;`` / ``#pragma fragment frag_other;``: the name is the identifier, so
    frag_other draws (its exact constant on every covered pixel). Control: ``frag;`` draws frag's
    other constant, so the pragma, not a default, picks the function; a name no function has is
    still refused, naming it without the semicolon, with the shader's file and the pragma's line."""
    pixels, _ = _urp(tmp_path, language, fragment="frag_other", end=";")
    assert _drew(pixels, OTHER)
    control, _ = _urp(tmp_path, language, fragment="frag", end=";")
    assert _drew(control, FRAG) and not _drew(control, OTHER)
    with pytest.raises(PbrlabError) as refused:
        _urp(tmp_path, language, fragment="frag_missing", end=";")
    line = (_URP.split("\n").index("            #pragma fragment %(fragment)s%(end)s") + 1)
    assert f"{tmp_path / 't.shader'}:{line}: #pragma fragment frag_missing: no function frag_missing(...) is defined" \
        in str(refused.value)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_semicolon_after_a_stage_functions_name_in_cgprogram(tmp_path, language):
    """The same in the built-in pipeline's CGPROGRAM: frag_other's exact constant; control: frag's."""
    pixels, _ = render_constant(tmp_path, _BUILTIN % {"fragment": "frag_other"}, language, environment=False)
    assert _drew(pixels, OTHER)
    control, _ = render_constant(tmp_path, _BUILTIN % {"fragment": "frag"}, language, environment=False)
    assert _drew(control, FRAG)


# --- a RenderPipeline tag no pipeline has ---------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_misspelt_render_pipeline_tag_skips_its_subshader(tmp_path, language):
    """Unity runs a SubShader with a RenderPipeline tag only where the tag matches the pipeline's
    name exactly (Shader.globalRenderPipeline), so a misspelt first SubShader is skipped and the
    untagged second draws: its constant, not the first's. Control: spelt right, the first draws."""
    pixels, _ = _urp(tmp_path, language, tag="UniversalPipelien", second=_SECOND)
    assert _drew(pixels, OTHER)
    control, _ = _urp(tmp_path, language, tag="UniversalPipeline", second=_SECOND)
    assert _drew(control, FRAG)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_misspelt_render_pipeline_tag_alone_is_refused_naming_file_and_line(tmp_path, language):
    """With no other SubShader and FallBack Off nothing runs (Unity draws its error shader): the
    refusal names the shader's file, the line the tag is written on (the Tags block's second line),
    the tag and the spelling it resembles. Control: a tag unlike any pipeline's gets no such hint."""
    with pytest.raises(PbrlabError) as refused:
        _urp(tmp_path, language, tag="UniversalPipelien")
    line = _URP.split("\n").index('               "RenderPipeline" = "%(tag)s" }') + 1
    message = str(refused.value)
    assert (f'{tmp_path / "t.shader"}:{line}: SubShader 1 is tagged "RenderPipeline" = "UniversalPipelien", '
            "and the Universal Render Pipeline runs only a SubShader tagged") in message
    assert '"UniversalPipelien" looks like a misspelling of "UniversalPipeline"' in message
    with pytest.raises(PbrlabError) as other:
        _urp(tmp_path, language, tag="HDRenderPipeline")
    assert f'{line}: SubShader 1 is tagged "RenderPipeline" = "HDRenderPipeline"' in str(other.value)
    assert "misspelling" not in str(other.value)
