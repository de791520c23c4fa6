"""The camera's depth texture and G-buffer, rendered before the frame for the programs that
read them (Unity's ``_CameraDepthTexture``, ``_CameraGBufferTexture0..2``,
``_CameraNormalsTexture``: scene/gbuffer_surface.py names them).

One pass over the scene's objects that are in them (a material source's
``gbuffer_surface``: opaque and cutout pbrlab materials with their constant values; a Unity
shader of an opaque queue with Unity's default material; blended materials are not, as Unity
keeps its transparent queues out of the depth texture), drawn with a depth test into:

* the depth texture: the window depth of the nearest surface, GL's convention in [0, 1]
  (near 0, far 1, not reversed: the _ZBufferParams pbrlab sets are those of a GL depth buffer,
  so Linear01Depth and LinearEyeDepth of it give eye depth / far and eye depth), float32
  (R32F; Unity's GL depth texture is 24-bit or float), cleared to 1 (the far plane);
* RT0 diffuse colour rgb, occlusion a (GL_SRGB8_ALPHA8: Unity's ARGB32 G-buffer targets are
  sRGB in linear colour space, so rgb is stored sRGB-encoded, a linear; sampling decodes);
* RT1 specular colour rgb, smoothness a (GL_SRGB8_ALPHA8, likewise);
* RT2 world normal * 0.5 + 0.5 rgb, a 1 (GL_RGB10_A2, Unity's ARGB2101010), as Unity's
  fragDeferred (UnityStandardCore.cginc) and UnityStandardDataToGbuffer (UnityGBuffer.cginc)
  write them. RT3 (emission and ambient) is not made: a program reading it is refused
  (importers/unity/unprovided.py);
* URP's normals texture (its DepthNormals pre-pass, URP 10 and later): the unit world-space
  normal itself in rgb (signed, not remapped), a 0, cleared to 0, as URP's DepthNormals passes
  write it without _GBUFFER_NORMALS_OCT (the octahedral packing is its deferred renderer's
  "accurate G-buffer normals" option alone). URP renders it R8G8B8A8_SNorm where that format
  is renderable and R16G16B16A16_SFloat where not; GL 3.3 does not require SNorm targets to be
  renderable, so here it is half float (GL_RGBA16F, Unity's fallback).

A program reads the normals the way its pipeline stores them: a material source's
``camera_normals`` (``GBUFFER_NORMALS``, the built-in pipeline's RT2, by default;
``WORLD_NORMALS``, URP's) picks the texture bound under ``_CameraNormalsTexture``.

Meshes are rasterised at their mesh positions (a Unity program that moves its vertices is seen
here where its mesh is); ray-traced spheres are traced per pixel (their exact depth and
normal). Sampled nearest: Unity's passes read them at pixel centres.

    textures = CameraTextures(ctx, scene, frame)
    textures.bound(source)                          # {uniform name: texture} for a material source
"""

from __future__ import annotations

import moderngl
import numpy as np

from . import instanced_draws
from ..foundation.errors import SceneError
from ..gpu import targets
from ..gpu.programs import set_uniform as _set
from ..scene import meshes
from ..scene.gbuffer_surface import (DEPTH_TEXTURE, GBUFFER_NORMALS, GBUFFER_TEXTURES, NORMALS_TEXTURE,
                                     WORLD_NORMALS, GBufferSurface, metallic_surface, specular_surface)
from ..scene.standard_material import BLENDED_ALPHA_MODES, source_of

GL_SRGB8_ALPHA8 = 0x8C43   # OpenGL 3.3 core, table 3.12
GL_RGB10_A2 = 0x8059

_VERTEX_MESH = """#version 330 core
in vec3 in_position;
in vec3 in_normal;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_proj;
out vec3 v_normal;
void main() {
    v_normal = u_normal_matrix * in_normal;
    gl_Position = u_view_proj * (u_model * vec4(in_position, 1.0));
}
"""
_VERTEX_FULLSCREEN = """#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
"""
_FRAGMENT = """#version 330 core
uniform vec3 u_diffuse;
uniform float u_occlusion;
uniform vec3 u_specular;
uniform float u_smoothness;
layout(location = 0) out vec4 out_gbuffer0;
layout(location = 1) out vec4 out_gbuffer1;
layout(location = 2) out vec4 out_gbuffer2;
layout(location = 3) out float out_depth;
layout(location = 4) out vec4 out_world_normal;
#ifdef PBRLAB_TRACED_SPHERE
uniform vec4 u_sphere;          // centre, radius
uniform mat4 u_view_proj;
uniform mat4 u_inv_view_proj;
uniform vec2 u_size;
#else
in vec3 v_normal;
#endif
void main() {
#ifdef PBRLAB_TRACED_SPHERE
    // the pixel's ray from the near plane to the far plane (perspective or orthographic)
    vec2 ndc = gl_FragCoord.xy / u_size * 2.0 - 1.0;
    vec4 a = u_inv_view_proj * vec4(ndc, -1.0, 1.0);
    vec4 b = u_inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 origin = a.xyz / a.w;
    vec3 d = normalize(b.xyz / b.w - origin);
    vec3 oc = origin - u_sphere.xyz;
    float half_b = dot(oc, d);
    float c = dot(oc, oc) - u_sphere.w * u_sphere.w;
    float disc = half_b * half_b - c;
    if (disc < 0.0) discard;
    float t = -half_b - sqrt(disc);
    if (t < 0.0) discard;
    vec3 p = origin + t * d;
    vec3 n = (p - u_sphere.xyz) / u_sphere.w;
    vec4 clip = u_view_proj * vec4(p, 1.0);
    gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
    out_depth = gl_FragDepth;
#else
    vec3 n = normalize(v_normal);
    out_depth = gl_FragCoord.z;
#endif
    out_gbuffer0 = vec4(u_diffuse, u_occlusion);
    out_gbuffer1 = vec4(u_specular, u_smoothness);
    out_gbuffer2 = vec4(n * 0.5 + 0.5, 1.0);
    out_world_normal = vec4(n, 0.0);
}
"""


def needed(scene) -> bool:
    """Whether a material of the scene's objects reads one of the camera's textures."""
    for name in {obj.material for obj in scene.objects}:
        material = scene.materials[name]
        reads = getattr(source_of(material), "camera_textures", None)
        if reads is not None and reads(material):
            return True
    return False


def surface_of(material, where: str) -> GBufferSurface | None:
    """The object's surface in the G-buffer (module doc), or None when it is not in it."""
    own = getattr(source_of(material), "gbuffer_surface", None)
    if own is not None:
        return own(material)
    if material.alpha_mode in BLENDED_ALPHA_MODES:
        return None
    if material.textures or material.surface is not None:
        raise SceneError(f"{where}: material {material.name!r} is drawn into the camera's G-buffer (a shader "
                         "of the scene reads it), which takes a material's constant values; it has "
                         f"{'textures' if material.textures else 'a surface file'}: give it constant values")
    if material.workflow == "specular":
        return specular_surface(material.albedo, material.specular, material.smoothness, material.occlusion)
    return metallic_surface(material.albedo, material.metallic, material.smoothness, material.occlusion)


class CameraTextures:
    """The depth texture and G-buffer of ``scene`` seen from ``frame`` (module doc)."""

    def __init__(self, ctx, scene, frame):
        self.ctx = ctx
        size = tuple(int(s) for s in frame.size)
        self.gbuffer = [ctx.texture(size, 4, dtype="f1", internal_format=GL_SRGB8_ALPHA8),
                        ctx.texture(size, 4, dtype="f1", internal_format=GL_SRGB8_ALPHA8),
                        ctx.texture(size, 4, dtype="f1", internal_format=GL_RGB10_A2)]
        self.depth = ctx.texture(size, 1, dtype="f4")
        self.world_normals = ctx.texture(size, 4, dtype="f2")  # GL_RGBA16F
        for texture in (*self.gbuffer, self.depth, self.world_normals):
            texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
            texture.repeat_x = texture.repeat_y = False
        self._depth_buffer = ctx.depth_renderbuffer(size)
        fbo = ctx.framebuffer([*self.gbuffer, self.depth, self.world_normals], self._depth_buffer)
        self.by_name = {DEPTH_TEXTURE: self.depth, NORMALS_TEXTURE: self.gbuffer[2],
                        **dict(zip(GBUFFER_TEXTURES, self.gbuffer))}
        self._normals = {GBUFFER_NORMALS: self.gbuffer[2], WORLD_NORMALS: self.world_normals}
        try:
            self._draw(ctx, scene, frame, fbo, size)
        finally:
            fbo.release()

    def bound(self, source) -> dict:
        """{uniform name: texture} for a program of material source ``source``: its
        _CameraNormalsTexture as its pipeline stores it (module doc)."""
        normals = self._normals[getattr(source, "camera_normals", GBUFFER_NORMALS)]
        return {**self.by_name, NORMALS_TEXTURE: normals}

    def _draw(self, ctx, scene, frame, fbo, size) -> None:
        fbo.use()
        ctx.viewport = (0, 0) + size
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)  # every attachment; the depth texture's far plane next
        ctx.enable_direct(targets.GL_FRAMEBUFFER_SRGB)  # RT0 and RT1 are stored sRGB-encoded
        mesh_program = ctx.program(vertex_shader=_VERTEX_MESH, fragment_shader=_FRAGMENT)
        sphere_program = ctx.program(vertex_shader=_VERTEX_FULLSCREEN,
                                     fragment_shader=_FRAGMENT.replace("#version 330 core",
                                                                       "#version 330 core\n#define PBRLAB_TRACED_SPHERE 1"))
        depth_clear = ctx.program(vertex_shader=_VERTEX_FULLSCREEN, fragment_shader="""#version 330 core
layout(location = 0) out vec4 out_gbuffer0;
layout(location = 1) out vec4 out_gbuffer1;
layout(location = 2) out vec4 out_gbuffer2;
layout(location = 3) out float out_depth;
layout(location = 4) out vec4 out_world_normal;
void main() {
    out_gbuffer0 = vec4(0.0);
    out_gbuffer1 = vec4(0.0);
    out_gbuffer2 = vec4(0.0);
    out_depth = 1.0;
    out_world_normal = vec4(0.0);
}
""")
        empty = ctx.vertex_array(depth_clear, [])
        try:
            ctx.disable(moderngl.DEPTH_TEST | moderngl.BLEND | moderngl.CULL_FACE)
            fbo.depth_mask = False
            empty.render(moderngl.TRIANGLES, vertices=3)  # the depth texture: the far plane
            fbo.depth_mask = True
            ctx.enable(moderngl.DEPTH_TEST)
            ctx.depth_func = "<"
            ctx.enable(moderngl.CULL_FACE)
            ctx.cull_face = "back"
            view_proj = tuple(np.asarray(frame.view_proj, np.float64).T.reshape(-1))
            for index, obj in enumerate(scene.objects):
                surface = surface_of(scene.materials[obj.material], obj.where or f"objects[{index}]")
                if surface is None:
                    continue
                program = sphere_program if obj.sphere is not None else mesh_program
                _set(program, "u_diffuse", surface.diffuse)
                _set(program, "u_occlusion", surface.occlusion)
                _set(program, "u_specular", surface.specular)
                _set(program, "u_smoothness", surface.smoothness)
                _set(program, "u_view_proj", view_proj)
                if obj.sphere is not None:
                    centre, radius = obj.sphere
                    _set(program, "u_sphere", (*np.asarray(centre, np.float64), float(radius)))
                    _set(program, "u_inv_view_proj",
                         tuple(np.linalg.inv(np.asarray(frame.view_proj, np.float64)).T.reshape(-1)))
                    _set(program, "u_size", tuple(float(s) for s in size))
                    vao = ctx.vertex_array(program, [])
                    vao.render(moderngl.TRIANGLES, vertices=3)
                    vao.release()
                    continue
                _set(program, "u_model", tuple(instanced_draws.model_matrix(obj.transform)))
                _set(program, "u_normal_matrix", tuple(instanced_draws.normal_matrix(obj.transform)))
                vao, buffers = meshes.vertex_array(ctx, program, obj)
                vao.render(moderngl.TRIANGLES)
                for resource in [vao, *buffers]:
                    resource.release()
        finally:
            ctx.disable_direct(targets.GL_FRAMEBUFFER_SRGB)
            ctx.disable(moderngl.CULL_FACE)
            for resource in (empty, depth_clear, mesh_program, sphere_program):
                resource.release()

    def release(self) -> None:
        for resource in (*self.gbuffer, self.depth, self.world_normals, self._depth_buffer):
            resource.release()
