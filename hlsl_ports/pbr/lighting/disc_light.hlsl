// pbr/lighting/disc_light.hlsl: a distant disc light (a sun) shaded as a directional light
// with the specular lobe widened to the disc's size.
//
// Provides: float pbr_disc_light_alpha(float alpha, float angularRadius)
// Include:  "pbr/lighting/disc_light.hlsl" (path relative to hlsl_ports/)
// Config macros read: none.
//
// Roughness widening (the idea of Karis 2013, "Real Shading in Unreal Engine 4", §"Area
// lights": widen the GGX lobe by the light's angle instead of integrating over its area).
// Here the width is matched at half maximum: GGX's D(h) falls to half its peak where
// tan(theta_h) = alpha sqrt(sqrt(2) - 1) = PBR_GGX_HALF_MAX_TAN_PER_ALPHA * alpha (from
// D = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2)); a disc of angular radius r seen by reflection
// spans half-vectors within r / 2 of its centre; the two widths add in quadrature:
//   alpha' = sqrt(alpha^2 + (r / (2 PBR_GGX_HALF_MAX_TAN_PER_ALPHA))^2)
// so a mirror (alpha 0) reflects the disc with a highlight whose half maximum is at the disc's
// own radius r (to first order in r), and a lobe much wider than the disc is left as it is.
// The light's irradiance is unchanged: the widened lobe spreads the same reflected energy.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_LIGHTING_DISC_LIGHT_HLSL
#define PBR_LIGHTING_DISC_LIGHT_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/lighting/disc_light.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate

// sqrt(sqrt(2) - 1): tan(theta_h) at GGX's half maximum, per unit alpha
#define PBR_GGX_HALF_MAX_TAN_PER_ALPHA 0.6435942529055827

// alpha (GGX, perceptual roughness squared) widened by a disc of angularRadius (radians)
float pbr_disc_light_alpha(float alpha, float angularRadius) {
    float disc = angularRadius / (2.0 * PBR_GGX_HALF_MAX_TAN_PER_ALPHA);
    return min(sqrt(alpha * alpha + disc * disc), 1.0);
}

#endif // PBR_LIGHTING_DISC_LIGHT_HLSL
