"""Core RP / URP names the stand-ins lacked (issue 34, session 47, s47-corenames), each rendered
in both languages from a minimal program of our own (shaders/s47-corenames/core_names.shader)
against a float64 value computed here from the documented formula, each with a control:

- Core RP's Random.hlsl reached through URP's Core.hlsl (Core RP 14.0.9 Common.hlsl includes it):
  InterleavedGradientNoise, GenerateHashedRandomFloat, Hash;
- Common.hlsl's float tests (IsNaN, AnyIsNaN, IsInf, AnyIsInf, IsFinite, IsPositiveFinite,
  SanitizeFinite), PositivePow, SafePositivePow, SafeDiv's vector forms;
- URP 12's MAX_VISIBLE_LIGHTS on OpenGL Core (Input.hlsl: 32);
- what URP's Lighting.hlsl brings: UNITY_SPECCUBE_LOD_STEPS (Core's ImageBasedLighting.hlsl, 6),
  IsOnlyAOLightingFeatureEnabled / IsLightingFeatureEnabled (DebuggingCommon.hlsl, no debug
  view), Core's scalar LerpWhiteTo (CommonMaterial.hlsl);
- Core RP's VolumeRendering.hlsl (media and phase functions; the rest refused by name);
- Core RP's gathers (GATHER_TEXTURE2D, GATHER_RED/GREEN/BLUE/ALPHA_TEXTURE2D, the _X forms) on a
  2x2 texture of known texels.

Scene: a unit UV sphere (test_urp_library_round2.render_constant); the program returns a
constant, so every covered pixel is checked. The render target is float32: bounds are counted in
float32 roundings (2^-24 relative each) from each formula's operations.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.foundation.images import write_png
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import texture_gather
from pbrlab.render.renderer import render_scene
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

SHADER = (Path(__file__).parent / "shaders" / "s47-corenames" / "core_names.shader").read_text()
EPS = 2.0 ** -24
LIGHTING = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'
VOLUME = '#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/VolumeRendering.hlsl"'
UNITY_NAME_REFUSED = "a Unity name pbrlab does not provide"


def _render(tmp_path, body, includes="", globals_="", properties=""):
    text = SHADER % {"body": body, "includes": includes, "globals": globals_, "properties": properties}
    return {language: render_constant(tmp_path, text, language, environment=False)[0][:, :3]
            for language in LANGUAGES}


def _close(pixels, expected, bound):
    for language, px in pixels.items():
        err = np.abs(px - np.asarray(expected, np.float64)).max()
        assert err <= bound, (language, err, bound, px[0], expected)


# --- Random.hlsl through Core.hlsl ----------------------------------------------------------------
def _jenkins(x: int) -> int:
    """Bob Jenkins' one-at-a-time round on a 32-bit word (Random.hlsl's JenkinsHash)."""
    m = 0xFFFFFFFF
    x = (x + (x << 10)) & m
    x ^= x >> 6
    x = (x + (x << 3)) & m
    x ^= x >> 11
    return (x + (x << 15)) & m


def _hash(s: int) -> float:
    """Random.hlsl's Hash: xor 2747636419, three multiplies by 2654435769 (two followed by an xor
    with the word shifted right 16), the word over 2^32."""
    m = 0xFFFFFFFF
    s ^= 2747636419
    s = (s * 2654435769) & m
    s ^= s >> 16
    s = (s * 2654435769) & m
    s ^= s >> 16
    s = (s * 2654435769) & m
    return s / 2.0 ** 32


def _ign(x: float, y: float, frame: int) -> float:
    """Interleaved gradient noise (Jimenez 2014, as Core RP's Random.hlsl moves it per frame)."""
    x, y = x + frame * 2.083, y + frame * 4.867
    return math.modf(52.9829189 * math.modf(x * 0.06711056 + y * 0.00583715)[0])[0]


# float32 bound of the noise: the moved pixel (~20) is off by a few ulps of 16..32 (3 * 2^-19 each),
# the dot's products and sum add 4 roundings of ~1.35 (and the constants' own 2^-24 relative), so
# the inner fraction is off by at most 16 * 2^-24; times 52.98 (plus that product's rounding of
# ~18.6, 2^-19 * 0.5) before the outer fraction.
IGN_BOUND = 52.9829189 * 16 * EPS + 32 * EPS


def test_core_hlsl_alone_reaches_random_hlsl(tmp_path):
    """A URP program that includes only Core.hlsl calls InterleavedGradientNoise(float2(12, 7), 3),
    GenerateHashedRandomFloat(12345u) and Hash(7u): Unity's Core.hlsl includes Core RP's
    Common.hlsl, which includes Random.hlsl (Core RP 14.0.9). Values: the float64 noise within
    IGN_BOUND; the hashed float (23 bits of the Jenkins hash as a mantissa, minus 1: exact in
    float32) and Hash (a word over 2^32, one rounding) within 2^-24. Control: without the
    stand-in Core.hlsl's include of Random.hlsl the program is refused (a Unity name pbrlab does
    not provide); the frame count matters: frame 0's noise differs by far more than the bound."""
    word = _jenkins(12345)
    hashed = ((word & 0x007FFFFF) / 2.0 ** 23)
    expected = [_ign(12.0, 7.0, 3), hashed, _hash(7)]
    pixels = _render(tmp_path, "return float4(InterleavedGradientNoise(float2(12.0, 7.0), 3),"
                               " GenerateHashedRandomFloat(12345u), Hash(7u), 1.0);")
    for language, px in pixels.items():
        assert abs(px[:, 0] - expected[0]).max() <= IGN_BOUND, (language, px[0], expected)
        assert abs(px[:, 1:] - expected[1:]).max() <= EPS, (language, px[0], expected)
    assert abs(_ign(12.0, 7.0, 0) - expected[0]) > 100 * IGN_BOUND


# --- Common.hlsl's float tests and positive powers --------------------------------------------------
NAN, INF = "asfloat(0x7FC00000u)", "asfloat(0x7F800000u)"
CHECKS = (f"IsFinite(1e30) && !IsFinite({INF}) && !IsFinite({NAN}) && IsNaN({NAN}) && !IsNaN({INF})"
          f" && IsInf(-{INF}) && !IsInf(3e38) && IsPositiveFinite(0.0) && !IsPositiveFinite(-1.0)"
          f" && !IsPositiveFinite({INF}) && SanitizeFinite({INF}) == 0.0 && SanitizeFinite(2.0) == 2.0"
          f" && SanitizePositiveFinite(-{INF}) == 0.0")
# pow(x, y) is exp2(y log2 x) (GLSL 4.60 spec, 4.5.1 precision: log2 3 ulp outside [0.5, 2],
# exp2 3 + 2|x| ulp): log2(0.25)'s 3 ulps of 2 (3 * 2^-22) times 2.2 and ln 2 is ~18 ulps of
# the result, exp2(-4.4)'s own 12: 40 ulps (2^-24 relative) bound it.
POW_ULPS = 40


def test_float_classification_and_positive_pow(tmp_path):
    """R: AnyIsNaN of a float3 holding a NaN (bits 0x7FC00000) and not of a finite one; G: AnyIsInf
    of a float2 holding +inf and not of one holding 3e38; B: PositivePow(-0.25, 2.2) where every
    other test of CHECKS holds (Core RP 14.0.9 Common.hlsl: NaN and infinity told by their
    exponent and mantissa bits), else 0. Expected (1, 1, 0.25^2.2), the power within POW_ULPS
    float32 ulps. Control: before this change these names were refused (unity_library_names);
    0.25^2 (PositivePow's exponent misread) is outside the bound, and B is 0 if any check fails."""
    body = (f"float r = (AnyIsNaN(float3(1.0, {NAN}, 0.0)) && !AnyIsNaN(float3(1.0, 2.0, 3.0))) ? 1.0 : 0.0;"
            f" float g = (AnyIsInf(float2({INF}, 0.0)) && !AnyIsInf(float2(3e38, 0.0))) ? 1.0 : 0.0;"
            f" float b = ({CHECKS}) ? PositivePow(-0.25, 2.2) : 0.0; return float4(r, g, b, 1.0);")
    expected = [1.0, 1.0, 0.25 ** 2.2]
    _close(_render(tmp_path, body), expected, POW_ULPS * EPS * expected[2])
    assert abs(0.25 ** 2.0 - expected[2]) > 100 * POW_ULPS * EPS * expected[2]


def test_vector_positive_pow_safe_pow_and_safe_div(tmp_path):
    """PositivePow of a float3 with a scalar power (HLSL splats it; GLSL takes the stand-in's own
    overload), SafePositivePow of a zero base (held at FLT_EPS = 2^-24: 2^-24^0.5 = 2^-12, times
    4096 is 1) and SafeDiv per component (0 / 0 is 1, Core's rule): R = PositivePow(float3(-0.5,
    0.25, 2), 2).x = 0.25, G = SafePositivePow(0, 0.5) * 4096 = 1, B = the mean of SafeDiv((1, 2,
    0), (4, 4, 0)) = (0.25 + 0.5 + 1) / 3. Bound: POW_ULPS ulps of each power and 4 roundings of the
    mean. Control: a plain division's 0 / 0 (NaN, here B non-finite) is what SafeDiv replaces; a
    mean with 0 there (0.25) is outside the bound."""
    body = ("float3 p = PositivePow(float3(-0.5, 0.25, 2.0), 2.0);"
            " float3 d = SafeDiv(float3(1.0, 2.0, 0.0), float3(4.0, 4.0, 0.0));"
            " return float4(p.x, SafePositivePow(0.0, 0.5) * 4096.0, (d.x + d.y + d.z) / 3.0, 1.0);")
    expected = [0.25, 1.0, (0.25 + 0.5 + 1.0) / 3.0]
    _close(_render(tmp_path, body), expected, POW_ULPS * EPS)
    assert abs(0.25 - expected[2]) > 100 * POW_ULPS * EPS


# --- MAX_VISIBLE_LIGHTS ---------------------------------------------------------------------------
def test_max_visible_lights_is_urp_12s_opengl_core_count(tmp_path):
    """MAX_VISIBLE_LIGHTS after Core.hlsl alone is 32 (URP 12+ Input.hlsl, which Core.hlsl
    includes: 32 on OpenGL Core, pbrlab's SHADER_API_GLCORE), usable in #if: R = 32 / 64, G = 1
    where ``#if MAX_VISIBLE_LIGHTS == 32``; exact (powers of two). Control: a program that
    #defines it (16) before the include keeps its own, R = 0.25 (user_definitions, as for Core's
    constants: glslang refuses a redefinition inside the stand-in, where FXC would warn and take
    Unity's later body)."""
    body = "return float4(MAX_VISIBLE_LIGHTS / 64.0, PBRLAB_T_IS_32, 0.0, 1.0);"
    test = ("#if MAX_VISIBLE_LIGHTS == 32\nstatic const float PBRLAB_T_IS_32 = 1.0;\n"
            "#else\nstatic const float PBRLAB_T_IS_32 = 0.0;\n#endif")
    _close(_render(tmp_path, body, globals_=test), [0.5, 1.0, 0.0], 0.0)
    text = SHADER.replace('#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"',
                          '#define MAX_VISIBLE_LIGHTS 16\n'
                          '            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"')
    text = text % {"body": body, "includes": "", "globals": test, "properties": ""}
    for language in LANGUAGES:
        px, _ = render_constant(tmp_path, text, language, environment=False)
        assert np.abs(px[:, :3] - [0.25, 0.0, 0.0]).max() == 0.0, (language, px[0])


# --- what Lighting.hlsl brings ----------------------------------------------------------------------
def test_lighting_hlsl_brings_speccube_steps_debug_queries_and_lerp_white_to(tmp_path):
    """After Lighting.hlsl (URP's brings GlobalIllumination.hlsl -> Core's ImageBasedLighting.hlsl,
    and Debug/Debugging3D.hlsl -> DebuggingCommon.hlsl): R = UNITY_SPECCUBE_LOD_STEPS / 8 (6, an
    integer #if reads: G's branch), G = 1 where IsLightingFeatureEnabled(4u) and not
    IsOnlyAOLightingFeatureEnabled() (URP 14.0.9 DebuggingCommon.hlsl without DEBUG_DISPLAY), B =
    Core's scalar LerpWhiteTo(0.5, 0.25) = (1 - 0.25) + 0.5 * 0.25. All exact in float32. Control:
    with Core.hlsl alone (as in Unity, where Core.hlsl reaches neither file) the debug query is
    refused, the compiler's error naming it."""
    body = ("float g = (IsLightingFeatureEnabled(4u) && !IsOnlyAOLightingFeatureEnabled()) ? PBRLAB_T_STEPS : 0.0;"
            " return float4(UNITY_SPECCUBE_LOD_STEPS / 8.0, g, LerpWhiteTo(0.5, 0.25), 1.0);")
    test = ("#if UNITY_SPECCUBE_LOD_STEPS == 6\nstatic const float PBRLAB_T_STEPS = 1.0;\n"
            "#else\nstatic const float PBRLAB_T_STEPS = 0.0;\n#endif")
    _close(_render(tmp_path, body, includes=LIGHTING, globals_=test), [0.75, 1.0, 0.875], 0.0)
    text = SHADER % {"body": "return float4(IsOnlyAOLightingFeatureEnabled() ? 1.0 : 0.0, 0.0, 0.0, 1.0);",
                     "includes": "", "globals": "", "properties": ""}
    with pytest.raises(PbrlabError, match="IsOnlyAOLightingFeatureEnabled"):
        render_constant(tmp_path, text, "glsl", environment=False)


# --- VolumeRendering.hlsl ---------------------------------------------------------------------------
def _hg(g, c):
    """Henyey-Greenstein phase function, normalised over the sphere: (1 - g^2) / (4 pi) /
    (1 + g^2 - 2 g c)^(3/2)."""
    return (1 - g * g) / (4 * math.pi) / (1 + g * g - 2 * g * c) ** 1.5


def _cornette_shanks(g, c):
    """Cornette-Shanks: 3 / (8 pi) (1 - g^2) / (2 + g^2) (1 + c^2) / (1 + g^2 - 2 g c)^(3/2)."""
    return 3 / (8 * math.pi) * (1 - g * g) / (2 + g * g) * (1 + c * c) / (1 + g * g - 2 * g * c) ** 1.5


# exp: 3 + 2|x| ulps (GLSL 4.60 4.5.1) of exp(-0.75) plus the product's rounding; each phase
# function is ~10 roundings (the base's 3, rsqrt's 2 ulps, the cube's 2, the constants' products
# 3): 16 ulps relative bound either.
VOLUME_ULPS = 16


def test_volume_rendering_media_and_phase_functions(tmp_path):
    """R = TransmittanceFromOpticalDepth(OpticalDepthHomogeneousMedium(0.5, 1.5)) = exp(-0.75)
    (Beer-Lambert), G = HenyeyGreensteinPhaseFunction(0.6, 0.3) * 4, B =
    CornetteShanksPhaseFunction(0.6, 0.3) * 4 (Core RP 14.0.9 VolumeRendering.hlsl's
    normalisation), each within VOLUME_ULPS float32 ulps of the float64 formula. Control: the
    isotropic phase (1 / (4 pi), what g = 0 gives) differs from G and B by far more than the
    bound; a name the stand-in does not write (ImportanceSampleRayleighPhase) is refused as
    Unity's (unity_library_names), not as the project's mistake."""
    body = ("float t = TransmittanceFromOpticalDepth(OpticalDepthHomogeneousMedium(0.5, 1.5));"
            " return float4(t, HenyeyGreensteinPhaseFunction(0.6, 0.3) * 4.0,"
            " CornetteShanksPhaseFunction(0.6, 0.3) * 4.0, 1.0);")
    expected = np.array([math.exp(-0.75), 4 * _hg(0.6, 0.3), 4 * _cornette_shanks(0.6, 0.3)])
    _close(_render(tmp_path, body, includes=VOLUME), expected, VOLUME_ULPS * EPS * expected.max())
    isotropic = 4 / (4 * math.pi)
    assert min(abs(expected[1:] - isotropic)) > 100 * VOLUME_ULPS * EPS
    text = SHADER % {"body": "return float4(ImportanceSampleRayleighPhase(0.5), 0.0, 0.0, 1.0);",
                     "includes": VOLUME, "globals": "", "properties": ""}
    for language in LANGUAGES:
        with pytest.raises(PbrlabError, match=f"uses ImportanceSampleRayleighPhase, {UNITY_NAME_REFUSED}"):
            render_constant(tmp_path, text, language, environment=False)


# --- gathers ----------------------------------------------------------------------------------------
# A 2x2 RGBA texture (PNG rows top first), linear (no sRGB decode): texel/255 each channel.
TEXELS = np.array([[[10, 20, 30, 40], [50, 60, 70, 80]], [[90, 100, 110, 120], [130, 140, 150, 160]]], np.uint8)
GATHERS = {"GATHER_TEXTURE2D": 0, "GATHER_RED_TEXTURE2D": 0, "GATHER_GREEN_TEXTURE2D": 1,
           "GATHER_BLUE_TEXTURE2D": 2, "GATHER_ALPHA_TEXTURE2D": 3, "GATHER_TEXTURE2D_X": 0,
           "GATHER_RED_TEXTURE2D_X": 0, "GATHER_GREEN_TEXTURE2D_X": 1, "GATHER_BLUE_TEXTURE2D_X": 2}


def _gathered(channel: int) -> np.ndarray:
    """The four texels a gather at the texture's centre returns, in the order OpenGL's
    textureGather and Direct3D's Gather share (GL 4.6 spec 8.14.2: (i0, j1), (i1, j1), (i1, j0),
    (i0, j0); D3D: counter-clockwise from the lower left): j counts rows from v = 0, the image's
    bottom (Unity's uv, which pbrlab's upload keeps), so j1 is the PNG's first row."""
    t = TEXELS[..., channel].astype(np.float64) / 255.0
    return np.array([t[0, 0], t[0, 1], t[1, 1], t[1, 0]])


def _render_gather(tmp_path, language, body):
    shader = tmp_path / "t.shader"
    shader.write_text(SHADER % {"properties": '_Tex ("Tex", 2D) = "white" {}', "includes": "",
                                "globals": "TEXTURE2D(_Tex); SAMPLER(sampler_Tex);", "body": body})
    write_png(tmp_path / "texels.png", TEXELS)
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_Tex": {"path": str(tmp_path / "texels.png"), "srgb": False}}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return image[covered, :3]


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("macro", sorted(GATHERS))
def test_gathers_return_the_four_texels_of_their_channel(tmp_path, language, macro):
    """``float4 g = MACRO(_Tex, sampler_Tex, float2(0.5, 0.5))`` on the 2x2 TEXELS (the centre:
    all four texels weigh), returned as (g.x, g.y, g.z / 4 + g.w): the channel's four texels in
    gather order (_gathered), each texel/255 (an 8-bit unorm's value; the float32 conversion
    within 1 ulp), B with one more rounding: 4 ulps of a value below 1. Control: a z/w or x/y swap,
    or another channel's texels, is outside the bound (checked on the float64 values)."""
    channel = GATHERS[macro]
    g = _gathered(channel)
    expected = np.array([g[0], g[1], g[2] / 4 + g[3]])
    body = f"float4 g = {macro}(_Tex, sampler_Tex, float2(0.5, 0.5)); return float4(g.x, g.y, g.z * 0.25 + g.w, 1.0);"
    px = _render_gather(tmp_path, language, body)
    assert np.abs(px - expected).max() <= 4 * EPS, (px[0] * 255, expected * 255)
    swapped = [np.array([g[0], g[1], g[3] / 4 + g[2]]), np.array([g[1], g[0], g[2] / 4 + g[3]])]
    others = [np.array([o[0], o[1], o[2] / 4 + o[3]]) for o in map(_gathered, range(4)) if not np.array_equal(o, g)]
    assert all(np.abs(e - expected).max() > 100 * 4 * EPS for e in swapped + others)


def test_gather_extensions_only_where_a_stage_gathers():
    """The GLSL 3.30 extensions a gather needs (GL_ARB_texture_gather, GL_ARB_gpu_shader5) go after
    the #version line of a stage that calls textureGather, and nowhere else (gpu_shader5's implicit
    conversions would change other programs' overload choices). Control: a stage without a gather
    is left as it was."""
    class Source:  # shaders.Source's text is all with_gather_extensions reads
        def __init__(self, text):
            self.text = text
    gathering = texture_gather.with_gather_extensions(Source("#version 330 core\nvec4 g = textureGather(t, uv, 1);\n"))
    assert gathering.text.splitlines()[:3] == ["#version 330 core", "#extension GL_ARB_texture_gather : enable",
                                               "#extension GL_ARB_gpu_shader5 : enable"]
    plain = "#version 330 core\nvec4 c = texture(t, uv);\n"
    assert texture_gather.with_gather_extensions(Source(plain)).text == plain


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("method", ["Gather", "GatherRed", "GatherGreen", "GatherBlue", "GatherAlpha"])
def test_texture_object_gather_methods(tmp_path, language, method):
    """A Texture2D object's own gather methods (``_Tex.GatherGreen(sampler_Tex, uv)``, Microsoft's
    HLSL reference, "Texture2D.Gather" / "GatherRed" ..), the same lookups as the macros, kept in a
    float3 (HLSL truncates the float4; the GLSL port's float4 constructor lets its type pass do the
    same): (g.x, g.y, g.z) of _gathered, within 2 ulps. Control: before this change the GLSL port
    left the method for the compiler to refuse; the next channel's texels are outside the bound."""
    channel = {"Gather": 0, "GatherRed": 0, "GatherGreen": 1, "GatherBlue": 2, "GatherAlpha": 3}[method]
    body = f"float3 g = _Tex.{method}(sampler_Tex, float2(0.5, 0.5)); return float4(g, 1.0);"
    px = _render_gather(tmp_path, language, body)
    expected = _gathered(channel)[:3]
    assert np.abs(px - expected).max() <= 2 * EPS, (px[0] * 255, expected * 255)
    assert np.abs(_gathered((channel + 1) % 4)[:3] - expected).max() > 100 * 2 * EPS
