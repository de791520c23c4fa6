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
    """A call of a function Core RP's ShaderLibrary defines (Color.hlsl's ApplyLut2D) that pbrlab's
    stand-ins do not: the refusal names it as one of Unity's names pbrlab does not provide, not as
    the project's mistake (unity_library_names). Control: Remap, which Unity's library does not
    define, is the project's (test above)."""
    from pbrlab.importers.unity.unity_library_names import UNITY_LIBRARY_NAMES
    from pbrlab.importers.unity.unprovided import provided_names
    name = next(n for n in ("ApplyLut2D", "ApplyLut3D", "GetLutStripValue") if n not in provided_names())
    assert name in UNITY_LIBRARY_NAMES and "Remap" not in UNITY_LIBRARY_NAMES
    body = f"float3 c = {name}(float3(0.5, 0.5, 0.5), float3(1.0, 1.0, 1.0));\n return float4(c, 1.0);"
    text = NAMES44_SHADER % {"properties": "", "includes": "", "globals": "", "body": body}
    with pytest.raises(PbrlabError, match=rf"uses {name}, a Unity name pbrlab does not provide"):
        render_constant(tmp_path, text, language, environment=False)
