"""The Khronos glTF Sample Renderer's transmission (npm @khronosgroup/gltf-viewer 1.1.0, the
version tools/sample_viewer pins) in float64: not pbrlab's shading, but the formulas the
agreement check (tests/importers/gltf/test_sample_viewer_agreement.py) names where the two renderers
differ, transcribed from the viewer's shaders (pbr.frag, punctual.glsl, ibl.glsl,
functions.glsl) so that each difference can be measured term by term. For a dielectric base
(metallic 0) without clear coat, sheen, film or KHR_materials_specular; f90 = 1; light and
environment radiance in the viewer's units (pbrlab's light radiance times pi).

Where they differ from KHR_materials_transmission (its "Transmission BTDF": specular_btdf(α =
roughness²), a BTDF, so light from the side of the surface opposite the view, weighted by
|n·l| like every light in the rendering integral) and from pbrlab
(pbr/shading/transmission.glsl, pbr/surface/lighting_transmission.glsl):
* punctual (punctual_transmission): the lobe is evaluated for every light, also one in front
  of the surface (no n·l < 0 test; n·l' is clamped to 0, where the viewer's V_GGX is still
  0.5 / (n·v α), not 0), without the |n·l| factor, weighted (1 - F(v·h')) inside and (1 -
  F(v·h)) again by the base's Fresnel mix; its roughness is α · clamp(2 ior - 2, 0, 1)
  (ior_scaled_roughness: the viewer's applyIorToRoughness, "so that an IOR of 1.0 results in
  no microfacet refraction"; the extension's normative text keeps α = roughness² and says
  only, non-normatively, that the blur "will be modulated by the material's index of
  refraction"); a volume's light direction is bent by the transmission ray (pointToLight -
  thickness · scale · refract(-v, n, 1/ior)) and attenuated over that ray;
* image-based (ibl_transmission): the copy behind the surface is weighted by 1 - (F0 A + B)
  (getIBLVolumeRefraction) and then by 1 - E_ms once more (the base's mix with the specular
  by getIBLGGXFresnel, its multiple-scattering Fresnel: reference/sample_viewer_specular.py),
  the Fresnel twice where pbrlab
  weighs once (rho (1 - E)).
A, B: the split-sum terms at the viewer's (n·v, perceptual roughness), here the float64
integral of reference/directional_albedo.py where the viewer reads its own GGX table
(sample_viewer_specular.split_sum_terms).
"""

import numpy as np

from . import brdf
from .sample_viewer_specular import ibl_ggx_fresnel, split_sum_terms

PI = np.pi


def _f(x):
    return np.asarray(x, np.float64)


def _dot(a, b):
    return np.sum(_f(a) * _f(b), axis=-1)


def _normalize(x):
    x = _f(x)
    return x / np.linalg.norm(x, axis=-1, keepdims=True)


def dielectric_f0(ior):
    """KHR_materials_ior: ((ior - 1) / (ior + 1))^2 (the viewer's f0_dielectric)."""
    return ((ior - 1.0) / (ior + 1.0)) ** 2


def ior_scaled_roughness(roughness, ior):
    """functions.glsl applyIorToRoughness: roughness · clamp(2 ior - 2, 0, 1) (1 at ior >= 1.5)."""
    return _f(roughness) * np.clip(2.0 * ior - 2.0, 0.0, 1.0)


def _V_GGX(NdotL, NdotV, alpha):
    """brdf.glsl V_GGX (height-correlated Smith over 4 n·l n·v), with its guard: 0 where
    its denominator is 0. At n·l = 0 it is 0.5 / (n·v α), not 0."""
    a2 = _f(alpha) ** 2
    NdotL, NdotV = _f(NdotL), _f(NdotV)
    ggx = NdotL * np.sqrt(NdotV ** 2 * (1 - a2) + a2) + NdotV * np.sqrt(NdotL ** 2 * (1 - a2) + a2)
    with np.errstate(divide="ignore"):
        return np.where(ggx > 0.0, 0.5 / np.where(ggx > 0.0, ggx, 1.0), 0.0)


def transmission_ray(n, v, thickness, ior, scale):
    """getVolumeTransmissionRay: normalize(refract(-v, n, 1/ior)) · thickness · scale (0 for a
    thin wall, thickness 0)."""
    n, v = _f(n), _f(v)
    eta = 1.0 / ior
    cos_i = _dot(n, v)
    k = 1.0 - eta ** 2 * (1.0 - cos_i ** 2)
    refracted = np.where((k >= 0)[..., None], -eta * v + (eta * cos_i - np.sqrt(np.maximum(k, 0.0)))[..., None] * n, 0.0)
    with np.errstate(invalid="ignore"):
        direction = np.nan_to_num(_normalize(refracted))
    return direction * thickness * scale


def punctual_transmission(n, v, point_to_light, intensity, base_color, perceptual_roughness, ior,
                          thickness=0.0, scale=1.0, attenuation_color=(1.0, 1.0, 1.0),
                          attenuation_distance=np.inf):
    """What one light adds through the surface at transmission 1 (pbr.frag's light loop, the
    transmission's share of l_diffuse after mix(l_diffuse, l_specular, F(v·h))):
        (1 - F(v·h)) · intensity · getPunctualRadianceTransmission(n, v, l') · T(|ray|)
    point_to_light: the light's position minus the point (a directional light: -direction);
    intensity: the radiance arriving there, in the viewer's units (getLighIntensity, from the
    unbent direction)."""
    n, v = _normalize(n), _normalize(v)
    f0 = dielectric_f0(ior)
    l = _normalize(point_to_light)
    h = _normalize(l + v)
    fresnel = brdf.F_Schlick(f0, np.abs(np.clip(_dot(v, h), 0.0, 1.0)))
    ray = transmission_ray(n, v, thickness, ior, scale)
    l_bent = _normalize(_f(point_to_light) - ray)
    # punctual.glsl getPunctualRadianceTransmission
    alpha = ior_scaled_roughness(perceptual_roughness ** 2, ior)
    l_mirror = _normalize(l_bent + 2.0 * n * _dot(-l_bent, n)[..., None])
    h_mirror = _normalize(l_mirror + v)
    D = brdf.D_GGX(np.clip(_dot(n, h_mirror), 0.0, 1.0), alpha)
    F = brdf.F_Schlick(f0, np.clip(_dot(v, h_mirror), 0.0, 1.0))
    Vis = _V_GGX(np.clip(_dot(n, l_mirror), 0.0, 1.0), np.clip(_dot(n, v), 0.0, 1.0), alpha)
    lobe = ((1.0 - F) * D * Vis)[..., None] * _f(base_color)
    attenuation = _f(attenuation_color) ** (np.linalg.norm(ray, axis=-1, keepdims=True) / attenuation_distance)
    return (1.0 - fresnel)[..., None] * _f(intensity) * lobe * attenuation


def ibl_transmission(n, v, behind, base_color, perceptual_roughness, ior, thickness=0.0, scale=1.0,
                     attenuation_color=(1.0, 1.0, 1.0), attenuation_distance=np.inf):
    """What the radiance seen through the surface (``behind``, the viewer's copy there)
    adds at transmission 1: getIBLVolumeRefraction, (1 - (f0 A + B)) · base · T(|ray|) ·
    behind, then weighted by 1 - E_ms in mix(f_diffuse, f_specular, getIBLGGXFresnel)."""
    NdotV = np.clip(_dot(_normalize(n), _normalize(v)), 0.0, 1.0)
    f0 = dielectric_f0(ior)
    A, B = np.moveaxis(split_sum_terms(NdotV, perceptual_roughness), -1, 0)
    ray = transmission_ray(n, v, thickness, ior, scale)
    attenuation = _f(attenuation_color) ** (np.linalg.norm(ray, axis=-1, keepdims=True) / attenuation_distance)
    refraction = (1.0 - (f0 * A + B))[..., None] * attenuation * _f(base_color) * _f(behind)
    return (1.0 - ibl_ggx_fresnel(NdotV, perceptual_roughness, f0))[..., None] * refraction
