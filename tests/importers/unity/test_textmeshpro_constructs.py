"""The forms of Cg that TextMesh Pro's shaders use (TMP_SDF, TMP_SDF-Mobile, TMP_Bitmap, ...: in
nearly every Unity project, copied into Assets/TextMesh Pro) and that the GLSL port or glslang's
HLSL did not take (issue 34, session 41), in a shader of our own written to reproduce each (TMP
is under the Unity Companion License: none of its text is here):

- ``bool raisedBevel = step(1, fmod(_ShaderFlags, 2));`` in TMPro.cginc, whose ``_ShaderFlags``
  TMPro_Properties.cginc declares: the port's type pass, reading one include at a time, cannot
  type it, and GLSL refuses a float given to a bool (cg_types ``bool_of_unknown``);
- the vertex output built by an initialiser list whose last items are under
  ``#if (UNDERLAY_ON | UNDERLAY_INNER)``: a trailing comma where they are compiled out (GLSL
  refuses it: cg_types ``comma_after_directive``), and a condition with C's bitwise ``|``, which
  the model's reader took as true, so the entry points passed a member the variant lacks
  (conditionals.py);
- ``UnpackUV(float)`` given a ``float2``: FXC truncates, glslang's HLSL finds no overload
  (cg_types.fxc_conversions);
- a material's keyword that adds a varying under its ``#if`` (``UNDERLAY_ON``): the model of the
  pass is read with the material's keywords (material.py), so the entry points pass it;
- Unity 2020's ``UIGammaToLinear`` (UnityUI.cginc), which TMP of that version calls.

What a TMP shader draws on the corpus sphere: its font atlas is Unity's default "white", so the
signed distance read from its alpha is 1 everywhere, and the face colour math gives a uniform
colour (TMP_SDF-Mobile's: ``faceColor * saturate(d * scale - bias)``, bias = (0.5 - weight) *
scale - 0.5). Readback as test_cg_dialect_round4.py: the corpus scene's ``linear`` image (the
fragment's colour), on the pixels the sphere covers whole, in both languages.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types, program
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.conditionals import _evaluate
from pbrlab.maths.reference.color import srgb_to_linear
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")

PROPERTIES_CGINC = """
    // the material's properties, declared in an include of their own (as TMPro_Properties.cginc)
    uniform float4 _FaceColor;
    uniform float4 _UnderlayColor;
    uniform float _ShaderFlags;
    uniform float _FaceDilate;
    uniform float _GradientScale;
    uniform float _PackedUV;
    sampler2D _MainTex;
"""

FUNCTIONS_CGINC = """
    // a flag of _ShaderFlags read into a bool (as TMPro.cginc's GetSurfaceNormal): bit 0
    float BevelFactor()
    {
        bool raised = step(1, fmod(_ShaderFlags, 2));
        return raised ? 1.0 : 0.25;
    }
"""

SHADER = """
Shader "t/textmeshpro_face" {
    Properties {
        _MainTex ("Font Atlas", 2D) = "white" {}
        _FaceColor ("Face Color", Color) = (0.75, 0.5, 0.25, 1)
        _UnderlayColor ("Underlay Color", Color) = (0, 0, 0.5, 1)
        _ShaderFlags ("Flags", Float) = {flags}
        _FaceDilate ("Face Dilate", Range(-1, 1)) = -0.5
        _GradientScale ("Gradient Scale", Float) = 5
        _PackedUV ("Packed UV", Float) = {packed}
    }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex VertShader
        #pragma fragment PixShader
        #pragma shader_feature __ UNDERLAY_ON UNDERLAY_INNER
        #include "UnityCG.cginc"
        #include "face_properties.cginc"
        #include "face_functions.cginc"

        struct vertex_t {
            float4 vertex : POSITION;
            fixed4 color : COLOR;
            float2 texcoord0 : TEXCOORD0;
        };

        struct pixel_t {
            float4 vertex : SV_POSITION;
            nointerpolation fixed4 faceColor : COLOR;
            float4 texcoord0 : TEXCOORD0;
            nointerpolation half4 param : TEXCOORD1;
        #if (UNDERLAY_ON | UNDERLAY_INNER)
            nointerpolation float4 texcoord1 : TEXCOORD3;
        #endif
        };

        // TMP's packing of two numbers in one float: x * 4096 + y, each in 1/512 steps
        float2 UnpackUV(float uv)
        {
            float2 output;
            output.x = floor(uv / 4096);
            output.y = uv - 4096 * output.x;
            return output * 0.001953125;
        }

        pixel_t VertShader(vertex_t input)
        {
            float scale = _GradientScale * 0.25;
            float weight = _FaceDilate * 0.5;
            float bias = (0.5 - weight) * scale - 0.5;
            float2 packed = float2(_PackedUV, 7.0);
            float2 unpacked = UnpackUV(packed);
            fixed4 faceColor = input.color * _FaceColor;
            faceColor.rgb *= faceColor.a * unpacked.y;
            pixel_t output = {
                UnityObjectToClipPos(input.vertex),
                faceColor,
                float4(input.texcoord0, 0, 0),
                half4(scale, bias, 0, 0),
            #if (UNDERLAY_ON | UNDERLAY_INNER)
                float4(input.texcoord0, 1, 0),
            #endif
            };
            return output;
        }

        fixed4 PixShader(pixel_t input) : SV_Target
        {
            half d = tex2D(_MainTex, input.texcoord0.xy).a * input.param.x;
            half4 c = input.faceColor * saturate(d - input.param.y);
            c.rgb *= BevelFactor();
        #if UNDERLAY_ON
            c += _UnderlayColor * input.texcoord1.z;
        #endif
            return c;
        }
        ENDCG
    } }
}
"""

FACE = np.array([0.75, 0.5, 0.25])
UNDERLAY = np.array([0.0, 0.0, 0.5])
PACKED = 4096 * 2 + 256   # UnpackUV: (2, 256) / 512 = (0.00390625, 0.5)


def face_colour(flags: float, packed: float = PACKED) -> tuple:
    """float64, TMP_SDF-Mobile's face colour math on a white atlas (distance d = 1):
    (face colour, scale, bias), the pixel being face * saturate(d scale - bias). scale =
    _GradientScale / 4 (this shader's stand-in for TMP's screen-space scale), weight =
    _FaceDilate / 2, bias = (0.5 - weight) scale - 0.5; face = vertex colour (white) *
    _FaceColor * alpha * UnpackUV(x).y, with FXC's truncation: UnpackUV takes the float2's first
    component; times the bevel flag (bit 0 of _ShaderFlags) 1 or 0.25."""
    scale, weight = 5.0 * 0.25, -0.5 * 0.5
    bias = (0.5 - weight) * scale - 0.5
    high = np.floor(packed / 4096)
    unpacked_y = (packed - 4096 * high) * 0.001953125
    bevel = 1.0 if np.fmod(flags, 2) >= 1 else 0.25
    return FACE * 1.0 * unpacked_y * bevel, scale, bias


def _covered(image):
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return covered


def _render(tmp_path, language, flags=1, packed=PACKED, keywords=()):
    """(the shader's render on the pixels the sphere covers whole, the float64 colour)."""
    folder = tmp_path / f"{language}_f{flags}_p{packed}_{'_'.join(keywords)}"
    folder.mkdir()
    (folder / "face_properties.cginc").write_text(textwrap.dedent(PROPERTIES_CGINC))
    (folder / "face_functions.cginc").write_text(textwrap.dedent(FUNCTIONS_CGINC))
    shader = folder / "face.shader"
    shader.write_text(textwrap.dedent(SHADER.replace("{flags}", str(flags)).replace("{packed}", str(packed))))
    data = corpus.scene_for(shader)
    if keywords:
        data["materials"]["m"]["keywords"] = list(keywords)
    image = render_scene(parse_scene(data, "t", folder), language=language).linear
    covered = _covered(image)
    face, scale, bias = face_colour(flags, packed)
    underlay = UNDERLAY if "UNDERLAY_ON" in keywords else np.zeros(3)
    return image[covered, :3], face * np.clip(1.0 * scale - bias, 0, 1) + underlay


# Exact: every value in the shader and the reference is a short binary fraction (0.75 x 0.5 x
# 0.8125, 7 / 512, ...), so each float32 operation is exact; the varyings are nointerpolation (the
# rasteriser's perspective-correct interpolation of a value equal at the three vertices moves it
# by ulps, which no construct here is about), and the white atlas's alpha is 255 / 255 = 1.
EXACT = 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_textmeshpro_face_colour_on_a_white_atlas(tmp_path, language):
    """The face colour (0.75, 0.5, 0.25) x UnpackUV's 0.5 x coverage 0.8125 on every covered
    pixel, to the bit."""
    got, want = _render(tmp_path, language)
    assert np.allclose(want, FACE * 0.5 * 0.8125, rtol=0, atol=1e-15)  # the reference by hand
    assert np.abs(got - want).max() <= EXACT


@pytest.mark.parametrize("language", LANGUAGES)
def test_textmeshpro_constructs_change_the_pixel_as_unity_does(tmp_path, language):
    """Controls, each construct perturbed, each to the bit against its float64 value and apart
    from the default's: _ShaderFlags 2 (bit 0 clear: the bool is false, the bevel factor 0.25);
    the packed float 7 (UnpackUV's y 7 / 512); UNDERLAY_ON (the member under ``#if (A | B)``
    and the initialiser's last item exist, and the underlay colour is added)."""
    base, _ = _render(tmp_path, language)
    for case in (dict(flags=2), dict(packed=7), dict(keywords=("UNDERLAY_ON",))):
        got, want = _render(tmp_path, language, **case)
        assert np.abs(got - want).max() <= EXACT, case
        assert np.abs(got - base).max() > 0.05, case


@pytest.mark.parametrize("patches, language, refusal", [
    # bool_of_unknown, and (since session 44) the sibling includes' globals, which now type
    # _ShaderFlags for TMPro.cginc's port: either types the bool's initialiser
    ([(cg_types._Parser, "bool_of_unknown", lambda self, e, target: None),
      (program, "_structs_and_globals", lambda text: "")], "glsl", "cannot be assigned to variable of type bool"),
    ([(cg_types._Parser, "comma_after_directive", lambda self, comma: None)], "glsl", "syntax error"),
    ([(program, "_fxc_spelled", lambda text, included, srp: text)], "hlsl", "'UnpackUV' : no matching overloaded"),
])
def test_without_each_mend_the_compiler_refuses_as_before(tmp_path, monkeypatch, patches, language, refusal):
    """Control: each mend undone, the shader is refused with the compiler's error the TextMesh
    Pro shaders met (so the renders above are the mends' doing)."""
    for owner, name, replacement in patches:
        monkeypatch.setattr(owner, name, replacement)
    with pytest.raises(PbrlabError, match=refusal):
        _render(tmp_path, language)


def test_bitwise_or_in_a_condition_is_evaluated():
    """``#if (UNDERLAY_ON | UNDERLAY_INNER)``: false without either keyword, true with one; a
    bitwise operator beside a comparison or a ``!`` (C's precedence differs from Python's) is
    beyond the reader (None: taken as true, as before)."""
    assert _evaluate("(UNDERLAY_ON | UNDERLAY_INNER)", {}) is False
    assert _evaluate("(UNDERLAY_ON | UNDERLAY_INNER)", {"UNDERLAY_INNER": 1}) is True
    assert _evaluate("A & B", {"A": 1, "B": 2}) is False
    assert _evaluate("A == 1 | B", {"A": 1}) is None
    assert _evaluate("!A | B", {"A": 1}) is None


def test_argument_truncation_edits_only_wider_arguments_of_the_programs_functions():
    """A float2 given to a float parameter -> ``.x``; as wide as the parameter, an argument of
    unknown type, or a function the program does not define (Unity's, an include's): unchanged."""
    program = textwrap.dedent("""
        float f(float a) { return a; }
        float3 g(float3 v) { return v; }
        float4 main4(float2 p, float3 q) {
            return float4(f(p), g(q).xy, f(p.y)) + f(unknown) + UnityFunction(p);
        }
    """)
    out = cg_types.fxc_conversions(program)
    assert "f(p.x)" in out and "g(q)" in out and "f(p.y)" in out and "f(unknown)" in out
    assert out.replace("f(p.x)", "f(p)", 1) == program


# pow() is exp2(y log2 x): log2's absolute error (< 2^-21 near 1, GLSL 4.60 section 4.7.1) times
# the exponent 2.4 is <= 1.2e-6 relative; the scale and offset before it add two float32
# roundings (1.2e-7): 2e-6 relative.
POW_RELATIVE = 2e-6


@pytest.mark.parametrize("language", LANGUAGES)
def test_ui_gamma_to_linear_is_the_srgb_decode(tmp_path, language):
    """UIGammaToLinear((0.5, 0.02, 1)) = the sRGB decode of each channel (IEC 61966-2-1; the toe's
    linear part for 0.02); control: the encoded value itself is over 0.2 away."""
    shader = tmp_path / "ui_gamma.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/ui_gamma" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            #include "UnityUI.cginc"
            float4 vert(float4 vertex : POSITION) : SV_POSITION { return UnityObjectToClipPos(vertex); }
            fixed4 frag() : SV_Target { return fixed4(UIGammaToLinear(half3(0.5, 0.02, 1.0)), 1); }
            ENDCG
        } } }
    """))
    image = render_scene(parse_scene(corpus.scene_for(shader), "t", tmp_path), language=language).linear
    got = image[_covered(image), :3]
    encoded = np.array([0.5, 0.02, 1.0])
    want = srgb_to_linear(encoded)
    assert (np.abs(got - want) <= POW_RELATIVE * want).all()
    assert np.abs(got - encoded).max() > 0.2
