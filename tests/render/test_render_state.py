"""A render starts from the same GL state whatever rendered before it in the context: the
lit scene has depth ties (a sphere resting on the ground), and a Unity pass's ZTest LEqual
once leaked into the next render and moved 7 of its pixels by up to 1.8, so its golden
depended on which test had run before it in the pytest worker."""

from pathlib import Path

import numpy as np

from pbrlab.checking.golden_scenes import lit_scene
from pbrlab.render.renderer import render_scene
from pbrlab.scene import load_scene

UNITY_MANUAL = Path(__file__).resolve().parents[2] / "scenes" / "unity_manual" / "scene.json"


def test_a_unity_render_leaves_no_state_for_the_next_render(gl_context):
    before = render_scene(lit_scene("high"), gl_context).linear
    render_scene(load_scene(UNITY_MANUAL), gl_context)  # Unity passes set ZTest LEqual, blending, culling
    after = render_scene(lit_scene("high"), gl_context).linear
    np.testing.assert_array_equal(after, before)

