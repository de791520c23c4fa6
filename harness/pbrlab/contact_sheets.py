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

from . import charts, outputs

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


def write_sheet(path: Path, name: str, srgb8: np.ndarray, status: str) -> None:
    """The labelled contact sheet of one demo image (PNG, matplotlib)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    info = layout(name)
    rgb = np.asarray(srgb8)[..., :3]
    height, width = rgb.shape[:2]
    scale = 1.0 / 80.0  # inches per image pixel: a 96 px cell is 1.2 in
    fig_w, fig_h = max(width * scale + 1.6, 5.0), height * scale + 1.4
    fig, ax = plt.subplots(figsize=(fig_w, fig_h), dpi=100)
    ax.imshow(rgb, interpolation="nearest")
    ax.set_xticks([]), ax.set_yticks([])
    if info.columns:
        ax.xaxis.set_ticks_position("top")
        ax.set_xticks([(j + 0.5) * PIXELS_PER_SPHERE for j in range(len(info.columns))], info.columns, fontsize=9)
        ax.xaxis.set_label_position("top")
        ax.set_xlabel(info.column_axis, fontsize=10)
    if info.rows:
        ax.set_yticks([(i + 0.5) * PIXELS_PER_SPHERE for i in range(len(info.rows))], info.rows, fontsize=9)
        ax.set_ylabel(info.row_axis, fontsize=10)
    for i, row in enumerate(info.cells):
        for j, label in enumerate(row):
            # a 96 px cell holds about 16 characters at 7 pt: longer names wrap at underscores
            text = textwrap.fill(label.replace("_", " "), width=16)
            ax.text((j + 0.5) * PIXELS_PER_SPHERE, (i + 1) * PIXELS_PER_SPHERE - 3, text,
                    ha="center", va="bottom", fontsize=7, color="white",
                    bbox={"boxstyle": "round,pad=0.15", "facecolor": "black", "alpha": 0.6, "linewidth": 0})
    ax.tick_params(length=0)
    for spine in ax.spines.values():
        spine.set_visible(False)
    caption = textwrap.fill(info.caption, width=int(fig_w * 14))  # ~14 characters per inch at 8 pt
    footer_in = 0.2 + 0.16 * (caption.count("\n") + 2)  # inches: caption lines + the status line
    fig.set_size_inches(fig_w, fig_h + footer_in)
    fig.text(0.5, 0.01, status, ha="center", va="bottom", fontsize=8,
             color="darkgreen" if status.startswith("matches") else "darkred")
    fig.text(0.5, 0.01 + 0.2 / (fig_h + footer_in + 0.4), caption, ha="center", va="bottom", fontsize=8)
    title_in = 0.4  # inches above the axes for the title
    fig.set_size_inches(fig_w, fig_h + footer_in + title_in)
    total = fig_h + footer_in + title_in
    fig.suptitle(info.title, fontsize=12, fontweight="bold", y=1 - 0.08 / total, va="top")
    fig.tight_layout(rect=(0, footer_in / total, 1, 1 - title_in / total))
    try:
        outputs.write_figure(path, fig)  # all or nothing: a full disk keeps the old sheet
    finally:
        plt.close(fig)


def write_index(path: Path, entries: list[dict]) -> None:
    """out/index.html: every sheet with its caption, golden status and the raw files."""
    blocks = []
    for e in entries:
        info = layout(e["name"])
        ok = e["status"].startswith("matches")
        blocks.append(
            f'<section><h2>{html.escape(info.title)}</h2>'
            f'<p>{html.escape(info.caption)}</p>'
            f'<p class="{"ok" if ok else "bad"}">golden: {html.escape(e["status"])}</p>'
            f'<a href="{html.escape(e["sheet"])}"><img src="{html.escape(e["sheet"])}" alt="{html.escape(info.title)}"></a>'
            f'<p class="files">raw: <a href="{html.escape(e["png"])}">{html.escape(e["png"])}</a> (sRGB) · '
            f'<a href="{html.escape(e["exr"])}">{html.escape(e["exr"])}</a> (linear radiance)</p></section>')
    page = ("<!doctype html><meta charset=\"utf-8\"><title>pbrlab demo</title>"
            "<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
            "img{max-width:100%;border:1px solid #ccc}.ok{color:#176f2c}.bad{color:#a11;font-weight:bold}"
            ".files{font-size:90%;color:#555}section{margin-bottom:2.5em}</style>"
            "<h1>pbrlab demo</h1>" + "\n".join(blocks))
    outputs.write_file(path, page)
