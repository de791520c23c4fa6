"""Float64 references of the UnityCG.cginc / UnityStandardUtils.cginc helpers in
glsl/pbr/unity/unity_cg.glsl, written from Unity's formulas (Unity 2018-2019 built-in shader
source: UnpackNormalmapRGorAG, UnpackNormalWithScale, BlendNormals, Luminance,
LinearRgbToLuminance, GammaToLinearSpace, LinearToGammaSpace, DecodeHDR), independent of the
GLSL. Arrays broadcast over leading axes; colours and packed normals in the last axis.
"""

from __future__ import annotations

import numpy as np

# unity_ColorSpaceLuminance, linear colour space (UnityCG.cginc)
LUMINANCE_WEIGHTS = np.array([0.0396819152, 0.458021790, 0.00609653955])
REC709_LUMINANCE = np.array([0.2126729, 0.7151522, 0.0721750])


def unpack_normalmap_rg_or_ag(packed):
    p = np.asarray(packed, np.float64)
    x = p[..., 0] * p[..., 3] * 2 - 1
    y = p[..., 1] * 2 - 1
    z = np.sqrt(1 - np.clip(x * x + y * y, 0, 1))
    return np.stack([x, y, z], -1)


def unpack_normal_with_scale(packed, scale):
    p = np.asarray(packed, np.float64)
    x = (p[..., 0] * p[..., 3] * 2 - 1) * scale
    y = (p[..., 1] * 2 - 1) * scale
    z = np.sqrt(1 - np.clip(x * x + y * y, 0, 1))
    return np.stack([x, y, z], -1)


def blend_normals(n1, n2):
    n1, n2 = np.asarray(n1, np.float64), np.asarray(n2, np.float64)
    v = np.concatenate([n1[..., :2] + n2[..., :2], n1[..., 2:3] * n2[..., 2:3]], -1)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def luminance(rgb):
    return np.asarray(rgb, np.float64) @ LUMINANCE_WEIGHTS


def linear_rgb_to_luminance(rgb):
    return np.asarray(rgb, np.float64) @ REC709_LUMINANCE


def gamma_to_linear_space(srgb):
    c = np.asarray(srgb, np.float64)
    return c * (c * (c * 0.305306011 + 0.682171111) + 0.012522878)


def linear_to_gamma_space(lin):
    c = np.maximum(np.asarray(lin, np.float64), 0.0)
    return np.maximum(1.055 * c ** 0.416666667 - 0.055, 0.0)


def decode_hdr(data, instructions):
    d, i = np.asarray(data, np.float64), np.asarray(instructions, np.float64)
    alpha = i[..., 3] * (d[..., 3] - 1.0) + 1.0
    return (i[..., 0] * alpha ** i[..., 1])[..., None] * d[..., :3]
