"""What the GL context can hold, checked before a render instead of failing inside GL.

Each limit is queried from the context (``ctx.info``), never assumed; llvmpipe (Mesa
25) reports GL_MAX_TEXTURE_SIZE = GL_MAX_RENDERBUFFER_SIZE = 16384,
GL_MAX_FRAGMENT_UNIFORM_VECTORS = 4096 and GL_MAX_TEXTURE_IMAGE_UNITS = 32. A scene
past a limit raises SceneError with the number it may have: "at most 1920 directional
lights" instead of a linker error, "at most 16384 pixels wide" instead of an incomplete
framebuffer.
"""

from __future__ import annotations

import ctypes

import numpy as np

from ..foundation.errors import PbrlabError, SceneError

FLOAT32_MAX = float(np.finfo(np.float32).max)

# Uniform vectors (vec4 slots) per light in scene_lighting.inc: a vec3 or a float array
# element each takes one slot. directional: direction, radiance; point: position,
# radiance, range; spot: position, radiance, range, direction, cone.
VECTORS_PER_LIGHT = {"directional": 2, "point": 3, "spot": 5}
# per direction of render.environment_visibility: three affine maps, the direction, its flux
VECTORS_PER_SKY_DIRECTION = 5
# Vectors the scene programs use besides the lights: camera (4 vec3 + viewport), two
# mat4 and a mat3 (11), material (8), SH9 (9), samplers and flags; 256 leaves room.
RESERVED_UNIFORM_VECTORS = 256
# Texture units the harness takes before a material's own: the DFG table and the
# prefiltered environment, the sheen table, the transmission copy, the irradiance cube, the
# sun's shadow map, the environment's visibility maps, the volumes' exits, the screen-space
# reflections' first pass and its positions (render._SceneResources.FIRST_MATERIAL_UNIT).
RESERVED_TEXTURE_UNITS = 10


def _limit(ctx, name: str, fallback: int) -> int:
    value = ctx.info.get(name, fallback)
    if isinstance(value, (tuple, list)):
        value = min(value)
    return int(value)


def max_render_size(ctx) -> int:
    return min(_limit(ctx, "GL_MAX_TEXTURE_SIZE", 16384),
               _limit(ctx, "GL_MAX_RENDERBUFFER_SIZE", 16384),
               _limit(ctx, "GL_MAX_VIEWPORT_DIMS", 16384))


def check_render_size(ctx, size, what: str = "render size") -> None:
    w, h = size
    most = max_render_size(ctx)
    if not (1 <= w <= most and 1 <= h <= most):
        raise PbrlabError(f"{what} {w}x{h}: this GL allows 1..{most} pixels per side "
                          "(GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS)")


def check_texture_size(ctx, size, what: str) -> None:
    w, h = size
    most = _limit(ctx, "GL_MAX_TEXTURE_SIZE", 16384)
    if w > most or h > most:
        raise PbrlabError(f"{what}: {w}x{h} pixels; this GL's textures are at most {most} "
                          "pixels per side (GL_MAX_TEXTURE_SIZE)")


def max_lights(ctx, light_type: str) -> int:
    """How many lights of one type (and no others) the scene programs can hold."""
    budget = _limit(ctx, "GL_MAX_FRAGMENT_UNIFORM_VECTORS", 1024) - RESERVED_UNIFORM_VECTORS
    return budget // VECTORS_PER_LIGHT[light_type]


def check_float32_products(scene) -> None:
    """Light radiance (color x intensity) and environment radiance reach the GPU as float32:
    each field is within float32 (json_input), their product must be too, or it is Inf."""
    products = [(f"lights[{i}]", light.color * light.intensity) for i, light in enumerate(scene.lights)]
    env = scene.environment
    if env is not None and env.color is not None:
        products.append(("environment", env.color * env.intensity))
    for where, value in products:
        if not np.all(np.abs(value) <= FLOAT32_MAX):
            raise SceneError(f"{scene.source}: {where}: color x intensity = {np.max(value):.4g} is "
                             f"beyond the float32 range (<= {FLOAT32_MAX:.8g}) the GPU computes in")


# glGetInternalformativ's enums (OpenGL 4.2 core, section 22.3): the sample counts a
# renderbuffer of an internal format takes, largest first.
_GL_RENDERBUFFER, _GL_NUM_SAMPLE_COUNTS, _GL_SAMPLES = 0x8D41, 0x9380, 0x80A9
_GL_DEPTH_COMPONENT24 = 0x81A6  # the depth renderbuffer moderngl makes (depth_renderbuffer)
_GL_HDR_FORMATS = {"f32": 0x8814, "f16": 0x881A}  # RGBA32F, RGBA16F (targets.HDR_DTYPES)


def sample_counts(ctx, kind: str) -> tuple[int, ...]:
    """The samples per pixel a multisampled ``kind`` ("f32" or "f16") target with depth may
    have on this context, ascending, 1 (no multisampling) first: the counts
    glGetInternalformativ(GL_SAMPLES) gives for both the colour and the depth format (OpenGL
    4.2); where the context lacks it (OpenGL 3.3), the powers of two up to GL_MAX_SAMPLES,
    which RenderbufferStorageMultisample must accept (OpenGL 3.3 core, section 4.4.2)."""
    most = _limit(ctx, "GL_MAX_SAMPLES", 1)
    powers = {2 ** k for k in range(1, most.bit_length()) if 2 ** k <= most}
    try:
        from . import gl
        query = gl.gl_function(ctx, "glGetInternalformativ")
    except PbrlabError:
        return (1, *sorted(powers))
    taken = None
    for internal_format in (_GL_HDR_FORMATS[kind], _GL_DEPTH_COMPONENT24):
        count = ctypes.c_int(0)
        query(_GL_RENDERBUFFER, internal_format, _GL_NUM_SAMPLE_COUNTS, 1, ctypes.byref(count))
        values = (ctypes.c_int * max(count.value, 1))()
        if count.value:
            query(_GL_RENDERBUFFER, internal_format, _GL_SAMPLES, count.value, values)
        found = {int(v) for v in values[:count.value] if v > 1}
        taken = found if taken is None else taken & found
    return (1, *sorted(taken))


def check_antialias(ctx, scene, kind: str) -> None:
    """Refuse a ``render.antialias`` this context's ``kind`` target cannot hold, naming what it can."""
    samples = scene.render.antialias
    counts = sample_counts(ctx, kind)
    if samples not in counts:
        taken = " or ".join([", ".join(map(str, counts[:-1])), str(counts[-1])] if len(counts) > 1 else ["1"])
        raise SceneError(f"{scene.source}: render.antialias: {samples} samples per pixel; this GL's "
                         f"{scene.render.hdr_target} target with depth takes {taken} "
                         f"(GL_MAX_SAMPLES = {_limit(ctx, 'GL_MAX_SAMPLES', 1)}, "
                         f"{ctx.info.get('GL_RENDERER', 'this renderer')})")


def check_scene(ctx, scene) -> None:
    """Refuse a scene this context cannot render, naming the limit."""
    check_render_size(ctx, scene.camera.size, f"{scene.source}: camera.size")
    check_float32_products(scene)
    budget = _limit(ctx, "GL_MAX_FRAGMENT_UNIFORM_VECTORS", 1024) - RESERVED_UNIFORM_VECTORS
    counts = {t: sum(1 for light in scene.lights if light.type == t) for t in VECTORS_PER_LIGHT}
    used = sum(VECTORS_PER_LIGHT[t] * n for t, n in counts.items())
    budget -= VECTORS_PER_SKY_DIRECTION * scene.render.environment_visibility
    if used > budget:
        most = ", ".join(f"at most {budget // VECTORS_PER_LIGHT[t]} {t}" for t in VECTORS_PER_LIGHT)
        have = ", ".join(f"{n} {t}" for t, n in counts.items() if n)
        raise SceneError(f"{scene.source}: lights: too many lights for this GL ({have}); a scene "
                         f"holds {most} lights (fewer when types are mixed: "
                         f"GL_MAX_FRAGMENT_UNIFORM_VECTORS = {budget + RESERVED_UNIFORM_VECTORS}, "
                         f"{', '.join(f'{t} {v}' for t, v in VECTORS_PER_LIGHT.items())} vectors each)")
    units = _limit(ctx, "GL_MAX_TEXTURE_IMAGE_UNITS", 16) - RESERVED_TEXTURE_UNITS
    for name, material in scene.materials.items():
        if len(material.textures) > units:
            raise SceneError(f"{scene.source}: materials.{name}.textures: {len(material.textures)} "
                             f"textures; a material binds at most {units} on this GL "
                             f"(GL_MAX_TEXTURE_IMAGE_UNITS less the {RESERVED_TEXTURE_UNITS} the renderer's lighting takes)")
