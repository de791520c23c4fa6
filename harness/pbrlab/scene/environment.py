"""Environment lighting data: order-2 spherical harmonics (9 RGB coefficients) of the
environment's radiance, projected in float64 from a constant colour or from an
equirectangular image (.hdr/.exr, read with OpenImageIO).

Direction convention of equirectangular images: +Y is up; the image's top row looks at
+Y, its bottom row at -Y; column u in [0, 1) has azimuth phi = 2*pi*u measured from -Z
towards +X, so the image centre (u = 0.5) looks at +Z.

Basis and order: the real SH basis of Ramamoorthi & Hanrahan 2001, "An Efficient
Representation for Irradiance Environment Maps", eq. 3, in the order
L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (the shader's u_env_sh[0..8]).
"""

from __future__ import annotations

import numpy as np

from ..foundation.errors import SceneError
from ..maths.reference.guards import HALF_MAX

# Ramamoorthi & Hanrahan 2001, eq. 3 (constants of the real SH basis).
SH_Y00 = 0.282095
SH_Y1 = 0.488603
SH_Y2_OFF = 1.092548  # xy, yz, xz
SH_Y20 = 0.315392     # times (3z^2 - 1)
SH_Y22 = 0.546274     # times (x^2 - y^2)
# Ramamoorthi & Hanrahan 2001, eq. 13 (irradiance from radiance coefficients).
SH_C1, SH_C2, SH_C3, SH_C4, SH_C5 = 0.429043, 0.511664, 0.743125, 0.886227, 0.247708


def sh_basis(d: np.ndarray) -> np.ndarray:
    """The 9 basis functions at unit directions d[..., 3] -> [..., 9]."""
    x, y, z = d[..., 0], d[..., 1], d[..., 2]
    return np.stack([
        np.full_like(x, SH_Y00), SH_Y1 * y, SH_Y1 * z, SH_Y1 * x,
        SH_Y2_OFF * x * y, SH_Y2_OFF * y * z, SH_Y20 * (3 * z * z - 1),
        SH_Y2_OFF * x * z, SH_Y22 * (x * x - y * y)], axis=-1)


def equirect_directions(height: int, width: int):
    """Unit directions of pixel centres and their solid angles (see module docstring)."""
    theta = (np.arange(height) + 0.5) / height * np.pi  # from +Y
    phi = (np.arange(width) + 0.5) / width * 2 * np.pi
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    d = np.stack(np.broadcast_arrays(st * np.sin(phi)[None], ct, -st * np.cos(phi)[None]), axis=-1)
    solid_angle = (2 * np.pi / width) * (np.pi / height) * np.broadcast_to(st, (height, width))
    return d, solid_angle


def project_equirect(image: np.ndarray) -> np.ndarray:
    """SH9 coefficients (9x3) of an equirectangular radiance image (HxWx>=3, linear)."""
    image = np.asarray(image, np.float64)[..., :3]
    d, solid_angle = equirect_directions(*image.shape[:2])
    weights = sh_basis(d) * solid_angle[..., None]  # H x W x 9
    return np.einsum("hwk,hwc->kc", weights, image)


def constant_sh(radiance) -> np.ndarray:
    """SH9 of a constant radiance: only L00 = radiance * Y00 * 4pi is non-zero."""
    sh = np.zeros((9, 3))
    sh[0] = np.asarray(radiance, np.float64) * SH_Y00 * 4 * np.pi
    return sh


def sh_irradiance(sh: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Irradiance E(n) (float64) from SH9 radiance coefficients: R&H 2001, eq. 13."""
    x, y, z = (n[..., i:i + 1] for i in range(3))
    return (SH_C1 * sh[8] * (x * x - y * y) + SH_C3 * sh[6] * z * z + SH_C4 * sh[0] - SH_C5 * sh[6]
            + 2 * SH_C1 * (sh[4] * x * y + sh[7] * x * z + sh[5] * y * z)
            + 2 * SH_C2 * (sh[3] * x + sh[1] * y + sh[2] * z))


def environment_image(environment) -> np.ndarray:
    """The environment as an equirectangular float32 radiance image (HxWx3), intensity
    applied; a constant colour becomes a tiny constant image."""
    if environment.color is not None:
        image = np.broadcast_to(np.asarray(environment.color, np.float32), (4, 8, 3))
        return (image * environment.intensity).astype(np.float32)
    from ..foundation.images import read_image

    if environment.path.suffix.lower() not in (".hdr", ".exr"):
        raise SceneError(f"{environment.path}: environments must be linear .hdr or .exr images")
    image = read_image(environment.path)
    if image.ndim != 3 or image.shape[2] < 3:
        raise SceneError(f"{environment.path}: an environment needs RGB channels")
    return (sanitize_radiance(image[..., :3]) * environment.intensity).astype(np.float32)


def sanitize_radiance(image: np.ndarray) -> np.ndarray:
    """Radiance the renderer can integrate: NaN and negative texels become 0 and +Inf
    (or anything above it) the largest half float, 65504, the library's pbr_sanitize rule
    (PBR_HALF_MAX). An HDR capture with a clipped or broken texel must not turn every
    pixel that integrates it into NaN."""
    clean = np.nan_to_num(np.asarray(image, np.float64), nan=0.0, posinf=HALF_MAX, neginf=0.0)
    return np.clip(clean, 0.0, HALF_MAX)


def environment_sh(environment) -> np.ndarray:
    """SH9 (9x3 float64) of a scene's environment, scaled by its intensity."""
    if environment.color is not None:
        return constant_sh(environment.color) * environment.intensity
    return project_equirect(environment_image(environment))
