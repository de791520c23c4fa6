"""Whether an image shows what its asset must show: the count a corpus check reports is of
images with content, never of exit codes or of alpha alone (issue 39: blank skinned renders
counted "180 of 180 render"; Unity pairs with all-black colour counted as drawn).

Coverage is alpha > 0 in pbrlab's linear image (``Rendering.linear``, the EXR of
``pbrlab render --hdr``: the material's alpha where a surface is drawn, 0 elsewhere).

BLACK_CODE: a covered pixel at or under this 8-bit sRGB code in every channel shows no light.
Under the sweeps' constant grey sky of radiance 0.3, an opaque dielectric reflects at least
its F0 of 0.04 (the glTF metallic-roughness default; the Fresnel term only grows towards
grazing) of it: linear 0.012, sRGB code 27 at normal incidence. Code 8 (linear 0.0024) is a
fifth of that: reached only where occlusion, a black specular colour or black emission with
nothing else leaves a surface unlit, which an image of the whole asset does not show on
every pixel.

The comparison with an independent renderer (three.js, tools/threejs_gltf) of the same
camera: coverage may differ only within 1 px of a silhouette of either image (antialiasing,
sub-pixel vertex placement); a pixel covered in one and not the other away from every
silhouette is geometry one renderer draws and the other does not.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage

BLACK_CODE = 8
# Pixels eroded from the jointly covered region before colours are compared (silhouettes
# blend with the background differently under each renderer's antialiasing).
EDGE_PX = 2


def covered(linear: np.ndarray) -> np.ndarray:
    return np.asarray(linear)[..., 3] > 0


def silhouette_band(mask: np.ndarray) -> np.ndarray:
    """Pixels within 1 px (4-neighbourhood) of a coverage change of ``mask``."""
    return mask ^ ndimage.binary_erosion(mask) | mask ^ ndimage.binary_dilation(mask)


@dataclass
class Content:
    verdict: str          # "drawn", "empty" (no covered pixel) or "black" (every covered pixel <= BLACK_CODE)
    coverage: float       # fraction of pixels covered
    lit_fraction: float   # fraction of covered pixels over BLACK_CODE in some channel


def content(linear: np.ndarray, srgb8: np.ndarray) -> Content:
    """What the image shows: ``linear`` gives coverage, ``srgb8`` (HxWx3 or 4, the display
    image) the colour a reader sees."""
    mask = covered(linear)
    if not mask.any():
        return Content("empty", 0.0, 0.0)
    lit = np.asarray(srgb8)[..., :3].max(axis=-1)[mask] > BLACK_CODE
    return Content("drawn" if lit.any() else "black", float(mask.mean()), float(lit.mean()))


def coverage_disagreement(ours: np.ndarray, theirs: np.ndarray) -> int:
    """Pixels covered in one linear image and not the other, away from every silhouette of
    both (module doc)."""
    a, b = covered(ours), covered(theirs)
    return int(((a ^ b) & ~(silhouette_band(a) | silhouette_band(b))).sum())


def mean_colour_difference(ours: np.ndarray, theirs: np.ndarray, encode) -> float | None:
    """The largest channel's |mean sRGB code difference| over the pixels both cover (eroded
    by EDGE_PX); ``encode``: linear straight colour -> sRGB codes. None when they share none."""
    inner = ndimage.binary_erosion(covered(ours) & covered(theirs), iterations=EDGE_PX)
    if not inner.any():
        return None
    a = encode(np.clip(ours[..., :3], 0, None))[inner].astype(np.float64)
    b = encode(np.clip(theirs[..., :3], 0, None))[inner].astype(np.float64)
    return float(np.abs(a.mean(axis=0) - b.mean(axis=0)).max())
