"""A shader test as a project that installed the pbrlab wheel would write it (scripts/check_wheel.sh).

It renders a scene the wheel ships and compares it with this project's own golden through
the ``golden`` fixture of pbrlab's pytest plugin.
"""

from pbrlab.render import renderer as render
from pbrlab.scene import model as scene
from pbrlab.foundation.locations import locate


def test_example_scene_matches_its_golden(gl_context, golden):
    example = scene.load_scene(locate("scenes") / "example.json")
    rendering = render.render_scene(example, gl_context, size=(64, 48))
    golden.check("example_scene", rendering.linear, rendering.srgb8)


def test_without_pbrlab_fixtures():
    """Runs in the same session; the plugin must not need it to use any fixture."""
    assert 1 + 1 == 2
