"""Float64 references of Unity's legacy lighting models, written from Unity's Lighting.cginc
(Unity 5-2019: UnityLambertLight, UnityBlinnPhongLight) and the custom models of the Unity
manual's "Surface Shader lighting examples"; independent of the GLSL under test.

Inputs are numpy arrays broadcast together; directions unit length, pointing away from the
surface; ``light`` is the light's colour times intensity (Unity's _LightColor0 / light.color).
"""

from __future__ import annotations

import numpy as np


def _dot(a, b):
    return np.sum(np.asarray(a, np.float64) * np.asarray(b, np.float64), axis=-1, keepdims=True)


def lambert(albedo, n, l, light):
    """UnityLambertLight: albedo * light * max(0, n.l)."""
    return np.asarray(albedo, np.float64) * light * np.maximum(0.0, _dot(n, l))


def blinn_phong(albedo, n, l, v, light, specular, gloss, spec_color):
    """UnityBlinnPhongLight: albedo * light * max(0, n.l) + light * specColor * pow(max(0, n.h), specular * 128) * gloss."""
    h = np.asarray(l, np.float64) + v
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    spec = np.maximum(0.0, _dot(n, h)) ** (specular * 128.0) * gloss
    return lambert(albedo, n, l, light) + light * np.asarray(spec_color, np.float64) * spec


def wrap_lambert(albedo, n, l, light):
    """The manual's WrapLambert: albedo * light * (n.l * 0.5 + 0.5)."""
    return np.asarray(albedo, np.float64) * light * (_dot(n, l) * 0.5 + 0.5)


def simple_specular(albedo, n, l, v, light, power=48.0):
    """The manual's SimpleSpecular: (albedo * light * max(0, n.l) + light * pow(max(0, n.h), 48))."""
    h = np.asarray(l, np.float64) + v
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    return lambert(albedo, n, l, light) + light * np.maximum(0.0, _dot(n, h)) ** power
