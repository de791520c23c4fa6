"""Checking the prefiltered environment (gpu/ibl.py) as the shaders read it, against the float64
brute force (maths/reference/prefilter.py): the directions that exercise it (poles, the u = 0
seam, around the brightest texel, random), a GPU lookup through textureLod on the cube at a
given level, and the cube-face coordinates that the bilinear reconstruction works in.
Used by tests/render/test_prefiltered_environment.py and benchmarks/prefilter_accuracy.py.
"""

from __future__ import annotations

import moderngl
import numpy as np

from ..gpu import shaders, targets
from ..gpu.programs import template_source
from ..maths.reference import prefilter as ref_prefilter

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # ITU-R BT.709 (the library's pbr_luminance)

_LOOKUP = """#version 330 core
uniform samplerCube u_env;
uniform sampler2D u_dirs;
uniform float u_lod;
out vec4 out_radiance;
void main() {
    vec3 d = texelFetch(u_dirs, ivec2(gl_FragCoord.xy), 0).xyz;
    out_radiance = vec4(textureLod(u_env, d, u_lod).rgb, 1.0);
}
"""


def ring(center: np.ndarray, radius_deg: float, count: int) -> np.ndarray:
    """count unit directions at radius_deg degrees around the unit direction center."""
    c = np.asarray(center, np.float64) / np.linalg.norm(center)
    a = np.array([1.0, 0.0, 0.0]) if abs(c[0]) < 0.9 else np.array([0.0, 0.0, 1.0])
    t = np.cross(c, a)
    t /= np.linalg.norm(t)
    b = np.cross(c, t)
    phi = np.arange(count) / count * 2.0 * np.pi
    r = np.radians(radius_deg)
    return np.cos(r) * c + np.sin(r) * (np.cos(phi)[:, None] * t + np.sin(phi)[:, None] * b)


def brightest_direction(image: np.ndarray) -> np.ndarray:
    h, w = image.shape[:2]
    j, i = np.unravel_index(np.asarray(image[..., :3], np.float64).sum(-1).argmax(), (h, w))
    return ref_prefilter.equirect_direction((i + 0.5) / w, 1.0 - (j + 0.5) / h)


def direction_sets(image: np.ndarray, random_count: int = 400, seed: int = 38, ring_count: int = 16) -> dict[str, np.ndarray]:
    """Unit directions (N, 3) by name: "poles" (both poles and rings at 0.5 .. 20 degrees around
    them, where the equirect image pinches), "seam" (elevations -60 .. 60 at azimuths within a
    degree of u = 0), "sun" (the brightest texel and rings at 1 .. 30 degrees around it),
    "random" (uniform on the sphere)."""
    up, down = np.array([0.0, 1.0, 0.0]), np.array([0.0, -1.0, 0.0])
    poles = np.concatenate([up[None], down[None]] + [ring(p, r, ring_count) for p in (up, down) for r in (0.5, 2, 5, 10, 20)])
    el = np.radians(np.array([-60.0, -30.0, -5.0, 0.0, 5.0, 30.0, 60.0]))
    az = np.radians(np.array([-1.0, -0.1, 0.0, 0.1, 1.0]))
    E, A = np.meshgrid(el, az)
    seam = np.stack([np.cos(E) * np.sin(A), np.sin(E), -np.cos(E) * np.cos(A)], -1).reshape(-1, 3)
    sun = brightest_direction(image)
    suns = np.concatenate([sun[None]] + [ring(sun, r, max(ring_count * 3 // 4, 4)) for r in (1, 3, 10, 30)])
    rnd = np.random.default_rng(seed).normal(size=(random_count, 3))
    rnd /= np.linalg.norm(rnd, axis=1, keepdims=True)
    return {"poles": poles, "seam": seam, "sun": suns, "random": rnd}


def cube_lookup(ctx: moderngl.Context, cube: moderngl.TextureCube, directions: np.ndarray, lod: float) -> np.ndarray:
    """textureLod(cube, d, lod).rgb at each direction (N, 3) -> (N, 3) float64, as the scene
    programs read the prefiltered environment (PBRLAB_SAMPLE_TEXCUBE_LOD)."""
    program = shaders.build_program(ctx, template_source("fullscreen.vert", {}), shaders.expand(_LOOKUP))
    n = len(directions)
    dirs = ctx.texture((n, 1), 4, np.concatenate([directions, np.zeros((n, 1))], 1).astype("f4").tobytes(), dtype="f4")
    dirs.filter = (moderngl.NEAREST, moderngl.NEAREST)
    vao = ctx.vertex_array(program, [])
    try:
        with targets.Target(ctx, (n, 1), "f32", depth=False) as target:
            target.use()
            cube.use(0)
            dirs.use(1)
            program["u_env"].value = 0
            program["u_dirs"].value = 1
            program["u_lod"].value = float(lod)
            vao.render(moderngl.TRIANGLES, vertices=3)
            return target.read()[0, :, :3].astype(np.float64)
    finally:
        vao.release()
        dirs.release()


def face_coordinates(d: np.ndarray):
    """(face, sc, tc) of unit directions (N, 3): the inverse of OpenGL 4.6's table 8.19 as
    maths/reference/prefilter.py cube_face_directions writes it (faces +X, -X, +Y, -Y, +Z, -Z;
    sc, tc in [-1, 1])."""
    d = np.asarray(d, np.float64)
    axis = np.abs(d).argmax(axis=1)
    sign = np.take_along_axis(d, axis[:, None], 1)[:, 0] < 0
    face = 2 * axis + sign
    x, y, z = d[:, 0], d[:, 1], d[:, 2]
    m = np.abs(np.take_along_axis(d, axis[:, None], 1)[:, 0])
    sc = np.choose(face, [-z, z, x, x, x, -x]) / m
    tc = np.choose(face, [-y, -y, z, -z, -y, -y]) / m
    return face, sc, tc


def face_direction(face: np.ndarray, sc: np.ndarray, tc: np.ndarray) -> np.ndarray:
    """The unit direction of face coordinates (sc, tc) on a face's plane (table 8.19; the
    plane extends past the face's edge, so offsets of a texel or two stay well defined)."""
    one = np.ones_like(sc)
    candidates = np.stack([np.stack(f, -1) for f in (
        (one, -tc, -sc), (-one, -tc, sc), (sc, one, tc), (sc, -one, -tc), (sc, -tc, one), (-sc, -tc, -one))])
    d = candidates[face, np.arange(len(face))]
    return d / np.linalg.norm(d, axis=1, keepdims=True)
