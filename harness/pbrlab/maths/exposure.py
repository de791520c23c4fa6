"""A metered exposure for scenes in physical light units (glTF's KHR_lights_punctual: lux
and candela), shown through Khronos PBR Neutral: the exposure darkens the image, never
brightens it, just enough that at most CLIPPED_FRACTION of the covered pixels reach the
display's top code.

Why metered from the image and not from the lights alone: what blows out is decided by
where the surfaces are relative to the lights (LightsPunctualLamp's 15 cd bulb sits 0.2 m
inside its shade). An incident-light rule (a white Lambert surface facing the lights at
the median illuminance of the model's surface maps to 1.0) gives that lamp -5 EV and a
near-black stand (median code 2); this rule gives about -2.5 EV (docs/gltf.md, measured).
Why never brighter: a dim file stays as its author lit it; only clipping is corrected.

    exposure_ev = min(0, log2(NEUTRAL_SATURATES_AT / q))

q being the (1 - CLIPPED_FRACTION) quantile of the covered pixels' largest channel
(linear radiance, alpha > 0). NEUTRAL_SATURATES_AT is the grey input Khronos PBR Neutral
maps to the linear value that rounds to code 255 (srgb8.ENCODE_EDGES[-1]): in the
neutral's own terms (Khronos PBR Neutral README, "Tone mapping"), for a grey x above the
knee, p = x - F90 and the output is p_n = 1 - (1 - K_s)^2 / (p + 1 - 2 K_s), so
p_n = e at x = F90 + (1 - K_s)^2 / (1 - e) - 1 + 2 K_s (about 13.5).
"""

from __future__ import annotations

import math

import numpy as np

from .reference.tonemap import KHRONOS_NEUTRAL_F90, KHRONOS_NEUTRAL_KS
from .srgb8 import ENCODE_EDGES

CLIPPED_FRACTION = 0.01  # the covered pixels allowed to reach code 255 (1 %)
METERED_TONEMAP = "khronos_neutral"  # the glTF Sample Viewer's default display mapping
_TOP_EDGE = float(ENCODE_EDGES[-1])  # the least linear value encoded as code 255
NEUTRAL_SATURATES_AT = (KHRONOS_NEUTRAL_F90 + (1.0 - KHRONOS_NEUTRAL_KS) ** 2 / (1.0 - _TOP_EDGE)
                        - 1.0 + 2.0 * KHRONOS_NEUTRAL_KS)


def metered_exposure(linear: np.ndarray) -> float:
    """The exposure (EV stops, <= 0) for a rendering's linear HxWx4 radiance (module doc)."""
    covered = linear[..., 3] > 0
    if not covered.any():
        return 0.0
    peak = np.nan_to_num(linear[..., :3][covered], nan=0.0, posinf=np.finfo(np.float32).max).max(axis=-1)
    q = float(np.quantile(peak.astype(np.float64), 1.0 - CLIPPED_FRACTION))
    if not q > NEUTRAL_SATURATES_AT:
        return 0.0
    return math.log2(NEUTRAL_SATURATES_AT / q)
