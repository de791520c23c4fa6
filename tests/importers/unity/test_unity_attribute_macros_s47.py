"""HLSL flow-control attributes written as a program's own macro (URP's SMAA include:
``#define SMAA_FLATTEN [flatten]``, then ``SMAA_FLATTEN if (...)``). Unity's compilers take them
(a hint on Direct3D, nothing on its GLSL targets); the GLSL port left the ``[flatten]`` where the
macro was used, and GLSL has no attribute syntax ("syntax error, unexpected '['"). The macro's
body is blanked (cg_spellings._ATTRIBUTE_MACRO), as Unity's own UNITY_BRANCH-style hints are."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking.unity_corpus import run_shader
from pbrlab.importers.unity import cg_spellings

SHADER = Path(__file__).parent / "shaders" / "s47_attribute_macros" / "AttributeMacros.shader"


def test_a_macro_of_attributes_is_blanked_in_its_definition_only():
    text = "#define F [flatten]\n#define U [unroll(4)] [loop]\n#define K 4\nF if (x) y = 1;\n"
    spelled = cg_spellings.respelled(text)
    assert spelled.splitlines()[0].rstrip() == "#define F" and spelled.splitlines()[1].rstrip() == "#define U"
    assert "#define K 4" in spelled and "F if (x)" in spelled and len(spelled) == len(text)  # offsets kept


def test_a_macro_whose_body_is_more_than_attributes_is_kept():
    """Control: an index expression is no attribute (``#define FIRST a[0]``), nor is an attribute
    name HLSL does not define for flow control."""
    text = "#define FIRST a[0]\n#define N [numthreads(8,8,1)]\n"
    assert cg_spellings.respelled(text) == text


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_attributes_change_nothing_that_is_computed(language):
    """Stripes of the sphere's UVs: red where frac(8u) > 0.5, green where frac(8v) > 0.5, and
    blue 4 x 0.125 = 0.5 from the unrolled loop, in both languages. The program is unlit and the
    corpus scene shows its output unchanged at these values (0, 0.5 and 1 are exact in float32),
    so each channel must hold exactly its two values (both branches taken somewhere) or its one.
    Fails on the GLSL port without the blanking (a compile error, not a render)."""
    o = run_shader(SHADER, language)
    assert o.status == "rendered", o.message
    rgb = np.asarray(o.image, np.float64)[..., :3]
    covered = np.asarray(o.image)[..., 3] > 0.5
    assert covered.sum() > 500
    blue = rgb[..., 2][covered]
    assert np.ptp(blue) < 1e-6 and blue.min() > 0  # the loop's 0.5 everywhere, one value
    red = rgb[..., 0][covered]
    green = rgb[..., 1][covered]
    # two values each (0 and the tone-mapped 1), both present: the branches were taken as written
    for channel in (red, green):
        values = np.unique(np.round(channel, 6))
        assert len(values) == 2 and values[0] == 0.0, values
