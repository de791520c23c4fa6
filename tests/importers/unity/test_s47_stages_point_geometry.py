"""Point-input geometry functions (``void geom(point v2g IN[1], inout TriangleStream<g2f> s)``:
billboards, grass; s47-stages, issue 34). Unity draws a mesh's triangles whatever the geometry
function's input; D3D11 drivers that draw the mismatch give the function each triangle's first
vertex as its point (DXVK's emulation of them: geometry_stage.py's docstring has the sources).
Before the change pbrlab refused ``point`` input by name; the render tests below then fail.

The shaders (shaders/s47-stages/point_billboard.shader, its URP twin) place the plane's corners
(x, z) / 0.3 at NDC (S x / 0.3, -S z / 0.3) and emit a square of half side HALF around the point,
coloured (uv, 0.5). The plane's two triangles are (0, 2, 1) and (0, 3, 2)
(scene/primitives.plane): both start at corner 0, (x, z) = (-0.3, -0.3), uv (0, 1), so the
only square is around NDC (-S, S), coloured (0, 1, 0.5) exactly. Control: drawing each mesh
vertex as a point (GL_POINTS) would add squares at the other three corners; those pixels must
stay empty.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

HERE = Path(__file__).parent
SHADERS = {"builtin": HERE / "shaders/s47-stages/point_billboard.shader",
           "urp": HERE.parent / "urp/shaders/s47-stages/urp_point_billboard.shader"}
S, HALF = 0.6, 0.1
EDGE_PX = 0.02  # pixel centres this close to a square's edge may fall either way (1/256 px snapping)


def _render(tmp_path, language, which, change=None):
    text = SHADERS[which].read_text()
    if change:
        text = text.replace(*change)
    shader = tmp_path / f"{which}.shader"
    shader.write_text(text)
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def _square(shape, cx, cy, margin=0.0):
    h, w = shape
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    return (np.abs(X - cx) <= HALF + margin) & (np.abs(Y - cy) <= HALF + margin)


@pytest.mark.parametrize("which", ["builtin", "urp"])
@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_each_triangle_draws_its_first_vertex(tmp_path, language, which):
    image = _render(tmp_path, language, which)
    shape = image.shape[:2]
    d = EDGE_PX * 2 / shape[1]
    inner, outer = _square(shape, -S, S, -d), _square(shape, -S, S, d)
    drawn = image[..., 3] > 0
    assert inner.sum() > 20
    assert drawn[inner].all() and not drawn[~outer].any()
    assert np.array_equal(image[inner][:, :3], np.tile([0.0, 1.0, 0.5], (int(inner.sum()), 1)))
    for cx, cy in ((S, S), (S, -S), (-S, -S)):  # control: no point at the other corners
        assert _square(shape, cx, cy, -d).sum() > 20 and not drawn[_square(shape, cx, cy, -d)].any()


@pytest.mark.parametrize("change, named", [
    (("point v2g IN[1]", "line v2g IN[2]"), "takes line input"),
    (("point v2g IN[1]", "point v2g IN[3]"), r"a point input array holds 1 vertex"),
])
def test_other_inputs_are_refused_by_name(tmp_path, change, named):
    with pytest.raises(PbrlabError, match=r"builtin\.shader:\d+: .*" + named):
        _render(tmp_path, "glsl", "builtin", change)
