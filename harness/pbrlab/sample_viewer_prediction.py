"""The Khronos glTF Sample Renderer's image of a transmissive scene predicted from pbrlab's:
what its transmission formulas (reference/sample_viewer_transmission.py, gltf-viewer 1.1.0)
add to or take from pbrlab's render, per pixel, in float64.

    delta, texture_edges = viewer_minus_pbrlab(scene)
    predicted = ours[..., :3] + delta

Per pixel of a transmissive material (metallic 0, white or coloured base, no coat, sheen or
film), with the geometry the CPU renderer sees (cpu_render.visible_surfaces) and the
material's transmission and thickness textures read at the pixel's texture coordinate
(nearest texel), each named difference is the viewer's term minus pbrlab's (cpu_render's
float64 twin of the shaders), times the pixel's transmission:
  DIFFERENCES[0] "punctual": each light through the surface: the viewer's lobe (for every
      light, also one in front; no |n·l|; the Fresnel twice; roughness scaled by ior; a
      volume's bent light) against pbrlab's (a light behind only: the thin wall's mirrored
      lobe, or Walter's BTDF into a volume);
  DIFFERENCES[1] "second_fresnel": the environment seen through: (1 - E_ms)(1 - (f0 A + B))
      against pbrlab's rho (1 - E);
  DIFFERENCES[2] "specular_albedo": the environment's specular reflection, E_ms (the viewer's
      multiple-scattering Fresnel, its F90 = max(1 - roughness, f0)) against pbrlab's E: on an
      opaque base the diffuse takes up the difference (both reflect all of a white furnace),
      on a transmitting one only the (1 - transmission) share of it does;
  DIFFERENCES[3] "copy_8bit": the viewer's transmission copy is an RGBA8 target, so the
      environment seen through is rounded to 1/255 (linear).
The environment must be constant (scene.environment.color) and nothing opaque may lie
behind a transmissive pixel (the viewer's copy then holds the environment there, as
pbrlab's). ``texture_edges``: the pixels whose 3 x 3 neighbourhood reads more than one value
of a transmission or thickness texture (there both renderers filter, and the nearest texel
read here does not).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .cpu_render import environment_specular_albedo, transmitted_fraction, transmitted_light, visible_surfaces
from .errors import PbrlabError
from .reference import sample_viewer_transmission as viewer

DIFFERENCES = ("punctual", "second_fresnel", "specular_albedo", "copy_8bit")
COPY_LEVELS = 255  # the viewer's transmission copy: RGBA8 (UNSIGNED_BYTE), linear values
# Texture channels: KHR_materials_transmission's factor in R, KHR_materials_volume's thickness in G
TEXTURE_CHANNELS = {"transmission": 0, "thickness": 1}


def _texel(image, uv):
    """The nearest texel of a top-row-first image at pbrlab's texture coordinates (GL's v up,
    glTF's 1 - v), channels / 255; NaN where uv is."""
    pixels = image.pixels()
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


def _one_material(scene, material, n, v, p, differences):
    """The viewer's terms minus pbrlab's at transmission 1, [N, 3]."""
    rough = 1.0 - material.smoothness
    # pbrlab's thickness holds the node's scale already: the viewer's thickness x modelScale
    args = (material.albedo, rough, material.ior, material.thickness, 1.0, material.attenuation_color,
            material.attenuation_distance)
    delta = np.zeros(n.shape)
    if "punctual" in differences:
        delta -= transmitted_light(scene, material, n, v, p)
        for to_light, intensity in _lights(scene, p):
            delta += viewer.punctual_transmission(n, v, to_light, intensity, *args)
    if scene.environment is not None:
        sky = np.asarray(scene.environment.color, float) * scene.environment.intensity
        e_ms = viewer.multiple_scattering_fresnel(np.clip(np.sum(n * v, axis=-1), 0.0, 1.0), rough,
                                                  viewer.dielectric_f0(material.ior))[:, None]
        if "second_fresnel" in differences:
            seen = np.round(sky * COPY_LEVELS) / COPY_LEVELS if "copy_8bit" in differences else sky
            delta += viewer.ibl_transmission(n, v, seen, *args) - transmitted_fraction(scene, material, n, v) * sky
        if "specular_albedo" in differences:
            delta += (e_ms - environment_specular_albedo(scene, material, n, v)) * sky
    return delta


def viewer_minus_pbrlab(scene, differences=DIFFERENCES):
    """(HxWx3 float64: the viewer's radiance minus pbrlab's from the named ``differences``,
    0 off transmissive pixels; HxW bool: texture_edges, see the module's doc)."""
    unknown = set(differences) - set(DIFFERENCES)
    if unknown:
        raise ValueError(f"unknown differences {sorted(unknown)}: expected some of {DIFFERENCES}")
    if scene.environment is not None and scene.environment.color is None:
        raise PbrlabError("sample viewer prediction: a constant environment only")
    surfaces = visible_surfaces(scene)
    delta = np.zeros(surfaces["p"].shape)
    edges = np.zeros(surfaces["object"].shape, bool)
    for index, obj in enumerate(scene.objects):
        material = scene.materials[obj.material]
        if material.transmission <= 0.0:
            continue
        # a dielectric: metallic 0 (the importer's KHR_materials_ior gives the specular workflow
        # its F0, ((ior - 1) / (ior + 1))^2, the viewer's f0_dielectric)
        from_ior = material.workflow == "metallic" or np.allclose(material.specular, viewer.dielectric_f0(material.ior))
        if not from_ior or material.metallic > 0.0 or material.clearcoat > 0.0 or max(material.sheen_color) > 0.0 \
                or material.iridescence > 0.0:
            raise PbrlabError(f"sample viewer prediction: material {obj.material}: a transmissive dielectric "
                              "base (F0 from its ior) without a coat, sheen or film only")
        pixels = surfaces["object"] == index
        factor = np.where(pixels, material.transmission, 0.0)
        thickness = np.where(pixels, material.thickness, 0.0)
        for slot, channel in TEXTURE_CHANNELS.items():
            if slot in material.textures:
                values = _texel(material.textures[slot], surfaces["uv"])[..., channel]
                edges |= _varies_nearby(values, pixels)
                (factor if slot == "transmission" else thickness)[pixels] *= values[pixels]
        for value in np.unique(thickness[pixels]):  # one material per thickness read
            chosen = pixels & (thickness == value)
            at = dataclasses.replace(material, transmission=1.0, thickness=float(value))
            delta[chosen] = factor[chosen][:, None] * _one_material(
                scene, at, surfaces["n"][chosen], surfaces["v"][chosen], surfaces["p"][chosen], differences)
    return delta, edges
