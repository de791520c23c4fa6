"""Built-in pipeline names, includes and keywords a seen sample found missing (session 43):
an include written in another letter case (Unity's ``unityCG.cginc``, the project's own file),
a keyword set without ``_`` drawing its first keyword, HLSLSupport.cginc's UNITY_SAMPLE_1CHANNEL
and clip-plane values, and the forward base pass's four vertex point lights (Shade4PointLights).
Each against a float64 value, with a control.

Each pass is drawn on the corpus scene's sphere into its rgba32f target; a check reads the
colour at every pixel the sphere covers whole (alpha 1), where the fragment's constant shows.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("hlsl", "glsl")  # HLSL as written, then the GLSL port

PASS = """
Shader "t/{name}" {{
    Properties {{
{properties}
    }}
    SubShader {{ Pass {{
        Tags {{ "LightMode" = "{light_mode}" }}
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
{pragmas}
        #include "{include}"
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
        v2f vert(appdata_base v) {{
            v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy;
            return o;
        }}
        float4 frag(v2f i) : SV_Target {{
{body}
        }}
        ENDCG
    }}
{more}
    }}
}}
"""


def _shader(tmp_path, name, body, *, properties="", pragmas="", include="UnityCG.cginc", light_mode="Always", more=""):
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(PASS.format(name=name, properties=properties, pragmas=pragmas, include=include,
                                                light_mode=light_mode, body=body, more=more)))
    return path


def _render(tmp_path, shader, language, keywords=None, lights=None):
    scene = corpus.scene_for(shader)
    if keywords is not None:
        scene["materials"]["m"]["keywords"] = keywords
    if lights is not None:
        scene["lights"] = lights
    return render_scene(parse_scene(scene, "t", tmp_path), language=language).linear


def _colour(image):
    """The one colour of the covered pixels (every one the same: the fragments return constants)."""
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    got = image[covered][:, :3].astype(np.float64)
    return got


# -- includes in another letter case ----------------------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_unity_include_in_another_case_is_read_as_unitys(tmp_path, language):
    """``#include "unityCG.cginc"`` compiles in Unity on Windows and macOS (their file systems
    ignore case): read as UnityCG.cginc, with a warning; the pass's appdata_base and
    UnityObjectToClipPos come from it. Control: a name no file matches in any case is refused."""
    body = "            return float4(0.25, 0.5, 0.75, 1);"
    with pytest.warns(UserWarning, match=r'#include "unityCG.cginc" read as UnityCG.cginc'):
        image = _render(tmp_path, _shader(tmp_path, "lower", body, include="unityCG.cginc"), language)
    got = _colour(image)
    assert np.array_equal(got, np.broadcast_to([0.25, 0.5, 0.75], got.shape))
    with pytest.raises(PbrlabError, match=r"unityCGX\.cginc"):
        _render(tmp_path, _shader(tmp_path, "none", body, include="unityCGX.cginc"), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_project_include_in_another_case_is_read(tmp_path, language):
    """The project's own ``Inc/MyColour.cginc`` included as ``inc/mycolour.CGINC``: read so,
    its colour drawn. Control: two files that differ only in case are refused, naming both."""
    (tmp_path / "Inc").mkdir()
    (tmp_path / "Inc" / "MyColour.cginc").write_text("#include \"UnityCG.cginc\"\n"
                                                     "float4 MyColour() { return float4(0.125, 0.625, 0.375, 1); }\n")
    body = "            return MyColour();"
    with pytest.warns(UserWarning, match=r"read as Inc/MyColour\.cginc"):
        image = _render(tmp_path, _shader(tmp_path, "own", body, include="inc/mycolour.CGINC"), language)
    got = _colour(image)
    assert np.array_equal(got, np.broadcast_to([0.125, 0.625, 0.375], got.shape))
    (tmp_path / "Inc" / "mycolour.cginc").write_text((tmp_path / "Inc" / "MyColour.cginc").read_text())
    with pytest.raises(PbrlabError, match=r"matches Inc/MyColour\.cginc and Inc/mycolour\.cginc ignoring case"):
        _render(tmp_path, _shader(tmp_path, "two", body, include="inc/MYCOLOUR.cginc"), language)


# -- a keyword set without "_" ------------------------------------------------------------------

KEYWORD_BODY = """            #if defined(_TINT_RED)
            return float4(1, 0, 0, 1);
            #elif defined(_TINT_GREEN)
            return float4(0, 1, 0, 1);
            #else
            return float4(0, 0, 1, 1);
            #endif"""


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("directive", ["multi_compile", "shader_feature", "shader_feature_local"])
def test_a_set_without_underscore_draws_its_first_keyword(tmp_path, language, directive):
    """Unity's manual ("Shader variants and keywords"): a set without ``_`` has no variant with
    all its keywords off; with none enabled, the first keyword's variant is drawn. Controls: the
    material enabling the second draws it; a set with ``_`` draws the all-off variant."""
    first = _shader(tmp_path, "first", KEYWORD_BODY, pragmas=f"        #pragma {directive} _TINT_RED _TINT_GREEN")
    got = _colour(_render(tmp_path, first, language))
    assert np.array_equal(got, np.broadcast_to([1.0, 0.0, 0.0], got.shape))
    got = _colour(_render(tmp_path, first, language, keywords=["_TINT_GREEN"]))
    assert np.array_equal(got, np.broadcast_to([0.0, 1.0, 0.0], got.shape))
    off = _shader(tmp_path, "off", KEYWORD_BODY, pragmas=f"        #pragma {directive} _ _TINT_RED _TINT_GREEN")
    got = _colour(_render(tmp_path, off, language))
    assert np.array_equal(got, np.broadcast_to([0.0, 0.0, 1.0], got.shape))


# -- HLSLSupport.cginc's names ------------------------------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_sample_1channel_reads_the_texels_alpha(tmp_path, language):
    """UNITY_SAMPLE_1CHANNEL(tex, uv) is the texel's alpha (HLSLSupport.cginc, since Unity 4.0).
    Unity's "bump" default texel is (0.5, 0.5, 1, 1) here: alpha 1, red 0.5. Control: its red
    channel read beside it differs."""
    shader = _shader(tmp_path, "one", "            return float4(UNITY_SAMPLE_1CHANNEL(_Tex, i.uv), "
                                      "tex2D(_Tex, i.uv).r, 0, 1);",
                     properties='        _Tex ("t", 2D) = "bump" {}', pragmas="        sampler2D _Tex;")
    got = _colour(_render(tmp_path, shader, language))
    # 8-bit texels: 0.5 is stored as 128/255 or 127/255 (half a step of 1/255 either way)
    assert np.all(got[:, 0] == 1.0)
    assert np.all(np.abs(got[:, 1] - 0.5) <= 0.5 / 255 + 1e-7)


@pytest.mark.parametrize("language", LANGUAGES)
def test_non_stereo_screen_position_is_unitys_formula(tmp_path, language):
    """UnityCG.cginc's ComputeNonStereoScreenPos(pos): xy = (pos.x, pos.y * _ProjectionParams.x) / 2
    + pos.w / 2, zw = pos.zw (one eye: the same as ComputeScreenPos). float64 at pos = (0.2, -0.4,
    0.5, 1) with _ProjectionParams.x = 1 (GL: no flip): (0.6, 0.3, 0.5); the third channel is the
    flip sign itself, a control that the formula read it. Exact: halves and sums of dyadic values."""
    body = ("            float4 s = ComputeNonStereoScreenPos(float4(0.2, -0.4, 0.5, 1));\n"
            "            return float4(s.xy, s.z * _ProjectionParams.x, 1);")
    got = _colour(_render(tmp_path, _shader(tmp_path, "nonstereo", body), language))
    want = np.array([0.5 * 0.2 + 0.5, 0.5 * -0.4 * 1.0 + 0.5, 0.5], np.float64)
    assert np.all(np.abs(got - want) <= 2 ** -23)


@pytest.mark.parametrize("language", LANGUAGES)
def test_clip_values_are_where_the_projection_puts_the_planes(tmp_path, language):
    """UNITY_NEAR_CLIP_VALUE and UNITY_RAW_FAR_CLIP_VALUE are the clip-space z / w of the camera's
    near and far planes (HLSLSupport.cginc, per graphics API): pbrlab's projection
    (UNITY_MATRIX_P, OpenGL's clip space) puts a view point at depth near (_ProjectionParams.y)
    and far (.z) there. The fragment writes 0.5 + (z/w - the value) for each: 0.5 where they
    agree (a control: Direct3D's near value, 0, is 1 away). Bound: z/w = (a n + b) / n from
    float32 P entries a = -(f+n)/(f-n), b = -2fn/(f-n), |a n| and |b| at most 2f: a few ulps of
    2f / n; the corpus camera's f / n is below 1e4 (0.3 .. far), so 1e4 * 2 * 4 * 2^-24 < 5e-3."""
    body = """            float4 nearClip = mul(UNITY_MATRIX_P, float4(0, 0, -_ProjectionParams.y, 1));
            float4 farClip = mul(UNITY_MATRIX_P, float4(0, 0, -_ProjectionParams.z, 1));
            return float4(0.5 + nearClip.z / nearClip.w - UNITY_NEAR_CLIP_VALUE,
                          0.5 + farClip.z / farClip.w - UNITY_RAW_FAR_CLIP_VALUE, 0.5 + UNITY_NEAR_CLIP_VALUE, 1);"""
    got = _colour(_render(tmp_path, _shader(tmp_path, "clip", body), language))
    assert np.all(np.abs(got[:, :2] - 0.5) <= 5e-3)
    assert np.all(got[:, 2] == -0.5)  # GL's -1, not Direct3D's 0 (0.5) or reversed Z's 1 (1.5)


# -- the forward base pass's four vertex point lights ---------------------------------------------

FOUR_BODY = """            float3 p = float3(0.25, -0.5, 0.75);
            float3 n = normalize(float3(0.2, 0.3, 1.0));
            float3 c = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
                unity_4LightAtten0, p, n);
            return float4(c, 1);"""
ADD_PASS = """    Pass { Tags { "LightMode" = "ForwardAdd" } Blend One One
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
        float4 frag() : SV_Target { return 0; }
        ENDCG
    }"""
LIGHTS = [{"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0},
          {"type": "point", "position": [1.5, 1.0, 2.0], "color": [1, 0.5, 0.25], "intensity": 2.0, "range": 10},
          {"type": "point", "position": [-1.0, 2.0, 1.5], "color": [0.5, 1, 1], "intensity": 3.0}]


def shade4_reference(p, n, lights) -> np.ndarray:
    """UnityCG.cginc's Shade4PointLights in float64: per light, colour * max(0, n . l) /
    (1 + d^2 * atten), d^2 = max(|light - p|^2, 1e-6), atten Unity's 25 / range^2 (1 without a
    range: generate_pass._four_lights)."""
    p, n = np.asarray(p, np.float64), np.asarray(n, np.float64)
    n = n / np.linalg.norm(n)
    out = np.zeros(3)
    for light in lights:
        to = np.asarray(light["position"], np.float64) - p
        d2 = max(float(to @ to), 1e-6)
        atten = 25.0 / light["range"] ** 2 if "range" in light else 1.0
        cosine = max(0.0, float(to @ n) / math.sqrt(d2))
        out += np.asarray(light["color"], np.float64) * light["intensity"] * cosine / (1.0 + d2 * atten)
    return out


@pytest.mark.parametrize("language", LANGUAGES)
def test_four_vertex_point_lights_of_a_base_pass(tmp_path, language):
    """A ForwardBase pass of a shader without a ForwardAdd pass sees the scene's point lights as
    Unity's four vertex lights: Shade4PointLights at a fixed point and normal against float64.
    Bound: float32 evaluation of a sum of two terms of size <= 3, a few ulps each: 1e-5.
    Controls: the same pass in a shader with a ForwardAdd pass (the point lights drawn per pixel
    there) sees none (0); the scene without point lights, none."""
    shader = _shader(tmp_path, "four", FOUR_BODY, light_mode="ForwardBase")
    got = _colour(_render(tmp_path, shader, language, lights=LIGHTS))
    want = shade4_reference([0.25, -0.5, 0.75], [0.2, 0.3, 1.0], LIGHTS[1:])
    assert want.min() > 0.05
    assert np.all(np.abs(got - want) <= 1e-5)
    with_add = _shader(tmp_path, "add", FOUR_BODY, light_mode="ForwardBase", more=ADD_PASS)
    got = _colour(_render(tmp_path, with_add, language, lights=LIGHTS))
    assert np.all(got == 0.0)
    got = _colour(_render(tmp_path, shader, language, lights=LIGHTS[:1]))
    assert np.all(got == 0.0)


# -- refusals that name the shader's own missing piece ---------------------------------------------

_OWN_INCLUDE = """Shader "t/own" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        #include "Noise.cginc"
        ENDCG
    } }
FALLBACK
}
"""


def test_a_missing_include_names_a_copy_elsewhere_in_the_repository(tmp_path):
    """An include no folder Unity searches holds, of which the repository keeps a copy outside the
    Unity project (an author's copy of a Unity install's CGIncludes): still refused (Unity would
    not find it), naming the copy. Control: without the copy, no such hint."""
    from pbrlab.importers.unity import parse
    from pbrlab.importers.unity.source_text import UnityShaderError
    shader_dir = tmp_path / "Repo" / "Project" / "Assets" / "Shaders"
    shader_dir.mkdir(parents=True)
    path = shader_dir / "own.shader"
    path.write_text(_OWN_INCLUDE.replace("FALLBACK", ""))
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(path)
    assert f"{path}:7: uses Noise.cginc" in str(info.value) and "lies at" not in str(info.value)
    (tmp_path / "Repo" / "includes").mkdir()
    (tmp_path / "Repo" / "includes" / "Noise.cginc").write_text("float noise(float x) { return x; }\n")
    with pytest.raises(UnityShaderError, match=r"a file of that name lies at \S*Repo/includes/Noise\.cginc"):
        parse.read_shader(path)


def test_a_shader_with_one_subshader_and_no_fallback_gives_its_own_reason_first(tmp_path):
    """One SubShader that cannot run (a missing include) and a Fallback pbrlab does not have: the
    refusal begins with this shader's file, line and reason, then says the Fallback is missing.
    Control: two SubShaders that cannot run keep "no SubShader can run here" first."""
    from pbrlab.importers.unity import parse
    from pbrlab.importers.unity.source_text import UnityShaderError
    path = tmp_path / "one.shader"
    path.write_text(_OWN_INCLUDE.replace("FALLBACK", 'Fallback "Nowhere/Else"'))
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(path)
    message = str(info.value)
    assert message.startswith(f"{path}:7: uses Noise.cginc")
    assert message.index("uses Noise.cginc") < message.index('Fallback "Nowhere/Else" is a shader pbrlab does not have')
    two = tmp_path / "two.shader"
    sub = _OWN_INCLUDE.split("    SubShader", 1)[1].split("FALLBACK")[0]
    two.write_text('Shader "t/two" {\n    SubShader' + sub + "    SubShader" + sub + 'Fallback "Nowhere/Else"\n}\n')
    with pytest.raises(UnityShaderError, match=r"no SubShader can run here \(SubShader 1"):
        parse.read_shader(two)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_void_vertex_function_is_refused_as_drawing_nothing(tmp_path, language):
    """``void vert() {}`` (a tutorial's empty pass): Unity compiles it, but no vertex is placed,
    so nothing is drawn; refused naming the file and the pragma's line and saying so. Control:
    a vertex function returning its position renders (the other tests here)."""
    path = tmp_path / "empty.shader"
    path.write_text('Shader "t/empty" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n'
                    "void vert() {}\nvoid frag() {}\nENDCG\n} } }\n")
    with pytest.raises(PbrlabError, match=r"vert\(\) writes no SV_POSITION.*returns void and has no out parameter"):
        _render(tmp_path, path, language)


# -- a variable assigned in its own initialiser; a compute buffer of the program's include -------

@pytest.mark.parametrize("language", LANGUAGES)
def test_a_variable_assigned_in_its_own_initialiser(tmp_path, language):
    """``float4 c = cond ? c = a : b;`` (a tutorial's): FXC's C scope makes ``c`` the variable
    being declared, so it is a, or b (self_initialisers.py); glslang and GLSL refused ``c`` as
    undeclared. Control: the property flipping the condition draws the other operand."""
    body = ("            float4 c = (_Flag > 0.5) ? c = float4(0.25, 0.5, 0.125, 1) * 2 : float4(0.75, 0.75, 0.75, 1);\n"
            "            return c;")
    shader = _shader(tmp_path, "selfinit", body, properties='        _Flag ("f", Float) = 1',
                     pragmas="        float _Flag;")
    got = _colour(_render(tmp_path, shader, language))
    assert np.array_equal(got, np.broadcast_to([0.5, 1.0, 0.25], got.shape))
    scene = corpus.scene_for(shader)
    scene["materials"]["m"]["properties"] = {"_Flag": 0.0}
    got = _colour(render_scene(parse_scene(scene, "t", tmp_path), language=language).linear)
    assert np.array_equal(got, np.broadcast_to([0.75, 0.75, 0.75], got.shape))


def test_a_compute_buffer_an_include_declares_is_refused_at_its_line(tmp_path):
    """A procedural draw's buffer declared in the program's own include and read by the pass:
    refused naming the include file and the declaration's line (the program's own declaration
    was already). Control: the include's buffer that the drawn pass does not read is no refusal."""
    from pbrlab.importers.unity import parse
    from pbrlab.importers.unity.source_text import UnityShaderError
    (tmp_path / "Buf.hlsl").write_text("#include \"UnityCG.cginc\"\n// the generated triangles\n"
                                       "StructuredBuffer<float4> _Data;\n")
    read = _shader(tmp_path, "reads", "            return _Data[0];", include="Buf.hlsl")
    with pytest.raises(UnityShaderError, match=rf"{tmp_path}/Buf\.hlsl:3: reads StructuredBuffer _Data, a compute buffer"):
        parse.read_shader(read)
    unread = _shader(tmp_path, "unread", "            return 1;", include="Buf.hlsl")
    assert parse.read_shader(unread).passes


def test_a_shadow_caster_only_shader_is_refused_as_invisible_in_unity(tmp_path):
    """A shader whose one pass is a ShadowCaster: Unity draws the object only into the shadow
    map, so it shows as its shadow on other objects; the refusal says so. Control: a skipped
    editor pass (not a shadow) gets no such words."""
    from pbrlab.importers.unity import parse
    from pbrlab.importers.unity.source_text import UnityShaderError
    caster = tmp_path / "caster.shader"
    caster.write_text('Shader "t/caster" { SubShader { Pass { Tags { "LightMode" = "ShadowCaster" }\nCGPROGRAM\n'
                      "#pragma vertex vert\n#pragma fragment frag\n#include \"UnityCG.cginc\"\n"
                      "float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }\n"
                      "float4 frag() : SV_Target { return 0; }\nENDCG\n} } }\n")
    with pytest.raises(UnityShaderError, match=r"nothing here draws .*ShadowCaster.*the object itself is invisible"):
        parse.read_shader(caster)
    picking = tmp_path / "picking.shader"
    picking.write_text(caster.read_text().replace('"ShadowCaster"', '"Picking"'))
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(picking)
    assert "nothing here draws" in str(info.value) and "invisible" not in str(info.value)


@pytest.mark.parametrize("language", LANGUAGES)
def test_property_drawers_enable_their_keywords(tmp_path, language):
    """Unity's material inspector enables a drawer's keyword from the property's value
    (MaterialPropertyDrawer): ``[KeywordEnum(Red, Green)] _Tint = 1`` enables _TINT_GREEN, not the
    set's first; ``[Toggle(_HALF)] _Half = 1`` enables _HALF. Controls: the value 0 given in the
    material draws _TINT_RED and no _HALF; a keyword the material names itself wins."""
    body = KEYWORD_BODY.replace("return float4(1, 0, 0, 1);", "return float4(1, 0, 0, 1) * (_HALF_ON_SCALE);") \
        .replace("return float4(0, 1, 0, 1);", "return float4(0, 1, 0, 1) * (_HALF_ON_SCALE);")
    pragmas = ("        #pragma shader_feature _TINT_RED _TINT_GREEN\n        #pragma shader_feature _HALF\n"
               "        #if defined(_HALF)\n        #define _HALF_ON_SCALE 0.5\n        #else\n"
               "        #define _HALF_ON_SCALE 1.0\n        #endif")
    shader = _shader(tmp_path, "drawers", body, pragmas=pragmas,
                     properties='        [KeywordEnum(Red, Green)] _Tint ("t", Float) = 1\n'
                                '        [Toggle(_HALF)] _Half ("h", Float) = 1')
    got = _colour(_render(tmp_path, shader, language))
    assert np.array_equal(got, np.broadcast_to([0.0, 0.5, 0.0], got.shape))
    scene = corpus.scene_for(shader)
    scene["materials"]["m"]["properties"] = {"_Tint": 0, "_Half": 0}
    got = _colour(render_scene(parse_scene(scene, "t", tmp_path), language=language).linear)
    assert np.array_equal(got, np.broadcast_to([1.0, 0.0, 0.0], got.shape))
    got = _colour(_render(tmp_path, shader, language, keywords=["_TINT_RED"]))
    assert np.array_equal(got, np.broadcast_to([0.5, 0.0, 0.0], got.shape))
