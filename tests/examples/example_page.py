"""The example pages as a reader sees them (examples/threejs, examples/babylonjs): the page opened
without ``?test``, the files README.md has the reader write served at their names, and a PNG of
its canvas as shown (``render.mjs`` with ``"show": true``). A page counts as showing the scene
when its status line says it drew and enough of its canvas differs from the page's background.

The bound: the spheres of the examples' scene.json cover 31.5 % of the image (5,808 of 18,432
pixels in the float render); a drawn pixel differs from the page's background (#222, which shows
through the canvas's transparent clear) by more than DRAWN_STEP in some channel. Measured: 31.4 %
of either page's canvas (768 x 385 as shown) drawn, every drawn pixel more than 32 steps from
the background, so the fraction does not hang on the step; 25 % leaves the silhouettes and the
canvas's scaling room. The control (the tests beside each use) is the same page drawing the
scene without objects: its status says it drew, and 0.0 % of its canvas differs."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from browser_example import is_driver_performance_notice, run_render_mjs
from pbrlab.foundation import images

PAGE_BACKGROUND = np.array([0x22, 0x22, 0x22])  # index.html's body background
DRAWN_STEP = 8            # 8-bit steps from the background that count as drawn
MIN_DRAWN_FRACTION = 0.25


def view_of_page(tool: Path, scene: Path, library: Path, dfg: Path, tmp: Path) -> tuple[str, np.ndarray, list[str]]:
    """(status line, canvas RGB as uint8 HxWx3, console messages) of the example's page."""
    meta = run_render_mjs(tool, {"scene": scene, "library": library, "dfg": dfg, "show": True}, tmp / "page")
    pixels = images.read_image(tmp / "page.png")
    assert pixels.dtype == np.uint8, pixels.dtype
    return meta["status"], pixels[..., :3], meta["messages"]


def drawn_fraction(rgb: np.ndarray) -> float:
    return float((np.abs(rgb.astype(np.int16) - PAGE_BACKGROUND).max(axis=-1) > DRAWN_STEP).mean())


def page_of_scene(tool: Path, example: Path, files: dict, tmp: Path, without_objects: bool = False):
    """(status line, drawn fraction, console messages other than driver notices) of the example's
    page drawing its scene.json (or, for the control, that scene without objects)."""
    scene = example / "scene.json"
    if without_objects:
        empty = json.loads(scene.read_text(encoding="utf-8"))
        empty["objects"] = []
        scene = tmp / "scene.json"
        scene.write_text(json.dumps(empty), encoding="utf-8")
    status, rgb, messages = view_of_page(tool, scene, files["library"], files["dfg"], tmp)
    return status, drawn_fraction(rgb), [m for m in messages if not is_driver_performance_notice(m)]
