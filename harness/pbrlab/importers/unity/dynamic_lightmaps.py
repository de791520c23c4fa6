"""Realtime GI (Enlighten) lightmaps the user supplies: a Unity material's ``dynamic_lightmap``,

    "materials": {"m": {"surface": "GI.shader",
                        "dynamic_lightmap": {"path": "Realtime-0.exr", "scale_offset": [0.5, 0.5, 0, 0.5]}}}

is the realtime lightmap of the objects drawn with the material (Unity keeps it per renderer:
its realtime lightmap index and ``realtimeLightmapScaleOffset``). The harness runs no Enlighten;
it draws what Unity draws for an object with realtime GI from that lightmap:

- ``unity_DynamicLightmap`` is the image, ``unity_DynamicLightmapST`` the scale (xy) and offset
  (zw) that take the object's realtime lightmap UVs (``TEXCOORD2``) into it;
- ``TEXCOORD2`` is those UVs. Unity's manual ("Real-time lightmap UVs"): Unity takes a mesh's
  Mesh.uv3 (TEXCOORD2) as the input of its realtime UV packing, and its Mesh.uv2 (the baked
  lightmap UVs, TEXCOORD1) where it has no uv3, and passes the packed per-renderer result
  (MeshRenderer.enlightenVertexStream) to TEXCOORD2. No mesh here carries a third UV set (the
  glTF importer reads TEXCOORD_0 and TEXCOORD_1 only), so TEXCOORD2 is the lightmap UVs of
  TEXCOORD1 (the baked lightmap's: a glTF mesh's TEXCOORD_1, its TEXCOORD_0 where it has none; a
  primitive's only UV set); Unity's per-renderer repacking is the engine's, the supplied
  ``scale_offset`` is what addresses the object's chart. An object without a realtime lightmap
  reads TEXCOORD2 as 0, as before (no uv3 here);
- ``unity_DynamicLightmap_HDR`` = (1, 1, 0, 0), the decode ``DecodeRealtimeLightmap`` reads
  (cginc/UnityRealtimeLightmap.cginc: Unity's pow((x a) rgb, y)). The encoding is Unity's on
  hardware with RGB9E5 textures (Unity manual, "Lightmaps: Technical information", Precomputed
  Realtime GI: "If your graphics hardware supports it, Unity stores the irradiance output texture
  using the RGB9E5 format", a shared-exponent float format; Direct3D 11, OpenGL 3.0+, Metal and
  Vulkan have it: Scripting API, TextureFormat.RGB9e5Float): a float image read as it is, linear,
  alpha 1, so the decode is the texel's RGB. Hence an HDR image (.exr/.hdr) only; its floats are
  read unquantised (RGB9E5's 9-bit mantissas are not emulated). Enlighten's 8-bit RGBM fallback for
  hardware without RGB9E5 is not supplied. Sampled bilinearly with mipmaps, clamped to the edge;
- ``DYNAMICLIGHTMAP_ON`` is defined in each vertex/fragment program that declares it (its
  ``#pragma multi_compile`` lines, or ``multi_compile_fwdbase``, whose variants include it: Unity
  manual, "Shader variants and keywords"), as Unity sets it for an object lit by realtime GI.

Refused by name: a program that reads ``unity_DynamicLightmap``, ``unity_DynamicLightmapST``,
``unity_DynamicLightmap_HDR`` or ``DecodeRealtimeLightmap`` in the variant drawn when the material
supplies no realtime lightmap (at the line that reads it: it would read zeros), a surface shader
with one, a stand-in that does not honour DYNAMICLIGHTMAP_ON, and ``unity_DynamicDirectionality``
(directional realtime lightmaps: unprovided.py).

    dynamic = read_dynamic_lightmap(r, base)             # material.read_material
    pipeline = realtime_lit(pipeline, dynamic)            # DYNAMICLIGHTMAP_ON where declared
    check_reads(shader, dynamic, r)                       # refusals, as above
    defines = program_defines(unity_pass, dynamic)        # DYNAMICLIGHTMAP_ON, TEXCOORD2's source
    bind(program, dynamic, cache, unit)                   # the uniforms above
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass
from pathlib import Path

import moderngl

from ...gpu import programs
from ...gpu.programs import set_uniform as _set
from .conditionals import active_text, defines_of
from .source_text import blank_comments, declared_keywords, line_of, refused_keywords

KEYWORD = "DYNAMICLIGHTMAP_ON"
# The define that makes the vertex entry's TEXCOORD2 the lightmap UVs (generate_pass.py).
UV_DEFINE = "PBRLAB_REALTIME_LIGHTMAP_UV"
# unity_DynamicLightmap_HDR of an RGB9E5 lightmap: DecodeRealtimeLightmap's pow((x a) rgb, y) is rgb.
FULL_HDR_DECODE = (1.0, 1.0, 0.0, 0.0)
_HDR_IMAGES = (".exr", ".hdr")


@dataclass(frozen=True)
class DynamicLightmap:
    path: Path
    scale_offset: tuple = (1.0, 1.0, 0.0, 0.0)   # unity_DynamicLightmapST: scale xy, offset zw


def read_dynamic_lightmap(r, base: Path) -> DynamicLightmap | None:
    """The material's ``dynamic_lightmap`` (module docstring), or None; ``r`` the material's reader."""
    if not r.has("dynamic_lightmap"):
        return None
    child = r.child("dynamic_lightmap")
    path = child.file("path", base)
    if path.suffix.lower() not in _HDR_IMAGES:
        child.fail(f"{path.name}: a realtime GI lightmap is an HDR image (Unity's RGB9E5 floats): give an "
                   ".exr or .hdr file", "path")
    scale_offset = tuple(float(v) for v in child.vector("scale_offset", 4, [1.0, 1.0, 0.0, 0.0]))
    child.finish()
    return DynamicLightmap(path, scale_offset)


def realtime_lit(pipeline, dynamic: DynamicLightmap | None):
    """``pipeline`` (parse.Pipeline) as it reads a shader for an object with realtime GI:
    DYNAMICLIGHTMAP_ON on where a program declares it."""
    if dynamic is None:
        return pipeline
    # (not LIGHTPROBE_SH, the variant of an object without a lightmap: light_probes.py)
    unlit = tuple(k for k in pipeline.keywords if k != "LIGHTPROBE_SH")
    return dataclasses.replace(pipeline, keywords=unlit + (KEYWORD,))


# What a supplied realtime lightmap provides (cginc/UnityRealtimeLightmap.cginc).
SUPPLIED = ("unity_DynamicLightmap", "unity_DynamicLightmapST", "unity_DynamicLightmap_HDR", "DecodeRealtimeLightmap")
_READ = re.compile(r"\b(" + "|".join(sorted(SUPPLIED, key=len, reverse=True)) + r")\b")
_FWDBASE = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+multi_compile_fwdbase\b", re.M)


def declares_dynamic_lightmap_on(program: str) -> bool:
    """Whether ``program`` has a DYNAMICLIGHTMAP_ON variant: a multi_compile/shader_feature naming
    it, or multi_compile_fwdbase (Unity manual, "Shader variants and keywords": its ForwardBase
    keywords include DYNAMICLIGHTMAP_ON)."""
    return KEYWORD in declared_keywords(program) or bool(_FWDBASE.search(blank_comments(program)))


def first_read(program: str, keywords=()):
    """(name, offset) of the first realtime-lightmap name ``program`` reads in the variant with
    ``keywords`` (comments and branches not taken blanked); None when it reads none."""
    masked = blank_comments(program)
    m = _READ.search(active_text(masked, defines_of(masked, keywords)))
    return (m.group(1), m.start()) if m else None


def _drawn_programs(shader) -> list:
    return [p for p in shader.passes if getattr(p, "kind", "") == "vertex-fragment"
            and getattr(p, "language", "") != "unity-glsl"]


def check_reads(shader, dynamic: DynamicLightmap | None, r, keywords=()) -> None:
    """Refuse (``r.fail``) a shader that needs a realtime lightmap the material does not supply
    (in the variant its ``keywords`` draw), or one given a realtime lightmap it cannot draw with:
    a surface shader, or a pass whose DYNAMICLIGHTMAP_ON variant a pbrlab stand-in does not honour."""
    if dynamic is not None:
        if shader.surface is not None:
            r.fail(f"{shader.surface.path}: a surface shader with a realtime GI lightmap: pbrlab's surface "
                   "programs do not draw Unity's realtime-GI variant (remove `dynamic_lightmap`)", "dynamic_lightmap")
        for p in _drawn_programs(shader):
            reason = refused_keywords(p.program, p.path.parent).get(KEYWORD)
            if reason and declares_dynamic_lightmap_on(p.program):
                r.fail(f"{p.path}:{p.program_line}: {KEYWORD} (set for an object with realtime GI): {reason}",
                       "dynamic_lightmap")
        return
    read_by = _drawn_programs(shader) + [p for p in shader.passes if getattr(p, "kind", "") == "surface"
                                         and getattr(p, "language", "") == "hlsl"]
    for p in read_by:
        found = first_read(p.program, keywords)
        if found:
            name, offset = found
            line = p.program_line - 1 + line_of(p.program, offset)
            r.fail(f"{p.path}:{line}: uses {name}, part of realtime GI lightmaps: the object's realtime (Enlighten) "
                   "lightmap, which the material does not supply (give it a `dynamic_lightmap`: docs/unity.md, "
                   "\"Supplied lightmaps\")", "surface")


def needs_dynamic_lightmap(shader) -> bool:
    """Whether a drawn vertex/fragment pass of ``shader`` reads a realtime lightmap."""
    return any(first_read(p.program) for p in _drawn_programs(shader))


def program_defines(unity_pass, dynamic: DynamicLightmap | None) -> dict:
    """The defines a realtime-lit object's program takes: TEXCOORD2 the lightmap UVs, and
    DYNAMICLIGHTMAP_ON where the pass declares it."""
    if dynamic is None or unity_pass.kind == "surface":
        return {}
    out = {UV_DEFINE: 1}
    if declares_dynamic_lightmap_on(unity_pass.program):
        out[KEYWORD] = 1
    return out


# Clamped at the edges, filtered bilinearly, mipmapped (trilinear), as the baked lightmap (lightmaps.py).
_SAMPLER = (False, False, moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)


def bind(program, dynamic: DynamicLightmap | None, cache, unit: int) -> int:
    """Bind the realtime lightmap's texture (at ``unit``) and uniforms; the units used (0 or 1)."""
    if dynamic is None:
        return 0
    _set(program, "unity_DynamicLightmapST", dynamic.scale_offset)
    _set(program, "unity_DynamicLightmap_HDR", FULL_HDR_DECODE)
    if not programs.uniforms_named(program, "unity_DynamicLightmap"):
        return 0
    cache.texture(dynamic.path, False, _SAMPLER).use(unit)
    _set(program, "unity_DynamicLightmap", unit)
    return 1
