"""The default material charts (what `make demo` renders) against their goldens."""

import pytest

from pbrlab.checking.charts import CHARTS
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene


@pytest.mark.parametrize("chart", sorted(CHARTS))
def test_chart_matches_golden(chart, gl_context, golden):
    rendering = render_scene(parse_scene(CHARTS[chart](), origin=chart), gl_context)
    golden.check(chart, rendering.linear, rendering.srgb8)
