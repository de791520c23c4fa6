"""The mesh a sphere becomes when its material's surface shader has a ``vertex:`` function.

Spheres are ray-traced per pixel (render.py), which has no vertices for a vertex function to
move; such a sphere is drawn instead as this UV sphere, whose object space is the unit sphere
(unity_ObjectToWorld = translate(centre) * scale(radius), as program.object_matrix) and whose
UVs are the ray-traced sphere's (pbr_equirect_uv of the normal; the seam column duplicated),
so a surface shader sees the same Input on both. Tangents: meshes.tangents (Lengyel 2001).
"""

from __future__ import annotations

from functools import lru_cache

import moderngl
import numpy as np

from ...scene import meshes

SEGMENTS = (256, 128)  # longitude x latitude quads: 0.7 degree steps; at 512 px across a
                       # sphere the polygon's silhouette departs from the circle by < 0.02 px


@lru_cache(maxsize=2)
def sphere_arrays(segments=SEGMENTS):
    """(positions, normals, uvs, tangents, indices) of the unit UV sphere, float32 / int32."""
    nu, nv = segments
    u = np.linspace(0.0, 1.0, nu + 1)
    v = np.linspace(0.0, 1.0, nv + 1)
    uu, vv = np.meshgrid(u, v)                      # [row v, column u]
    phi, theta = 2.0 * np.pi * uu, (1.0 - vv) * np.pi  # pbr_equirect_direction
    p = np.stack([np.sin(theta) * np.sin(phi), np.cos(theta), -np.sin(theta) * np.cos(phi)], -1).reshape(-1, 3)
    uv = np.stack([uu, vv], -1).reshape(-1, 2)
    idx = np.arange((nu + 1) * (nv + 1)).reshape(nv + 1, nu + 1)
    a, b, c, d = idx[:-1, :-1], idx[:-1, 1:], idx[1:, :-1], idx[1:, 1:]
    faces = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3), np.stack([a, d, c], -1).reshape(-1, 3)])
    e1, e2 = p[faces[:, 1]] - p[faces[:, 0]], p[faces[:, 2]] - p[faces[:, 0]]
    centre = p[faces].mean(axis=1)
    area = np.linalg.norm(np.cross(e1, e2), axis=1)
    faces = faces[area > 1e-12]                      # the poles' collapsed triangles
    e1, e2 = p[faces[:, 1]] - p[faces[:, 0]], p[faces[:, 2]] - p[faces[:, 0]]
    centre = p[faces].mean(axis=1)
    inward = np.sum(np.cross(e1, e2) * centre, axis=1) < 0
    faces[inward] = faces[inward][:, ::-1]          # counter-clockwise seen from outside
    tan = meshes.tangents(p, p, uv, faces)
    return (p.astype(np.float32), p.astype(np.float32), uv.astype(np.float32), tan.astype(np.float32),
            faces.astype(np.int32).reshape(-1))


def sphere_vertex_array(ctx: moderngl.Context, program):
    """A VertexArray of the unit UV sphere on ``program``, plus its buffers to release."""
    positions, normals, uv, tan, indices = sphere_arrays()
    white = np.ones((len(positions), 4))  # no vertex colours: Unity's white; the one UV set twice
    data = np.concatenate([positions, normals, uv, tan, uv, white], axis=1).astype(np.float32)
    vbo, ibo = ctx.buffer(data.tobytes()), ctx.buffer(indices.tobytes())
    fmt, layout = [], []
    for name, f in [("in_position", "3f"), ("in_normal", "3f"), ("in_uv", "2f"), ("in_tangent", "4f"),
                    ("in_uv1", "2f"), ("in_color", "4f")]:
        if program.get(name, None) is not None:
            fmt.append(f)
            layout.append(name)
        else:
            fmt.append(f[0] + "x4")
    vao = ctx.vertex_array(program, [(vbo, " ".join(fmt), *layout)], index_buffer=ibo)
    return vao, [vbo, ibo]
