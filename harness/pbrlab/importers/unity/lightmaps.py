"""Baked lightmaps the user supplies: a Unity material's ``lightmap`` field,

    "materials": {"m": {"surface": "Lit.shader",
                        "lightmap": {"path": "Lightmap-0_comp_light.exr", "scale_offset": [0.5, 0.5, 0, 0.5],
                                     "encoding": "full_hdr"}}}

is the lightmap of the objects drawn with the material (Unity keeps it per renderer: its
lightmap index and ``lightmapScaleOffset``; here a lightmapped object has a material of its own).
The harness bakes nothing; it draws what Unity draws for an object with that lightmap:

- ``unity_Lightmap`` is the image, ``unity_LightmapST`` the scale (xy) and offset (zw) that take
  the mesh's second UV set (``TEXCOORD1``, Unity's Mesh.uv2: the lightmap UVs; a glTF mesh's
  TEXCOORD_1, its TEXCOORD_0 where it has none; a primitive's only UV set) into the image;
- ``unity_Lightmap_HDR`` the decode instructions and a macro for the encoding, which
  ``DecodeLightmap`` (cginc/UnityLightmapDecoding.cginc) reads. Unity picks the encoding by
  platform and the Player's "Lightmap Encoding" (Unity manual, "Lightmaps: Technical
  information"); here it is the supplied image's: ``full_hdr`` (High Quality: a float image,
  the default for .exr/.hdr files), ``rgbm`` (Normal Quality, desktop's default: an 8-bit RGBA
  image, sampled as sRGB, decoded 34.49 a^2.2 rgb; the default for other files) or ``dldr`` (Low
  Quality on mobile: 8-bit, sampled as sRGB, decoded 4.59482 rgb). Linear colour space
  throughout, as the harness renders. Sampled bilinearly with mipmaps, clamped to the edge;
- ``LIGHTMAP_ON`` is defined in each vertex/fragment program that declares it (its
  ``#pragma multi_compile`` lines, or ``multi_compile_fwdbase``, whose variants include it: Unity
  manual, "Shader variants and keywords", its built-in shortcuts), as Unity sets it for a
  lightmapped renderer;
- a lightmapped object's legacy vertex-lit pass is its ``VertexLMRGBM`` pass (``VertexLM`` for a
  dLDR lightmap) instead of its ``Vertex`` pass, as in Unity's vertex-lit path (Unity manual,
  "Pass tags": VertexLMRGBM for RGBM-encoded lightmaps on PC and consoles, VertexLM for
  double-LDR ones on mobile); a SubShader with only one of them draws that one (its program
  reads the lightmap through DecodeLightmap, which decodes any encoding).

- ``unity_LightmapInd``, a directional lightmap's direction texture: the lightmap's ``direction``
  image (``"direction": "Lightmap-0_comp_dir.png"``, linear data), or a grey texel (0.5, 0.5, 0.5,
  0.5) of no dominant direction, under which ``DecodeDirectionalLightmap`` returns the lightmap;
- ``unity_ShadowMask``, the baked shadow mask: white (no baked shadow; the harness bakes none),
  its ``unity_OcclusionMaskSelector`` the first channel.

Refused by name: a program that reads ``unity_Lightmap``, ``unity_LightmapST``, ``unity_Lightmap_HDR``
or ``DecodeLightmap`` in the variant drawn when the material supplies no lightmap (at the line
that reads it), and a surface shader with one (pbrlab's surface programs do not draw Unity's
lightmapped surface variant). Realtime GI lightmaps (``unity_DynamicLightmap*``) are
dynamic_lightmaps.py's.

    lightmap = read_lightmap(r, base)                    # material.read_material
    pipeline = lightmapped(BUILTIN, lightmap)            # the passes a lightmapped object draws
    check_reads(shader, lightmap, r)                     # refusals, as above
    defines = program_defines(unity_pass, lightmap)      # LIGHTMAP_ON where declared, the encoding's macro
    bind(program, lightmap, cache, unit)                 # the uniforms above
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

# Unity's manual, "Lightmaps: Technical information": an RGBM lightmap spans [0, 5] in gamma
# space, [0, 5^2.2 = 34.49] in linear space (M is a gamma-space multiplier: M^2.2 in linear);
# a dLDR lightmap maps [0, 2] to [0, 1]: times 2 in gamma space, 2^2.2 = 4.59482 in linear.
RGBM_GAMMA_RANGE = 5.0
GAMMA = 2.2
RGBM_LINEAR_RANGE = RGBM_GAMMA_RANGE ** GAMMA
DLDR_LINEAR_SCALE = 2.0 ** GAMMA


@dataclass(frozen=True)
class Encoding:
    macro: str              # Unity's platform macro DecodeLightmap tests
    decode: tuple           # unity_Lightmap_HDR: (range, exponent of M, 0, 0)
    srgb: bool              # sampled from an sRGB texture (Unity marks encoded lightmaps sRGB in linear space)
    vertex_lit_passes: tuple  # the LightModes of the legacy vertex-lit pass drawn instead of Vertex, preferred first


ENCODINGS = {
    "full_hdr": Encoding("UNITY_LIGHTMAP_FULL_HDR", (1.0, 1.0, 0.0, 0.0), False, ("vertexlmrgbm", "vertexlm")),
    "rgbm": Encoding("UNITY_LIGHTMAP_RGBM_ENCODING", (RGBM_LINEAR_RANGE, GAMMA, 0.0, 0.0), True,
                     ("vertexlmrgbm", "vertexlm")),
    "dldr": Encoding("UNITY_LIGHTMAP_DLDR_ENCODING", (DLDR_LINEAR_SCALE, 0.0, 0.0, 0.0), True,
                     ("vertexlm", "vertexlmrgbm")),
}
_FLOAT_IMAGES = (".exr", ".hdr")
_LIGHTMAP_PASSES = ("vertexlm", "vertexlmrgbm")


@dataclass(frozen=True)
class Lightmap:
    path: Path
    scale_offset: tuple = (1.0, 1.0, 0.0, 0.0)   # unity_LightmapST: scale xy, offset zw
    encoding: str = "full_hdr"
    direction: Path | None = None                # unity_LightmapInd: a directional lightmap's direction image


def read_lightmap(r, base: Path) -> Lightmap | None:
    """The material's ``lightmap`` (module docstring), or None; ``r`` the material's reader."""
    if not r.has("lightmap"):
        return None
    child = r.child("lightmap")
    path = child.file("path", base)
    default = "full_hdr" if path.suffix.lower() in _FLOAT_IMAGES else "rgbm"
    encoding = child.choice("encoding", tuple(ENCODINGS), default)
    scale_offset = tuple(float(v) for v in child.vector("scale_offset", 4, [1.0, 1.0, 0.0, 0.0]))
    direction = child.file("direction", base) if child.has("direction") else None
    child.finish()
    return Lightmap(path, scale_offset, encoding, direction)


def lightmapped(pipeline, lightmap: Lightmap):
    """``pipeline`` (parse.Pipeline) as it reads a shader for an object with ``lightmap``: its
    VertexLM/VertexLMRGBM passes drawn instead of its Vertex pass (``vertex_lit_passes`` keeps the
    encoding's where a SubShader has both), LIGHTMAP_ON on where a program declares it. A pipeline
    without a Vertex pass (URP) keeps its passes: LIGHTMAP_ON only."""
    if "vertex" not in pipeline.drawn:
        return dataclasses.replace(pipeline, keywords=_no_probe_sh(pipeline.keywords) + ("LIGHTMAP_ON",))
    skipped = {k: v for k, v in pipeline.skipped.items() if k not in _LIGHTMAP_PASSES}
    skipped["vertex"] = "for objects without a lightmap (this one has one: its VertexLM pass draws)"
    drawn = tuple(m for m in pipeline.drawn if m != "vertex") + _LIGHTMAP_PASSES
    return dataclasses.replace(pipeline, drawn=drawn, skipped=skipped,
                               keywords=_no_probe_sh(pipeline.keywords) + ("LIGHTMAP_ON",))


def _no_probe_sh(keywords: tuple) -> tuple:
    """``keywords`` without LIGHTPROBE_SH, the variant of an object without a lightmap (light_probes.py)."""
    return tuple(k for k in keywords if k != "LIGHTPROBE_SH")


def vertex_lit_passes(passes: list, lightmap: Lightmap | None) -> list:
    """``passes`` of a lightmapped object without the VertexLM/VertexLMRGBM pass of the other
    encoding where both are there (Unity draws VertexLMRGBM for an RGBM lightmap, VertexLM for a
    dLDR one; a shader with one of them draws it: its program decodes by DecodeLightmap)."""
    if lightmap is None:
        return passes
    modes = {getattr(p, "light_mode", "").lower() for p in passes}
    preferred, other = ENCODINGS[lightmap.encoding].vertex_lit_passes
    if preferred in modes and other in modes:
        return [p for p in passes if getattr(p, "light_mode", "").lower() != other]
    return passes


# Textures Unity's engine binds per renderer, which no material property sets (parse's implicit
# texture properties leave them out): the supplied lightmap's, and the realtime GI lightmap's
# (dynamic_lightmaps.py).
# The directional lightmap's direction texture and the shadow mask are engine-set as well
# (cginc/UnityLightmapDecoding.cginc): the first bound here, the mask left to the unset-sampler
# default, white (unset_samplers.py).
ENGINE_SET_TEXTURES = frozenset({"unity_Lightmap", "unity_DynamicLightmap", "unity_LightmapInd", "unity_ShadowMask"})
# A direction texel of no dominant direction: DecodeDirectionalLightmap's half-Lambert term is
# 0.5 for every normal and the rebalancing factor w 0.5, so the lightmap's colour comes back as it is.
NO_DIRECTION = (0.5, 0.5, 0.5, 0.5)
# What a supplied lightmap provides (cginc/UnityLightmapDecoding.cginc).
SUPPLIED = ("unity_Lightmap", "unity_LightmapST", "unity_Lightmap_HDR", "DecodeLightmap", "DecodeLightmapRGBM",
            "DecodeLightmapDoubleLDR")
_READ = re.compile(r"\b(" + "|".join(sorted(SUPPLIED, key=len, reverse=True)) + r")\b")
# URP's Core.hlsl stand-in defines unity_LightmapST for every object (the identity without a
# lightmap, as URP's UnityPerDraw holds it): a URP program reading it needs no lightmap.
_READ_URP = re.compile(r"\b(" + "|".join(sorted(set(SUPPLIED) - {"unity_LightmapST"}, key=len, reverse=True)) + r")\b")
_FWDBASE = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+multi_compile_fwdbase\b", re.M)


def declares_lightmap_on(program: str) -> bool:
    """Whether ``program`` has a LIGHTMAP_ON variant: a multi_compile/shader_feature naming it,
    or multi_compile_fwdbase (Unity manual, "Shader variants and keywords": its set of
    ForwardBase keywords includes LIGHTMAP_ON)."""
    return "LIGHTMAP_ON" in declared_keywords(program) or bool(_FWDBASE.search(blank_comments(program)))


def first_read(program: str, keywords=(), urp: bool = False):
    """(name, offset) of the first lightmap name ``program`` reads in the variant with
    ``keywords`` (comments and branches not taken blanked); None when it reads none. With
    ``urp``, the names URP's stand-ins leave undefined without a lightmap."""
    masked = blank_comments(program)
    m = (_READ_URP if urp else _READ).search(active_text(masked, defines_of(masked, keywords)))
    return (m.group(1), m.start()) if m else None


def check_reads(shader, lightmap: Lightmap | None, r, keywords=()) -> None:
    """Refuse (``r.fail``) a shader that needs a lightmap the material does not supply (in the
    variant its ``keywords`` draw), or one given a lightmap it cannot draw with: a surface shader,
    or a pass whose LIGHTMAP_ON variant a pbrlab stand-in does not honour (module docstring)."""
    programs_drawn = [p for p in shader.passes if getattr(p, "kind", "") == "vertex-fragment"
                      and getattr(p, "language", "") != "unity-glsl"]
    if lightmap is not None:
        if shader.surface is not None:
            r.fail(f"{shader.surface.path}: a surface shader with a lightmap: pbrlab's surface programs do not "
                   "draw Unity's lightmapped variant (remove `lightmap`)", "lightmap")
        for p in programs_drawn:
            reason = refused_keywords(p.program, p.path.parent).get("LIGHTMAP_ON")
            if reason and declares_lightmap_on(p.program):
                r.fail(f"{p.path}:{p.program_line}: LIGHTMAP_ON (set for a lightmapped object): {reason}",
                       "lightmap")
        return
    read_by = programs_drawn + [p for p in shader.passes if getattr(p, "kind", "") == "surface"
                                and getattr(p, "language", "") == "hlsl"]
    for p in read_by:  # a surface program reading one would read zeros: refused as well
        found = first_read(p.program, keywords)
        if found:
            name, offset = found
            line = p.program_line - 1 + line_of(p.program, offset)
            r.fail(f"{p.path}:{line}: uses {name}, part of baked lightmaps: the object's lightmap, which the "
                   "material does not supply (give it a `lightmap`: docs/unity.md, \"Supplied lightmaps\")",
                   "surface")


def needs_lightmap(shader, urp: bool = False) -> bool:
    """Whether a drawn vertex/fragment pass of ``shader`` (read without a lightmap; ``urp``: for
    URP, first_read) reads one."""
    return any(getattr(p, "kind", "") == "vertex-fragment" and getattr(p, "language", "") != "unity-glsl"
               and first_read(p.program, urp=urp) for p in shader.passes)


def program_defines(unity_pass, lightmap: Lightmap | None) -> dict:
    """The defines a lightmapped object's program takes: the encoding's macro, and LIGHTMAP_ON
    where the pass declares it."""
    if lightmap is None or unity_pass.kind == "surface":
        return {}
    out = {ENCODINGS[lightmap.encoding].macro: 1}
    if declares_lightmap_on(unity_pass.program):
        out["LIGHTMAP_ON"] = 1
    return out


# Unity's lightmaps are clamped at their edges (a chart's border texels are dilated, not wrapped)
# and filtered bilinearly; mipmaps as any texture here (trilinear).
_SAMPLER = (False, False, moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)


def bind(program, lightmap: Lightmap | None, cache, unit: int) -> int:
    """Bind the lightmap's texture (at ``unit``), its direction texture (the material's
    ``direction`` image, linear data as Unity imports it, or NO_DIRECTION) and uniforms; the
    units used (0 to 2)."""
    if lightmap is None:
        return 0
    encoding = ENCODINGS[lightmap.encoding]
    _set(program, "unity_LightmapST", lightmap.scale_offset)
    _set(program, "unity_Lightmap_HDR", encoding.decode)
    used = 0
    if programs.uniforms_named(program, "unity_Lightmap"):
        cache.texture(lightmap.path, encoding.srgb, _SAMPLER).use(unit)
        _set(program, "unity_Lightmap", unit)
        used += 1
    if programs.uniforms_named(program, "unity_LightmapInd"):
        direction = (cache.texture(lightmap.direction, False, _SAMPLER) if lightmap.direction is not None
                     else cache.constant_texture(NO_DIRECTION))
        direction.use(unit + used)
        _set(program, "unity_LightmapInd", unit + used)
        used += 1
    return used
