"""A hull function's ``[partitioning(...)]`` argument given by a macro (s47-stages, issue 34):
``#define PARTITION_METHOD MY_INTEGER`` / ``#define MY_INTEGER "integer"`` then
``[UNITY_partitioning(PARTITION_METHOD)]`` (and ``[UNITY_outputcontrolpoints(CONTROL_POINTS)]``),
as FXC and glslang read it: the preprocessor expands the attribute's argument like any tokens
(tessellation_syntax._expanded). Before the change pbrlab read the argument as written and refused
``[partitioning("PARTITION_METHOD")]``; the render tests below then fail.

The shaders (shaders/s47-stages/partitioning_macro.shader, its URP twin) place each plane
triangle as a patch in NDC, |x|, |y| <= S, and push a patch edge's generated vertices outward by
h = 4 A s t. A level L of integer partitioning puts ceil(L) segments on each edge at t = i / n
(D3D11's integer mode; GL 4.0 section 2.12.2, equal_spacing: "rounded up to the nearest integer"),
so a side bulges as the polyline through (i / n, h(i / n)): LEVEL 2.5 draws n = 3. Fractional odd
partitioning of level 2.5 instead gives two short segments (GL 4.0 section 2.12.2), not the
uniform polyline: the control that the macro's value, not a default, reached the draw.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.tessellation_syntax import _expanded
from pbrlab.render.renderer import render_scene

HERE = Path(__file__).parent
SHADERS = {"builtin": HERE / "shaders/s47-stages/partitioning_macro.shader",
           "urp": HERE.parent / "urp/shaders/s47-stages/urp_partitioning_macro.shader"}
S, A = 0.6, 0.25
# a pixel centre within this many pixels of the covered region's edge may fall either way under
# the rasteriser's 1/256 px snapping and float32 vertex positions (< 1e-6 px at 64 px): left out
EDGE_PX = 0.02


def _render(tmp_path, language, which, change=None):
    text = SHADERS[which].read_text()
    if change:
        text = text.replace(*change)
    shader = tmp_path / f"{which}.shader"
    shader.write_text(text)
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def _covered(X, Y, n):
    """Whether NDC (X, Y) lies in the square with each side bulged by the polyline of
    h(t) = 4 A t (1 - t) through t = i / n, in float64."""
    inside = (np.abs(X) <= S) & (np.abs(Y) <= S)
    knots = np.arange(n + 1) / n
    heights = 4 * A * knots * (1 - knots)
    for along, across in ((Y, X), (Y, -X), (X, Y), (X, -Y)):
        t = (along + S) / (2 * S)
        beyond = across - S
        inside |= (t >= 0) & (t <= 1) & (beyond > 0) & (beyond <= np.interp(t, knots, heights))
    return inside


def _wrong_pixels(image, n) -> int:
    h, w = image.shape[:2]
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    covered = _covered(X, Y, n)
    d = EDGE_PX * 2 / w
    near = np.zeros_like(covered)
    for dx in (-d, d):
        for dy in (-d, d):
            near |= _covered(X + dx, Y + dy, n) != covered
    return int((((image[..., 3] > 0) != covered) & ~near).sum())


@pytest.mark.parametrize("which", ["builtin", "urp"])
@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_macro_partitioning_draws_its_mode(tmp_path, language, which):
    image = _render(tmp_path, language, which)
    assert _wrong_pixels(image, 3) == 0      # integer at 2.5: three equal segments per edge
    assert _wrong_pixels(image, 2) > 0       # control: the expectation tells levels apart
    odd = _render(tmp_path, language, which, ('#define MY_INTEGER "integer"', '#define MY_INTEGER "fractional_odd"'))
    assert _wrong_pixels(odd, 3) > 0         # control: the macro's mode is the one drawn


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_fractional_odd_by_macro_at_a_whole_odd_level(tmp_path, language):
    """At a whole odd level fractional_odd places integer's vertices (GL 4.0 section 2.12.2)."""
    image = _render(tmp_path, language, "builtin", ('#define LEVEL 2.5', '#define LEVEL 3.0'))
    assert _wrong_pixels(image, 3) == 0


def test_the_expansion_follows_chains_and_the_last_definition():
    before = '#define B "integer"\n#define A B\n  #  define A "fractional_even"\n'
    assert _expanded("A", before) == '"fractional_even"'
    assert _expanded("B", before) == '"integer"'
    assert _expanded('"pow2"', before) == '"pow2"'
    assert _expanded("UNDEFINED", before) == "UNDEFINED"
