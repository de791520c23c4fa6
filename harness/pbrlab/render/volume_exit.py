"""Where the view ray leaves each volume (render.volume_chord): the path length through a
KHR_materials_volume object measured from its geometry, not read from its thickness.

KHR_materials_volume gives a rasteriser the thickness beneath the surface as a material value
(thicknessFactor x the thickness texture's G) because the distance light travels inside a
closed mesh is hard to find without tracing rays; its "Thickness Texture" section names
deriving it along the ray from the geometry as the preferred approach, which path tracers and
"more sophisticated raster techniques" take, ignoring the thickness map. Decided by that text:
where the geometry gives a chord, the chord replaces the material's thickness (for the
Beer-Lambert attenuation and for where the transmitted ray leaves the volume); the thickness
still says whether the material is a volume at all (0: thin-walled, as the extension defines).

The geometry, one pass before the frame: the back faces of every object whose material
transmits with a thickness > 0 (front faces culled; the importers wind every front face
counter-clockwise, a mirroring node's triangles turned round), depth-tested nearest-first, each
pixel storing the world position of the back face it sees and its material's id (``ids``: 1,
2, ... by material name; 0 where no volume's back face was drawn).

The path (templates/transmission_scene.inc, pbrlab_volume_path_length): from the surface point
p along the transmitted ray d (refracted by the volume's IOR), a point q is inside the volume
while q's pixel holds its material's back face and q lies in front of it. CHORD_STEPS even steps
over [0, reach] find the first point outside, CHORD_REFINE bisections then halve the interval
that holds the crossing. reach: the longest segment inside the material's objects, their
largest world bounding-box diagonal. For a convex body the inside of the ray is one interval,
so the crossing is found to within reach / (CHORD_STEPS 2^CHORD_REFINE) = reach / 512 (the
float64 chords of pbrlab.maths.reference.volume_chord: tests/render/test_volume_chord.py); in a
concave one a gap thinner than a step may be stepped over. The inside test sees each pixel's
NEAREST back face only: a ray that leaves through a face turned towards the camera is taken to
be inside until it passes the back face behind that face (a slanted view into a box's side),
and a point's pixel is the one its centre projects into (a drawn pixel's width of blur).
A pixel whose own back face is not its material's (a silhouette's edge sample under
antialiasing) keeps the material's thickness. Ray-traced spheres, objects whose program moves
their vertices, and non-triangle meshes draw no back face: they keep their thickness.

Cost: up to CHORD_STEPS + CHORD_REFINE + 1 = 22 taps of the exit texture and projections per
transmissive pixel, and one more draw of the volumes.

    exits = VolumeExit(ctx, scene, frame, plan)   # before the frame; exits.bind per program
"""

from __future__ import annotations

import moderngl
import numpy as np

from . import instanced_draws
from .depth_range import _moves_vertices, _object_box
from ..gpu.programs import set_uniform
from ..scene import meshes

# The uniforms templates/transmission_scene.inc declares (PBRLAB_VOLUME_CHORD).
TEXTURE_UNIFORM = "u_volume_exit"
ID_UNIFORM = "u_volume_exit_id"
REACH_UNIFORM = "u_volume_exit_reach"
# The search along the ray (module doc; the shader's PBRLAB_VOLUME_CHORD_STEPS and _REFINE, whose
# defaults these are): a convex body's crossing within reach / (16 x 2^5) = reach / 512.
CHORD_STEPS = 16
CHORD_REFINE = 5

_VERTEX = """#version 330 core
in vec3 in_position;
uniform mat4 u_model, u_view_proj;
out vec3 v_world;  // the back face's world position, what the pass stores
void main() {
    v_world = (u_model * vec4(in_position, 1.0)).xyz;
    gl_Position = u_view_proj * vec4(v_world, 1.0);
}
"""
_FRAGMENT = """#version 330 core
in vec3 v_world;
uniform float u_id;
out vec4 out_exit;
void main() {
    out_exit = vec4(v_world, u_id);
}
"""


def volume_materials(scene, plan) -> list[str]:
    """The names of the materials whose program transmits and whose thickness is > 0 (sorted)."""
    return sorted(name for name, material in scene.materials.items()
                  if "PBRLAB_TRANSMISSION" in plan.defines.get(name, {}) and material.thickness > 0.0)


def volumes(scene, ids: dict) -> list:
    """The objects whose back faces the pass draws (module doc), of the materials in ``ids``."""
    out = []
    for obj in scene.objects:
        if obj.material not in ids or obj.sphere is not None or _moves_vertices(scene.materials[obj.material]):
            continue
        if obj.geometry is not None and obj.geometry.topology != "triangles":
            continue
        out.append(obj)
    return out


class VolumeExit:
    """The nearest back face of the scene's volumes per drawn pixel (module doc)."""

    def __init__(self, ctx: moderngl.Context, scene, frame, plan):
        self.ids = {name: float(k + 1) for k, name in enumerate(volume_materials(scene, plan))}
        drawn = volumes(scene, self.ids)
        self.reach = {}
        for obj in drawn:
            box = _object_box(obj)
            diagonal = float(np.linalg.norm(box.max(axis=0) - box.min(axis=0)))
            self.reach[obj.material] = max(self.reach.get(obj.material, 0.0), diagonal)
        size = tuple(int(s) for s in frame.size)
        self.texture = ctx.texture(size, 4, dtype="f4")
        self.texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
        self.texture.repeat_x = self.texture.repeat_y = False
        depth = ctx.depth_renderbuffer(size)
        fbo = ctx.framebuffer([self.texture], depth)
        program = ctx.program(vertex_shader=_VERTEX, fragment_shader=_FRAGMENT)
        try:
            fbo.use()
            ctx.viewport = (0, 0) + size
            fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)  # id 0: no volume
            ctx.disable(moderngl.BLEND)
            ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
            ctx.depth_func = "<"
            ctx.front_face, ctx.cull_face = "ccw", "front"
            set_uniform(program, "u_view_proj", tuple(np.asarray(frame.view_proj, np.float64).T.reshape(-1)))
            for obj in drawn:
                set_uniform(program, "u_id", self.ids[obj.material])
                set_uniform(program, "u_model", tuple(instanced_draws.model_matrix(obj.transform)))
                vao, buffers = meshes.vertex_array(ctx, program, obj)
                try:
                    vao.render(moderngl.TRIANGLES)
                finally:  # released if the draw fails too
                    for resource in (vao, *buffers):
                        resource.release()
        finally:
            ctx.disable(moderngl.CULL_FACE | moderngl.DEPTH_TEST)
            ctx.cull_face = "back"
            program.release()
            fbo.release()
            depth.release()

    def bind(self, program, unit: int, material_name: str) -> None:
        """The exit texture and the material's id (0 for a material that is no volume: it
        matches no drawn pixel); a program that declares neither ignores them."""
        self.texture.use(unit)
        set_uniform(program, TEXTURE_UNIFORM, unit)
        set_uniform(program, ID_UNIFORM, self.ids.get(material_name, 0.0))
        set_uniform(program, REACH_UNIFORM, self.reach.get(material_name, 0.0))

    def read(self) -> np.ndarray:
        """The texture, top row first (HxWx4 float32: exit position, id), for the tests."""
        data = np.frombuffer(self.texture.read(), np.float32).reshape(self.texture.height, self.texture.width, 4)
        return data[::-1].copy()

    def release(self) -> None:
        self.texture.release()
