"""GPU rendering of a scene: spheres ray-traced per pixel, meshes rasterised, one HDR
float pass, then exposure + tonemap into an sRGB framebuffer (hardware encode).

``render_scene(scene)`` returns a ``Rendering`` with ``linear`` (HxWx4 float32 scene
radiance, before exposure: what the EXR holds) and ``srgb8`` (HxWx4 uint8 display image).
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import moderngl
import numpy as np

from . import gl, meshes, shaders, targets
from .camera import camera_frame
from .environment import environment_sh
from .images import read_image
from .reference.shading import glsl_defines
from .scene import TEXTURE_SLOTS, Scene

TEMPLATES = Path(str(resources.files("pbrlab").joinpath("templates")))
_LIGHT_TYPE = {"directional": 0, "point": 1, "spot": 2}
_UNIT_CUBE = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], np.float32)
# Triangles of the unit cube, counter-clockwise seen from outside.
_CUBE_TRIANGLES = np.array([
    0, 2, 1, 1, 2, 3,  4, 5, 6, 5, 7, 6,  0, 1, 4, 1, 5, 4,
    2, 6, 3, 3, 6, 7,  0, 4, 2, 2, 4, 6,  1, 3, 5, 3, 7, 5], np.int32)


@dataclass
class Rendering:
    linear: np.ndarray  # HxWx4 float32 radiance; alpha = material alpha where covered, 0 elsewhere
    srgb8: np.ndarray   # HxWx4 uint8, exposure + tonemap + hardware sRGB encode
    info: dict


def _defines_block(defines: dict) -> str:
    return "\n".join(f"#define {k} {v}".rstrip() for k, v in sorted(defines.items()))


_PROGRAMS: dict = {}


def _program(ctx, vert: str, frag: str, defines: dict):
    """Compile (once per context, shader pair and defines) a harness program."""
    key = (id(ctx), vert, frag, tuple(sorted(defines.items())))
    if key not in _PROGRAMS:
        _PROGRAMS[key] = _compile(ctx, vert, frag, defines)
    return _PROGRAMS[key]


def _compile(ctx, vert: str, frag: str, defines: dict):
    def load(name):
        text = (TEMPLATES / name).read_text(encoding="utf-8")
        return shaders.expand(text.replace("//@DEFINES", _defines_block(defines)),
                              f"pbrlab/templates/{name}", include_dirs=[TEMPLATES])
    return shaders.build_program(ctx, load(vert), load(frag))


def _set(program, name, value):
    """Set a uniform if the compiler kept it (unused uniforms are optimised away)."""
    uniform = program.get(name, None)
    if uniform is not None:
        uniform.value = value


def _set_array(program, name, values):
    uniform = program.get(name, None)
    if uniform is not None:
        uniform.write(np.ascontiguousarray(values, dtype=np.float32).tobytes())


def scene_radius(scene: Scene) -> float:
    """A radius around the camera target that holds every object (for the depth range)."""
    radius = 1.0
    for obj in scene.objects:
        if obj.sphere is not None:
            centre, r = obj.sphere
        else:
            centre, r = obj.transform[:3, 3], meshes.bounding_radius(obj)
        radius = max(radius, float(np.linalg.norm(centre - scene.camera.target)) + r)
    return radius


def _scene_defines(scene: Scene) -> dict:
    defines = {"PBRLAB_LIGHT_COUNT": len(scene.lights)}
    if scene.environment is not None:
        defines["PBRLAB_ENV_SH"] = 1
    return defines


def _material_defines(material) -> dict:
    """The library's variant selectors for this material's BRDF terms."""
    return glsl_defines(**material.brdf)


def _upload_scene_uniforms(program, scene: Scene, frame, env_sh):
    _set(program, "u_camera_position", tuple(frame.position))
    _set(program, "u_camera_forward", tuple(frame.forward))
    _set(program, "u_camera_right", tuple(frame.right))
    _set(program, "u_camera_up", tuple(frame.up))
    _set(program, "u_viewport_size", tuple(float(s) for s in frame.size))
    _set(program, "u_view_proj", tuple(frame.view_proj.T.reshape(-1)))  # GL is column-major
    if scene.lights:
        pos_type, direction, radiance, range_cones = [], [], [], []
        for light in scene.lights:
            xyz = light.direction if light.type == "directional" else light.position
            pos_type.append([*xyz, _LIGHT_TYPE[light.type]])
            direction.append(light.direction if light.direction is not None else [0, 0, -1])
            radiance.append(light.color * light.intensity)
            cos_outer = np.cos(np.radians(light.outer_cone_deg))
            cos_inner = np.cos(np.radians(light.inner_cone_deg))
            range_cones.append([min(light.range, 3.0e38), cos_outer,
                                1.0 / max(cos_inner - cos_outer, 1e-4)])
        _set_array(program, "u_light_position_type", pos_type)
        _set_array(program, "u_light_direction", direction)
        _set_array(program, "u_light_radiance", radiance)
        _set_array(program, "u_light_range_cones", range_cones)
    if env_sh is not None:
        _set_array(program, "u_env_sh", env_sh)


def _upload_material(program, material):
    _set(program, "u_workflow", 0 if material.workflow == "metallic" else 1)
    _set(program, "u_albedo", tuple(material.albedo))
    _set(program, "u_specular", tuple(material.specular))
    _set(program, "u_metallic", material.metallic)
    _set(program, "u_smoothness", material.smoothness)
    _set(program, "u_emission", tuple(material.emission))
    _set(program, "u_occlusion", material.occlusion)
    _set(program, "u_alpha", material.alpha)


COLOR_TRANSFERS = ("HARDWARE", "SRGB", "GAMMA22", "FAST")  # PBR_COLOR_TRANSFER_*


def render_scene(scene: Scene, ctx: moderngl.Context | None = None, size=None,
                 hdr_format: str = "f32", transfer: str = "HARDWARE") -> Rendering:
    """Render ``scene`` (optionally at another ``size``) on ``ctx`` (default: shared).

    ``transfer`` picks the lecture's linear-space path for the display image: HARDWARE
    (sRGB framebuffer encodes) or a DIY shader encode into a plain 8-bit target: SRGB
    (exact curve), GAMMA22 (pow 1/2.2) or FAST (sqrt).
    """
    if transfer not in COLOR_TRANSFERS:
        raise ValueError(f"transfer={transfer!r}: expected one of {COLOR_TRANSFERS}")
    ctx = gl.make_current(ctx or gl.shared_context())
    if size is not None:
        scene.camera.size = tuple(size)
    frame = camera_frame(scene.camera, scene_radius(scene))
    env_sh = environment_sh(scene.environment) if scene.environment is not None else None
    base_defines = _scene_defines(scene)
    w, h = frame.size

    with targets.Target(ctx, (w, h), hdr_format) as hdr:
        hdr.use()
        ctx.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)  # alpha = coverage: background is 0
        ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        ctx.front_face = "ccw"

        # Meshes: rasterised with the material's texture slots compiled in.
        for obj in scene.meshes:
            material = scene.materials[obj.material]
            defines = dict(base_defines, **_material_defines(material))
            for slot in material.textures:
                defines[f"PBRLAB_{slot.upper()}_MAP"] = 1
            program = _program(ctx, "mesh.vert", "mesh.frag", defines)
            _upload_scene_uniforms(program, scene, frame, env_sh)
            _upload_material(program, material)
            _set(program, "u_model", tuple(obj.transform.T.reshape(-1)))
            normal_matrix = np.linalg.inv(obj.transform[:3, :3]).T
            _set(program, "u_normal_matrix", tuple(normal_matrix.T.reshape(-1)))
            textures = []
            for unit, (slot, path) in enumerate(sorted(material.textures.items())):
                tex = targets.upload_texture(ctx, read_image(path), srgb=TEXTURE_SLOTS[slot] == "srgb")
                tex.use(unit)
                _set(program, f"u_{slot}_map", unit)
                textures.append(tex)
            vao, buffers = meshes.vertex_array(ctx, program, obj)
            vao.render(moderngl.TRIANGLES)
            for resource in [vao, *buffers, *textures]:
                resource.release()

        # Spheres: back faces of each bounding cube, ray-traced in the fragment shader;
        # one program per set of material BRDF variants (compiled once, cached).
        if scene.spheres:
            vbo = ctx.buffer(_UNIT_CUBE.tobytes())
            ibo = ctx.buffer(_CUBE_TRIANGLES.tobytes())
            ctx.cull_face = "front"
            for obj in scene.spheres:
                material = scene.materials[obj.material]
                program = _program(ctx, "sphere.vert", "sphere.frag",
                                   dict(base_defines, **_material_defines(material)))
                _upload_scene_uniforms(program, scene, frame, env_sh)
                _upload_material(program, material)
                centre, radius = obj.sphere
                _set(program, "u_sphere", (*centre, radius))
                inside = bool(np.all(np.abs(frame.position - centre) <= radius * 1.001))
                _set(program, "u_fullscreen", inside)
                ctx.disable(moderngl.CULL_FACE) if inside else ctx.enable(moderngl.CULL_FACE)
                vao = ctx.vertex_array(program, [(vbo, "3f", "in_position")], index_buffer=ibo)
                vao.render(moderngl.TRIANGLES, vertices=3 if inside else 36)
                vao.release()
            ctx.cull_face = "back"
            vbo.release()
            ibo.release()
        ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        linear = hdr.read()

        # Resolve: exposure + tonemap, hardware sRGB encode.
        resolve = _program(ctx, "fullscreen.vert", "resolve.frag", {
            "PBR_TONEMAP": f"PBR_TONEMAP_{scene.render.tonemap.upper()}",
            "PBR_COLOR_TRANSFER": f"PBR_COLOR_TRANSFER_{transfer}"})
        display_kind = "srgb8" if transfer == "HARDWARE" else "unorm8"
        with targets.Target(ctx, (w, h), display_kind, depth=False) as display:
            display.use()
            hdr.color.use(0)
            _set(resolve, "u_hdr", 0)
            _set(resolve, "u_exposure_ev", scene.render.exposure)
            vao = ctx.vertex_array(resolve, [])
            vao.render(moderngl.TRIANGLES, vertices=3)
            vao.release()
            srgb8 = display.read()
            ctx.disable_direct(targets.GL_FRAMEBUFFER_SRGB)
    return Rendering(linear=linear, srgb8=srgb8, info=gl.context_info(ctx))
