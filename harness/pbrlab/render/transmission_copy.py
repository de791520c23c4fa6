"""The transmission copy of the scene: what a transmissive material sees behind it.

As the Khronos glTF Sample Viewer does (source/Renderer/renderer.js: its transmission
framebuffer), a scene with a transmissive material is drawn twice: first every object whose
material does not transmit, into an offscreen linear HDR target of the frame's size whose
mip chain is then generated, and then the whole scene, where the transmissive programs read
that copy along the transmitted ray (templates/transmission_scene.inc: the projection, the
mip level from the roughness, the environment where the copy has nothing). A scene without
a transmissive object draws nothing more and binds nothing more: its programs do not
declare the copy (PBRLAB_TRANSMISSION is compiled only for transmissive materials,
features.py).

The copy holds radiance premultiplied by coverage: cleared to (0, 0, 0, 0), an opaque draw
writes alpha 1 and a blended one accumulates its coverage, as in the main target.
"""

from __future__ import annotations

import math

import moderngl

from . import features
from ..gpu import targets
from ..gpu.programs import set_uniform

# The uniforms templates/transmission_scene.inc declares.
TEXTURE_UNIFORM = "u_transmission_scene"
VIEW_PROJ_UNIFORM = "u_transmission_view_proj"
LOD_SCALE_UNIFORM = "u_transmission_lod_scale"


def transmits(plan: features.ProgramPlan, material_name: str) -> bool:
    """Whether the program of ``material_name`` reads the copy (it transmits)."""
    return "PBRLAB_TRANSMISSION" in plan.defines[material_name]


def seen_through(scene, plan: features.ProgramPlan) -> list | None:
    """The objects the copy holds: those whose material does not transmit (none, when every
    object transmits: the copy is then empty and the environment shows through); None when
    no object's material transmits (then there is no copy, and no program samples one)."""
    if not any(transmits(plan, obj.material) for obj in scene.objects):
        return None
    return [obj for obj in scene.objects if not transmits(plan, obj.material)]


def lod_scale(size) -> float:
    """log2 of the copy's larger side: the mip level a perceptual roughness of 1 reads (the
    Sample Viewer's log2(framebuffer width), for a copy that need not be square)."""
    return math.log2(max(size))


class TransmissionCopy:
    """The copy's target (``render_scene`` draws into it), then its mip-mapped texture."""

    def __init__(self, ctx: moderngl.Context, size, hdr_format: str, samples: int = 1):
        self.target = targets.Target(ctx, size, hdr_format, samples=samples)
        self.size = self.target.size

    def finish(self) -> moderngl.Texture:
        """Generate the mip chain (glGenerateMipmap on the float texture: a 2x2 box per
        level on llvmpipe) and set trilinear filtering, clamped at the screen's edges. A
        multisampled copy is resolved first (its samples averaged in linear radiance)."""
        texture = self.target.resolve()
        texture.build_mipmaps()
        texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
        texture.repeat_x = texture.repeat_y = False
        return texture

    def bind(self, program, unit: int, view_proj) -> None:
        """The copy, the camera's view-projection and the lod scale, for a transmissive program."""
        self.target.color.use(unit)
        set_uniform(program, TEXTURE_UNIFORM, unit)
        set_uniform(program, VIEW_PROJ_UNIFORM, tuple(view_proj.T.reshape(-1)))  # GL is column-major
        set_uniform(program, LOD_SCALE_UNIFORM, lod_scale(self.size))

    def release(self) -> None:
        self.target.release()
