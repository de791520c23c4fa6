"""The one interface every material gives the renderer, whatever its source.

A material (``scene.model.Material``) carries a ``source``: the object that says how it is
drawn. pbrlab's own materials (JSON scenes, glTF) have the standard source
(``scene.standard_material``); a Unity shader's material has the Unity importer's
(``importers.unity.material``); a new source (another shading language's files, another
pipeline's passes) implements ``MaterialSource`` in its own importer folder and the renderer
draws it unchanged.

The renderer asks a source for its passes, in draw order. Each ``Pass`` is either a grab
(``grab`` names the texture that receives what is drawn so far, for the passes after it) or a
draw: for each repetition it asks for (``draws``: once, or once per light for a per-light
pass), its program (per stem and language), its render state (``RenderState``), and its
bindings beyond the scene's (``bind``). A source also answers what the rest of the renderer
plans with: whether objects of the material may share an instanced draw, whether its programs
place vertices themselves (a sphere is then tessellated, bounds do not hold), the nearest
depth its camera planes need, the surface file whose layers and samplers it compiles.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from ..gpu.stencil_state import StencilState

@dataclass(frozen=True)
class RenderState:
    """How one draw writes the target: ``blend`` the (source, destination, source alpha,
    destination alpha) GL factors or None (no blending); ``depth_write``; ``depth_func``
    (moderngl's spelling: "<", "<=", ..., "1" always, "0" never); ``cull`` "front", "back",
    "off", or None for the material's own sidedness (double-sided or blended: none culled);
    ``color_mask`` the (r, g, b, a) channels it writes (alpha: the target's coverage);
    ``stencil`` its stencil test and writes (``gpu.stencil_state.StencilState``), or None for
    the test off."""
    blend: tuple | None
    depth_write: bool
    depth_func: str
    cull: str | None = None
    color_mask: tuple = (True, True, True, True)
    stencil: StencilState | None = None


class Pass(Protocol):
    """One pass of a material, as the renderer draws it."""
    grab: str | None        # a grab pass: the sampler name that receives the target as drawn so far
    traces_spheres: bool    # a sphere object is ray-traced by this pass's program (else tessellated)

    def draws(self, defines: dict) -> list[tuple[dict, RenderState]]:
        """(the program's defines, its render state) for each draw of the pass: one, or one per
        light for a pass that adds each light on its own."""

    def program(self, ctx, stem: str, defines: dict, language: str, surface: Path | None,
                mesh_fragment: str):
        """The GL program of stem "sphere" or "mesh" with ``defines`` in ``language``."""

    def bind(self, program, material, obj, frame, cache, environment_cube, first_unit: int,
             grabbed: dict) -> None:
        """Its own uniforms and textures, after the scene's (the renderer's ``bind``):
        texture units from ``first_unit`` on; ``grabbed`` the grab passes' textures so far."""

    def sphere_vertex_array(self, ctx, program):
        """(vertex array, buffers) of a tessellated sphere, for a pass that does not trace one."""


class MaterialSource(Protocol):
    """What a material is drawn with (module doc)."""
    moves_vertices: bool         # its programs place vertices: spheres tessellated, bounds do not hold
    camera_near: float | None    # the nearest eye depth its camera planes must keep, or None
    camera_far: float | None     # the far plane its engine's camera keeps, where its programs move vertices, or None

    def passes(self, material) -> list:
        """``material``'s passes (``Pass``), in draw order."""

    def defines(self, material) -> dict:
        """Defines every program of the material takes beyond the scene's (enabled keywords)."""

    def instanceable(self, material) -> bool:
        """Whether objects of ``material`` may share one instanced draw."""

    def surface_file(self, material, language: str) -> Path | None:
        """The surface file its programs include in ``language`` (its samplers are bound by
        name and its layers compiled), or None."""

    def layers(self, material) -> frozenset | None:
        """The layers its programs compile, or None to read them from the material."""
