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

import copy
import json
import os
import shutil
import signal
import subprocess
from pathlib import Path

import numpy as np
import pytest

from example_page import MIN_DRAWN_FRACTION, drawn_fraction, view_of_page
from pbrlab.gpu import engine_tables, shaders
from pbrlab.render.renderer import render_scene
from pbrlab.scene import load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "threejs"
TOOL = ROOT / "tools" / "threejs"
CHROMIUM = Path(os.environ.get("PBRLAB_CHROMIUM", "/usr/bin/chromium"))
TIMEOUT_S = 180
RELATIVE_FLOOR = 1e-2      # radiance below which the difference is taken as absolute
MAX_RELATIVE = 2e-2        # for all but FRACTION_OVER of the pixels
FRACTION_OVER = 5e-3
CAP_RELATIVE = 5e-2        # for every pixel
COVERAGE_FRACTION = 1e-3


def _setup_problems() -> list[str]:
    problems = []
    if shutil.which("node") is None:
        problems.append("node is not on PATH")
    if not CHROMIUM.is_file():
        problems.append(f"{CHROMIUM} is missing")
    for package in ("three", "playwright-core"):
        if not (TOOL / "node_modules" / package / "package.json").is_file():
            problems.append(f"npm package {package} is not installed in {TOOL}")
    return problems


def _is_driver_performance_notice(message: str) -> bool:
    return message.startswith("warning: ") and "GL Driver Message (OpenGL, Performance," in message


@pytest.fixture(scope="module")
def threejs_render(tmp_path_factory):
    problems = _setup_problems()
    assert not problems, "; ".join(problems) + " (bash scripts/setup.sh installs them)"
    tmp = tmp_path_factory.mktemp("threejs")
    library = tmp / "pbrlab_library.glsl"
    library.write_text(shaders.expand_file(EXAMPLE / "library_entry.glsl", [], line_directives=False).text,
                       encoding="utf-8")
    engine_tables.write_tables(tmp)
    spec = tmp / "spec.json"
    spec.write_text(json.dumps({"scene": str(EXAMPLE / "scene.json"), "library": str(library),
                                "dfg": str(tmp / "pbrlab_dfg.exr")}), encoding="utf-8")
    node = subprocess.Popen(["node", str(TOOL / "render.mjs"), str(spec), str(tmp / "out")],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        stdout, stderr = node.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        os.killpg(node.pid, signal.SIGKILL)
        node.communicate()
        raise
    assert node.returncode == 0, stderr or stdout
    meta = json.loads((tmp / "out.json").read_text(encoding="utf-8"))
    # A shader that fails to compile says so here. Chromium's own driver notices of the
    # "Performance" kind ("GPU stall due to ReadPixels", printed or not depending on timing)
    # say nothing about the page and are left out.
    problems = [m for m in meta["messages"] if not _is_driver_performance_notice(m)]
    assert not problems, problems
    meta["files"] = {"library": library, "dfg": tmp / "pbrlab_dfg.exr"}
    width, height = meta["size"]
    return np.fromfile(tmp / "out.f32", np.float32).reshape(height, width, 4), meta


def _relative_difference(ours, theirs):
    both = (ours[..., 3] > 0) & (theirs[..., 3] > 0)
    diff = np.abs(ours[..., :3] - theirs[..., :3]).max(axis=-1)
    scale = np.maximum(np.abs(ours[..., :3]).max(axis=-1), RELATIVE_FLOOR)
    return (diff / scale)[both], both


def _within_tolerance(ours, theirs) -> tuple[bool, str]:
    relative, both = _relative_difference(ours, theirs)
    coverage = ((ours[..., 3] > 0) ^ (theirs[..., 3] > 0)).mean()
    over = (relative > MAX_RELATIVE).mean()
    figures = (f"{both.sum()} pixels: {over:.2%} over {MAX_RELATIVE:g} relative (allowed {FRACTION_OVER:.1%}), "
               f"worst {relative.max():.3g} (cap {CAP_RELATIVE:g}); coverage differs on {coverage:.2%}")
    ok = over <= FRACTION_OVER and relative.max() <= CAP_RELATIVE and coverage <= COVERAGE_FRACTION
    return ok, figures


def test_threejs_draws_the_scene_as_pbrlab_renders_it(threejs_render, gl_context):
    pixels, meta = threejs_render
    scene = load_scene(EXAMPLE / "scene.json")
    ours = render_scene(scene, gl_context).linear
    assert pixels.shape == ours.shape
    assert (pixels[..., 3] > 0).mean() > 0.25  # the spheres were drawn
    ok, figures = _within_tolerance(ours, pixels)
    assert ok, f"three.js ({meta['renderer']}, r{meta['three']}) against pbrlab render: {figures}"


def test_the_tolerance_tells_a_rougher_gold_apart(threejs_render, gl_context):
    """The control: pbrlab render of the scene with the gold 0.05 rougher fails the check."""
    pixels, _ = threejs_render
    data = json.loads((EXAMPLE / "scene.json").read_text(encoding="utf-8"))
    rougher = copy.deepcopy(data)
    rougher["materials"]["gold"]["smoothness"] -= 0.05
    ours = render_scene(parse_scene(rougher, base=EXAMPLE), gl_context).linear
    ok, figures = _within_tolerance(ours, pixels)
    assert not ok, figures


def test_only_chromiums_performance_notices_are_left_out():
    notice = ("warning: [.WebGL-0xc7400421a00]GL Driver Message (OpenGL, Performance, GL_CLOSE_PATH_NV, "
              "High): GPU stall due to ReadPixels (this message will no longer repeat)")
    assert _is_driver_performance_notice(notice)
    assert not _is_driver_performance_notice("error: THREE.WebGLProgram: Shader Error 1282 - VALIDATE_STATUS false")
    assert not _is_driver_performance_notice("warning: THREE.WebGLProgram: Program Info Log: 'x' : undeclared identifier")
    assert not _is_driver_performance_notice("pageerror: GL Driver Message (OpenGL, Performance, x)")


def test_the_page_shows_the_spheres(threejs_render, tmp_path):
    """index.html as README.md has a reader open it draws scene.json on its canvas
    (tests/examples/example_page.py: the bound and why)."""
    _, meta = threejs_render
    files = meta["files"]
    status, rgb, messages = view_of_page(TOOL, EXAMPLE / "scene.json", files["library"], files["dfg"], tmp_path)
    assert status == "scene.json, drawn by three.js with the pbrlab library", status
    assert not [m for m in messages if not _is_driver_performance_notice(m)], messages
    assert drawn_fraction(rgb) >= MIN_DRAWN_FRACTION, f"{drawn_fraction(rgb):.1%} of the canvas drawn"


def test_the_page_check_fails_on_an_empty_canvas(threejs_render, tmp_path):
    """The control: the same page drawing a scene without objects says it drew, yet fails."""
    _, meta = threejs_render
    files = meta["files"]
    empty = json.loads((EXAMPLE / "scene.json").read_text(encoding="utf-8"))
    empty["objects"] = []
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps(empty), encoding="utf-8")
    status, rgb, _ = view_of_page(TOOL, scene, files["library"], files["dfg"], tmp_path)
    assert status == "scene.json, drawn by three.js with the pbrlab library", status
    assert drawn_fraction(rgb) < MIN_DRAWN_FRACTION, f"{drawn_fraction(rgb):.1%}"
