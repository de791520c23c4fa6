"""Constructs of real Unity shaders (issue 34's hidden6 sample, session 45: measured, not
committed) that FXC accepts and the GLSL port or glslang's HLSL front end refused, each in a
minimal shader of ours, drawn in both languages; the fragment returns values computed from the
construct, checked on every covered pixel against float64 (HLSL's definition: Microsoft's HLSL
reference, Unity's HLSLSupport.cginc), with a control (the old behaviour restored) that the check
rejects.

Readback and tolerance as test_port_round43.py: the corpus scene's ``linear`` image is the
fragment's colour; EXACT is 2 ulp of 1 (every expected value below is a product of dyadic
fractions, exact in float32)."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types, port
from test_port_round43 import EXACT, LANGUAGES, _assert_colour, _covered_rgb, _shader
from test_geometry_shaders import UV_BOUND
from test_unity_names_round5 import _render  # pytest puts this folder on sys.path

MUL_BY_SCALAR = """
            float3 v = float3(0.25, 0.5, 0.125);
            float s = 1.5;
            float2x2 m = float2x2(0.5, 0.25, 0.125, 1.0);
            float3 a = mul(v, s);
            float3 b = mul(0.5, v);
            return float4(a.xy, b.z + mul(s, 0.25) * mul(m, 2.0)[0][1], 1);"""


def _mul_by_scalar_expected():
    """Microsoft's HLSL reference, "mul": with x or y a scalar, out = x * y componentwise."""
    v, s = np.array([0.25, 0.5, 0.125]), 1.5
    m = np.array([[0.5, 0.25], [0.125, 1.0]])  # HLSL's constructor takes rows
    a, b = v * s, 0.5 * v
    return [a[0], a[1], b[2] + (s * 0.25) * (m * 2.0)[0, 1]]


@pytest.mark.parametrize("language", LANGUAGES)
def test_mul_with_a_scalar_operand_is_the_componentwise_product(tmp_path, language, monkeypatch):
    """``mul(rayDir, currentDistance)`` (eurigilberto's VolumetricClouds): HLSL's mul of a vector
    or matrix and a scalar, either side, and of two scalars, is x * y (0.375, 0.75, 0.25 here).
    Control: without the port's spelling the GLSL port is refused as before ("no matching
    function for call to mul(vec3, float)"); glslang's HLSL front end took it already."""
    shader = _shader(tmp_path, "mul_scalar", MUL_BY_SCALAR)
    _assert_colour(tmp_path, shader, language, _mul_by_scalar_expected())
    if language == "glsl":
        monkeypatch.setattr(cg_types._Parser, "mul_by_scalar", lambda self, name, a, b: None)
        with pytest.raises(PbrlabError, match="mul"):
            _render(tmp_path, _shader(tmp_path, "mul_scalar_old", MUL_BY_SCALAR), language)


FIXED_MATRICES = """
            fixed3x3 m = fixed3x3(0.5, 0.25, 0, 0, 0.25, 0, 0, 0, 1);
            fixed2x2 n = fixed2x2(1, 0.5, 0, 1);
            fixed4x4 q = fixed4x4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.125, 0, 0, 0, 1);
            return float4(mul(m, float3(1, 1, 0.5)).xy, mul(n, float2(0, 0.5)).x + mul(q, float4(0, 0, 0, 1)).z, 1);"""


def _fixed_matrices_expected():
    """HLSLSupport.cginc: fixedRxC is halfRxC, an HLSL matrix of R rows (the constructor's
    arguments row by row), mul(M, v) = M v."""
    m = np.array([[0.5, 0.25, 0], [0, 0.25, 0], [0, 0, 1]])
    n = np.array([[1, 0.5], [0, 1]])
    q = np.eye(4)
    q[2, 3] = 0.125
    a = m @ np.array([1, 1, 0.5])
    return [a[0], a[1], (n @ np.array([0, 0.5]))[0] + (q @ np.array([0, 0, 0, 1]))[2]]


@pytest.mark.parametrize("language", LANGUAGES)
def test_fixed_square_matrices(tmp_path, language):
    """``fixed3x3 TBN = fixed3x3(...)`` (corsair0909's Dota2 shader): Unity's HLSLSupport.cginc
    defines fixed2x2, fixed3x3 and fixed4x4 beside fixed..fixed4; the HLSL path (the hand-written
    shim's fixed* macros) lacked the matrices ("'fixed3x3' : unknown variable"). Expected
    (0.75, 0.25, 0.375): a row/column mix-up shows. Control: the same program with the names
    taken away (#undef) is refused in HLSL as before; the GLSL port renames the Cg types itself."""
    _assert_colour(tmp_path, _shader(tmp_path, "fixed_matrices", FIXED_MATRICES), language,
                   _fixed_matrices_expected())
    if language == "hlsl":
        undone = "        #undef fixed2x2\n        #undef fixed3x3\n        #undef fixed4x4"
        with pytest.raises(PbrlabError, match="fixed"):
            _render(tmp_path, _shader(tmp_path, "fixed_matrices_old", FIXED_MATRICES, undone), language)


UNIFORM_DECLARE_HEAD = """
        uniform UNITY_DECLARE_TEX2D(_MainTex);
        uniform UNITY_DECLARE_TEX2DARRAY(_Layers);"""
UNIFORM_DECLARE_BODY = """
            float4 layer = UNITY_SAMPLE_TEX2DARRAY(_Layers, float3(i.uv, 0));
            return float4(0.25 * UNITY_SAMPLE_TEX2D(_MainTex, i.uv).r, 0.5, 0.75 + 0 * layer.a, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_uniform_before_a_declaring_macro(tmp_path, language, monkeypatch):
    """``uniform UNITY_DECLARE_TEX2DARRAY(_MainTex);`` (Amplify Shader Editor's
    TextureArrayInspector): a global is uniform anyway in HLSL; the GLSL macro writes its own
    ``uniform``. The unset 2D texture reads white (Unity's default), so (0.25, 0.5, 0.75).
    Control: the written word kept, the GLSL port is refused as before ("duplicate storage
    qualifier"); HLSL took it already."""
    shader = _shader(tmp_path, "uniform_declare", UNIFORM_DECLARE_BODY, UNIFORM_DECLARE_HEAD)
    _assert_colour(tmp_path, shader, language, [0.25, 0.5, 0.75])
    if language == "glsl":
        monkeypatch.setattr(port, "_drop_uniform_before_declaring_macro", lambda code: code)
        with pytest.raises(PbrlabError, match="storage qualifier"):
            _render(tmp_path, _shader(tmp_path, "uniform_declare_old", UNIFORM_DECLARE_BODY,
                                      UNIFORM_DECLARE_HEAD), language)


GEOMETRY_ARGUMENT = """
Shader "t/geometry_argument" {
    SubShader { Pass {
        Cull Off
        CGPROGRAM
        #pragma vertex vert
        #pragma geometry geom
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct v2g { float4 pos : SV_POSITION; };
        struct g2f { float4 pos : SV_POSITION; float3 colour : TEXCOORD0; };
        float Half(float angle) { return 0.5 * angle; }
        v2g vert(float4 vertex : POSITION) { v2g o; o.pos = UnityObjectToClipPos(vertex); return o; }
        [maxvertexcount(3)]
        void geom(triangle v2g IN[3], inout TriangleStream<g2f> stream) {
            float2 wind = float2(0.75, 0.25);
            g2f o;
            for (int k = 0; k < 3; k++) {
                o.pos = IN[k].pos;
                o.colour = float3(Half(wind), 0.25, 0.5);
                stream.Append(o);
            }
            stream.RestartStrip();
        }
        float4 frag(g2f i) : SV_Target { return float4(i.colour, 1); }
        ENDCG
    } }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_geometry_functions_calls_are_converted_as_fxc_does(tmp_path, language, monkeypatch):
    """``AngleAxis3x3(UNITY_PI * windSample, wind)`` in a geometry function (eangulee's Grass,
    a float2 to a float parameter): FXC passes the vector's first component (warning X3206,
    implicit truncation); the type pass skipped the whole function (its ``triangle v2g IN[3]``
    and ``inout TriangleStream<g2f>`` parameters and ``stream.Append``), so the HLSL as written
    kept the call glslang refuses. Expected (0.375, 0.25, 0.5): Half(0.75). Control: the
    parameters unread as before, the HLSL path is refused ("no matching overloaded function");
    the GLSL port (its geometry syntax respelled first) took it already."""
    shader = tmp_path / "geometry_argument.shader"
    shader.write_text(GEOMETRY_ARGUMENT)
    # the colour is a varying, interpolated perspective-correctly: test_geometry_shaders' bound
    rgb = _covered_rgb(_render(tmp_path, shader, language))
    assert np.abs(rgb - [0.375, 0.25, 0.5]).max() <= UV_BOUND
    if language == "hlsl":
        monkeypatch.setattr(cg_types._Parser, "geometry_parameter_type", lambda self: None)
        old = tmp_path / "geometry_argument_old.shader"  # another text: the type pass is cached per text
        old.write_text(GEOMETRY_ARGUMENT.replace("float2 wind", "float2  wind"))
        with pytest.raises(PbrlabError, match="Half"):
            _render(tmp_path, old, language)
