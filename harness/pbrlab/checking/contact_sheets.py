"""Pictures for people: `pbrlab demo`'s labelled contact sheets and its out/index.html.

A raw render (NAME.png) is pixels only; its contact sheet (NAME_sheet.png, matplotlib) adds
the chart's title, what the rows and columns vary with their values, each sphere's material
or term where cells differ by name, and the golden verdict. index.html shows every sheet with
its caption, its golden status and links to the raw PNG and EXR.
"""

from __future__ import annotations

import html
import textwrap
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import charts
from ..foundation import outputs

PIXELS_PER_SPHERE = 96  # charts._grid_scene's default: one cell per sphere
TERM_TITLES = {"specular_d": "D: normal distribution", "specular_v": "V: visibility",
               "specular_f": "F: Fresnel", "diffuse": "Fd: diffuse"}


@dataclass
class Layout:
    """What a picture shows: a title, a caption, and (charts) row/column titles and values."""

    title: str
    caption: str
    row_axis: str = ""
    rows: tuple = ()
    column_axis: str = ""
    columns: tuple = ()
    cells: tuple = ()  # per row, a label per cell (cells that differ by name, not by a value)


def _smoothness_columns() -> tuple:
    return tuple(f"{s:g}" for s in charts.SMOOTHNESS_STEPS)


def _cell_names(scene: dict) -> list[list[str]]:
    """Material names per row, top to bottom (objects are laid out row by row, y descending)."""
    rows: dict[float, list[tuple[float, str]]] = {}
    for obj in scene["objects"]:
        x, y, _ = obj["sphere"]["center"]
        rows.setdefault(round(-y, 6), []).append((x, obj["material"]))
    return [[name for _, name in sorted(cells)] for _, cells in sorted(rows.items())]


def layout(name: str) -> Layout:
    """The labels of a demo image (a chart of charts.CHARTS, or the lit scene)."""
    if name == "chart_metallic":
        return Layout("Metallic workflow", "Albedo (0.9, 0.45, 0.2) at every metallic value and "
                      "smoothness; two directional lights, no tonemapping.",
                      "metallic", ("1", "0.75", "0.5", "0.25", "0"), "smoothness", _smoothness_columns())
    if name == "chart_metallic_environment":
        return Layout("Metallic workflow, under a grey sky", "chart_metallic with a constant environment "
                      f"of radiance {charts.GREY_SKY[0]:g} added: the smooth metals, black without an "
                      "environment (nothing to reflect), reflect the sky tinted by their F0.",
                      "metallic", ("1", "0.75", "0.5", "0.25", "0"), "smoothness", _smoothness_columns())
    if name == "chart_specular":
        return Layout("Specular workflow", "Specular colour (F0) per row at every smoothness; "
                      "grey albedo 0.5 for the dielectric rows, none for the metals.",
                      "specular F0", ("0.02", "0.04", "0.17", "gold", "copper"), "smoothness",
                      _smoothness_columns())
    if name == "chart_f0":
        names = _cell_names(charts.f0_chart())
        return Layout("F0 tables (Lagarde 2011)", "One sphere per material of the lecture's F0 "
                      "tables at smoothness 0.8: dielectrics (grey F0, albedo 0.35) in the top "
                      "rows, metals (coloured F0) below.", cells=tuple(tuple(r) for r in names))
    if name == "chart_terms":
        names = _cell_names(charts.terms_chart())
        terms = [next(term for term in TERM_TITLES if cells[0].startswith(term + "_")) for cells in names]
        rows = tuple(TERM_TITLES[term] for term in terms)
        variants = tuple(tuple(cell[len(term) + 1:] for cell in cells) for term, cells in zip(terms, names))
        return Layout("BRDF term variants", "Each row swaps one term of the standard model "
                      "(the others at their defaults): D, V and F on gold at smoothness 0.55 "
                      "(specular only), diffuse on a rough orange dielectric.",
                      "term", rows, cells=variants)
    if name.startswith("lit_scene_"):
        tier = name.removeprefix("lit_scene_").upper()
        return Layout(f"Lit example, {tier} tier", "The Unity-style surface API: a textured brick "
                      "surface function under a directional, a point and a spot light with an HDR "
                      f"environment (scenes/unity_example), {tier} quality tier.")
    return Layout(name, name)


# Sheet geometry, in inches (the image is drawn at 80 pixels per inch: a 96 px cell is 1.2 in).
INCHES_PER_PIXEL = 1.0 / 80.0
TITLE_IN = 0.45          # the title band above everything
COLUMN_LABELS_IN = 0.5   # column values and their axis name, above the image
ROW_AXIS_IN = 0.3        # the row axis' name, left of the row values
MARGIN_IN = 0.25         # around everything else
CHAR_IN = {7: 0.062, 8: 0.07, 9: 0.078}  # an average character's width at a font size (DejaVu Sans)
LINE_IN = {7: 0.125, 8: 0.14, 9: 0.155}  # a line's height at a font size
CELL_LABEL_CHARS = 16    # a cell label's wrap width: 16 characters at 7 pt fill 1.0 of a 1.2 in cell
MIN_WIDTH_IN = 5.0


@dataclass
class Sheet:
    """A built contact sheet: the matplotlib figure, its image axes, and the sphere discs
    (x, y, radius in the axes' data units: sheet pixels) that no label may cover."""

    figure: object
    axes: object
    discs: list


def _label_band_px(cells) -> int:
    """The height of the black band under each row of spheres that holds their labels."""
    lines = max((textwrap.fill(label.replace("_", " "), CELL_LABEL_CHARS).count("\n") + 1
                 for row in cells for label in row), default=0)
    return 0 if not lines else int(round((lines * LINE_IN[7] + 0.08) / INCHES_PER_PIXEL))


def build_sheet(name: str, srgb8: np.ndarray, status: str) -> Sheet:
    """The labelled contact sheet of one demo image. Cell labels sit in a band under their
    row of spheres (the image is split by rows), never on a sphere; the caption and the
    status wrap to the sheet's width."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    info = layout(name)
    rgb = np.asarray(srgb8)[..., :3]
    height, width = rgb.shape[:2]
    band = _label_band_px(info.cells)
    n_rows = height // PIXELS_PER_SPHERE if (info.cells or info.rows) else 1
    row_px = PIXELS_PER_SPHERE if (info.cells or info.rows) else height
    shown_h = n_rows * (row_px + band)
    image_w_in, image_h_in = width * INCHES_PER_PIXEL, shown_h * INCHES_PER_PIXEL
    left_in = MARGIN_IN + (ROW_AXIS_IN + CHAR_IN[9] * max(map(len, info.rows)) if info.rows else 0.0)
    fig_w = max(left_in + image_w_in + MARGIN_IN, MIN_WIDTH_IN)
    left_in = max(left_in, (fig_w - image_w_in) / 2)  # centred when the minimum width leaves room
    chars = int((fig_w - 2 * MARGIN_IN) / CHAR_IN[8])
    caption = textwrap.fill(info.caption, width=chars)
    status_text = textwrap.fill(status, width=chars)
    footer_in = MARGIN_IN + LINE_IN[8] * (caption.count("\n") + status_text.count("\n") + 2) + 0.1
    top_in = TITLE_IN + (COLUMN_LABELS_IN if info.columns else 0.1)
    fig_h = top_in + image_h_in + footer_in
    fig = plt.figure(figsize=(fig_w, fig_h), dpi=100)
    ax = fig.add_axes((left_in / fig_w, footer_in / fig_h, image_w_in / fig_w, image_h_in / fig_h))
    ax.set_facecolor("black")
    for i in range(n_rows):  # each row of spheres, then its label band
        top = i * (row_px + band)
        ax.imshow(rgb[i * row_px:(i + 1) * row_px], extent=(0, width, top + row_px, top), interpolation="nearest")
    ax.set_xlim(0, width)
    ax.set_ylim(shown_h, 0)
    ax.set_xticks([]), ax.set_yticks([])
    if info.columns:
        ax.xaxis.set_ticks_position("top")
        ax.set_xticks([(j + 0.5) * PIXELS_PER_SPHERE for j in range(len(info.columns))], info.columns, fontsize=9)
        ax.xaxis.set_label_position("top")
        ax.set_xlabel(info.column_axis, fontsize=10)
    if info.rows:
        ax.set_yticks([i * (row_px + band) + row_px / 2 for i in range(len(info.rows))], info.rows, fontsize=9)
        ax.set_ylabel(info.row_axis, fontsize=10)
    discs = []
    radius_px = PIXELS_PER_SPHERE / charts.SPACING  # a unit sphere per SPACING-wide cell
    for i, row in enumerate(info.cells):
        for j, label in enumerate(row):
            top = i * (row_px + band)
            discs.append(((j + 0.5) * PIXELS_PER_SPHERE, top + row_px / 2, radius_px))
            ax.text((j + 0.5) * PIXELS_PER_SPHERE, top + row_px + band / 2,
                    textwrap.fill(label.replace("_", " "), width=CELL_LABEL_CHARS),
                    ha="center", va="center", fontsize=7, color="white")
    if info.rows and not info.cells:
        discs = [((j + 0.5) * PIXELS_PER_SPHERE, i * row_px + row_px / 2, radius_px)
                 for i in range(n_rows) for j in range(width // PIXELS_PER_SPHERE)]
    ax.tick_params(length=0)
    for spine in ax.spines.values():
        spine.set_visible(False)
    fig.text(0.5, MARGIN_IN / fig_h, status_text, ha="center", va="bottom", fontsize=8,
             color="darkgreen" if status.startswith("matches") else "black" if status.startswith("rendered")
             else "darkred")
    fig.text(0.5, (MARGIN_IN + LINE_IN[8] * (status_text.count("\n") + 1) + 0.05) / fig_h, caption,
             ha="center", va="bottom", fontsize=8)
    fig.suptitle(info.title, fontsize=12, fontweight="bold", y=1 - 0.1 / fig_h, va="top")
    return Sheet(fig, ax, discs)


def write_sheet(path: Path, name: str, srgb8: np.ndarray, status: str) -> None:
    """The labelled contact sheet of one demo image (PNG, matplotlib): build_sheet's figure."""
    import matplotlib.pyplot as plt

    sheet = build_sheet(name, srgb8, status)
    try:
        outputs.write_figure(path, sheet.figure)  # all or nothing: a full disk keeps the old sheet
    finally:
        plt.close(sheet.figure)


def write_index(path: Path, entries: list[dict]) -> None:
    """out/index.html: every sheet with its caption, golden status and the raw files."""
    blocks = []
    for e in entries:
        info = layout(e["name"])
        verdict = "ok" if e["status"].startswith("matches") else \
            "none" if e["status"].startswith("rendered") else "bad"
        blocks.append(
            f'<section><h2>{html.escape(info.title)}</h2>'
            f'<p>{html.escape(info.caption)}</p>'
            f'<p class="{verdict}">golden: {html.escape(e["status"])}</p>'
            f'<a href="{html.escape(e["sheet"])}"><img src="{html.escape(e["sheet"])}" alt="{html.escape(info.title)}"></a>'
            f'<p class="files">raw: <a href="{html.escape(e["png"])}">{html.escape(e["png"])}</a> (sRGB) · '
            f'<a href="{html.escape(e["exr"])}">{html.escape(e["exr"])}</a> (linear radiance)</p></section>')
    page = ("<!doctype html><meta charset=\"utf-8\"><title>pbrlab demo</title>"
            "<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
            "img{max-width:100%;border:1px solid #ccc}.ok{color:#176f2c}.none{color:#555}.bad{color:#a11;font-weight:bold}"
            ".files{font-size:90%;color:#555}section{margin-bottom:2.5em}</style>"
            "<h1>pbrlab demo</h1>" + "\n".join(blocks))
    outputs.write_file(path, page)
