"""HLSL's matrix forms and written globals in URP programs (issue 34, session 41: the unseen and
development samples' TBN shaders and Dissolve-style programs), in both languages: the GLSL port
spells what FXC does implicitly (cg_types.py), the pass entry passes a matrix varying as its
vectors (generate_pass._slots), and a program that writes a material uniform reads and writes a
static copy set at each entry (written_globals.py; FXC's backwards-compatibility mode).

Each program returns values computed from constants (no texture, no light), so every covered
pixel holds the same colour; it is compared with its float64 value from HLSL's documented
semantics (Microsoft's HLSL reference: matrices are row-major as written, ``m[i]`` is row ``i``,
``_mRC`` / ``_RC`` name row R and column C (from 0 / from 1), an initialiser list fills rows,
``mul(v, M)`` is the row vector times M, a conversion to a smaller matrix keeps the upper-left
block, a vector longer than the matrix side it meets is truncated (FXC warning X3206); arrays of
arrays as C's).
Controls: the transposed (GLSL's column) reading of the same program is rejected by the bound.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
# float32 evaluation of a few products and sums of values below 64 (relative error of each
# operation 2^-24, at most 4 in a chain): 4 * 64 * 2^-24 = 1.5e-5. It covers the interpolated
# cases too: a varying below 1, the same at every vertex, arrives within 64 * 2^-24 (each
# barycentric weight a float32 plane equation at window coordinates up to corpus.SIZE, 64).
BOUND = 4 * 64 * 2.0 ** -24

# a URP pass around %(program)s, with the property _Offset
_SHADER = """
Shader "t/%(name)s" {
    Properties { _Offset ("offset", Vector) = (0.1, 0.2, 0.3, 0.4) }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
%(program)s
            ENDHLSL
        }
    }
}
"""

_PROGRAM = """
            CBUFFER_START(UnityPerMaterial)
            float4 _Offset;
            CBUFFER_END
            static const float W[2][3] = {{1, 2, 3}, {4, 5, 6}};
            float4x4 Big() { float4x4 b = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}; return b; }
            float3 RowOne(float3x3 a) { return a[1]; }
            float Half(float x) { return x * 0.5; }
            float3x3 UpperLeft() { return Big(); }
            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; float3x3 tbn : TEXCOORD1; float4 offset : TEXCOORD5; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                float3x3 m = (float3x3)0;
                m[0] = float3(0.6, 0.8, 0.0);
                m[1] += float3(-0.32, 0.24, 0.5);
                m[2][0] = 0.1;
                m[2].y = 0.2;
                m[2][2] = 0.3;
                OUT.tbn = m;
                %(vertex)s
                OUT.offset = _Offset;
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target {
                float4x4 B = Big();
                %(body)s
            }"""

BIG = np.arange(1.0, 17.0).reshape(4, 4)           # the rows as the initialiser list lists them
V = np.array([1.0, 0.1, 0.01])
TBN = np.array([[0.6, 0.8, 0.0], [-0.32, 0.24, 0.5], [0.1, 0.2, 0.3]])  # the rows vert() writes
WEIGHTS = np.array([0.25, 0.5, 0.75])

# (name, fragment body, float64 rgb, the transposed reading's rgb: the control)
CASES = [
    ("truncated_assignment", "float3x3 m = B; return float4(mul(m, float3(1, 0.1, 0.01)), 1);",
     BIG[:3, :3] @ V, BIG[:3, :3].T @ V),
    ("transpose_cast", "float3x3 t = transpose(B); return float4(mul((float3x3)t, float3(1, 0.1, 0.01)), 1);",
     BIG.T[:3, :3] @ V, BIG[:3, :3] @ V),
    ("mul_truncates_vector", "float3x3 m = (float3x3)B; return float4(mul(float4(1, 0.1, 0.01, 100), m), 1);",
     V @ BIG[:3, :3], BIG[:3, :3] @ V),
    ("element_swizzles", "return float4(B._m03_m13_m23 * 0.1 + float3(B._21, B._m12, B._34), 1);",
     BIG[:3, 3] * 0.1 + np.array([BIG[1, 0], BIG[1, 2], BIG[2, 3]]),
     BIG[3, :3] * 0.1 + np.array([BIG[0, 1], BIG[2, 1], BIG[3, 2]])),
    ("argument_and_return", "return float4(RowOne((float3x3)B) * 0.1 + UpperLeft()[2] * 0.01, 1);",
     BIG[1, :3] * 0.1 + BIG[2, :3] * 0.01, BIG[:3, 1] * 0.1 + BIG[:3, 2] * 0.01),
    ("matrix_varying_rows", "return float4(mul(float3(0.25, 0.5, 0.75), IN.tbn), 1);",
     WEIGHTS @ TBN, TBN @ WEIGHTS),
    ("mixed_intrinsic_arguments", "return float4(clamp(float3(-1, 0.5, 2), 0, float3(1, 1, 1.5))"
     " + abs(0.3 < 0.5) * float3(0, 0, 0.25), 1);",
     np.array([0.0, 0.5, 1.75]), np.array([-1.0, 0.5, 2.25])),
    # HLSL's arrays of arrays (C's: W[i][j] is row i, element j), a global and a local
    ("arrays_of_arrays", "float a[2][2]; a[0][0] = 1; a[0][1] = 2; a[1][0] = 3; a[1][1] = 4;"
     " return float4(W[1][2] + a[1][0], W[0][1] * a[0][1], W[1][0], 1);",
     np.array([6.0 + 3.0, 2.0 * 2.0, 4.0]), np.array([3.0 + 2.0, 4.0 * 3.0, 2.0])),
    # a float2 passed to a float parameter: FXC takes its x (warning X3206; glslang refuses it)
    ("vector_argument_truncated", "return float4(Half(float2(0.5, 7)), 0, 0, 1);",
     np.array([0.25, 0.0, 0.0]), np.array([3.5, 0.0, 0.0])),
    # _Offset written in the vertex stage (zw + 0.25), passed on, written again in the fragment
    # stage from the uniform's own value (xy * 2): each stage's copy starts from the material's
    ("written_material_uniform", "_Offset.xy *= 2.0; return float4(_Offset.x + IN.offset.x, _Offset.y + IN.offset.w, IN.offset.z, 1);",
     np.array([0.2 + 0.1, 0.4 + 0.65, 0.55]), np.array([0.2 + 0.2, 0.4 + 0.4, 0.3])),
]


def _render(tmp_path, name, body, language):
    shader = tmp_path / f"{name}.shader"
    vertex = "_Offset.zw += 0.25;" if "written" in name else ""
    program = _PROGRAM % {"body": body, "vertex": vertex}
    shader.write_text(textwrap.dedent(_SHADER % {"name": name, "program": program}))
    data = corpus.scene_for(shader)
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("name, body, expected, transposed", CASES, ids=[c[0] for c in CASES])
def test_hlsl_matrix_form_renders_its_float64_value(tmp_path, language, name, body, expected, transposed):
    image = _render(tmp_path, name, body, language)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    err = np.abs(image[covered][:, :3] - expected).max(axis=1)
    assert (err <= BOUND).all(), (name, language, image[covered][0, :3], expected)
    # control: the other reading (columns for rows, the vector uncut, the uniform unwritten)
    assert np.abs(expected - transposed).max() > 100 * BOUND
    assert (np.abs(image[covered][:, :3] - transposed).max(axis=1) > BOUND).all()


# the pass's functions in the shader's own include, which declares _Offset and writes it in the
# vertex function (VKev's StylizeGrass_ForwardLit_Pass.hlsl does so with _WindTexture_ST)
_WRITTEN_PASS_HLSL = """
float4 _Offset;
struct Attributes { float4 positionOS : POSITION; };
struct Varyings { float4 positionCS : SV_POSITION; float4 offset : TEXCOORD0; };
Varyings vert(Attributes IN) {
    Varyings OUT;
    OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
    _Offset.zw += 0.25;
    OUT.offset = _Offset;
    return OUT;
}
float4 frag(Varyings IN) : SV_Target { return float4(IN.offset.zw, _Offset.z, 1); }
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_uniform_written_in_an_included_pass_file(tmp_path, language):
    """The vertex stage's copy: z + 0.25, w + 0.25; the fragment's own: the property's z.
    Control: the unwritten uniform (0.3, 0.4) is rejected."""
    (tmp_path / "written_pass.hlsl").write_text(textwrap.dedent(_WRITTEN_PASS_HLSL))
    shader = tmp_path / "included.shader"
    shader.write_text(textwrap.dedent(_SHADER % {"name": "written in include",
                                                 "program": '            #include "written_pass.hlsl"'}))
    image = render_scene(parse_scene(corpus.scene_for(shader), "t", tmp_path), language=language).linear
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    expected, unwritten = np.array([0.55, 0.65, 0.3]), np.array([0.3, 0.4, 0.3])
    got = image[covered][:, :3].astype(np.float64)
    assert (np.abs(got - expected).max(axis=1) <= BOUND).all(), got[0]
    assert (np.abs(got - unwritten).max(axis=1) > BOUND).all()
