"""Whether a mesh draw needs the degenerate-tangent fallback (PBRLAB_TANGENT_FALLBACK).

``pbrlab_tangent_to_world_normal`` (templates/scene_lighting.inc) builds the pixel's tangent
by Gram-Schmidt, ``t = T - n (n.T)``, from the interpolated world tangent T and the unit
interpolated normal n, and replaces it by another unit vector orthogonal to n where
``|t|^2 <= 1e-12`` (the fallback). Here the harness decides, from the vertex data it draws,
whether any pixel of a draw can reach that case; if none can, the draw's program is compiled
with ``PBRLAB_TANGENT_FALLBACK 0`` and has no select and no stand-in (25 RDNA3 instructions
in the DamagedHelmet program, issue 35). Where the fallback is not taken the two programs
compute the same value, so the image is the same bit for bit.

The bound. At a pixel with barycentric weights w (w_i >= 0, sum 1), mesh.vert gives
T = sum w_i a_i and N = sum w_i b_i, a_i = M t_i (the model's 3x3 times the vertex tangent)
and b_i = M^-T n_i (the normal matrix times the vertex normal), and ``|t| = |T x N/|N||``.
Write a_i = |a_i| u_i and b_i = |b_i| v_i with unit u_i, v_i; then T = s_T sum p_i u_i and
N = s_N sum q_j v_j with other convex weights p, q and s_T >= min |a_i|. With |sum q_j v_j|
<= 1,

    |t| >= s_T |sum_ij p_i q_j (u_i x v_j)| >= min_i |a_i| * min_ij (u_i x v_j) . e

for any unit e (the bilinear form is a convex combination of the nine cross products; its
length is at least its component along e). e is taken along the sum of the nine. A
primitive is safe when that bound exceeds ``THRESHOLD``; the draw is safe when every
primitive is (lines: two vertices, points: one; the same bound).

Weights outside the triangle. A single-sampled rasteriser interpolates at the pixel centre,
which its coverage test found inside the triangle. llvmpipe tests coverage on vertex
positions snapped to its subpixel grid (8 bits: within 1/512 pixel per coordinate) and
interpolates from the unsnapped positions, so a covered centre can lie up to sqrt(2)/512
pixel outside the triangle the weights come from: a weight can then be as low as
-0.0028 / h, h the triangle's height in pixels. The bound is taken over the triangle grown
to weights >= -``OUTSIDE`` (its corners (1 + 2 eta) x_k - eta (the other two); T and N are
linear in w and follow exactly): 1/256 covers triangles at least 0.7 pixel tall. On a
thinner sliver the production program normalises whatever t the extrapolated frame gives;
only an exactly zero t (NaN, then refused by `pbrlab render`'s check of the float image)
would differ in kind. Measured on corpus/gltf/khronos: of the meshes the bound accepts, the
margin at 1/256 is 0.87 of the margin at 0 or more on all but RiggedSimple (0.08: 1.3e-4 of
1.7e-3, still above the threshold); at 1/16 ClearCoatTest's spheres, accepted at 1/256
(margin 0.0103), fail (-0.009). A multisampled target interpolates at the pixel centre even
where only some samples are covered (no ``centroid``): the weights there are not bounded,
so such renders keep the fallback (``needs_fallback``'s ``samples``).

The threshold. The fallback is taken at |t| <= 1e-6; float32 interpolation and Gram-Schmidt
round T and t by a few units in the last place of the largest a_i (2^-24 each: the three
interpolation products and sums, the dot product and the subtraction, about 8 roundings,
bounded by 16 ulp here): ``THRESHOLD`` = 1e-6 + 16 * 2^-24 * max |a_i|.
"""

from __future__ import annotations

import weakref
from collections import OrderedDict

import numpy as np

TANGENT_FALLBACK_DEFINE = "PBRLAB_TANGENT_FALLBACK"
FALLBACK_TAKEN_BELOW = 1e-6   # |t| at or under which the shader's fallback is taken (|t|^2 <= 1e-12)
ROUNDING_ULPS = 16            # float32 roundings of T and t, in units of 2^-24 max |a_i| (module doc)
OUTSIDE = 1.0 / 256.0         # barycentric weights down to -OUTSIDE covered (module doc)
_SIMILARITY_TOLERANCE = 1e-9  # relative: M^T M = s^2 I within this is a rotation times a scale

# A program reads the tangent only where a surface may tilt the normal or turn the
# anisotropy direction (surface_pixel.inc): a normal or coat-normal map, an anisotropy, or a
# surface file. Elsewhere the tangent's terms are multiplied by zero and folded away, so a
# draw's bound is not computed (the define's default, the fallback, stays: safe either way).
TANGENT_READERS = ("PBRLAB_NORMAL_MAP", "PBRLAB_CLEARCOAT_NORMAL_MAP", "PBRLAB_ANISOTROPY")
# Bounds kept per vertex arrays and transform (a weak reference to the tangents: a mesh's
# arrays are freed with it), most recently used last.
_BOUNDS: OrderedDict = OrderedDict()
BOUNDS_KEPT = 4096


def _primitives(indices: np.ndarray, topology: str) -> np.ndarray:
    """Indices as rows of one primitive's vertices (3 per triangle, 2 per line, 1 per point)."""
    width = {"triangles": 3, "lines": 2, "points": 1}[topology]
    indices = np.asarray(indices, np.int64)
    return indices[: len(indices) - len(indices) % width].reshape(-1, width)


def _grown(values: np.ndarray) -> np.ndarray:
    """Per primitive (P, k, 3): the corners of the primitive grown to weights >= -OUTSIDE."""
    k = values.shape[1]
    if k == 1:
        return values
    total = values.sum(axis=1, keepdims=True)
    return (1.0 + k * OUTSIDE) * values - OUTSIDE * total


def frame_bound(tangents: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """Per primitive, the margin of the bound over the threshold: ``min|a| * min (u_i x v_j).e
    - THRESHOLD`` (module doc) for world tangents ``tangents`` and normals ``normals``, both
    (P, k, 3) float64; > 0 where no pixel of the primitive can take the fallback."""
    a = _grown(tangents)
    b = _grown(normals)
    a_len = np.linalg.norm(a, axis=2)
    b_len = np.linalg.norm(b, axis=2)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = a / a_len[..., None]
        v = b / b_len[..., None]
        crosses = np.cross(u[:, :, None, :], v[:, None, :, :])          # (P, k, k, 3)
        direction = crosses.sum(axis=(1, 2))
        e = direction / np.linalg.norm(direction, axis=1, keepdims=True)
        along = np.einsum("pijc,pc->pij", crosses, e).min(axis=(1, 2))
        bound = a_len.min(axis=1) * along
    threshold = FALLBACK_TAKEN_BELOW + ROUNDING_ULPS * 2.0 ** -24 * a_len.max(axis=1)
    margin = bound - threshold
    return np.where(np.isfinite(margin), margin, -np.inf)


def _similarity_scale(m3: np.ndarray) -> float | None:
    """s when ``m3`` is s times a rotation (or reflection), else None."""
    gram = m3.T @ m3
    s2 = np.trace(gram) / 3.0
    if s2 <= 0 or np.abs(gram - s2 * np.eye(3)).max() > _SIMILARITY_TOLERANCE * s2:
        return None
    return float(np.sqrt(s2))


def _world_margin(arrays, topology: str, transform: np.ndarray) -> float:
    """The least margin (frame_bound) over the mesh's primitives drawn with ``transform``."""
    normals, tangents, indices = np.asarray(arrays[1], np.float64), np.asarray(arrays[3], np.float64), arrays[4]
    m3 = np.asarray(transform, np.float64)[:3, :3]
    rows = _primitives(indices, topology)
    if len(rows) == 0:
        return np.inf
    normal_matrix = np.linalg.inv(m3).T
    world_t = tangents[:, :3] @ m3.T
    world_n = normals @ normal_matrix.T
    return float(frame_bound(world_t[rows], world_n[rows]).min())


def _object_bound(arrays, topology: str) -> tuple[float, float]:
    """(least bound min|a| * min (u x v).e, largest |a_i|) in the mesh's own space: under
    M = s R both scale by s (the directions rotate, lengths of a scale by s, of b by 1/s)."""
    tangents = np.asarray(arrays[3], np.float64)[:, :3]
    rows = _primitives(arrays[4], topology)
    if len(rows) == 0:
        return np.inf, 0.0
    margin = frame_bound(tangents[rows], np.asarray(arrays[1], np.float64)[rows])
    a_max = np.linalg.norm(_grown(tangents[rows]), axis=2).max(axis=1)
    bound = margin + _threshold(a_max)  # the bound itself; the threshold is re-derived per scale
    return float(np.min(np.where(np.isfinite(bound), bound, -np.inf))), float(a_max.max())


def _threshold(a_max):
    """The least |t| bound that keeps the fallback untaken for tangents up to ``a_max`` (module doc)."""
    return FALLBACK_TAKEN_BELOW + ROUNDING_ULPS * 2.0 ** -24 * a_max


def _cached(arrays, topology: str, what, compute):
    """``compute()``, kept per (vertex arrays, topology, ``what``) while the arrays live."""
    key = (id(arrays[3]), id(arrays[1]), id(arrays[4]), topology, what)
    entry = _BOUNDS.get(key)
    if entry is not None and entry[0]() is arrays[3]:
        _BOUNDS.move_to_end(key)
        return entry[1]
    value = compute()
    _BOUNDS[key] = (weakref.ref(arrays[3]), value)
    while len(_BOUNDS) > BOUNDS_KEPT:
        _BOUNDS.popitem(last=False)
    return value


def _draw_safe(arrays, topology: str, transform) -> bool:
    """Whether no pixel of the mesh drawn with ``transform`` can take the fallback."""
    m3 = np.asarray(transform, np.float64)[:3, :3]
    scale = _similarity_scale(m3)
    if scale is None:
        margin = _cached(arrays, topology, m3.tobytes(), lambda: _world_margin(arrays, topology, transform))
        return margin > 0
    bound, a_max = _cached(arrays, topology, "object", lambda: _object_bound(arrays, topology))
    return scale * bound - _threshold(scale * a_max) > 0


def needs_fallback(objects, samples: int = 1) -> bool:
    """Whether a draw of ``objects`` (one mesh object, or the instances of one batch: the same
    geometry) into a target of ``samples`` per pixel needs the tangent fallback compiled."""
    from ..scene import meshes  # loaded on use

    if samples != 1:
        return True  # pixel-centre interpolation outside the triangle (module doc)
    obj = objects[0]
    arrays = meshes.mesh_data(obj).arrays
    topology = "triangles" if obj.geometry is None else obj.geometry.topology
    return not all(_draw_safe(arrays, topology, instance.transform) for instance in objects)


def draw_defines(objects, defines: dict, samples: int = 1, custom_surface: bool = False) -> dict:
    """The define a mesh draw of ``objects`` adds to its program's ``defines``: the fallback
    left out (``PBRLAB_TANGENT_FALLBACK 0``) where the program reads the tangent
    (``TANGENT_READERS``, or a ``custom_surface`` file) and ``needs_fallback`` is False;
    nothing otherwise (the templates' default keeps it)."""
    if not custom_surface and not any(name in defines for name in TANGENT_READERS):
        return {}
    return {} if needs_fallback(objects, samples) else {TANGENT_FALLBACK_DEFINE: 0}
