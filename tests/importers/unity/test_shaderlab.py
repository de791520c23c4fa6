"""ShaderLab as Unity reads it (harness/pbrlab/importers/unity/shaderlab.py, parse.py): SubShader choice,
CGINCLUDE, Pass blocks beside a surface program, Fallback, property syntax, vertex/fragment
passes (generate_pass.py) and Unity's per-light keywords, each through both languages and
checked for what it must show."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from pbrlab.render import renderer as render
from pbrlab import scene
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import UnityShaderError, parse

HERE = Path(__file__).resolve().parent / "shaders"
LANGUAGES = ("hlsl", "glsl")
SIZE = 64


def _scene(surface, properties=None, lights=None, mesh=False, base=HERE, environment=None):
    obj = ({"mesh": {"primitive": "uv_sphere", "radius": 1.0}} if mesh
           else {"sphere": {"center": [0, 0, 0], "radius": 1}})
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [SIZE, SIZE]},
            "lights": lights if lights is not None else
            [{"type": "directional", "direction": [-0.5, -0.3, -1.0], "intensity": 1.0}],
            "environment": environment,
            "materials": {"m": {"surface": str(surface), **({"properties": properties} if properties else {})}},
            "objects": [{**obj, "material": "m"}]}
    return scene.parse_scene(data, "<test>", base)


def _render(surface, language, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return render.render_scene(_scene(surface, **kw), language=language).linear


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("language", LANGUAGES)
def test_second_subshader_runs_with_cginclude_and_loose_property_syntax(language):
    """The first SubShader is fixed-function with a texture matrix (cannot run here), the second's surface program
    takes surf from the CGINCLUDE; _Tint is a 3-component colour bound to a fixed3 and
    Emission = _Tint * _Gain + _Bias exactly (the two other properties share a line)."""
    shader = parse.read_shader(HERE / "layered.shader")
    assert [p.kind for p in shader.passes] == ["surface"]
    assert any("SubShader 2 of 2 runs" in n and "texture matrices" in n for n in shader.notes)
    props = shader.properties
    assert props["_Tint"].default == (0.5, 0.25, 1.0, 1.0) and props["_Tint"].attributes == ("Header(Colours)", "HDR")
    assert props["_Gain"].kind == "Float" and props["_Bias"].range == (0.0, 1.0)
    assert props["_MainTex"].kind == "2D"
    got = _render(HERE / "layered.shader", language, lights=[])
    covered = got[..., 3] > 0
    want = np.array([0.5, 0.25, 1.0]) * 2.0 + 0.125
    assert covered.mean() > 0.3
    assert np.abs(got[covered][:, :3] - want).max() <= 1e-6


def test_cginclude_keeps_the_files_line_numbers():
    shader = parse.read_shader(HERE / "layered.shader").surface
    text = (HERE / "layered.shader").read_text()
    line = next(i for i, t in enumerate(text.splitlines(), 1) if "void surf" in t)
    program_line = next(i for i, t in enumerate(shader.program.splitlines(), shader.program_line) if "void surf" in t)
    assert program_line == line


@pytest.mark.parametrize("language", LANGUAGES)
def test_unlit_vertex_fragment_pass_draws_its_colour(language, tmp_path):
    """A plain Unity vertex/fragment shader (appdata/v2f, UnityObjectToClipPos, a texture
    times a colour): every covered pixel is exactly the colour (white texture)."""
    path = _write(tmp_path, "unlit.shader", """
Shader "t/Unlit" {
    Properties { _Color ("Color", Color) = (0.25, 0.5, 1, 1) _MainTex ("Tex", 2D) = "white" {} }
    SubShader { Tags { "RenderType"="Opaque" } LOD 100
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct appdata { float4 vertex : POSITION; float2 uv : TEXCOORD0; };
            struct v2f { float2 uv : TEXCOORD0; float4 vertex : SV_POSITION; };
            sampler2D _MainTex; float4 _MainTex_ST; fixed4 _Color;
            v2f vert (appdata v) { v2f o; o.vertex = UnityObjectToClipPos(v.vertex);
                                   o.uv = TRANSFORM_TEX(v.uv, _MainTex); return o; }
            fixed4 frag (v2f i) : SV_Target { return tex2D(_MainTex, i.uv) * _Color; }
            ENDCG
        }
    }
}
""")
    got = _render(path, language, base=tmp_path)
    covered = got[..., 3] > 0
    assert 0.3 < covered.mean() < 0.8  # the sphere, tessellated, drawn where a sphere is
    assert np.abs(got[covered][:, :3] - [0.25, 0.5, 1.0]).max() == 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_outline_pass_draws_a_shell_of_the_stated_width(language):
    """Pass 1 (Cull Front) pushes the back faces out by _Outline and draws them red; the surface
    program draws the sphere over it. The centre row's red run on each side is the
    silhouette of radius 1 + _Outline less that of radius 1: tan(asin(r / D)) / tan(fov / 2)
    * H / 2 per side, camera at D = 4, fov 40 degrees."""
    def half_width(r):
        return np.tan(np.arcsin(r / 4.0)) / np.tan(np.radians(20.0)) * SIZE / 2

    got = _render(HERE / "outline.shader", language, properties={"_Outline": 0.25})
    row = got[SIZE // 2]
    red = (row[:, 0] > 0.99) & (row[:, 1] == 0) & (row[:, 2] == 0)
    shell = red.sum() / 2
    want = half_width(1.25) - half_width(1.0)
    # pixel centres inside each silhouette: within one pixel per side; measured below 0.5
    assert abs(shell - want) <= 1.0, (shell, want)
    lit = (row[:, 3] > 0) & ~red
    assert abs(lit.sum() / 2 - half_width(1.0)) <= 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_per_light_keywords_follow_the_light_being_drawn(language):
    """Unity compiles a light's pass with its keyword: USING_DIRECTIONAL_LIGHT for the
    directional light (red: _LightColor0 = 1 everywhere, no cosine in this model), POINT for
    the point light (green: its falloff), never neither (blue)."""
    lights = [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0},
              {"type": "point", "position": [0, 0, 2], "intensity": 3.0, "range": 20}]
    got = _render(HERE / "light_keywords.shader", language, lights=lights)
    covered = got[..., 3] > 0
    px = got[covered][:, :3]
    assert np.abs(px[:, 0] - 1.0).max() <= 1e-6
    assert px[:, 1].min() > 0.05 and px[:, 1].max() < 3.0
    assert px[:, 2].max() == 0.0


def test_fallback_resolves_to_a_shader_of_that_name_beside_it(tmp_path):
    _write(tmp_path, "plain.shader", """Shader "My/Plain" { SubShader { CGPROGRAM
#pragma surface surf Lambert
struct Input { float3 worldPos; };
void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }
ENDCG } }""")
    path = _write(tmp_path, "fancy.shader", """Shader "My/Fancy" {
SubShader { Pass { Lighting On Material { Diffuse (1,1,1,1) } SetTexture [_T] { matrix [_M] combine texture } } }
Fallback "My/Plain" }""")
    shader = parse.read_shader(path)
    assert shader.passes[0].path.name == "plain.shader"
    assert any('Fallback "My/Plain"' in n for n in shader.notes)


_PLAIN = """Shader "Lib/Plain" { SubShader { Pass { Name "FORWARD" Tags { "LightMode" = "ForwardBase" } CGPROGRAM
#pragma vertex v
#pragma fragment f
float4 v(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
fixed4 f() : SV_Target { return fixed4(0.25, 0.5, 1, 1); }
ENDCG } } }"""
_USER = """Shader "Game/Uses" { SubShader { UsePass "Lib/Plain/FORWARD" } }"""
_FALLS_BACK = """Shader "Game/Falls" { SubShader { Pass { CGPROGRAM
#pragma vertex v
#pragma geometry g
#pragma fragment f
ENDCG } } Fallback "Lib/Plain" }"""


@pytest.mark.parametrize("text", [_USER, _FALLS_BACK], ids=["UsePass", "Fallback"])
def test_a_shader_is_found_by_name_anywhere_in_its_unity_project(tmp_path, text):
    """Unity finds the shader a UsePass or Fallback names by its `Shader "name"` anywhere in the
    project (its Assets and Packages), not only beside the shader: a library shader in another
    folder of Assets is found, and its pass drawn."""
    _write(tmp_path / "Project" / "Assets" / "ThirdParty" / "Lib", "plain.shader", _PLAIN)
    (tmp_path / "Project" / "Packages").mkdir()
    path = _write(tmp_path / "Project" / "Assets" / "Game" / "Shaders", "uses.shader", text)
    shader = parse.read_shader(path)
    assert shader.passes[0].path.name == "plain.shader"


@pytest.mark.parametrize("text, message", [(_USER, 'no shader "Lib/Plain" here'),
                                           (_FALLS_BACK, 'Fallback "Lib/Plain" is a shader pbrlab does not have')],
                         ids=["UsePass", "Fallback"])
def test_outside_a_unity_project_a_shader_elsewhere_is_not_found(tmp_path, text, message):
    """Control: the same two folders with no Assets folder above them are no Unity project, so
    nothing outside the shader's own folder is searched, and the message says where to put it."""
    _write(tmp_path / "Project" / "ThirdParty" / "Lib", "plain.shader", _PLAIN)
    path = _write(tmp_path / "Project" / "Game" / "Shaders", "uses.shader", text)
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(path)
    assert message in str(info.value) and "Unity project's Assets" in str(info.value)


@pytest.mark.parametrize("text, message", [
    ('Shader "x" { SubShader { Pass { SetTexture [_MainTex] { matrix [_M] combine texture } } } FallBack "VertexLit" }',
     'Fallback "VertexLit" is one of the shaders Unity ships with the editor'),
    ('Shader "x" { SubShader { Pass { SetTexture [_MainTex] { matrix [_M] combine texture } } } }',
     "SetTexture [_MainTex] { matrix }: texture matrices are not supported"),
    ('Shader "x" { SubShader { Pass { SetTexture [_MainTex] { combine texture * primary QUIRKY } } } }',
     "combine: 'primary QUIRKY' is not a source"),
    ('Shader "x" { SubShader { Pass { Material { Glow (1, 1, 1, 1) } } } }',
     "Material { Glow }: not a fixed-function material colour"),
    ('Shader "x" { Properties { _A ("A", Float) = nan } SubShader { } }', "is not a finite float32 number"),
    ('Shader "x" { Properties { _C ("C", Color) = (1e999, 0, 0, 1) } SubShader { } }', "not a finite float32"),
    ('Shader "x" { Properties { _A ("A", Float) = 1 junk } SubShader { } }', "cannot read this Properties text"),
    ('Shader "x" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n#pragma hull h\n#pragma fragment f\nENDCG } } }',
     "#pragma hull without #pragma domain: tessellation needs both a hull and a domain function"),
    ('Shader "x" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n#pragma hull h\n#pragma domain d\n'
     '#pragma fragment f\nfloat4 v(float4 p : POSITION) : SV_POSITION { return p; }\n'
     'float4 f() : SV_Target { return 1; }\nENDCG } } }', "#pragma hull h: no function h(...) is defined"),
    ('Shader "x" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n#pragma geometry g\n#pragma fragment f\n'
     'float4 v(float4 p : POSITION) : SV_POSITION { return p; }\nfloat4 f() : SV_Target { return 1; }\nENDCG } } }',
     "#pragma geometry g: no function void g(...) is defined"),
    ('Shader "x" { SubShader { Pass { CGPROGRAM\n#pragma vertex v\n#pragma fragment f\nENDCG } } }',
     "#pragma vertex v: no function v(...) is defined"),
    ('Shader "x" { SubShader { CGPROGRAM\nfloat4 x;\n } }', "CGPROGRAM without ENDCG"),
])
def test_shaderlab_refusals_name_the_line_and_the_feature(tmp_path, text, message):
    path = _write(tmp_path, "bad.shader", text)
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(path)
    assert message in str(info.value)
    assert "bad.shader" in str(info.value)


def test_skipped_passes_are_noted_once_each(tmp_path):
    path = _write(tmp_path, "passes.shader", """Shader "x" { SubShader {
CGPROGRAM
#pragma surface surf Lambert
struct Input { float3 worldPos; };
void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }
ENDCG
Pass { Tags { "LightMode" = "ShadowCaster" } CGPROGRAM
#pragma vertex v
#pragma fragment f
ENDCG }
Pass { Name "META" Tags { "LightMode" = "Meta" } CGPROGRAM
#pragma vertex v
#pragma fragment f
ENDCG }
} }""")
    shader = parse.read_shader(path)
    assert [p.kind for p in shader.passes] == ["surface"]
    assert sum("ShadowCaster" in n and "no shadow maps" in n for n in shader.notes) == 1
    assert sum("Meta" in n and "lightmap" in n for n in shader.notes) == 1


def test_state_read_from_properties_and_several_commands_per_line(tmp_path):
    path = _write(tmp_path, "state.shader", """Shader "x" {
Properties { [Enum(UnityEngine.Rendering.CullMode)] _Cull ("Cull", Float) = 1
             [Enum(UnityEngine.Rendering.BlendMode)] _Src ("Src", Float) = 5
             [Enum(UnityEngine.Rendering.BlendMode)] _Dst ("Dst", Float) = 10 }
SubShader { Pass { ZTest Always Cull [_Cull] ZWrite Off Blend [_Src] [_Dst]
CGPROGRAM
#pragma vertex v
#pragma fragment f
float4 v(float4 p : POSITION) : SV_POSITION { return p; }
fixed4 f() : SV_Target { return 1; }
ENDCG } } }""")
    state = parse.read_shader(path).passes[0].state
    assert (state.ztest, state.cull, state.zwrite) == ("always", "front", False)
    assert state.blend_factors == ("SrcAlpha", "OneMinusSrcAlpha")


def test_a_shader_file_with_a_byte_order_mark_reads(tmp_path):
    path = tmp_path / "bom.shader"
    path.write_bytes("\ufeffShader \"x\" { SubShader { CGPROGRAM\n#pragma surface surf Lambert\n"
                     "struct Input { float3 worldPos; };\nvoid surf(Input IN, inout SurfaceOutput o) "
                     "{ o.Albedo = 1; }\nENDCG } }".encode("utf-8"))
    assert parse.read_shader(path).surface is not None


def test_port_unity_refuses_to_replace_its_input(tmp_path):
    from pbrlab.commands.cli import main
    path = HERE / "layered.shader"
    before = path.read_bytes()
    assert main(["port-unity", str(path), "-o", str(path)]) == 2
    assert path.read_bytes() == before
    assert main(["port-unity", str(path), "-o", str(tmp_path / "x.png")]) == 2
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize("language", LANGUAGES)
def test_grabpass_hands_the_passes_after_it_what_is_behind(language, tmp_path):
    """GrabPass copies what is drawn so far (an emissive plane behind the sphere, nothing
    else lit: one radiance everywhere); the pass after it draws half of what it grabbed at
    each pixel (ComputeGrabScreenPos): the sphere shows half the plane's radiance exactly."""
    shader = _write(tmp_path, "glass.shader", """
Shader "t/Glass" {
    SubShader { Tags { "Queue" = "Transparent" }
        GrabPass { Tags { "LightMode" = "Always" } "_BehindTex" }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            sampler2D _BehindTex;
            struct v2f { float4 pos : SV_POSITION; float4 grab : TEXCOORD0; };
            v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex);
                                       o.grab = ComputeGrabScreenPos(o.pos); return o; }
            half4 frag(v2f i) : SV_Target { return tex2Dproj(_BehindTex, UNITY_PROJ_COORD(i.grab)) * 0.5; }
            ENDCG
        }
    }
}
""")
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [SIZE, SIZE]},
            "lights": [],
            "materials": {"wall": {"albedo": [0, 0, 0], "emission": [1.0, 0.5, 0.25], "smoothness": 0},
                          "glass": {"surface": str(shader)}},
            "objects": [{"mesh": {"primitive": "plane", "size": 20}, "material": "wall",
                         "transform": {"translate": [0, 0, -3], "rotate_deg": [90, 0, 0]}},
                        {"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "glass"}]}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        got = render.render_scene(scene.parse_scene(data, "<test>", tmp_path), language=language).linear
    centre = got[SIZE // 2 - 4:SIZE // 2 + 4, SIZE // 2 - 4:SIZE // 2 + 4, :3].reshape(-1, 3)
    wall = got[2, 2, :3]
    assert np.abs(wall - [1.0, 0.5, 0.25]).max() <= 2e-3  # the emission, as the default surface stores it
    assert np.abs(centre - 0.5 * wall).max() <= 1e-6, (centre[:3], wall)


@pytest.mark.parametrize("language", LANGUAGES)
def test_fmod_truncates_as_direct3d_defines_it(language, tmp_path):
    """fmod(x, y) = x - y trunc(x / y), the sign of x (glslang lowers HLSL's fmod to GLSL's
    floored mod; the harness's HLSL support calls the truncating one): fmod(-5.5, 2) = -1.5,
    fmod(5.5, 2) = 1.5, fmod(-7, 3) = -1, fmod(7, 3) = 1, exactly."""
    path = _write(tmp_path, "fmod.shader", """Shader "t/fmod" { SubShader { Pass { CGPROGRAM
#pragma vertex vert
#pragma fragment frag
float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
fixed4 frag() : SV_Target { return fixed4(fmod(-5.5, 2.0) + 2.0, fmod(5.5, 2.0), fmod(float2(-7, 7), float2(3, 3)) + float2(2, 0)); }
ENDCG } } }""")
    got = _render(path, language, base=tmp_path)
    covered = got[..., 3] > 0
    assert np.abs(got[covered][:, :3] - [0.5, 1.5, 1.0]).max() == 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_default_arguments_of_a_cg_function(language, tmp_path):
    """HLSL's default arguments (GLSL has none: the port adds the shorter overloads, each
    calling the full form with the defaults): x k + b with k = 0.5, b = 0.125 by default."""
    path = _write(tmp_path, "defaults.shader", """Shader "t/defaults" { SubShader { Pass { CGPROGRAM
#pragma vertex vert
#pragma fragment frag
float scale(float x, float k = 0.5, float b = 0.125) { return x * k + b; }
float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
fixed4 frag() : SV_Target { return fixed4(scale(1.0), scale(1.0, 0.25), scale(1.0, 1.0, 0.0), 1); }
ENDCG } } }""")
    got = _render(path, language, base=tmp_path)
    covered = got[..., 3] > 0
    assert np.abs(got[covered][:, :3] - [0.625, 0.375, 1.0]).max() == 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_componentwise_select_on_a_vector_condition(language, tmp_path):
    """HLSL's c ? a : b with a vector c selects per component (a scalar branch splats): for
    c = (1, -1, 2) > 0 and a = 0.25, b = (0.5, 0.75, 1): (0.25, 0.75, 0.25)."""
    path = _write(tmp_path, "select.shader", """Shader "t/select" { SubShader { Pass { CGPROGRAM
#pragma vertex vert
#pragma fragment frag
float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
fixed4 frag() : SV_Target { float3 c = float3(1, -1, 2); return fixed4(c > 0 ? 0.25 : float3(0.5, 0.75, 1), 1); }
ENDCG } } }""")
    got = _render(path, language, base=tmp_path)
    covered = got[..., 3] > 0
    assert np.abs(got[covered][:, :3] - [0.25, 0.75, 0.25]).max() == 0.0


def test_a_define_naming_another_macro_takes_its_value_in_later_conditions():
    # Skybox-Procedural: `#define SKYBOX_SUNDISK SKYBOX_SUNDISK_HQ` (2), then `#if SKYBOX_SUNDISK ==
    # SKYBOX_SUNDISK_HQ` picks the v2f members; read as 1 it took the SIMPLE branch's rayDir
    from pbrlab.importers.unity.conditionals import active_text, defines_of
    text = ("#define MODE_SIMPLE 1\n#define MODE_HQ 2\n#define MODE MODE_HQ // the default\n"
            "#if MODE == MODE_HQ\nhq\n#elif MODE == MODE_SIMPLE\nsimple\n#endif\n")
    lines = active_text(text, defines_of(text)).splitlines()
    assert "hq" in lines and "simple" not in lines


def test_a_usepass_by_another_path_names_the_project_shader_of_that_name(tmp_path):
    """A UsePass naming "Other/Plain" where the project has "Lib/Plain" is refused (Unity finds a
    shader by its whole name only), and the refusal names the project's "Lib/Plain". Control: a
    last name no project shader has gets no such hint."""
    _write(tmp_path / "Project" / "Assets" / "Lib", "plain.shader", _PLAIN)
    path = _write(tmp_path / "Project" / "Assets" / "Game", "uses.shader", _USER.replace("Lib/Plain", "Other/Plain"))
    with pytest.raises(UnityShaderError, match=r'no shader "Other/Plain" here.*the project has "Lib/Plain" '
                                               r'\(plain\.shader\)'):
        parse.read_shader(path)
    other = _write(tmp_path / "Project" / "Assets" / "Game", "other.shader", _USER.replace("Lib/Plain", "Lib/Nothing"))
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(other)
    assert "the project has" not in str(info.value)


def test_a_fallback_that_cannot_run_either_is_refused_with_this_shaders_reason_first(tmp_path):
    """Game/Falls' SubShader cannot run (a geometry function it does not define) and its
    Fallback, a shader whose only pass is fixed-function texture-matrix code, cannot either: the
    refusal gives Game/Falls' reason, then the Fallback's. Control: the Fallback alone is refused
    with its own reason only."""
    _write(tmp_path, "plain.shader", 'Shader "Lib/Plain" { SubShader { Pass { SetTexture [_MainTex] '
                                     '{ matrix [_M] combine texture } } } }')
    path = _write(tmp_path, "falls.shader", _FALLS_BACK)
    with pytest.raises(UnityShaderError) as info:
        parse.read_shader(path)
    message = str(info.value)
    assert message.index("no SubShader can run here (SubShader 1") < message.index(
        'its Fallback "Lib/Plain" (plain.shader) cannot run either') < message.index("texture matrices")
    with pytest.raises(UnityShaderError, match="texture matrices") as alone:
        parse.read_shader(tmp_path / "plain.shader")
    assert "no SubShader can run" not in str(alone.value)
