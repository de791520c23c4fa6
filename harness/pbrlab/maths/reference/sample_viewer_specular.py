"""The Khronos glTF Sample Renderer's environment Fresnel (npm @khronosgroup/gltf-viewer 1.1.0,
the version tools/sample_viewer pins) in float64: not pbrlab's shading, but the formula the
agreement check names where the two renderers weigh a constant environment differently,
transcribed from the viewer's shaders (ibl.glsl getIBLGGXFresnel; material_info.glsl
getIorInfo, getSpecularInfo; pbr.frag's image-based block). Colours on the last axis.

The viewer's dielectric (material_info.glsl): KHR_materials_ior gives
    f0_dielectric  = ((ior - 1) / (ior + 1))^2                       (getIorInfo; 0.04 without it)
and KHR_materials_specular
    f0_dielectric  = min(f0_dielectric x specularColorFactor x specularColorTexture.rgb, 1)
    specularWeight = specularFactor x specularTexture.a              (getSpecularInfo; 1 without it)
so the strength is not folded into F0 as the extension's README writes dielectric_f0
(reference/specular_extension.py): it scales the whole environment Fresnel instead.

getIBLGGXFresnel (ibl.glsl) is Fdez-Agüera 2019 ("A Multiple-Scattering Microfacet Model for
Real-Time Image-based Lighting", JCGT 8(1), 45-55: section 2's E_ms = 1 - E_ss, section 3's
series over the average Fresnel, and its listing's roughness-dependent Fresnel), for
perceptual roughness r and the split-sum terms (A, B) of the viewer's GGX table at (n·v, r):
    Fr       = max(1 - r, F0) - F0
    k_S      = F0 + Fr (1 - n·v)^5            (the Schlick weight's F90 is max(1 - r, F0), not 1)
    FssEss   = w (k_S A + B)                  (single scattering; w = specularWeight)
    Ems      = 1 - (A + B)                    (the energy single scattering misses)
    F_avg    = w (F0 + (1 - F0) / 21)         (Schlick's F averaged over the hemisphere)
    FmsEms   = Ems FssEss F_avg / (1 - F_avg Ems)
    E        = FssEss + FmsEms
pbrlab's is the integral of Schlick's F, F0 A + F90 B with F90 = specularFactor (or
pbr_f90_from_f0), times Fdez-Agüera's compensation 1 + F0 (1/(A+B) - 1): at roughness 0 the
viewer's k_S A adds w (1 - F0)(1 - n·v)^5 A, largest at the rims.

pbr.frag then mixes (no transmission, sheen, coat, film; occlusion 1):
    f_diffuse  = getDiffuseLight(n) x baseColor          (the Lambertian-filtered environment)
    dielectric = mix(f_diffuse, f_specular, E(f0_dielectric, specularWeight))
    metal      = E(baseColor, 1) x f_specular
    colour     = mix(dielectric, metal, metallic)
The viewer's (A, B) come from its own table, sampled bilinearly at texel centres (render.mjs
lowers its size to LUT_RESOLUTION); here they are the float64 integral of
reference/directional_albedo.py at max(r, the table's first row), the roughness the viewer
reads for r below it (CLAMP_TO_EDGE).
"""

from __future__ import annotations

import numpy as np

from . import directional_albedo

LUT_RESOLUTION = 128  # tools/sample_viewer/render.mjs: "this.lutResolution = 128;"
LUT_FIRST_ROW_ROUGHNESS = 0.5 / LUT_RESOLUTION  # the table's first texel centre (perceptual roughness)


def _f(x):
    return np.asarray(x, np.float64)


def dielectric_f0(ior, specular_color=1.0):
    """f0_dielectric: min(((ior - 1) / (ior + 1))^2 x specularColor, 1) (getIorInfo, getSpecularInfo)."""
    return np.minimum(((_f(ior) - 1.0) / (_f(ior) + 1.0)) ** 2 * _f(specular_color), 1.0)


def split_sum_terms(NdotV, perceptual_roughness):
    """(A, B) on the last axis where the viewer reads its GGX table: the float64 integral at
    alpha = max(r, LUT_FIRST_ROW_ROUGHNESS)^2."""
    r = max(float(perceptual_roughness), LUT_FIRST_ROW_ROUGHNESS)
    return directional_albedo.split_sum_terms_at_alpha(np.clip(_f(NdotV), 0.0, 1.0), r * r)


def ibl_ggx_fresnel(NdotV, perceptual_roughness, f0, specular_weight=1.0):
    """getIBLGGXFresnel(n, v, r, F0, specularWeight): the fraction of the prefiltered
    environment the lobe reflects, single plus multiple scattering. f0 a scalar or a colour
    (then the result has its last axis); NdotV: any shape."""
    A, B = np.moveaxis(split_sum_terms(NdotV, perceptual_roughness), -1, 0)
    f0 = _f(f0)
    if f0.ndim:  # a colour: the per-pixel terms get its axis
        A, B, NdotV = A[..., None], B[..., None], _f(NdotV)[..., None]
    w = _f(specular_weight)
    fr = np.maximum(1.0 - float(perceptual_roughness), f0) - f0
    k_s = f0 + fr * (1.0 - np.clip(_f(NdotV), 0.0, 1.0)) ** 5
    fss_ess = w * (k_s * A + B)
    e_ms = 1.0 - (A + B)
    f_avg = w * (f0 + (1.0 - f0) / 21.0)
    return fss_ess + e_ms * fss_ess * f_avg / (1.0 - f_avg * e_ms)


def environment_radiance(NdotV, perceptual_roughness, base_color, metallic, f0_dielectric, specular_weight,
                         diffuse_radiance, specular_radiance):
    """pbr.frag's image-based colour (no transmission, sheen, coat or film):
    mix(mix(diffuse_radiance x baseColor, specular_radiance, E_dielectric),
        E(baseColor, 1) x specular_radiance, metallic).
    diffuse_radiance: getDiffuseLight(n), the Lambertian-filtered environment (a constant
    sky's radiance); specular_radiance: getIBLRadianceGGX, the prefiltered one. [..., 3]."""
    base = _f(base_color)
    e_dielectric = ibl_ggx_fresnel(NdotV, perceptual_roughness, np.broadcast_to(_f(f0_dielectric), base.shape[-1:]),
                                   specular_weight)
    e_metal = ibl_ggx_fresnel(NdotV, perceptual_roughness, np.broadcast_to(base, e_dielectric.shape))
    dielectric = _f(diffuse_radiance) * base * (1.0 - e_dielectric) + _f(specular_radiance) * e_dielectric
    metal = e_metal * _f(specular_radiance)
    m = _f(metallic)
    return dielectric * (1.0 - m) + metal * m
