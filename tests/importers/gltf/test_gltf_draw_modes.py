"""How glTF primitives are drawn (issue 24): EXT_mesh_gpu_instancing as one instanced draw
(instanced_draws.py), and the POINTS, LINES, LINE_LOOP and LINE_STRIP modes
(gltf/points_lines.py). Assets: scenes/gltf/make_draw_assets.py."""

from __future__ import annotations

import numpy as np
import pytest

from gltf_helpers import quad_document
from pbrlab.render import instanced_draws
from pbrlab.checking.golden_scenes import GLTF_DIR
from pbrlab.importers.gltf import load_gltf
from pbrlab.render.renderer import render_scene
from pbrlab.scene.model import Environment
from test_gltf_errors import _refused

ENV = Environment(color=np.array([0.3, 0.3, 0.35]))
PIXELS = 64  # points_lines.gltf puts its vertices on this image's pixel centres
FLOAT32 = 1e-6  # linear radiance: float32 rounding of the same value computed twice


def _load(name, size):
    return load_gltf(GLTF_DIR / name, size=size, environment=ENV, emit_warnings=False)


# --- EXT_mesh_gpu_instancing ------------------------------------------------------------

def test_125_instances_are_one_draw_call_and_the_same_image_as_125(monkeypatch):
    result = _load("instanced_cubes.glb", (128, 128))
    assert result.warnings == [] and len(result.scene.objects) == 125
    instanced = render_scene(result.scene)
    monkeypatch.setattr(instanced_draws, "batches", lambda ordered, instanceable: [[o] for o in ordered])
    one_by_one = render_scene(result.scene)
    assert (instanced.draw_calls, one_by_one.draw_calls) == (1, 125)
    assert (instanced.linear[..., 3] > 0).mean() > 0.2  # the cubes fill a fifth of the frame
    np.testing.assert_array_equal(instanced.linear, one_by_one.linear)


def test_instances_of_a_blended_material_are_drawn_one_by_one_far_to_near():
    scene = _load("instanced_cubes.glb", (32, 32)).scene
    next(iter(scene.materials.values())).alpha_mode = "fade"
    assert render_scene(scene).draw_calls == 125


def test_a_batch_is_drawn_where_its_first_instance_stood():
    class Obj:
        def __init__(self, group, geometry="g", material="m"):
            self.instance_group, self.geometry, self.material = group, geometry, material
    a0, single, a1, b0 = Obj("a"), Obj(None), Obj("a"), Obj("a", material="other")
    assert instanced_draws.batches([a0, single, a1, b0], lambda o: True) == [[a0, a1], [single], [b0]]
    assert instanced_draws.batches([a0, a1], lambda o: False) == [[a0], [a1]]


# --- POINTS and LINES -------------------------------------------------------------------

@pytest.fixture(scope="module")
def points_lines():
    result = _load("points_lines.gltf", (PIXELS, PIXELS))
    return result, render_scene(result.scene).linear


def _pixel(image, column, row):
    return image[row, column]


def test_points_and_lines_are_drawn_without_warnings(points_lines):
    result, _ = points_lines
    assert result.warnings == []
    topologies = sorted(o.geometry.topology for o in result.scene.objects)
    assert topologies == ["lines"] * 4 + ["points", "triangles"]


def test_points_land_on_their_pixels_unlit_in_their_vertex_colours(points_lines):
    _, image = points_lines
    grid = [(c, r) for r in (4, 8, 12) for c in (4, 10, 16, 22, 28)]
    for c, r in grid:  # make_draw_assets.points_lines: base colour white x COLOR_0, no light
        expected = [(c % 3 == 0) * 0.75 + 0.25, r / 12, 1.0 - c / 32]
        np.testing.assert_allclose(_pixel(image, c, r)[:3], expected, atol=FLOAT32)
        assert _pixel(image, c, r)[3] == 1.0
        assert _pixel(image, c + 1, r)[3] == 0.0 and _pixel(image, c, r + 1)[3] == 0.0  # one pixel each


def test_line_modes_join_their_vertices_as_the_specification_says(points_lines):
    result, image = points_lines
    orange = next(m for m in result.scene.materials.values() if m.name.startswith("orange [unlit")).albedo
    covered = image[..., 3] > 0
    # LINES: (36, 4)-(60, 4) and (36, 10)-(60, 12), not (60, 4)-(36, 10)
    np.testing.assert_allclose(image[4, 37:60, :3], np.tile(orange[:3], (23, 1)), atol=FLOAT32)
    assert covered[9:14, 37:60].sum(axis=0).min() >= 1 and not covered[6:8, 44:52].any()
    # LINE_LOOP: the square's four sides, the last vertex joined to the first (column 6)
    assert covered[21:34, 6].all() and covered[21:34, 26].all() and covered[20, 7:26].all() and covered[34, 7:26].all()
    # LINE_STRIP: the zigzag, not closed (row 20 between its vertices stays empty)
    assert covered[25, 37:56].sum() >= 4 and not covered[20, 48:51].any()


def test_a_line_with_normals_is_lit_as_a_surface_of_its_material(points_lines):
    result, image = points_lines
    lit_line = _pixel(image, 16, 44)[:3]
    quad = image[46:58, 44:56, :3].reshape(-1, 3)  # inside the quad of the same material and normal
    np.testing.assert_allclose(quad, np.tile(quad[0], (len(quad), 1)), atol=FLOAT32)
    np.testing.assert_allclose(lit_line, quad[0], rtol=1e-5)
    unlit = next(m for m in result.scene.materials.values() if m.name.startswith("orange [unlit")).albedo
    assert np.abs(lit_line - np.asarray(unlit[:3])).max() > 0.05  # lit, not the unlit base colour


@pytest.mark.parametrize("mode, count, message", [(1, 3, "a LINES primitive needs an even number of vertices, got 3"),
                                                  (3, 1, "a LINE_STRIP primitive needs 2 vertices at least, got 1")])
def test_a_line_primitive_with_too_few_vertices_is_refused(tmp_path, capsys, mode, count, message):
    doc = quad_document()
    doc["accessors"].append({"bufferView": 3, "componentType": 5123, "count": count, "type": "SCALAR"})
    doc["meshes"][0]["primitives"][0].update({"mode": mode, "indices": len(doc["accessors"]) - 1})
    _refused(tmp_path, capsys, doc, f"meshes[0].primitives[0]: {message}")
