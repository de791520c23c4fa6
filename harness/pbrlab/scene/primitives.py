"""Built-in meshes (a scene's ``{"primitive": ...}``) made in numpy, with UVs.

Each generator returns a ``Primitive``: float64 positions, unit normals, UVs and int64
triangles (counter-clockwise seen from outside). Positions, triangle order and winding are
those trimesh 5.2's ``trimesh.creation`` gives for the same parameters (vertices the same
point for point, so untextured images stay as they were; tests/scene/test_primitives.py
compares them), made here so that a scene of primitives never imports trimesh (0.7 s with
scipy, issue 35). Vertices are split where a UV seam or a hard edge needs two values.

The shapes and their UV mappings (u grows to the right and v upwards seen from outside, so
a texture is never mirrored):

* ``uv_sphere`` (radius): 31 latitude bands x 64 longitude sections about +Z. Vertex
  (i, j) sits at longitude phi = 2 pi i / 64 and polar angle theta = pi j / 31 measured
  from -Z; u = i / 64 (the seam column i = 64 is a duplicate of i = 0 with u = 1),
  v = j / 31 (0 at the south pole -Z, 1 at the north pole +Z). A pole vertex is one per
  triangle, at the middle of its triangle's u span. Smooth normals.
* ``icosphere`` (radius, subdivisions): an icosahedron split ``subdivisions`` times, each
  vertex pushed out to the radius. Spherical mapping about +Z as the uv_sphere's:
  u = atan2(y, x) / 2 pi (in [0, 1)), v = arccos(-z / |p|) / pi. A triangle whose corners
  straddle the seam (u span over 1/2) takes u + 1 at its corners below 1/2; a corner on the
  Z axis (x = y = 0, where u is undefined) takes the mean u of its triangle's other two
  corners. Smooth normals.
* ``torus`` (major_radius, minor_radius): 32 sections about +Z (angle theta = 2 pi i / 32)
  x 32 around the tube (angle phi = 2 pi j / 32, 0 at the outer equator, rising to +Z);
  u = i / 32 around the major circle, v = j / 32 around the tube, both seams duplicated.
  Smooth normals.
* ``cylinder`` (radius, height): axis Z, centred, 32 sections. Side: u = i / 32 around,
  v = (z + height / 2) / height; caps: planar, u, v = 1/2 + (x, y) / (2 radius) on the top
  cap (+Z) and (1/2 - x / (2 radius), 1/2 + y / (2 radius)) on the bottom one. Hard edges
  at the rims: radial normals on the side, +-Z on the caps (trimesh's shared rim vertices
  averaged them into a rounded edge).
* ``box`` (size): a cube centred at the origin, 12 triangles in trimesh's order. Each face
  0..1 in u and v, v up along +Y on the four side faces, towards -Z on the top face and +Z
  on the bottom one. Hard edges: each face its own normal (trimesh's 8 shared corners
  averaged them).
* ``plane`` (size): a square in XZ facing +Y, u along +X, v along -Z, over [0, 1]^2.

Smooth normals are trimesh's: each vertex the angle-weighted sum of its triangles' unit
normals (Thuerrner and Wuethrich 1998, "Computing Vertex Normals from Polygonal Facets",
J. Graphics Tools 3(1)), summed in triangle order, then normalised.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

# Resolution fixed by trimesh's defaults, kept so that images made before stay the same.
UV_SPHERE_BANDS, UV_SPHERE_SECTIONS = 32, 64    # latitude lines (31 bands), longitude sections
TORUS_SECTIONS, TORUS_TUBE_SECTIONS = 32, 32
CYLINDER_SECTIONS = 32
# trimesh's zero test for a vector norm (100 x float64 resolution), used as trimesh uses it
# so that normals come out the same bits.
_NORM_ZERO = 100 * float(np.finfo(np.float64).resolution)
# An angle of a triangle below this (radians) marks it degenerate: it adds no weight to its
# vertices' normals (trimesh's tol.merge).
_DEGENERATE_ANGLE = 1e-8
# A sphere vertex within this fraction of the radius of the Z axis is a pole (its longitude
# undefined); exact zeros in practice (midpoints of mirrored vertices).
_POLE_FRACTION = 1e-9

# trimesh's icosahedron (its resources/creation.json): unit vertices (0, +-a, +-b) cycled,
# a = 1 / sqrt(1 + phi^2), b = phi a with phi the golden ratio, and its 20 triangles.
_ICOSAHEDRON_A, _ICOSAHEDRON_B = 0.5257311121191336, 0.85065080835204
_ICOSAHEDRON_VERTICES = [[-1, 2, 0], [1, 2, 0], [-1, -2, 0], [1, -2, 0], [0, -1, 2], [0, 1, 2],
                         [0, -1, -2], [0, 1, -2], [2, 0, -1], [2, 0, 1], [-2, 0, -1], [-2, 0, 1]]
_ICOSAHEDRON_FACES = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9],
                      [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2],
                      [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
                      [8, 6, 7], [9, 8, 1]]
# trimesh's unit cube: corner k at (k >> 2 & 1, k >> 1 & 1, k & 1) - 1/2, and its triangles.
_BOX_FACES = [[1, 3, 0], [4, 1, 0], [0, 3, 2], [2, 4, 0], [1, 7, 3], [5, 1, 4],
              [5, 7, 1], [3, 7, 2], [6, 4, 2], [2, 7, 6], [6, 5, 4], [7, 5, 6]]


@dataclass(frozen=True)
class Primitive:
    """A generated mesh: positions (n, 3), unit normals (n, 3), uv (n, 2), all float64, and
    triangles (m, 3) int64 into them."""
    positions: np.ndarray
    normals: np.ndarray
    uv: np.ndarray
    faces: np.ndarray


def _unit_rows(vectors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each row divided by its length (rows not longer than _NORM_ZERO kept as they are),
    and which rows were long enough: trimesh's util.unitize, operation for operation."""
    norm = np.sqrt(np.dot(vectors * vectors, [1.0] * vectors.shape[1]))
    valid = norm > _NORM_ZERO
    norm[valid] **= -1
    return vectors * norm.reshape((-1, 1)), valid


def _face_normals(corners: np.ndarray) -> np.ndarray:
    """Unit normals of triangles (m, 3, 3) from the cross product of their first two edges;
    zero for a triangle without area."""
    edges = corners[:, 1:, :] - corners[:, :2, :]
    unit, valid = _unit_rows(np.cross(edges[:, 0], edges[:, 1]))
    unit[~valid] = 0.0
    return unit


def _corner_angles(corners: np.ndarray) -> np.ndarray:
    """The angle (radians) at each corner of triangles (m, 3, 3); all three zero for a
    triangle with an angle under _DEGENERATE_ANGLE."""
    u = _unit_rows(corners[:, 1] - corners[:, 0])[0]
    v = _unit_rows(corners[:, 2] - corners[:, 0])[0]
    w = _unit_rows(corners[:, 2] - corners[:, 1])[0]
    angles = np.zeros((len(corners), 3))
    angles[:, 0] = np.arccos(np.clip(np.dot(u * v, [1.0, 1.0, 1.0]), -1, 1))
    angles[:, 1] = np.arccos(np.clip(np.dot(-u * w, [1.0, 1.0, 1.0]), -1, 1))
    angles[:, 2] = np.pi - angles[:, 0] - angles[:, 1]
    angles[(angles < _DEGENERATE_ANGLE).any(axis=1), :] = 0.0
    return angles


def smooth_normals(positions: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Angle-weighted vertex normals (Thuerrner and Wuethrich 1998), summed per vertex in
    triangle order as trimesh's sparse product sums them; zero for an unused vertex."""
    corners = positions[faces]
    normals = _face_normals(corners)
    angles = _corner_angles(corners)
    kept = (normals ** 2).sum(axis=1) > 0.5
    summed = np.zeros((len(positions), 3))
    np.add.at(summed, faces[kept].ravel(), angles[kept].reshape(-1, 1) * np.repeat(normals[kept], 3, axis=0))
    return _unit_rows(summed)[0]


def _distinct_rows(columns: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(index of the first row of each distinct row, each row's distinct number) of the rows
    made of ``columns`` (equal length)."""
    order = np.lexsort(columns[::-1])
    ordered = np.stack([c[order] for c in columns], axis=1)
    starts = np.ones(len(order), bool)
    starts[1:] = (ordered[1:] != ordered[:-1]).any(axis=1)
    number = np.empty(len(order), np.int64)
    number[order] = np.cumsum(starts) - 1
    return order[starts], number


def _assemble(positions, faces, corner_uv, corner_normals=None) -> Primitive:
    """A Primitive from welded ``positions`` (n, 3), ``faces`` (m, 3) into them, each
    corner's uv (m, 3, 2) and, for hard edges, each corner's normal (m, 3, 3; smooth
    normals of the welded mesh when None). Corners sharing a position, a uv and a normal
    share one vertex."""
    index, uv = faces.ravel(), corner_uv.reshape(-1, 2)
    if corner_normals is not None:  # hard edges (box, cylinder: small): every attribute decides
        first, vertex = _distinct_rows([index, *uv.T, *corner_normals.reshape(-1, 3).T])
        return Primitive(positions[index[first]], corner_normals.reshape(-1, 3)[first], uv[first],
                         vertex.reshape(-1, 3))
    normals = smooth_normals(positions, faces)
    # each position keeps the uv of its first corner; corners with another uv (the seam's,
    # the poles') become vertices of their own, one per distinct (position, uv)
    first_corner = np.full(len(positions), len(index))
    np.minimum.at(first_corner, index, np.arange(len(index)))
    used = first_corner < len(index)
    own = np.all(uv == uv[first_corner[index].clip(max=len(index) - 1)], axis=1)
    renumber = np.cumsum(used) - 1
    vertex = renumber[index]
    other = np.flatnonzero(~own)
    extra_first, extra = _distinct_rows([index[other], *uv[other].T])
    vertex[other] = used.sum() + extra
    kept = np.concatenate([first_corner[used], other[extra_first]])
    return Primitive(positions[index[kept]], normals[index[kept]], uv[kept], vertex.reshape(-1, 3))


def _weld(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(distinct points, index of each input point among them): points equal to 8 decimal
    places are one, placed where the first of them is (trimesh's merge_vertices, as it
    welds a revolved profile's closing point and poles)."""
    rounded = np.round(points * 1e8).astype(np.int64)
    _, first, inverse = np.unique(rounded, axis=0, return_index=True, return_inverse=True)
    order = np.argsort(first)                       # distinct points in order of first use
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return points[first[order]], rank[inverse.ravel()]


def _revolve(profile: np.ndarray, sections: int):
    """A profile (p, 2) of (distance from the Z axis, z) turned about +Z in ``sections``
    steps, as trimesh.creation.revolve lays it out: grid vertex (i, j) at angle
    2 pi i / sections (i = 0 .. sections, the last a copy of the first) and profile point j;
    index i * p + j. Returns (grid points ((sections + 1) p, 3), triangles into the grid:
    per section, per profile segment j, (j, p + j, j + 1) then (j + 1, p + j, p + j + 1))."""
    per = len(profile)
    theta = np.linspace(0, 2 * np.pi, sections + 1)
    circle = np.column_stack((np.cos(theta), np.sin(theta)))
    grid = np.column_stack((np.tile(circle, (1, per)).reshape((-1, 2)) * np.tile(profile[:, 0], len(circle)).reshape((-1, 1)),
                            np.tile(profile[:, 1], len(circle))))
    quad = np.array([[0, per, 1], [1, per, per + 1]])
    single = (quad[None] + np.arange(per - 1)[:, None, None]).reshape(-1, 3)
    faces = (single[None] + (np.arange(sections) * per)[:, None, None]).reshape(-1, 3)
    return grid, faces, per


def _grid_uv(sections: int, per: int, v_of_j: np.ndarray) -> np.ndarray:
    """UV of each revolve grid vertex: u = i / sections, v = v_of_j[j]."""
    u = np.repeat(np.arange(sections + 1) / sections, per)
    return np.column_stack((u, np.tile(v_of_j, sections + 1)))


def _welded_revolution(grid, faces, per, sections):
    """The revolved grid with its closing copy (i = sections) mapped onto i = 0 and equal
    points welded: (positions, faces into them)."""
    wrapped = np.arange(len(grid)) % (sections * per)
    positions, index = _weld(grid[: sections * per])
    return positions, index[wrapped][faces]


def uv_sphere(radius: float) -> Primitive:
    """A latitude/longitude sphere, poles on +-Z (mapping: the module docstring)."""
    bands, sections = UV_SPHERE_BANDS, UV_SPHERE_SECTIONS
    theta = np.linspace(0.0, np.pi, num=bands)
    profile = np.column_stack((np.sin(theta), -np.cos(theta))) * radius
    grid, faces, per = _revolve(profile, sections)
    # the first triangle of the first segment and the second of the last touch a pole twice
    single = np.ones(2 * (per - 1), bool)
    single[[0, -1]] = False
    faces = faces[np.tile(single, sections)]
    uv = _grid_uv(sections, per, np.arange(per) / (per - 1))
    # a pole vertex serves one triangle: the south pole of column i the one spanning
    # columns i - 1 .. i, the north pole of column i the one spanning i .. i + 1
    uv[0::per, 0] -= 0.5 / sections
    uv[per - 1::per, 0] += 0.5 / sections
    positions, welded = _welded_revolution(grid, faces, per, sections)
    return _assemble(positions, welded, uv[faces])


def torus(major_radius: float, minor_radius: float) -> Primitive:
    """A torus about +Z, u around the major circle, v around the tube."""
    sections, tube = TORUS_SECTIONS, TORUS_TUBE_SECTIONS
    phi = np.linspace(0, 2 * np.pi, tube + 1, endpoint=True)
    profile = np.column_stack((minor_radius * np.cos(phi), minor_radius * np.sin(phi))) + [major_radius, 0]
    grid, faces, per = _revolve(profile, sections)
    uv = _grid_uv(sections, per, np.arange(per) / tube)
    positions, welded = _welded_revolution(grid, faces, per, sections)
    return _assemble(positions, welded, uv[faces])


def cylinder(radius: float, height: float) -> Primitive:
    """A capped cylinder along Z, centred; the side and each cap mapped on their own."""
    sections = CYLINDER_SECTIONS
    half = abs(float(height)) / 2.0
    profile = np.array([[0, -half], [radius, -half], [radius, half], [0, half]], np.float64)
    grid, faces, per = _revolve(profile, sections)
    # per section: [degenerate, bottom cap, side, side, top cap, degenerate]
    kind = np.tile(np.array(["", "bottom", "side", "side", "top", ""]), sections)
    faces, kind = faces[kind != ""], kind[kind != ""]
    corner = grid[faces]
    side_uv = _grid_uv(sections, per, np.array([0.0, 0.0, 1.0, 1.0]))[faces]
    plane_u = 0.5 + corner[..., 0] / (2 * radius)
    plane_v = 0.5 + corner[..., 1] / (2 * radius)
    cap_u = np.where((kind == "top")[:, None], plane_u, 1.0 - plane_u)
    uv = np.where((kind == "side")[:, None, None], side_uv, np.stack([cap_u, plane_v], axis=-1))
    radial = np.stack([corner[..., 0], corner[..., 1], np.zeros_like(corner[..., 0])], axis=-1) / radius
    axial = np.zeros_like(corner)
    axial[..., 2] = np.where(kind == "top", 1.0, -1.0)[:, None]
    normals = np.where((kind == "side")[:, None, None], radial, axial)
    positions, welded = _welded_revolution(grid, faces, per, sections)
    return _assemble(positions, welded, uv, normals)


def box(size: float) -> Primitive:
    """A cube of edge ``size`` centred at the origin, each face mapped over [0, 1]^2."""
    corners = np.array([[(k >> 2) & 1, (k >> 1) & 1, k & 1] for k in range(8)], np.float64)
    positions = (corners - 0.5) * np.asarray([size] * 3, np.float64)
    faces = np.array(_BOX_FACES, np.int64)
    corner = positions[faces]
    normal = np.sign(np.cross(corner[:, 1] - corner[:, 0], corner[:, 2] - corner[:, 0]))
    # v up: +Y on the side faces; on the top face -Z, on the bottom +Z; u = up x normal
    up = np.where(np.abs(normal[:, 1:2]) > 0, [[0.0, 0.0, 1.0]] * -normal[:, 1:2], [[0.0, 1.0, 0.0]])
    right = np.cross(up, normal)
    uv = np.stack([0.5 + np.einsum("fcx,fx->fc", corner, right) / size,
                   0.5 + np.einsum("fcx,fx->fc", corner, up) / size], axis=-1)
    return _assemble(positions, faces, uv, np.repeat(normal[:, None, :], 3, axis=1))


def plane(size: float) -> Primitive:
    """A square of side ``size`` in XZ facing +Y, u along +X, v along -Z."""
    s = size / 2
    positions = np.array([[-s, 0, -s], [s, 0, -s], [s, 0, s], [-s, 0, s]], np.float64)
    uv = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float64)
    faces = np.array([[0, 2, 1], [0, 3, 2]], np.int64)
    return Primitive(positions, smooth_normals(positions, faces), uv, faces)


def _subdivided(positions: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each triangle split into four at its edge midpoints (trimesh.remesh.subdivide's
    layout: midpoints appended in order of (larger, smaller) end index)."""
    edges = np.sort(faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    packed = edges[:, 1] * (1 << 32) + edges[:, 0]
    _, unique, inverse = np.unique(packed, return_index=True, return_inverse=True)
    mid = positions[edges[unique]].mean(axis=1)
    m = inverse.reshape((-1, 3)) + len(positions)
    new_faces = np.column_stack([faces[:, 0], m[:, 0], m[:, 2], m[:, 0], faces[:, 1], m[:, 1],
                                 m[:, 2], m[:, 1], faces[:, 2], m[:, 0], m[:, 1], m[:, 2]]).reshape((-1, 3))
    return np.vstack((positions, mid)), new_faces


def _to_radius(positions: np.ndarray, radius: float) -> np.ndarray:
    """Each point moved along its direction from the origin to ``radius`` (trimesh's step)."""
    scalar = np.sqrt(np.dot(positions ** 2, [1, 1, 1]))
    unit = positions / scalar.reshape((-1, 1))
    return positions + unit * (radius - scalar).reshape((-1, 1))


def icosphere(radius: float, subdivisions: int) -> Primitive:
    """A subdivided icosahedron on the sphere of ``radius``, mapped as the uv_sphere."""
    radius = float(radius)
    unit = {0: 0.0, 1: _ICOSAHEDRON_A, 2: _ICOSAHEDRON_B}
    positions = np.array([[np.sign(c) * unit[abs(c)] for c in row] for row in _ICOSAHEDRON_VERTICES], np.float64)
    faces = np.array(_ICOSAHEDRON_FACES, np.int64)
    for _ in range(int(subdivisions)):
        positions, faces = _subdivided(positions, faces)
        positions = _to_radius(positions, radius)
    if subdivisions <= 0:
        positions = _to_radius(positions, radius)
    corner = positions[faces]
    u = (np.arctan2(corner[..., 1], corner[..., 0]) / (2 * np.pi)) % 1.0
    length = np.linalg.norm(corner, axis=-1)
    v = np.arccos(np.clip(-corner[..., 2] / length, -1.0, 1.0)) / np.pi
    pole = np.hypot(corner[..., 0], corner[..., 1]) <= _POLE_FRACTION * length
    # seam: a triangle spanning more than half a turn wraps; its low corners move past 1
    spread = np.where(pole, -np.inf, u).max(axis=1) - np.where(pole, np.inf, u).min(axis=1)
    u = np.where((spread > 0.5)[:, None] & (u < 0.5), u + 1.0, u)
    others = np.where(pole, 0.0, u).sum(axis=1, keepdims=True) / np.maximum((~pole).sum(axis=1, keepdims=True), 1)
    u = np.where(pole, others, u)
    return _assemble(positions, faces, np.stack([u, v], axis=-1))


def make(kind: str, params: dict) -> Primitive:
    """The primitive ``kind`` with ``params`` (every parameter of meshes._PRIMITIVE_DEFAULTS)."""
    if kind == "icosphere":
        return icosphere(params["radius"], int(params["subdivisions"]))
    return {"box": box, "uv_sphere": uv_sphere, "cylinder": cylinder, "torus": torus, "plane": plane}[kind](**params)
