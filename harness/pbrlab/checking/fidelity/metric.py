"""The glTF Render Fidelity protocol's score of a candidate image against a golden one.

Source: model-viewer, packages/render-fidelity-tools/src/common.ts (ImageComparator.analyze,
toDecibel, MAX_COLOR_DISTANCE, FIDELITY_TEST_THRESHOLD) and its copy of pixelmatch's
colorDelta (third_party/pixelmatch/color-delta.ts; Kotsarenko & Ramos 2010, "Measuring
perceived color difference using YIQ NTSC transmission color space in mobile applications"):

* each pixel of both 8-bit RGBA images is blended over white with its own alpha:
  c' = 255 + (c - 255) * a / 255;
* delta = 0.5053 dY^2 + 0.299 dI^2 + 0.1957 dQ^2 of the two blended colours (a squared
  distance; 35215 is its largest value);
* over the pixels the CANDIDATE covers (alpha != 0): ratio = sqrt(mean(delta^2)) / 35215;
* the score is 10 log10(ratio) dB: lower is closer; -22 dB is the protocol's pass line.
"""

from __future__ import annotations

import math

import numpy as np

MAX_COLOR_DISTANCE = 35215.0   # common.ts: the largest value of the YIQ delta
PASS_LINE_DB = -22.0           # common.ts: FIDELITY_TEST_THRESHOLD

# color-delta.ts: rgb2y, rgb2i, rgb2q
_Y = np.array([0.29889531, 0.58662247, 0.11448223])
_I = np.array([0.59597799, -0.27417610, -0.32180189])
_Q = np.array([0.21147017, -0.52261711, 0.31114694])


def over_white(rgba8: np.ndarray) -> np.ndarray:
    """colorDelta's blend: each colour over white by its alpha, float64 HxWx3."""
    rgba = rgba8.astype(np.float64)
    alpha = rgba[..., 3:4] / 255.0
    return 255.0 + (rgba[..., :3] - 255.0) * alpha


def color_delta(candidate: np.ndarray, golden: np.ndarray) -> np.ndarray:
    """pixelmatch's YIQ delta per pixel (HxW float64) of two HxWx4 uint8 images."""
    a, b = over_white(candidate), over_white(golden)
    y = a @ _Y - b @ _Y
    i = a @ _I - b @ _I
    q = a @ _Q - b @ _Q
    return 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q


def rms_distance_ratio(candidate: np.ndarray, golden: np.ndarray) -> float:
    """ImageComparator.analyze's rmsDistanceRatio: RMS of the delta over the pixels the
    candidate covers, over MAX_COLOR_DISTANCE."""
    candidate, golden = np.asarray(candidate), np.asarray(golden)
    if candidate.shape != golden.shape or candidate.ndim != 3 or candidate.shape[2] != 4:
        raise ValueError(f"image sizes do not match (candidate {candidate.shape}, golden {golden.shape})")
    if candidate.dtype != np.uint8 or golden.dtype != np.uint8:
        raise ValueError("the protocol scores 8-bit images: pass display.display_rgba8 of each")
    covered = candidate[..., 3] != 0
    if not covered.any():
        raise ValueError("the candidate covers no pixel: nothing to score (an empty image is a defect)")
    delta = color_delta(candidate, golden)[covered]
    return math.sqrt(float(np.mean(delta * delta))) / MAX_COLOR_DISTANCE


def decibels(ratio: float) -> float:
    """toDecibel: 10 log10(ratio); a perfect match (ratio 0) is -inf dB."""
    return 10.0 * math.log10(ratio) if ratio > 0 else -math.inf


def score_db(candidate: np.ndarray, golden: np.ndarray) -> float:
    """The protocol's score of ``candidate`` against ``golden`` (both HxWx4 uint8), in dB."""
    return decibels(rms_distance_ratio(candidate, golden))
