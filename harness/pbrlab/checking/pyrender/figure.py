"""The labelled figure of the pyrender cross-check (docs/pyrender_vs_pbrlab.png).

Four panels top to bottom, each titled: pyrender's output; pbrlab composing pyrender's
terms (gamma 2.2); pbrlab's defaults (high tier, sRGB); the relative linear difference
pyrender vs pbrlab default, with a colour bar (its scale is pyrender_check's black -> red ->
yellow -> white ramp, 0 .. HEATMAP_FULL_SCALE; grey: not compared). Rows are labelled with
the base colours, columns with (metallic, roughness).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ...foundation import outputs
from . import check as pc

PANEL_TITLES = ("pyrender 0.1.45 (its own output, gamma 2.2)",
                "pbrlab composing pyrender's terms (encoded with gamma 2.2)",
                "pbrlab defaults (HIGH tier, exact sRGB)",
                "relative linear difference, pyrender vs pbrlab defaults")


def write(path: Path, results: dict) -> None:
    """Draw the figure of one crosscheck() result (matplotlib, PNG)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LinearSegmentedColormap, Normalize

    stacked = pc.figure(results["pyrender"], results["matched"], results["default"].linear,
                        results["default"].srgb8)[..., :3]
    h = results["pyrender"].rgb8.shape[0]
    w = stacked.shape[1]
    panels = [stacked[i * (h + 2):i * (h + 2) + h] for i in range(4)]
    columns = [f"m {m:g}\nr {r:g}" for m in pc.METALLIC for r in pc.ROUGHNESS]
    rows = list(pc.BASE_COLOURS)
    fig, axes = plt.subplots(4, 1, figsize=(w / 60 + 2.2, 4 * (h / 60 + 0.75)), dpi=100)
    for k, (ax, panel, title) in enumerate(zip(axes, panels, PANEL_TITLES)):
        ax.imshow(panel, interpolation="nearest")
        ax.set_title(title, fontsize=9)
        ax.set_yticks([(i + 0.5) * h / len(rows) for i in range(len(rows))], rows, fontsize=8)
        ax.set_xticks([(j + 0.5) * w / len(columns) for j in range(len(columns))],
                      columns if k == 0 else [""] * len(columns), fontsize=7)
        if k == 0:
            ax.xaxis.set_ticks_position("top")
        ax.tick_params(length=0)
    ramp = np.linspace(0.0, 1.0, 256)
    colours = np.stack([np.clip(3 * ramp, 0, 1), np.clip(3 * ramp - 1, 0, 1), np.clip(3 * ramp - 2, 0, 1)], axis=1)
    cmap = LinearSegmentedColormap.from_list("pbrlab_heat", colours)
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=Normalize(0.0, 100.0 * pc.HEATMAP_FULL_SCALE), cmap=cmap),
                       ax=axes[3], orientation="vertical", fraction=0.04, pad=0.02)
    bar.set_label(f"|Δ| / pyrender, % (white ≥ {100 * pc.HEATMAP_FULL_SCALE:g} %; grey: not compared)", fontsize=7)
    bar.ax.tick_params(labelsize=7)
    fig.suptitle("Cross-check against pyrender: columns metallic (m) × roughness (r), rows base colour",
                 fontsize=10)
    fig.tight_layout()
    try:
        outputs.write_figure(path, fig)  # all or nothing: a full disk keeps the old figure
    finally:
        plt.close(fig)
