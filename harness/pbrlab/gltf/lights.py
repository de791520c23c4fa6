"""KHR_lights_punctual lights as pbrlab lights, and the unit conversion.

glTF gives directional lights in lux (lm/m^2) and point and spot lights in candela
(lm/sr), and renderers (the Khronos sample viewer, pyrender) shade with
radiance_out = BRDF x intensity x color x NdotL (x 1/d^2): a white Lambert surface
(BRDF = 1/pi) facing a 1-lux light returns 1/pi. pbrlab's lights are the lecture's
"pi times too bright" ones (README, "Conventions"): the shader multiplies by pi, so that
the same surface under an intensity-1 pbrlab light returns 1. The same radiance needs

    pbrlab intensity = glTF intensity / pi          (GLTF_TO_PBRLAB_INTENSITY)

for all three types (lux and candela alike: the 1/d^2 of point and spot lights is the
same in both). Range: pbrlab windows the inverse square with saturate(1 - (d/range)^4)^2
(Karis 2013), the extension's README recommends the unsquared window; both reach 0 at
range and the extension leaves the falloff inside it to the renderer. Cones: glTF's
innerConeAngle / outerConeAngle (radians from the axis, defaults 0 and pi/4) become
inner_cone_deg / outer_cone_deg; both use the squared linear ramp in cos(angle) (the
extension README's reference implementation squares it too).
"""

from __future__ import annotations

import json
import math

import numpy as np

from ..scene import Light
from .document import Document

GLTF_TO_PBRLAB_INTENSITY = 1.0 / math.pi
DEFAULT_OUTER_CONE = math.pi / 4  # KHR_lights_punctual README, "Spot"


def _number(doc, spec, key, where, default, lo, hi=math.inf, lo_open=False):
    value = spec.get(key, default)
    ok = (not isinstance(value, bool) and isinstance(value, (int, float))
          and (lo < value if lo_open else lo <= value) and value <= hi)
    if not ok:
        doc.fail(where, f"{key} must be a number in {'(' if lo_open else '['}{lo:g}, {hi:g}], got {json.dumps(value)}")
    return float(value)


def punctual_light(doc: Document, index: int, world: np.ndarray, where: str) -> Light:
    """Light ``index`` of the extension placed by the node's world matrix (lights shine
    down the node's -Z; position is its origin)."""
    lights = doc.json.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    if isinstance(index, bool) or not isinstance(index, int) or not 0 <= index < len(lights):
        doc.fail(where, f"refers to KHR_lights_punctual light {json.dumps(index)}, but the file has {len(lights)}")
    spec = lights[index]
    lw = f"extensions.KHR_lights_punctual.lights[{index}]"
    kind = spec.get("type")
    if kind not in ("directional", "point", "spot"):
        doc.fail(lw, f"type must be directional, point or spot, got {json.dumps(kind)}")
    colour = spec.get("color", [1.0, 1.0, 1.0])
    if (not isinstance(colour, list) or len(colour) != 3
            or not all(isinstance(c, (int, float)) and not isinstance(c, bool) and 0 <= c for c in colour)):
        doc.fail(lw, f"color must be 3 non-negative numbers, got {json.dumps(colour)}")
    intensity = _number(doc, spec, "intensity", lw, 1.0, 0.0)
    light = Light(type=kind, color=np.array(colour, np.float64),
                  intensity=intensity * GLTF_TO_PBRLAB_INTENSITY)
    direction = world[:3, :3] @ np.array([0.0, 0.0, -1.0])
    if kind in ("directional", "spot"):
        norm = np.linalg.norm(direction)
        if not norm > 0:
            doc.fail(where, "its transform collapses the light's direction")
        light.direction = direction / norm
    if kind in ("point", "spot"):
        light.position = world[:3, 3].astype(np.float64)
        if "range" in spec:
            light.range = _number(doc, spec, "range", lw, None, 0.0, lo_open=True)
    if kind == "spot":
        cone = spec.get("spot", {})
        inner = _number(doc, cone, "innerConeAngle", f"{lw}.spot", 0.0, 0.0, math.pi / 2)
        outer = _number(doc, cone, "outerConeAngle", f"{lw}.spot", DEFAULT_OUTER_CONE, 0.0, math.pi / 2, lo_open=True)
        if inner >= outer:
            doc.fail(f"{lw}.spot", f"innerConeAngle ({inner:g}) must be smaller than outerConeAngle ({outer:g})")
        light.inner_cone_deg, light.outer_cone_deg = math.degrees(inner), math.degrees(outer)
    return light
