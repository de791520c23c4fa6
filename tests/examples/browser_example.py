"""What the two browser examples' tests share (examples/threejs, examples/babylonjs): each draws
scene.json in headless Chromium (WebGL2 on SwiftShader) through its tool's render.mjs, reads back
the float radiance and compares it with `pbrlab render` of the same scene.

The bound (derived in tests/examples/test_threejs_example.py's docstring, shared by Babylon.js's,
whose error sources are the same): relative difference max(|a - b|) / max(|a|, RELATIVE_FLOOR) per
pixel at most MAX_RELATIVE for all but FRACTION_OVER of the pixels both draw, CAP_RELATIVE for
every pixel; coverage may differ on COVERAGE_FRACTION of the image (silhouettes)."""

from __future__ import annotations

import copy
import json
import os
import shutil
import signal
import subprocess
from pathlib import Path

import numpy as np

from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

CHROMIUM = Path(os.environ.get("PBRLAB_CHROMIUM", "/usr/bin/chromium"))
TIMEOUT_S = 240
RELATIVE_FLOOR = 1e-2      # radiance below which the difference is taken as absolute
MAX_RELATIVE = 2e-2        # for all but FRACTION_OVER of the pixels
FRACTION_OVER = 5e-3
CAP_RELATIVE = 5e-2        # for every pixel
COVERAGE_FRACTION = 1e-3


def setup_problems(tool: Path, packages: tuple[str, ...]) -> list[str]:
    """What scripts/setup.sh has not installed for the tool: node, Chromium, its npm packages."""
    problems = []
    if shutil.which("node") is None:
        problems.append("node is not on PATH")
    if not CHROMIUM.is_file():
        problems.append(f"{CHROMIUM} is missing")
    for package in packages:
        if not (tool / "node_modules" / package / "package.json").is_file():
            problems.append(f"npm package {package} is not installed in {tool}")
    return problems


def is_driver_performance_notice(message: str) -> bool:
    """Chromium's own driver notices of the "Performance" kind ("GPU stall due to ReadPixels",
    printed or not depending on timing) say nothing about the page."""
    return message.startswith("warning: ") and "GL Driver Message (OpenGL, Performance," in message


def run_render_mjs(tool: Path, spec: dict, out: Path) -> dict:
    """Runs tool/render.mjs on the spec (written beside out), killing its process group past
    TIMEOUT_S; returns the out.json it writes."""
    spec_file = out.with_name(out.name + ".spec.json")
    spec_file.write_text(json.dumps({key: str(value) if isinstance(value, Path) else value
                                     for key, value in spec.items()}), encoding="utf-8")
    node = subprocess.Popen(["node", str(tool / "render.mjs"), str(spec_file), str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        stdout, stderr = node.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        os.killpg(node.pid, signal.SIGKILL)
        node.communicate()
        raise
    assert node.returncode == 0, stderr or stdout
    return json.loads(out.with_name(out.name + ".json").read_text(encoding="utf-8"))


def render_float(tool: Path, scene: Path, library: Path, dfg: Path, tmp: Path) -> tuple[np.ndarray, dict]:
    """(linear RGBA float32, rows bottom to top; the tool's facts) of scene.json drawn by the tool.
    A shader that fails to compile says so in the page's messages, which must hold nothing else
    than driver performance notices."""
    out = tmp / "out"
    meta = run_render_mjs(tool, {"scene": scene, "library": library, "dfg": dfg}, out)
    problems = [m for m in meta["messages"] if not is_driver_performance_notice(m)]
    assert not problems, problems
    meta["files"] = {"library": library, "dfg": dfg}
    width, height = meta["size"]
    return np.fromfile(tmp / "out.f32", np.float32).reshape(height, width, 4), meta


def within_tolerance(ours: np.ndarray, theirs: np.ndarray) -> tuple[bool, str]:
    """Whether the engine's image is within the bound of pbrlab's, and the figures."""
    both = (ours[..., 3] > 0) & (theirs[..., 3] > 0)
    diff = np.abs(ours[..., :3] - theirs[..., :3]).max(axis=-1)
    relative = (diff / np.maximum(np.abs(ours[..., :3]).max(axis=-1), RELATIVE_FLOOR))[both]
    coverage = ((ours[..., 3] > 0) ^ (theirs[..., 3] > 0)).mean()
    over = (relative > MAX_RELATIVE).mean()
    figures = (f"{both.sum()} pixels: {over:.2%} over {MAX_RELATIVE:g} relative (allowed {FRACTION_OVER:.1%}), "
               f"worst {relative.max():.3g} (cap {CAP_RELATIVE:g}); coverage differs on {coverage:.2%}")
    ok = over <= FRACTION_OVER and relative.max() <= CAP_RELATIVE and coverage <= COVERAGE_FRACTION
    return ok, figures


def rougher_gold_within_tolerance(example: Path, pixels: np.ndarray, gl_context) -> tuple[bool, str]:
    """The control: the check run on pbrlab's render of the scene with the gold 0.05 rougher."""
    rougher = copy.deepcopy(json.loads((example / "scene.json").read_text(encoding="utf-8")))
    rougher["materials"]["gold"]["smoothness"] -= 0.05
    return within_tolerance(render_scene(parse_scene(rougher, base=example), gl_context).linear, pixels)
