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

from . import face_positions
from .depth_range import _object_box
from ..gpu.programs import set_uniform

# The uniforms templates/transmission_scene.inc declares (PBRLAB_VOLUME_CHORD).
TEXTURE_UNIFORM = "u_volume_exit"
ID_UNIFORM = "u_volume_exit_id"
REACH_UNIFORM = "u_volume_exit_reach"
# The search along the ray (module doc; the shader's PBRLAB_VOLUME_CHORD_STEPS and _REFINE, whose
# defaults these are): a convex body's crossing within reach / (16 x 2^5) = reach / 512.
CHORD_STEPS = 16
CHORD_REFINE = 5


def volume_materials(scene, plan) -> list[str]:
    """The names of the materials whose program transmits and whose thickness is > 0 (sorted)."""
    return sorted(name for name, material in scene.materials.items()
                  if "PBRLAB_TRANSMISSION" in plan.defines.get(name, {}) and material.thickness > 0.0)


def volumes(scene, ids: dict) -> list:
    """The objects whose back faces the pass draws (module doc), of the materials in ``ids``."""
    return [obj for obj in scene.objects if obj.material in ids and face_positions.drawable(scene, obj)]


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
        # the nearest back face per pixel: front faces culled (face_positions.py)
        self.texture = face_positions.draw_face_positions(ctx, frame, drawn, self.ids, cull="front")

    def bind(self, program, unit: int, material_name: str) -> None:
        """The exit texture and the material's id (0 for a material that is no volume: it
        matches no drawn pixel); a program that declares neither ignores them."""
        self.texture.use(unit)
        set_uniform(program, TEXTURE_UNIFORM, unit)
        set_uniform(program, ID_UNIFORM, self.ids.get(material_name, 0.0))
        set_uniform(program, REACH_UNIFORM, self.reach.get(material_name, 0.0))

    def read(self) -> np.ndarray:
        """The texture, top row first (HxWx4 float32: exit position, id), for the tests."""
        return face_positions.read_texture(self.texture)

    def release(self) -> None:
        self.texture.release()
