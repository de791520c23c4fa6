"""Include and name gaps real URP shaders met (issue 34, session 46): an include named in angle
brackets (``#include <file>``, read as Unity reads a quoted one), Unity 6.0's four-argument
OUTPUT_SH4 beside Unity 6.1's five, and a call of a function nothing defines (``Remap``, which
neither URP's nor Core's ShaderLibrary defines) refused as the project's own mistake naming the
file and line. Rendered in both languages from minimal shaders of our own, against float64
values, each with a control.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity.cg_spellings import respelled
from test_urp_library_round2 import AMBIENT_BOUND, AMBIENT_INCLUDE, LANGUAGES, _expected_ambient, render_constant
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24


# --- #include <name> -------------------------------------------------------------------------
# helper.hlsl (beside the shader) includes gain.hlsl in angle brackets too: the respelling holds
# for the project's include files as for the program.
HELPER = "#include <gain.hlsl>\nfloat3 Tinted(float3 c) { return c * PBRLAB_TEST_GAIN; }\n"
GAIN = "#define PBRLAB_TEST_GAIN 0.5\n"


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_include_in_angle_brackets_is_read_as_a_quoted_one(tmp_path, language):
    """``#include <helper.hlsl>`` in the program and ``#include <gain.hlsl>`` inside it: Unity's
    compiler looks for either spelling in the including file's folder, then its own include
    folders; pbrlab reads them as quoted names. The pixel is (0.2, 0.4, 0.6) times the included
    gain 0.5. Bound: one float32 product each, 2^-24 relative. Control: without the include the
    program's own fallback gain 1 gives (0.2, 0.4, 0.6), which the bound rejects."""
    (tmp_path / "helper.hlsl").write_text(HELPER)
    (tmp_path / "gain.hlsl").write_text(GAIN)
    body = "return float4(Tinted(float3(0.2, 0.4, 0.6)), 1.0);"
    text = NAMES44_SHADER % {"properties": "", "includes": "#include <helper.hlsl>", "globals": "", "body": body}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    expected = np.array([0.2, 0.4, 0.6]) * 0.5
    assert (np.abs(pixels[:, :3] - expected) <= 2 * EPS).all(), (pixels[0], expected)
    control = np.array([0.2, 0.4, 0.6])
    assert (np.abs(control - expected) > 100 * EPS).all()


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_missing_include_in_angle_brackets_is_refused_by_name(tmp_path, language):
    """A project's include in angle brackets that no folder holds is refused naming it, as a
    quoted one is (Unity would not find it either). Control: the quoted spelling's refusal names
    the same file."""
    for spelled in ("<absent_helper.hlsl>", '"absent_helper.hlsl"'):
        text = NAMES44_SHADER % {"properties": "", "includes": f"#include {spelled}", "globals": "",
                                 "body": "return float4(1, 1, 1, 1);"}
        with pytest.raises(PbrlabError, match="absent_helper.hlsl"):
            render_constant(tmp_path, text, language, environment=False)


# --- OUTPUT_SH4 of four arguments (Unity 6.0) ----------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_four_argument_output_sh4_is_the_ambient_probe_at_the_normal(tmp_path, language):
    """Unity 6.0's OUTPUT_SH4 (position, normal, view direction, the SH output; Unity 6.1 added
    the probe occlusion output, test_urp_unity6_names) writes the ambient probe's SH at the normal
    as the five-argument form does without probe volumes. Normal -y: the float64 SH9 irradiance
    along -y over pi (unity_AmbientGround's value), within AMBIENT_BOUND. Control: the SH along +y
    (unity_AmbientSky), which differs by far more than the bound; and the spelling renames the
    four-argument call only (a five-argument call keeps its name)."""
    body = ("float3 sh = float3(0, 0, 0); float3 p = float3(0.3, 0.2, 0.1);"
            " OUTPUT_SH4(p, float3(0, -1, 0), GetWorldSpaceNormalizeViewDir(p), sh); return float4(sh, 1.0);")
    pixels, scene = render_constant(
        tmp_path, NAMES44_SHADER % {"properties": "", "includes": AMBIENT_INCLUDE, "globals": "", "body": body}, language)
    ground, sky = (_expected_ambient(scene, n) for n in ("unity_AmbientGround", "unity_AmbientSky"))
    assert (np.abs(pixels[:, :3] - ground).max(axis=1) > AMBIENT_BOUND).mean() == 0.0, (pixels[0], ground)
    assert np.abs(sky - ground).max() > 100 * AMBIENT_BOUND
    assert respelled("OUTPUT_SH4(a, f(b, c), d, o.sh);") == "OUTPUT_SH4_FOUR_ARGUMENTS(a, f(b, c), d, o.sh);"
    assert respelled("OUTPUT_SH4(a, b, d, o.sh, o.occ);") == "OUTPUT_SH4(a, b, d, o.sh, o.occ);"


# --- a call of a function nothing defines ---------------------------------------------------------
REMAP_BODY = "float y = Remap(1.0, 10.0, 0.0, 1.0, 4.0);\n return float4(y, y * 0.5, 0.0, 1.0);"
OWN_REMAP = ("float Remap(float a, float b, float c, float d, float x)"
             " { return c + (x - a) * (d - c) / (b - a); }")


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_undefined_function_is_refused_as_the_projects_mistake(tmp_path, language):
    """``Remap(...)`` in a program that defines none: URP's and Core RP's ShaderLibrary define no
    Remap either (Core's Common.hlsl has Remap01 and Remap10 only), so Unity's compiler refuses it
    too; the refusal says the project's own code calls an undefined function, naming the file and
    the call's line. Control: with the project's own Remap (a linear map of [1, 10] onto [0, 1])
    the shader renders its float64 value (4 - 1) / 9, within a few float32 roundings."""
    text = NAMES44_SHADER % {"properties": "", "includes": "", "globals": "", "body": REMAP_BODY}
    line = next(i for i, row in enumerate(text.splitlines(), 1) if "Remap(" in row)
    with pytest.raises(PbrlabError, match=rf"t\.shader:{line}: calls Remap, a function that neither the shader.*"
                                          r"the project's own code calls an undefined function"):
        render_constant(tmp_path, text, language, environment=False)
    text = NAMES44_SHADER % {"properties": "", "includes": "", "globals": OWN_REMAP, "body": REMAP_BODY}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    y = (4.0 - 1.0) / 9.0
    assert (np.abs(pixels[:, :3] - [y, y * 0.5, 0.0]) <= 8 * EPS).all(), pixels[0]


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_unity_library_function_pbrlab_lacks_is_named_as_unitys(tmp_path, language):
    """A call of a function Core RP's ShaderLibrary defines (Color.hlsl's ApplyLut3D) that pbrlab's
    stand-ins do not: the refusal names it as one of Unity's names pbrlab does not provide, not as
    the project's mistake (unity_library_names). Control: Remap, which Unity's library does not
    define, is the project's (test above)."""
    from pbrlab.importers.unity.unity_library_names import UNITY_LIBRARY_NAMES
    from pbrlab.importers.unity.unprovided import provided_names
    name = next(n for n in ("ApplyLut3D", "GetLutStripValue", "RangeRemap") if n not in provided_names())
    assert name in UNITY_LIBRARY_NAMES and "Remap" not in UNITY_LIBRARY_NAMES
    body = f"float3 c = {name}(float3(0.5, 0.5, 0.5), float3(1.0, 1.0, 1.0));\n return float4(c, 1.0);"
    text = NAMES44_SHADER % {"properties": "", "includes": "", "globals": "", "body": body}
    with pytest.raises(PbrlabError, match=rf"uses {name}, a Unity name pbrlab does not provide"):
        render_constant(tmp_path, text, language, environment=False)


# --- Core RP's FastSign and ApplyLut2D (a project's copy of URP's post-processing Common.hlsl) ----
@pytest.mark.parametrize("language", LANGUAGES)
def test_fast_sign_counts_zero_as_positive(tmp_path, language):
    """Core's FastSign: -1 for -0.3, +1 for 0 (ignoreNegZero, the default: -0 is +0), -1 for -0 with
    ignoreNegZero false (its sign bit). The pixel maps each to 0.5 + 0.25 s: exact. Control: HLSL's
    sign(0) is 0 (0.5), which differs from FastSign's 1 (0.75)."""
    body = ("float z = -0.3 * 0.0;"  # -0 at run time (a literal -0.0 may be folded to +0)
            " return float4(0.5 + 0.25 * FastSign(-0.3), 0.5 + 0.25 * FastSign(0.0),"
            " 0.5 + 0.25 * FastSign(z, false), 1.0);")
    text = NAMES44_SHADER % {"properties": "", "includes": "", "globals": "", "body": body}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    assert (pixels[:, :3] == [0.25, 0.75, 0.25]).all(), pixels[0]
    assert 0.5 + 0.25 * np.sign(0.0) != 0.75


LUT_PASS = NAMES44_SHADER.replace('Shader "t/names44" {', 'Shader "t/lut" {')


def _render_lut(tmp_path, language, body):
    """The pixels of a pass that grades through _Lut, a 2-slice identity table (4 x 2 texels)."""
    from pbrlab.checking import unity_corpus as corpus
    from pbrlab.foundation.images import write_png
    from pbrlab.importers.loader import parse_scene
    from pbrlab.render.renderer import render_scene
    # texel (x = 2 b + r, row from the top = 1 - g) holds (r, g, b), each 0 or 1: the same value
    # in sRGB and linear, so the table is the identity whatever the texture's colour space
    lut = np.zeros((2, 4, 4), np.uint8)
    for x in range(4):
        for row in range(2):
            lut[row, x] = [255 * (x % 2), 255 * (1 - row), 255 * (x // 2), 255]
    write_png(tmp_path / "lut.png", lut)
    shader = tmp_path / "t.shader"
    shader.write_text(LUT_PASS % {"properties": '_Lut ("lut", 2D) = "white" {}', "includes": AMBIENT_INCLUDE.replace(
        "universal/ShaderLibrary/Lighting.hlsl", "core/ShaderLibrary/Color.hlsl"),
        "globals": "TEXTURE2D(_Lut); SAMPLER(sampler_Lut);", "body": body})
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_Lut": {"path": str(tmp_path / "lut.png")}}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    return image[image[..., 3] == 1.0, :3]


@pytest.mark.parametrize("language", LANGUAGES)
def test_apply_lut_2d_of_an_identity_table_returns_its_input(tmp_path, language):
    """Core's ApplyLut2D of a colour through a strip table with scaleOffset (1 / width, 1 / height,
    N - 1): trilinear interpolation of the table, so an identity table (N = 2, corners 0 and 1)
    returns the colour, (0.25, 0.75, 0.5) here. Bound: bilinear filtering's weights, which GL lets
    an implementation hold to 8 fractional bits (llvmpipe does): 2^-8 per lookup, two lookups
    blended (the weights here, 1/4 and 3/4, are exact in 8 bits). Control: a wrong scaleOffset (1 /
    height 0.75 for 0.5, a table of another size) moves the lookup off the texel centres and onto
    another slice: it differs by more than the bound."""
    body = ("float3 c = ApplyLut2D(TEXTURE2D_ARGS(_Lut, sampler_Lut), float3(0.25, 0.75, 0.5),"
            " float3(0.25, 0.5, 1.0)); return float4(c, 1.0);")
    got = _render_lut(tmp_path, language, body)
    bound = 2 * 2.0 ** -8
    assert got.shape[0] > 200
    assert (np.abs(got - [0.25, 0.75, 0.5]).max(axis=1) > bound).mean() == 0.0, got[0]
    edges = _render_lut(tmp_path, language, body.replace("float3(0.25, 0.5, 1.0)", "float3(0.25, 0.75, 1.0)"))
    assert (np.abs(edges - [0.25, 0.75, 0.5]).max(axis=1) > bound).mean() > 0.9
