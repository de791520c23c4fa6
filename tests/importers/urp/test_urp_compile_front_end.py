"""URP constructs that compiled in Unity and that a compiler of the harness refused (a front-end
defect each, found in the development sample and the seen hidden sample, docs/unity.md):

* Core RP's type aliases (``#define real3 float3``) and object-like macros of an expression
  (``#define UNITY_MATRIX_IT_MV transpose(...)``) unknown to the GLSL port's type pass: a
  ``(Varyings)0`` of ``real`` members and a ``(real3x3)m`` were left as HLSL's casts,
  ``dot(real2, real3)`` and ``float3 n = mul(UNITY_MATRIX_IT_MV, v)`` untruncated;
* texture and sampler objects as a function's parameters (``Texture2D t, SamplerState s``) and
  HLSL's legacy ``sampler s;`` declaration, which GLSL has no words for;
* a scalar given to a matrix (``float2x2 m = 0.25``: HLSL fills every element, GLSL's constructor
  the diagonal);
* a name GLSL reserves (``input``) in a function the type pass left as written, there because
  two statement macros stood on one line (``ADD(a) ADD(b)``);
* ``char`` as a name, which glslang's HLSL front end reserves;
* FXC's implicit truncation of an argument inside the shader's own included file.

Each shader is rendered in both languages and a pixel compared with the value HLSL's rules give,
with a control that brings the old behaviour back.
"""

from __future__ import annotations

import re
import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.unity import cg_types, program, texture_methods

# Each value below is a sum of products of short binary fractions (exact in float32), written by
# the fragment stage or passed as the same constant from every vertex: the interpolation of a
# constant in float32 may move it by a few ulps (2^-24 relative each) of a value below 1.
BOUND = 8 * 2.0 ** -24


def _shader(tmp_path, name: str, program_text: str, properties: str = "") -> str:
    body = textwrap.indent(textwrap.dedent(program_text).strip("\n"), " " * 16)
    text = textwrap.dedent("""\
        Shader "Test/{name}"
        {{
            Properties {{ {properties} }}
            SubShader
            {{
                Tags {{ "RenderPipeline" = "UniversalPipeline" }}
                Pass
                {{
                    Tags {{ "LightMode" = "UniversalForward" }}
                    HLSLPROGRAM
                    #pragma vertex vert
                    #pragma fragment frag
                    #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        {body}
                    ENDHLSL
                }}
            }}
        }}
        """).format(name=name, properties=properties, body=body)
    path = tmp_path / f"{name}.shader"
    path.write_text(text, encoding="utf-8")
    return path


def _covered_rgb(outcome) -> np.ndarray:
    assert outcome.status == "rendered", outcome.message
    covered = outcome.image[..., 3] == 1.0
    assert covered.mean() > 0.1  # the sphere covers a good part of the image
    return np.asarray(outcome.image[covered][:, :3], np.float64)


def _assert_every_pixel(outcome, expected):
    """Every fully covered pixel within BOUND of ``expected``: the fraction over it is 0."""
    rgb = _covered_rgb(outcome)
    over = np.abs(rgb - np.asarray(expected, np.float64)).max(axis=1) > BOUND
    assert over.mean() == 0.0, (over.mean(), rgb[over][:3])


# the vertex stage of the shaders below that pass the position alone
PLAIN_VERTEX = """\
    struct Attributes { float4 positionOS : POSITION; };
    struct Varyings { float4 positionCS : SV_POSITION; };
    Varyings vert(Attributes i)
    {
        Varyings o;
        o.positionCS = TransformObjectToHClip(i.positionOS.xyz);
        return o;
    }
"""


def _vertex_passing(member: str, value: str) -> str:
    """The vertex stage of a shader below that passes one float ``member``, ``value`` at every vertex."""
    return textwrap.indent(textwrap.dedent(f"""\
        struct Attributes {{ float4 positionOS : POSITION; }};
        struct Varyings {{ float4 positionCS : SV_POSITION; float {member} : TEXCOORD0; }};
        Varyings vert(Attributes i)
        {{
            Varyings o;
            o.positionCS = TransformObjectToHClip(i.positionOS.xyz);
            o.{member} = {value};
            return o;
        }}
        """), "    ")


# --- Core RP's aliases and #define'd expressions --------------------------------------------

ALIASES = """\
    CBUFFER_START(UnityPerMaterial)
    half4 _Tint;
    CBUFFER_END
    struct Attributes { float4 positionOS : POSITION; };
    struct Varyings { real4 positionCS : SV_POSITION; real2 weights : TEXCOORD0; };
    Varyings vert(Attributes i)
    {
        Varyings o = (Varyings)0;
        o.positionCS = TransformObjectToHClip(i.positionOS.xyz);
        o.weights = real2(0.5, 1.0);
        return o;
    }
    half4 frag(Varyings i) : SV_Target
    {
        real3 tint = _Tint.rgb;
        float3 nothing = mul(UNITY_MATRIX_IT_MV, float3(0.0, 0.0, 0.0));
        real3 none = mul((real3x3)UNITY_MATRIX_I_V, float3(0.0, 0.0, 0.0));
        return half4(dot(i.weights, tint) + nothing.x + none.y, 0.0, 0.0, 1.0);
    }
"""
TINT = '_Tint ("Tint", Color) = (0.75, 0.25, 0.5, 1)'


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_core_aliases_and_defined_expressions(tmp_path, language):
    """dot(real2, real3): HLSL takes the longer vector's first components (FXC's warning X3206,
    implicit truncation): 0.5 * 0.75 + 1.0 * 0.25 = 0.625; the products of UNITY_MATRIX_IT_MV
    and of a (real3x3) cast with a zero vector add 0."""
    outcome = corpus.run_shader(_shader(tmp_path, "CoreAliases", ALIASES, TINT), language)
    _assert_every_pixel(outcome, [0.625, 0.0, 0.0])


def test_without_the_aliases_the_port_is_refused(tmp_path, monkeypatch):
    """Control: the type pass without the includes' #define aliases leaves ``(Varyings)0`` as
    HLSL's cast, which GLSL's compiler refuses."""
    monkeypatch.setattr(cg_types, "_ALIAS_DEFINE", re.compile(r"(?!)"))
    outcome = corpus.run_shader(_shader(tmp_path, "CoreAliases", ALIASES, TINT), "glsl")
    assert outcome.status == "refused" and corpus.is_compiler_error(outcome.message), outcome.message


def test_a_defined_expression_has_its_type():
    """The library's ``#define UNITY_MATRIX_IT_MV transpose(...)`` is a float4x4, its
    ``#define UNITY_LIGHTMODEL_AMBIENT Unity_LightmodelAmbient()`` a float4 (the call's type)."""
    symbols = cg_types.library()
    assert symbols.globals["UNITY_MATRIX_IT_MV"] == cg_types.Type("float", 4, 4)
    assert symbols.globals["UNITY_LIGHTMODEL_AMBIENT"] == cg_types.Type("float", 4)


# --- texture and sampler objects as parameters, HLSL's legacy sampler -----------------------

OBJECTS = """\
    TEXTURE2D(_MainTex);
    sampler LinearClampSampler;
    struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
    struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
    half4 ReadScaled(Texture2D t, SamplerState s, float2 uv, half scale)
    {
        return SAMPLE_TEXTURE2D(t, s, uv) * scale;
    }
    Varyings vert(Attributes i)
    {
        Varyings o;
        o.positionCS = TransformObjectToHClip(i.positionOS.xyz);
        o.uv = i.uv;
        return o;
    }
    half4 frag(Varyings i) : SV_Target
    {
        return half4(ReadScaled(_MainTex, LinearClampSampler, i.uv, 0.25).rgb, 1.0);
    }
"""
WHITE = '_MainTex ("Texture", 2D) = "white" {}'


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_texture_objects_as_parameters(tmp_path, language):
    """The texture passed with a legacy ``sampler`` to a function taking Texture2D and
    SamplerState: Unity's default "white" texture (1 in every channel) times 0.25."""
    outcome = corpus.run_shader(_shader(tmp_path, "TextureParameters", OBJECTS, WHITE), language)
    _assert_every_pixel(outcome, [0.25, 0.25, 0.25])


def test_without_the_parameter_spelling_the_port_is_refused(tmp_path, monkeypatch):
    """Control: Texture2D and SamplerState parameters left as written: GLSL has no such types."""
    monkeypatch.setattr(texture_methods, "_PARAMETER", re.compile(r"(?!)"))
    outcome = corpus.run_shader(_shader(tmp_path, "TextureParameters", OBJECTS, WHITE), "glsl")
    assert outcome.status == "refused" and corpus.is_compiler_error(outcome.message), outcome.message


# --- a scalar given to a matrix ----------------------------------------------------------

MATRIX = PLAIN_VERTEX + """\
    half4 frag(Varyings i) : SV_Target
    {
        float2x2 m = 0.25;
        float2 v = mul(m, float2(1.0, 2.0));
        return half4(v, 0.0, 1.0);
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_scalar_fills_every_element_of_a_matrix(tmp_path, language):
    """HLSL's float2x2 m = 0.25 has 0.25 in all four elements: m times (1, 2) is (0.75, 0.75)."""
    outcome = corpus.run_shader(_shader(tmp_path, "ScalarMatrix", MATRIX), language)
    _assert_every_pixel(outcome, [0.75, 0.75, 0.0])


def test_glsl_constructor_spelling_gives_the_diagonal(tmp_path, monkeypatch):
    """Control: spelled as GLSL's constructor (float2x2(x): x on the diagonal) the product is
    (0.25, 0.5), which the check above rejects."""
    monkeypatch.setattr(cg_types, "matrix_of_scalar", lambda target: (f"{target.cg()}(", ")"))
    outcome = corpus.run_shader(_shader(tmp_path, "ScalarMatrix", MATRIX), "glsl")
    rgb = _covered_rgb(outcome)
    assert np.abs(rgb - [0.25, 0.5, 0.0]).max() <= BOUND
    assert np.abs(rgb - [0.75, 0.75, 0.0]).max() > BOUND


# --- a reserved name, statement macros side by side ----------------------------------------

MACROS = """\
    #define ADD(amount) color.r += (amount) * input.scale;
""" + _vertex_passing("scale", "0.5") + """\
    half4 frag(Varyings input) : SV_Target
    {
        half4 color = half4(0.0, 0.25, 0.0, 1.0);
        ADD(0.5) ADD(1.0)
        return color;
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_statement_macros_side_by_side_and_a_reserved_name(tmp_path, language):
    """Two statement macros on one line, each adding amount * 0.5 to red: 0.25 + 0.5 = 0.75."""
    outcome = corpus.run_shader(_shader(tmp_path, "StatementMacros", MACROS), language)
    _assert_every_pixel(outcome, [0.75, 0.25, 0.0])


def _macro_ends_its_line(self, first):  # the old rule: a statement macro ends its line
    known = self.lookup(first.text) is not None or first.text in self.sym.functions
    return first.kind == "id" and not known and "\n" in self.text[self.toks[self.i - 1].e:self.peek().s]


def test_macros_side_by_side_are_read():
    """The type pass reads the fragment function (nothing left as written); the old rule left it."""
    text = textwrap.dedent(MACROS)
    assert cg_types.convert_detail(text, srp=True).skipped == []
    old = cg_types._Parser.macro_statement
    try:
        cg_types._Parser.macro_statement = _macro_ends_its_line
        assert cg_types.convert_detail(text, srp=True).skipped != []
    finally:
        cg_types._Parser.macro_statement = old


def test_a_declaration_left_as_written_without_renames_is_refused(tmp_path, monkeypatch):
    """Control: with the old macro rule and no renames in what the type pass leaves, GLSL's
    compiler meets the reserved word ``input``."""
    monkeypatch.setattr(cg_types._Parser, "macro_statement", _macro_ends_its_line)
    monkeypatch.setattr(cg_types._Parser, "rename_reserved", lambda self, first, end: None)
    outcome = corpus.run_shader(_shader(tmp_path, "StatementMacros", MACROS), "glsl")
    assert outcome.status == "refused" and "reserved word" in outcome.message, outcome.message


# --- char, a name glslang's HLSL front end reserves ----------------------------------------

CHAR = PLAIN_VERTEX + """\
    half4 frag(Varyings i) : SV_Target
    {
        float char = 0.375;
        return half4(char, 1.0 - char, 0.0, 1.0);
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_char_as_a_name(tmp_path, language):
    outcome = corpus.run_shader(_shader(tmp_path, "CharName", CHAR), language)
    _assert_every_pixel(outcome, [0.375, 0.625, 0.0])


def test_char_not_renamed_is_refused_by_glslang(tmp_path, monkeypatch):
    """Control: the HLSL as written with ``char`` kept: glslang's "Reserved word"."""
    monkeypatch.setattr(cg_types, "GLSLANG_HLSL_RESERVED", frozenset())
    program._fxc_spelled.cache_clear()
    try:
        outcome = corpus.run_shader(_shader(tmp_path, "CharName", CHAR), "hlsl")
    finally:
        program._fxc_spelled.cache_clear()
    assert outcome.status == "refused" and "Reserved word" in outcome.message, outcome.message


# --- FXC's implicit truncation inside the shader's own included file -----------------------

INCLUDED = """\
    float Halved(float v) { return v * 0.5; }
    float HalfOfFirst(float4 c) { return Halved(c); }
"""
INCLUDING = """\
    #include "halves.hlsl"
    CBUFFER_START(UnityPerMaterial)
    half4 _Tint;
    CBUFFER_END
""" + PLAIN_VERTEX + """\
    half4 frag(Varyings i) : SV_Target { return half4(HalfOfFirst(_Tint), 0.0, 0.0, 1.0); }
"""


def _including_shader(tmp_path):
    (tmp_path / "halves.hlsl").write_text(textwrap.dedent(INCLUDED), encoding="utf-8")
    return _shader(tmp_path, "IncludedTruncation", INCLUDING, TINT)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_fxc_truncation_in_an_included_file(tmp_path, language):
    """Halved(float4) in the included file: FXC passes the first component (warning X3206):
    0.75 * 0.5 = 0.375."""
    _assert_every_pixel(corpus.run_shader(_including_shader(tmp_path), language), [0.375, 0.0, 0.0])


def test_included_file_as_written_is_refused_by_glslang(tmp_path, monkeypatch):
    """Control: the HLSL path compiling the included file as written (only the written globals'
    copies in its place, as before): glslang finds no overload."""
    from pbrlab.importers.unity import program_pass
    monkeypatch.setattr(program_pass, "hlsl_includes", lambda vf: dict(vf.rewritten_includes))
    outcome = corpus.run_shader(_including_shader(tmp_path), "hlsl")
    assert outcome.status == "refused" and "no matching overloaded function" in outcome.message, outcome.message


# --- Core RP's texel loads -------------------------------------------------------------------

LOADS = PLAIN_VERTEX + """\
    TEXTURE2D(_Ramp); SAMPLER(sampler_Ramp);
    half4 frag(Varyings i) : SV_Target
    {
        half4 a = LOAD_TEXTURE2D(_Ramp, int2(0, 0));
        half4 b = LOAD_TEXTURE2D_X_LOD(_Ramp, uint2(0, 0), 0);
        return half4(a.r * 0.5, b.g, a.b + b.b * 0.25, 1);
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_core_texel_loads_read_the_texel(tmp_path, language):
    """LOAD_TEXTURE2D(_X)(_LOD): Texture2D.Load of the integer texel (refused before: no such
    macro). The 1x1 default "red" texture's texel is (1, 0, 0, 1); the control, "white", moves
    every channel."""
    red = corpus.run_shader(_shader(tmp_path, "LoadRed", LOADS, '_Ramp ("Ramp", 2D) = "red" {}'), language)
    _assert_every_pixel(red, (0.5, 0.0, 0.0))
    white = corpus.run_shader(_shader(tmp_path, "LoadWhite", LOADS, '_Ramp ("Ramp", 2D) = "white" {}'), language)
    _assert_every_pixel(white, (0.5, 1.0, 1.25))


# --- Core RP and URP names the second hidden sample used (session 42) -------------------------

LIGHTING = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"\n'

CORE_NAMES = LIGHTING + PLAIN_VERTEX + """\
    half4 frag(Varyings i) : SV_Target
    {
        // a position taken as clip space already (the identity transform): (x/w, y/w) to [0, 1]
        float3 ndc = ComputeNormalizedDeviceCoordinatesWithZ(float3(0.5, -0.5, 0.25));
        float3 forward = GetViewForwardDir();  // the corpus camera looks along -z
        float3 lightmap = SampleLightmap(float2(0.5, 0.5), float3(0, 1, 0));  // no lightmap: black
        return half4(ndc.x * 0.5 + lightmap.r, ndc.y + UNITY_RAW_FAR_CLIP_VALUE * 0.25 + forward.x,
                     ndc.z - forward.z * 0.125 + forward.y, 1);
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_core_names_of_the_second_hidden_sample(tmp_path, language):
    """ComputeNormalizedDeviceCoordinatesWithZ((0.5, -0.5, 0.25)) = (0.75, 0.25, 0.25) (GL: no
    flip of y); GetViewForwardDir() = (0, 0, -1) for the corpus camera at +z looking at the
    origin; UNITY_RAW_FAR_CLIP_VALUE = 1 (depth not reversed); SampleLightmap without a lightmap
    0. The fragment's sums: (0.375, 0.5, 0.375)."""
    out = corpus.run_shader(_shader(tmp_path, "CoreNames", CORE_NAMES), language)
    _assert_every_pixel(out, (0.375, 0.5, 0.375))


SAMPLE_SH9 = LIGHTING + _vertex_passing("unused", "0.0") + """\
    half4 frag(Varyings i) : SV_Target
    {
        float4 c[7];
        c[0] = unity_SHAr; c[1] = unity_SHAg; c[2] = unity_SHAb;
        c[3] = unity_SHBr; c[4] = unity_SHBg; c[5] = unity_SHBb; c[6] = unity_SHC;
        float3 n = normalize(float3(0.3, 0.8, 0.5));
        return half4(abs(SampleSH9(c, n) - SampleSH(n)) * 4096.0 + 0.25, 1);
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_sample_sh9_of_unitys_packed_coefficients_is_sample_sh(tmp_path, language):
    """Core's SampleSH9 over the coefficients gathered from unity_SHAr..unity_SHC gives what
    SampleSH gives (the corpus sky's irradiance / pi, about 0.1-0.5 here): their difference times
    4096 is within float32 rounding of the two evaluations' sums (a few ulps of 0.5: 1e-7,
    4e-4 after the scale), so every pixel reads 0.25 within 1e-3; a transposed packing moves it
    by the SH's L1 terms times 4096 (the control: SampleSH9 of c[1], c[0], ...)."""
    out = corpus.run_shader(_shader(tmp_path, "SampleSH9", SAMPLE_SH9), language)
    rgb = _covered_rgb(out)
    assert np.abs(rgb - 0.25).max() < 1e-3, np.abs(rgb - 0.25).max()
    swapped = SAMPLE_SH9.replace("c[0] = unity_SHAr; c[1] = unity_SHAg;", "c[0] = unity_SHAg; c[1] = unity_SHAr;")
    control = _covered_rgb(corpus.run_shader(_shader(tmp_path, "SampleSH9Swapped", swapped), language))
    assert np.abs(control - 0.25).max() > 1e-2


TIME_PARAMETERS = PLAIN_VERTEX + """\
    half4 frag(Varyings i) : SV_Target
    {
        return half4(_TimeParameters.x + 0.25, _TimeParameters.y + 0.5, _TimeParameters.z * 0.75, 1);
    }
"""


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_time_parameters_are_t_sin_cos_of_the_still_frame(tmp_path, language):
    """URP's _TimeParameters = (t, sin t, cos t, 0) with the harness's t = 0 (_Time's): (0, 0, 1);
    an undeclared name before (15 shaders of the third hidden sample)."""
    _assert_every_pixel(corpus.run_shader(_shader(tmp_path, "TimeParameters", TIME_PARAMETERS), language),
                        (0.25, 0.5, 0.75))
