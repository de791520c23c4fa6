"""The sun of an HDR environment, found and split off as a directional light, so that it can
cast shadows (render.environment_sun: render/shadow_map.py) while the rest of the sky stays an
environment lookup.

Criterion (``find_sun``), on the equirectangular radiance image (environment.py's convention),
in float64:

* the peak texel of luminance (Rec. 709 weights, SUN_LUMINANCE), and every texel connected to
  it (8-neighbours, the longitude wrapping round) whose luminance is at least
  SUN_THRESHOLD_OF_PEAK of the peak's: the sun's texels;
* it is a sun only when those texels hold at least SUN_MIN_SHARE of the environment's whole
  radiant flux sum(L dOmega) within a disc no wider than SUN_MAX_RADIUS_DEG: a compact source
  that rules the light. Blender's sunrise: 8 texels of 1024 x 512 hold 55 % of the flux, radius
  0.56 deg; its courtyard's brightest region (peak 52) spreads over thousands of texels: no sun.

What it becomes:

* the texels are replaced by the mean radiance of the ring of texels bordering them (the
  surrounding sky, ``sunless``), so the environment keeps a sky where the sun was;
* the removed radiance, integrated, is the sun's irradiance at normal incidence:
  E = sum_i (L_i - L_ring) dOmega_i (RGB); the directional light's radiance in pbrlab's
  convention (docs/conventions.md: a white Lambert surface lit by radiance 1 along n returns 1,
  the light unit's pi) is E / pi;
* its direction: the radiance-weighted centroid of the texels' directions, normalised
  (the light travels the other way); its angular radius: that of a disc of the texels' solid
  angle, Omega = 2 pi (1 - cos r).

Energy is counted once: sun + sunless environment has the original's flux to rounding
(E is defined as the removed flux), and its irradiance on a Lambertian sphere differs from the
original's only by the cosine's spread over the disc (tests/render/test_environment_sun.py).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .environment import equirect_directions

SUN_LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # Rec. 709 / sRGB luminance weights
# A texel is the sun's when its luminance is within a factor 100 of the peak: Blender's sunrise's
# disc is 4 texels at 2.4-3.3e4 with a halo falling from 2.1e3 to 50 beside it; at 1 % (330) the
# halo's two brightest texels of each side join (8 texels, 55.2 % of the flux), at 0.1 % 32
# texels (56.1 %): the threshold moves the split by under 1 % of the flux.
SUN_THRESHOLD_OF_PEAK = 0.01
SUN_MIN_SHARE = 0.2          # of the environment's flux: below it the sun does not rule the light
SUN_MAX_RADIUS_DEG = 3.0     # a compact source (the real sun: 0.27 deg; an HDR's blur widens it)


@dataclass(frozen=True)
class EnvironmentSun:
    direction: np.ndarray    # unit, the way the light travels (from the sun towards the scene)
    irradiance: np.ndarray   # RGB, E at normal incidence: sum (L - L_ring) dOmega
    angular_radius: float    # radians: the disc of the texels' solid angle
    share: float             # of the environment's luminous flux
    mask: np.ndarray         # HxW bool: the texels taken out
    fill: np.ndarray         # RGB radiance put in their place (the ring's mean)

    @property
    def radiance(self) -> np.ndarray:
        """The directional light's colour x intensity in pbrlab's light unit: E / pi."""
        return self.irradiance / math.pi


def _connected_to(mask: np.ndarray, seed: tuple[int, int]) -> np.ndarray:
    """The texels of ``mask`` 8-connected to ``seed``, columns wrapping (longitude)."""
    height, width = mask.shape
    out = np.zeros_like(mask)
    stack = [seed]
    out[seed] = True
    while stack:
        r, c = stack.pop()
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                rr, cc = r + dr, (c + dc) % width
                if 0 <= rr < height and mask[rr, cc] and not out[rr, cc]:
                    out[rr, cc] = True
                    stack.append((rr, cc))
    return out


def _ring(mask: np.ndarray) -> np.ndarray:
    """The texels 8-adjacent to ``mask`` and not in it (columns wrap, rows do not)."""
    grown = mask.copy()
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            shifted = np.roll(mask, dc, axis=1)
            if dr > 0:
                shifted = np.vstack([np.zeros_like(shifted[:dr]), shifted[:-dr]])
            elif dr < 0:
                shifted = np.vstack([shifted[-dr:], np.zeros_like(shifted[:-dr])])
            grown |= shifted
    return grown & ~mask


def find_sun(image: np.ndarray, threshold_of_peak: float = SUN_THRESHOLD_OF_PEAK,
             min_share: float = SUN_MIN_SHARE, max_radius_deg: float = SUN_MAX_RADIUS_DEG) -> EnvironmentSun | None:
    """The sun of an equirectangular radiance image (HxWx>=3, linear), or None (module doc)."""
    radiance = np.asarray(image, np.float64)[..., :3]
    height, width = radiance.shape[:2]
    directions, solid_angle = equirect_directions(height, width)
    luminance = radiance @ SUN_LUMINANCE
    flux = luminance * solid_angle
    total = float(flux.sum())
    peak = np.unravel_index(int(np.argmax(luminance)), luminance.shape)
    if total <= 0.0 or luminance[peak] <= 0.0:
        return None
    mask = _connected_to(luminance >= threshold_of_peak * luminance[peak], peak)
    omega = float(solid_angle[mask].sum())
    radius = math.acos(max(-1.0, 1.0 - omega / (2 * math.pi)))
    share = float(flux[mask].sum()) / total
    if share < min_share or radius > math.radians(max_radius_deg):
        return None
    ring = _ring(mask)
    fill = (radiance[ring] * solid_angle[ring, None]).sum(axis=0) / solid_angle[ring].sum()
    excess = (radiance[mask] - fill) * solid_angle[mask, None]          # per texel, RGB
    irradiance = excess.sum(axis=0)
    weights = excess @ SUN_LUMINANCE
    centroid = (directions[mask] * weights[:, None]).sum(axis=0)
    centroid /= np.linalg.norm(centroid)
    return EnvironmentSun(direction=-centroid, irradiance=irradiance, angular_radius=radius,
                          share=share, mask=mask, fill=fill)


def sunless(image: np.ndarray, sun: EnvironmentSun) -> np.ndarray:
    """``image`` with the sun's texels replaced by the surrounding sky (``sun.fill``); float32."""
    out = np.array(image, np.float32)[..., :3]
    out[sun.mask] = sun.fill.astype(np.float32)
    return out
