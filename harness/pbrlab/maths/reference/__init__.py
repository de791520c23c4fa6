"""float64 numpy references of the pbrlab GLSL shading library, one module per layer.

Each module mirrors a folder of ``glsl/pbr/`` with the same semantics (same clamps,
same edge cases, same variant defaults) but in float64 and in the textbook form of each
formula, so that ``tests/library`` can compare the GPU against it:

  constants  PI, INV_PI, LIGHT_UNIT_SCALE          (glsl/pbr/common/)
  guards     the numeric guards' constants and helpers (common/guards.glsl)
  color      sRGB curves, pow 2.2 / fast gamma, luminance, transfer paths (glsl/pbr/color/)
  remap      smoothness / perceptual roughness / alpha / gloss remaps (material/remap.glsl)
  material   metallic & specular workflows, F0 tables, F0 <-> IOR (material/)
  brdf       every D, G, V, F and Fd term           (glsl/pbr/brdf/)
  shading    variant dispatch, standard BRDF, punctual lights (shading/, lighting/)
  tonemap    exposure and tonemappers              (glsl/pbr/tonemap/)
  surface    environment BRDF, pbr_lighting_standard, Unity helpers (ibl/, surface/, unity/)
  multiple_scattering  GGX's albedo with multiple scattering (random walk, Kulla-Conty), the
             reference of pbr_energy_compensation (ibl/environment_brdf.glsl)
  unity_brdf Unity's BRDF1/2/3 and GI inputs, transcribed from Unity's .cginc sources
             (not from glsl/pbr/unity/, which tests/importers/unity/ checks against it)

Arrays broadcast like numpy; colours and directions carry their 3 components on the last
axis. Functions return float64 arrays.
"""

from . import brdf, color, constants, guards, material, remap, shading, tonemap, unity_brdf

__all__ = ["brdf", "color", "constants", "guards", "material", "remap", "shading", "tonemap", "unity_brdf"]
