"""Screen-space reflections (render.screen_space_reflections): the frame's own surfaces where a
lobe's reflected ray meets them, in place of the environment (templates/screen_space_reflection.inc
states the search, the hit and the fades).

A path tracer follows a mirror-like surface's reflected ray into the model itself; an environment
lookup sees the sky there (docs/fidelity.md measured it on DamagedHelmet's visor and
TransmissionRoughnessTest's polished bars). With the option the frame is drawn twice:

* before it, the nearest surface's world position per pixel of every object the frame draws
  opaque or cut out (face_positions.py, both sides; blended objects, ray-traced spheres and
  programs that move vertices are not in it), and the search's reach, the drawn objects'
  bounding diagonal (the search's step is reach / SSR_STEPS, and a hit may lie a step behind a
  stored surface);
* the first pass: every object drawn as the frame draws it, single-sampled, into a linear HDR
  target of the frame's size (``colour``), its programs reading the environment alone (u_ssr_on 0);
* the frame, whose programs read the first pass where their rays meet its surfaces.

Cost: one more draw of the scene and one of its positions; per shaded pixel of a lobe smoother than
0.6 up to SSR_STEPS + SSR_REFINE + 1 projections and taps (two lobes under a clear coat).

    ssr = ScreenSpaceReflection(ctx, scene, frame, hdr_format)   # the positions drawn
    ... draw the scene into ssr.colour_target (bound with on=False) ...; ssr.finish()
    ssr.bind(program, colour_unit, surface_unit)                # every program after
"""

from __future__ import annotations

import moderngl
import numpy as np

from . import face_positions
from .depth_range import _object_box
from ..gpu import targets
from ..gpu.programs import set_uniform
from ..scene.standard_material import BLENDED_ALPHA_MODES

# The uniforms templates/screen_space_reflection.inc declares.
COLOUR_UNIFORM = "u_ssr_colour"
SURFACE_UNIFORM = "u_ssr_surface"
VIEW_PROJ_UNIFORM = "u_ssr_view_proj"
REACH_UNIFORM = "u_ssr_reach"
THICKNESS_UNIFORM = "u_ssr_thickness"
ON_UNIFORM = "u_ssr_on"
# The search (the shader's PBRLAB_SSR_STEPS and _REFINE, whose defaults these are): a crossing
# found to within reach / (32 x 2^6) = reach / 2048 of where the ray passes behind the surface.
SSR_STEPS = 32
SSR_REFINE = 5
MAX_ROUGHNESS = 0.6  # perceptual roughness from which the environment alone is read (the shader's fade)


def reflected_objects(scene) -> list:
    """The objects whose surfaces a reflected ray can meet (module doc)."""
    return [obj for obj in scene.objects
            if scene.materials[obj.material].alpha_mode not in BLENDED_ALPHA_MODES
            and face_positions.drawable(scene, obj)]


def reach(objects) -> float:
    """The search's length: the drawn objects' world bounding diagonal (0 with none)."""
    if not objects:
        return 0.0
    corners = np.concatenate([_object_box(obj) for obj in objects])
    return float(np.linalg.norm(corners.max(axis=0) - corners.min(axis=0)))


class ScreenSpaceReflection:
    """The positions pass and the first pass's target (module doc)."""

    def __init__(self, ctx: moderngl.Context, scene, frame, hdr_format: str):
        objects = reflected_objects(scene)
        self.reach = reach(objects)
        self.view_proj = np.asarray(frame.view_proj, np.float64)
        self.surface = face_positions.draw_face_positions(
            ctx, frame, objects, {obj.material: 1.0 for obj in objects}, cull=None)
        self.colour_target = targets.Target(ctx, tuple(int(s) for s in frame.size), hdr_format)
        self.on = False  # the first pass reads the environment alone

    def finish(self) -> None:
        """After the first pass: its colour is read from now on."""
        texture = self.colour_target.resolve()
        texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
        texture.repeat_x = texture.repeat_y = False
        self.on = True

    def bind(self, program, colour_unit: int, surface_unit: int) -> None:
        """The two textures and the search's uniforms; a program without the option ignores them."""
        self.colour_target.color.use(colour_unit)
        self.surface.use(surface_unit)
        set_uniform(program, COLOUR_UNIFORM, colour_unit)
        set_uniform(program, SURFACE_UNIFORM, surface_unit)
        set_uniform(program, VIEW_PROJ_UNIFORM, tuple(self.view_proj.T.reshape(-1)))  # GL is column-major
        set_uniform(program, REACH_UNIFORM, self.reach)
        set_uniform(program, THICKNESS_UNIFORM, self.reach / SSR_STEPS)
        set_uniform(program, ON_UNIFORM, 1.0 if self.on else 0.0)

    def release(self) -> None:
        self.surface.release()
        self.colour_target.release()
