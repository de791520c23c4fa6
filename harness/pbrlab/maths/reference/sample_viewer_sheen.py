"""The Khronos glTF Sample Renderer's sheen layer (npm @khronosgroup/gltf-viewer 1.1.0, the
version tools/sample_viewer pins) in float64: not pbrlab's shading, but the formulas the
agreement check names where the two renderers weigh KHR_materials_sheen differently,
transcribed from the viewer's shaders (pbr.frag's punctual and image-based blocks, brdf.glsl
V_Sheen / D_Charlie, ibl.glsl getIBLRadianceCharlie, ibl_filtering.frag LUT) and its loader
(gltf-viewer.module.js loadEnvironment, WebGl.setTexture). Colours on the last axis.

pbr.frag, per light and for the environment (the coat then mixed over, as pbrlab does):
    colour = f_sheen + colour_base x (1 - max3(sheenColor) x E_table(n·v, sheenRoughness))
with, for a light, the smaller of that scaling at n·v and n·l. E_table is
texture(u_SheenELUT, (n·v, r)).r, and in 1.1.0 that texture is never filled: loadEnvironment
marks the texture of lut_sheen_E.png "initialized" ("iblsampler has already initialized the
texture", copied from the GGX and Charlie tables above it, which the sampler does fill), so
setTexture skips the PNG's texImage2D and binds an empty texture object, which WebGL2 samples
as (0, 0, 0, 1). So E_table = 0 and the base under the sheen keeps all its light
(VIEWER_SHEEN_TABLE_ALBEDO), where KHR_materials_sheen and pbrlab scale it by
1 - max3(c) E (pbr/shading/sheen.glsl). Whatever lut_sheen_E.png holds does not matter
(tools/sample_viewer serves a 1 x 1 white stand-in: read as 1, a white sheen would hide its
base entirely, which the viewer's image does not).

The environment's sheen (getIBLRadianceCharlie): the Charlie-prefiltered environment (a
constant sky: the sky) x sheenColor x lut_charlie.b at (n·v, r), the table its iblSampler
integrates with Ashikhmin's visibility, V_Ashikhmin = clamp(1 / (4 (n·l + n·v - n·l n·v)), 0,
1) (Ashikhmin & Premoze 2007, the viewer's "Charlie" table), not the Charlie visibility with
Estevez & Kulla's Λ fit that its lights use (V_Sheen) and pbrlab uses for both: its albedo is
E_A = ∫ D_Charlie V_Ashikhmin (n·l) dω (sample_viewer_prediction integrates it with
sheen_table.integrate_sheen_albedo's "NEUBELT" visibility, the same formula without the clamp
at 1, which binds only where n·v and n·l are both below about 0.13).
"""

from __future__ import annotations

import numpy as np

VIEWER_SHEEN_TABLE_ALBEDO = 0.0  # texture(u_SheenELUT, ...).r: the empty texture's 0 (above)


def base_scaling(sheen_color, E_table=VIEWER_SHEEN_TABLE_ALBEDO):
    """The viewer's albedoSheenScaling, 1 - max3(sheenColor) x E_table (pbr.frag; no clamp)."""
    return 1.0 - np.max(np.asarray(sheen_color, np.float64), axis=-1) * E_table


def environment_sheen(sky, sheen_color, ashikhmin_albedo):
    """getIBLRadianceCharlie under a constant sky: sky x sheenColor x lut_charlie.b (= E_A)."""
    return np.asarray(sky, np.float64) * np.asarray(sheen_color, np.float64) \
        * np.asarray(ashikhmin_albedo, np.float64)[..., None]


def coat_weight(clearcoat, NdotV, coat_f0=0.04):
    """pbr.frag's mix(colour, coat, clearcoatFactor x F_Schlick(0.04, 1, n·v)) weight of what
    lies under the coat: 1 - clearcoatFactor x (F0 + (1 - F0)(1 - n·v)^5) (Schlick 1994)."""
    NdotV = np.clip(np.asarray(NdotV, np.float64), 0.0, 1.0)
    return 1.0 - clearcoat * (coat_f0 + (1.0 - coat_f0) * (1.0 - NdotV) ** 5)
