"""A shadow map for one directional light (the environment's sun: scene/environment_sun.py,
render.environment_sun): a depth pass of the scene's meshes seen along the light, read back by
the scene programs with percentage-closer filtering (scene_lighting.inc, pbrlab_sun_visibility).

Projection: orthographic along the light, fitted to the world-space bounding boxes of every
object (depth_range._object_box): the light's frame (u, v across, w along the way light
travels, so depth grows away from the sun) spans their corners' extent, padded by
PAD_TEXELS texels on each side so that the filter's taps stay inside. A point p maps to
(dot(p - origin, U), dot(p - origin, V), dot(p - origin, W)) in [0, 1]^3, with U, V, W the
axes divided by the extent: what the depth pass writes (depth = W's coordinate, exactly
linear) and what the shader reads. The map's texel footprint is t = extent / size (world units).

Filter and bias: 3 x 3 taps one texel apart, nearest, averaged (PCF; Reeves et al. 1987). A tap
reads the depth the rasteriser stored at a texel's centre: up to 1.5 sqrt(2) t = 2.12 t
sideways from the shaded point (its own texel's corner, plus one texel). Over that distance a
plane tilted by theta from facing the light falls by 2.12 t tan(theta) along the light, and a
point moved off the plane by delta along its normal stands delta / cos(theta) above it along
the light: delta = NORMAL_OFFSET_TEXELS t sin(theta) (normal offset, Holbrook 2011) clears every
tap of a planar receiver, at every tilt. DEPTH_BIAS_TEXELS t more, along the light, absorbs what
is not planar (a smooth-shaded mesh's interpolated normal against its faces' planes). The
shadow's edge is then where float64 geometry puts it, to within the filter's reach plus the
offset: at most (1 + 1.5 sqrt 2 + NORMAL_OFFSET_TEXELS) t sideways
(tests/render/test_environment_sun.py measures it on a plane under an occluder).

Casters: every mesh object whose material is not blended and whose program does not move its
vertices (their positions are the mesh's); ray-traced spheres cast none. Two-sided (no culling):
a closed mesh's back faces are its shadow too.
"""

from __future__ import annotations

from dataclasses import dataclass

import moderngl
import numpy as np

from .depth_range import _moves_vertices, _object_box
from . import instanced_draws
from ..scene import meshes
from ..scene.standard_material import BLENDED_ALPHA_MODES

# texels per side: the fidelity benchmark frames each model (its bounds span about the view) at
# 384 drawn pixels (192 x supersample 2), so a texel is about a fifth of a drawn pixel and the
# shadow edge's whole uncertainty (the filter's reach plus the offsets, 5.2 texels: module doc)
# about one pixel; memory 16 MiB (32-bit depth)
SHADOW_MAP_SIZE = 2048
PAD_TEXELS = 4.0             # around the casters' extent: the 3x3 filter reaches 1.5 texels out
NORMAL_OFFSET_TEXELS = 1.5 * np.sqrt(2.0)   # the taps' farthest reach (module doc), in texels
DEPTH_BIAS_TEXELS = 1.0      # what is not planar (module doc), in texels

_VERTEX = """#version 330 core
in vec3 in_position;
uniform mat4 u_model;
uniform vec3 u_origin;
uniform vec3 u_axes[3];
void main() {
    vec3 q = (u_model * vec4(in_position, 1.0)).xyz - u_origin;
    gl_Position = vec4(dot(q, u_axes[0]) * 2.0 - 1.0, dot(q, u_axes[1]) * 2.0 - 1.0,
                       dot(q, u_axes[2]) * 2.0 - 1.0, 1.0);
}
"""
_FRAGMENT = """#version 330 core
void main() {}
"""


def casters(scene) -> list:
    """The objects that cast the sun's shadow (module doc)."""
    out = []
    for obj in scene.objects:
        material = scene.materials.get(obj.material)
        if obj.sphere is not None or material is None:
            continue
        if material.alpha_mode in BLENDED_ALPHA_MODES or _moves_vertices(material):
            continue
        out.append(obj)
    return out


@dataclass(frozen=True)
class LightFrame:
    """The orthographic projection along the light (module doc)."""
    origin: np.ndarray   # world point mapped to (0, 0, 0)
    axes: np.ndarray     # 3x3 rows U, V, W: world -> [0, 1]^3 after subtracting origin
    texel: float         # t: world size of one texel across the light
    size: int

    def project(self, points: np.ndarray) -> np.ndarray:
        """(u, v, depth) in [0, 1] of world points (float64)."""
        return (np.asarray(points, np.float64) - self.origin) @ self.axes.T


def light_frame(scene, direction, size: int = SHADOW_MAP_SIZE) -> LightFrame | None:
    """The frame fitted to ``scene``'s objects for light travelling along ``direction``."""
    objects = list(scene.objects)  # casters and receivers: every one inside the map
    if not objects:
        return None
    corners = np.concatenate([_object_box(o) for o in objects])
    w = np.asarray(direction, np.float64)
    w = w / np.linalg.norm(w)
    helper = np.array([0.0, 1.0, 0.0]) if abs(w[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(helper, w)
    u /= np.linalg.norm(u)
    v = np.cross(w, u)
    basis = np.stack([u, v, w])
    local = corners @ basis.T
    lo, hi = local.min(axis=0), local.max(axis=0)
    across = float(max(hi[0] - lo[0], hi[1] - lo[1], 1e-6))
    extent = across * size / (size - 2 * PAD_TEXELS)  # the padding inside the map's size
    texel = extent / size
    centre = (lo + hi) / 2
    depth_pad = 4 * texel  # the depth range: the casters' own, plus the bias's reach
    lo_w, hi_w = lo[2] - depth_pad, hi[2] + depth_pad
    origin_local = np.array([centre[0] - extent / 2, centre[1] - extent / 2, lo_w])
    axes = np.stack([u / extent, v / extent, w / (hi_w - lo_w)])
    return LightFrame(origin=origin_local @ basis, axes=axes, texel=texel, size=size)


def draw_depth(ctx: moderngl.Context, scene, frame: LightFrame, fbo, viewport=None, objects=None,
               single_sided: bool = False) -> None:
    """The casters' depth along ``frame``'s light into ``fbo``'s depth attachment, within
    ``viewport`` (x, y, w, h; the whole target when None): one tile of an atlas of maps
    (render/environment_visibility.py) or a whole map; ``objects``: the casters (``casters``
    when None). ``single_sided``: a material that is not double-sided casts only from the faces
    that face the light (a rasteriser does not draw a single-sided face seen from behind; a closed
    mesh still has a face towards the light on every ray through it). The frame's axes (u, v, w)
    are right-handed with w into the map, so a face whose normal points at the light (along -w)
    winds clockwise there. The caller clears it first."""
    program = ctx.program(vertex_shader=_VERTEX, fragment_shader=_FRAGMENT)
    try:
        fbo.use()
        if viewport is not None:
            fbo.viewport = viewport
        ctx.enable(moderngl.DEPTH_TEST)
        ctx.disable(moderngl.CULL_FACE | moderngl.BLEND)
        ctx.depth_func = "<"
        program["u_origin"].value = tuple(frame.origin)
        program["u_axes"].write(np.ascontiguousarray(frame.axes, np.float32).tobytes())
        for obj in casters(scene) if objects is None else objects:
            material = scene.materials[obj.material]
            if single_sided and not material.double_sided:
                ctx.enable(moderngl.CULL_FACE)
                ctx.front_face, ctx.cull_face = "cw", "back"
            else:
                ctx.disable(moderngl.CULL_FACE)
            program["u_model"].value = tuple(instanced_draws.model_matrix(obj.transform))
            vao, buffers = meshes.vertex_array(ctx, program, obj)
            topology = "triangles" if obj.geometry is None else obj.geometry.topology
            if topology == "triangles":
                vao.render(moderngl.TRIANGLES)
            for resource in [vao, *buffers]:
                resource.release()
    finally:
        ctx.front_face = "ccw"
        ctx.disable(moderngl.CULL_FACE)
        program.release()


class ShadowMap:
    """The depth of the casters seen along the light (a depth texture), and its uniforms."""

    def __init__(self, ctx: moderngl.Context, scene, frame: LightFrame):
        self.frame = frame
        self.texture = ctx.depth_texture((frame.size, frame.size))
        self.texture.compare_func = ""  # read the stored depth, compared in the shader
        self.texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
        self.texture.repeat_x = self.texture.repeat_y = False
        fbo = ctx.framebuffer(depth_attachment=self.texture)
        try:
            fbo.use()
            ctx.clear(depth=1.0)
            draw_depth(ctx, scene, frame, fbo)
        finally:
            fbo.release()

    def uniforms(self) -> dict:
        f = self.frame
        extent_depth = 1.0 / float(np.linalg.norm(f.axes[2]))
        return {"u_sun_shadow_origin": tuple(f.origin), "u_sun_shadow_u": tuple(f.axes[0]),
                "u_sun_shadow_v": tuple(f.axes[1]), "u_sun_shadow_w": tuple(f.axes[2]),
                # (normal offset in world units, depth bias in depth units, one texel in uv)
                "u_sun_shadow_bias": (NORMAL_OFFSET_TEXELS * f.texel, DEPTH_BIAS_TEXELS * f.texel / extent_depth,
                                      1.0 / f.size)}

    def release(self):
        self.texture.release()


class SunShadow:
    """The environment's sun's shadow map for one render, and how a program reads it."""

    def __init__(self, ctx: moderngl.Context, scene, sun):
        self.sun = sun
        frame = light_frame(scene, sun.direction)
        self.map = ShadowMap(ctx, scene, frame)

    def bind(self, program, unit: int) -> None:
        from ..gpu.programs import set_uniform
        if program.get("u_sun_shadow_map", None) is None:
            return  # a program without the sun (an unlit material)
        self.map.texture.use(unit)
        set_uniform(program, "u_sun_shadow_map", unit)
        for name, value in self.map.uniforms().items():
            set_uniform(program, name, value)
        set_uniform(program, "u_sun_angular_radius", float(self.sun.angular_radius))

    def release(self):
        self.map.release()
