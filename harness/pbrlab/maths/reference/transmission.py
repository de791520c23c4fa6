"""Float64 references of pbr/brdf/btdf_walter.glsl and pbr/shading/transmission.glsl: light
through a dielectric interface (KHR_materials_transmission) and through a volume
(KHR_materials_volume).

* The rough dielectric BTDF of Walter, Marschner, Li & Torrance 2007, "Microfacet Models for
  Refraction through Rough Surfaces", eq. 21, with the GGX distribution (eq. 33) and the
  separable Smith masking G = G1(v) G1(l) (eqs. 23, 34), written here from the paper with the
  generalised half vector of eq. 16 and the exact Fresnel of eq. 22 (brdf.F_Dielectric: an
  independent Born & Wolf formulation).
* The thin-walled lobe of KHR_materials_transmission (the extension's "Thin-walled" BTDF,
  as the Khronos sample viewer evaluates it): the reflection lobe D · V about the light
  mirrored through the surface plane, tinted by the base colour.
* Beer-Lambert attenuation of KHR_materials_volume: sigma_t = -ln(attenuationColor) /
  attenuationDistance, T = exp(-sigma_t d).
"""

import numpy as np

from . import brdf

PI = np.pi


def _f(x):
    return np.asarray(x, np.float64)


def _dot(a, b):
    return np.sum(_f(a) * _f(b), axis=-1)


def btdf_walter_ggx(n, v, l, alpha, eta):
    """f_t(l -> v) in 1/sr for light arriving from ``l`` (below the interface, n.l < 0) and
    leaving towards ``v`` (above, n.v > 0); ``eta`` = index on l's side / index on v's side.

    Walter 2007 eq. 21 (i = l, o = v, eta_i / eta_o = eta; both directions point away):
        h  = -(eta l + v) / |eta l + v|, taken on n's side                     (eq. 16)
        ft = |l.h| |v.h| / (|l.n| |v.n|) (1 - F(v.h)) G D / (eta (l.h) + (v.h))^2
    with F the exact dielectric Fresnel for light meeting the microfacet from v's side at
    index ratio eta (equal to F seen from l's side wherever a refracted pair exists), and
    0 where v and l lie on the same side of the microfacet ((l.h)(v.h) >= 0), i.e. no
    refraction joins them."""
    n, v, l, alpha, eta = map(_f, (n, v, l, alpha, eta))
    ht = -(eta[..., None] * l + v)
    length = np.linalg.norm(ht, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        h = ht / length[..., None]
    h = np.where((_dot(h, n) < 0.0)[..., None], -h, h)
    NdotV, NdotL, NdotH = _dot(n, v), _dot(n, l), _dot(n, h)
    VdotH, LdotH = _dot(v, h), _dot(l, h)
    refracts = (VdotH * LdotH < 0.0) & (NdotV > 0.0) & (NdotL < 0.0) & (length > 0.0)
    D = brdf.D_GGX(NdotH, alpha)
    # Smith G1 of each direction about its own side of the macro surface, with the
    # microfacet on the same side of each (Walter eq. 23's chi+ (v.h / v.n))
    G = brdf.G1_SmithGGX(np.abs(NdotV), alpha) * brdf.G1_SmithGGX(np.abs(NdotL), alpha)
    F = brdf.F_Dielectric(np.abs(VdotH), eta)
    with np.errstate(divide="ignore", invalid="ignore"):
        ft = (np.abs(LdotH) * np.abs(VdotH) / (np.abs(NdotL) * np.abs(NdotV))
              * (1.0 - F) * G * D / (eta * LdotH + VdotH) ** 2)
    return np.where(refracts, ft, 0.0)


def transmission_walter_punctual(n, v, l, light_radiance, alpha, eta):
    """The lecture's light units (pbr_shade_punctual): pi C_light f_t |n.l|."""
    ft = btdf_walter_ggx(n, v, l, alpha, eta)
    return PI * _f(light_radiance) * (ft * np.abs(_dot(n, l)))[..., None]


def mirror_through_surface(n, l):
    """l reflected through the surface's plane: l - 2 (n.l) n (a light below seen above)."""
    n, l = _f(n), _f(l)
    return l - 2.0 * _dot(n, l)[..., None] * n


def transmission_thin_punctual(n, v, l, light_radiance, base_color, alpha):
    """KHR_materials_transmission's thin-walled lobe for a light below the surface:
    pi C_light base_color D(h') V(l', v) |n.l|, l' the light mirrored through the plane,
    h' = normalize(l' + v), D GGX, V the height-correlated Smith visibility (Heitz 2014
    eq. 99 over 4 |n.l'| |n.v|); 0 for a light above the surface or a view below it."""
    n, v, l = map(_f, (n, v, l))
    lm = mirror_through_surface(n, l)
    h = lm + v
    with np.errstate(divide="ignore", invalid="ignore"):
        h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    NdotL, NdotV, NdotH = _dot(n, lm), _dot(n, v), _dot(n, h)
    below = (_dot(n, l) < 0.0) & (NdotV > 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        lobe = brdf.D_GGX(NdotH, alpha) * brdf.V_SmithGGXCorrelated(NdotL, NdotV, alpha)
    value = PI * np.where(below, lobe * NdotL, 0.0)
    return _f(light_radiance) * _f(base_color) * value[..., None]


def volume_attenuation(distance, attenuation_color, attenuation_distance):
    """Beer-Lambert over ``distance`` (KHR_materials_volume): attenuation_color ** (d / D).
    An infinite attenuation distance (the extension's default) or d = 0 transmits all; a
    colour channel of 0 absorbs all over any d > 0."""
    d, c, D = _f(distance), _f(attenuation_color), _f(attenuation_distance)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        t = np.where(c > 0.0, np.exp(np.log(np.where(c > 0.0, c, 1.0)) * (d / D)[..., None]), 0.0)
    t = np.where((d[..., None] <= 0.0) | np.isinf(D)[..., None], 1.0, t)
    return t


def refraction_direction(n, v, eta):
    """The direction light from v travels after refracting into a medium of relative index
    eta (Snell's law in vector form, Glassner 1989 / GLSL refract(-v, n, 1 / eta)); eta >= 1
    has no total internal reflection entering."""
    n, v, eta = _f(n), _f(v), _f(eta)
    i = -v
    cos_i = -_dot(n, i)
    k = 1.0 - (1.0 - cos_i ** 2) / eta ** 2
    t = i / eta[..., None] + (cos_i / eta - np.sqrt(np.maximum(k, 0.0)))[..., None] * n
    return np.where((k < 0.0)[..., None], 0.0, t)
