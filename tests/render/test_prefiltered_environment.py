"""The prefiltered environment (gpu/ibl.py, issue 38) as the scene programs read it (textureLod on
the cube at lod = level) against the float64 brute force (maths/reference/prefilter.py), at every
level, at the poles, the u = 0 seam, around the sun and at random directions
(checking/prefilter.py), under two real environments: Blender's CC0 sunrise (a sun 10^4 times
its sky) and studio (bright lamps), box-averaged to 128 x 64 to keep the brute force short.

Per direction n, the lookup may differ from the brute force P(n) by at most the sum of

* E_ref: the brute force's own quadrature error, (4/3) |P_2 - P_4| (midpoint rule on 2 x 2 and
  4 x 4 sub-cells per texel, O(h^2): Richardson);
* E_texel: the error of the level's texels, estimated the same way from the level's own
  algorithm: the CPU levels' texel sum at the box-averaged width W against the width 2W
  ((4/3) |T_W - T_2W|, O(h^2)); the GPU level's filtered importance sampling at N samples
  against 4N (2 |F_N - F_4N|: an error falling at least as N^-1/2 gives e_N <= 2 |F_N - F_4N|);
  for the mirror (the same bilinear image at the texel centres), the error of the direction's
  (u, t) in the prefilter pass: pbr_equirect_uv's atan and acos may err by 4096 ULP of their
  result (the Vulkan specification's "Precision and Operation of SPIR-V Instructions" table,
  the bound GL drivers are held to in practice; GLSL 4.60 sets none), 4096 * 2^-22 rad for
  results up to pi, times the image's slope in u and t (central differences over a texel);
* E_bright: the bright texels' sum puts each texel's excess at its centre, the brute force
  spreads it over the bilinear tent of +-1 texel, whose second moment per axis is h^2 / 6, so
  the midpoint error is sum over texels of excess * solid angle * (h_u^2 |w_uu| + h_t^2 |w_tt|) / 12
  (w the lobe weight, its second differences over one texel in u and t), over N(alpha);
* E_interp: bilinear reconstruction between the cube's texel centres (Delta = 2 / edge apart
  in the face coordinates). The brute force is only piecewise smooth: the mirror is GL's
  bilinear image, C0 with slope jumps at its texel edges, and (n.l)+ puts a slope jump on the
  terminator of a sun at roughness 1. Linear interpolation over a cell [a, a + Delta] of a
  function whose slope jumps by s at x0 errs by s (x0 - a)(a + Delta - x0) / Delta <= s Delta / 4,
  while the second difference at step Delta centred within Delta / 2 of x0 is at least
  s Delta / 2; so, per face axis, the error is at most half the largest second difference
  centred at the cell's corners or at the point (for smooth f, Delta^2 |f''| / 8 is smaller
  still). Bilinear filtering interpolates along s on the cell's two rows, then along t on the
  point's column: E_interp is half the largest s-difference centred at the four corners plus
  half the largest t-difference centred at the column's two ends. Across a face's edge the
  seamless filter takes the neighbouring face's texels: a convex combination of texel values,
  so there E_interp is the largest |f(n) - f(c)| over those texels' centres c;
* E_f32: float32 storage and filtering, 2^-20 of (P + the local mean).

The second differences sample the cell at five centres, not every point, and two kinks in one
cell add, so the bound can fall short at a few directions: at most ALLOWED_FRACTION of the directions may exceed it.
Errors are in luminance (BT.709).
"""

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import prefilter as check
from pbrlab.foundation.images import read_image
from pbrlab.gpu import ibl
from pbrlab.maths.reference import prefilter as ref

ENVIRONMENTS = Path(__file__).resolve().parents[2] / "scenes" / "assets" / "environments"
ALLOWED_FRACTION = 0.01
RANDOM_DIRECTIONS = 100
F32_RELATIVE = 2.0 ** -20
UV_ANGLE_ERROR = 4096 * 2.0 ** -22  # rad: 4096 ULP of a result below pi (module docstring)


def _environment(name: str) -> np.ndarray:
    """The CC0 environment at 128 x 64: solid-angle-weighted 2 x 2 means of its 256 x 128
    texels (rows near the poles are smaller), so a sun keeps its energy."""
    image = np.asarray(read_image(ENVIRONMENTS / f"{name}_256.exr"), np.float64)[..., :3]
    _, solid = ref.equirect_texels(*image.shape[:2])
    h, w = image.shape[0] // 2, image.shape[1] // 2
    weighted = (image * solid[..., None]).reshape(h, 2, w, 2, 3).sum(axis=(1, 3))
    return weighted / solid.reshape(h, 2, w, 2).sum(axis=(1, 3))[..., None]


def _luminance(rgb):
    return np.asarray(rgb, np.float64) @ check.LUMINANCE


def _interpolation_error(image, directions, roughness, edge, cells):
    """E_interp (module docstring) of each direction, in luminance."""
    face, sc, tc = check.face_coordinates(directions)
    step = 2.0 / edge
    s0 = -1.0 + (np.floor((sc + 1.0) / step - 0.5) + 0.5) * step
    t0 = -1.0 + (np.floor((tc + 1.0) / step - 0.5) + 0.5) * step

    def f(points):
        return _luminance(ref.prefiltered_radiance(image, np.concatenate(points), roughness, cells=cells)).reshape(
            len(points), len(directions))

    def second_difference(s, t, ds, dt):
        v = f([check.face_direction(face, s - ds, t - dt), check.face_direction(face, s, t),
               check.face_direction(face, s + ds, t + dt)])
        return np.abs(v[0] - 2.0 * v[1] + v[2])

    # Tensor-product bilinear: along s on the cell's rows t0 and t0 + Delta (centres: the
    # four corners), then along t on the point's column (centres: its two ends).
    along_s = np.max([second_difference(s, t, step, 0.0) for s in (s0, s0 + step) for t in (t0, t0 + step)], axis=0)
    along_t = np.max([second_difference(sc, t, 0.0, step) for t in (t0, t0 + step)], axis=0)
    interior = (s0 > -1.0) & (s0 + step < 1.0) & (t0 > -1.0) & (t0 + step < 1.0)
    # A cell across a face's edge takes its texels from the neighbouring face (seamless
    # filtering): the lookup is a convex combination of the texels the direction falls
    # between, so it errs by at most max |f(n) - f(c)| over their centres c (each found as the
    # face texel nearest the extended plane's corner).
    corners = []
    for s in (s0, s0 + step):
        for t in (t0, t0 + step):
            cface, cs, ct = check.face_coordinates(check.face_direction(face, s, t))
            snap = lambda x: -1.0 + (np.clip(np.floor((x + 1.0) / step), 0, edge - 1) + 0.5) * step
            corners.append(check.face_direction(cface, snap(cs), snap(ct)))
    values = f(corners + [directions])
    convex = np.abs(values[:4] - values[4]).max(axis=0)
    return np.where(interior, (along_s + along_t) / 2.0, convex)


def _bright_midpoint_error(directions, image, roughness):
    """E_bright (module docstring): the bright texels' excess at their centres against its
    bilinear tent, from the lobe weight's second differences over one texel in u and t."""
    _, bright = ibl.split_bright(image)
    d, solid, radiance = bright
    if len(d) == 0:
        return np.zeros(len(directions))
    h, w = image.shape[:2]
    u, t = ref.equirect_uv(d)
    alpha = roughness ** 2
    norm = ibl.lobe_normalisation(alpha)

    def weight(uu, tt):
        return ref.lobe_weight(directions @ ref.equirect_direction(uu, tt).T, alpha) if alpha > 0 else 0.0

    centre = weight(u, t)
    w_uu = np.abs(weight(u + 1.0 / w, t) - 2.0 * centre + weight(u - 1.0 / w, t))
    w_tt = np.abs(weight(u, np.minimum(t + 1.0 / h, 1.0)) - 2.0 * centre + weight(u, np.maximum(t - 1.0 / h, 0.0)))
    # The second differences over one texel are h^2 f''; the midpoint error is h^2 f'' / 12 per axis.
    return ((w_uu + w_tt) / 12.0 * solid) @ _luminance(radiance) / norm


def _texel_error(gl_context, image, level, directions, roughness):
    """E_texel (module docstring) at the directions."""
    clipped, _ = ibl.split_bright(image)
    if level == 0:
        h, w = image.shape[:2]
        angle = UV_ANGLE_ERROR
        u, t = ref.equirect_uv(directions)
        slope_u = np.abs(_luminance(ref.bilinear(image, u + 1.0 / w, t)) - _luminance(ref.bilinear(image, u - 1.0 / w, t))) * w / 2.0
        slope_t = np.abs(_luminance(ref.bilinear(image, u, t + 1.0 / h)) - _luminance(ref.bilinear(image, u, t - 1.0 / h))) * h / 2.0
        return slope_u * angle / (2.0 * np.pi) + slope_t * angle / np.pi
    if level >= ibl.PREFILTER_CPU_FIRST_LEVEL:
        width = ibl.PREFILTER_CPU_SOURCE_WIDTH[level]
        coarse = ibl._texel_sum(directions, ibl.box_average(clipped, width), roughness)
        fine = ibl._texel_sum(directions, ibl.box_average(clipped, 2 * width), roughness)
        return (4.0 / 3.0) * np.abs(_luminance(coarse) - _luminance(fine))
    looked_up = []
    for samples in (ibl.PREFILTER_SAMPLES, 4 * ibl.PREFILTER_SAMPLES):
        faces = _gpu_level(gl_context, clipped, level, samples)
        cube = ibl.float_cube_from_levels(gl_context, [faces])
        looked_up.append(_luminance(check.cube_lookup(gl_context, cube, directions, 0.0)))
        cube.release()
    return 2.0 * np.abs(looked_up[0] - looked_up[1])


def _gpu_level(gl_context, clipped, level, samples):
    saved = ibl.PREFILTER_SAMPLES
    ibl.PREFILTER_SAMPLES = samples
    try:
        return ibl._prefilter_gpu_level(gl_context, clipped.astype(np.float32), level)
    finally:
        ibl.PREFILTER_SAMPLES = saved


@pytest.fixture(scope="module", params=["sunrise", "studio"])
def environment(request):
    return request.param, _environment(request.param)


# Level 1 is filtered importance sampling on the GPU (256 samples): its error at a direction is
# not bounded by its own N-against-4N estimate (Hammersley sets of N and 4N points share
# structure, and FIS's mip blur is a bias, not noise): 16 (sunrise) and 47 (studio) of 242
# directions over, up to 0.6 % of P. Known, open (docs/shading.md); strict, so a fix shows.
LEVELS = [pytest.param(level, marks=pytest.mark.xfail(
    strict=True, reason="level 1 (FIS on the GPU) has no derived bound yet: see the comment above"))
    if 0 < level < ibl.PREFILTER_CPU_FIRST_LEVEL else level for level in range(ibl.PREFILTER_LEVELS)]


@pytest.mark.parametrize("level", LEVELS)
def test_prefiltered_environment_matches_the_float64_brute_force_at_every_level(gl_context, environment, level):
    name, image = environment
    cube = ibl.float_cube_from_levels(gl_context, ibl._prefilter_levels(gl_context, image.astype(np.float32)))
    sets = check.direction_sets(image, random_count=RANDOM_DIRECTIONS, ring_count=8)
    directions = np.concatenate(list(sets.values()))
    labels = np.concatenate([[k] * len(v) for k, v in sets.items()])
    roughness = ibl.prefilter_level_roughness(level)
    edge = ibl.prefilter_level_size(level)
    cells2, cells4 = ref.quadrature_cells(image, 2), ref.quadrature_cells(image, 4)

    got = _luminance(check.cube_lookup(gl_context, cube, directions, level))
    want = _luminance(ref.prefiltered_radiance(image, directions, roughness, cells=cells2))
    fine = _luminance(ref.prefiltered_radiance(image, directions, roughness, cells=cells4))
    local_mean = _luminance(ref.prefiltered_radiance(image, directions, 1.0, cells=cells2))
    e_ref = (4.0 / 3.0) * np.abs(want - fine)
    e_texel = _texel_error(gl_context, image, level, directions, roughness)
    e_bright = _bright_midpoint_error(directions, image, roughness) if level else 0.0
    e_interp = _interpolation_error(image, directions, roughness, edge, cells2)
    e_f32 = F32_RELATIVE * (np.abs(want) + local_mean)
    bound = e_ref + e_texel + e_bright + e_interp + e_f32
    error = np.abs(got - want)
    over = error > bound
    worst = np.argmax(error / bound)
    assert over.mean() <= ALLOWED_FRACTION, (
        f"{name} level {level} (roughness {roughness}, faces {edge}^2): {over.sum()} of {len(over)} "
        f"directions over the bound ({', '.join(sorted(set(labels[over])))}); worst {labels[worst]} "
        f"error {error[worst]:.4g} bound {bound[worst]:.4g} (ref {e_ref[worst]:.3g}, texel "
        f"{np.broadcast_to(e_texel, error.shape)[worst]:.3g}, bright {np.broadcast_to(e_bright, error.shape)[worst]:.3g}, "
        f"interp {e_interp[worst]:.3g}) at P = {want[worst]:.4g}, local mean {local_mean[worst]:.4g}")
    cube.release()
