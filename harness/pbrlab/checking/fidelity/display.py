"""The glTF Render Fidelity protocol's display transform: one linear image to the 8-bit RGBA
image the protocol scores.

Source: model-viewer, packages/render-fidelity-tools/test/renderers/blender-cycles/render.py
(the protocol's Cycles renderer; the Khronos glTF-Render-Fidelity-Generator keeps it):

    colour x 1/0.6                  (three.js's ACESFilmicToneMapping divides its exposure by 0.6)
    three.js's ACES fit             (Hill's fit: ACESInputMat, RRTAndODTFit, ACESOutputMat)
    pow(clip(c, 0, 0.9999), 1/2.2)  (a gamma 2.2 encode, not the sRGB curve)
    x 255, truncated to uint8       (numpy's astype: toward zero), alpha too

Every renderer's linear output goes through this one transform, so the score compares
shading, not tone mappers. Colours are straight (not premultiplied by alpha); alpha is the
coverage the metric composites over white (metric.py).
"""

from __future__ import annotations

import numpy as np

from ...maths.reference.tonemap import tonemap_aces_fitted

EXPOSURE_SCALE = 1.0 / 0.6   # render.py: image[:, :, :3] *= 1.0 / 0.6
GAMMA = 2.2                  # render.py: np.power(..., 1.0 / 2.2)
CLIP_MAX = 0.9999            # render.py: np.clip(..., 0.0, 0.9999), so 255 is never reached


def display_rgba8(linear: np.ndarray) -> np.ndarray:
    """HxWx4 uint8 of an HxWx4 linear image (float, straight colour, alpha = coverage).

    NaN and infinities are an error of the renderer that made them, not a colour: refused."""
    linear = np.asarray(linear, np.float64)
    if linear.ndim != 3 or linear.shape[2] != 4:
        raise ValueError(f"expected an HxWx4 image, got shape {linear.shape}")
    if not np.isfinite(linear).all():
        bad = int((~np.isfinite(linear)).any(axis=2).sum())
        raise ValueError(f"{bad} pixels are not finite: a renderer's defect, not a colour to display")
    # tonemap_aces_fitted clips to [0, 1]; the protocol clips to [0, 0.9999] after: the same
    # as one clip to [0, 0.9999] (the gamma curve is monotonic and maps 0 to 0)
    toned = tonemap_aces_fitted(linear[..., :3] * EXPOSURE_SCALE)
    encoded = np.power(np.clip(toned, 0.0, CLIP_MAX), 1.0 / GAMMA)
    out = np.empty(linear.shape, np.uint8)
    out[..., :3] = (encoded * 255).astype(np.uint8)
    out[..., 3] = (np.clip(linear[..., 3], 0.0, 1.0) * 255).astype(np.uint8)
    return out
