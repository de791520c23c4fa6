"""The Khronos glTF Sample Renderer's image predicted from pbrlab's: what its named formula
differences (reference/sample_viewer_transmission.py, reference/sample_viewer_specular.py,
gltf-viewer 1.1.0) add to or take from pbrlab's render, per pixel, in float64.

    delta, texture_edges = viewer_minus_pbrlab(scene)

A diagnostic and the size of a named difference, never a correction: the agreement checks
(tests/importers/gltf/test_sample_viewer_agreement.py, test_khronos_models.py) compare the
two images as rendered and grow the per-pixel bound by the codes ``delta`` moves pbrlab's pixel
by, and report which named difference accounts for each pixel beyond the plain bound.

Per pixel of a material without coat, sheen, film, anisotropy, occlusion or surface
function (a metal in the metallic workflow only), with the geometry the CPU renderer sees
(cpu_render.visible_surfaces) and the material's textures that enter these terms read at
the pixel's texture coordinate (nearest texel, TEXTURE_CHANNELS), each named difference is
the viewer's term minus pbrlab's (cpu_render's float64 twin of the shaders):
  DIFFERENCES[0] "punctual": each light through a transmissive surface: the viewer's lobe
      (for every light, also one in front; no |n·l|; the Fresnel twice; roughness scaled by
      ior; a volume's bent light) against pbrlab's (a light behind only: the thin wall's
      mirrored lobe, or Walter's BTDF into a volume), times the transmission;
  DIFFERENCES[1] "second_fresnel": the environment seen through a transmissive surface:
      (1 - E_ms)(1 - (f0 A + B)) against pbrlab's rho (1 - E), times the transmission;
  DIFFERENCES[2] "environment_fresnel": the constant environment reflected, the viewer's
      mix(mix(L baseColor, L, E_dielectric), E_metal L, metallic), E its getIBLGGXFresnel
      (Fdez-Agüera's single and multiple scattering with the roughness-dependent F90 max(1 -
      roughness, f0); KHR_materials_specular's strength as its specularWeight, the colour in
      f0_dielectric), the diffuse's share (1 - transmission) of it, against pbrlab's coupled
      diffuse plus the split sum F0 A + F90 B, compensated (cpu_render.environment_reflected);
  DIFFERENCES[3] "copy_8bit": the viewer's transmission copy is an RGBA8 target, so the
      environment seen through is rounded to 1/255 (linear).
KHR_materials_sheen has its own entry, viewer_minus_pbrlab_sheen(scene, under_sheen): two
named differences (reference/sample_viewer_sheen.py) applied to pbrlab's render of the light
the sheen scales:
  SHEEN_DIFFERENCES[0] "base_unscaled": the viewer's sheen albedo table reads 0, so its base
      keeps the max3(c) min(E, 1) x under_sheen that pbrlab's scaling takes away;
  SHEEN_DIFFERENCES[1] "environment_ashikhmin": the constant sky's sheen, c x sky x E_A with
      E_A the albedo under Ashikhmin's visibility (the viewer's lut_charlie.b), against
      pbrlab's c x sky x min(E, 1);
both times the viewer's coat weight 1 - clearcoat F_Schlick(0.04, n·v) on a coated material.
The environment must be constant (scene.environment.color) and nothing opaque may lie
behind a transmissive pixel (the viewer's copy then holds the environment there, as
pbrlab's). ``texture_edges``: the pixels whose 3 x 3 neighbourhood reads more than one value
of a texture read here (there both renderers filter, and the nearest texel read here does
not).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..render.cpu_render import (environment_reflected, transmitted_fraction, transmitted_light, visible_surfaces)
from ..foundation.errors import PbrlabError
from ..maths.reference import material as ref_material
from ..maths.reference import remap as ref_remap
from ..maths.reference.guards import MIN_NDOTV
from ..maths.reference import sample_viewer_sheen as viewer_sheen
from ..maths.reference import sample_viewer_specular as viewer_specular
from ..maths.reference import sample_viewer_transmission as viewer
from ..gpu.sheen_table import integrate_sheen_albedo, sample_sheen_lut, sheen_lut
from ..maths.srgb8 import DECODE_TABLE

DIFFERENCES = ("punctual", "second_fresnel", "environment_fresnel", "copy_8bit")
SHEEN_DIFFERENCES = ("base_unscaled", "environment_ashikhmin")
# KHR_materials_sheen's texture slots: the colour (RGB, sRGB) and the roughness (A)
SHEEN_TEXTURE_CHANNELS = {"sheen_color": slice(0, 3), "sheen_roughness": slice(3, 4)}
ASHIKHMIN_GRID = 1e-3  # E_A is integrated once per (n·v, r) rounded to this (|dE_A| < 1e-3 there)
COPY_LEVELS = 255  # the viewer's transmission copy: RGBA8 (UNSIGNED_BYTE), linear values
# The texture slots these terms read and their channels: the base colour (RGB), KHR_materials_
# specular's colour (RGB) and strength (A), KHR_materials_transmission's factor (R) and
# KHR_materials_volume's thickness (G); an emission texture is left alone (both renderers add it)
TEXTURE_CHANNELS = {"albedo": slice(0, 3), "specular_color": slice(0, 3), "specular_strength": slice(3, 4),
                    "transmission": slice(0, 1), "thickness": slice(1, 2)}
IGNORED_TEXTURES = ("emission",)
NO_F90 = -1.0  # _per_pixel's F90 column where the material's F90 follows its F0


def _texel(image, uv):
    """The nearest texel of a top-row-first image at pbrlab's texture coordinates (GL's v up,
    glTF's 1 - v) as RGBA / 255 (grey copied to RGB, alpha 1 where the image has none); NaN
    where uv is."""
    pixels = image.pixels()
    if pixels.ndim == 2:
        pixels = pixels[..., None]
    channels = pixels.shape[-1]
    rgb = pixels[..., :3] if channels >= 3 else np.repeat(pixels[..., :1], 3, axis=-1)
    alpha = pixels[..., channels - 1:] if channels in (2, 4) else np.full(pixels.shape[:2] + (1,), 255)
    pixels = np.concatenate([rgb, alpha], axis=-1)
    height, width = pixels.shape[:2]
    known = np.isfinite(uv).all(axis=-1)
    safe = np.where(known[..., None], uv, 0.0)
    col = np.clip(np.floor(safe[..., 0] * width).astype(int), 0, width - 1)
    row = np.clip(np.floor((1.0 - safe[..., 1]) * height).astype(int), 0, height - 1)
    return np.where(known[..., None], pixels[row, col].astype(np.float64) / 255.0, np.nan)


def _varies_nearby(values, where):
    """Pixels in ``where`` whose 3 x 3 neighbourhood holds another value."""
    varies = np.zeros(values.shape, bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            varies |= np.roll(values, (dy, dx), axis=(0, 1)) != values
    return where & varies


def _lights(scene, p):
    """(point-to-light vectors, radiance arriving in the viewer's units: pbrlab's times pi) per light."""
    for light in scene.lights:
        if light.type == "directional":
            to_light = np.broadcast_to(-np.asarray(light.direction, float), p.shape)
            radiance = np.broadcast_to(light.color * light.intensity, p.shape)
        elif light.type == "point" and not np.isfinite(light.range):
            to_light = np.asarray(light.position, float) - p
            radiance = light.color * light.intensity / np.sum(to_light ** 2, axis=-1, keepdims=True)
        else:
            raise PbrlabError(f"sample viewer prediction: a {light.type} light with range {light.range} "
                              "is not modelled (directional and unbounded point lights are)")
        yield to_light, np.pi * radiance


def _transmission_terms(scene, material, n, v, p, differences):
    """The viewer's transmission terms minus pbrlab's at transmission 1, [N, 3]."""
    rough = 1.0 - material.smoothness
    # pbrlab's thickness holds the node's scale already: the viewer's thickness x modelScale
    args = (material.albedo, rough, material.ior, material.thickness, 1.0, material.attenuation_color,
            material.attenuation_distance)
    delta = np.zeros(n.shape)
    if "punctual" in differences:
        delta -= transmitted_light(scene, material, n, v, p)
        for to_light, intensity in _lights(scene, p):
            delta += viewer.punctual_transmission(n, v, to_light, intensity, *args)
    if scene.environment is not None and "second_fresnel" in differences:
        sky = np.asarray(scene.environment.color, float) * scene.environment.intensity
        seen = np.round(sky * COPY_LEVELS) / COPY_LEVELS if "copy_8bit" in differences else sky
        delta += viewer.ibl_transmission(n, v, seen, *args) - transmitted_fraction(scene, material, n, v) * sky
    return delta


def _viewer_dielectric(material):
    """(f0_dielectric, specularWeight) the viewer reads for pbrlab's material (gltf/materials.py
    _specular's fields): KHR_materials_specular's strength is pbrlab's explicit F90 and the
    viewer's weight (F0 = min(F0_ior x colour, 1) x strength: the viewer's f0_dielectric is F0
    / strength, where pbrlab's clamp does not bind before a colour texture); the specular workflow without it (KHR_materials_ior) has weight 1 and F0 as
    f0_dielectric; the metallic workflow the viewer's 0.04."""
    if material.workflow == "metallic":
        return np.full(3, ref_material.DIELECTRIC_F0), 1.0
    if material.specular_f90 is None:
        return np.asarray(material.specular, float), 1.0
    weight = float(material.specular_f90)
    return (np.asarray(material.specular, float) / weight if weight > 0.0 else np.zeros(3)), weight


def _environment_fresnel(scene, material, n, v):
    """The viewer's image-based colour minus pbrlab's under the constant sky, [N, 3] (the
    light through a transmissive surface left to _transmission_terms)."""
    sky = np.asarray(scene.environment.color, float) * scene.environment.intensity
    NdotV = np.clip(np.sum(n * v, axis=-1), 0.0, 1.0)
    f0_dielectric, weight = _viewer_dielectric(material)
    ours = environment_reflected(scene, material, n, v)
    theirs = viewer_specular.environment_radiance(
        NdotV, 1.0 - material.smoothness, material.albedo, material.metallic, f0_dielectric, weight,
        sky * (1.0 - material.transmission), sky)
    return theirs - ours


def _modelled(name, material):
    """Refuses a material whose viewer formulas these differences do not hold."""
    textures = set(material.textures) - set(IGNORED_TEXTURES)
    if material.clearcoat > 0.0 or max(material.sheen_color) > 0.0 or material.iridescence > 0.0 \
            or material.anisotropy_strength > 0.0 or material.occlusion != 1.0 or material.unlit \
            or material.surface or material.source is not None:
        raise PbrlabError(f"sample viewer prediction: material {name}: a base without a coat, sheen, film, "
                          "anisotropy, occlusion or surface function only")
    if not textures <= set(TEXTURE_CHANNELS):
        raise PbrlabError(f"sample viewer prediction: material {name}: its {sorted(textures - set(TEXTURE_CHANNELS))} "
                          f"textures are not read here (only {sorted(TEXTURE_CHANNELS)})")
    for slot in textures:
        if material.texture_uv_set.get(slot, 0) != 0 or material.texture_transform.get(slot) is not None:
            raise PbrlabError(f"sample viewer prediction: material {name}: its {slot} texture's UV set "
                              "or transform is not modelled (TEXCOORD_0 untransformed only)")
    if material.transmission > 0.0:
        # a dielectric: metallic 0 (the importer's KHR_materials_ior gives the specular workflow
        # its F0, ((ior - 1) / (ior + 1))^2, the viewer's f0_dielectric)
        from_ior = material.workflow == "metallic" or np.allclose(material.specular, viewer.dielectric_f0(material.ior))
        if not from_ior or material.metallic > 0.0:
            raise PbrlabError(f"sample viewer prediction: material {name}: a transmissive dielectric base "
                              "(F0 from its ior) only")
    elif material.metallic > 0.0 and material.workflow != "metallic":
        raise PbrlabError(f"sample viewer prediction: material {name}: a metal in the metallic workflow only")


def _per_pixel(material, pixels, uv, edges):
    """The fields the textures change, [N, 9] at the ``pixels``: albedo (3), specular (3, pbrlab's
    F0: min(F0 x colour, 1) x strength, default_surface.inc), F90 (NO_F90: from F0), transmission,
    thickness; texels read at ``uv`` (nearest), and ``edges`` |= where one varies nearby."""
    count = int(pixels.sum())
    albedo = np.tile(np.asarray(material.albedo, float), (count, 1))
    specular = np.tile(np.asarray(material.specular, float), (count, 1))
    f90 = np.full((count, 1), NO_F90 if material.specular_f90 is None else float(material.specular_f90))
    transmission = np.full((count, 1), float(material.transmission))
    thickness = np.full((count, 1), float(material.thickness))
    for slot in material.textures:
        if slot in IGNORED_TEXTURES:
            continue
        texel = _texel(material.textures[slot], uv)
        for channel in range(4)[TEXTURE_CHANNELS[slot]]:
            edges |= _varies_nearby(texel[..., channel], pixels)
        values = texel[pixels][:, TEXTURE_CHANNELS[slot]]
        if material.texture_srgb.get(slot) and values.shape[-1] == 3:
            values = DECODE_TABLE[np.rint(values * 255).astype(int)]
        if slot == "albedo":
            albedo *= values
        elif slot == "specular_color":
            specular = np.minimum(specular * values, 1.0)
        elif slot == "specular_strength":
            specular *= values
            f90 = np.where(f90 == NO_F90, NO_F90, f90 * values)
        elif slot == "transmission":
            transmission *= values
        else:
            thickness *= values
    return np.concatenate([albedo, specular, f90, transmission, thickness], axis=-1)


def _checked_surfaces(scene, differences, known) -> dict:
    """visible_surfaces(scene), after refusing differences not in ``known`` (a caller's
    mistake: ValueError) and an environment other than a constant colour (PbrlabError)."""
    unknown = set(differences) - set(known)
    if unknown:
        raise ValueError(f"unknown differences {sorted(unknown)}: expected some of {known}")
    if scene.environment is not None and scene.environment.color is None:
        raise PbrlabError("sample viewer prediction: a constant environment only")
    return visible_surfaces(scene)


def viewer_minus_pbrlab(scene, differences=DIFFERENCES):
    """(HxWx3 float64: the viewer's radiance minus pbrlab's from the named ``differences``,
    0 where none applies; HxW bool: texture_edges, see the module's doc)."""
    surfaces = _checked_surfaces(scene, differences, DIFFERENCES)
    delta = np.zeros(surfaces["p"].shape)
    edges = np.zeros(surfaces["object"].shape, bool)
    environment = scene.environment is not None and "environment_fresnel" in differences
    for index, obj in enumerate(scene.objects):
        material = scene.materials[obj.material]
        if material.transmission <= 0.0 and not environment:
            continue
        _modelled(obj.material, material)
        pixels = surfaces["object"] == index
        fields = _per_pixel(material, pixels, surfaces["uv"], edges)
        at_pixels = {key: surfaces[key][pixels] for key in ("n", "v", "p")}
        out = np.zeros(at_pixels["n"].shape)
        values, group = np.unique(fields, axis=0, return_inverse=True)
        for which, row in enumerate(values):  # one material per combination of texels read
            chosen = group.reshape(-1) == which
            at = dataclasses.replace(material, albedo=row[0:3], specular=row[3:6],
                                     specular_f90=None if row[6] == NO_F90 else float(row[6]),
                                     transmission=float(row[7]), thickness=float(row[8]))
            n, v, p = (at_pixels[key][chosen] for key in ("n", "v", "p"))
            if at.transmission > 0.0:
                out[chosen] += at.transmission * _transmission_terms(
                    scene, dataclasses.replace(at, transmission=1.0), n, v, p, differences)
            if environment:
                out[chosen] += _environment_fresnel(scene, at, n, v)
        delta[pixels] = out
    return delta, edges


def _sheen_per_pixel(name, material, pixels, uv):
    """(sheen colour [N, 3], sheen perceptual roughness [N]) at the ``pixels``: the factors times
    the nearest texels at ``uv`` (the colour decoded from sRGB)."""
    colour = np.tile(np.asarray(material.sheen_color, float), (int(pixels.sum()), 1))
    rough = np.full(int(pixels.sum()), float(ref_remap.perceptual_roughness_from_smoothness(material.sheen_smoothness)))
    for slot, channels in SHEEN_TEXTURE_CHANNELS.items():
        if slot not in material.textures:
            continue
        if material.texture_uv_set.get(slot, 0) != 0 or material.texture_transform.get(slot) is not None:
            raise PbrlabError(f"sample viewer prediction: material {name}: its {slot} texture's UV set "
                              "or transform is not modelled (TEXCOORD_0 untransformed only)")
        values = np.nan_to_num(_texel(material.textures[slot], uv)[pixels][:, channels])
        if slot == "sheen_color":
            colour *= DECODE_TABLE[np.rint(values * 255).astype(int)] if material.texture_srgb.get(slot) else values
        else:
            rough *= values[:, 0]
    return colour, rough


def viewer_minus_pbrlab_sheen(scene, under_sheen, differences=SHEEN_DIFFERENCES):
    """HxWx3 float64: the viewer's radiance minus pbrlab's from the named sheen ``differences``
    (module doc), 0 off the sheened materials. ``under_sheen``: pbrlab's linear HxWx3 render of
    ``scene`` with every sheen and coat removed, the light pbrlab's sheen scales."""
    surfaces = _checked_surfaces(scene, differences, SHEEN_DIFFERENCES)
    delta = np.zeros(surfaces["p"].shape)
    table = sheen_lut()
    for index, obj in enumerate(scene.objects):
        material = scene.materials[obj.material]
        if max(material.sheen_color) <= 0.0:
            continue
        pixels = surfaces["object"] == index
        colour, rough = _sheen_per_pixel(obj.material, material, pixels, surfaces["uv"])
        NdotV = np.clip(np.sum(surfaces["n"][pixels] * surfaces["v"][pixels], axis=-1), MIN_NDOTV, 1.0)
        E = np.minimum(sample_sheen_lut(table, NdotV, rough), 1.0)  # pbrlab's E' (PBR_SHEEN_ENERGY_NORMALIZED)
        out = np.zeros(colour.shape)
        if "base_unscaled" in differences:
            pbrlab_scaling = np.clip(1.0 - colour.max(axis=-1) * E, 0.0, 1.0)
            out += (viewer_sheen.base_scaling(colour) - pbrlab_scaling)[:, None] * under_sheen[pixels]
        if scene.environment is not None and "environment_ashikhmin" in differences:
            sky = np.asarray(scene.environment.color, float) * scene.environment.intensity
            grid, inverse = np.unique(np.round(np.stack([NdotV, rough], axis=-1) / ASHIKHMIN_GRID), axis=0,
                                      return_inverse=True)
            ashikhmin = integrate_sheen_albedo(grid[:, 0] * ASHIKHMIN_GRID, grid[:, 1] * ASHIKHMIN_GRID,
                                               "NEUBELT")[inverse.reshape(-1)]
            out += viewer_sheen.environment_sheen(sky, colour, ashikhmin) - sky * colour * E[:, None]
        delta[pixels] = out * viewer_sheen.coat_weight(material.clearcoat, NdotV)[:, None]
    return delta
