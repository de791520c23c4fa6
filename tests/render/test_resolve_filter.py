"""The Blackman-Harris resolve (render.antialias_filter, templates/resolve_samples.frag): every
pixel the weighted sum of the samples within 1.5 px of its centre, weights the separable
4-term Blackman-Harris window (Harris 1978), renormalised. Checked against the same sum in
float64 over which samples a half-plane covers (the GL's own sample positions), and a
constant image staying constant."""

import math

import numpy as np
import pytest

from pbrlab.foundation.errors import SceneError
from pbrlab.gpu import targets
from pbrlab.render.renderer import scene_frame
from pbrlab.scene import parse_scene

from test_antialias import (AMBIGUOUS_PX, SAMPLES, SIZE, WHITE, _data, _edge_line, _half_plane_objects, _offsets,
                            _render, _taken, _window_samples)

RADIUS = targets.BLACKMAN_HARRIS_RADIUS
# float32 sums of at most 5 x 5 x 4 = 100 products of weights in [0, 1] and values in [0, 1]:
# each rounding adds at most 2^-24 of the running sum
FLOAT32_SUMS = 100 * 2.0 ** -24


def blackman_harris(x):
    t = 2 * np.pi * (np.asarray(x, np.float64) + RADIUS) / (2 * RADIUS)
    w = 0.35875 - 0.48829 * np.cos(t) + 0.14128 * np.cos(2 * t) - 0.01168 * np.cos(3 * t)
    return np.where(np.abs(x) < RADIUS, w, 0.0)


def filtered(values, offsets):
    """HxW of the filter applied to per-sample values HxWxS (float64), as the shader does."""
    h, w, s = values.shape
    out = np.zeros((h, w))
    weights = np.zeros((h, w))
    reach = math.ceil(RADIUS + 0.5)
    for dy in range(-reach, reach + 1):      # window rows: dy up the image is -1 in array rows
        for dx in range(-reach, reach + 1):
            for k in range(s):
                wgt = blackman_harris(dx + offsets[k, 0]) * blackman_harris(dy + offsets[k, 1])
                if wgt <= 0:
                    continue
                shifted = np.full((h, w), np.nan)
                src = values[:, :, k]
                # array row r is window row h-1-r: the neighbour dy up the window is array row r - dy
                ys, yd = (slice(0, h - dy), slice(dy, h)) if dy >= 0 else (slice(-dy, h), slice(0, h + dy))
                xs, xd = (slice(dx, w), slice(0, w - dx)) if dx >= 0 else (slice(0, w + dx), slice(-dx, w))
                shifted[yd, xd] = src[ys, xs]
                ok = ~np.isnan(shifted)
                out[ok] += wgt * shifted[ok]
                weights[ok] += wgt
    return out / weights


def _bh_data(objects):
    data = _data(WHITE, objects, SAMPLES)
    data["render"]["antialias_filter"] = "blackman_harris"
    return data


def test_the_filtered_edge_is_the_window_over_its_samples(gl_context):
    _taken(gl_context)
    offsets = _offsets(gl_context)
    scene, got = _render(_bh_data(_half_plane_objects()), gl_context)
    alpha = got.linear[..., 3].astype(np.float64)
    n, c = _edge_line(scene_frame(scene))
    distance = _window_samples((SIZE, SIZE), offsets) @ n - c
    expected = filtered((distance < 0).astype(np.float64), offsets)
    ambiguous = filtered((np.abs(distance) < AMBIGUOUS_PX).astype(np.float64), offsets)
    error = np.abs(alpha - expected)
    assert np.all(error <= ambiguous + FLOAT32_SUMS), (error.max(), np.argwhere(error > ambiguous + FLOAT32_SUMS)[:5])
    # wider than the box: pixels two columns from the edge are partly covered now
    box = _render(_data(WHITE, _half_plane_objects(), SAMPLES), gl_context)[1].linear[..., 3]
    partial = lambda a: ((a > 1e-6) & (a < 1 - 1e-6)).sum()  # noqa: E731
    assert partial(alpha) > 2 * partial(box)


def test_a_constant_image_stays_constant(gl_context):
    _taken(gl_context)
    wall = [{"mesh": {"primitive": "plane", "size": 40}, "material": "m", "transform": {"rotate_deg": [90, 0, 0]}}]
    _, got = _render(_bh_data(wall), gl_context)
    assert np.abs(got.linear - 1.0).max() <= FLOAT32_SUMS


@pytest.mark.parametrize("samples", [1, 32])
def test_the_filter_needs_two_to_sixteen_samples(samples):
    data = _bh_data(_half_plane_objects())
    data["render"]["antialias"] = samples
    with pytest.raises(SceneError, match="antialias_filter.*2 to 16"):
        parse_scene(data)
