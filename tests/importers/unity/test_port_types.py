"""The port's type pass (harness/pbrlab/importers/unity/cg_types.py): each implicit Cg/HLSL conversion
GLSL refuses, as a small Cg function. The ported text is checked exactly (the pass changes
only what the rule needs), and the port, compiled as GLSL after cg_compat.glsl, evaluates to
what the original gives on the HLSL path (glslang's HLSL front end compiles it as written)."""

from __future__ import annotations

import numpy as np
import pytest

import pbrlab
from pbrlab.importers.unity import cg_types, port

# Two helpers every case may call: a static global (static is dropped, no uniform added)
# and a user function whose float3 parameters take a truncated float4 and a splatted scalar.
PRELUDE = "static float3 pbr_k = 2;\nfloat3 pbr_g(float3 v, float3 s) { return v * s; }\n"
PRELUDE_GLSL = "vec3 pbr_k = vec3(2);\nvec3 pbr_g(vec3 v, vec3 s) { return v * s; }\n"

CASES = [  # (rule, Cg body of pbr_test(), its port, return type)
    ('vector_op_truncates_larger', 'float3 a = float3(1, 2, 3); float4 b = float4(4, 5, 6, 7); return float4(a * b, 1);', 'vec3 a = vec3(1, 2, 3); vec4 b = vec4(4, 5, 6, 7); return vec4(a * b.xyz, 1);'),
    ('swizzle_shortened', 'float4 c = float4(1, 2, 3, 4); float3 a = float3(5, 6, 7); return float4(c.rgba + a, 0);', 'vec4 c = vec4(1, 2, 3, 4); vec3 a = vec3(5, 6, 7); return vec4(c.rgb + a, 0);'),
    ('init_truncates', 'float3 c = float4(1, 2, 3, 4); return float4(c, 0);', 'vec3 c = vec4(1, 2, 3, 4).xyz; return vec4(c, 0);'),
    ('assign_truncates_expression', 'float3 c; c = float4(1, 2, 3, 4) * 2; return float4(c, 0);', 'vec3 c; c = (vec4(1, 2, 3, 4) * 2).xyz; return vec4(c, 0);'),
    ('scalar_init_splats', 'float3 c = 0.5; return float4(c, 1);', 'vec3 c = vec3(0.5); return vec4(c, 1);'),
    ('return_truncates', 'return float4(1, 2, 3, 4) * 0.5;', 'return (vec4(1, 2, 3, 4) * 0.5).xy;', 'float2'),
    ('return_splats', 'return 3;', 'return vec3(3);', 'float3'),
    ('float_to_int', 'int i = 2.7; return i;', 'int i = int(2.7); return float(i);', 'float'),
    ('bool_to_float', 'float f = true; return f + 1;', 'float f = float(true); return f + 1;', 'float'),
    ('if_float_condition', 'float x = 0.5; if (x) return 1; return 2;', 'float x = 0.5; if (bool(x)) return float(1); return float(2);', 'float'),
    ('logical_float_operands', 'float x = 0.5; float y = 0; return (x && !y) ? 3 : 4;', 'float x = 0.5; float y = 0; return float((bool(x) && !bool(y)) ? 3 : 4);', 'float'),
    ('ternary_sizes', 'float x = 1; float3 v = x > 0.5 ? float4(1, 2, 3, 4) : 0.25; return float4(v, 0);', 'float x = 1; vec3 v = (x > 0.5 ? vec4(1, 2, 3, 4) : vec4(0.25)).xyz; return vec4(v, 0);'),
    ('scalar_swizzle', 'float x = 2; float3 v = x.xxx + x.x; return float4(v, 0);', 'float x = 2; vec3 v = vec3(x) + x; return vec4(v, 0);'),
    ('vector_comparison', 'float3 a = float3(1, 5, 3); return any(a > 2) ? float4(a < 2, 1) : 0;', 'vec3 a = vec3(1, 5, 3); return any(greaterThan(a, vec3(2))) ? vec4(lessThan(a, vec3(2)), 1) : vec4(0);'),
    ('float_modulo', 'float3 a = float3(5.5, 1.25, 7); float b = 7.5; return float4(a % 2, b % 2);', 'vec3 a = vec3(5.5, 1.25, 7); float b = 7.5; return vec4(fmod(a, 2), fmod(b, 2));'),
    ('intrinsic_scalar_first', 'float3 v = float3(-1, 0.25, 2); return float4(max(0, v), step(v, 0.5).x);', 'vec3 v = vec3(-1, 0.25, 2); return vec4(max(vec3(0), v), step(v, vec3(0.5)).x);'),
    ('lerp_float4_weight', 'float3 a = 0; float3 b = 1; float4 t = float4(0.25, 0.5, 0.75, 1); return float4(lerp(a, b, t), 0);', 'vec3 a = vec3(0); vec3 b = vec3(1); vec4 t = vec4(0.25, 0.5, 0.75, 1); return vec4(lerp(a, b, t.xyz), 0);'),
    ('dot_cross_truncate', 'float3 a = float3(1, 2, 3); float4 b = float4(4, 5, 6, 7); return float4(cross(a, b), dot(a, b));', 'vec3 a = vec3(1, 2, 3); vec4 b = vec4(4, 5, 6, 7); return vec4(cross(a, b.xyz), dot(a, b.xyz));'),
    ('cast', 'float4 c = float4(1, 2, 3, 4); float3 v = (float3)c * 2; return float4(v, (float)c.w);', 'vec4 c = vec4(1, 2, 3, 4); vec3 v = vec3(c) * 2; return vec4(v, float(c.w));'),
    ('array_initialiser', 'float a[3] = {1, 2, 3}; return float4(a[0], a[1], a[2], a[1.7]);', 'float a[3] = float[3](1, 2, 3); return vec4(a[0], a[1], a[2], a[int(1.7)]);'),
    ('matrix_rows', 'float3x3 m = float3x3(1, 2, 3, 4, 5, 6, 7, 8, 9); float3 r = m[1]; return float4(r, mul(m, float3(1, 0, 0)).y);', 'mat3 m = transpose(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)); vec3 r = transpose(m)[1]; return vec4(r, mul(m, vec3(1, 0, 0)).y);'),
    ('matrix_row_vectors', 'float3x3 m = float3x3(float3(1, 2, 3), float3(4, 5, 6), float3(7, 8, 9)); return float4(mul(m, float3(0, 1, 0)), m[2].x);', 'mat3 m = transpose(mat3(vec3(1, 2, 3), vec3(4, 5, 6), vec3(7, 8, 9))); return vec4(mul(m, vec3(0, 1, 0)), transpose(m)[2].x);'),
    ('reserved_names', 'float input = 1; float3 filter = 2; float sample = input + filter.y; return float4(filter, sample);', 'float pbr_unity_input = 1; vec3 pbr_unity_filter = vec3(2); float pbr_unity_sample = pbr_unity_input + pbr_unity_filter.y; return vec4(pbr_unity_filter, pbr_unity_sample);'),
    ('literal_suffix', 'half h = 0.5h; return float4(h, 1.0f, 2.h, 3);', 'float h = 0.5f; return vec4(h, 1.0f, 2.f, 3);'),
    ('compound_truncates', 'float3 c = 1; c += float4(1, 2, 3, 4); c *= float4(2, 2, 2, 2); return float4(c, 0);', 'vec3 c = vec3(1); c += vec4(1, 2, 3, 4).xyz; c *= vec4(2, 2, 2, 2).xyz; return vec4(c, 0);'),
    ('user_function_arguments', 'return float4(pbr_g(float4(1, 2, 3, 4), 2), 0);', 'return vec4(pbr_g(vec4(1, 2, 3, 4).xyz, vec3(2)), 0);'),
    ('static_global', 'return float4(pbr_k, 0);', 'return vec4(pbr_k, 0);'),
    ('uint_compares_int', 'float s = 0; for (uint i = 0; i < 3; i++) { s += 0.5; } return s + (2u > 1 ? 1 : 0);', 'float s = 0; for (uint i = uint(0); i < uint(3); i++) { s += 0.5; } return s + (2u > uint(1) ? 1 : 0);', 'float'),
    ('loop_attribute', 'float s = 0; [unroll] for (int i = 0; i < 3; i++) { s += i * 0.5; } return s;', 'float s = 0; for (int i = 0; i < 3; i++) { s += i * 0.5; } return s;', 'float'),
]


def _function(body, ret="float4"):
    return f"{ret} pbr_test() {{ {body} }}\n"


@pytest.mark.parametrize("rule, cg, glsl, ret", [(*c, "float4")[:4] for c in CASES], ids=[c[0] for c in CASES])
def test_type_pass_spells_out_the_conversion(rule, cg, glsl, ret, tmp_path):
    ported = port.port_text(PRELUDE + _function(cg, ret))
    glsl_ret = port.port_code_types(ret)
    assert ported == PRELUDE_GLSL + f"{glsl_ret} pbr_test() {{ {glsl} }}\n"

    (tmp_path / "t.hlsl").write_text(PRELUDE + _function(cg, ret))
    (tmp_path / "t.glsl").write_text(ported)
    hlsl = pbrlab.evaluate("pbr_test()", includes=["t.hlsl"], include_dirs=[tmp_path], language="hlsl")
    ours = pbrlab.evaluate("pbr_test()", includes=["unity_compat/cg_compat.glsl", "t.glsl"],
                           include_dirs=[tmp_path])
    # Same operations in the same order on exact small values: bit-identical.
    assert np.array_equal(hlsl, ours), (hlsl, ours)


def test_float_modulo_truncates_like_d3d(tmp_path):
    """HLSL's float % and fmod keep the sign of x (D3D's fmod: x - y * trunc(x / y)); the
    port's fmod (cg_compat.glsl) does. (The harness's HLSL path does not: glslang emits a
    floored remainder, -5.5 % 2 = 0.5 there, so this case is checked against the definition.)"""
    (tmp_path / "t.glsl").write_text(port.port_text(_function("float x = -5.5; float3 v = float3(x, 5.5, -1); return float4(x % 2, v % 2);")))
    got = pbrlab.evaluate("pbr_test()", includes=["unity_compat/cg_compat.glsl", "t.glsl"], include_dirs=[tmp_path])
    assert got.tolist() == [-1.5, -1.5, 1.5, -1.0]


def test_text_outside_the_conversions_is_kept_byte_for_byte():
    cg = ("// a comment: float3 c = tex2D(_MainTex, uv);\n"
          "sampler2D _MainTex;   /* multi\n   line */ fixed4 _Color;\n"
          "#define PBR_TINT(c) ((c) * _Color)\n"
          "struct Input { float2 uv_MainTex : TEXCOORD0; INTERNAL_DATA };\n"
          "void surf (Input IN, inout SurfaceOutputStandard o) {\n"
          "\tfixed4 c = tex2D (_MainTex,\n\t\tIN.uv_MainTex)\n\t\t* _Color;\n"
          "\to.Albedo = c;  // truncated\n"
          "}\n")
    out = cg_types.convert(cg)
    assert out == cg.replace("sampler2D _MainTex;", "uniform sampler2D _MainTex;") \
        .replace("fixed4 _Color;", "uniform fixed4 _Color;").replace("o.Albedo = c;", "o.Albedo = c.xyz;")
    assert out.count("\n") == cg.count("\n")


def test_unknown_types_are_left_alone():
    # MY_SAMPLE is a macro the pass knows nothing of: its result is not truncated. (The library's
    # UNITY_SAMPLE_TEX2D is known since session 45: a function-like macro has its body's type.)
    cg = "void surf (Input IN, inout SurfaceOutputStandard o) { o.Albedo = MY_SAMPLE(_T, IN.uv); }\n"
    assert cg_types.convert(cg) == cg


def test_a_declaration_the_parser_cannot_read_is_kept_and_reported():
    # an HLSL class is beyond the parser (a nested initialiser list was, until it read them)
    cg = "class C { float f() { return 1; } };\nfloat g() { float3 c = 1; return c; }\n"
    result = cg_types.convert_detail(cg)
    assert result.skipped == [1]
    assert result.text == "class C { float f() { return 1; } };\n" \
        "float g() { float3 c = float3(1); return c.x; }\n"


def test_a_nested_initialiser_of_an_array_of_vectors_is_spelled_in_constructors():
    cg = "float4 f(float4 x) { float2 a[2] = { {1, 2}, {3, 4} }; return x; }\n"
    result = cg_types.convert_detail(cg)
    assert result.skipped == []
    assert result.text == "float4 f(float4 x) { float2 a[2] = float2[2]( float2(1, 2), float2(3, 4) ); return x; }\n"


def test_library_signatures_come_from_the_glsl_includes():
    lib = cg_types.library()
    assert lib.functions["UnpackNormal"][0].ret == cg_types.Type("float", 3)
    assert lib.structs["SurfaceOutputStandard"]["Albedo"] == cg_types.Type("float", 3)
    assert lib.aliases["UnityGI"] == "pbr_GI" and "indirect" in lib.structs["pbr_GI"]
    assert lib.globals["unity_ObjectToWorld"] == cg_types.Type("float", 4, 4)


def test_matrix_types_are_named_columns_first():
    # HLSL float3x4: 3 rows of 4; GLSL mat4x3: 4 columns of 3 (the same shape).
    assert port.port_code_types("float3x4 m; float2x2 n;") == "mat4x3 m; mat2 n;"
    assert cg_types.convert("float3x4 m = float3x4(a, b, c);") == \
        "uniform float3x4 m = transpose(float4x3(a, b, c));"


def test_types_and_macros_from_unread_includes_do_not_stop_the_pass():
    # v2f_surf comes from an include the pass does not read; UNITY_TRANSFER_FOG brings its own ';'.
    cg = ("CBUFFER_START(UnityPerMaterial)\nfixed4 _Color;\nCBUFFER_END\n"
          "float4 frag (v2f_surf IN) : SV_Target {\n\tv2f_surf o;\n\tUNITY_TRANSFER_FOG(o, IN.pos)\n"
          "\tfloat3 c = _Color;\n\treturn IN.color;\n}\n")
    result = cg_types.convert_detail(cg)
    assert result.skipped == []
    assert "float3 c = _Color.xyz;" in result.text and "return IN.color;" in result.text


def test_a_numeric_define_has_its_literals_type():
    # `#define MAX_STEPS 10` compared with a uint loop counter (a sphere tracer's loop): HLSL
    # converts the int to uint, GLSL 330 refuses the mixed comparison
    cg = "#define MAX_STEPS 10\n#define EPS 0.01\nfloat pbr_test() { float s = 0; for (uint i = 0; i < MAX_STEPS; i++) s += EPS; return s; }\n"
    assert port.port_text(cg) == ("#define MAX_STEPS 10\n#define EPS 0.01\nfloat pbr_test() { float s = 0; "
                                  "for (uint i = uint(0); i < uint(MAX_STEPS); i++) s += EPS; return s; }\n")


def test_discard_is_the_stage_neutral_macro():
    # GLSL refuses `discard` in a vertex stage even inside a function that stage never calls
    assert port.port_text("float4 frag() { discard; return 0; }\n") == \
        "vec4 frag() { PBR_UNITY_DISCARD; return vec4(0); }\n"
