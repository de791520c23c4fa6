"""GPU rendering of a scene: spheres ray-traced per pixel, meshes rasterised, one HDR
float pass, then exposure + tonemap, then the display encode to 8-bit sRGB.

With ``render.antialias`` = N > 1 the float pass is multisampled (N samples per pixel,
targets.Target): meshes by the rasteriser's coverage, spheres by their own (the sphere
program shades once per pixel and writes which samples' rays hit the sphere to the sample
mask: scene_geometry.inc, pbrlab_sphere_coverage); the samples are averaged in linear
radiance (targets.Target.resolve) before metering, exposure, tone mapping and the encode,
and the linear image's alpha becomes the pixel's coverage.

``render_scene(scene)`` returns a ``Rendering`` with ``linear`` (HxWx4 float32 scene
radiance, before exposure: what the EXR holds) and ``srgb8`` (HxWx4 uint8 display image).
By default the tonemapped display values are rendered to float and encoded on the CPU with
the exact curve (``pbrlab.maths.srgb8``), so the display image is the same on every machine;
``transfer="HARDWARE"`` takes the lecture's sRGB-framebuffer path instead.
"""

from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass
from pathlib import Path

import moderngl
import numpy as np

from . import camera_textures, environment_visibility, features, instanced_draws, resource_cache, shadow_map, tangent_frames
from ..gpu import gl, gl_limits, ibl, stencil_state, surface_bindings
from ..scene import meshes, surface_layers
from ..gpu import targets
from ..gpu.cancellation import dies_on_signal
from ..gpu.driver_time_limit import within_time_limit
from . import screen_space_reflection, transmission_copy, volume_exit
from ..maths import srgb8 as srgb8_codes
from .depth_range import scene_frame, scene_radius  # noqa: F401 (scene_radius: public)
from ..foundation.errors import PbrlabError, SceneError
from ..maths.exposure import metered_exposure
from ..maths.reference import shading as ref_shading
from ..foundation.file_identity import include_closure
from ..gpu.hlsl import HLSL_ROOT
from ..gpu.programs import LANGUAGES, fragment_template, program_from_templates
from ..gpu.programs import set_uniform as _set
from ..gpu.programs import set_uniform_array as _set_array
from ..gpu.programs import SAMPLES_DEFINE
from ..scene.model import HDR_TARGETS, Light, Scene
from ..scene.standard_material import BLENDED_ALPHA_MODES, source_of
from ..gpu.shaders import GLSL_ROOT

_UNIT_CUBE = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], np.float32)
# Triangles of the unit cube, counter-clockwise seen from outside.
_CUBE_TRIANGLES = np.array([
    0, 2, 1, 1, 2, 3,  4, 5, 6, 5, 7, 6,  0, 1, 4, 1, 5, 4,
    2, 6, 3, 3, 6, 7,  0, 4, 2, 2, 4, 6,  1, 3, 5, 3, 7, 5], np.int32)


@dataclass
class Rendering:
    linear: np.ndarray  # HxWx4 float32 radiance; alpha = material alpha where covered, 0 elsewhere
    srgb8: np.ndarray   # HxWx4 uint8, exposure + tonemap + sRGB encode (see ``transfer``)
    info: dict
    programs: "features.ProgramPlan" = None  # what was compiled
    draw_calls: int = 0  # the objects' draw calls (an instanced draw counts once)
    exposure_ev: float = 0.0  # the exposure the display image was made with (metered or not)


class _SceneResources:
    """GPU data of every draw of one render: environment, DFG table, textures, and the
    neutral stand-ins the full program reads where the scene has nothing; kept between
    renders by the context's resource_cache."""

    ENV_UNITS = {"u_dfg_lut": 0, "u_env_prefiltered": 1, "u_sheen_lut": 2, "u_env_irradiance": 4}
    TRANSMISSION_COPY_UNIT = 3  # the scene's transmission copy (transmission_copy.py), when it has one
    SUN_SHADOW_UNIT = 5  # the environment's sun's shadow map (shadow_map.py), when render.environment_sun finds one
    SKY_SHADOW_UNIT = 6  # the environment's visibility maps (environment_visibility.py), render.environment_visibility
    VOLUME_EXIT_UNIT = 7  # the volumes' exit points (volume_exit.py), render.volume_chord
    SSR_COLOUR_UNIT, SSR_SURFACE_UNIT = 8, 9  # render.screen_space_reflections (screen_space_reflection.py)
    FIRST_MATERIAL_UNIT = 10
    # 1x1 float textures: multiplying by them, or unpacking the normal, changes nothing.
    NEUTRAL_TEXEL = {"normal": (0.5, 0.5, 1.0, 1.0)}  # UnpackNormal -> (0, 0, 1) exactly

    def __init__(self, ctx, scene: Scene, full: bool, sun=None):
        self.full = full
        self.sun_shadow = None  # set by render_scene once the shadow map is drawn
        self.sky_visibility = None  # set by render_scene once the visibility maps are drawn
        self.camera_textures = None  # set by render_scene where a program reads them (camera_textures.py)
        self.cache = resource_cache.context_cache(ctx)
        self.env_sh = None
        self.transmission_copy = None  # set by render_scene once the copy is drawn
        self.volume_exit = None  # set by render_scene once the volumes' back faces are drawn
        self.reflection = None  # set by render_scene with render.screen_space_reflections
        # the DFG table serves every light (diffuse-specular coupling), not only the environment
        # in the tier's layout (PBR_DFG_LUT_LAYOUT, pbr/shading/dispatch.glsl: LOW reads its own)
        layout = ref_shading.QUALITY_DFG_LUT_LAYOUT[scene.render.quality.upper()]
        self.env_textures = {"u_dfg_lut": self.cache.dfg(layout)}
        # the sheen albedo table (sheen_table.py), for materials with a sheen (PBRLAB_SHEEN)
        if any("sheen" in surface_layers.material_layers(m) for m in scene.materials.values()):
            self.env_textures["u_sheen_lut"] = self.cache.sheen()
        if scene.environment is not None:
            environment = self.cache.environment(scene.environment, sun)
        elif full:  # the full program always samples an environment: a black one
            environment = self.cache.black_environment()
        else:
            return
        self.env_sh = environment.sh
        self.env_textures["u_env_prefiltered"] = environment.prefiltered
        self.env_textures["u_env_irradiance"] = environment.irradiance

    def neutral_texture(self, slot: str) -> moderngl.Texture:
        return self.cache.constant_texture(self.NEUTRAL_TEXEL.get(slot, (1.0, 1.0, 1.0, 1.0)))

    def bind(self, program, scene, frame, material):
        _upload_scene_uniforms(program, scene, frame, self.env_sh)
        for name, unit in self.ENV_UNITS.items():
            if name in self.env_textures:
                self.env_textures[name].use(unit)
                _set(program, name, unit)
        _set(program, "u_env_lod_count", float(ibl.PREFILTER_LEVELS))
        if self.sun_shadow is not None:
            self.sun_shadow.bind(program, self.SUN_SHADOW_UNIT)
        if self.sky_visibility is not None:
            self.sky_visibility.bind(program, self.SKY_SHADOW_UNIT)
        if self.transmission_copy is not None:  # a program that does not transmit declares none of it
            self.transmission_copy.bind(program, self.TRANSMISSION_COPY_UNIT, frame.view_proj)
        if self.volume_exit is not None:
            self.volume_exit.bind(program, self.VOLUME_EXIT_UNIT, material.name)
        if self.reflection is not None:
            self.reflection.bind(program, self.SSR_COLOUR_UNIT, self.SSR_SURFACE_UNIT)
        _upload_material(program, material)
        unit = self.FIRST_MATERIAL_UNIT
        for name, path in sorted(material.textures.items()):
            self.cache.texture(path, material.texture_srgb[name], material.texture_sampler.get(name)).use(unit)
            _set(program, f"u_{name}_map" if material.surface is None else name, unit)
            unit += 1
        if self.full and material.surface is None:
            for slot in features.FULL_MAP_SLOTS:
                if slot not in material.textures:
                    self.neutral_texture(slot).use(unit)
                    _set(program, f"u_{slot}_map", unit)
                    unit += 1


def _with_environment_sun(ctx, scene: Scene):
    """(scene, sun): with render.environment_sun and an environment that has a sun
    (scene/environment_sun.py), the sun as directional light 0 (shadow_map.py shadows it) and the
    environment read without it (_SceneResources); otherwise the scene with the option off."""
    if not scene.render.environment_sun:
        return scene, None
    sun = None
    if scene.environment is not None:
        sun = resource_cache.context_cache(ctx).environment_sun(scene.environment)
    if sun is None:  # nothing to split off: the scene is drawn as without the option
        return dataclasses.replace(scene, render=dataclasses.replace(scene.render, environment_sun=False)), None
    light = Light(type="directional", color=np.asarray(sun.radiance, np.float64), intensity=1.0,
                  direction=np.asarray(sun.direction, np.float64))
    return dataclasses.replace(scene, lights=[light, *scene.lights]), sun


def _with_environment_visibility(scene: Scene) -> Scene:
    """The scene with render.environment_visibility off where it has nothing to do: no
    environment, or no object to cast or receive (environment_visibility.py)."""
    if scene.render.environment_visibility and (scene.environment is None or not scene.objects):
        return dataclasses.replace(scene, render=dataclasses.replace(scene.render, environment_visibility=0))
    return scene


def _upload_scene_uniforms(program, scene: Scene, frame, env_sh):
    _set(program, "u_camera_position", tuple(frame.position))
    _set(program, "u_camera_forward", tuple(frame.forward))
    _set(program, "u_camera_right", tuple(frame.right))
    _set(program, "u_camera_up", tuple(frame.up))
    _set(program, "u_viewport_size", tuple(float(s) for s in frame.size))
    _set(program, "u_view_proj", tuple(frame.view_proj.T.reshape(-1)))  # GL is column-major
    by_type = {t: [light for light in scene.lights if light.type == t] for t in features.LIGHT_TYPES}
    for light_type, lights in by_type.items():
        _set(program, f"u_{light_type}_active", len(lights))
    if by_type["directional"]:
        _set_array(program, "u_directional_direction", [l.direction for l in by_type["directional"]])
        _set_array(program, "u_directional_radiance", [l.color * l.intensity for l in by_type["directional"]])
    for light_type in ("point", "spot"):
        lights = by_type[light_type]
        if not lights:
            continue
        _set_array(program, f"u_{light_type}_position", [l.position for l in lights])
        _set_array(program, f"u_{light_type}_radiance", [l.color * l.intensity for l in lights])
        _set_array(program, f"u_{light_type}_range", [min(l.range, 3.0e38) for l in lights])
    if by_type["spot"]:
        cones = []
        for light in by_type["spot"]:
            cos_outer = np.cos(np.radians(light.outer_cone_deg))
            cos_inner = np.cos(np.radians(light.inner_cone_deg))
            cones.append([cos_outer, 1.0 / max(cos_inner - cos_outer, 1e-4)])
        _set_array(program, "u_spot_direction", [l.direction for l in by_type["spot"]])
        _set_array(program, "u_spot_cone", cones)
    if env_sh is not None:
        _set_array(program, "u_env_sh", env_sh)


def _upload_material(program, material):
    _set(program, "u_albedo", tuple(material.albedo))
    _set(program, "u_specular", tuple(material.specular))
    _set(program, "u_metallic", material.metallic)
    _set(program, "u_smoothness", material.smoothness)
    _set(program, "u_emission", tuple(material.emission))
    _set(program, "u_occlusion", material.occlusion)
    # opaque materials show no alpha: the full program is fed the neutral 1
    _set(program, "u_alpha", material.alpha if material.alpha_mode != "opaque" else 1.0)
    _set(program, "u_alpha_cutoff", material.alpha_cutoff)
    _set(program, "u_normal_scale", material.normal_scale)
    _set(program, "u_occlusion_strength", material.occlusion_strength)
    _set(program, "u_clearcoat", material.clearcoat)
    _set(program, "u_clearcoat_smoothness", material.clearcoat_smoothness)
    _set(program, "u_clearcoat_normal_scale", material.clearcoat_normal_scale)
    _set(program, "u_sheen_color", tuple(material.sheen_color))
    _set(program, "u_sheen_smoothness", material.sheen_smoothness)
    _set(program, "u_anisotropy_strength", material.anisotropy_strength)
    _set(program, "u_anisotropy_rotation", material.anisotropy_rotation)
    _set(program, "u_iridescence", material.iridescence)
    _set(program, "u_iridescence_ior", material.iridescence_ior)
    _set(program, "u_iridescence_thickness", (material.iridescence_thickness_min, material.iridescence_thickness_max))
    _set(program, "u_transmission", material.transmission)
    _set(program, "u_thickness", material.thickness)
    _set(program, "u_attenuation_color", tuple(material.attenuation_color))
    _set(program, "u_attenuation_distance", material.attenuation_distance)
    _set(program, "u_transmission_ior", material.ior)
    if material.specular_f90 is not None:
        _set(program, "u_specular_f90", material.specular_f90)
    if material.dielectric_specular is not None:
        _set(program, "u_dielectric_specular", tuple(material.dielectric_specular))
    for slot, transform in material.texture_transform.items():
        _set_array(program, f"u_{slot}_uv_transform", np.asarray(transform)[:2])


# The display encodes: EXACT (the shader writes linear display values to a float target,
# pbrlab.maths.srgb8 rounds them on the exact curve) or a PBR_COLOR_TRANSFER_* path of the shader.
COLOR_TRANSFERS = ("EXACT", "HARDWARE", "SRGB", "GAMMA22", "FAST")


def _clear_and_reset(ctx) -> None:
    """The bound target cleared (colour 0: alpha is coverage, the background 0; depth 1; stencil
    0, cleared with depth, as engines clear it each frame), and the state every render starts
    from, whatever an earlier render in this context left (a pass's own ZTest once leaked into
    the next scene: "<=" moved 7 depth-tie pixels of the lit scene, so a golden depended on
    which test ran before it in the process)."""
    ctx.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
    stencil_state.clear(ctx)  # and the stencil test off
    ctx.enable(moderngl.DEPTH_TEST)
    ctx.disable(moderngl.BLEND | moderngl.CULL_FACE)
    ctx.depth_func = "<"
    ctx.front_face = "ccw"
    ctx.cull_face = "back"


def _draw_order(scene: Scene, frame):
    """Opaque and cutout objects first, then blended ones from far to near, then the objects
    whose material draws a full-screen pass (they read what the others drew)."""
    def centre(obj):
        if obj.sphere is not None:
            return obj.sphere[0]
        return obj.transform[:3, :3] @ meshes.local_centre(obj) + obj.transform[:3, 3]
    opaque = [o for o in scene.objects if scene.materials[o.material].alpha_mode in ("opaque", "cutout")]
    blended = [o for o in scene.objects if scene.materials[o.material].alpha_mode in BLENDED_ALPHA_MODES]
    blended.sort(key=lambda o: -float(np.linalg.norm(centre(o) - frame.position)))

    def fullscreen(o):  # a full-screen pass (its material source says so: draws_fullscreen)
        material = scene.materials[o.material]
        return getattr(source_of(material), "draws_fullscreen", lambda m: False)(material)
    return sorted(opaque + blended, key=fullscreen)  # (stable) they read the scene: drawn last


def input_files(scene: Scene, language: str = "glsl") -> list[tuple[Path, str]]:
    """Every file a render of ``scene`` reads, with its role: what an output must not be."""
    found = []
    if scene.environment is not None and scene.environment.path is not None:
        found.append((scene.environment.path, "the scene's environment image"))
    for name, material in scene.materials.items():
        for slot, path in material.textures.items():
            if isinstance(path, (str, Path)):  # not an image an importer decoded from its file's bytes
                found.append((path, f"material {name}'s {slot} texture"))
        for prop, value in material.properties.items():  # a shader material's texture properties (with a path)
            if isinstance(getattr(value, "path", None), Path):
                found.append((value.path, f"material {name}'s {prop} texture property"))
        if material.surface is not None:
            for surface in {material.surface, material.surface.with_suffix(".hlsl")}:
                if surface.is_file():
                    found.append((surface, f"material {name}'s surface file"))
                    text = surface.read_text(encoding="utf-8", errors="replace")
                    found += [(p, f"a file material {name}'s surface includes") for p in
                              include_closure(text, [surface.parent, GLSL_ROOT, HLSL_ROOT], surface.parent)]
    for i, obj in enumerate(scene.objects):
        if obj.mesh_path is not None:
            found.append((obj.mesh_path, f"objects[{i}]'s mesh"))
    return found + list(scene.read_files)  # what the importers read (a model's file, buffers, images)


def checked_size(size) -> tuple[int, int]:
    """``size`` as (width, height): two integers >= 1 (numpy integers too)."""
    try:
        w, h = size
    except (TypeError, ValueError):
        raise PbrlabError(f"size={size!r}: expected (width, height)") from None
    for v in (w, h):
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)) or v < 1:
            raise PbrlabError(f"size={size!r}: expected (width, height), two integers >= 1")
    return int(w), int(h)


def render_scene(scene: Scene, ctx: moderngl.Context | None = None, size=None,
                 transfer: str = "EXACT", specialise: bool = True,
                 language: str = "glsl", mesh_fragment: str | None = None,
                 checking: bool = True) -> Rendering:
    """Render ``scene`` (optionally at another ``size``) on ``ctx`` (default: shared).

    ``transfer`` picks the display encode: EXACT (default: float display values rounded
    to the nearest code of the exact sRGB curve on the CPU, identical on every machine),
    HARDWARE (the lecture's sRGB framebuffer: llvmpipe's encode, whose last bit depends on
    the CPU vendor) or a DIY shader encode into a plain 8-bit target: SRGB (exact curve),
    GAMMA22 (pow 1/2.2) or FAST (sqrt). ``specialise=False`` renders every
    material with the full program (every effect compiled in, fed neutral values):
    the same image, at the full program's cost (harness/pbrlab/render/features.py).
    ``language="hlsl"`` shades with the HLSL library (hlsl_ports/) and the harness's HLSL
    pixel shaders, cross-compiled by glslang and spirv-cross (harness/pbrlab/gpu/programs.py);
    a material's ``surface`` file then needs its ``.hlsl`` twin beside it.
    ``mesh_fragment`` replaces the meshes' fragment template (the pyrender cross-check's
    composition, templates/pyrender_mesh.frag). ``checking=False`` shades with the production
    programs (PBRLAB_CHECKING 0: no test of the surface's output for NaN or Inf, so a NaN
    normal may shade black instead of making the pixel non-finite; features.plan_programs):
    where every surface output is finite, the same image bit for bit.
    """
    if transfer not in COLOR_TRANSFERS:
        raise PbrlabError(f"transfer={transfer!r}: expected one of {', '.join(COLOR_TRANSFERS)}")
    if language not in LANGUAGES:
        raise ValueError(f"language={language!r}: expected one of {LANGUAGES}")
    if not isinstance(scene, Scene):
        hint = (" (a file path: read it with pbrlab.scene.load_scene first)"
                if isinstance(scene, (str, os.PathLike)) else
                " (a dict: check it with pbrlab.scene.parse_scene first)" if isinstance(scene, dict) else "")
        raise PbrlabError(f"render_scene takes a Scene, got {type(scene).__name__}{hint}")
    if size is not None:  # on a copy: the caller's Scene keeps its own size
        scene = dataclasses.replace(scene, camera=dataclasses.replace(
            scene.camera, size=checked_size(size)))
    supersample = scene.render.supersample
    if supersample > 1:  # drawn larger, filtered down to the camera's size (targets.Target downsample)
        scene = dataclasses.replace(scene, camera=dataclasses.replace(
            scene.camera, size=tuple(int(s) * supersample for s in scene.camera.size)))
    if scene.camera.ortho_half_height is not None and scene.spheres:
        raise SceneError(f"{scene.source}: an orthographic camera draws meshes only; the scene has spheres")
    mesh_fragment = mesh_fragment or fragment_template("mesh", language)
    surfaces = {name: source_of(m).surface_file(m, language) for name, m in scene.materials.items()}
    surface_bindings.check_bindings(scene, surfaces, [HLSL_ROOT if language == "hlsl" else GLSL_ROOT])
    surface_layers.check_twins(scene, surfaces)
    ctx = gl.make_current(ctx or gl.shared_context())
    scene, sun = _with_environment_sun(ctx, scene)  # the sun a light like the scene's own, for the limits too
    scene = _with_environment_visibility(scene)
    gl_limits.check_scene(ctx, scene)
    frame = scene_frame(scene)
    plan = features.plan_programs(scene, specialise, checking=checking)
    hdr_format = HDR_TARGETS[scene.render.hdr_target]
    samples = scene.render.antialias
    if samples != 1:
        gl_limits.check_antialias(ctx, scene, hdr_format)
    w, h = frame.size
    resources = _SceneResources(ctx, scene, full=not plan.specialised, sun=sun)
    if sun is not None and scene.objects:  # the sun's depth pass, before any target of the frame is bound
        resources.sun_shadow = shadow_map.SunShadow(ctx, scene, sun)
    if camera_textures.needed(scene):  # the camera's depth texture and G-buffer, before the frame
        resources.camera_textures = camera_textures.CameraTextures(ctx, scene, frame)
    if scene.render.environment_visibility:  # the sky's K maps, from the sky the environment lookup reads
        from ..scene.environment import environment_image
        resources.sky_visibility = environment_visibility.EnvironmentVisibility(
            ctx, scene, environment_image(scene.environment), scene.render.environment_visibility, sun)
    behind = transmission_copy.seen_through(scene, plan)
    if scene.render.volume_chord and behind is not None:  # the volumes' back faces, before the frame
        resources.volume_exit = volume_exit.VolumeExit(ctx, scene, frame, plan)
    cube_holder = []

    def environment_cube():  # made once per render, only if a shader samples a cube
        if not cube_holder:
            from ..scene import cubemap  # loaded on use
            cube_holder.append(cubemap.environment_cube(ctx, scene.environment))
        return cube_holder[0]

    resources.environment_cube = environment_cube
    grab_holder = []
    cube_vbo = ctx.buffer(_UNIT_CUBE.tobytes())
    cube_ibo = ctx.buffer(_CUBE_TRIANGLES.tobytes())
    draw = _Draw(plan, surfaces, language, mesh_fragment, scene, frame, resources, cube_vbo, cube_ibo,
                 grab_holder)
    copy = None
    draw_calls = 0
    try:
        if behind is not None:  # a transmissive material: first the scene it sees (transmission_copy.py)
            copy = transmission_copy.TransmissionCopy(ctx, (w, h), hdr_format, samples)
            copy.target.use()
            _clear_and_reset(ctx)
            seen = _draw_order(dataclasses.replace(scene, objects=behind), frame)
            draw_calls += _draw_objects(ctx, copy.target, seen, draw)
            ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE | moderngl.BLEND)
            copy.target.fbo.depth_mask = True
            copy.finish()
            resources.transmission_copy = copy
        if scene.render.screen_space_reflections and scene.environment is not None and scene.objects:
            # the frame drawn once (its programs reading the environment alone), then read where a
            # reflected ray meets its surfaces (screen_space_reflection.py)
            resources.reflection = screen_space_reflection.ScreenSpaceReflection(ctx, scene, frame, hdr_format)
            first = resources.reflection.colour_target
            first.use()
            _clear_and_reset(ctx)
            draw_calls += _draw_objects(ctx, first, _draw_order(scene, frame), draw)
            ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE | moderngl.BLEND)
            first.fbo.depth_mask = True
            resources.reflection.finish()
        with targets.Target(ctx, (w, h), hdr_format, samples=samples,
                            resolve_filter=scene.render.antialias_filter, downsample=supersample) as hdr:
            hdr.use()
            _clear_and_reset(ctx)
            draw_calls += _draw_objects(ctx, hdr, _draw_order(scene, frame), draw)
            ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE | moderngl.BLEND)
            hdr.fbo.depth_mask = True
            with dies_on_signal():  # waits for llvmpipe to finish every draw
                linear = hdr.read()  # resolved: each pixel's samples averaged in linear radiance
            if scene.render.exposure_metered:  # darkened just enough not to clip (pbrlab.maths.exposure)
                metered = scene.render.exposure + metered_exposure(linear)
                scene = dataclasses.replace(scene, render=dataclasses.replace(scene.render, exposure=metered))
            srgb8 = _resolve(ctx, hdr, scene, transfer, language)
    finally:
        cube_vbo.release()
        cube_ibo.release()
        if copy is not None:
            copy.release()
        if resources.sun_shadow is not None:
            resources.sun_shadow.release()
        if resources.sky_visibility is not None:
            resources.sky_visibility.release()
        if resources.camera_textures is not None:
            resources.camera_textures.release()
        if resources.volume_exit is not None:
            resources.volume_exit.release()
        if resources.reflection is not None:
            resources.reflection.release()
        for resource in cube_holder + grab_holder:
            resource.release()
    return Rendering(linear=linear, srgb8=srgb8, info=gl.context_info(ctx), programs=plan, draw_calls=draw_calls,
                     exposure_ev=scene.render.exposure)


@dataclass
class _Draw:
    """What every draw of one render shares."""
    plan: "features.ProgramPlan"
    surfaces: dict
    language: str
    mesh_fragment: str
    scene: Scene
    frame: object
    resources: _SceneResources
    cube_vbo: moderngl.Buffer
    cube_ibo: moderngl.Buffer
    grab_holder: list


def _draw_objects(ctx, hdr, objects, draw) -> int:
    """Draw ``objects`` in order into the target ``hdr`` (bound and cleared by the caller);
    ``draw`` holds what every draw of the render shares. Each object's material gives its
    passes (scene.material_passes); each pass draws once or once per light, or grabs what is
    drawn so far. Returns the draw calls made (the instances of one batch are one instanced
    call: instanced_draws.py)."""
    scene = draw.scene
    draw_calls = 0
    try:
        for batch in instanced_draws.batches(objects, lambda o: _instanceable(scene.materials[o.material])):
            obj = batch[0]
            material = scene.materials[obj.material]
            source = source_of(material)
            defines = {**draw.plan.defines[obj.material], **source.defines(material)}
            # the camera's textures (camera_textures.py) are bound as a grab's, by name
            grabbed = draw.resources.camera_textures.bound(source) if draw.resources.camera_textures else {}
            for material_pass in source.passes(material):
                if material_pass.grab is not None:  # what is drawn so far, for the passes after it
                    grabbed[material_pass.grab] = _grab(ctx, hdr, draw.grab_holder,
                                                        getattr(material_pass, "clamp_to_edge", False))
                    continue
                for keyed, state in material_pass.draws(defines):
                    traced = obj.sphere is not None and material_pass.traces_spheres
                    _apply_state(ctx, hdr, state, traced)
                    draw_calls += 1
                    if traced:
                        _draw_sphere(ctx, hdr, obj, material, material_pass, keyed, draw, grabbed)
                    else:  # meshes, and spheres whose pass moves vertices (tessellated)
                        _draw_mesh(ctx, obj, material, material_pass, keyed, state, draw, grabbed, batch)
    finally:
        # the test off again: what follows (grabs, the resolve) is not a pass's; and after a
        # draw that raised (a refused program), nothing else that uses the context gets it
        stencil_state.apply(ctx, None)
    return draw_calls


def _apply_state(ctx, hdr, state, traced: bool = False) -> None:
    """Blending, depth and colour writes, the depth and stencil tests of a pass's draw (its
    culling: ``_cull``). ``traced``: a ray-traced sphere, drawn through its bounding box's back
    faces, takes the stencil state of front faces (the surface it shows)."""
    if state.blend is not None:
        ctx.enable(moderngl.BLEND)
        ctx.blend_func = state.blend
    else:
        ctx.disable(moderngl.BLEND)
    hdr.fbo.depth_mask = state.depth_write
    if tuple(hdr.fbo.color_mask) != tuple(state.color_mask):
        # moderngl keeps a framebuffer's colour mask until the framebuffer is used (its depth
        # mask applies at once): use() it again, the target it already is
        hdr.fbo.color_mask = state.color_mask
        hdr.fbo.use()
    ctx.depth_func = state.depth_func
    stencil = state.stencil
    stencil_state.apply(ctx, stencil.front_on_both_faces() if traced and stencil is not None else stencil)


def _grab(ctx, hdr, holder, clamp_to_edge=False):
    """A grab pass: a copy of the float target as drawn so far (released after the render);
    from a multisampled target the blit resolves (each pixel's samples averaged). Repeating,
    or ``clamp_to_edge``."""
    texture = ctx.texture(hdr.size, 4, dtype=hdr.color.dtype)
    texture.filter = (moderngl.LINEAR, moderngl.LINEAR)
    texture.repeat_x = texture.repeat_y = not clamp_to_edge
    copy = ctx.framebuffer([texture])
    ctx.copy_framebuffer(copy, hdr.fbo)  # a framebuffer blit: float to float, exact
    copy.release()
    hdr.fbo.use()
    holder.append(texture)
    return texture


def _program(ctx, stem, material, material_pass, defines, draw, obj, grabbed):
    """The object's program in ``material_pass``, bound: the scene's bindings, then the pass's."""
    resources = draw.resources
    program = material_pass.program(ctx, stem, defines, draw.language, draw.surfaces[obj.material],
                                    draw.mesh_fragment)
    resources.bind(program, draw.scene, draw.frame, material)
    material_pass.bind(program, material, obj, draw.frame, resources.cache, resources.environment_cube,
                       _SceneResources.FIRST_MATERIAL_UNIT, grabbed)
    return program


def _draw_sphere(ctx, hdr, obj, material, material_pass, defines, draw, grabbed):
    """Back faces of the sphere's bounding cube, ray-traced in the fragment shader; into a
    multisampled ``hdr``, the program also writes which samples the sphere covers."""
    if hdr.samples > 1:
        defines = {**defines, SAMPLES_DEFINE: hdr.samples}
    program = _program(ctx, "sphere", material, material_pass, defines, draw, obj, grabbed)
    centre, radius = obj.sphere
    _set(program, "u_sphere", (*centre, radius))
    if hdr.samples > 1:  # the offsets the sphere's own coverage is tested at (scene_geometry.inc)
        _set_array(program, "u_sample_offsets", hdr.sample_offsets())
    inside = bool(np.all(np.abs(draw.frame.position - centre) <= radius * 1.001))
    _set(program, "u_fullscreen", inside)
    if inside:
        ctx.disable(moderngl.CULL_FACE)
    else:
        ctx.enable(moderngl.CULL_FACE)
        ctx.cull_face = "front"
    vao = ctx.vertex_array(program, [(draw.cube_vbo, "3f", "in_position")], index_buffer=draw.cube_ibo)
    # llvmpipe compiles a program's code at its first draw
    with dies_on_signal(), within_time_limit(f"drawing {obj.where or 'a sphere'} (material {material.name!r})"):
        vao.render(moderngl.TRIANGLES, vertices=3 if inside else 36)
    vao.release()


_TOPOLOGY = {"triangles": moderngl.TRIANGLES, "lines": moderngl.LINES, "points": moderngl.POINTS}


def _instanceable(material) -> bool:
    """Whether objects of ``material`` may share an instanced draw (instanced_draws.py)."""
    return source_of(material).instanceable(material)


def _cull(ctx, material, cull) -> None:
    """Face culling of a mesh: a pass's own (``cull``: front, back, off), else the material's
    sidedness (double-sided, or blended without a say: nothing culled)."""
    two_sided = material.alpha_mode in BLENDED_ALPHA_MODES if material.double_sided is None else material.double_sided
    if cull in ("front", "back"):
        ctx.enable(moderngl.CULL_FACE)
        ctx.cull_face = cull
    elif two_sided or cull == "off":
        ctx.disable(moderngl.CULL_FACE)  # see-through (blended), double-sided, a pass's Cull Off
    else:
        ctx.enable(moderngl.CULL_FACE)
        ctx.cull_face = "back"


def _draw_mesh(ctx, obj, material, material_pass, defines, state, draw, grabbed, batch=None):
    """``batch``: the instances drawn with ``obj`` in one instanced call (obj among them)."""
    instances = None
    if batch is not None and len(batch) > 1:
        defines = {**defines, instanced_draws.INSTANCED_DEFINE: 1}
        instances = instanced_draws.instance_data(batch)
    if getattr(material_pass, "tangents_from_mesh", False) and obj.sphere is None:
        # the degenerate-tangent fallback only where the mesh data can reach it (tangent_frames.py)
        defines = {**defines, **tangent_frames.draw_defines(batch or [obj], defines, draw.scene.render.antialias,
                                                            material.surface is not None)}
    program = _program(ctx, "mesh", material, material_pass, defines, draw, obj, grabbed)
    if instances is None:
        _set(program, "u_model", tuple(instanced_draws.model_matrix(obj.transform)))
        _set(program, "u_normal_matrix", tuple(instanced_draws.normal_matrix(obj.transform)))
    _cull(ctx, material, state.cull)
    if getattr(material_pass, "fullscreen", False):  # a procedural full-screen draw, no mesh
        vao, buffers = material_pass.fullscreen_vertex_array(ctx, program)
    elif obj.sphere is not None:  # a sphere whose pass moves vertices: tessellated by the pass
        vao, buffers = material_pass.sphere_vertex_array(ctx, program)
    else:
        vao, buffers = meshes.vertex_array(ctx, program, obj, instances)
    topology = "triangles" if obj.geometry is None else obj.geometry.topology
    mode = _TOPOLOGY[topology]
    patch = (getattr(program, "extra", None) or {}).get("patch_vertices")
    if patch and topology == "triangles":  # a program with tessellation stages: each triangle a patch
        ctx.patch_vertices, mode = patch, moderngl.PATCHES
    # llvmpipe compiles a program's code at its first draw
    with dies_on_signal(), within_time_limit(f"drawing {obj.where or 'an object'} (material {material.name!r})"):
        vao.render(mode, instances=1 if instances is None else len(instances))
    for resource in [vao, *buffers]:
        resource.release()


def _resolve(ctx, hdr, scene, transfer, language):
    """Exposure + tonemap, then the display encode (see render_scene's ``transfer``)."""
    shader_transfer = "HARDWARE" if transfer == "EXACT" else transfer  # EXACT: shader writes linear
    resolve = program_from_templates(ctx, "fullscreen.vert", fragment_template("resolve", language), {
        "PBR_TONEMAP": f"PBR_TONEMAP_{scene.render.tonemap.upper()}",
        "PBR_COLOR_TRANSFER": f"PBR_COLOR_TRANSFER_{shader_transfer}"})
    display_kind = {"EXACT": "f32", "HARDWARE": "srgb8"}.get(transfer, "unorm8")
    radiance = hdr.resolve()  # before the display is bound (a multisampled target's blit binds its own)
    with targets.Target(ctx, hdr.output_size, display_kind, depth=False) as display:
        display.use()
        radiance.use(0)
        _set(resolve, "u_hdr", 0)
        _set(resolve, "u_exposure_ev", scene.render.exposure)
        vao = ctx.vertex_array(resolve, [])
        with dies_on_signal():
            vao.render(moderngl.TRIANGLES, vertices=3)
            pixels = display.read()
        vao.release()
        ctx.disable_direct(targets.GL_FRAMEBUFFER_SRGB)
    if transfer != "EXACT":
        return pixels
    srgb8 = np.full(pixels.shape, 255, np.uint8)  # the display image is opaque (alpha 1)
    srgb8[..., :3] = srgb8_codes.encode(pixels[..., :3])
    return srgb8
