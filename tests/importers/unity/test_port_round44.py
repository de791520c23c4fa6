"""Constructs of real Unity shaders (issue 34's samples, session 44: last session's hidden sets,
measured, not committed) that FXC accepts and the GLSL port, glslang's HLSL front end or both
refused, each in a minimal shader of ours, drawn in both languages; the fragment returns values
computed from the construct, checked on every covered pixel against float64 (HLSL's definition of
the construct: Microsoft's HLSL reference, Unity's CGIncludes), with a control (the old
behaviour restored, or the construct perturbed) that the check rejects.

Readback and tolerance as test_port_round43.py: the corpus scene's ``linear`` image is the
fragment's colour; EXACT is 2 ulp of 1 (each expected value below is exact in binary or one
rounding from it)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types, written_globals
from test_port_round43 import EXACT, LANGUAGES, _assert_colour, _covered_rgb, _shader
from test_unity_names_round5 import _render  # pytest puts this folder on sys.path

PBS = '        #include "UnityPBSLighting.cginc"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_unity_light_ndotl_and_dot_clamped(tmp_path, language):
    """UnityLight's deprecated member ndotl (UnityLightingCommon.cginc: assigned and read by older
    shaders, read by nothing of Unity's) and DotClamped (UnityStandardBRDF.cginc: max(0, a·b)):
    dir = (1, 2, 2) / 3 meets n = z at 2/3, the opposite normal at 0 (DotClamped's clamp: the
    control, where dot would give -2/3)."""
    body = """
            UnityLight l;
            l.color = float3(0.75, 0.375, 1.5);
            l.dir = float3(1, 2, 2) / 3.0;
            l.ndotl = DotClamped(l.dir, float3(0, 0, 1));
            return float4(l.color.xy * l.ndotl, DotClamped(l.dir, float3(0, 0, -1)), 1);"""
    _assert_colour(tmp_path, _shader(tmp_path, "ndotl", body, PBS), language, [0.5, 0.25, 0.0])


@pytest.mark.parametrize("language", LANGUAGES)
def test_unity_gi_input_probe_hdr(tmp_path, language):
    """UnityGIInput's probeHDR[2] (UnityGlobalIllumination.cginc), which shaders fill from
    unity_SpecCube0_HDR: stored and read back; the second element apart (the control: an index
    mix-up shows)."""
    body = """
            UnityGIInput d;
            d.probeHDR[0] = float4(0.5, 0.25, 0.125, 1);
            d.probeHDR[1] = float4(0.75, 0.625, 0.875, 1);
            return float4(d.probeHDR[0].xy, d.probeHDR[1].z, 1);"""
    _assert_colour(tmp_path, _shader(tmp_path, "probe_hdr", body, PBS), language, [0.5, 0.25, 0.875])


GLOBAL_BY_OUT_HEAD = """
        float g;
        float3 COLOR_BLACK = float3(0, 0, 0);
        void setIt(out float x) { x = 0.375; }"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_global_written_through_an_out_parameter(tmp_path, language, monkeypatch):
    """A global (a uniform to the compilers) passed to an out parameter (hyunxiGit's
    ``DiffuseAndSpecularFromMetallic(..., oneMinusReflectivity)``): FXC's backwards-compatibility
    mode lets the program write it, the value living in that invocation (written_globals); a
    global with an initialiser's commas beside it (``float3 COLOR_BLACK = float3(0, 0, 0)``) is
    not read as globals named ``0``, and ``max(g, 0)`` (in parameters) writes nothing. Control: the write through the
    call not seen (the old reading) is refused in both languages (a read-only variable)."""
    body = "            setIt(g); return float4(max(g, 0), COLOR_BLACK.x + 0.25, 0, 1);"
    _assert_colour(tmp_path, _shader(tmp_path, "out_global", body, GLOBAL_BY_OUT_HEAD), language, [0.375, 0.25, 0])
    monkeypatch.setattr(written_globals, "_written", lambda name, b, program="": False)  # the body has no assignment to g
    with pytest.raises(PbrlabError):
        _render(tmp_path, _shader(tmp_path, "out_global_old", body, GLOBAL_BY_OUT_HEAD), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_sv_primitive_id_is_the_triangles_index(tmp_path, language):
    """A fragment's ``uint id : SV_PrimitiveID`` (Amplify's PrimitiveID node, frettini's
    stochastic transparency): the index of the triangle in the draw. The corpus sphere has many
    triangles: pixels of triangle 0 give (1, 0), the others (0, 1), and both occur; the control
    is the old value, a constant 0 (HLSL; GLSL refused the int 0 given to a uint), which the
    second assertion rejects."""
    path = tmp_path / "primitive_id.shader"
    path.write_text(textwrap.dedent("""
        Shader "t/primitive_id" { SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 vertex : POSITION) : SV_POSITION { return UnityObjectToClipPos(vertex); }
            float4 frag(float4 pos : SV_POSITION, uint id : SV_PrimitiveID) : SV_Target {
                return float4(id == 0u ? 1.0 : 0.0, min(id, 1u), 0.5, 1);
            }
            ENDCG
        } } }
    """))
    rgb = _covered_rgb(_render(tmp_path, path, language))
    first = np.abs(rgb - [1.0, 0.0, 0.5]).max(axis=1) <= EXACT
    others = np.abs(rgb - [0.0, 1.0, 0.5]).max(axis=1) <= EXACT
    assert np.all(first | others)
    assert others.any() and others.mean() > 0.5


# The 4x4 of k/16, row by row (k = 1..16): HLSL's constructor takes rows.
MATRIX = "float4x4 a = float4x4(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16) / 16.0;"


def _a():
    return np.arange(1, 17, dtype=np.float64).reshape(4, 4) / 16.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_matrices_multiply_component_by_component(tmp_path, language, monkeypatch):
    """HLSL's ``*`` of two matrices is componentwise (Microsoft's HLSL reference, "Per-component
    math"), GLSL's the linear-algebra product; of a 3x3 and a 4x4 (chenzwsss's
    ``(float3x3)UNITY_MATRIX_I_V * UNITY_MATRIX_I_M``) FXC cuts the 4x4 to its upper-left 3x3
    first (the smaller's size). glslang's HLSL front end multiplies matrices as linear algebra too,
    so the HLSL as written calls a componentwise helper. Control: the old texts (neither call)
    draw the linear-algebra product of the same-size pair in both languages (44/256 where 4/256
    is due), and the GLSL port refused the mixed pair."""
    body = f"""
            {MATRIX}
            float3x3 b = (float3x3)a;
            float3x3 c = b * a;
            float3x3 d = b * b;
            return float4(c[1][0], d[0][1], d[2][2] + c[2][0] - c[2][0], 1);"""
    b = _a()[:3, :3]
    want = [(b * b)[1, 0], (b * b)[0, 1], (b * b)[2, 2]]
    _assert_colour(tmp_path, _shader(tmp_path, "matrix_product", body), language, want)
    assert abs((b @ b)[0, 1] - want[1]) > 0.1  # what GLSL's * alone gives
    monkeypatch.setattr(cg_types._Parser, "matrix_componentwise", lambda self, x, op, y, t: cg_types.E(x.s, y.e, None, False))
    same = f"""
            {MATRIX}
            float3x3 b = (float3x3)a;
            float3x3 d = b * b;
            return float4(d[1][0], d[0][1], d[2][2], 1);"""
    rgb = _covered_rgb(_render(tmp_path, _shader(tmp_path, "matrix_product_old", same), language))
    assert np.abs(rgb[:, 1] - want[1]).max() > 0.1
    if language == "glsl":
        with pytest.raises(PbrlabError):
            _render(tmp_path, _shader(tmp_path, "matrix_product_old_mixed", body), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_fxc_conversions_of_vectors_and_matrices(tmp_path, language):
    """Each, as FXC compiles it (Microsoft's HLSL reference):
    * ``mul(v3, w3)``, two vectors: their inner product ("mul": vector x vector -> scalar);
    * ``float2x2 m = v4``: a vector to a matrix of as many components, filled row by row
      ("Casting and conversions", vector-to-matrix): m[0][1] = v.y, m[1][0] = v.z, and
      mul(m, (1, 0)) is the first column (v.x, v.z);
    * ``n *= 0.75`` of an int: computed in float, converted back toward 0 (warning X3205):
      5 * 0.75 = 3.75 -> 3.
    Each value differs from the neighbouring misreading (the vector's column fill would swap
    v.y and v.z; an int product 5 * int(0.75) gives 0), the perturbation the check rejects."""
    body = """
            float3 v = float3(0.25, 0.5, 0.125), w = float3(0.5, 0.25, 1.0);
            float4 q = float4(0.125, 0.25, 0.5, 0.75);
            float2x2 m = q;
            float2 col = mul(m, float2(1, 0));
            int n = 5;
            n *= 0.75;
            return float4(mul(v, w), m[0][1] + 4.0 * m[1][0], col.y + 4.0 * col.x, 1) + float4(0, 0, n, 0) / 8.0;"""
    v, w, q = np.array([0.25, 0.5, 0.125]), np.array([0.5, 0.25, 1.0]), np.array([0.125, 0.25, 0.5, 0.75])
    m = q.reshape(2, 2)  # row by row
    col = m @ np.array([1.0, 0.0])
    n = int(5 * 0.75)
    want = [v @ w, m[0, 1] + 4.0 * m[1, 0], col[1] + 4.0 * col[0] + n / 8.0]
    assert abs(want[1] - (m[1, 0] + 4.0 * m[0, 1])) > 0.1  # the column fill's value
    _assert_colour(tmp_path, _shader(tmp_path, "fxc_conversions", body), language, want)


@pytest.mark.parametrize("language", LANGUAGES)
def test_sample_level_of_a_longer_location(tmp_path, language):
    """``SampleLevel`` of a TextureCube given a float4 location (yunyufeiwei's
    ``SAMPLE_TEXTURECUBE_LOD(t, s, float4(dir, mip), 3)``): FXC passes its first three (warning
    X3206); the GLSL port built a five-component float4. The cube, a property-less one, is the
    scene's environment (unset_samplers): the float4 location reads what its xyz reads, on every
    pixel; the control, the opposite direction (ground for sky), reads another colour."""
    head = """
        TextureCube _Cube; SamplerState sampler_Cube;"""

    def drawn(name, location):
        body = f"""
            return float4(_Cube.SampleLevel(sampler_Cube, {location}, 0).rgb, 1);"""
        return _covered_rgb(_render(tmp_path, _shader(tmp_path, name, body, head), language))

    longer = drawn("cube_float4", "float4(0, 1, 0, 7)")
    assert np.all(np.isfinite(longer))
    assert np.abs(longer - drawn("cube_float3", "float3(0, 1, 0)")).max() <= EXACT
    assert np.abs(longer - drawn("cube_down", "float3(0, -1, 0)")).max() > 0.01


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_library_function_given_a_longer_vector(tmp_path, language, monkeypatch):
    """``Linear01Depth(tex2D(_CameraDepthTexture, uv))`` (seyedmoeinsaadati's ShowDepth): a
    float4 to UnityCG's float parameter, which FXC cuts to its first component (warning X3206);
    glslang's HLSL found no overload. Drawn as the ``.r`` form draws it; control: without the
    cut in the HLSL as written (the old reading of a library function), HLSL is refused."""
    head = """
        sampler2D _CameraDepthTexture;"""

    def drawn(name, read, green=0.25):
        body = f"""
            return float4(Linear01Depth({read}), {green}, 0.5, 1);"""
        return _covered_rgb(_render(tmp_path, _shader(tmp_path, name, body, head), language))

    whole = drawn("depth_float4", "tex2D(_CameraDepthTexture, i.uv)")
    assert np.all(np.isfinite(whole))
    assert np.abs(whole - drawn("depth_r", "tex2D(_CameraDepthTexture, i.uv).r")).max() <= EXACT
    if language == "hlsl":
        monkeypatch.setattr(cg_types._Parser, "fxc_argument", lambda self, a, param: None)
        with pytest.raises(PbrlabError):
            drawn("depth_float4_old", "tex2D(_CameraDepthTexture, i.uv)", 0.125)  # another program: none reused


GEOMETRY_UINT = """
Shader "t/geometry_uint" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma geometry geom
    #pragma fragment frag
    #include "UnityCG.cginc"
    struct v2g { float4 pos : SV_POSITION; };
    struct g2f { float4 pos : SV_POSITION; uint layer : TEXCOORD1; };
    v2g vert(float4 vertex : POSITION) { v2g o; o.pos = UnityObjectToClipPos(vertex); return o; }
    [maxvertexcount(3)]
    void geom(triangle v2g IN[3], inout TriangleStream<g2f> stream) {
        g2f o;
        for (int k = 0; k < 3; k++) { o.pos = IN[k].pos; o.layer = uint(3); stream.Append(o); }
    }
    float4 frag(g2f i) : SV_Target { return float4(i.layer / 4.0, 0.5, 0.25, 1); }
    ENDCG
} } }
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_geometry_stage_passes_a_uint(tmp_path, language, monkeypatch):
    """A geometry stage's uint output (frettini's shell layers, ``uint layerNum : TEXCOORD1``):
    flat in both stages (an integer varying is flat in GLSL; the HLSL path's spirv-cross
    geometry output was plain, and GLSL 3.30 refused to link it to the flat fragment input).
    The layer, 3, reaches the fragment: 3 / 4. Control: the HLSL path's output left plain is
    refused (the link error)."""
    path = tmp_path / "geometry_uint.shader"
    path.write_text(GEOMETRY_UINT)
    rgb = _covered_rgb(_render(tmp_path, path, language))
    assert np.abs(rgb - [0.75, 0.5, 0.25]).max() <= EXACT
    if language == "hlsl":
        from pbrlab.importers.unity import geometry_stage
        renamed = geometry_stage.hlsl_renamed
        monkeypatch.setattr(geometry_stage, "hlsl_renamed", lambda vf, glsl: renamed(vf, glsl).replace("flat out", "out"))
        path = tmp_path / "geometry_uint_old.shader"
        path.write_text(GEOMETRY_UINT.replace("uint(3)", "uint(2)"))  # another program: no compiled one reused
        with pytest.raises(PbrlabError):
            _render(tmp_path, path, language)
