"""Unity tessellation (``#pragma hull`` / ``#pragma domain``, issue 34): the hull, patch-constant
and domain functions run between the pass's vertex and fragment stages in both languages (HLSL
as written through glslang's tesc/tese stages; GLSL through the port), checked per pixel against
a float64 expectation.

The test shader places the plane's corners (a, b) = (x, z) / 0.3 at clip (S a, -S b, 0, 1)
(a square of half side S in NDC, no camera), tessellates each of its two triangles with every
level FACTOR (integer partitioning) and, in the domain function, moves each generated vertex
that lies on a patch edge (one domain coordinate exactly 0: GL 4.0 section 2.12.2 places the
outer edges' vertices at coordinates with one component 0) outward from the opposite corner by
h = 4 A s t, s and t the edge's two other coordinates (s + t = 1). Integer partitioning of an
outer level n puts the edge's vertices at t = i / n (equal_spacing; D3D11's integer mode alike),
so each side of the square bulges as the polyline through (t_i, h(t_i)): a pixel outside the
square is covered where its distance beyond a side is below that polyline's height. Factor 1
puts only the corners (h = 0) there: the flat square, the control.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.tessellation_syntax import spell_for_glsl
from pbrlab.render.renderer import render_scene

S, A = 0.6, 0.25
# A pixel centre this close (in pixels) to the covered region's edge may fall either way under
# the rasteriser's fixed-point snapping (llvmpipe: 1/256 px) and the float32 positions of the
# generated vertices (a few ulp of values <= 1 in NDC: < 1e-6 px at 64 px): left out.
EDGE_PX = 0.02

BULGE = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        Cull Off
        CGPROGRAM
        #pragma target 5.0
        #pragma vertex vert
        #pragma hull hull
        #pragma domain domain
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct ControlPoint {{ float4 position : INTERNALTESSPOS; float2 uv : TEXCOORD0; }};
        struct Factors {{ float edge[3] : SV_TessFactor; float inside : SV_InsideTessFactor; }};
        struct v2f {{ float4 pos : SV_POSITION; float3 colour : TEXCOORD0; }};
        ControlPoint vert(appdata_base v) {{
            ControlPoint o;
            o.position = float4({s} * v.vertex.x / 0.3, -{s} * v.vertex.z / 0.3, 0.0, 1.0);
            o.uv = v.texcoord.xy;
            return o;
        }}
        Factors levels(InputPatch<ControlPoint, 3> patch) {{
            Factors f;
            f.edge[0] = {factor}; f.edge[1] = {factor}; f.edge[2] = {factor}; f.inside = {factor};
            return f;
        }}
        [domain("tri")]
        [outputcontrolpoints({points})]
        [outputtopology("triangle_cw")]
        [partitioning("{partitioning}")]
        [patchconstantfunc("levels")]
        ControlPoint hull(InputPatch<ControlPoint, 3> patch, uint id : SV_OutputControlPointID) {{
            return patch[id];
        }}
        // the vertex on the edge opposite corner k (coordinate k is 0) moves away from corner k
        float2 outward(float2 p0, float2 p1, float2 away) {{
            float2 e = p1 - p0;
            float2 n = normalize(float2(-e.y, e.x));
            return dot(n, away - p0) > 0 ? -n : n;
        }}
        [domain("tri")]
        v2f domain(Factors f, OutputPatch<ControlPoint, 3> patch, float3 b : SV_DomainLocation) {{
            v2f o;
            float4 p = patch[0].position * b.x + patch[1].position * b.y + patch[2].position * b.z;
            float2 p0 = patch[0].position.xy, p1 = patch[1].position.xy, p2 = patch[2].position.xy;
            if (b.x == 0) p.xy += outward(p1, p2, p0) * 4 * {a} * b.y * b.z;
            if (b.y == 0) p.xy += outward(p0, p2, p1) * 4 * {a} * b.x * b.z;
            if (b.z == 0) p.xy += outward(p0, p1, p2) * 4 * {a} * b.x * b.y;
            o.pos = p;
            o.colour = float3(patch[0].uv * b.x + patch[1].uv * b.y + patch[2].uv * b.z, 1);
            return o;
        }}
        float4 frag(v2f i) : SV_Target {{ return float4(i.colour, 1); }}
        ENDCG
    }} }}
}}
"""


def _text(name, factor=4, partitioning="integer", points=3):
    return textwrap.dedent(BULGE.format(name=name, s=S, a=A, factor=float(factor), partitioning=partitioning,
                                        points=points))


def _render(tmp_path, language, name, **kw):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(_text(name, **kw))
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def _covered(X, Y, n):
    """Whether the NDC point (X, Y) lies in the square with its sides bulged by the polyline of
    h(t) = 4 A t (1 - t) through t = i / n (module docstring), float64."""
    inside = (np.abs(X) <= S) & (np.abs(Y) <= S)
    knots = np.arange(n + 1) / n
    heights = 4 * A * knots * (1 - knots)
    for along, across in ((Y, X), (Y, -X), (X, Y), (X, -Y)):  # the four sides
        t = (along + S) / (2 * S)
        beyond = across - S
        ok = (t >= 0) & (t <= 1) & (beyond > 0)
        inside |= ok & (beyond <= np.interp(t, knots, heights))
    return inside


def expected_coverage(size, n):
    """(covered, near an edge) per pixel; row 0 is the top (NDC y = +1)."""
    h, w = size
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    covered = _covered(X, Y, n)
    d = EDGE_PX * 2 / w
    near = np.zeros_like(covered)
    for dx in (-d, d):
        for dy in (-d, d):
            near |= _covered(X + dx, Y + dy, n) != covered
    return covered, near


def coverage_problems(image, n) -> list[str]:
    covered, near = expected_coverage(image.shape[:2], n)
    wrong = ((image[..., 3] > 0) != covered) & ~near
    return [f"{int(wrong.sum())} pixels covered where float64 says otherwise"] if wrong.any() else []


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_domain_stage_moves_the_generated_edge_vertices(tmp_path, language):
    image = _render(tmp_path, language, "bulge")
    covered, _ = expected_coverage(image.shape[:2], 4)
    assert (covered & ~((np.abs(np.arange(64) + 0.5 - 32) / 32 <= S)[:, None]
                        & (np.abs(np.arange(64) + 0.5 - 32) / 32 <= S)[None, :])).sum() > 40  # the bulges
    assert coverage_problems(image, 4) == []
    assert coverage_problems(image, 2)  # control: another level's polyline is rejected


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_factor_one_draws_the_flat_patch(tmp_path, language):
    image = _render(tmp_path, language, "flat", factor=1)
    assert coverage_problems(image, 1) == []
    assert coverage_problems(image, 4)  # control: the tessellated expectation is rejected


def test_the_languages_agree(tmp_path):
    """The GLSL port and the HLSL as written draw the same pixels (coverage and the interpolated
    uv: measured identical)."""
    glsl, hlsl = (_render(tmp_path, language, f"agree_{language}") for language in ("glsl", "hlsl"))
    assert np.abs(glsl - hlsl).max() <= 1e-6


@pytest.mark.parametrize("partitioning, spacing", [("integer", "equal_spacing"),
                                                    ("fractional_odd", "fractional_odd_spacing"),
                                                    ("fractional_even", "fractional_even_spacing")])
def test_partitioning_is_the_gl_spacing(tmp_path, partitioning, spacing):
    """Each D3D11 partitioning mode reaches the evaluation stage as GL's spacing (GL 4.0 section
    2.12.2), in both languages; at a whole odd (even) level the fractional modes place the
    integer mode's vertices, so level 3 (4) draws the integer polyline."""
    from pbrlab.importers.unity.tessellation_syntax import SPACINGS
    assert SPACINGS[partitioning] == spacing
    level = 4 if partitioning == "fractional_even" else 3
    for language in ("glsl", "hlsl"):
        image = _render(tmp_path, language, f"{partitioning}_{language}", factor=level, partitioning=partitioning)
        assert coverage_problems(image, level) == []


def test_the_glsl_spelling_keeps_lines_and_spells_the_patches():
    text = ('[domain("tri")]\n[patchconstantfunc("pc")]\nCP hull(InputPatch<CP, 3> p,\n uint id) {\n}\n'
            "D dom(F f, const OutputPatch<CP, 3> q) { return q[0]; }\n")
    spelled = spell_for_glsl(text)
    assert spelled.count("\n") == text.count("\n")
    assert "domain" not in spelled and "patchconstantfunc" not in spelled
    assert "CP p[3]" in spelled and "CP q[3]" in spelled
    assert spell_for_glsl("float4 f(float x) { return x; }") == "float4 f(float x) { return x; }"


@pytest.mark.parametrize("change, named", [
    (('[patchconstantfunc("levels")]', ""), "no \\[patchconstantfunc"),
    (("[outputcontrolpoints(3)]", "[outputcontrolpoints(4)]"), "outputcontrolpoints\\(4\\)\\] differs"),
    (('[partitioning("integer")]', '[partitioning("pow2")]'), "GL has no pow2"),
    (("#pragma domain domain", ""), "#pragma hull without #pragma domain"),
])
def test_a_malformed_hull_is_named(tmp_path, change, named):
    shader = tmp_path / "refused.shader"
    shader.write_text(_text("refused").replace(*change))
    data = corpus.scene_for(shader)
    with pytest.raises(PbrlabError, match=r"refused\.shader:\d+: .*" + named):
        render_scene(parse_scene(data, "t", tmp_path), language="glsl")


PLAIN_VERTEX = """v2f plain(appdata_base v) {
            v2f o;
            o.pos = float4(%s * v.vertex.x / 0.3, -%s * v.vertex.z / 0.3, 0.0, 1.0);
            o.colour = 1;
            return o;
        }
        ControlPoint vert(""" % (S, S)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_triangle_cw_keeps_the_front_faces(tmp_path, language):
    """Under Cull Back a level-1 patch of [outputtopology("triangle_cw")] covers what the mesh
    drawn without tessellation does (Unity's tessellation shaders draw their front faces so:
    tessellation_syntax.ORDERS); control: triangle_ccw turns them to back faces (nothing drawn)."""
    def coverage(name, text):
        shader = tmp_path / f"{name}.shader"
        shader.write_text(text.replace("Cull Off", "Cull Back"))
        data = corpus.scene_for(shader)
        data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
        return render_scene(parse_scene(data, "t", tmp_path), language=language).linear[..., 3] > 0
    plain = _text("plain").replace("#pragma hull hull", "").replace("#pragma domain domain", "")
    plain = plain.replace("#pragma vertex vert", "#pragma vertex plain").replace("ControlPoint vert(", PLAIN_VERTEX)
    flat = coverage("plain", plain)
    assert flat.mean() > 0.3
    assert np.array_equal(coverage("cw", _text("cw", factor=1)), flat)
    assert not coverage("ccw", _text("ccw", factor=1).replace("triangle_cw", "triangle_ccw")).any()


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_patch_constant_struct_reaches_the_domain(tmp_path, language):
    """A member of the patch-constant struct besides the levels (an array of a custom semantic)
    is the domain function's: the colour it writes, exactly (a patch varying, not interpolated);
    control: the colour of the uv interpolation (the test shader's own) differs."""
    text = _text("tint").replace("float inside : SV_InsideTessFactor; }", "float inside : SV_InsideTessFactor; "
                                 "float3 tint[2] : TINT; }")
    text = text.replace("f.inside = 4.0;", "f.inside = 4.0; f.tint[0] = 0; f.tint[1] = float3(0.25, 0.5, 0.75);")
    text = text.replace("o.colour = float3(", "o.colour = f.tint[1] + 0 * float3(")
    shader = tmp_path / "tint.shader"
    shader.write_text(text)
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    drawn = image[..., 3] > 0
    assert drawn.mean() > 0.3
    assert np.array_equal(image[drawn][:, :3], np.tile([0.25, 0.5, 0.75], (int(drawn.sum()), 1)))
    plain = _render(tmp_path, language, "untinted")
    assert not np.array_equal(plain[drawn][:, :3], image[drawn][:, :3])
