"""Metallic / specular workflows, F0 tables and F0 <-> IOR: glsl/pbr/material/."""

import numpy as np

DIELECTRIC_F0 = 0.04  # PBR_DIELECTRIC_F0: glass, IOR 1.5 (Lagarde 2011; Karis 2013; Unity)

# Lagarde 2011, "Feeding a physically based shading model", as in the lecture's slides
# (PBR_F0_<NAME> in glsl/pbr/material/f0_tables.glsl).
F0_DIELECTRICS = {
    "QUARTZ": 0.045593921,
    "ICE": 0.017908907,
    "WATER": 0.020373188,
    "ALCOHOL": 0.01995505,
    "GLASS": 0.04,
    "MILK": 0.022181983,
    "RUBY": 0.077271957,
    "CRYSTAL": 0.111111111,
    "DIAMOND": 0.171968833,
    "SKIN": 0.028,
}
F0_METALS = {
    "SILVER": (0.971519, 0.959915, 0.915324),
    "ALUMINIUM": (0.913183, 0.921494, 0.924524),
    "GOLD": (1.0, 0.765557, 0.336057),
    "COPPER": (0.955008, 0.637427, 0.538163),
    "CHROMIUM": (0.549585, 0.556114, 0.554256),
    "NICKEL": (0.659777, 0.608679, 0.525649),
    "TITANIUM": (0.541931, 0.496791, 0.449419),
    "COBALT": (0.662124, 0.654864, 0.633732),
    "PLATINUM": (0.672411, 0.637331, 0.585456),
}


def _f(x):
    return np.asarray(x, dtype=np.float64)


def f0_from_metallic(albedo, metallic):
    """lerp(0.04, albedo, metallic)."""
    m = _f(metallic)[..., None]
    return DIELECTRIC_F0 * (1.0 - m) + _f(albedo) * m


def diffuse_from_metallic(albedo, metallic):
    """Unity's form: albedo * (1 - 0.04) * (1 - metallic)."""
    return _f(albedo) * ((1.0 - DIELECTRIC_F0) * (1.0 - _f(metallic)))[..., None]


def f0_from_metallic_dielectric(albedo, metallic, dielectric_f0):
    """pbr_f0_from_metallic_dielectric: lerp(dielectric_f0, albedo, metallic), RGB on the last
    axis (KHR_materials_specular, "Implementation": F0 = lerp(dielectric_f0, baseColor, metallic))."""
    m = _f(metallic)[..., None]
    return _f(dielectric_f0) * (1.0 - m) + _f(albedo) * m


def diffuse_from_metallic_dielectric(albedo, metallic, dielectric_f0):
    """pbr_diffuse_from_metallic_dielectric, pbrlab's energy rule: Unity's metallic diffuse
    albedo (1 - 0.04)(1 - metallic) with 0.04 generalised to the dielectric's monochrome
    reflectivity max(dielectric_f0), as Unity's specular workflow weighs its diffuse
    (EnergyConservationBetweenDiffuseAndSpecular, UNITY_CONSERVE_ENERGY_MONOCHROME):
    albedo (1 - max(dielectric_f0)) (1 - metallic). Equal to diffuse_from_metallic at
    dielectric_f0 = 0.04 and to diffuse_from_specular at metallic = 0."""
    return _f(albedo) * ((1.0 - np.max(_f(dielectric_f0), axis=-1)) * (1.0 - _f(metallic)))[..., None]


def f90_from_metallic(dielectric_f90, metallic):
    """pbr_f90_from_metallic: lerp(dielectric_f90, 1, metallic) (KHR_materials_specular,
    "Implementation": F90 = lerp(dielectric_f90, 1, metallic))."""
    m = _f(metallic)
    return _f(dielectric_f90) * (1.0 - m) + m


def diffuse_from_specular(albedo, specular):
    """Monochrome energy conservation: albedo * (1 - max(specular))."""
    return _f(albedo) * (1.0 - np.max(_f(specular), axis=-1))[..., None]


def diffuse_from_specular_per_channel(albedo, specular):
    return _f(albedo) * (1.0 - _f(specular))


def f0_from_ior(eta):
    eta = _f(eta)
    return ((eta - 1.0) / (eta + 1.0)) ** 2


def ior_from_f0(f0):
    s = np.sqrt(_f(f0))
    return (1.0 + s) / (1.0 - s)
