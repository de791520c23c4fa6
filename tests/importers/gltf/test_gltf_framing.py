"""The framing camera (gltf/cameras.py framing_camera) of a file without a camera fits
the scene to the view on both axes: a wide and a tall model each span most of their
limiting axis, whatever the image's aspect ratio, and no vertex leaves the view."""

from __future__ import annotations

import pytest

from gltf_helpers import quad_document, write
from pbrlab.importers.gltf import load_gltf
from pbrlab.importers.gltf.cameras import FRAMING_MARGIN
from pbrlab.render.renderer import render_scene

# the limiting axis spans 1/FRAMING_MARGIN (95 %) of the image by construction; a
# rasterised silhouette loses up to a pixel at each end
FILLS_AT_LEAST = 0.85


def _coverage(tmp_path, gl_context, scale, size):
    doc = quad_document()
    doc["nodes"][0]["scale"] = scale
    scene = load_gltf(write(tmp_path, doc), size=size, emit_warnings=False).scene
    return render_scene(scene, gl_context).linear[..., 3] > 0


def _span(mask, axis) -> float:
    """The fraction of the image the silhouette spans along ``axis`` (0 rows, 1 columns)."""
    hit = mask.any(axis=1 - axis).nonzero()[0]
    return (hit[-1] - hit[0] + 1) / mask.shape[axis]


@pytest.mark.parametrize("size", [(160, 120), (120, 160), (96, 96)])
@pytest.mark.parametrize("shape, limiting", [("wide", 1), ("tall", 0)])
def test_framing_fills_the_limiting_axis(tmp_path, gl_context, size, shape, limiting):
    scale = [6.0, 1.0, 1.0] if shape == "wide" else [1.0, 6.0, 1.0]
    mask = _coverage(tmp_path, gl_context, scale, size)
    assert _span(mask, limiting) >= FILLS_AT_LEAST, (shape, size, _span(mask, limiting))
    assert _span(mask, limiting) <= 1 / FRAMING_MARGIN + 2 / mask.shape[limiting]
    assert not mask[0].any() and not mask[-1].any() and not mask[:, 0].any() and not mask[:, -1].any()
