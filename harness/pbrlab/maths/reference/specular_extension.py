"""Float64 reference of KHR_materials_specular's dielectric, written from the specification.

Khronos, "KHR_materials_specular" (ratified; extensions/2.0/Khronos/KHR_materials_specular/
README.md in KhronosGroup/glTF), section "Implementation" and "Interaction with other
extensions" (KHR_materials_ior):

    specular      = specularFactor x specularTexture.a
    specularColor = specularColorFactor x specularColorTexture.rgb (decoded from sRGB)
    dielectric_f0  = min(((ior - 1) / (ior + 1))^2 x specularColor, 1) x specular
    dielectric_f90 = specular
    dielectric_fresnel = mix(dielectric_f0, dielectric_f90, (1 - |VdotH|)^5)

(the clamp applies to the product of the IOR's F0 and the colour, before the strength). The
specular lobe is dielectric_fresnel x specular_brdf, glTF 2.0's specular_brdf (Appendix B):
D_GGX x V_GGX (Heitz's height-correlated Smith, Walter et al. 2007's GGX, alpha =
roughness^2). Its directional albedo under a uniform environment is the integral of
Schlick's F against that lobe, linear in F0 and F90:

    E(NdotV) = F0 A + F90 B     (Karis 2013, eq. 8; A and B as directional_albedo.py defines
                                 them, integrated here by its own quadrature)

so F90 < 1 can only lower the albedo below A + B <= 1: the white furnace cannot exceed 1.

On a metallic material the same section mixes the dielectric with the metal:

    F0  = lerp(dielectric_f0, baseColor.rgb, metallic)
    F90 = lerp(dielectric_f90, 1, metallic)

and weighs the diffuse c_diff = lerp(baseColor.rgb, 0, metallic) by 1 - F per channel, F
Schlick's at the light's VdotH. The Khronos Sample Renderer (gltf-viewer 1.1.0) does the
same per light, mix(diffuse, specular_dielectric, F_Schlick(dielectric_f0, dielectric_f90,
VdotH)), and for the environment the roughness-dependent getIBLGGXFresnel; pbrlab keeps
Unity's constant weight 1 - max(dielectric_f0) (reference/material.py,
diffuse_from_metallic_dielectric) and couples the diffuse to the dielectric's directional
albedo 1 - E (pbr/shading/energy_conservation.glsl): the named difference in docs/gltf.md.

With the layers that change the base (each extension's own text, and the Khronos glTF Sample
Renderer where the text leaves the combination open):

* KHR_materials_anisotropy ("Implementation"): the specular_brdf's D and V become the
  anisotropic ones; the Fresnel above is unchanged (the Sample Renderer's dielectric_fresnel
  F_Schlick(f0 x specularWeight, specularWeight, VdotH) multiplies whichever lobe it computed):
  ``anisotropic_lobe``.
* KHR_materials_iridescence: the film's Fresnel F_iridescence replaces Schlick's by
  mix(F_schlick, F_iridescence, iridescence) over the dielectric's F0 (its base IOR from the
  dielectric's own F0: the Sample Renderer's evalIridescence(1, iridescenceIor, NdotV,
  thickness, f0_dielectric)), and the specular weight scales the result (the Sample Renderer's
  2023 release: specularWeight x mix(F_Schlick(f0, f90, VdotH), iridescenceFresnel,
  iridescenceFactor) in BRDF_specularGGXIridescence and getIBLRadianceGGXIridescence):
  ``iridescent_f0_f90``, pbrlab's fold of that Fresnel at the view into an F0 with F90 =
  specular (glsl/pbr/surface/lighting_iridescence.glsl).
* KHR_materials_transmission: the specular_btdf takes part of the diffuse's place inside the
  same fresnel_mix, so the transmission is weighted by 1 - specular x F like the diffuse (the
  extension's "Transmission BTDF" layering; reference/surface.py lighting_transmission with
  coat_f90).

These functions take the extension's parameters, not pbrlab's: pbrlab's library and harness
(pbr_*_f90, reference/shading.py, reference/surface.py, reference/material.py) are tested
against them.
"""

from __future__ import annotations

import numpy as np

from . import directional_albedo


def _f(x):
    return np.asarray(x, np.float64)


def f0_from_ior(ior, outside_ior=1.0):
    """KHR_materials_ior: ((ior - outside_ior) / (ior + outside_ior))^2."""
    return ((_f(ior) - outside_ior) / (_f(ior) + outside_ior)) ** 2


def dielectric_f0(ior, specular_color, specular):
    """min(f0_ior x specularColor, 1) x specular (RGB on the last axis)."""
    return np.minimum(f0_from_ior(ior)[..., None] * _f(specular_color), 1.0) * _f(specular)[..., None]


def dielectric_f90(specular):
    """dielectric_f90 = specular, whatever the colour."""
    return _f(specular)


def metallic_f0(dielectric_f0_, base_color, metallic):
    """F0 = lerp(dielectric_f0, baseColor, metallic), RGB on the last axis."""
    t = _f(metallic)[..., None]
    return (1.0 - t) * _f(dielectric_f0_) + t * _f(base_color)


def metallic_f90(dielectric_f90_, metallic):
    """F90 = lerp(dielectric_f90, 1, metallic)."""
    t = _f(metallic)
    return (1.0 - t) * _f(dielectric_f90_) + t


def dielectric_fresnel(f0, f90, VdotH):
    """mix(f0, f90, (1 - |VdotH|)^5), RGB on the last axis of f0."""
    w = (1.0 - np.abs(_f(VdotH))) ** 5
    return _f(f0) * (1.0 - w)[..., None] + _f(f90)[..., None] * w[..., None]


def _ggx_D(NdotH, alpha):
    """Walter et al. 2007, eq. 33: alpha^2 / (pi ((NdotH)^2 (alpha^2 - 1) + 1)^2)."""
    a2 = _f(alpha) ** 2
    return a2 / (np.pi * (_f(NdotH) ** 2 * (a2 - 1.0) + 1.0) ** 2)


def _ggx_V(NdotL, NdotV, alpha):
    """glTF 2.0 Appendix B's V_GGX (Heitz 2014, height-correlated Smith / (4 NdotL NdotV))."""
    a2 = _f(alpha) ** 2
    gl = _f(NdotV) * np.sqrt(_f(NdotL) ** 2 * (1.0 - a2) + a2)
    gv = _f(NdotL) * np.sqrt(_f(NdotV) ** 2 * (1.0 - a2) + a2)
    return 0.5 / (gl + gv)


def specular_lobe(n, v, l, f0, f90, alpha):
    """dielectric_fresnel x D x V (1/sr; no cosine, no light): the extension's specular term
    of one light, for unit n, v, l above the surface (last axis 3)."""
    n, v, l = _f(n), _f(v), _f(l)
    h = l + v
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    NdotL, NdotV = np.sum(n * l, -1), np.sum(n * v, -1)
    NdotH, VdotH = np.sum(n * h, -1), np.sum(v * h, -1)
    F = dielectric_fresnel(f0, np.broadcast_to(_f(f90), NdotL.shape), VdotH)
    return F * (_ggx_D(NdotH, alpha) * _ggx_V(NdotL, NdotV, alpha))[..., None]


def environment_albedo(NdotV, alpha, f0, f90):
    """E = F0 A + F90 B: the lobe's directional albedo at each NdotV (a float64 quadrature of
    the integral, directional_albedo.split_sum_terms), RGB on the last axis."""
    ab = directional_albedo.split_sum_terms_grid(NdotV, alpha)
    return _f(f0) * ab[..., 0:1] + _f(f90)[..., None] * ab[..., 1:2]


def anisotropic_lobe(n, v, l, t, b, f0, f90, alpha, strength):
    """dielectric_fresnel x D_aniso x V_aniso (1/sr) for unit n, v, l above the surface and the
    unit anisotropic frame t, b: KHR_materials_anisotropy's alphaT = mix(alpha, 1, strength^2),
    alphaB = alpha, its D and V (reference/anisotropy.py, written from the extension's
    "Implementation"), under this extension's Fresnel."""
    from . import anisotropy
    n, v, l, t, b = _f(n), _f(v), _f(l), _f(t), _f(b)
    h = l + v
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    at = _f(alpha) + (1.0 - _f(alpha)) * _f(strength) ** 2
    dot = lambda x, y: np.sum(x * y, -1)  # noqa: E731
    D = anisotropy.D_GGX_Anisotropic(dot(n, h), dot(t, h), dot(b, h), at, alpha)
    V = anisotropy.V_SmithGGXCorrelated_Anisotropic(dot(n, l), dot(n, v), dot(t, v), dot(b, v), dot(t, l),
                                                     dot(b, l), at, alpha)
    F = dielectric_fresnel(f0, np.broadcast_to(_f(f90), dot(n, l).shape), dot(v, h))
    return F * (D * V)[..., None]


def iridescent_f0_f90(f0, f90, NdotV, factor, film_ior, thickness_nm):
    """The F0' whose Schlick curve towards F90 passes through the filmed, weighted Fresnel at
    the view: F90 x mix(c, F0_film(c), factor), c = f0 / f90 the dielectric's unit-strength F0
    (f90 = 0: 0), F0_film = the film's F_iridescence(1, film_ior, NdotV, thickness, c)
    (reference/iridescence.py, the extension's formulas) inverted to an F0 with F90 = 1
    (reference/surface.py f0_from_schlick, pbrlab's stated fold). RGB on the last axis."""
    from . import surface
    f0, f90 = _f(f0), _f(f90)
    c = np.clip(f0 / np.where(f90 > 0.0, f90, 1.0)[..., None], 0.0, 1.0)
    return f90[..., None] * surface.iridescent_f0(c, NdotV, factor, film_ior, thickness_nm)


def iridescent_f0_f90_with_coat(f0, f90, coat_f0, coat_f90, NdotV, factor, film_ior, thickness_nm):
    """pbr_iridescent_f0_f90_with_coat: (iridescent_f0_f90 of f0 with f90, of coat_f0 with
    coat_f90), one film for both (reference/surface.py iridescent_f0_with_coat)."""
    from . import surface

    def unit(x, x90):
        x, x90 = _f(x), _f(x90)
        return np.clip(x / np.where(x90 > 0.0, x90, 1.0)[..., None], 0.0, 1.0)
    base, coat = surface.iridescent_f0_with_coat(unit(f0, f90), unit(coat_f0, coat_f90), NdotV, factor, film_ior,
                                                 thickness_nm)
    return _f(f90)[..., None] * base, _f(coat_f90)[..., None] * coat
