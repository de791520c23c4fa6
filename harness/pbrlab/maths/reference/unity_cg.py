"""Float64 references of the UnityCG.cginc / UnityStandardUtils.cginc helpers in
glsl/pbr/unity/unity_cg.glsl, written from Unity's formulas (Unity 2018-2019 built-in shader
source: UnpackNormalmapRGorAG, UnpackNormalWithScale, BlendNormals, Luminance,
LinearRgbToLuminance, GammaToLinearSpace, LinearToGammaSpace, DecodeHDR, UnpackNormalDXT5nm,
ParallaxOffset, ComputeGrabScreenPos) and of UnityCG's helpers over Unity's camera globals in
glsl/unity_compat/shader_variables.glsl (UnityPixelSnap, Linear01Depth, LinearEyeDepth with
_ZBufferParams from the planes), independent of the GLSL. Arrays broadcast over leading axes; colours and packed normals in the last axis.
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


def decode_hdr(data, instructions, colorspace_is_gamma=False):
    """UnityCG.cginc's DecodeHDR: multiplier * alpha^exponent * rgb, alpha = 1 + use_alpha *
    (a - 1); in a gamma colour space (its three-argument form's flag) the exponent is skipped."""
    d, i = np.asarray(data, np.float64), np.asarray(instructions, np.float64)
    alpha = i[..., 3] * (d[..., 3] - 1.0) + 1.0
    return (i[..., 0] * (alpha if colorspace_is_gamma else alpha ** i[..., 1]))[..., None] * d[..., :3]


def unpack_normal_dxt5nm(packed):
    p = np.asarray(packed, np.float64)
    x, y = p[..., 3] * 2 - 1, p[..., 1] * 2 - 1
    return np.stack([x, y, np.sqrt(1 - np.clip(x * x + y * y, 0, 1))], -1)


def parallax_offset(h, height, view_dir):
    """(h - 1/2) height * v.xy / (v.z + 0.42), v the unit tangent-space view direction."""
    v = np.asarray(view_dir, np.float64)
    v = v / np.linalg.norm(v, axis=-1, keepdims=True)
    shift = (np.asarray(h, np.float64) - 0.5) * np.asarray(height, np.float64)
    return shift[..., None] * v[..., :2] / (v[..., 2:3] + 0.42)


def compute_grab_screen_pos(clip, uv_starts_at_top=False):
    c = np.asarray(clip, np.float64)
    sign = -1.0 if uv_starts_at_top else 1.0
    x = (c[..., 0] + c[..., 3]) / 2
    y = (sign * c[..., 1] + c[..., 3]) / 2
    return np.stack([x, y, c[..., 2], c[..., 3]], -1)


def pixel_snap(clip, width, height):
    """Clip xy moved so that NDC xy lands on a multiple of 2/size (a pixel corner)."""
    c = np.asarray(clip, np.float64)
    half = np.array([width, height], np.float64) / 2
    ndc = c[..., :2] / c[..., 3:4]
    snapped = np.round(ndc * half) / half * c[..., 3:4]  # numpy rounds half to even, as HLSL
    return np.concatenate([snapped, c[..., 2:]], -1)


def zbuffer_params(near, far):
    """_ZBufferParams of a GL (not reversed) depth buffer (UnityShaderVariables.cginc)."""
    x = 1 - far / near
    y = far / near
    return np.array([x, y, x / far, y / far])


def depth_buffer_value(eye_depth, near, far):
    """The [0, 1] depth a GL perspective projection stores for a point at eye_depth:
    (z_ndc + 1) / 2, z_ndc = (far + near) / (far - near) - 2 far near / ((far - near) eye_depth)."""
    d = np.asarray(eye_depth, np.float64)
    z_ndc = (far + near) / (far - near) - 2 * far * near / ((far - near) * d)
    return (z_ndc + 1) / 2


def linear_eye_depth(z, near, far):
    """Inverse of depth_buffer_value: 1/d is affine in z, 1/near at 0 and 1/far at 1."""
    z = np.asarray(z, np.float64)
    return 1 / (z * (1 / far - 1 / near) + 1 / near)


def linear01_depth(z, near, far):
    return linear_eye_depth(z, near, far) / far


def lerp_one_to(b, t):
    """UnityStandardUtils.cginc LerpOneTo(b, t) = 1 - t + b t (LerpWhiteTo: the same per channel)."""
    b, t = np.asarray(b, np.float64), np.asarray(t, np.float64)
    return (1.0 - t) + b * t
