"""One pass before the frame that stores, per drawn pixel, the world position of the nearest face
of some objects and an id (the object's material's number, 0 where none was drawn): what a search
along a ray in the shader compares the ray's points with (templates/ray_march.inc).

Two users: the volumes' back faces (volume_exit.py, render.volume_chord: front faces culled) and
the frame's own surfaces for its screen-space reflections (screen_space_reflection.py: nothing
culled). Drawn at the frame's size with the frame's view-projection, depth-tested nearest-first,
into a nearest-sampled RGBA32F texture (position, id); the importers wind every front face
counter-clockwise (a mirroring node's triangles turned round).

    texture = draw_face_positions(ctx, frame, objects, ids, cull="front")   # ids: material -> float
"""

from __future__ import annotations

import moderngl
import numpy as np

from . import instanced_draws
from .depth_range import _moves_vertices
from ..gpu.programs import set_uniform
from ..scene import meshes

_VERTEX = """#version 330 core
in vec3 in_position;
uniform mat4 u_model, u_view_proj;
out vec3 v_world;  // the face's world position, what the pass stores
void main() {
    v_world = (u_model * vec4(in_position, 1.0)).xyz;
    gl_Position = u_view_proj * vec4(v_world, 1.0);
}
"""
_FRAGMENT = """#version 330 core
in vec3 v_world;
uniform float u_id;
out vec4 out_position;
void main() {
    out_position = vec4(v_world, u_id);
}
"""


def drawable(scene, obj) -> bool:
    """Whether the pass can draw ``obj``: a triangle mesh whose program leaves its vertices where
    its mesh has them (ray-traced spheres, lines and points, and programs that move vertices are
    not drawn: their pixels keep id 0)."""
    if obj.sphere is not None or _moves_vertices(scene.materials[obj.material]):
        return False
    return obj.geometry is None or obj.geometry.topology == "triangles"


def draw_face_positions(ctx: moderngl.Context, frame, objects, ids: dict, cull: str | None) -> moderngl.Texture:
    """The texture (module doc) of ``objects`` seen from ``frame``; ``ids``: material name -> id
    (> 0); ``cull``: "front", "back" or None (both sides drawn)."""
    size = tuple(int(s) for s in frame.size)
    texture = ctx.texture(size, 4, dtype="f4")
    texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
    texture.repeat_x = texture.repeat_y = False
    depth = ctx.depth_renderbuffer(size)
    fbo = ctx.framebuffer([texture], depth)
    program = ctx.program(vertex_shader=_VERTEX, fragment_shader=_FRAGMENT)
    try:
        fbo.use()
        ctx.viewport = (0, 0) + size
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)  # id 0: nothing drawn
        ctx.disable(moderngl.BLEND)
        ctx.enable(moderngl.DEPTH_TEST)
        ctx.depth_func = "<"
        if cull is not None:
            ctx.enable(moderngl.CULL_FACE)
            ctx.front_face, ctx.cull_face = "ccw", cull
        set_uniform(program, "u_view_proj", tuple(np.asarray(frame.view_proj, np.float64).T.reshape(-1)))
        for obj in objects:
            set_uniform(program, "u_id", ids[obj.material])
            set_uniform(program, "u_model", tuple(instanced_draws.model_matrix(obj.transform)))
            vao, buffers = meshes.vertex_array(ctx, program, obj)
            try:
                vao.render(moderngl.TRIANGLES)
            finally:  # released if the draw fails too
                for resource in (vao, *buffers):
                    resource.release()
    except BaseException:
        texture.release()
        raise
    finally:
        ctx.disable(moderngl.CULL_FACE | moderngl.DEPTH_TEST)
        ctx.cull_face = "back"
        program.release()
        fbo.release()
        depth.release()
    return texture


def read_texture(texture: moderngl.Texture) -> np.ndarray:
    """The texture, top row first (HxWx4 float32: position, id), for the tests."""
    data = np.frombuffer(texture.read(), np.float32).reshape(texture.height, texture.width, 4)
    return data[::-1].copy()
