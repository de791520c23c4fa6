"""A Unity shader as a scene material: what the scene model reads for a material whose
``surface`` is a ``.shader`` (or a surface shader's text), and how the renderer draws it
(``scene.material_passes.MaterialSource``).

    UnitySource(shader).passes(material)   # its passes, in the shader's order

Reading (``read_material``): the shader's Properties overridden by the material's
``properties``, its ``keywords``, the alpha mode and cutoff from ``#pragma surface`` (a
vertex/fragment shader's from its Blend lines). Drawing: each pass that runs, in the shader's
order. A GrabPass copies what is drawn so far; a surface program draws once, or, when it tests
Unity's per-light keywords, as Unity's forward path does (a base program for directional
lights, ambient and emission, and a ForwardAdd program per other light type, added on top); a
vertex/fragment pass draws as its LightMode says (ForwardBase once with DIRECTIONAL, ForwardAdd
once per further light), blended, depth-tested and culled by its own lines; a deferred light
pass (vertex function vert_deferred) once per scene light, reading the camera's depth texture
and G-buffer (deferred.py; render/camera_textures.py renders them), in which a Unity shader's
object of an opaque queue shows Unity's default material (``gbuffer_surface``).
"""

from __future__ import annotations

import dataclasses
import re
import warnings
from pathlib import Path

import moderngl

from ...gpu.programs import set_uniform as _set
from ...scene.fields import TRANSMISSION_KEYS
from ...scene.material_passes import RenderState
from ...scene.standard_material import BLENDED_ALPHA_MODES, alpha_mode_state
from . import deferred
from . import (conditionals, dynamic_lightmaps, fullscreen_pass, graphics_api, light_probes, light_space, lightmaps,
               shadow_maps, unset_samplers, user_definitions)
from .keyword_drawers import drawer_keywords
from .model import GrabPass as GrabPassModel

# Unity's Camera.nearClipPlane default (0.3 units): the farthest near plane a Unity program
# sees (render/depth_range.py keeps the scene's near plane no farther: its programs read the
# planes, and one that fades what lies near the near plane faded a whole sphere away).
UNITY_CAMERA_NEAR = 0.3
# Unity's default camera far plane (Camera.farClipPlane, 1000): where a program of its own places
# the vertices, they are drawn up to it, not clipped at the far side of the mesh's own bounds.
UNITY_CAMERA_FAR = 1000.0

# ShaderLab's blend factors (Blend SrcFactor DstFactor) and depth tests, as moderngl's.
_UNITY_FACTORS = {"Zero": moderngl.ZERO, "One": moderngl.ONE, "DstColor": moderngl.DST_COLOR,
                  "SrcColor": moderngl.SRC_COLOR, "OneMinusDstColor": moderngl.ONE_MINUS_DST_COLOR,
                  "SrcAlpha": moderngl.SRC_ALPHA, "OneMinusSrcColor": moderngl.ONE_MINUS_SRC_COLOR,
                  "DstAlpha": moderngl.DST_ALPHA, "OneMinusDstAlpha": moderngl.ONE_MINUS_DST_ALPHA,
                  "SrcAlphaSaturate": 0x0308, "OneMinusSrcAlpha": moderngl.ONE_MINUS_SRC_ALPHA}
_UNITY_DEPTH = {"less": "<", "greater": ">", "lequal": "<=", "gequal": ">=", "equal": "==",
                "notequal": "!=", "always": "1", "never": "0"}
# The material fields a Unity shader's material does not take (its Properties do).
_NOT_FOR_UNITY = ("textures", "albedo", "metallic", "specular", "smoothness", "emission",
                  "occlusion", "alpha", "alpha_mode", "alpha_cutoff", "brdf", "workflow", "clearcoat",
                  "clearcoat_smoothness", "unlit", "sheen_color", "sheen_smoothness", "anisotropy_strength",
                  "anisotropy_rotation", "iridescence", "iridescence_ior", "iridescence_thickness_min",
                  "iridescence_thickness_max", "specular_f90", "dielectric_specular")


def light_programs(unity_pass, defines: dict, four_lights: bool = False) -> list[tuple[dict, bool]]:
    """[(defines, additive)]: the programs one pass of a Unity shader draws with. One, unless a
    surface program tests Unity's per-light keywords: then, as Unity's forward path, a base
    program with DIRECTIONAL and USING_DIRECTIONAL_LIGHT (directional lights, ambient,
    emission) and a ForwardAdd program with POINT, or SPOT, for each other light type the
    scene has, added on top. A vertex/fragment ForwardBase pass sees DIRECTIONAL; its
    ForwardAdd pass draws once per other light (DIRECTIONAL, POINT or SPOT, as Unity's forward
    path), blended by its own Blend line (the target's alpha, the coverage, kept); ``four_lights``
    (a shader without a ForwardAdd pass) gives its ForwardBase pass the point lights as Unity's
    four vertex lights (generate_pass._four_lights)."""
    if unity_pass.kind != "surface":
        if deferred.is_light_pass(unity_pass):  # the deferred path's: once per light (deferred.py)
            return [(keyed, False) for keyed in deferred.light_draws(defines)]
        mode = unity_pass.light_mode.lower()
        if mode == "forwardbase":
            four = {"PBRLAB_UNITY_FOUR_LIGHTS": 1} if four_lights else {}
            return [({**defines, "DIRECTIONAL": 1, "USING_DIRECTIONAL_LIGHT": 1, **four}, False)]
        if mode == "forwardadd":  # one draw per light after the main one, blended by the pass's lines
            out = [({**defines, "DIRECTIONAL": 1, "USING_DIRECTIONAL_LIGHT": 1, "PBRLAB_UNITY_ADD_DIRECTIONAL": i}, False)
                   for i in range(1, defines.get("PBRLAB_DIRECTIONAL_COUNT", 0))]
            for kind in ("POINT", "SPOT"):
                out += [({**defines, kind: 1, f"PBRLAB_UNITY_ADD_{kind}": i}, False)
                        for i in range(defines.get(f"PBRLAB_{kind}_COUNT", 0))]
            return out
        if mode == "vertex":  # Unity's vertex lights (generate_pass._vertex_lights)
            return [({**defines, "PBRLAB_UNITY_VERTEX_LIGHTS": 1}, False)]
        return [(defines, False)]
    if not unity_pass.light_keywords:
        return [(defines, False)]
    counts = {kind: defines.get(f"PBRLAB_{kind}_COUNT", 0) for kind in ("DIRECTIONAL", "POINT", "SPOT")}
    none = {f"PBRLAB_{kind}_COUNT": 0 for kind in counts}
    out = [({**defines, **none, "PBRLAB_DIRECTIONAL_COUNT": counts["DIRECTIONAL"], "DIRECTIONAL": 1,
             "USING_DIRECTIONAL_LIGHT": 1}, False)]
    for kind in ("POINT", "SPOT"):
        if counts[kind]:
            out.append(({**defines, **none, f"PBRLAB_{kind}_COUNT": counts[kind], kind: 1,
                         "PBRLAB_UNITY_FORWARD_ADD": 1}, True))
    return out


# Unity's ColorWriteMask bits (a ColorMask [_Property] of a number): red 8, green 4, blue 2, alpha 1.
_MASK_BITS = (8, 4, 2, 1)


def color_mask(words: str) -> tuple:
    """ShaderLab's ``ColorMask`` as (r, g, b, a) writes: channel letters (RGB, A, RGBA), 0 (none),
    or a ColorWriteMask number."""
    words = words.strip().lower()
    if words.isdigit():
        return tuple(bool(int(words) & bit) for bit in _MASK_BITS)
    if words == "0":
        return (False, False, False, False)
    return tuple(c in words for c in "rgba")


def pass_state(alpha_mode: str, unity_pass, additive: bool = False) -> RenderState:
    """Blending, depth writes, depth test and culling of one pass of a Unity shader: a surface
    program's from its #pragma surface alpha option (and ZWrite line), a vertex/fragment
    pass's from its Blend, ZWrite and ZTest lines; its Cull line for meshes; its ColorMask and Stencil
    block (a surface program's, its SubShader's, in its ForwardAdd draws too). ``additive``: a
    ForwardAdd program, added to what the base program drew (Unity: Blend One One, or SrcAlpha
    One when the surface blends; ZWrite Off), the target's alpha kept."""
    state = unity_pass.state
    if additive:
        source = moderngl.SRC_ALPHA if alpha_mode in BLENDED_ALPHA_MODES else moderngl.ONE
        return RenderState(blend=(source, moderngl.ONE, moderngl.ZERO, moderngl.ONE), depth_write=False,
                           depth_func="<=", cull=state.cull, color_mask=color_mask(state.color_mask),
                           stencil=state.stencil)
    if unity_pass.kind == "surface":
        blended = alpha_mode_state(alpha_mode, "<=", None if state.zwrite is None else state.zwrite)
        return RenderState(blend=blended.blend, depth_write=blended.depth_write, depth_func="<=", cull=state.cull,
                           color_mask=color_mask(state.color_mask), stencil=state.stencil)
    blend = None
    if state.blend_factors:
        blend = tuple(_UNITY_FACTORS[f] for f in state.blend_factors)
        if unity_pass.light_mode.lower() == "forwardadd":  # light added: the coverage stays
            blend = (*blend[:2], moderngl.ZERO, moderngl.ONE)
    return RenderState(blend=blend, depth_write=True if state.zwrite is None else state.zwrite,
                       depth_func=_UNITY_DEPTH[state.ztest], cull=state.cull, color_mask=color_mask(state.color_mask),
                       stencil=state.stencil)


class GrabPass:
    """``GrabPass { "_Name" }``: the target as drawn so far, for the passes after it."""
    traces_spheres = False

    def __init__(self, unity_pass):
        self.grab = unity_pass.texture


class ProgramPass:
    """A surface program or a vertex/fragment pass of a Unity shader."""
    grab = None
    four_lights = False  # a ForwardBase pass of a shader without a ForwardAdd pass (light_programs)

    def __init__(self, unity_pass, alpha_mode: str, moves_vertices: bool, lightmap=None, dynamic_lightmap=None):
        self.unity_pass = unity_pass
        self.alpha_mode = alpha_mode
        self.lightmap = lightmap  # the material's supplied lightmap (lightmaps.py), or None
        self.dynamic_lightmap = dynamic_lightmap  # its realtime GI lightmap (dynamic_lightmaps.py), or None
        # a sphere is ray-traced by a surface program that leaves vertices where they are
        self.traces_spheres = unity_pass.kind == "surface" and not moves_vertices
        self.fullscreen = fullscreen_pass.is_fullscreen(unity_pass)  # drawn as Unity's Blitter draws

    def draws(self, defines: dict) -> list:
        defines = {**defines, **lightmaps.program_defines(self.unity_pass, self.lightmap),
                   **dynamic_lightmaps.program_defines(self.unity_pass, self.dynamic_lightmap),
                   **light_probes.program_defines(self.unity_pass, self.lightmap, self.dynamic_lightmap),
                   **user_definitions.program_defines(self.unity_pass),
                   **graphics_api.program_defines(self.unity_pass)}  # SHADER_API_GLCORE
        if getattr(self.unity_pass, "srp", False):  # the Unity of the URP the stand-ins follow (conditionals)
            defines["UNITY_VERSION"] = conditionals.URP_UNITY_VERSION
        out = [(keyed, pass_state(self.alpha_mode, self.unity_pass, additive))
               for keyed, additive in light_programs(self.unity_pass, defines, self.four_lights)]
        if deferred.is_light_pass(self.unity_pass):  # lights after the first: the coverage stays
            out[1:] = [(keyed, dataclasses.replace(state, blend=(*state.blend[:2], moderngl.ZERO, moderngl.ONE))
                        if state.blend is not None else state) for keyed, state in out[1:]]
        return out

    def program(self, ctx, stem, defines, language, surface, mesh_fragment):
        from . import program as unity_program
        from . import program_pass as unity_program_pass
        if self.unity_pass.kind == "surface":
            return unity_program.build_program(ctx, self.unity_pass, language, stem, defines)
        return unity_program_pass.build_pass_program(ctx, self.unity_pass, language, defines,
                                                     blended=bool(self.unity_pass.state.blend_factors))

    def bind(self, program, material, obj, frame, cache, environment_cube, first_unit, grabbed) -> None:
        from . import program as unity_program
        unity_program.bind(program, material, obj, frame, cache, environment_cube, first_unit)
        if self.fullscreen:
            fullscreen_pass.bind(program, frame)
        unit = first_unit + len(material.properties)
        for i, (name, texture) in enumerate(sorted(grabbed.items())):
            texture.use(unit + i)  # a GrabPass's texture, over the white stand-in bound above
            _set(program, name, unit + i)
            w, h = texture.size  # and its _TexelSize, as Unity sets it for the grab, into the type the
            # program declares (its leading components: a float2 takes 1/width, 1/height)
            unity_program._bind_vector(program, f"{name}_TexelSize", f"the GrabPass texture {name}'s _TexelSize",
                                       (1.0 / w, 1.0 / h, float(w), float(h)))
        unit += len(grabbed)
        unit += light_space.bind(program, cache, unit)  # the light's attenuation and cookie textures
        used = lightmaps.bind(program, self.lightmap, cache, unit)
        used += dynamic_lightmaps.bind(program, self.dynamic_lightmap, cache, unit + used)
        used += shadow_maps.bind_unset_compared(program, cache, unit + used,  # URP's empty shadow map,
                                                material.properties)  # or a property's compared view
        unset_samplers.bind_unset(program, cache, environment_cube, unit + used)  # last: what no binder set

    def sphere_vertex_array(self, ctx, program):
        from . import tessellate
        return tessellate.sphere_vertex_array(ctx, program)

    def fullscreen_vertex_array(self, ctx, program):
        # the Blitter's triangle, or its quad (fullscreen_pass.py)
        return fullscreen_pass.vertex_array(ctx, program, fullscreen_pass.draws_quad(self.unity_pass))


class UnitySource:
    """``MaterialSource`` of a material whose surface is a Unity shader (module doc)."""
    camera_near = UNITY_CAMERA_NEAR
    camera_far = UNITY_CAMERA_FAR

    def __init__(self, shader, lightmap=None):
        self.shader = shader  # model.UnityShader: every pass that runs
        self.moves_vertices = shader.moves_vertices
        self.lightmap = lightmap  # the supplied lightmap of the material's objects (lightmaps.py)
        self.dynamic_lightmap = None  # their supplied realtime GI lightmap (dynamic_lightmaps.py)

    def passes(self, material) -> list:
        out = []
        adds = any(p.kind != "grab" and p.kind != "surface" and p.light_mode.lower() == "forwardadd"
                   for p in self.shader.passes)
        for p in lightmaps.vertex_lit_passes(self.shader.passes, self.lightmap):
            if _skipped(p, self.shader.path) or fullscreen_pass.not_drawn(p, out):
                continue
            for name in dict.fromkeys(_NAMED_TEXTURES.findall(_read_text(p, self.shader.path))
                                      if p.kind != "grab" else ()):
                if not any(q.grab == name for q in out):  # URP's opaque copy, or its colour target
                    out.append(GrabPass(GrabPassModel(name, p.program_line)))
            if fullscreen_pass.is_fullscreen(p):  # its _BlitTexture: the camera's colour so far
                out.append(fullscreen_pass.SourceGrab())
            out.append(GrabPass(p) if p.kind == "grab" else ProgramPass(p, material.alpha_mode, self.moves_vertices,
                                                                        self.lightmap, self.dynamic_lightmap))
            out[-1].four_lights = not adds
        return out

    def camera_textures(self, material) -> frozenset:
        """The camera's textures its passes read (render/camera_textures.py renders them; scene/gbuffer_surface.py)."""
        from ...scene.gbuffer_surface import read_by
        return frozenset().union(*(read_by(_read_text(p, self.shader.path)) for p in self.shader.passes
                                   if p.kind != "grab"))

    def gbuffer_surface(self, material):
        """What the object shows in the depth pre-pass and the G-buffer: in the depth texture
        when its shader's Queue is opaque (Unity's rule: render queue <= 2500, Geometry by
        default); its surface there Unity's default material's (Default-Material: Standard,
        white albedo, metallic 0, smoothness 0.5): the harness has no Deferred pass of its own
        to run (render/camera_textures.py)."""
        from ...scene.gbuffer_surface import DEFAULT_STANDARD_SURFACE
        if self.draws_fullscreen(material):  # no surface of its own there (fullscreen_pass.py)
            return None
        return DEFAULT_STANDARD_SURFACE if _render_queue(self.shader.path) <= _OPAQUE_QUEUE_LIMIT else None

    def draws_fullscreen(self, material) -> bool:
        """Whether it draws a full-screen pass, after the rest of the scene (fullscreen_pass.py)."""
        return any(fullscreen_pass.is_fullscreen(p) for p in self.shader.passes)

    def defines(self, material) -> dict:
        return {k: 1 for k in material.keywords}  # the keywords the material enables

    def instanceable(self, material) -> bool:
        return False

    def surface_file(self, material, language: str):
        return None  # its programs are generated from the shader (program.py), not a surface file

    def layers(self, material) -> frozenset:
        return frozenset().union(*(p.layers for p in self.shader.passes if p.kind == "surface"))


# Unity's named render queues ("Queue"="Transparent+1"); the depth texture and the G-buffer
# hold the objects of queue 2500 and below (Unity's manual, "Camera's depth texture").
_QUEUES = {"background": 1000, "geometry": 2000, "alphatest": 2450, "transparent": 3000, "overlay": 4000}
_OPAQUE_QUEUE_LIMIT = 2500
_QUEUE_TAG = re.compile(r'"Queue"\s*=\s*"(\w+)\s*([+-]\s*\d+)?"', re.I)


# URP's opaque texture (DeclareOpaqueTexture.hlsl, or the program's own declaration of it): a
# copy of the target as drawn before the object, as a built-in GrabPass makes (the stand-in says
# what it holds). The camera's colour target _CameraColorTexture, which a program may declare and
# sample itself: URP renders the object into that target, so a read of it shows the frame as
# drawn so far at best (a read of the target being written is undefined on Direct3D and GL), the
# same copy under its own name.
OPAQUE_TEXTURE = "_CameraOpaqueTexture"
_NAMED_TEXTURES = re.compile(r"\b(_CameraOpaqueTexture|_CameraColorTexture)\b")


def _read_text(unity_pass, path: Path) -> str:
    """The text whose names say which camera textures a pass reads: its program, and for a URP
    program the files it includes too (URP's DeclareDepthTexture.hlsl declares the depth texture
    its SampleSceneDepth reads, which the program need not name)."""
    if not getattr(unity_pass, "srp", False):
        return unity_pass.program
    from .source_text import included_text
    return unity_pass.program + included_text(unity_pass.program, path.parent)


def _render_queue(path: Path) -> int:
    """The render queue the shader's first Queue tag names (Geometry, 2000, without one)."""
    from .source_text import blank_comments
    m = _QUEUE_TAG.search(blank_comments(path.read_text(encoding="utf-8", errors="replace")))
    if m is None or m.group(1).lower() not in _QUEUES:
        return _QUEUES["geometry"]
    return _QUEUES[m.group(1).lower()] + int((m.group(2) or "0").replace(" ", ""))


def _skipped(unity_pass, path: Path) -> bool:
    """A pass of a deferred shader Unity does not draw in the harness's setting (deferred.py), warned."""
    reason = deferred.skipped_reason(unity_pass)
    if reason is not None:
        from . import UnityShaderWarning
        named = f"Pass '{unity_pass.name}'" if unity_pass.name else "the Pass"
        warnings.warn(f"{path.name}: {named} at line {unity_pass.program_line} skipped: {reason}",
                      UnityShaderWarning, stacklevel=3)
    return reason is not None


def reads(path: Path) -> bool:
    """Whether a material's ``surface`` file is a Unity shader this importer reads."""
    from . import is_unity_surface
    return is_unity_surface(path)


def read_material(r, m, base: Path, pipeline=None, source_type=None) -> None:
    """Fill ``m`` (scene.model.Material) from a material whose surface is a Unity shader: its
    Properties, overridden by `properties`; alpha mode and cutoff from its #pragma surface.
    ``r`` is the scene model's reader of the material's fields (fail, has, raw, finish).
    ``pipeline`` (parse.BUILTIN by default) picks the SubShaders and passes that run, and
    ``source_type`` (UnitySource by default) is the material source made of the shader: the
    Universal Render Pipeline's importer (importers/urp/) passes its own."""
    from . import BUILTIN, UnityShaderError, load_shader, read_shader, resolve_properties
    lightmap = lightmaps.read_lightmap(r, base)  # URP's too (its stand-ins' SampleLightmap reads it)
    dynamic = dynamic_lightmaps.read_dynamic_lightmap(r, base)
    if dynamic is not None and pipeline not in (None, BUILTIN):
        r.fail(f"a supplied realtime GI lightmap is read for Unity's built-in render pipeline only, not "
               f"{pipeline.name}", "dynamic_lightmap")
    drawn = dynamic_lightmaps.realtime_lit(lightmaps.lightmapped(pipeline or BUILTIN, lightmap) if lightmap else pipeline or BUILTIN,
                                           dynamic)
    try:
        shader = load_shader(m.surface, drawn)
    except UnityShaderError as exc:
        r.fail(str(exc), "surface")
    for key in _NOT_FOR_UNITY + TRANSMISSION_KEYS:
        if r.has(key):
            r.fail(f"a Unity surface shader's material takes its values from `properties` "
                   f"(the shader's Properties) and its alpha mode from #pragma surface; "
                   f"remove `{key}`", key)
    m.properties = resolve_properties(shader, r.raw("properties", {}), base,
                                      f"{r.origin}: {r.path.lstrip('.')}.properties")
    keywords = r.raw("keywords", [])
    declared = shader.keywords
    if not isinstance(keywords, list) or not all(isinstance(k, str) for k in keywords):
        r.fail("expected a list of shader keyword names", "keywords")
    for k in keywords:
        if k not in declared:
            r.fail(f"{k!r} is not a keyword of {m.surface.name} (its #pragma multi_compile / "
                   f"shader_feature lines declare: {', '.join(sorted(declared)) or 'none'})", "keywords")
        refused = shader.refused_keywords.get(k)
        if refused:
            r.fail(f"{k!r}: {refused}", "keywords")
    m.keywords = tuple(dict.fromkeys(keywords))
    # the keywords Unity's material inspector enables from its property drawers ([Toggle],
    # [KeywordEnum]...: keyword_drawers.py), then each remaining set's first (a set without _)
    m.keywords += shader.unset_keywords(drawer_keywords(shader.properties, m.properties), m.keywords)
    m.keywords += tuple(k for k in shader.first_keywords(m.keywords) if k not in shader.refused_keywords)
    if m.keywords:  # the variant the material draws: the struct members and functions its
        # keywords' #if branches hold (parse_pass reads a program's conditionals for its model)
        try:
            shader = read_shader(m.surface, dataclasses.replace(drawn, keywords=drawn.keywords + m.keywords))
        except UnityShaderError as exc:
            r.fail(str(exc), "surface")
    m.source = (source_type or UnitySource)(shader)
    if lightmap is not None:
        m.source.lightmap = lightmap
    if dynamic is not None:
        m.source.dynamic_lightmap = dynamic
    if pipeline in (None, BUILTIN):  # (URP's package stand-ins have their own lightmap macros)
        lightmaps.check_reads(shader, lightmap, r, m.keywords)
        dynamic_lightmaps.check_reads(shader, dynamic, r, m.keywords)
    surface = shader.surface
    if surface is not None:
        m.alpha_mode = surface.pragma.alpha_mode
    else:  # vertex/fragment passes blend by their own Blend lines; "fade" sorts them back to front
        m.alpha_mode = "fade" if any(p.state.blend_factors and getattr(p, "light_mode", "").lower() != "forwardadd"
                                     for p in shader.passes) else "opaque"  # adding light is not fading
    m.workflow = "specular" if surface is not None and surface.output_type in (
        "SurfaceOutputStandardSpecular", "SurfaceOutputStandardSpecularLayered") else "metallic"
    cutoff = surface.pragma.cutoff_property if surface is not None else None
    if cutoff is not None:
        value = m.properties.get(cutoff)
        m.alpha_cutoff = float(value) if isinstance(value, float) else 0.5
    r.finish()


def check_objects(objects, materials, origin: str) -> None:
    """A Unity shader's Cull Front/Off is applied to meshes; a ray-traced sphere shows its
    front surface only (a sphere whose shader has a vertex: function is a mesh): warned."""
    from . import UnityShaderWarning
    for i, obj in enumerate(objects):
        source = materials[obj.material].source
        shader = source.shader.surface if isinstance(source, UnitySource) else None
        if obj.sphere is not None and shader is not None and not source.moves_vertices \
                and shader.state.cull != "back":
            warnings.warn(f"{origin}: objects[{i}]: {shader.path.name}: Cull {shader.state.cull.capitalize()} "
                          "is not applied to a ray-traced sphere (its front surface only); use a mesh "
                          "(e.g. {\"primitive\": \"uv_sphere\"}) to see back faces",
                          UnityShaderWarning, stacklevel=4)
