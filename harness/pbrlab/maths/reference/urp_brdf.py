"""Float64 transcription of the Universal Render Pipeline's physically based model (URP 12,
Unity 2021 LTS): the BRDF setup (BRDF.hlsl's InitializeBRDFData, metallic and specular
workflows), the direct lobe (DirectBRDFSpecular and LightingPhysicallyBased), the environment
BRDF (EnvironmentBRDFSpecular, GlobalIllumination) and the lit pixel (UniversalFragmentPBR),
written from Unity's documentation and talk of the model (Unity, "Optimizing PBR for Mobile",
SIGGRAPH 2015 course: the D * V * F fold r^2 / (d^2 max(0.1, LdotH^2) (4r + 2)); URP's
manual for the surface inputs) — URP's source is under the Unity Companion License and is not
copied. This is the independent side of tests/importers/urp/: the stand-in Lighting.hlsl
(harness/pbrlab/importers/unity/package_stand_ins/) is checked against it, not the reverse.

Constants as URP has them: kDielectricSpec = (0.04, 0.04, 0.04, 1 - 0.04); roughness floored
at HALF_MIN_SQRT = 2^-7 and its square at HALF_MIN = 2^-14 (the smallest normal half); the
1.00001 in d and the 0.1 floor of LdotH^2 are the model's own. Vectors carry xyz on the last
axis; scalars broadcast.
"""

from __future__ import annotations

import numpy as np

DIELECTRIC_F0 = 0.04
HALF_MIN = 6.103515625e-5
HALF_MIN_SQRT = 0.0078125


def _dot(a, b):
    return np.sum(np.asarray(a, np.float64) * np.asarray(b, np.float64), axis=-1)


def _normalize(v):
    v = np.asarray(v, np.float64)
    return v / np.sqrt(np.maximum(_dot(v, v), np.finfo(np.float32).tiny))[..., None]


def brdf_data(albedo, metallic, smoothness, specular=None):
    """URP's BRDFData: (diffuse, f0, roughness2, normalization, grazing, perceptualRoughness).
    ``specular`` given: the specular workflow (F0 = specular, diffuse = albedo (1 - specular),
    reflectivity its largest channel); else the metallic one (F0 = lerp(0.04, albedo, metallic),
    diffuse = albedo (0.96 - 0.96 metallic), reflectivity 1 - that factor)."""
    albedo = np.asarray(albedo, np.float64)
    metallic = np.asarray(metallic, np.float64)
    smoothness = np.asarray(smoothness, np.float64)
    if specular is None:
        one_minus_reflectivity = (1.0 - DIELECTRIC_F0) - metallic * (1.0 - DIELECTRIC_F0)
        reflectivity = 1.0 - one_minus_reflectivity
        diffuse = albedo * one_minus_reflectivity[..., None]
        f0 = DIELECTRIC_F0 + (albedo - DIELECTRIC_F0) * metallic[..., None]
    else:
        specular = np.asarray(specular, np.float64)
        reflectivity = np.max(specular, axis=-1)
        diffuse = albedo * (1.0 - specular)
        f0 = specular
    perceptual_roughness = 1.0 - smoothness
    roughness = np.maximum(perceptual_roughness ** 2, HALF_MIN_SQRT)
    roughness2 = np.maximum(roughness ** 2, HALF_MIN)
    return {"diffuse": diffuse, "f0": f0, "roughness2": roughness2, "normalization": roughness * 4.0 + 2.0,
            "grazing": np.clip(smoothness + reflectivity, 0.0, 1.0), "perceptual_roughness": perceptual_roughness}


def direct_specular(data, n, l, v):
    """DirectBRDFSpecular: roughness2 / (d^2 max(0.1, LdotH^2) (4 roughness + 2)), with
    d = NdotH^2 (roughness2 - 1) + 1.00001 (the specular term before F0 and the light)."""
    h = _normalize(np.asarray(l, np.float64) + np.asarray(v, np.float64))
    NoH = np.clip(_dot(n, h), 0.0, 1.0)
    LoH = np.clip(_dot(l, h), 0.0, 1.0)
    d = NoH * NoH * (data["roughness2"] - 1.0) + 1.00001
    return data["roughness2"] / ((d * d) * np.maximum(0.1, LoH * LoH) * data["normalization"])


def direct_light(data, n, l, v, light_color, attenuation=1.0):
    """LightingPhysicallyBased: (diffuse + f0 DirectBRDFSpecular) light_color attenuation NdotL."""
    NdotL = np.clip(_dot(n, l), 0.0, 1.0)
    radiance = np.asarray(light_color, np.float64) * (np.asarray(attenuation, np.float64) * NdotL)[..., None]
    brdf = data["diffuse"] + data["f0"] * direct_specular(data, n, l, v)[..., None]
    return brdf * radiance


def environment_specular(data, NoV):
    """EnvironmentBRDFSpecular: lerp(f0, grazing, (1 - NoV)^4) / (roughness2 + 1)."""
    fresnel = (1.0 - np.clip(NoV, 0.0, 1.0)) ** 4
    f = data["f0"] + (data["grazing"][..., None] - data["f0"]) * fresnel[..., None]
    return f / (data["roughness2"] + 1.0)[..., None]


def global_illumination(data, baked_gi, reflected, occlusion, n, v):
    """GlobalIllumination: (bakedGI diffuse + reflected EnvironmentBRDFSpecular) occlusion;
    ``reflected`` is the environment's radiance along reflect(-v, n) at URP's mip."""
    NoV = _dot(n, v)
    c = np.asarray(baked_gi, np.float64) * data["diffuse"] + np.asarray(reflected, np.float64) * environment_specular(data, NoV)
    return c * np.asarray(occlusion, np.float64)[..., None]


def blinn_phong_light(albedo, specular, smoothness, n, l, v, light_color, attenuation=1.0, highlights=True):
    """SimpleLit's light (URP's CalculateBlinnPhong): Lambert's light_color attenuation NdotL
    times the albedo, plus, where the material has highlights (_SPECULAR_COLOR or
    _SPECGLOSSMAP), light_color attenuation specular NdotH^exponent with the exponent
    exp2(10 smoothness + 1) and h = normalize(l + v)."""
    color = np.asarray(light_color, np.float64) * np.asarray(attenuation, np.float64)[..., None]
    NdotL = np.clip(_dot(n, l), 0.0, 1.0)
    out = color * NdotL[..., None] * np.asarray(albedo, np.float64)
    if highlights:
        h = _normalize(np.asarray(l, np.float64) + np.asarray(v, np.float64))
        NdotH = np.clip(_dot(n, h), 0.0, 1.0)
        exponent = np.exp2(10.0 * np.asarray(smoothness, np.float64) + 1.0)
        out = out + color * np.asarray(specular, np.float64) * (NdotH ** exponent)[..., None]
    return out
