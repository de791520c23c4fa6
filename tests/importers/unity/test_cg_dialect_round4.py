"""Forms of Cg/HLSL that real built-in-pipeline shaders nobody here wrote use (issue 34's unseen
shaders, session 40: przemyslawzaworski/Unity3D-CG-programming, measured not committed) and that
the GLSL port or both languages did not take: Direct3D 11 texture objects (texture_methods.py),
system-value vertex inputs, HLSL's bit casts and explicit-derivative lookups, a program's own
functions and globals under Unity's names, Unity 5.3's matrix names, GLSL-reserved member names,
nointerpolation members, vector<T, N> and nested initialisers; and the refusals that must name
what is missing (compute buffers, a GLSLPROGRAM's tessellation stages, an empty file).

Readback as test_unity_names_round3.py: the corpus scene's ``linear`` image (the fragment's
colour; alpha the coverage), on the pixels the sphere covers whole. Both languages must give the
expected colour: GLSL through the port, HLSL as written.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.foundation.images import write_png
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
# float32 rounding of a texel read and of a few operations on it: the colours below are exact
# 8-bit texels or exact small sums, so the two sides agree to a few ulp of 1.
EXACT = 1e-6

PASS = """
Shader "t/{name}" {{
    Properties {{
        _MainTex ("t", 2D) = "white" {{}}
    }}
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
{head}
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
        v2f vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {{
            v2f o; o.pos = UnityObjectToClipPos(vertex); o.uv = uv; return o; }}
        float4 frag(v2f i) : SV_Target {{
{body}
        }}
        ENDCG
    }} }}
}}
"""


def _shader(tmp_path, name, body, head="        sampler2D _MainTex;"):
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(PASS.format(name=name, head=head, body=body)))
    return path


def _render(tmp_path, shader, language, texture=None):
    data = corpus.scene_for(shader)
    if texture is not None:
        data["materials"]["m"]["properties"] = {"_MainTex": {"path": str(texture)}}
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear


def _covered(image):
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return covered


@pytest.fixture()
def checker(tmp_path):
    """An 8 x 8 texture of 2 x 2 blocks, each a different colour (mip 0 differs from mip 3, its
    mean)."""
    rng = np.random.default_rng(40)
    blocks = rng.integers(0, 256, (4, 4, 3), dtype=np.uint8)
    rgba = np.concatenate([np.repeat(np.repeat(blocks, 2, 0), 2, 1), np.full((8, 8, 1), 255, np.uint8)], axis=2)
    path = tmp_path / "checker.png"
    write_png(path, rgba)
    return path


DX11 = "        Texture2D _MainTex; SamplerState sampler_MainTex;"


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("dx11, cg", [
    ("return _MainTex.Sample(sampler_MainTex, i.uv);", "return tex2D(_MainTex, i.uv);"),
    ("return _MainTex.SampleLevel(sampler_MainTex, i.uv, 0.0);", "return tex2Dlod(_MainTex, float4(i.uv, 0, 0));"),
    # (explicit derivatives: llvmpipe's implicit LOD differs from textureGrad's by up to 3e-3 here)
    ("return _MainTex.SampleGrad(sampler_MainTex, i.uv, ddx(i.uv), ddy(i.uv));",
     "return tex2Dgrad(_MainTex, i.uv, ddx(i.uv), ddy(i.uv));"),
    # Cg's four-argument tex2D is the same lookup (cg_spellings: spelled tex2Dgrad in both)
    ("return _MainTex.SampleGrad(sampler_MainTex, i.uv, ddx(i.uv), ddy(i.uv));",
     "return tex2D(_MainTex, i.uv, ddx(i.uv), ddy(i.uv));"),
    ("return _MainTex.Load(int3(3, 5, 0));", "return tex2Dlod(_MainTex, float4(3.5 / 8, 5.5 / 8, 0, 0));"),
])
def test_direct3d11_texture_objects_read_what_the_cg_lookup_reads(tmp_path, checker, language, dx11, cg):
    """Texture2D + SamplerState and their methods (Microsoft's HLSL reference) read the texel
    tex2D / tex2Dlod reads; control: the same read at mip 3 (the texture's mean) differs."""
    got = _render(tmp_path, _shader(tmp_path, "dx11", dx11, DX11), language, checker)
    want = _render(tmp_path, _shader(tmp_path, "cg", cg), language, checker)
    covered = _covered(want)
    assert np.abs(got[covered, :3] - want[covered, :3]).max() <= EXACT
    if "Load" not in dx11:
        mean = _render(tmp_path, _shader(tmp_path, "mip3", "return _MainTex.SampleLevel(sampler_MainTex, i.uv, 3.0);",
                                         DX11), language, checker)
        assert np.mean(np.abs(mean[covered, :3] - want[covered, :3]).max(axis=-1) > 0.05) > 0.5


@pytest.mark.parametrize("language", LANGUAGES)
def test_bit_casts_and_cg_lookups_hlsl_has(tmp_path, checker, language):
    """asuint / asfloat round trip, rcp, mad, log10 and tex2Dgrad (GLSL has none of the names):
    (0.25, 0.5, 3, 1) then the texel, against the same texel read by tex2D."""
    body = """
            float a = asfloat(asuint(0.25));
            float b = rcp(2.0);
            float c = mad(2.0, 1.0, 1.0) * log10(10.0);
            return float4(a, b, c, 1) + 0 * tex2Dgrad(_MainTex, i.uv, ddx(i.uv), ddy(i.uv));"""
    image = _render(tmp_path, _shader(tmp_path, "casts", body), language, checker)
    covered = _covered(image)
    assert np.abs(image[covered, :3] - np.array([0.25, 0.5, 3.0])).max() <= 1e-5  # log10's float32 rounding


@pytest.mark.parametrize("language", LANGUAGES)
def test_vertex_id_reaches_the_vertex_function(tmp_path, language):
    """SV_VertexID: the index the mesh's index buffer gives; a colour from its parity varies over
    the sphere (both values drawn), and SV_InstanceID is 0 (one instance)."""
    shader = tmp_path / "vid.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/vid" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct v2f { float4 pos : SV_POSITION; float parity : TEXCOORD0; float instance : TEXCOORD1; };
            v2f vert(float4 vertex : POSITION, uint id : SV_VertexID, uint inst : SV_InstanceID) {
                v2f o; o.pos = UnityObjectToClipPos(vertex); o.parity = id % 2; o.instance = inst; return o; }
            float4 frag(v2f i) : SV_Target { return float4(i.parity, i.instance, 0, 1); }
            ENDCG
        } } }
        """))
    image = _render(tmp_path, shader, language)
    covered = _covered(image)
    assert image[covered, 0].min() < 0.1 and image[covered, 0].max() > 0.9
    assert np.abs(image[covered, 1]).max() == 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_program_of_its_own_under_unity_names(tmp_path, language):
    """A program that includes nothing and defines ComputeScreenPos itself, declares
    _LightColor0 in a list with its own globals, spells _Object2World (Unity 5.3), names a member
    gl_Position and reads UNITY_LIGHTMODEL_AMBIENT into a float3: rendered, its own function
    used (it returns (0.5, 0.25, 0, 1) whatever the position)."""
    shader = tmp_path / "own.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/own" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 _LightColor0, _Mine;
            float4 ComputeScreenPos(float4 p) { return float4(0.5, 0.25, 0, 1); }
            struct v2f { float4 gl_Position : SV_POSITION; float4 screen : TEXCOORD0; float3 world : TEXCOORD1; };
            v2f vert(float4 vertex : POSITION) {
                v2f o; o.gl_Position = UnityObjectToClipPos(vertex); o.screen = ComputeScreenPos(o.gl_Position);
                o.world = mul(_Object2World, vertex).xyz; return o; }
            float4 frag(v2f i) : SV_Target {
                float3 ambient = UNITY_LIGHTMODEL_AMBIENT;
                return float4(i.screen.xy, 0 * ambient.x + 0 * i.world.x, 1); }
            ENDCG
        } } }
        """))
    image = _render(tmp_path, shader, language)
    covered = _covered(image)
    assert np.abs(image[covered, :3] - np.array([0.5, 0.25, 0.0])).max() <= EXACT


@pytest.mark.parametrize("language", LANGUAGES)
def test_nointerpolation_member_is_flat(tmp_path, language):
    """A nointerpolation member holds one vertex's value over each triangle: the vertex's own
    position there, so neighbouring pixels take only a few distinct values; the same member
    interpolated (control) takes about one value a pixel."""
    def render(qualifier):
        shader = tmp_path / f"flat_{qualifier or 'smooth'}.shader"
        shader.write_text(textwrap.dedent(f"""
            Shader "t/flat" {{ SubShader {{ Pass {{
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                struct v2f {{ linear float4 pos : SV_POSITION; {qualifier} float4 p : TEXCOORD0; }};
                v2f vert(float4 vertex : POSITION) {{ v2f o; o.pos = UnityObjectToClipPos(vertex); o.p = vertex * 0.5 + 0.5; return o; }}
                float4 frag(v2f i) : SV_Target {{ return float4(i.p.xyz, 1); }}
                ENDCG
            }} }} }}
            """))
        image = _render(tmp_path, shader, language)
        return image[_covered(image), :3]
    flat, smooth = render("nointerpolation"), render("")
    distinct_flat = len(np.unique(np.round(flat, 6), axis=0))
    distinct_smooth = len(np.unique(np.round(smooth, 6), axis=0))
    assert distinct_flat < 0.5 * len(flat) < distinct_smooth


@pytest.mark.parametrize("language", LANGUAGES)
def test_vector_template_nested_initialiser_and_vector_not(tmp_path, language):
    """vector<bool, 3>, a nested array initialiser and ! of a bool vector (HLSL: componentwise):
    (1, 0, 1) from the middle of the three values."""
    body = """
            static const float2 points[2] = {{0.25, 0.5}, {0.75, 1.0}};
            vector<bool, 3> c = bool3(points[0].x > 0.5, points[1].x > 0.5, points[0].y > 0.75);
            bool3 n = !c;
            return float4(n.x ? 1 : 0, n.y ? 1 : 0, n.z ? 1 : 0, 1);"""
    image = _render(tmp_path, _shader(tmp_path, "vec", body), language)
    covered = _covered(image)
    assert np.abs(image[covered, :3] - np.array([1.0, 0.0, 1.0])).max() == 0.0


@pytest.mark.parametrize("declaration, named", [
    ("StructuredBuffer<float3> _Points;", "StructuredBuffer _Points"),
    ("ByteAddressBuffer _Raw;", "ByteAddressBuffer _Raw"),
])
def test_a_compute_buffer_is_refused_by_name_at_its_line(tmp_path, declaration, named):
    reads = "_Points[0]" if "_Points" in declaration else "asfloat(_Raw.Load3(0))"
    body = f"            return float4({reads}, 1);"
    shader = _shader(tmp_path, "buffer", body, f"        sampler2D _MainTex;\n        {declaration}")
    line = next(n for n, text in enumerate(shader.read_text().splitlines(), 1) if declaration in text)
    with pytest.raises(PbrlabError, match=rf"buffer\.shader:{line}: reads {named}, a compute buffer"):
        _render(tmp_path, shader, "hlsl")


def test_a_glslprogram_with_tessellation_stages_is_refused_at_the_block(tmp_path):
    shader = tmp_path / "tess.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/tess" { SubShader { Pass {
            GLSLPROGRAM
            #ifdef VERTEX
            void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
            #endif
            #ifdef HULL
            layout (vertices = 3) out;
            void main() { }
            #endif
            #ifdef FRAGMENT
            void main() { gl_FragColor = vec4(1.0); }
            #endif
            ENDGLSL
        } } }
        """))
    with pytest.raises(PbrlabError, match=r"tess\.shader:\d+: #ifdef HULL: a GLSLPROGRAM's tessellation control stage"):
        _render(tmp_path, shader, "glsl")


def test_an_empty_file_says_so(tmp_path):
    shader = tmp_path / "empty.shader"
    shader.write_text("")
    with pytest.raises(PbrlabError, match=r"empty\.shader:1: the file is empty"):
        _render(tmp_path, shader, "glsl")


@pytest.mark.parametrize("language", LANGUAGES)
def test_vert_img_is_unitys_image_effect_vertex_stage(tmp_path, language):
    """#pragma vertex vert_img (UnityCG.cginc's, with appdata_img and v2f_img) draws what a
    vertex function passing the UV on draws."""
    def shader(name, vertex, frag_input, head):
        path = tmp_path / f"{name}.shader"
        path.write_text(textwrap.dedent(f"""
            Shader "t/{name}" {{ SubShader {{ Pass {{
                CGPROGRAM
                #pragma vertex {vertex}
                #pragma fragment frag
                #include "UnityCG.cginc"
{head}
                float4 frag({frag_input} i) : SV_Target {{ return float4(i.uv, 0.25, 1); }}
                ENDCG
            }} }} }}
            """))
        return path
    own = """
                struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
                v2f vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                    v2f o; o.pos = UnityObjectToClipPos(vertex); o.uv = uv; return o; }"""
    got = _render(tmp_path, shader("img", "vert_img", "v2f_img", ""), language)
    want = _render(tmp_path, shader("own", "vert", "v2f", own), language)
    covered = _covered(want)
    assert np.abs(got[covered, :3] - want[covered, :3]).max() <= EXACT
    assert np.ptp(want[covered, 0]) > 0.5  # the UV varies: the check sees a wrong mapping


@pytest.mark.parametrize("language", LANGUAGES)
def test_tangent_space_rotation_and_world_transform_params(tmp_path, language):
    """TANGENT_SPACE_ROTATION's rows are tangent, binormal and normal (UnityCG.cginc), so it
    takes the unit normal to (0, 0, 1) and the tangent to (1, 0, 0); its transpose (the wrong
    order) would not. unity_WorldTransformParams.w is 1 for the unmirrored sphere."""
    shader = tmp_path / "tbn.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/tbn" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct v2f { float4 pos : SV_POSITION; float3 n : TEXCOORD0; float3 t : TEXCOORD1; };
            v2f vert(appdata_tan v) {
                v2f o; o.pos = UnityObjectToClipPos(v.vertex);
                TANGENT_SPACE_ROTATION;
                o.n = mul(rotation, normalize(v.normal));
                o.t = mul(rotation, normalize(v.tangent.xyz)) * unity_WorldTransformParams.w;
                return o; }
            float4 frag(v2f i) : SV_Target { return float4(i.n.z, i.t.x, abs(i.n.x) + abs(i.n.y) + abs(i.t.y) + abs(i.t.z), 1); }
            ENDCG
        } } }
        """))
    image = _render(tmp_path, shader, language)
    covered = _covered(image)
    # interpolation between vertices shortens the unit vectors by at most 1 - cos(half the
    # sphere's 5.6-degree facets) = 1.2e-3 (31 bands x 64 sections)
    assert np.abs(image[covered, :2] - 1.0).max() <= 1.2e-3
    assert np.percentile(image[covered, 2], 99) <= 0.1


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("scale", [0.25, 0.3])
def test_a_global_the_program_writes_starts_as_its_property(tmp_path, language, scale):
    """FXC's compatibility mode (how Unity compiles) lets a program write a global: the write
    lasts the invocation, the value before it is the property's. `_Scale *= 2` in a helper the
    fragment calls, twice in a list declaration with another written global: 2 x scale, 4 x
    scale; IsGammaSpace() is false (linear colour space)."""
    shader = tmp_path / "written.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/written" {
            Properties { _Scale ("s", Float) = 0.25 }
            SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float _Scale, _Twice;
            float4 vert(float4 vertex : POSITION) : SV_POSITION { return UnityObjectToClipPos(vertex); }
            void doubled() { _Scale *= 2.0; _Twice = _Scale * 2.0; }
            float4 frag() : SV_Target { doubled(); return float4(_Scale, _Twice, IsGammaSpace() ? 1 : 0, 1); }
            ENDCG
        } } }
        """))
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_Scale": scale}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear
    covered = _covered(image)
    assert np.abs(image[covered, :3] - np.array([2 * scale, 4 * scale, 0.0])).max() <= EXACT


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_array_member_is_one_varying_per_element(tmp_path, language):
    """``float2 uv[3] : TEXCOORD0`` (the image effects' neighbour taps) occupies TEXCOORD0..2:
    each element reaches the fragment stage as written (the sphere's UV plus k x (0.25, 0.125))."""
    shader = tmp_path / "taps.shader"
    shader.write_text(textwrap.dedent("""
        Shader "t/taps" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct v2f { float4 pos : SV_POSITION; float2 uv[3] : TEXCOORD0; };
            v2f vert(appdata_base v) {
                v2f o; o.pos = UnityObjectToClipPos(v.vertex);
                for (int k = 0; k < 3; k++) o.uv[k] = v.texcoord.xy + k * float2(0.25, 0.125);
                return o; }
            float4 frag(v2f i) : SV_Target { return float4(i.uv[1] - i.uv[0], i.uv[2].x - i.uv[1].x, 1); }
            ENDCG
        } } }
        """))
    image = _render(tmp_path, shader, language)
    covered = _covered(image)
    # each element is interpolated on its own (llvmpipe: a0 + dadx x + dady y in float32, terms
    # larger than the value), which moves an interpolated value by up to ~1e-5 of its size
    # (tests/importers/unity/test_corpus.py's note); the difference of two, values <= 1.5: 2e-5
    assert np.abs(image[covered, :3] - np.array([0.25, 0.125, 0.25])).max() <= 2e-5


PROBE = """
Shader "t/probe" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "UnityCG.cginc"
    struct v2f { float3 worldRefl : TEXCOORD0; float4 pos : SV_POSITION; };
    v2f vert (float4 vertex : POSITION, float3 normal : NORMAL) {
        v2f o; o.pos = UnityObjectToClipPos(vertex);
        float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
        o.worldRefl = reflect(-normalize(UnityWorldSpaceViewDir(worldPos)), UnityObjectToWorldNormal(normal));
        return o; }
    fixed4 frag (v2f i) : SV_Target {
        half4 sharp = UNITY_SAMPLE_TEXCUBE(unity_SpecCube0, i.worldRefl);
        half4 rough = UNITY_SAMPLE_TEXCUBE_LOD(unity_SpecCube0, i.worldRefl, 6.0);
        half4 old = texCUBElod(unity_SpecCube0, float4(i.worldRefl, 3.0));
        return float4(DecodeHDR(sharp, unity_SpecCube0_HDR).r, rough.g, old.b, 1); }
    ENDCG
} } }
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_pass_reads_the_reflection_probe_the_scene_environment(tmp_path, language):
    """unity_SpecCube0 read by a vertex/fragment pass (Unity manual's environment-reflection
    example; UNITY_SAMPLE_TEXCUBE, _LOD at mip 6, texCUBElod): the scene environment's
    prefiltered chain; under a constant sky every level and direction is that radiance (float32
    filtering of equal texels: exact to rounding). Control: without an environment, black."""
    shader = tmp_path / "probe.shader"
    shader.write_text(PROBE)
    sky = [0.25, 0.5, 0.75]
    data = corpus.scene_for(shader)
    data["environment"] = {"color": sky}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear
    covered = _covered(image)
    assert np.abs(image[covered, :3] - np.array(sky)).max() <= 1e-6
    del data["environment"]
    dark = render_scene(parse_scene(data, "t", tmp_path), language=language).linear
    assert np.abs(dark[covered, :3]).max() == 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_float4x4_times_a_float3_assigned_to_a_float3(tmp_path, language):
    """`r = mul(M, r)` with M a float4x4 (the view matrix: a rotation and a translation) and r a
    float3 (FXC takes it: the matrix cut to three columns, the result truncated on assignment):
    the same as mul((float3x3)M, r); control: with the translation (float4(r, 1)) it differs."""
    def render(expression, name):
        body = f"""
            float3 r = float3(i.uv, 0.5);
            r = {expression};
            return float4(frac(r * 0.5), 1);"""
        return _render(tmp_path, _shader(tmp_path, name, body), language)
    got = render("mul(UNITY_MATRIX_V, r)", "cut")
    want = render("mul((float3x3)UNITY_MATRIX_V, r)", "three")
    moved = render("mul(UNITY_MATRIX_V, float4(r, 1)).xyz", "moved")
    covered = _covered(want)
    assert np.abs(got[covered, :3] - want[covered, :3]).max() <= EXACT
    assert np.abs(moved[covered, :3] - want[covered, :3]).max() > 0.1
