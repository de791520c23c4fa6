"""Full-screen passes: a Unity pass drawn as Unity's Blitter (Core RP) and URP's Full Screen
Pass Renderer Feature draw one, over the whole viewport instead of the object's mesh.

Which pass is one: a vertex/fragment pass whose vertex function's input carries
``SV_VertexID`` and no ``POSITION`` (Core RP's Blit.hlsl ``Vert`` takes ``Attributes``
{ ``uint vertexID : SV_VertexID`` }; a pass of one's own that places the full-screen triangle
with ``GetFullScreenTriangleVertexPosition(id)`` reads the same). Such a program cannot read the
mesh (it has no vertex attribute), and a program that indexes a compute buffer by the vertex id
is refused before it gets here (compute_buffers.py), so what is left positions its vertices from
the id alone: Unity draws it procedurally, 3 vertices with no mesh (the Blitter's
``DrawProcedural(..., MeshTopology.Triangles, 3)``), and so does pbrlab. A pass whose vertex
function is Blit.hlsl's ``VertQuad`` or ``VertQuadPadding``, or whose program calls Core's
``GetQuadVertexPosition``, is the Blitter's quad instead (``Blitter.BlitQuad``: 4 vertices, drawn
as the triangles (0, 1, 2) and (0, 2, 3)): an index buffer of those 6 ids, which GL hands the
vertex stage as SV_VertexID.

How it is drawn (Unity's documentation of the Blitter and the Full Screen Pass Renderer
Feature, whose default injection point is after the scene is rendered):

* after every other object of the scene (renderer._draw_order), once: the shader's first
  full-screen pass that runs, the feature's Pass Index 0 (a shader's later full-screen passes
  are the steps a C# script chains with Blitter calls of its own, which a scene here has not);
* ``_BlitTexture``: a copy of the camera's colour as drawn so far (a grab of the float target,
  exact: the scene rendered without the object), bilinear and clamped to its edges (URP's
  camera targets' wrap mode; the sampler state a program names is the texture's here, as for
  every sampler: GlobalSamplers.hlsl), with its ``_BlitTexture_TexelSize``;
* ``_BlitScaleBias`` = ``_BlitScaleBiasRt`` = (1, 1, 0, 0) (the whole source, to the whole
  target), ``_BlitMipLevel`` 0, ``_BlitTextureSize`` the target's size;
* the object is kept out of the camera's depth texture and G-buffer (it has no surface there).

    fullscreen_pass.is_fullscreen(unity_pass)     # the rule above
    fullscreen_pass.vertex_array(ctx, program, draws_quad(unity_pass))   # (vao, buffers)
"""

from __future__ import annotations

import numpy as np

from ...gpu.programs import set_uniform as _set
from . import model as M
from .generate_pass import _struct, canonical

SOURCE_TEXTURE = "_BlitTexture"
# The Blitter's procedural triangle (Core RP's GetFullScreenTriangleVertexPosition: vertex ids 0..2).
VERTICES = 3
_WHOLE = (1.0, 1.0, 0.0, 0.0)  # scale (1, 1), bias (0, 0)
# The Blitter's quad: its 4 corners' ids as two triangles (Core RP's GetQuadVertexPosition order).
QUAD_IDS = (0, 1, 2, 0, 2, 3)
_QUAD_VERTEX_FUNCTIONS = ("VertQuad", "VertQuadPadding")


def _input_semantics(vf: M.VertexFragmentPass) -> set:
    """The semantics of everything the vertex function reads: its in (and inout) parameters and
    the members of those that are structs."""
    found = set()
    for qual, kind, _name, semantic in vf.vertex_params:
        if qual == "out":
            continue
        members = _struct(vf, kind)
        if members is not None:
            found |= {canonical(s) for _t, _n, s in members if s}
        elif semantic:
            found.add(canonical(semantic))
    return found


def is_fullscreen(unity_pass) -> bool:
    """Whether ``unity_pass`` is drawn as a full-screen pass (module doc): a vertex/fragment pass
    (no geometry or tessellation stage) whose vertex input has SV_VertexID and no POSITION."""
    if not isinstance(unity_pass, M.VertexFragmentPass) or unity_pass.language != "hlsl":
        return False
    if unity_pass.geometry is not None or unity_pass.tessellation is not None:
        return False
    semantics = _input_semantics(unity_pass)
    return "SV_VERTEXID" in semantics and not semantics & {"POSITION", "SV_POSITION"}


def draws_quad(unity_pass) -> bool:
    """Whether a full-screen pass draws the Blitter's quad, not its triangle (module doc)."""
    return unity_pass.vertex in _QUAD_VERTEX_FUNCTIONS or "GetQuadVertexPosition" in unity_pass.program


def not_drawn(unity_pass, drawn: list) -> bool:
    """A full-screen pass after the shader's first one that runs (``drawn``: the material's
    passes so far): the Full Screen Pass Renderer Feature draws its Pass Index alone, 0 by default."""
    return is_fullscreen(unity_pass) and any(getattr(p, "fullscreen", False) for p in drawn)


class SourceGrab:
    """The grab before a full-screen pass: the camera's colour as drawn so far, as _BlitTexture,
    clamped to its edges (module doc)."""
    grab = SOURCE_TEXTURE
    clamp_to_edge = True
    traces_spheres = False


def bind(program, frame) -> None:
    """The Blitter's uniforms for a full-screen program (module doc)."""
    w, h = frame.size
    _set(program, "_BlitScaleBias", _WHOLE)
    _set(program, "_BlitScaleBiasRt", _WHOLE)
    _set(program, "_BlitMipLevel", 0.0)
    _set(program, "_BlitTextureSize", (float(w), float(h)))


def vertex_array(ctx, program, quad: bool = False):
    """(vertex array, buffers) of the procedural triangle (no buffers, 3 vertices) or quad (an
    index buffer of QUAD_IDS): the vertex stage places them by their id; a mesh attribute the
    generated entry declares reads GL's default (0, 0, 0, 1), and the program reads none."""
    if not quad:
        vao = ctx.vertex_array(program, [])
        vao.vertices = VERTICES
        return vao, []
    ids = ctx.buffer(np.asarray(QUAD_IDS, np.int32).tobytes())
    return ctx.vertex_array(program, [], index_buffer=ids, index_element_size=4), [ids]
