"""What an object shows in the camera's depth texture and G-buffer (Unity's deferred path), and
which shader names read those textures.

A material source may answer ``gbuffer_surface(material)``: a ``GBufferSurface`` (the object is
in the depth pre-pass and the G-buffer with that surface) or None (it is not: a blended
material, as Unity keeps transparent queues out of the depth texture). pbrlab's own materials
give their constant values (``standard_surface``); a Unity shader's material gives Unity's
default material (``DEFAULT_STANDARD_SURFACE``: importers/unity/material.py says why).
render/camera_textures.py draws them.

    read_by(program_text)     # the camera textures a program names
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

# The names Unity binds the camera's textures under, as the harness provides them:
# the depth texture (window depth of the nearest opaque surface, GL's [0, 1], far = 1), the
# deferred path's G-buffer RT0..RT2, and the normals buffer its depth-normals combine reads
# (Unity binds the G-buffer's normals RT2 under _CameraNormalsTexture there).
DEPTH_TEXTURE = "_CameraDepthTexture"
GBUFFER_TEXTURES = ("_CameraGBufferTexture0", "_CameraGBufferTexture1", "_CameraGBufferTexture2")
NORMALS_TEXTURE = "_CameraNormalsTexture"
CAMERA_TEXTURES = (DEPTH_TEXTURE, *GBUFFER_TEXTURES, NORMALS_TEXTURE)
# What _CameraNormalsTexture holds for a program, by its material source's ``camera_normals``
# (render/camera_textures.py binds the one named): the built-in deferred path's RT2 (the world
# normal * 0.5 + 0.5, the default) or URP's DepthNormals texture (the world normal itself).
GBUFFER_NORMALS = "gbuffer"
WORLD_NORMALS = "world"
_NAMES = re.compile(r"\b(" + "|".join(CAMERA_TEXTURES) + r")\b")
# UnityStandardConfig / UnityCG.cginc: unity_ColorSpaceDielectricSpec in linear colour space
# (rgb 0.04: the F0 of a dielectric of index 1.5; a = 1 - 0.04).
DIELECTRIC_SPEC = 0.04


def read_by(program: str) -> frozenset:
    """The camera textures ``program`` (a pass's Cg text, with the includes it names) reads."""
    names = set(_NAMES.findall(program))
    if re.search(r'#\s*include\s+"UnityDeferredLibrary\.cginc"', program):
        names.add(DEPTH_TEXTURE)  # the library reads it for its shaders
    return frozenset(names)


@dataclass(frozen=True)
class GBufferSurface:
    """An object's surface in Unity's G-buffer layout (UnityGBuffer.cginc, fragDeferred):
    diffuse colour and occlusion (RT0), specular colour and smoothness (RT1), all linear."""
    diffuse: tuple
    occlusion: float
    specular: tuple
    smoothness: float


def metallic_surface(albedo, metallic: float, smoothness: float, occlusion: float = 1.0) -> GBufferSurface:
    """Unity's DiffuseAndSpecularFromMetallic (UnityStandardUtils.cginc): specular colour
    lerp(0.04, albedo, metallic), diffuse colour albedo (1 - 0.04) (1 - metallic)."""
    albedo = np.asarray(albedo, np.float64)[:3]
    specular = DIELECTRIC_SPEC + (albedo - DIELECTRIC_SPEC) * metallic
    diffuse = albedo * (1.0 - DIELECTRIC_SPEC) * (1.0 - metallic)
    return GBufferSurface(tuple(diffuse), float(occlusion), tuple(specular), float(smoothness))


def specular_surface(albedo, specular, smoothness: float, occlusion: float = 1.0) -> GBufferSurface:
    """Unity's EnergyConservationBetweenDiffuseAndSpecular, monochrome (UnityStandardUtils.cginc,
    UNITY_CONSERVE_ENERGY_MONOCHROME): diffuse colour albedo (1 - max(specular))."""
    albedo = np.asarray(albedo, np.float64)[:3]
    specular = np.asarray(specular, np.float64)[:3]
    return GBufferSurface(tuple(albedo * (1.0 - specular.max())), float(occlusion), tuple(specular),
                          float(smoothness))


# Unity's Default-Material (the material a new object gets): the Standard shader with
# _Color white, _Metallic 0, _Glossiness 0.5, occlusion 1.
DEFAULT_STANDARD_SURFACE = metallic_surface((1.0, 1.0, 1.0), 0.0, 0.5)
