"""A Range property whose default lies outside its range (issue 34; Fake Interiors Free.shader's
`_RoomTile ("Room Tile", Range(0.1, 10)) = 0`): Unity keeps the default as written (the range
bounds the Inspector's slider only: importers/unity/parse.py), so pbrlab draws it as written,
warning with the file and line.

Scene: test_urp_library_round2's unit UV sphere; the pass returns the property, so every covered
pixel is checked.
"""

from __future__ import annotations

import textwrap
import warnings

import numpy as np
import pytest

from pbrlab.importers.unity import UnityShaderWarning
from test_urp_library_round2 import LANGUAGES, render_constant, urp_pass


def _with_property(default: str) -> str:
    text = urp_pass("range default", "return float4(_Tile + 0.25, 0.0, 0.0, 1.0);",
                    "float _Tile;")
    properties = textwrap.indent(f'Properties {{\n    _Tile ("Tile", Range(0.1, 10)) = {default}\n}}\n', "    ")
    return text.replace('Shader "t/range default" {\n', 'Shader "t/range default" {\n' + properties, 1)


# exact: 0 + 0.25 and 0.5 + 0.25 are float32 numbers
BOUND = 0.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_range_default_outside_its_range_is_used_as_written(tmp_path, language):
    """Default 0 with Range(0.1, 10): the pixel's red is 0 + 0.25 (as written), and a warning
    names the file, the line and the property. Controls: clamped, it would be 0.1 + 0.25, far
    outside the bound; a default inside the range (0.5) draws 0.75 with no such warning."""
    text = _with_property("0")
    line = text.splitlines().index(next(ln for ln in text.splitlines() if "_Tile (" in ln)) + 1
    with pytest.warns(UnityShaderWarning) as caught:
        pixels, _ = render_constant(tmp_path, text, language, environment=False)
    messages = [str(w.message) for w in caught]
    assert any(f"t.shader:{line}: _Tile: default 0 lies outside its Range(0.1, 10); used as written" in m
               for m in messages), messages
    assert (np.abs(pixels[:, 0] - 0.25) > BOUND).mean() == 0.0
    assert abs((0.1 + 0.25) - 0.25) > 1000 * 2.0 ** -24  # the clamped value is told apart
    with warnings.catch_warnings(record=True) as inside:
        warnings.simplefilter("always")
        pixels, _ = render_constant(tmp_path, _with_property("0.5"), language, environment=False)
    assert not any("outside its Range" in str(w.message) for w in inside)
    assert (np.abs(pixels[:, 0] - 0.75) > BOUND).mean() == 0.0


# A global with an initialiser and no property (WoBok's Color.shader: `float c_r=1;` in its
# UnityPerMaterial): a uniform in Unity, whose initialiser Unity ignores (a value no property
# or global sets is 0), as glslang's HLSL reads it; the GLSL port declares the uniform alone.
INITIALISED = "float _Gain = 2.0;\n            static float _Kept = 0.5;"


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_uniform_initialiser_is_not_its_value(tmp_path, language):
    """The pixel's red is _Gain + 0.25 = 0.25 (the uniform's 0, not its initialiser 2), green
    the static's 0.5 (a static's initialiser is its value). Control: the initialiser as the value
    would give 2.25, far outside the exact bound."""
    text = urp_pass("initialised global", "return float4(_Gain + 0.25, _Kept, 0.0, 1.0);", INITIALISED)
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    assert (np.abs(pixels[:, :2] - [0.25, 0.5]).max(axis=1) > BOUND).mean() == 0.0


def test_a_macros_body_keeps_its_initialised_locals():
    """A line of a multi-line #define at brace depth 0 (UnityStandardParticles.cginc's
    fragColorMode(i): ``half3 particleHSV = RGBtoHSV(...); \\``) is the macro's text, not a global:
    its initialiser stays; a global's after it is still taken out (the control)."""
    from pbrlab.importers.unity import port
    text = "#define TINT(i) \\\n    float hsv = i.x; \\\n    i.y = hsv;\nfloat g = 2.0;\n"
    ported = port.port_text(text)
    assert "float hsv = i.x;" in ported and "uniform float hsv" not in ported
    assert "uniform float g;" in ported
