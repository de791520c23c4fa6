"""Where a fidelity row's score comes from: the per-pixel squared YIQ delta of pbrlab against
Cycles (pbrlab.checking.fidelity.metric: the score is 10 log10 of the RMS of the delta over the
pixels pbrlab covers, over 35,215, so each pixel's share of the score is its delta squared over
their sum), split by where the pixel lies:

* edge: within 2 px of a silhouette of either image (alpha crossing 0.5; a pixel that one image
  covers and the other not is an edge pixel too);
* emissive (with --emissive): not edge, and pbrlab's display changes by at least EMISSIVE_CODES
  codes in a channel when the row is rendered again with every material's emission (factor and map) removed;
* highlight: not edge or emissive, and either image shows a near-white pixel (any channel's code >= 240:
  glints of the sun, the emissive parts at their brightest);
* brighter / darker: the rest, by the sign of pbrlab's luminance minus Cycles' (luminance as the
  delta weighs it, YIQ's Y).

For each, its share of the squared error, its share of the pixels, and what the score would be
with those pixels matched (the delta set to 0 there): how many dB that kind of pixel costs.
Also the share of the squared error the worst 1 % of the pixels hold. With --png, a heat map of
delta squared (white 0, black the row's largest) beside the two images.
A measurement: it prints figures and asserts nothing.

    python benchmarks/fidelity_error_map.py OUT_DIR KEY [KEY ...] [--png DIR] [--emissive]

OUT_DIR: a `pbrlab fidelity --out` folder (its KEY/pbrlab.png); Cycles' image is the committed
reference (benchmarks/fidelity/references/KEY/cycles.png).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
from scipy import ndimage

from pbrlab.checking.fidelity import benchmark, metric
from pbrlab.foundation import images

EDGE_PX = 2           # the band either side of a silhouette (docs/fidelity.md's edge band)
HIGHLIGHT_CODE = 240  # a display code this high in any channel: near white after the protocol's tone map
EMISSIVE_CODES = 8    # the emission visibly lit the pixel: at least this many codes of 255 in a channel


def without_emission(key: str) -> np.ndarray:
    """pbrlab's display image of the row ``key`` with every material's emission removed (the
    benchmark's view and render block)."""
    from pbrlab.checking.fidelity import display, renderers, staging
    from pbrlab.importers.loader import parse_scene
    from pbrlab.render.renderer import render_scene
    import dataclasses
    import tempfile

    scenario = next(s for s in staging.read_scenarios() if s.key == key)
    with tempfile.TemporaryDirectory() as folder:
        environment = staging.prepare_environment(scenario.lighting, Path(folder))
        view = staging.view_spec(scenario, benchmark.COMMITTED_SCALE, environment, staging.model_bounds(scenario.model))
        camera = view["camera"]
        scene = parse_scene({"camera": {"position": camera["eye"], "target": camera["target"], "up": camera["up"],
                                        "fov_y_deg": camera["yfov_deg"], "size": list(view["size"])},
                             "environment": {"path": view["environment"]}, "objects": [{"gltf": view["gltf"]}],
                             "render": dict(benchmark.PBRLAB_RENDER)}, origin=key, base=Path(view["gltf"]).parent)
        for name, material in scene.materials.items():
            textures = {k: v for k, v in material.textures.items() if k != "emission"}
            scene.materials[name] = dataclasses.replace(material, emission=np.zeros(3), textures=textures)
        linear = np.ascontiguousarray(render_scene(scene).linear, np.float32)
    return display.display_rgba8(renderers.straight(linear))


def categories(pbrlab: np.ndarray, cycles: np.ndarray, dark: np.ndarray | None = None) -> dict:
    """Boolean masks (HxW) of the module doc's kinds of pixel, over the pixels pbrlab covers
    (``dark``: pbrlab without emission, for the emissive kind)."""
    covered = pbrlab[..., 3] != 0
    edges = np.zeros(covered.shape, bool)
    for image in (pbrlab, cycles):
        inside = image[..., 3] >= 128
        edges |= inside ^ ndimage.binary_erosion(inside, iterations=1, border_value=0)
    edges |= (pbrlab[..., 3] >= 128) ^ (cycles[..., 3] >= 128)
    edge = ndimage.binary_dilation(edges, iterations=EDGE_PX) & covered
    emissive = np.zeros(covered.shape, bool)
    if dark is not None:
        lit = np.abs(pbrlab[..., :3].astype(int) - dark[..., :3].astype(int)) >= EMISSIVE_CODES
        emissive = lit.any(axis=-1) & covered & ~edge
    bright = ((pbrlab[..., :3] >= HIGHLIGHT_CODE) | (cycles[..., :3] >= HIGHLIGHT_CODE)).any(axis=-1)
    highlight = bright & covered & ~edge & ~emissive
    rest = covered & ~edge & ~emissive & ~highlight
    dy = metric.over_white(pbrlab) @ metric._Y - metric.over_white(cycles) @ metric._Y
    kinds = {"edge": edge, "emissive": emissive, "highlight": highlight, "brighter": rest & (dy > 0),
             "darker": rest & (dy <= 0)}
    return kinds if dark is not None else {k: v for k, v in kinds.items() if k != "emissive"}


def analyse(pbrlab: np.ndarray, cycles: np.ndarray, dark: np.ndarray | None = None) -> tuple[float, dict, np.ndarray]:
    """(score dB, {kind: (share of squared error, share of pixels, dB with those matched)}, delta^2)."""
    covered = pbrlab[..., 3] != 0
    delta = metric.color_delta(pbrlab, cycles)
    squared = np.where(covered, delta * delta, 0.0)
    total = squared.sum()
    count = covered.sum()

    def db(sum_squared):
        return metric.decibels(math.sqrt(sum_squared / count) / metric.MAX_COLOR_DISTANCE)

    kinds = {}
    for name, mask in categories(pbrlab, cycles, dark).items():
        part = squared[mask].sum()
        kinds[name] = (part / total, mask.sum() / count, db(total - part))
    return db(total), kinds, squared


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("keys", nargs="+")
    parser.add_argument("--png", type=Path, default=None)
    parser.add_argument("--emissive", action="store_true", help="render each row again without emission")
    args = parser.parse_args()
    for key in args.keys:
        pbrlab = images.read_image(args.out / key / "pbrlab.png")
        cycles = images.read_image(benchmark.reference_path(key, "cycles"))
        dark = without_emission(key) if args.emissive else None
        score, kinds, squared = analyse(pbrlab, cycles, dark)
        ordered = np.sort(squared[pbrlab[..., 3] != 0])[::-1]
        top = int(np.ceil(0.01 * len(ordered)))
        parts = ", ".join(f"{name} {share:.0%} of the error on {pixels:.0%} of the pixels ({matched:+.1f} dB matched)"
                          for name, (share, pixels, matched) in kinds.items())
        print(f"{key}: {score:.2f} dB; the worst 1% of the pixels hold {ordered[:top].sum() / ordered.sum():.0%} "
              f"of the error; {parts}")
        if args.png is not None:
            args.png.mkdir(parents=True, exist_ok=True)
            heat = np.rint(255.0 * (1.0 - np.sqrt(squared / max(squared.max(), 1e-30)))).astype(np.uint8)
            tiles = [np.rint(metric.over_white(cycles)).astype(np.uint8),
                     np.rint(metric.over_white(pbrlab)).astype(np.uint8), np.repeat(heat[..., None], 3, axis=-1)]
            images.write_png(args.png / f"{key}.png", np.concatenate(tiles, axis=1))


if __name__ == "__main__":
    main()
