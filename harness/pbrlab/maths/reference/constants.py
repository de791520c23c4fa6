"""Constants shared with glsl/pbr/common/ (tested equal to the GLSL macros)."""

import math

PI = math.pi                  # PBR_PI
INV_PI = 1.0 / math.pi        # PBR_INV_PI
TWO_PI = 2.0 * math.pi        # PBR_TWO_PI
HALF_PI = 0.5 * math.pi       # PBR_HALF_PI

# PBR_LIGHT_UNIT_SCALE: the lecture's "lights are π times too bright" convention,
# C_final = C_light * LIGHT_UNIT_SCALE * BRDF * max(0, NdotL) (glsl/pbr/common/conventions.glsl §5).
LIGHT_UNIT_SCALE = PI
