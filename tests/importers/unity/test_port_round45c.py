"""Constructs of real built-in-pipeline shaders (issue 34's hidden7 sample, session 45, third
round: measured, not committed) that FXC accepts and the GLSL port refused, each in a minimal
shader of ours drawn in both languages; the fragment returns values computed from the construct,
checked on every covered pixel against float64 (Microsoft's HLSL reference, Unity's UnityCG),
with a control (the old behaviour restored) that the check rejects. Readback and tolerance as
test_port_round43.py (EXACT: 2 ulp of 1; every value is a sum of products of dyadic fractions)."""

from __future__ import annotations

import re
import textwrap

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_spellings, cg_types, written_globals
from test_port_round43 import EXACT, LANGUAGES, _assert_colour, _shader
from test_unity_names_round5 import _covered, _render  # pytest puts this folder on sys.path

# prprprprprppr's ParallaxHeight2: ``TANGENT_SPACE_ROTATION; float3 p = mul(rotation, v.vertex);``
ROTATION_HEAD = """
        struct my_in { float3 normal; float4 tangent; };
        float3 my_rotated(my_in v) {
            TANGENT_SPACE_ROTATION;
            return mul(rotation, float4(0.25, 0.5, 0.125, 8.0)) + binormal * 0.0;
        }"""
ROTATION = """
            my_in v;
            v.normal = float3(0, 0, 1);
            v.tangent = float4(0, 1, 0, 1);
            return float4(my_rotated(v) + 0.5, 1);"""


def _rotation_expected():
    """UnityCG.cginc's TANGENT_SPACE_ROTATION: binormal = cross(normalize(n), normalize(t.xyz)) *
    t.w, rotation's rows (t.xyz, binormal, n); mul(float3x3, float4) takes the vector's first three
    components (FXC warning X3206, "Implicit conversions")."""
    n, t = np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0, 1.0])
    binormal = np.cross(n, t[:3]) * t[3]
    rotation = np.array([t[:3], binormal, n])
    return rotation @ np.array([0.25, 0.5, 0.125]) + 0.5


@pytest.mark.parametrize("language", LANGUAGES)
def test_tangent_space_rotation_declares_its_locals(tmp_path, language, monkeypatch):
    """The locals TANGENT_SPACE_ROTATION declares (binormal, rotation) are typed for the
    statements after it, so ``mul(rotation, float4)`` is cut to the float3 as FXC does:
    (1.0, 0.25, 0.625). Control: the macro's locals unknown (the old reading), the GLSL port is
    refused ("no matching function for call to `mul(mat3, vec4)'")."""
    shader = _shader(tmp_path, "rotation", ROTATION, ROTATION_HEAD)
    _assert_colour(tmp_path, shader, language, _rotation_expected())
    if language == "glsl":
        monkeypatch.setattr(cg_types, "_DECLARING_STATEMENTS", {})
        with pytest.raises(PbrlabError, match="mul"):
            _render(tmp_path, _shader(tmp_path, "rotation_old", ROTATION, ROTATION_HEAD), language)


# prprprprprppr's ParallaxHeightWithSoftShadow: ``void ParallaxFunc(in out float2 uv, float3 view)``
IN_OUT_HEAD = """
        void my_step(in out float2 uv, float k) { uv = uv * k + 0.25; }"""
IN_OUT = """
            float2 uv = float2(0.5, 0.125);
            my_step(uv, 0.5);
            my_step(uv, 0.5);
            return float4(uv, 0.75, 1);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_in_out_is_inout(tmp_path, language, monkeypatch):
    """HLSL reads ``in out`` as ``inout`` (Microsoft's HLSL reference, "Function parameters"): the
    argument is written back, twice: uv = (uv * 0.5 + 0.25) * 0.5 + 0.25. Control: the two words
    left, the GLSL port is refused ("duplicate in/out/inout qualifier")."""
    uv = np.array([0.5, 0.125])
    for _ in range(2):
        uv = uv * 0.5 + 0.25
    shader = _shader(tmp_path, "in_out", IN_OUT, IN_OUT_HEAD)
    _assert_colour(tmp_path, shader, language, [uv[0], uv[1], 0.75])
    if language == "glsl":
        monkeypatch.setattr(cg_spellings, "_IN_OUT", re.compile(r"(?!x)x"))
        with pytest.raises(PbrlabError, match="duplicate in/out/inout"):
            _render(tmp_path, _shader(tmp_path, "in_out_old", IN_OUT, IN_OUT_HEAD), language)


# Amplify's Preview_NandNode: ``(!tex2D(_A, uv) && !tex2D(_B, uv)) ? 1.xxxx : 0.xxxx``;
# abcwangxiaoqi's DepthTroughtWall02: ``if (player < 1.0 & depth < 1.0 & depth > 0 & player > depth)``.
LOGIC = """
            float4 a = float4({a});
            float4 b = float4(0, 0, 1, 1);
            float p = {p};
            float d = 0.25;
            float4 n = (!a && !b) ? 0.75 : 0.25;
            float4 o = (a || b) ? 0.75 : 0.25;
            float k = ((p < 1.0 & d < 1.0 & d > 0) | (p > 2.0)) ^ (d > 1.0) ? 1.0 : 0.0;
            return float4(n.x, n.y, o.y * k, 1);"""


def _logic_expected(a, p):
    """HLSL's && and || of vectors are componentwise (Microsoft's HLSL reference, "Operators":
    Boolean math operators work per component), ``!v`` is v == 0 per component, and the ternary
    of a bool vector selects per component; & | ^ of bools are FXC's integer 0/1 operations,
    the logical and, or, xor."""
    a, b, d = np.array(a, np.float64), np.array([0.0, 0.0, 1.0, 1.0]), 0.25
    n = np.where((a == 0) & (b == 0), 0.75, 0.25)
    o = np.where((a != 0) | (b != 0), 0.75, 0.25)
    k = 1.0 if ((p < 1.0 and d < 1.0 and d > 0) or p > 2.0) != (d > 1.0) else 0.0
    return [n[0], n[1], o[1] * k]


@pytest.mark.parametrize("language", LANGUAGES)
def test_vector_logic_is_componentwise_and_bitwise_bools_are_logical(tmp_path, language):
    """The pixel follows HLSL's rules for two inputs: (0.75, 0.25, 0.75) and, perturbed (a's x
    set, p past 1), (0.25, 0.25, 0): the control, which the first expectation rejects. (The GLSL
    port refused both constructs before: "LHS of `&&' must be scalar boolean", "LHS of `&' must
    be an integer".)"""
    cases = (("0, 1, 0, 1", 0.5), ("1, 1, 0, 1", 1.5))
    wants = [_logic_expected([float(c) for c in a.split(",")], p) for a, p in cases]
    assert np.abs(np.subtract(wants[0], wants[1])).max() >= 0.5  # the control moves the pixel
    for i, ((a, p), want) in enumerate(zip(cases, wants)):
        shader = _shader(tmp_path, f"logic{i}", LOGIC.format(a=a, p=p))
        _assert_colour(tmp_path, shader, language, want)


# anohis's Blocking and Ghost: a geometry function writes a global of the material
# (``_Alpha = _Alpha * (1 - _Step);``). The geometry function emits the triangle only where the
# value it wrote is the one expected, so the check reads no interpolated value.
WRITTEN_IN_GEOMETRY = """
Shader "t/{name}" {{
    Properties {{ _Amount ("a", Float) = 0.5 }}
    SubShader {{ Pass {{
        Cull Off
        CGPROGRAM
        #pragma vertex vert
        #pragma geometry geom
        #pragma fragment frag
        #include "UnityCG.cginc"
        float _Amount;
        struct v2g {{ float4 pos : SV_POSITION; }};
        struct g2f {{ float4 pos : SV_POSITION; }};
        v2g vert(appdata_base v) {{ v2g o; o.pos = UnityObjectToClipPos(v.vertex); return o; }}
        [maxvertexcount(3)]
        void geom(triangle v2g IN[3], inout TriangleStream<g2f> stream) {{
            _Amount = _Amount * 0.5;
            if (_Amount == 0.25) {{
                g2f o;
                for (int k = 0; k < 3; k++) {{
                    o.pos = IN[k].pos;
                    stream.Append(o);
                }}
            }}
        }}
        float4 frag(g2f i) : SV_Target {{ return float4(0.25, _Amount, 0.75, 1); }}
        ENDCG
    }} }}
}}
"""


def _written_in_geometry(tmp_path, language, name):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(WRITTEN_IN_GEOMETRY.format(name=name)))
    return _render(tmp_path, shader, language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_global_the_geometry_function_writes(tmp_path, language, monkeypatch):
    """FXC's backwards-compatibility mode lets a program write a global, the value living in that
    invocation (written_globals.py): the geometry function halves its copy of _Amount (0.5 ->
    0.25, so it emits the triangles) and the fragment reads the material's 0.5: every covered
    pixel (0.25, 0.5, 0.75). Control: the geometry entry without the copy's statement (the copy
    left at 0): nothing is emitted. (Before, the GLSL port was refused: "assignment to read-only
    variable '_Amount'".)"""
    image = _written_in_geometry(tmp_path, language, "written")
    rgb = image[_covered(image), :3].astype(np.float64)
    assert np.abs(rgb - np.array([0.5 * 0.5, 0.5, 0.75])).max() <= EXACT
    monkeypatch.setattr(written_globals, "copy_statements", lambda written: "")
    assert (_written_in_geometry(tmp_path, language, "written_old")[..., 3] > 0).sum() == 0
