"""The scene's environment as a cubemap, for a surface shader's ``samplerCUBE`` / ``texCUBE``
(Unity samples a reflection probe there; the harness's probe is the environment).

Made from the equirectangular radiance image (``environment.environment_image``) by
bilinear resampling at each texel centre's direction, with the face layout of the OpenGL
4.6 specification, table 8.19 (major axis, sc, tc per face); mipmapped.
"""

from __future__ import annotations

import moderngl
import numpy as np

from .environment import environment_image

FACE_SIZE = 128  # texels per face edge: the environments here are 512x256 or smaller


def face_directions(n: int) -> list[np.ndarray]:
    """Unnormalised directions of the n x n texel centres of faces +X, -X, +Y, -Y, +Z, -Z;
    row j is t = (j + 0.5) / n (GL's first row), column i is s."""
    c = (np.arange(n) + 0.5) / n * 2.0 - 1.0
    sc, tc = np.meshgrid(c, c)  # [j, i]
    one = np.ones_like(sc)
    return [np.stack(f, axis=-1) for f in (
        (one, -tc, -sc), (-one, -tc, sc), (sc, one, tc), (sc, -one, -tc), (sc, -tc, one), (-sc, -tc, -one))]


def equirect_lookup(image: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Bilinear sample of a top-row-first equirect image along directions ``d`` (pbr_equirect_uv)."""
    d = d / np.linalg.norm(d, axis=-1, keepdims=True)
    u = np.mod(np.arctan2(d[..., 0], -d[..., 2]) / (2.0 * np.pi), 1.0)
    t = 1.0 - np.arccos(np.clip(d[..., 1], -1.0, 1.0)) / np.pi
    h, w = image.shape[:2]
    x = u * w - 0.5
    y = (1.0 - t) * h - 0.5
    x0 = np.floor(x).astype(int)
    y0 = np.floor(y).astype(int)
    fx, fy = (x - x0)[..., None], (y - y0)[..., None]
    y0c, y1c = np.clip(y0, 0, h - 1), np.clip(y0 + 1, 0, h - 1)
    x0w, x1w = np.mod(x0, w), np.mod(x0 + 1, w)
    top = image[y0c, x0w] * (1 - fx) + image[y0c, x1w] * fx
    bottom = image[y1c, x0w] * (1 - fx) + image[y1c, x1w] * fx
    return top * (1 - fy) + bottom * fy


def environment_cube(ctx: moderngl.Context, environment) -> moderngl.TextureCube:
    """The environment (or black without one) as an RGBA32F cube texture."""
    if environment is None:
        image = np.zeros((4, 8, 3), np.float32)
    else:
        image = environment_image(environment)
    faces = []
    for d in face_directions(FACE_SIZE):
        rgb = equirect_lookup(image.astype(np.float64), d)
        faces.append(np.concatenate([rgb, np.ones(rgb.shape[:2] + (1,))], axis=-1).astype(np.float32))
    tex = ctx.texture_cube((FACE_SIZE, FACE_SIZE), 4, np.stack(faces).tobytes(), dtype="f4")
    tex.build_mipmaps()
    tex.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    return tex
