"""The depth range of a render: near and far planes from what the camera sees of the scene.

A 24-bit depth buffer resolves eye depth z in steps of z^2 (1/near - 1/far) / 2^24, so the
near plane sets the precision. It used to be far * 1e-5 whatever the scene; it is now the
nearest point of the scene's bounds inside the view frustum (each object's oriented
bounding box clipped to the frustum; the object's own triangles where the camera is inside
that box), and far the farthest such point (camera.NEAR_FAR_MARGIN around both).

Measured (benchmarks/depth_resolution.py: decal quads above a base plane, 128x128, Mesa
llvmpipe 22.3; the smallest offset, relative to the plane's size, at which the decal wins
at every pixel it covers; plane sizes 0.1, 1, 100, 1e4, camera at 2.5x the size head-on and tilted 60 degrees, at 10x
tilted 30 degrees):
    near = far * 1e-5, 24-bit (before)         5.6e-6 .. 5.6e-2 (0.01 units at 5 units z-fights)
    near from the bounds, 24-bit (this)        5.6e-8 .. 5.6e-7
    reversed-Z, 32-bit float, near = far*1e-5  3.2e-8 .. 1.0e-6
At the sample models' framing (their distance z to the target) the 24-bit step
z^2 (1/near - 1/far) / 2^24, before -> now, and reversed-Z's float32 step z * 2^-23, in units:
    TextureTransformTest (z 5.57)   1.9e-2 -> 7.5e-8   (reversed-Z 6.6e-7)
    AlphaBlendModeTest   (z 13.0)   5.5e-2 -> 2.0e-7   (reversed-Z 1.5e-6)
    NegativeScaleTest    (z 19.6)   8.2e-2 -> 3.0e-7   (reversed-Z 2.3e-6)
against their 0.01-unit decal offsets.
Reversed-Z is as precise with the camera outside the scene and also inside it, but needs
glClipControl (GL 4.5), a float depth attachment moderngl does not make, and a reversed
clip space that every Unity shader sees (UNITY_MATRIX_P, _ZBufferParams, LinearEyeDepth,
UNITY_REVERSED_Z); bounds keep GL's clip space, so every program (rasterised meshes, the
ray-traced spheres' gl_FragDepth, Unity passes and their ZTest) is unchanged: they all read
the one CameraFrame. Where the camera is inside geometry's bounds and its triangles reach
the eye, near falls back to far * 1e-5, and so it does when any object's material moves its
vertices in a program of its own (a Unity `vertex:` function, a vertex/fragment pass): the
mesh's bounds say nothing of where such a program puts it (normal extrusion pushed a sphere's
front through a near plane set from its undisplaced box), unless a program reads the camera's
depth texture (render/camera_textures.py): then near is its engine's camera near plane
(Unity's 0.3, clipping what Unity's camera clips), as that texture's precision is the near
plane's (a window depth z resolves eye depth e to within e^2 / near * dz: at the corpus
scene's e = 2.2 and the fallback's near = 1e-4, a float32 depth's dz = 2^-24 is 1.3e-3 of the
depth; at near 0.3, 4.4e-7). A scene with a Unity shader keeps
a near plane no farther than Unity's default camera's (its material source's camera_near,
importers/unity/material.py's UNITY_CAMERA_NEAR): its programs read
the planes (`_ProjectionParams`, `_ZBufferParams`, `unity_CameraInvProjection`), and one that
fades what lies near the near plane (Sebastian Lague's Stipple) faded the whole sphere away
when near sat just in front of it.

Before any of that, ``check_float32_reach`` refuses (naming the object) a scene the GPU
cannot draw: bounds finite in float64 but not in float32 (a mesh of size 1e30 scaled by
1e30), or an object so far from the camera that the squared distances the shaders take in
float32 overflow (a sphere at 1e30 drew as a dim screen-filling disc).
"""

from __future__ import annotations

import numpy as np

from . import camera_textures
from ..scene import meshes
from ..maths.camera import NEAR_FAR_MARGIN, CameraFrame, camera_frame
from ..foundation.errors import SceneError
from ..foundation.json_input import FLOAT32_MAX

# Above this many triangles an object is bounded by its box only (the triangle test is
# numpy work over every triangle, about 1 s per million).
MAX_REFINED_TRIANGLES = 200_000
_BOX_FACES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                       [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
_CORNERS = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float64)


def scene_radius(scene) -> float:
    """A radius around the camera target that holds every object (the fallback depth range)."""
    radius = 1.0
    for obj in scene.objects:
        if obj.sphere is not None:
            centre, r = obj.sphere
        else:
            centre = obj.transform[:3, :3] @ meshes.local_centre(obj) + obj.transform[:3, 3]
            r = meshes.bounding_radius(obj)
        radius = max(radius, float(np.linalg.norm(centre - scene.camera.target)) + r)
    return radius


def check_float32_reach(scene, frame: CameraFrame) -> None:
    """Refuse, naming the object, one whose world-space bounds are not finite in float32, or
    whose farthest point is beyond ``reach``: the shaders square distances from the camera in
    float32 (the ray-traced sphere |(camera - centre) x D|^2 with the unnormalised pixel ray
    D, a mesh's view and light vectors in normalize()), which overflow past
    sqrt(FLOAT32_MAX) / |D| (|D| <= |forward + right + up|, the frustum's corner ray)."""
    corner_ray = max(1.0, float(np.linalg.norm(frame.forward + frame.right + frame.up)))
    reach = float(np.sqrt(FLOAT32_MAX)) / corner_ray
    for index, obj in enumerate(scene.objects):
        name = obj.where or f"objects[{index}]"
        with np.errstate(over="ignore", invalid="ignore"):
            box = _object_box(obj)
            largest = float(np.abs(box).max())
            farthest = float(np.linalg.norm(box - frame.position, axis=1).max())
        if not largest <= FLOAT32_MAX:
            raise SceneError(f"{name}: its world-space bounds reach {largest:.3g}: finite in float64, "
                             f"not in float32 (|x| <= {FLOAT32_MAX:.8g}), which the GPU computes in "
                             "(a huge mesh or scale)")
        if not farthest <= reach:
            raise SceneError(f"{name}: reaches {farthest:.3g} from the camera; the shaders square "
                             f"distances in float32, which overflows beyond {reach:.3g} at this "
                             "camera's field of view (move the object or the camera nearer, or "
                             "scale the scene down)")


def scene_frame(scene) -> CameraFrame:
    """The camera frame every renderer of ``scene`` uses: planes from the visible bounds."""
    radius = scene_radius(scene)
    frame = camera_frame(scene.camera, radius)
    check_float32_reach(scene, frame)
    if scene.camera.ortho_half_height is not None:
        return frame  # linear depth: (far - near) / 2^24 everywhere, precise already
    if any(_moves_vertices(scene.materials.get(obj.material)) for obj in scene.objects):
        # its geometry is where its program puts it, not where its bounds are: as far as its
        # engine's camera draws (a billboard its program pushes past the mesh's far side)
        far = max([frame.far] + _engine_fars(scene))
        if camera_textures.needed(scene):  # a program reads the camera's depth: its engine's near plane
            return camera_frame(scene.camera, radius, (_engine_near(scene) * NEAR_FAR_MARGIN, far / NEAR_FAR_MARGIN))
        if far > frame.far:
            return camera_frame(scene.camera, radius, (frame.near * NEAR_FAR_MARGIN, far / NEAR_FAR_MARGIN))
        return frame
    depths = visible_depths(scene, frame)
    if depths is None:
        return frame
    nears = [source.camera_near for source in (getattr(scene.materials.get(obj.material), "source", None)
                                               for obj in scene.objects)
             if source is not None and source.camera_near is not None]
    if nears:  # a shader that reads the camera's planes expects its engine's near plane or nearer
        depths = (min(depths[0], min(nears) * NEAR_FAR_MARGIN), depths[1])
    return camera_frame(scene.camera, radius, depths)


def _engine_near(scene) -> float:
    """The nearest camera near plane the scene's material sources ask for (Unity's 0.3)."""
    nears = [source.camera_near for source in (getattr(scene.materials.get(obj.material), "source", None)
                                               for obj in scene.objects)
             if source is not None and source.camera_near is not None]
    return min(nears) if nears else scene_radius(scene) * 1e-5


def _engine_fars(scene) -> list[float]:
    """The far planes the material sources of objects whose programs move vertices ask for
    (Unity's 1000: importers/unity/material.py's UNITY_CAMERA_FAR)."""
    sources = (getattr(scene.materials.get(obj.material), "source", None) for obj in scene.objects)
    return [source.camera_far for source in sources
            if source is not None and source.moves_vertices and getattr(source, "camera_far", None) is not None]


def visible_depths(scene, frame: CameraFrame) -> tuple[float, float] | None:
    """(nearest, farthest) eye depth of the scene's bounds inside the view frustum, or
    None when no bound reaches into it."""
    lo, hi = np.inf, -np.inf
    for obj in scene.objects:
        box = _object_box(obj)
        found = _triangle_depths(box[_BOX_FACES], frame)
        if found is None:
            continue
        near, far = found
        if near < far * 1e-3 and obj.sphere is None:  # the camera is in (or at) the box
            triangles = _object_triangles(obj)
            if triangles is not None:
                near = (_triangle_depths(triangles, frame) or (near, far))[0]
        if obj.sphere is not None:  # no point of a sphere is nearer than its distance
            centre, radius = obj.sphere
            near = max(near, (float(np.linalg.norm(centre - frame.position)) - radius) * _cos_corner(frame))
        lo, hi = min(lo, near), max(hi, far)
    return None if hi < lo else (max(lo, 0.0), hi)


def _moves_vertices(material) -> bool:
    """Whether a program of the material's own places its vertices (bounds do not hold)."""
    source = getattr(material, "source", None)
    return source is not None and source.moves_vertices


def _cos_corner(frame) -> float:
    """Cosine of the angle between the view axis and the frustum's corner rays."""
    corner = np.linalg.norm(frame.right + frame.up)
    return float(1.0 / np.sqrt(1.0 + corner * corner))


def _object_box(obj) -> np.ndarray:
    """The 8 world-space corners of the object's local bounding box."""
    if obj.sphere is not None:
        centre, radius = obj.sphere
        return np.asarray(centre, np.float64) + (2 * _CORNERS - 1) * radius
    positions = np.asarray(meshes.mesh_data(obj).arrays[0], np.float64)
    lo, hi = positions.min(axis=0), positions.max(axis=0)
    local = lo + _CORNERS * (hi - lo)
    return local @ obj.transform[:3, :3].T + obj.transform[:3, 3]


def _object_triangles(obj) -> np.ndarray | None:
    arrays = meshes.mesh_data(obj).arrays
    indices = np.asarray(arrays[4]).reshape(-1, 3)
    if len(indices) > MAX_REFINED_TRIANGLES:
        return None
    world = np.asarray(arrays[0], np.float64) @ obj.transform[:3, :3].T + obj.transform[:3, 3]
    return world[indices]


def _triangle_depths(triangles: np.ndarray, frame: CameraFrame) -> tuple[float, float] | None:
    """Least and greatest eye depth of the triangles (Tx3x3 world) clipped to the frustum.
    Depth is linear on a triangle, so both lie at vertices of the clipped polygons: the
    triangles' vertices inside the frustum, their edges' crossings of the four side planes
    inside it, and the frustum's corner rays through the triangles."""
    tx = float(np.linalg.norm(frame.right)) * 1.001  # a hair wide: never nearer than needed
    ty = float(np.linalg.norm(frame.up)) * 1.001
    basis = np.stack([frame.right / np.linalg.norm(frame.right), frame.up / np.linalg.norm(frame.up),
                      frame.forward])
    q = (triangles - frame.position) @ basis.T  # eye coordinates: x right, y up, d forward
    planes = np.array([[-1, 0, tx], [1, 0, tx], [0, -1, ty], [0, 1, ty]], np.float64)  # >= 0 inside

    def inside(points):
        slack = 1e-9 * np.abs(points).sum(axis=-1, keepdims=True)
        return ((points @ planes.T) >= -slack).all(axis=-1)

    depths = [q[..., 2][inside(q)]]
    for a, b in ((0, 1), (1, 2), (2, 0)):
        p0, p1 = q[:, a], q[:, b]
        s0, s1 = p0 @ planes.T, p1 @ planes.T  # T x 4
        crossing = (s0 * s1) < 0
        t = np.where(crossing, s0 / np.where(crossing, s0 - s1, 1.0), 0.0)
        points = p0[:, None] + t[..., None] * (p1 - p0)[:, None]  # T x 4 x 3
        depths.append(points[..., 2][crossing & inside(points)])
    for sx in (-tx, tx):
        for sy in (-ty, ty):
            depths.append(_ray_hits(q, np.array([sx, sy, 1.0])))
    depths = np.concatenate(depths)
    if depths.size == 0:
        return None
    return float(depths.min()), float(depths.max())


def _ray_hits(q: np.ndarray, direction: np.ndarray) -> np.ndarray:
    """Depths at which the ray from the eye along ``direction`` (depth component 1) meets
    the triangles (Moller-Trumbore, edges included)."""
    e1, e2 = q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]
    p = np.cross(direction, e2)
    det = (e1 * p).sum(axis=1)
    ok = np.abs(det) > 1e-300
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = -q[:, 0]
    u = (s * p).sum(axis=1) * inv
    qv = np.cross(s, e1)
    v = (qv @ direction) * inv
    t = (e2 * qv).sum(axis=1) * inv
    eps = 1e-9
    hit = ok & (u >= -eps) & (v >= -eps) & (u + v <= 1 + eps) & (t > 0)
    return t[hit]
