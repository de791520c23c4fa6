"""`pbrlab demo`'s contact sheets, checked geometrically: every piece of text lies inside the
sheet (nothing clipped at an edge, even a long failure verdict) and no cell label covers a
sphere's disc. The sheets are built from blank images of each demo image's size: the layout
depends on the size and the labels, not on the pixels."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

from pbrlab.checking import contact_sheets
from pbrlab.checking.charts import CHARTS
from pbrlab.checking.golden_scenes import LIT_SCENE
from pbrlab.scene import load_scene, parse_scene

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.text import Text  # noqa: E402

LONG_FAILURE = ("DIFFERS from goldens/chart_f0: max abs 0.01 linear at (y=10, x=10); 1 of 184320 pixels "
                "over tolerance max_abs 1e-05 linear; 3 of 184320 pixels over tolerance max_abs 1e-05 "
                "(sRGB codes: max 3 at (y=10, x=10)); tolerance profile llvmpipe on llvmpipe (LLVM 15.0.6, 128 bits)")
STATUSES = {"matches": "matches goldens/x (max abs 0)", "long failure": LONG_FAILURE,
            "no golden": "rendered, no golden to compare"}
DISC_MARGIN = 1.05  # a disc's drawn radius may exceed PIXELS_PER_SPHERE / SPACING by perspective (< 1 %)


def _size(name):
    scene = load_scene(LIT_SCENE) if name == "lit_scene_high" else parse_scene(CHARTS[name]())
    width, height = scene.camera.size
    return height, width


def _texts(figure):
    return [t for t in figure.findobj(Text) if t.get_visible() and t.get_text().strip()]


@pytest.mark.parametrize("status", STATUSES)
@pytest.mark.parametrize("name", [*CHARTS, "lit_scene_high"])
def test_sheet_text_stays_inside_and_off_the_spheres(name, status):
    sheet = contact_sheets.build_sheet(name, np.zeros((*_size(name), 3), np.uint8), STATUSES[status])
    try:
        figure = sheet.figure
        figure.canvas.draw()
        renderer = figure.canvas.get_renderer()
        width, height = figure.canvas.get_width_height()
        boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in _texts(figure)]
        assert any(STATUSES[status].split()[0] in text for text, _ in boxes)
        for text, box in boxes:
            assert box.x0 >= 0 and box.y0 >= 0 and box.x1 <= width and box.y1 <= height, \
                f"{text!r} at {box} leaves the {width}x{height} sheet"
        to_display = sheet.axes.transData
        for cx, cy, r in sheet.discs:
            (x, y), (x_edge, _) = to_display.transform([(cx, cy), (cx + r * DISC_MARGIN, cy)])
            radius = x_edge - x
            for text, box in boxes:
                nearest_x = min(max(x, box.x0), box.x1)
                nearest_y = min(max(y, box.y0), box.y1)
                assert (nearest_x - x) ** 2 + (nearest_y - y) ** 2 > radius ** 2, \
                    f"{text!r} covers the sphere at ({cx:g}, {cy:g})"
    finally:
        plt.close(sheet.figure)


def test_labelled_charts_have_their_discs_checked():
    """The check above sees every sphere of every chart (it would pass vacuously without them)."""
    for name, build in CHARTS.items():
        sheet = contact_sheets.build_sheet(name, np.zeros((*_size(name), 3), np.uint8), "matches")
        plt.close(sheet.figure)
        assert len(sheet.discs) == len(build()["objects"]), name


def test_the_old_layout_would_fail():
    """A label drawn on the sphere's lower edge, as the sheets did before (3 px above the
    cell's bottom), is caught: the check can fail."""
    sheet = contact_sheets.build_sheet("chart_f0", np.zeros((*_size("chart_f0"), 3), np.uint8), "matches")
    try:
        cx, cy, r = sheet.discs[0]
        sheet.axes.text(cx, cy + contact_sheets.PIXELS_PER_SPHERE / 2 - 3, "quartz", ha="center", va="bottom",
                        fontsize=7)
        figure = sheet.figure
        figure.canvas.draw()
        box = [t for t in _texts(figure) if t.get_text() == "quartz"][-1].get_window_extent(figure.canvas.get_renderer())
        (x, y), (x_edge, _) = sheet.axes.transData.transform([(cx, cy), (cx + r, cy)])
        nearest_x, nearest_y = min(max(x, box.x0), box.x1), min(max(y, box.y0), box.y1)
        assert (nearest_x - x) ** 2 + (nearest_y - y) ** 2 <= (x_edge - x) ** 2
    finally:
        plt.close(sheet.figure)
