"""The GLSL port's reading of a URP program's texture objects and stage signatures (issue 34).

- A texture declared with Core RP's macros (``TEXTURE2D(_Tex); SAMPLER(sampler_Tex);``, which
  Core RP's API/D3D11.hlsl expands to ``Texture2D _Tex; SamplerState sampler_Tex;``) sampled
  through its method ``_Tex.Sample(sampler_Tex, uv)`` (Microsoft's HLSL reference,
  "Texture2D.Sample"), here in a product in the return; a ``uniform``-qualified object too.
- A fragment input whose type is an object-like #define's alias of the struct
  (``#define MY_V2F Varyings`` then ``float4 frag(MY_V2F IN)``): the preprocessor's text.

Scene: the corpus scene's UV sphere; the pass returns a constant, so every covered pixel is
checked in both languages.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.foundation.images import write_png
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import parse_pass, texture_methods
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
# The texel is (255, 0, 255): 1 and 0 in either colour space (sRGB decodes 0 and 1 to
# themselves), times _Scale = 0.25, a power of two: every value is exact in float32, so the
# bound is only the filter's rounding of four identical texels, a few float32 ulps of 1.
EXACT = 8 * 2.0 ** -24
TEXEL = np.array([1.0, 0.0, 1.0])
SCALE = 0.25

PASS = """
Shader "t/{name}" {{
    Properties {{ _Tex ("Tex", 2D) = "white" {{}} _Scale ("Scale", Float) = 0.25 }}
    SubShader {{
        Tags {{ "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }}
        Pass {{
            Tags {{ "LightMode" = "UniversalForward" }}
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            {declare}
            float _Scale;
            struct Attributes {{ float4 positionOS : POSITION; float2 uv : TEXCOORD0; }};
            struct Varyings {{ float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; float4 tint : TEXCOORD1; }};
            #define MY_V2F Varyings
            Varyings vert(Attributes IN) {{
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.uv = IN.uv;
                OUT.tint = float4(0.25, 0.5, 0.75, 1.0);
                return OUT;
            }}
            float4 frag({input} IN) : SV_Target {{
                {body}
            }}
            ENDHLSL
        }}
    }}
}}
"""


def _render(tmp_path, language, declare="", body="return IN.tint;", input="Varyings"):
    shader = tmp_path / "t.shader"
    shader.write_text(textwrap.dedent(PASS.format(name="t", declare=declare, body=body, input=input)))
    texture = tmp_path / "magenta.png"
    write_png(texture, np.tile(np.array([255, 0, 255, 255], np.uint8), (8, 8, 1)))
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_Tex": {"path": str(texture)}}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return image[covered, :3]


SAMPLED = "return _Tex.Sample(sampler_Tex, IN.uv) * _Scale;"
MACROS = ["TEXTURE2D(_Tex); SAMPLER(sampler_Tex);", "TEXTURE2D_X(_Tex); SAMPLER(sampler_Tex);"]


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("declare", MACROS + ["uniform Texture2D _Tex; uniform SamplerState sampler_Tex;"])
def test_sample_method_of_a_macro_declared_texture(tmp_path, language, declare):
    """Texture2D.Sample of the material's texture times _Scale: the texel times 0.25 at every
    pixel; control: the material's _Scale changed changes it (the product is read)."""
    got = _render(tmp_path, language, declare, SAMPLED)
    assert np.mean(np.abs(got - TEXEL * SCALE).max(axis=-1) > EXACT) == 0.0
    doubled = _render(tmp_path, language, declare, SAMPLED.replace("_Scale", "(2.0 * _Scale)"))
    assert np.mean(np.abs(doubled - TEXEL * 2 * SCALE).max(axis=-1) > EXACT) == 0.0


@pytest.mark.parametrize("declare", MACROS)
def test_control_without_the_macro_declarations_the_port_refuses(tmp_path, monkeypatch, declare):
    """Control: the GLSL port without the Core RP declarations read as texture objects is the
    old refusal (GLSL has no Sample method)."""
    monkeypatch.setattr(texture_methods, "_MACRO_DECLARATION", texture_methods.re.compile(r"(?!)"))
    with pytest.raises(PbrlabError, match="Sample"):
        _render(tmp_path, "glsl", declare, SAMPLED)


@pytest.mark.parametrize("language", LANGUAGES)
def test_fragment_input_typed_by_a_define_alias(tmp_path, language):
    """``float4 frag(MY_V2F IN)`` after ``#define MY_V2F Varyings``: the varying the vertex stage
    wrote (0.25, 0.5, 0.75), as with the struct's own name; control: the alias left unresolved
    is refused naming the type (it once put a literal None in the entry code)."""
    tint = np.array([0.25, 0.5, 0.75])
    for input in ("MY_V2F", "Varyings"):
        got = _render(tmp_path, language, input=input)
        assert np.mean(np.abs(got - tint).max(axis=-1) > EXACT) == 0.0


def test_control_an_unresolved_alias_is_refused_by_name(tmp_path, monkeypatch):
    monkeypatch.setattr(parse_pass, "_dealiased", lambda found, text: found)
    with pytest.raises(PbrlabError, match="MY_V2F"):
        _render(tmp_path, "glsl", input="MY_V2F")
