"""The fidelity protocol's score between two linear renders: how far apart two seeds of the
same Cycles view are (the reference's own noise floor).

    python tools/cycles/noise_floor.py A.f32 B.f32 [WIDTH HEIGHT]

A.f32 and B.f32 are float32 RGBA, rows top to bottom, linear, premultiplied alpha (what
tools/cycles/render.py writes; the size is read from the OUT.json beside each file unless
given). Prints the score of B (the "candidate") against A in dB, and of A against B.
numpy only; no bpy. The lead's canonical implementation is pbrlab.checking.fidelity; this
one measures now, written from the protocol in /work/fidelity_spec.md (issue 38):

display (the Khronos glTF Render Fidelity's treatment of Cycles' linear EXR):
    x * (1 / 0.6) -> three.js ACESFilmicToneMapping's fit (ACESInputMat, RRTAndODTFit,
    ACESOutputMat, saturate; three.js src/renderers/shaders/ShaderChunk/
    tonemapping_pars_fragment.glsl.js, toneMappingExposure 1) -> pow(clip(x, 0, 0.9999), 1/2.2)
    -> x 255 truncated to uint8; alpha x 255 truncated. The colour put through it is the
    straight (un-premultiplied) colour, as a PNG stores it.
metric: each image blended over white with its alpha (pixelmatch's blend: 255 + (c - 255) a),
    pixelmatch's YIQ colour delta (colorDelta: 0.5053 y^2 + 0.299 i^2 + 0.1957 q^2 of the
    differences of rgb2y/rgb2i/rgb2q, mapbox/pixelmatch index.js), RMS of the delta over the
    pixels where the candidate's 8-bit alpha is not 0, divided by 35215 (the delta's largest
    value), in dB: 10 log10.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

# three.js ACESFilmicToneMapping. GLSL's mat3(c0, c1, c2) takes COLUMNS; written here as rows.
ACES_INPUT = np.array([[0.59719, 0.35458, 0.04823],
                       [0.07600, 0.90834, 0.01566],
                       [0.02840, 0.13383, 0.83777]])
ACES_OUTPUT = np.array([[1.60475, -0.53108, -0.07367],
                        [-0.10208, 1.10813, -0.00605],
                        [-0.00327, -0.07276, 1.07602]])
MAX_YIQ_DELTA = 35215.0  # pixelmatch: 0.5053 * 255^2 + 0.299 * 255^2 + 0.1957 * 255^2


def rrt_and_odt_fit(v: np.ndarray) -> np.ndarray:
    a = v * (v + 0.0245786) - 0.000090537
    b = v * (0.983729 * v + 0.4329510) + 0.238081
    return a / b


def display(linear_rgba: np.ndarray) -> np.ndarray:
    """HxWx4 linear premultiplied float -> HxWx4 uint8 straight-alpha display image."""
    rgba = np.asarray(linear_rgba, np.float64)
    alpha = np.clip(rgba[..., 3], 0.0, 1.0)
    colour = np.where(alpha[..., None] > 0, rgba[..., :3] / np.maximum(alpha, 1e-30)[..., None], 0.0)
    colour = colour * (1.0 / 0.6)
    colour = colour @ ACES_INPUT.T
    colour = rrt_and_odt_fit(colour)
    colour = np.clip(colour @ ACES_OUTPUT.T, 0.0, 1.0)
    colour = np.power(np.clip(colour, 0.0, 0.9999), 1.0 / 2.2)
    out = np.empty(rgba.shape[:2] + (4,), np.uint8)
    out[..., :3] = np.floor(colour * 255.0).astype(np.uint8)
    out[..., 3] = np.floor(alpha * 255.0).astype(np.uint8)
    return out


def _yiq(rgb: np.ndarray):
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    return (r * 0.29889531 + g * 0.58662247 + b * 0.11448223,
            r * 0.59597799 - g * 0.27417610 - b * 0.32180189,
            r * 0.21147017 - g * 0.52261711 + b * 0.31114694)


def over_white(rgba8: np.ndarray) -> np.ndarray:
    a = rgba8[..., 3:4].astype(np.float64) / 255.0
    return 255.0 + (rgba8[..., :3].astype(np.float64) - 255.0) * a


def score_db(reference8: np.ndarray, candidate8: np.ndarray) -> float:
    """The protocol's score of the candidate against the reference (both HxWx4 uint8)."""
    if reference8.shape != candidate8.shape:
        raise ValueError(f"image sizes differ: {reference8.shape} and {candidate8.shape}")
    y1, i1, q1 = _yiq(over_white(reference8))
    y2, i2, q2 = _yiq(over_white(candidate8))
    delta = 0.5053 * (y1 - y2) ** 2 + 0.299 * (i1 - i2) ** 2 + 0.1957 * (q1 - q2) ** 2
    covered = candidate8[..., 3] != 0
    if not covered.any():
        raise ValueError("the candidate covers no pixel")
    rms = np.sqrt(np.mean(delta[covered] ** 2)) / MAX_YIQ_DELTA
    return float(10.0 * np.log10(max(rms, 1e-30)))


def read_f32(path: Path, size: tuple[int, int] | None = None) -> np.ndarray:
    if not path.is_file():
        raise SystemExit(f"noise_floor.py: file not found: {path}")
    if size is None:
        meta = path.with_suffix(".json")
        if not meta.is_file():
            raise SystemExit(f"noise_floor.py: no {meta} beside {path}: give WIDTH HEIGHT")
        size = tuple(json.loads(meta.read_text())["size"])
    width, height = size
    data = np.fromfile(path, np.float32)
    if data.size != width * height * 4:
        raise SystemExit(f"noise_floor.py: {path} holds {data.size} floats, not {width}x{height}x4")
    return data.reshape(height, width, 4)


def main(argv: list[str]) -> int:
    if len(argv) not in (2, 4):
        raise SystemExit("usage: noise_floor.py A.f32 B.f32 [WIDTH HEIGHT]")
    size = (int(argv[2]), int(argv[3])) if len(argv) == 4 else None
    a, b = read_f32(Path(argv[0]), size), read_f32(Path(argv[1]), size)
    if a.shape != b.shape:
        raise SystemExit(f"noise_floor.py: sizes differ: {a.shape[1]}x{a.shape[0]} and {b.shape[1]}x{b.shape[0]}")
    da, db = display(a), display(b)
    print(f"{score_db(da, db):.2f} dB (B against A)  {score_db(db, da):.2f} dB (A against B)  "
          f"covered {int((db[..., 3] != 0).sum())} px, 8-bit display values differing: "
          f"{float((da != db).any(-1).mean()) * 100:.1f}% of pixels")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
