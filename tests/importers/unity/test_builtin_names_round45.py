"""Built-in names Unity gives a vertex/fragment CGPROGRAM that pbrlab refused (session 45's
samples): UnityCG.cginc's whole family of pi constants (UNITY_HALF_PI, UNITY_FOUR_PI, ...),
HLSLSupport.cginc's UNITY_VPOS_TYPE in a program that includes nothing (Unity includes
HLSLSupport.cginc in every CGPROGRAM), UnityShaderVariables.cginc's older vertex-light colours
unity_LightColor0..3 and the second reflection probe unity_SpecCube1* (with one reflection
source Unity's probe-0 weight unity_SpecCube0_BoxMin.w is 1: a blend reads probe 0)."""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

PASS = textwrap.dedent("""\
    Shader "Test/Round45Names"
    {
        SubShader
        {
            Pass
            {
                %(tags)s
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                %(include)s
                struct v2f { float4 pos : SV_POSITION; float3 col : TEXCOORD0; float3 dir : TEXCOORD1; };
                v2f vert(float4 p : POSITION, float3 n : NORMAL)
                {
                    v2f o;
                    o.pos = mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, p));
                    o.col = %(vertex)s;
                    o.dir = normalize(mul((float3x3)unity_ObjectToWorld, n));
                    return o;
                }
                %(fragment)s
                ENDCG
            }
        }
    }
    """)


def _shader(fragment, vertex="float3(0, 0, 0)", include="", tags=""):
    return PASS % {"fragment": fragment, "vertex": vertex, "include": include, "tags": tags}


def _run(tmp_path, text, language):
    path = tmp_path / "n.shader"
    path.write_text(text)
    return corpus.run_shader(path, language)


def _covered(result):
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    return np.asarray(result.image, np.float64)[covered][:, :3]


# -- UnityCG.cginc's pi family ---------------------------------------------------------------------
# Each constant scaled by a power of two (exact in float32) to pi / 4 or 1 / pi.
PI_QUARTERS = "float4(UNITY_HALF_PI / 2.0, UNITY_FOUR_PI / 16.0, UNITY_TWO_PI / 8.0, 1)"
INV_PIS = "float4(UNITY_INV_HALF_PI / 2.0, UNITY_INV_TWO_PI * 2.0, UNITY_INV_FOUR_PI * 4.0, 1)"
PI_AND_INVERSE = "float4(UNITY_PI / 4.0, UNITY_INV_PI, 0.5, 1)"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("returned, expected", [
    (PI_QUARTERS, [math.pi / 4] * 3),
    (INV_PIS, [1 / math.pi] * 3),
    (PI_AND_INVERSE, [math.pi / 4, 1 / math.pi, 0.5]),
])
def test_the_pi_constants_are_pis_multiples_and_reciprocals(tmp_path, language, returned, expected):
    """Against float64 pi: the 12-digit literal (relative error < 1e-11), its rounding to
    float32 and the one exact power-of-two scaling leave each within half an ulp of float32,
    2^-24 relative; the stored float32 colour rounds once more: 2^-23 in all."""
    include = '#include "UnityCG.cginc"'
    rgb = _covered(_run(tmp_path, _shader(f"float4 frag(v2f i) : SV_Target {{ return {returned}; }}", include=include), language))
    want = np.asarray(expected, np.float64)
    assert np.all(np.abs(rgb - want) <= 2.0 ** -23 * want)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_a_constant_unity_does_not_name_is_refused(tmp_path, language):
    """A pi multiple UnityCG.cginc lacks (UNITY_THIRD_PI) is refused naming it; and a swapped
    constant (UNITY_PI for UNITY_HALF_PI) is caught by the bound above (pi/2 against pi/4)."""
    result = _run(tmp_path, _shader("float4 frag(v2f i) : SV_Target { return float4(UNITY_THIRD_PI, 0, 0, 1); }"), language)
    assert result.status == "refused" and "UNITY_THIRD_PI" in result.message, result.message
    swapped = _covered(_run(tmp_path, _shader(
        f"float4 frag(v2f i) : SV_Target {{ return {PI_QUARTERS.replace('UNITY_HALF_PI', 'UNITY_PI')}; }}"), language))
    assert np.all(np.abs(swapped[:, 0] - math.pi / 2) <= 2.0 ** -23 * math.pi)


# -- HLSLSupport.cginc's UNITY_VPOS_TYPE, no include -----------------------------------------------
VPOS = "float4 frag(v2f i, UNITY_VPOS_TYPE screenPos : VPOS) : SV_Target { return float4(frac(screenPos.xy / 64.0), 0, 1); }"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("include", ["", '#include "UnityCG.cginc"'])
def test_vpos_type_needs_no_include_and_is_the_window_position(tmp_path, language, include):
    """VPOS is the pixel centre's window position (x + 0.5 from the left edge): red in each
    covered column c is frac((c + 0.5) / 64), exact in float32 (a short binary fraction)."""
    result = _run(tmp_path, _shader(VPOS, include=include), language)
    assert result.status == "rendered", result.message
    image = np.asarray(result.image, np.float64)
    rows, cols = np.nonzero(image[..., 3] == 1.0)
    assert rows.size > 0.1 * image[..., 3].size
    assert np.array_equal(image[rows, cols, 0], ((cols + 0.5) / 64.0) % 1.0)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_a_misspelt_vpos_type_is_refused_at_its_line(tmp_path, language):
    result = _run(tmp_path, _shader(VPOS.replace("UNITY_VPOS_TYPE", "UNITY_VPOS_TYPES")), language)
    assert result.status == "refused" and "n.shader:" in result.message, result.message


# -- UnityShaderVariables.cginc's unity_LightColor0..3 ---------------------------------------------
LIGHT = (0.75, 0.25, 0.5)


def _vertex_lit(tmp_path, language, vertex):
    shader = tmp_path / "v.shader"
    shader.write_text(_shader("float4 frag(v2f i) : SV_Target { return float4(i.col, 1); }", vertex=vertex,
                              tags='Tags { "LightMode" = "Vertex" }'))
    data = corpus.scene_for(shader)
    data.pop("environment", None)
    data["lights"] = [{"type": "directional", "direction": [0.0, 0.0, -1.0], "color": list(LIGHT), "intensity": 1.0}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.1
    return image[covered, :3]


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_the_older_vertex_light_colour_names_are_the_arrays_first_four(tmp_path, language):
    """A Vertex pass's first light is the scene's directional light, its colour (0.75, 0.25,
    0.5) times intensity 1 (short binary fractions: exact); unity_LightColor1 is the absent
    second light's black (the control: the index matters)."""
    first = _vertex_lit(tmp_path, language, "unity_LightColor0")
    assert np.array_equal(first, np.broadcast_to(np.asarray(LIGHT), first.shape))
    second = _vertex_lit(tmp_path, language, "unity_LightColor1")
    assert not second.any()


# -- the second reflection probe -------------------------------------------------------------------
PROBE = "float4 frag(v2f i) : SV_Target { return float4(%s, 1); }"
BLEND = ("lerp(texCUBE(unity_SpecCube1, i.dir).rgb * unity_SpecCube1_HDR.x * (1 + unity_SpecCube1_BoxMin.x * 0), "
         "texCUBE(unity_SpecCube0, i.dir).rgb, unity_SpecCube0_BoxMin.w)")


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_probe_one_is_the_sky_and_a_blend_reads_probe_zero(tmp_path, language):
    """Unity's blend of the two probes, lerp(probe 1, probe 0, unity_SpecCube0_BoxMin.w), with
    weight 1 is probe 0 exactly; probe 1 read alone is the same sky, texel for texel."""
    zero = _covered(_run(tmp_path, _shader(PROBE % "texCUBE(unity_SpecCube0, i.dir).rgb"), language))
    assert zero.max() > 0.0
    one = _covered(_run(tmp_path, _shader(PROBE % "texCUBE(unity_SpecCube1, i.dir).rgb"), language))
    assert np.array_equal(one, zero)
    blend = _covered(_run(tmp_path, _shader(PROBE % BLEND), language))
    assert np.array_equal(blend, zero)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_probe_one_read_elsewhere_differs_and_a_third_probe_is_refused(tmp_path, language):
    zero = _covered(_run(tmp_path, _shader(PROBE % "texCUBE(unity_SpecCube0, i.dir).rgb"), language))
    flipped = _covered(_run(tmp_path, _shader(PROBE % "texCUBE(unity_SpecCube1, -i.dir).rgb"), language))
    assert not np.array_equal(flipped, zero)
    third = _run(tmp_path, _shader(PROBE % "texCUBE(unity_SpecCube2, i.dir).rgb"), language)
    assert third.status == "refused" and "unity_SpecCube2" in third.message, third.message


# -- UnityGlobalIllumination.cginc's ResetUnityGI --------------------------------------------------
RESET = """float4 frag(v2f i) : SV_Target
                {
                    UnityGI gi;
                    gi.light.color = 0.5; gi.light.dir = 0.5; gi.light.ndotl = 0.5;
                    gi.indirect.diffuse = 0.5; gi.indirect.specular = 0.5;
                    %s
                    return float4(gi.light.color.x + gi.light.dir.y + gi.light.ndotl + 0.25, gi.indirect.diffuse.x + gi.indirect.specular.x + 0.125, 0, 1);
                }"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_reset_unity_gi_zeroes_every_member(tmp_path, language):
    """After ResetUnityGI every member is 0: red 0.25 and green 0.125 exactly; the control (the
    reset left out) keeps the 0.5s: 1.75 and 1.125."""
    include = '#include "Lighting.cginc"'
    reset = _covered(_run(tmp_path, _shader(RESET % "ResetUnityGI(gi);", include=include), language))
    assert np.array_equal(reset, np.broadcast_to([0.25, 0.125, 0.0], reset.shape))
    kept = _covered(_run(tmp_path, _shader(RESET % "", include=include), language))
    assert np.array_equal(kept, np.broadcast_to([1.75, 1.125, 0.0], kept.shape))


# -- a Unity name the shader declares again ---------------------------------------------------------
@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_unity_name_declared_again_is_refused_naming_it_and_its_line(tmp_path, language):
    """A Unity 4 shader's own ``sampler2D unity_Lightmap;`` after UnityCG.cginc (which declares it
    since Unity 5, a Texture2D and its sampler: a second declaration of another type, which
    Unity's compiler refuses as well); the control: a name of the shader's own declared twice
    gets the compiler's words, not this reading."""
    include = '#include "UnityCG.cginc"\n                sampler2D unity_Lightmap;'
    result = _run(tmp_path, _shader("float4 frag(v2f i) : SV_Target { return tex2D(unity_Lightmap, float2(0.5, 0.5)); }",
                                    include=include), language)
    assert result.status == "refused", result.message
    assert "n.shader:12: declares unity_Lightmap itself, which Unity's includes declare already" in result.message
    own = _run(tmp_path, _shader("float4 frag(v2f i) : SV_Target { return _Mine; }",
                                 include="float4 _Mine;\n                sampler2D _Mine;"), language)
    assert own.status == "refused" and "declares _Mine itself" not in own.message, own.message


# -- HLSLSupport.cginc's further texture forms, no include -----------------------------------------
FORMS = {
    "lod": ("UNITY_DECLARE_TEX2D(_MainTex);", "UNITY_SAMPLE_TEX2D_LOD(_MainTex, float2(0.5, 0.5), 0)"),
    "sampler_lod": ("UNITY_DECLARE_TEX2D(_Other); UNITY_DECLARE_TEX2D_NOSAMPLER(_MainTex);",
                    "UNITY_SAMPLE_TEX2D_SAMPLER_LOD(_MainTex, _Other, float2(0.5, 0.5), 0)"),
    "half": ("UNITY_DECLARE_TEX2D_HALF(_MainTex);", "UNITY_SAMPLE_TEX2D(_MainTex, float2(0.5, 0.5))"),
    "float": ("UNITY_DECLARE_TEX2D_FLOAT(_MainTex);", "UNITY_SAMPLE_TEX2D(_MainTex, float2(0.5, 0.5))"),
}
TEXTURED = textwrap.dedent("""\
    Shader "Test/Round45Forms"
    {
        Properties { _MainTex ("T", 2D) = "%(default)s" {} _Other ("O", 2D) = "black" {} }
        SubShader
        {
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                %(declare)s
                float4 vert(float4 p : POSITION) : SV_POSITION { return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, p)); }
                float4 frag() : SV_Target { return float4(%(read)s.rgb * float3(0.75, 0.25, 0.5), 1); }
                ENDCG
            }
        }
    }
    """)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("form", sorted(FORMS))
def test_further_texture_forms_need_no_include(tmp_path, language, form):
    """The texture the form names is read: "white" times the constant is (0.75, 0.25, 0.5)
    exactly; the control, "black", is black (and _Other, black, is not what the sampler form reads)."""
    declare, read = FORMS[form]
    for default, want in (("white", [0.75, 0.25, 0.5]), ("black", [0.0, 0.0, 0.0])):
        rgb = _covered(_run(tmp_path, TEXTURED % {"default": default, "declare": declare, "read": read}, language))
        assert np.array_equal(rgb, np.broadcast_to(want, rgb.shape)), (default, rgb[:2])


# (form, the plain read it equals: a level-0 read against the level-0 read, the others against the
# implicit level's)
CUBE_FORMS = (("UNITY_SAMPLE_TEXCUBE_SAMPLER(_D, _C, i.dir)", "UNITY_SAMPLE_TEXCUBE(_D, i.dir)"),
              ("UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(_D, _C, i.dir, 0)", "UNITY_SAMPLE_TEXCUBE_LOD(_D, i.dir, 0)"),
              ("f(UNITY_PASS_TEXCUBE(_D), i.dir)", "UNITY_SAMPLE_TEXCUBE(_D, i.dir)"))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_cube_forms_read_the_cube_they_name(tmp_path, language):
    """A cube declared without a sampler and read with another's, or passed to a function
    (UNITY_ARGS_TEXCUBE): the same texels as texCUBE of that cube (both the scene's sky here, the
    unset cube's default), and not black."""
    declare = ("UNITY_DECLARE_TEXCUBE(_C); UNITY_DECLARE_TEXCUBE_NOSAMPLER(_D);\n"
               "                float4 f(UNITY_ARGS_TEXCUBE(c), float3 d) { return UNITY_SAMPLE_TEXCUBE(c, d); }")
    for form, reference in CUBE_FORMS:
        plain = _covered(_run(tmp_path, _shader(PROBE % f"{reference}.rgb", include=declare), language))
        assert plain.max() > 0.0
        rgb = _covered(_run(tmp_path, _shader(PROBE % f"{form}.rgb", include=declare), language))
        assert np.array_equal(rgb, plain), form
    flipped = _covered(_run(tmp_path, _shader(PROBE % "f(UNITY_PASS_TEXCUBE(_D), -i.dir).rgb", include=declare), language))
    assert not np.array_equal(flipped, plain)
