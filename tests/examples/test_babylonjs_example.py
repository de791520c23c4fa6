"""The Babylon.js example (examples/babylonjs): the library amalgamated by `pbrlab amalgamate`
and handed to Babylon.js 9 unchanged (its own preprocessor evaluates the conditionals:
glsl/README.md, "One-level preprocessors"), in a ShaderMaterial fed the exported DFG table
(`pbrlab tables`, read by Babylon.js's EXR loader), drawn in headless Chromium (WebGL2 on
SwiftShader, tools/babylonjs/render.mjs) and compared with `pbrlab render` of the same
scene.json (the three.js example's scene).

Tolerance: the three.js example's (tests/examples/test_threejs_example.py), whose error sources
this render shares: the pixel's ray comes from the interpolated bounding mesh in float32 (from
the camera basis in pbrlab), which moves the normal most where it turns fastest, at the
silhouettes and in gold's narrow GGX highlight; SwiftShader's bilinear filter reads the DFG
table with its own weight precision. Relative difference max(|a - b|) / max(|a|, 0.01) per
pixel: 2e-2 for all but 0.5 % of pixels, 5e-2 for every pixel; coverage may differ on 0.1 %
of pixels. Measured (192 x 96, 5,808 sphere pixels): 6.7 % of pixels over 3e-3, 1.3 % over
1e-2, 0.24 % (14) over 2e-2, worst 4.5e-2 (the red sphere's silhouette, radiance 0.33);
coverage differs on 0.02 %. For scale, Babylon.js against three.js on the same scene: 0.57 %
over 2e-2, worst 5.7e-2 (their two ray set-ups' errors add). A gold 0.05 rougher fails it
(43 % of pixels over 2e-2: the control below)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from browser_example import (TIMEOUT_S, render_float, rougher_gold_within_tolerance,
                             setup_problems, within_tolerance)
from example_page import MIN_DRAWN_FRACTION, page_of_scene
from pbrlab.gpu import engine_tables
from pbrlab.render.renderer import render_scene
from pbrlab.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "babylonjs"
TOOL = ROOT / "tools" / "babylonjs"


@pytest.fixture(scope="module")
def babylon_render(tmp_path_factory):
    problems = setup_problems(TOOL, ("@babylonjs/core", "fflate", "playwright-core"))
    assert not problems, "; ".join(problems) + " (bash scripts/setup.sh installs them)"
    tmp = tmp_path_factory.mktemp("babylonjs")
    library = tmp / "pbrlab_library.glsl"
    # The library exactly as the command writes it.
    amalgamate = subprocess.run([sys.executable, "-m", "pbrlab", "amalgamate", str(EXAMPLE / "library_entry.glsl"),
                                 "-o", str(library)], capture_output=True, text=True, timeout=TIMEOUT_S)
    assert amalgamate.returncode == 0, amalgamate.stderr
    engine_tables.write_tables(tmp)
    return render_float(TOOL, EXAMPLE / "scene.json", library, tmp / "pbrlab_dfg.exr", tmp)


def test_babylonjs_draws_the_scene_as_pbrlab_renders_it(babylon_render, gl_context):
    pixels, meta = babylon_render
    assert meta["babylon"].startswith("9."), meta["babylon"]
    scene = load_scene(EXAMPLE / "scene.json")
    ours = render_scene(scene, gl_context).linear
    assert pixels.shape == ours.shape
    assert (pixels[..., 3] > 0).mean() > 0.25  # the spheres were drawn
    ok, figures = within_tolerance(ours, pixels)
    assert ok, f"Babylon.js {meta['babylon']} ({meta['renderer']}) against pbrlab render: {figures}"


def test_the_tolerance_tells_a_rougher_gold_apart(babylon_render, gl_context):
    """The control: pbrlab render of the scene with the gold 0.05 rougher fails the check."""
    pixels, _ = babylon_render
    ok, figures = rougher_gold_within_tolerance(EXAMPLE, pixels, gl_context)
    assert not ok, figures


def test_the_page_shows_the_spheres(babylon_render, tmp_path):
    """index.html as README.md has a reader open it draws scene.json on its canvas
    (tests/examples/example_page.py: the bound and why)."""
    status, drawn, messages = page_of_scene(TOOL, EXAMPLE, babylon_render[1]["files"], tmp_path)
    assert status == "scene.json, drawn by Babylon.js with the pbrlab library", status
    assert not messages, messages
    assert drawn >= MIN_DRAWN_FRACTION, f"{drawn:.1%} of the canvas drawn"


def test_the_page_check_fails_on_an_empty_canvas(babylon_render, tmp_path):
    """The control: the same page drawing a scene without objects says it drew, yet fails."""
    status, drawn, _ = page_of_scene(TOOL, EXAMPLE, babylon_render[1]["files"], tmp_path, without_objects=True)
    assert status == "scene.json, drawn by Babylon.js with the pbrlab library", status
    assert drawn < MIN_DRAWN_FRACTION, f"{drawn:.1%}"
