"""Depth resolution of three depth conventions, measured: the smallest decal offset
(relative to the base plane's size) at which a decal quad wins at every pixel it covers,
for plane sizes 0.1 .. 1e4 and three cameras. A benchmark: it prints the figures quoted in
harness/pbrlab/render/depth_range.py and asserts nothing.

    python benchmarks/depth_resolution.py

Conventions: GL depth in [-1, 1] with a 24-bit buffer and near = far * 1e-5 (pbrlab before
depth_range.py), the same with near and far around the plane's bounding sphere (what
depth_range.py chooses for a camera outside the scene), and reversed-Z (glClipControl
ZERO_TO_ONE, a DEPTH_COMPONENT32F buffer, depth test GREATER, cleared to 0) with
near = far * 1e-5. The EGL backend only (the GL entry points come from eglGetProcAddress).
"""

from __future__ import annotations

import ctypes
import math
import os

import moderngl
import numpy as np

from pbrlab.gpu import gl

SIZE = 128
GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F = 0x8D41, 0x8CAC
GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE, GL_ZERO_TO_ONE = 0x8CA1, 0x935E, 0x935F
CAMERAS = ((2.5, 0.0), (2.5, 60.0), (10.0, 30.0))  # distance / plane size, tilt from the normal


def _gl(name, *argtypes):
    egl = ctypes.CDLL(os.environ.get("GLCONTEXT_LINUX_LIBEGL", "libEGL.so.1"))
    egl.eglGetProcAddress.restype = ctypes.c_void_p
    egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
    return ctypes.CFUNCTYPE(None, *argtypes)(egl.eglGetProcAddress(name.encode()))


def _view_proj(dist, tilt_deg, near, far, reversed_z):
    t = math.radians(tilt_deg)
    eye = np.array([0.0, -dist * math.sin(t), dist * math.cos(t)])
    fwd = -eye / np.linalg.norm(eye)
    right = np.cross(fwd, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = right, up, -fwd
    view[:3, 3] = -view[:3, :3] @ eye
    proj = np.zeros((4, 4))
    proj[0, 0] = proj[1, 1] = 1 / math.tan(math.radians(22.5))
    proj[3, 2] = -1
    if reversed_z:  # eye depth near -> 1, far -> 0
        proj[2, 2], proj[2, 3] = near / (far - near), far * near / (far - near)
    else:
        proj[2, 2], proj[2, 3] = -(far + near) / (far - near), -2 * far * near / (far - near)
    return proj @ view


class Bench:
    def __init__(self):
        self.ctx = gl.shared_context("egl")
        self.clip_control = _gl("glClipControl", ctypes.c_uint, ctypes.c_uint)
        self.bind_rb = _gl("glBindRenderbuffer", ctypes.c_uint, ctypes.c_uint)
        self.rb_storage = _gl("glRenderbufferStorage", ctypes.c_uint, ctypes.c_uint, ctypes.c_int, ctypes.c_int)
        self.prog = self.ctx.program(
            vertex_shader="#version 330\nin vec3 p; uniform mat4 vp; void main() { gl_Position = vp * vec4(p, 1); }",
            fragment_shader="#version 330\nuniform vec4 c; out vec4 o; void main() { o = c; }")

    def lost_pixels(self, scale, dist_over, tilt, offset, mode) -> int:
        ctx, rz = self.ctx, mode == "reversed"
        dist = scale * dist_over
        far = (dist + scale * 0.75) * 1.05
        near = max((dist - scale * 0.75) / 1.05, far * 1e-5) if mode == "bounds" else max(far * 1e-5, 1e-4)
        depth = ctx.depth_renderbuffer((SIZE, SIZE))
        if rz:
            self.bind_rb(GL_RENDERBUFFER, depth.glo)
            self.rb_storage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, SIZE, SIZE)
        colour = ctx.renderbuffer((SIZE, SIZE), 4, dtype="f4")
        fbo = ctx.framebuffer([colour], depth)
        fbo.use()
        self.clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE if rz else GL_NEGATIVE_ONE_TO_ONE)
        ctx.enable(moderngl.DEPTH_TEST)
        ctx.depth_func = ">" if rz else "<"
        self.prog["vp"].write(_view_proj(dist, tilt, near, far, rz).T.astype("f4").tobytes())

        def draw(quads):
            for z, colour_, half in quads:
                quad = np.array([[-half, -half, z], [half, -half, z], [half, half, z],
                                 [-half, -half, z], [half, half, z], [-half, half, z]], "f4")
                vbo = ctx.buffer(quad.tobytes())
                vao = ctx.vertex_array(self.prog, [(vbo, "3f", "p")])
                self.prog["c"].value = colour_
                vao.render()
                vao.release()
                vbo.release()

        def read():
            return np.frombuffer(fbo.read(components=4, dtype="f4"), "f4").reshape(SIZE, SIZE, 4)

        decal = (offset * scale, (0, 1, 0, 1), scale * 0.3)
        ctx.clear(0, 0, 0, 0, depth=0.0 if rz else 1.0)
        draw([decal])
        covered = read()[..., 3] > 0
        ctx.clear(0, 0, 0, 0, depth=0.0 if rz else 1.0)
        draw([(0.0, (1, 0, 0, 1), scale / 2), decal])
        lost = int((read()[..., 0][covered] > 0).sum())
        self.clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE)
        ctx.depth_func = "<"
        for resource in (fbo, colour, depth):
            resource.release()
        return lost


def main() -> None:
    bench = Bench()
    modes = {"before": "near = far * 1e-5", "bounds": "near from bounds", "reversed": "reversed-Z float32"}
    for mode, label in modes.items():
        for scale in (0.1, 1.0, 100.0, 1e4):
            for dist_over, tilt in CAMERAS:
                best = None
                for k in range(4, 41):  # offsets 1e-1 .. 1e-10 of the plane, 4 per decade
                    offset = 10 ** (-k / 4)
                    if bench.lost_pixels(scale, dist_over, tilt, offset, mode):
                        break
                    best = offset
                shown = f"{best:.2g}" if best else "none of them"
                print(f"{label:18s} size {scale:<7g} camera {dist_over:g}x, {tilt:g} deg: smallest offset "
                      f"that holds {shown} of the plane")


if __name__ == "__main__":
    main()
