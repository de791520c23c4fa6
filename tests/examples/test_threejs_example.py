"""The three.js example (examples/threejs): the amalgamated library in a three.js ShaderMaterial,
fed the exported DFG table (pbrlab tables), drawn in headless Chromium (WebGL2 on
SwiftShader, tools/threejs/render.mjs) and compared with `pbrlab render` of the same
scene.json.

Tolerance, measured (192 x 96, 5,808 sphere pixels): relative difference max(|a - b|) /
max(|a|, 0.01) per pixel: 5 % of pixels over 3e-3, 1.1 % over 1e-2, 0.1 % (6) over 2e-2,
worst 3.4e-2 (gold's highlight, radiance 53, where GGX's narrow peak amplifies a float32
difference in the normal; the ray comes from the interpolated bounding mesh there, from
the camera basis in pbrlab); two bilinear filters (SwiftShader's and llvmpipe's) read the
DFG table with their own weight precision. Allowed: 2e-2 for all but 0.5 % of pixels, 5e-2
for every pixel; coverage may differ on 0.1 % of pixels (silhouettes). A gold 0.05 rougher
fails it (the control below)."""

from __future__ import annotations

from pathlib import Path

import pytest

from browser_example import (is_driver_performance_notice, render_float, rougher_gold_within_tolerance,
                             setup_problems, within_tolerance)
from example_page import MIN_DRAWN_FRACTION, page_of_scene
from pbrlab.gpu import engine_tables, shaders
from pbrlab.render.renderer import render_scene
from pbrlab.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "threejs"
TOOL = ROOT / "tools" / "threejs"


@pytest.fixture(scope="module")
def threejs_render(tmp_path_factory):
    problems = setup_problems(TOOL, ("three", "playwright-core"))
    assert not problems, "; ".join(problems) + " (bash scripts/setup.sh installs them)"
    tmp = tmp_path_factory.mktemp("threejs")
    library = tmp / "pbrlab_library.glsl"
    library.write_text(shaders.expand_file(EXAMPLE / "library_entry.glsl", [], line_directives=False).text,
                       encoding="utf-8")
    engine_tables.write_tables(tmp)
    return render_float(TOOL, EXAMPLE / "scene.json", library, tmp / "pbrlab_dfg.exr", tmp)


def test_threejs_draws_the_scene_as_pbrlab_renders_it(threejs_render, gl_context):
    pixels, meta = threejs_render
    scene = load_scene(EXAMPLE / "scene.json")
    ours = render_scene(scene, gl_context).linear
    assert pixels.shape == ours.shape
    assert (pixels[..., 3] > 0).mean() > 0.25  # the spheres were drawn
    ok, figures = within_tolerance(ours, pixels)
    assert ok, f"three.js ({meta['renderer']}, r{meta['three']}) against pbrlab render: {figures}"


def test_the_tolerance_tells_a_rougher_gold_apart(threejs_render, gl_context):
    """The control: pbrlab render of the scene with the gold 0.05 rougher fails the check."""
    pixels, _ = threejs_render
    ok, figures = rougher_gold_within_tolerance(EXAMPLE, pixels, gl_context)
    assert not ok, figures


def test_only_chromiums_performance_notices_are_left_out():
    notice = ("warning: [.WebGL-0xc7400421a00]GL Driver Message (OpenGL, Performance, GL_CLOSE_PATH_NV, "
              "High): GPU stall due to ReadPixels (this message will no longer repeat)")
    assert is_driver_performance_notice(notice)
    assert not is_driver_performance_notice("error: THREE.WebGLProgram: Shader Error 1282 - VALIDATE_STATUS false")
    assert not is_driver_performance_notice("warning: THREE.WebGLProgram: Program Info Log: 'x' : undeclared identifier")
    assert not is_driver_performance_notice("pageerror: GL Driver Message (OpenGL, Performance, x)")


def test_the_page_shows_the_spheres(threejs_render, tmp_path):
    """index.html as README.md has a reader open it draws scene.json on its canvas
    (tests/examples/example_page.py: the bound and why)."""
    status, drawn, messages = page_of_scene(TOOL, EXAMPLE, threejs_render[1]["files"], tmp_path)
    assert status == "scene.json, drawn by three.js with the pbrlab library", status
    assert not messages, messages
    assert drawn >= MIN_DRAWN_FRACTION, f"{drawn:.1%} of the canvas drawn"


def test_the_page_check_fails_on_an_empty_canvas(threejs_render, tmp_path):
    """The control: the same page drawing a scene without objects says it drew, yet fails."""
    status, drawn, _ = page_of_scene(TOOL, EXAMPLE, threejs_render[1]["files"], tmp_path, without_objects=True)
    assert status == "scene.json, drawn by three.js with the pbrlab library", status
    assert drawn < MIN_DRAWN_FRACTION, f"{drawn:.1%}"
