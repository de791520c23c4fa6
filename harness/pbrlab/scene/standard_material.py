"""pbrlab's own material as the renderer draws it: the material of JSON scenes and of glTF
files (``scene.model.Material`` with no shader of its own, or a GLSL/HLSL ``surface`` file).
One pass of the harness's scene program (templates/sphere.*, templates/mesh.*), its features
compiled in by the defines the render plans (render/features.py), blended by the alpha mode.
It implements ``scene.material_passes.MaterialSource``.
"""

from __future__ import annotations

import moderngl

from ..gpu.programs import fragment_template, program_from_templates, surface_file
from .material_passes import RenderState

# Blending per alpha mode (Unity's Standard shader): fade blends colour by alpha;
# transparent is premultiplied (the shader scaled the diffuse, the specular stays).
# The target's alpha accumulates coverage: ONE, ONE_MINUS_SRC_ALPHA for both.
BLENDED_ALPHA_MODES = {
    "fade": (moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA, moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA),
    "transparent": (moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA, moderngl.ONE, moderngl.ONE_MINUS_SRC_ALPHA),
}


def alpha_mode_state(alpha_mode: str, depth_func: str, depth_write: bool | None = None) -> RenderState:
    """Blending by ``alpha_mode``: blended modes do not write depth (unless ``depth_write`` says)."""
    blend = BLENDED_ALPHA_MODES.get(alpha_mode)
    write = (blend is None) if depth_write is None else depth_write
    return RenderState(blend=blend, depth_write=write, depth_func=depth_func)


class StandardPass:
    """The one pass of pbrlab's own material."""
    grab = None
    traces_spheres = True
    # its mesh programs shade with mesh.vert's tangent (the mesh's own, transformed): the
    # harness's bound on the vertex data (render/tangent_frames.py) speaks for them
    tangents_from_mesh = True

    def __init__(self, alpha_mode: str):
        # pbrlab's own materials: the first surface drawn wins a depth tie
        self.state = alpha_mode_state(alpha_mode, "<")

    def draws(self, defines: dict) -> list:
        return [(defines, self.state)]

    def program(self, ctx, stem, defines, language, surface, mesh_fragment):
        fragment = mesh_fragment if stem == "mesh" else fragment_template(stem, language)
        return program_from_templates(ctx, f"{stem}.vert", fragment, defines, surface)

    def bind(self, program, material, obj, frame, cache, environment_cube, first_unit, grabbed) -> None:
        return None  # the scene's bindings are all it reads

    def sphere_vertex_array(self, ctx, program):
        raise AssertionError("pbrlab's own material ray-traces its spheres")


class StandardSource:
    """``MaterialSource`` of pbrlab's own materials (module doc)."""
    moves_vertices = False
    camera_near = None
    camera_far = None

    def passes(self, material) -> list:
        return [StandardPass(material.alpha_mode)]

    def defines(self, material) -> dict:
        return {}

    def instanceable(self, material) -> bool:
        return material.alpha_mode not in BLENDED_ALPHA_MODES

    def surface_file(self, material, language: str):
        return surface_file(material.surface, language)

    def layers(self, material):
        return None


STANDARD = StandardSource()


def source_of(material):
    """``material``'s source (scene.material_passes.MaterialSource): its own, else the standard one."""
    return material.source if material.source is not None else STANDARD
