"""KHR_lights_punctual lights as pbrlab lights, and the unit conversion.

glTF gives directional lights in lux (lm/m^2) and point and spot lights in candela
(lm/sr), and renderers (the Khronos sample viewer, pyrender) shade with
radiance_out = BRDF x intensity x color x NdotL (x 1/d^2): a white Lambert surface
(BRDF = 1/pi) facing a 1-lux light returns 1/pi. pbrlab's lights are the lecture's
"pi times too bright" ones (docs/conventions.md): the shader multiplies by pi, so that
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

import math

import numpy as np

from ...scene.model import Light
from .document import LIGHTS, Document

GLTF_TO_PBRLAB_INTENSITY = 1.0 / math.pi
DEFAULT_OUTER_CONE = math.pi / 4  # KHR_lights_punctual README, "Spot"


def punctual_light(doc: Document, index: int, world: np.ndarray, where: str) -> Light:
    """Light ``index`` (checked: document.LIGHTS) of the extension placed by the node's
    world matrix (lights shine down the node's -Z; position is its origin); ``where``: the node."""
    spec = doc.items(LIGHTS)[index]
    kind = spec.enum("type", ("directional", "point", "spot"))
    if spec.has("name"):
        spec.string("name")
    colour = spec.numbers("color", 3, [1.0, 1.0, 1.0], 0.0)
    intensity = spec.number("intensity", 1.0, 0.0)
    light = Light(type=kind, color=colour, intensity=intensity * GLTF_TO_PBRLAB_INTENSITY)
    direction = world[:3, :3] @ np.array([0.0, 0.0, -1.0])
    if kind in ("directional", "spot"):
        norm = np.linalg.norm(direction)
        if not norm > 0:
            doc.fail(where, "its transform collapses the light's direction")
        light.direction = direction / norm
    if kind in ("point", "spot"):
        light.position = world[:3, 3].astype(np.float64)
        if spec.has("range"):
            light.range = spec.number("range", None, 0.0, lo_open=True)
    if kind == "spot":
        cone = spec.object("spot")
        inner = cone.number("innerConeAngle", 0.0, 0.0, math.pi / 2)
        outer = cone.number("outerConeAngle", DEFAULT_OUTER_CONE, 0.0, math.pi / 2, lo_open=True)
        if inner >= outer:
            cone.fail(f"innerConeAngle ({inner:g}) must be smaller than outerConeAngle ({outer:g})")
        light.inner_cone_deg, light.outer_cone_deg = math.degrees(inner), math.degrees(outer)
    return light
