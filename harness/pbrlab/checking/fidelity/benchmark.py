"""The fidelity benchmark: every (scene, lighting) of benchmarks/fidelity/scenarios.json
rendered by pbrlab (always, here and now) and scored with the protocol's metric against the
Cycles reference, beside the committed images of the peers (three.js, the Sample Viewer) and
of a second Cycles render with another seed (the reference's own noise).

Committed (benchmarks/fidelity/references/<scene@lighting>/): each renderer's display image
(display.display_rgba8 of its linear output) as <renderer>.png, made by this module with
``render=(...)`` on a machine that has the renderer, and facts.json (what made them: sizes,
versions, samples, seconds). pbrlab's image is never committed: CI re-renders it.

What a run reports per row: the score (dB) of every renderer against Cycles, the noise floor
(Cycles seed 1 against seed 0), which renderer is closest; and over the rows the medians, the
count of rows where pbrlab is the closest, where it is worse than the worst peer, and where it
reaches the protocol's pass line (-22 dB).

The bound each row is held to (``bound_db``): not worse than the worst peer, up to the
reference's own noise: pbrlab's ratio^2 <= worst peer's ratio^2 + noise ratio^2 (the ratios
are RMS values over the covered pixels, so independent errors add in squares; the reference's
noise is measured as seed 1 against seed 0, which counts its noise twice and is on the safe
side). It comes from the peers and the reference, never from pbrlab's own output.
"""

from __future__ import annotations

import json
import math
import statistics
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ...foundation import images
from ...foundation.errors import PbrlabError
from . import display, metric, renderers, staging

REFERENCES_DIR = staging.BENCHMARK_DIR / "references"
NOISE = "cycles_seed1"   # the second Cycles render: the reference's own noise
COMMITTED_SCALE = 0.25   # the committed references' size: a quarter of the protocol's (768 -> 192)
SAMPLES = 256            # Cycles samples per pixel of the committed references
DENOISE = True
# pbrlab's render block in the benchmark (docs/scenes.md, "Anti-aliasing"; docs/fidelity.md
# measures each step): 4x multisampling, drawn at 2x and resolved with Cycles' own pixel filter
# (Blackman-Harris over 1.5 px), so the reference's filter is no difference to score; the
# environment's sun, where it has one (sunrise), split off as a light that casts shadows
# (render.environment_sun: every sunrise row closer, docs/fidelity.md); the environment's specular
# light scaled by the sky the model itself leaves visible, from 16 shadow maps
# (render.environment_visibility: median -18.4 -> -18.7 dB; 32 or 64 maps move the median by
# 0.03 dB, no row by 0.4); the environment's specular read about a normal bent until the view's
# reflection stays above the geometric surface (render.valid_reflection_normal, as Cycles: the
# median unchanged at -18.66 dB, four rows 0.2-0.4 dB further, the held-out set's
# NormalTangentMirrorTest -13.9 -> -17.7 and -14.9 -> -21.2 dB); screen-space reflections, the model
# reflected in itself where a smooth lobe's ray meets the frame's own surfaces
# (render.screen_space_reflections: median -18.65 -> -19.68 dB, pbrlab the closest on 23 of 23 rows,
# 6 at the pass line; docs/fidelity.md)
PBRLAB_RENDER = {"antialias": 4, "antialias_filter": "blackman_harris", "supersample": 2, "environment_sun": True,
                 "environment_visibility": 16, "valid_reflection_normal": True, "screen_space_reflections": True}


@dataclass
class Row:
    key: str
    size: tuple[int, int]
    scores: dict = field(default_factory=dict)    # renderer -> dB against Cycles
    noise_db: float | None = None
    seconds: dict = field(default_factory=dict)   # renderer -> wall seconds of this run's renders

    def bound_db(self) -> float | None:
        """pbrlab's bound: the worst peer's ratio, widened by the reference's noise (module doc)."""
        peers = [self.scores[p] for p in renderers.PEERS if p in self.scores]
        if not peers or self.noise_db is None:
            return None
        ratio = math.sqrt(max(10 ** (p / 10) for p in peers) ** 2 + (10 ** (self.noise_db / 10)) ** 2)
        return metric.decibels(ratio)

    def closest(self) -> str | None:
        candidates = {r: s for r, s in self.scores.items() if r in ("pbrlab",) + renderers.PEERS}
        return min(candidates, key=candidates.get) if candidates else None


def references_for(scenarios_file: Path) -> Path:
    """The references folder of a scenarios file: beside it, named for it (scenarios.json ->
    references, heldout_scenarios.json -> heldout_references, other.json -> other_references)."""
    scenarios_file = Path(scenarios_file)
    stem = scenarios_file.stem
    if stem.endswith("scenarios"):
        name = stem[: -len("scenarios")] + "references"
    else:
        name = stem + "_references"
    return scenarios_file.parent / name


def reference_path(key: str, renderer: str, folder: Path = REFERENCES_DIR) -> Path:
    return Path(folder) / key / f"{renderer}.png"


def _render_display(name: str, renderer: str, view: dict, render_block: dict, out: Path | None):
    """``renderer``'s display image of ``view``; its linear EXR and PNG kept in ``out`` as <name>.*"""
    t0 = time.perf_counter()
    linear, facts = renderers.render(renderer, view, render_block)
    seconds = time.perf_counter() - t0
    shown = display.display_rgba8(linear)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        images.write_exr(out / f"{name}.exr", np.ascontiguousarray(linear, np.float32))
        images.write_png(out / f"{name}.png", shown)
    return shown, facts, seconds


def run(scenarios=None, *, keys=None, scale: float = COMMITTED_SCALE, render=("pbrlab",),
        update_references: bool = False, out: Path | None = None, render_block: dict | None = PBRLAB_RENDER,
        samples: int = SAMPLES, references: Path = REFERENCES_DIR, log=print) -> list[Row]:
    """Score every row. ``render``: the renderers to run now (others are read from
    ``references``); ``update_references``: write what was rendered (all but pbrlab) there."""
    scenarios = staging.read_scenarios() if scenarios is None else scenarios
    if keys:
        unknown = set(keys) - {s.key for s in scenarios}
        if unknown:
            raise PbrlabError(f"unknown scenes {sorted(unknown)} (known: {', '.join(s.key for s in scenarios)})")
        scenarios = [s for s in scenarios if s.key in keys]
    for name in render:
        if name not in renderers.RENDERERS + (NOISE,):
            raise PbrlabError(f"unknown renderer {name!r}: expected {', '.join(renderers.RENDERERS + (NOISE,))}")
        problems = renderers.missing_setup("cycles" if name == NOISE else name)
        if problems:
            raise PbrlabError(f"{name} cannot run here: " + "; ".join(problems))
    work = Path(out) if out else None
    if work is None:  # the prepared environments outside the checkout, for this run only
        scratch = tempfile.TemporaryDirectory(prefix="pbrlab-fidelity-")
        environment_cache = Path(scratch.name)
    else:
        environment_cache = work / "environments"
    rows = []
    for scenario in scenarios:
        environment = staging.prepare_environment(scenario.lighting, environment_cache)
        bounds = staging.model_bounds(scenario.model)
        row = Row(scenario.key, scenario.size(scale))
        shown, facts = {}, {}
        for name in render:
            seed = 1 if name == NOISE else 0
            view = staging.view_spec(scenario, scale, environment, bounds, samples=samples, seed=seed,
                                     denoise=DENOISE)
            renderer = "cycles" if name == NOISE else name
            image, fact, seconds = _render_display(name, renderer, view, render_block,
                                                   (work / scenario.key) if work else None)
            shown[name], facts[name], row.seconds[name] = image, {**fact, "view": view}, seconds
            if update_references and name != "pbrlab":
                path = reference_path(scenario.key, name, references)
                path.parent.mkdir(parents=True, exist_ok=True)
                images.write_png(path, image)
        if update_references and facts:
            _merge_facts(Path(references) / scenario.key / "facts.json",
                         {k: v for k, v in facts.items() if k != "pbrlab"}, row.seconds)
        for name in renderers.RENDERERS + (NOISE,):
            if name not in shown:
                path = reference_path(scenario.key, name, references)
                if path.is_file():
                    shown[name] = images.read_image(path)
        golden = shown.get(renderers.REFERENCE)
        if golden is None:
            raise PbrlabError(f"{scenario.key}: no Cycles reference (render it: --render cycles)")
        for name, image in shown.items():
            if image.shape != golden.shape:
                raise PbrlabError(f"{scenario.key}: {name}'s image is {image.shape[1]}x{image.shape[0]}, "
                                  f"the reference's {golden.shape[1]}x{golden.shape[0]}")
            if name == NOISE:
                row.noise_db = metric.score_db(image, golden)
            elif name != renderers.REFERENCE:
                row.scores[name] = metric.score_db(image, golden)
        if work:
            _write_side_by_side(work / scenario.key / "side_by_side.png", shown)
        log(f"{row.key}: " + ", ".join(f"{k} {v:.1f} dB" for k, v in sorted(row.scores.items()))
            + (f", noise {row.noise_db:.1f} dB" if row.noise_db is not None else ""))
        rows.append(row)
    return rows


def _merge_facts(path: Path, facts: dict, seconds: dict) -> None:
    old = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
    for name, fact in facts.items():
        old[name] = {**{k: v for k, v in fact.items() if k != "messages"}, "seconds": round(seconds[name], 2)}
    text = json.dumps(old, indent=1, sort_keys=True) + "\n"
    # no machine's paths in a committed file: the checkout's made relative, a run's scratch dropped
    text = text.replace(str(staging.REPO) + "/", "").replace(tempfile.gettempdir() + "/", "")
    path.write_text(text, encoding="utf-8")


SIDE_BY_SIDE = ("cycles", "pbrlab", "threejs", "sample_viewer")


def _write_side_by_side(path: Path, shown: dict) -> None:
    """Cycles | pbrlab | three.js | Sample Viewer, each over white (as the metric sees them)."""
    tiles = [np.rint(metric.over_white(shown[n])).astype(np.uint8) for n in SIDE_BY_SIDE if n in shown]
    gap = np.full((tiles[0].shape[0], 4, 3), 200, np.uint8)
    row = np.concatenate([x for t in tiles for x in (t, gap)][:-1], axis=1)
    images.write_png(path, row)


def summary(rows: list[Row]) -> dict:
    """The done-when figures over the rows that have every renderer."""
    full = [r for r in rows if "pbrlab" in r.scores and all(p in r.scores for p in renderers.PEERS)]
    out = {"rows": len(rows), "rows_with_every_renderer": len(full)}
    if not full:
        return out
    med = {name: statistics.median(r.scores[name] for r in full) for name in ("pbrlab",) + renderers.PEERS}
    out["median_db"] = {k: round(v, 2) for k, v in med.items()}
    out["pbrlab_minus_best_peer_median_db"] = round(med["pbrlab"] - min(med[p] for p in renderers.PEERS), 2)
    out["pbrlab_closest"] = sum(r.closest() == "pbrlab" for r in full)
    out["pbrlab_worse_than_worst_peer"] = [r.key for r in full
                                           if r.scores["pbrlab"] > max(r.scores[p] for p in renderers.PEERS)]
    out["pass_line"] = {name: sum(r.scores[name] <= metric.PASS_LINE_DB for r in full)
                        for name in ("pbrlab",) + renderers.PEERS}
    noise = [r.noise_db for r in full if r.noise_db is not None]
    if noise:
        out["noise_db_max"] = round(max(noise), 2)
    return out


def table(rows: list[Row]) -> str:
    """A markdown table: one row per scene, dB against Cycles (lower is closer)."""
    head = "| scene @ lighting | size | pbrlab | three.js | Sample Viewer | Cycles noise | closest |\n"
    head += "|---|---|---|---|---|---|---|\n"
    body = ""
    for r in rows:
        cell = {name: (f"**{r.scores[name]:.1f}**" if r.closest() == name else f"{r.scores[name]:.1f}")
                if name in r.scores else "—" for name in ("pbrlab",) + renderers.PEERS}
        noise = f"{r.noise_db:.1f}" if r.noise_db is not None else "—"
        body += (f"| {r.key} | {r.size[0]}×{r.size[1]} | {cell['pbrlab']} | {cell['threejs']} | "
                 f"{cell['sample_viewer']} | {noise} | {r.closest() or '—'} |\n")
    return head + body
