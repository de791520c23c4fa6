"""Unity geometry shaders (``#pragma geometry``, issue 34): the geometry stage runs between the
pass's vertex and fragment stages in both languages (HLSL as written through glslang's
geometry stage; GLSL through the port, ``stream.Append`` -> ``EmitVertex``), checked per
pixel against a float64 expectation.

The test shader places a plane's corners at clip positions of its own (no camera involved:
clip = (0.3 a, -0.5 b, 0, 1 + 0.4 a) for the corner (a, b) = (x, z) / 0.3, a perspective
trapezoid), and its geometry function emits each triangle twice, shifted by -0.45 and +0.45
in NDC x (clip x += shift * w), coloured (u, v, copy id). Inverting the projective map gives,
at each pixel centre (X, Y) in NDC, a = X' / (0.3 - 0.4 X') and b = -Y (1 + 0.4 a) / 0.5 with
X' = X - shift: the pixel is the copy's where |a|, |b| <= 1, with (u, v) = (a/2 + 1/2,
1/2 - b/2) (the plane primitive's UVs: u along +x, v along -z).
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.geometry_syntax import spell_for_glsl
from pbrlab.render.renderer import render_scene

SHIFTS = (-0.45, 0.45)
IDS = (0.25, 0.75)
# The float32 evaluation of perspective-correct interpolation (attribute / w at each vertex,
# the barycentric weights, the sum and the division: about 16 roundings of 2^-24 relative
# on values <= 1): 16 * 6e-8 = 1e-6. Measured on llvmpipe: 2.9e-7 (both languages).
UV_BOUND = 1e-6
# A pixel centre this close (in pixels) to a copy's edge may fall either way under the
# rasteriser's fixed-point snapping (llvmpipe: 1/256 px): left out of the comparison
# (measured: none of the 64 x 64 pixels is this close).
EDGE_PX = 0.02

COPIES = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        Cull Off
        CGPROGRAM
        #pragma vertex vert
        {pragma}
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct v2g {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
        struct g2f {{ float4 pos : SV_POSITION; float3 colour : TEXCOORD0; }};
        v2g vert(appdata_base v) {{
            v2g o;
            float a = v.vertex.x / 0.3, b = v.vertex.z / 0.3;
            o.pos = float4(0.3 * a, -0.5 * b, 0.0, 1.0 + 0.4 * a);
            o.uv = v.texcoord.xy;
            return o;
        }}
        [maxvertexcount(6)]
        void geom({primitive_id}triangle v2g IN[3], inout TriangleStream<g2f> stream) {{
            g2f o;
            for (int copy = 0; copy < 2; copy++) {{
                float shift = copy == 0 ? {left} : {right};
                for (int k = 0; k < 3; k++) {{
                    o.pos = IN[k].pos;
                    o.pos.x += shift * o.pos.w;
                    o.colour = float3({colour}, copy == 0 ? 0.25 : 0.75);
                    stream.Append(o);
                }}
                stream.RestartStrip();
            }}
        }}
        float4 frag(g2f i) : SV_Target {{ return float4(i.colour, 1); }}
        ENDCG
    }} }}
}}
"""


def _render(tmp_path, language, name, pragma="#pragma geometry geom", left=-0.45, right=0.45,
            colour="IN[k].uv", primitive_id=""):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(COPIES.format(name=name, pragma=pragma, left=left, right=right,
                                                    colour=colour, primitive_id=primitive_id)))
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def _plane_point(X, Y, shift):
    """(inside, a, b) of the NDC point (X, Y) on the copy shifted by ``shift`` (module docstring)."""
    Xs = X - shift
    a = Xs / (0.3 - 0.4 * Xs)
    b = -Y * (1 + 0.4 * a) / 0.5
    return (np.abs(a) <= 1) & (np.abs(b) <= 1) & (0.3 - 0.4 * Xs > 0), a, b


def expected_copies(size):
    """(colour, covered, near an edge) per pixel in float64; row 0 is the top (NDC y = +1)."""
    h, w = size
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    colour, covered, near_edge = np.zeros((h, w, 3)), np.zeros((h, w), bool), np.zeros((h, w), bool)
    d = EDGE_PX * 2 / w
    for shift, ident in zip(SHIFTS, IDS):
        inside, a, b = _plane_point(X, Y, shift)
        for dx in (-d, d):
            for dy in (-d, d):
                near_edge |= _plane_point(X + dx, Y + dy, shift)[0] != inside
        colour[inside] = np.stack([a / 2 + 0.5, 0.5 - b / 2, np.full_like(a, ident)], -1)[inside]
        covered |= inside
    return colour, covered, near_edge


def copies_problems(image) -> list[str]:
    colour, covered, near_edge = expected_copies(image.shape[:2])
    kept = ~near_edge
    problems = []
    drawn = image[..., 3] > 0
    wrong_cover = (drawn != covered) & kept
    if wrong_cover.any():
        problems.append(f"{int(wrong_cover.sum())} pixels covered where float64 says otherwise")
    error = np.abs(image[..., :3] - colour).max(-1)
    over = (error > UV_BOUND) & covered & drawn & kept
    if over.any():
        problems.append(f"{over.mean():.3%} of pixels over {UV_BOUND} (largest {error[over].max():.3g})")
    return problems


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_each_triangle_is_emitted_twice_where_float64_says(tmp_path, language):
    image = _render(tmp_path, language, "copies")
    assert image[..., 3].mean() > 0.3  # the two copies cover a third of the image
    assert copies_problems(image) == []


def test_the_languages_agree(tmp_path):
    """The GLSL port and the HLSL as written: the same pixels (measured: identical)."""
    glsl, hlsl = (_render(tmp_path, language, f"agree_{language}") for language in ("glsl", "hlsl"))
    assert np.abs(glsl - hlsl).max() <= UV_BOUND


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_controls_fail(tmp_path, language):
    """Without the geometry stage (one copy, unshifted) and with the shifts swapped (the ids on
    the wrong sides), the check fails."""
    assert copies_problems(_render(tmp_path, language, "no_geometry", pragma=""))
    assert copies_problems(_render(tmp_path, language, "swapped", left=0.45, right=-0.45))


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_sv_primitive_id_numbers_the_mesh_triangles(tmp_path, language):
    """SV_PrimitiveID: the plane's faces are (0, 2, 1) and (0, 3, 2) (primitives.plane), split
    by the diagonal a = b: triangle 0 holds the corner (a, b) = (1, -1), so b < a."""
    image = _render(tmp_path, language, "primitive_id", colour="float2(primitive, 0)",
                    primitive_id="uint primitive : SV_PrimitiveID, ")
    h, w = image.shape[:2]
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    for shift in SHIFTS:
        inside, a, b = _plane_point(X, Y, shift)
        clear = inside & (np.abs(a - b) > 0.1)  # away from the diagonal
        assert clear.sum() > 50
        np.testing.assert_allclose(image[clear][:, 0], np.where(b[clear] < a[clear], 0.0, 1.0), rtol=0, atol=UV_BOUND)


def test_the_glsl_spelling_keeps_lines_and_spells_the_stream():
    text = ("[maxvertexcount(3)]\nvoid geom(triangle v2g IN[3],\n  inout TriangleStream<g2f> s) {\n"
            "  s.Append(o); s . RestartStrip();\n}\n")
    spelled = spell_for_glsl(text)
    assert spelled.count("\n") == text.count("\n")
    assert "maxvertexcount" not in spelled and "triangle" not in spelled and "TriangleStream" not in spelled
    assert "PBRLAB_GEOMETRY_APPEND(o)" in spelled and "PBRLAB_GEOMETRY_RESTART()" in spelled
    assert spell_for_glsl("float4 f(float x) { return x; }") == "float4 f(float x) { return x; }"


@pytest.mark.parametrize("change, named", [
    (("[maxvertexcount(6)]", ""), "no [maxvertexcount(N)]"),
    # (point input runs since session 47: test_s47_stages_point_geometry.py)
    (("triangle v2g IN[3]", "line v2g IN[2]"), "takes line input"),
    (("inout TriangleStream<g2f> stream", "float extra"), "is not one pbrlab runs"),
])
def test_what_is_not_run_is_named(tmp_path, change, named):
    shader = tmp_path / "refused.shader"
    text = COPIES.format(name="refused", pragma="#pragma geometry geom", left=-0.45, right=0.45,
                         colour="IN[k].uv", primitive_id="")
    shader.write_text(textwrap.dedent(text.replace(*change)))
    data = corpus.scene_for(shader)
    with pytest.raises(PbrlabError, match=r"refused\.shader:\d+: .*" + named.replace("[", r"\[").replace("(", r"\(")
                       .replace(")", r"\)").replace("]", r"\]")):
        render_scene(parse_scene(data, "t", tmp_path), language="glsl")


# The same copies made by functions of the program that take the stream (HLSL allows an
# ``inout TriangleStream<T>`` parameter anywhere).
HELPERS = """
        void emit(inout TriangleStream<g2f> s, v2g v, float shift, float ident) {{
            g2f o;
            o.pos = v.pos;
            o.pos.x += shift * o.pos.w;
            o.colour = float3(v.uv, ident);
            s.Append(o);
        }}
        void copy(v2g IN[3], inout TriangleStream<g2f> s, float shift, float ident) {{
            for (int k = 0; k < 3; k++) emit(s, IN[k], shift, ident);
            s.RestartStrip();
        }}
        [maxvertexcount(6)]
        void geom(triangle v2g IN[3], inout TriangleStream<g2f> triStream) {{
            copy(IN, triStream, -0.45, 0.25);
            copy(IN, triStream, 0.45, 0.75);
        }}
"""


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_stream_handed_to_functions_emits_the_same(tmp_path, language):
    text = COPIES.replace(COPIES[COPIES.index("        [maxvertexcount(6)]"):COPIES.index("        float4 frag")], HELPERS)
    shader = tmp_path / "helpers.shader"
    shader.write_text(textwrap.dedent(text.format(name="helpers", pragma="#pragma geometry geom")))
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    assert copies_problems(image) == []


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_position_passes_as_sv_position(tmp_path, language):
    """A struct member with the legacy POSITION semantic is the clip position between the stages
    (as SV_Position), also into and out of the geometry stage."""
    text = COPIES.replace("SV_POSITION", "POSITION").format(
        name="position", pragma="#pragma geometry geom", left=-0.45, right=0.45, colour="IN[k].uv", primitive_id="")
    shader = tmp_path / "position.shader"
    shader.write_text(textwrap.dedent(text))
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    assert copies_problems(image) == []


# A ForwardBase pass drawing black and a ForwardAdd pass drawing the light of each further light
# (_LightColor0: pbrlab folds a point light's falloff in at the surface point), with or without a
# geometry stage that passes each triangle through.
FORWARD_ADD = """Shader "t/add" {{
    SubShader {{
        Pass {{ Tags {{ "LightMode" = "ForwardBase" }}
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION {{ return UnityObjectToClipPos(v); }}
            fixed4 frag() : SV_Target {{ return 0; }}
            ENDCG
        }}
        Pass {{ Tags {{ "LightMode" = "ForwardAdd" }} Blend One One
            CGPROGRAM
            #pragma vertex vert
            {pragma}
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct v2g {{ float4 pos : SV_POSITION; }};
            v2g vert(float4 v : POSITION) {{ v2g o; o.pos = UnityObjectToClipPos(v); return o; }}
            [maxvertexcount(3)]
            void geom(triangle v2g IN[3], inout TriangleStream<v2g> s) {{
                for (int k = 0; k < 3; k++) s.Append(IN[k]);
            }}
            float4 frag(v2g i) : SV_Target {{ return float4(_LightColor0.rgb, 1); }}
            ENDCG
        }}
    }}
}}
"""
# The fragment's surface point behind a geometry stage is solved from each emitted vertex's clip
# position (geometry_stage: three rows of P, then V^-1): float32, a 3 x 3 inverse of condition
# ~3 and two matrix products, about 30 roundings of 6e-8 times 3 = 5e-6 relative in the point,
# doubled by the inverse-square falloff: 1e-5. Measured: 1.7e-6 (both languages).
ADD_BOUND = 1e-5


def _forward_add(tmp_path, language, name, pragma, offset=0.0):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(FORWARD_ADD.format(pragma=pragma)))
    data = corpus.scene_for(shader)
    data["objects"][0]["transform"] = {"translate": [offset, 0.0, 0.0]}
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_point_light_is_evaluated_at_the_emitted_surface(tmp_path, language):
    """With the corpus scene's point light, a pass-through geometry stage gives the fragment
    the surface point the vertex stage would: the ForwardAdd light agrees with the pass without
    one. Control: the sphere moved by 1e-3 (every point off by that much) exceeds the bound."""
    plain = _forward_add(tmp_path, language, "plain", "")
    geometry = _forward_add(tmp_path, language, "geometry", "#pragma geometry geom")
    moved = _forward_add(tmp_path, language, "moved", "", offset=1e-3)
    covered = (plain[..., 3] > 0) & (moved[..., 3] > 0)
    assert plain[covered][:, :3].max() > 0.1  # the point light reaches the sphere

    def worst(image):
        return (np.abs(image - plain)[..., :3].max(-1) / np.maximum(plain[..., :3].max(-1), 1e-3))[covered].max()
    assert worst(geometry) <= ADD_BOUND
    assert worst(moved) > ADD_BOUND


def test_the_spelling_keeps_to_the_functions_that_take_a_stream():
    """A variable of another function named as a stream parameter keeps its uses."""
    text = ("float2 f(float x) { float s, c; sincos(x, s, c); return float2(s, c); }\n"
            "void emit(inout TriangleStream<g2f> s, g2f o) { s.Append(o); }\n"
            "void geom(triangle v2g IN[3], inout TriangleStream<g2f> s) { emit(s, o); }\n")
    spelled = spell_for_glsl(text)
    assert "sincos(x, s, c); return float2(s, c);" in spelled
    assert "void emit( g2f o) { PBRLAB_GEOMETRY_APPEND(o); }" in spelled.replace("  ", " ")
    assert "{ emit(o); }" in spelled


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_maxvertexcount_may_be_an_expression_of_the_programs_macros(tmp_path, language):
    """[maxvertexcount(COPIES * 3)] with #define COPIES 2 (GLSL: after the program, whose macros it
    names; a constant expression in a layout is GL_ARB_enhanced_layouts')."""
    text = COPIES.replace("[maxvertexcount(6)]", "#define COPIES 2\n        [maxvertexcount(COPIES * 3)]").format(
        name="expression", pragma="#pragma geometry geom", left=-0.45, right=0.45, colour="IN[k].uv", primitive_id="")
    shader = tmp_path / "expression.shader"
    shader.write_text(textwrap.dedent(text))
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    assert copies_problems(image) == []


# A bare value per vertex (FXC reads ``triangle float4 IN[3] : SV_POSITION`` as one member that
# carries the array's semantic): the vertex stage returns the clip position alone, and the
# geometry function colours each copy from it, (u, v) = (a/2 + 1/2, 1/2 - b/2) with a = x / 0.3,
# b = -y / 0.5 (the clip position's x and y, module docstring), the expectation above.
BARE = {
    "        v2g vert(appdata_base v) {{": "        float4 vert(appdata_base v) : SV_POSITION {{",
    "            v2g o;\n": "",
    "            o.pos = float4(": "            return float4(",
    "            o.uv = v.texcoord.xy;\n            return o;\n": "",
    "triangle v2g IN[3]": "triangle float4 IN[3] : SV_POSITION",
    "o.pos = IN[k].pos;": "o.pos = IN[k];",
}


def _bare(tmp_path, language, colour="float2(IN[k].x / 0.6 + 0.5, 0.5 + IN[k].y)", semantic=True):
    text = COPIES
    for old, new in BARE.items():
        assert old in text
        text = text.replace(old, new)
    if not semantic:
        text = text.replace(" : SV_POSITION, inout", ", inout")
    shader = tmp_path / "bare.shader"
    shader.write_text(textwrap.dedent(text.format(name="bare", pragma="#pragma geometry geom", left=-0.45,
                                                  right=0.45, colour=colour, primitive_id="")))
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_bare_value_per_vertex_is_the_geometry_input(tmp_path, language):
    image = _bare(tmp_path, language)
    assert image[..., 3].mean() > 0.3
    assert copies_problems(image) == []
    # control: u from the clip position's y instead of x: the float64 check rejects it
    assert copies_problems(_bare(tmp_path, language, colour="float2(IN[k].y / 0.6 + 0.5, 0.5 + IN[k].y)")) != []


def test_a_bare_geometry_input_without_a_semantic_is_named(tmp_path):
    with pytest.raises(PbrlabError, match=r"bare\.shader:\d+: .*array of float4 without a semantic"):
        _bare(tmp_path, "glsl", semantic=False)
