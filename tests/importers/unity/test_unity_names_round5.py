"""Unity names and ShaderLab forms an unseen built-in sample found missing (session 42, 234
vertex/fragment shaders of four public repositories): UnityCG.cginc's UNITY_SAMPLE_DEPTH and
TransformViewToProjection, ``ZTest On``, a Blend whose factors continue on the next line, and a
Float property over a float4 uniform. Each against a float64 value, with a control.

Readback: the corpus scene (a UV sphere, rgba32f target), the fragment's colour on the pixels
the sphere covers whole.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")

PASS = """
Shader "t/{name}" {{
    Properties {{
{properties}
    }}
    SubShader {{ Pass {{
{state}
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
{globals}
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float4 extra : TEXCOORD1; }};
        v2f vert(appdata_base v) {{
            v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy;
{vertex}
            return o;
        }}
        float4 frag(v2f i) : SV_Target {{
{body}
        }}
        ENDCG
    }} }}
}}
"""


def _shader(tmp_path, name, body, *, properties="", globals_="", vertex="            o.extra = 0;", state=""):
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(PASS.format(name=name, properties=properties, globals=globals_,
                                                vertex=vertex, body=body, state=state)))
    return path


def _render(tmp_path, shader, language):
    return render_scene(parse_scene(corpus.scene_for(shader), "t", tmp_path), language=language).linear


def _covered(image):
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return covered


@pytest.mark.parametrize("language", LANGUAGES)
def test_transform_view_to_projection_is_the_projections_upper_left_block(tmp_path, language):
    """UnityCG.cginc: mul((float2x2)UNITY_MATRIX_P, v) and the 3x3 form. The corpus camera's
    projection (vertical field of view 40°, square): its upper-left 2x2 is diag(f, f),
    f = 1 / tan(20°); z of the 3x3 form is -(far + near) / (far - near) times v.z, which depends
    on the frame's planes: checked against the 2x2 form's x (its first row is (f, 0, 0))."""
    shader = _shader(tmp_path, "tvp", "            return float4(TransformViewToProjection(float2(0.1, 0.2)), "
                                      "TransformViewToProjection(float3(0.25, 0, 0)).x, 1);")
    image = _render(tmp_path, shader, language)
    f = 1.0 / math.tan(math.radians(20.0))
    expected = np.array([0.1 * f, 0.2 * f, 0.25 * f])
    got = image[_covered(image)][:, :3].astype(np.float64)
    # float32 in the fragment stage: the projection's entries (f from tan in float64, rounded) and
    # one product each: a few ulps (6e-8) of values below 1, so 1e-6 holds with room (a varying's
    # perspective interpolation, avoided here, adds ~1.5e-6 relative)
    assert np.max(np.abs(got - expected)) < 1e-6, np.max(np.abs(got - expected))


@pytest.mark.parametrize("language", LANGUAGES)
def test_unity_sample_depth_is_the_texels_red_channel(tmp_path, language):
    shader = _shader(tmp_path, "usd", "            float4 t = float4(0.75, 0.5, 0.25, 1);\n"
                                      "            return float4(UNITY_SAMPLE_DEPTH(t), 0, 0, 1);")
    image = _render(tmp_path, shader, language)
    got = image[_covered(image)][:, :3]
    assert np.array_equal(got, np.broadcast_to([0.75, 0.0, 0.0], got.shape))


@pytest.mark.parametrize("language", LANGUAGES)
def test_ztest_on_is_the_default_depth_test(tmp_path, language):
    """``ZTest On`` draws as ``ZTest LEqual`` (a note says so); the control: ``ZTest Greater``
    against the cleared depth draws nothing."""
    body = "            return float4(0.5, 0.25, 0.125, 1);"
    on = _render(tmp_path, _shader(tmp_path, "zon", body, state="        ZTest On"), language)
    default = _render(tmp_path, _shader(tmp_path, "zdef", body), language)
    greater = _render(tmp_path, _shader(tmp_path, "zgt", body, state="        ZTest Greater"), language)
    assert np.array_equal(on, default)
    assert greater[..., 3].max() == 0.0 or not np.array_equal(greater, default)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_blend_whose_factors_continue_on_the_next_line(tmp_path, language):
    """``Blend SrcAlpha`` / ``OneMinusSrcAlpha`` on two lines is the one command (refused before:
    "expected Off or two (or four) of ..."); it blends as the one-line form does."""
    body = "            return float4(0.5, 0.25, 0.125, 0.5);"
    split = _render(tmp_path, _shader(tmp_path, "bsplit", body, state="        Blend SrcAlpha\n        OneMinusSrcAlpha"), language)
    one = _render(tmp_path, _shader(tmp_path, "bone", body, state="        Blend SrcAlpha OneMinusSrcAlpha"), language)
    off = _render(tmp_path, _shader(tmp_path, "boff", body), language)
    assert np.array_equal(split, one)
    assert not np.array_equal(one, off)  # control: the blend changes the image


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_float_property_over_a_float4_uniform_fills_every_component(tmp_path, language):
    """``_color ("Color Filter", Float) = 0.25`` read as ``float4 _color``: refused before (a
    script sets it with SetColor in Unity); the value promoted to every component, with a note."""
    shader = _shader(tmp_path, "fvec", "            return float4(_color.rgb, 1);",
                     properties='        _color ("Color Filter", Float) = 0.25', globals_="        float4 _color;")
    with pytest.warns(Warning, match="_color.*every component"):
        image = _render(tmp_path, shader, language)
    got = image[_covered(image)][:, :3]
    assert np.array_equal(got, np.broadcast_to([0.25, 0.25, 0.25], got.shape))


@pytest.mark.parametrize("language", LANGUAGES)
def test_fog_colour_is_render_settings_default_and_stereo_helpers_are_the_identity(tmp_path, language):
    """unity_FogColor: RenderSettings.fogColor's default, (0.5, 0.5, 0.5, 1) (pbrlab draws no fog);
    UnityStereoScreenSpaceUVAdjust (one eye): the coordinates as given, whatever the scale/offset."""
    body = ("            float2 uv = UnityStereoScreenSpaceUVAdjust(float2(0.25, 0.75), float4(0.5, 0.5, 0.5, 0));\n"
            "            return float4(unity_FogColor.r * uv.x, unity_FogColor.g * uv.y, unity_FogColor.a * 0.125, 1);")
    image = _render(tmp_path, _shader(tmp_path, "fog", body), language)
    got = image[_covered(image)][:, :3]
    assert np.array_equal(got, np.broadcast_to([0.125, 0.375, 0.125], got.shape))


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_array_of_vectors_from_a_flat_list_of_numbers(tmp_path, language):
    """``float2 taps[2] = { 0.25, 0.5, 0.125, 0.75 };``: HLSL fills the components in order (FXC
    takes it; glslang and GLSL refused: "array constructor must have exactly 2 parameters");
    the control is the order: a transposed reading would give (0.75, 0.125, 0.5)."""
    body = ("            float2 taps[2] =\n            {\n                0.25, 0.5,\n                0.125, 0.75\n            };\n"
            "            return float4(taps[0].x + taps[1].x, taps[0].y, taps[1].y, 1);")
    image = _render(tmp_path, _shader(tmp_path, "flat", body), language)
    got = image[_covered(image)][:, :3]
    assert np.array_equal(got, np.broadcast_to([0.375, 0.5, 0.75], got.shape))


@pytest.mark.parametrize("language", LANGUAGES)
def test_texture_matrices_are_the_identity_and_multiply_uv_applies_one(tmp_path, language):
    """UNITY_MATRIX_TEXTURE0..3 (the fixed-function texture matrices: the identity where no
    SetTexture Matrix sets one) and UnityCG's MultiplyUV(mat, uv) = mul(mat, (u, v, 0, 0)).xy: the
    identity keeps (0.25, 0.75); the control, a matrix of 0.5 on its diagonal, halves it."""
    body = ("            float2 a = MultiplyUV(UNITY_MATRIX_TEXTURE0, float2(0.25, 0.75));\n"
            "            float2 b = MultiplyUV(float4x4(0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1), float2(0.25, 0.75));\n"
            "            return float4(a, b.x + b.y, 1);")
    image = _render(tmp_path, _shader(tmp_path, "texmat", body), language)
    got = image[_covered(image)][:, :3]
    assert np.array_equal(got, np.broadcast_to([0.25, 0.75, 0.5], got.shape))
