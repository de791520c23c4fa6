"""The depth textures a Unity program samples through a comparison sampler (URP's
``TEXTURE2D_SHADOW(t); SAMPLER_CMP(s); SAMPLE_TEXTURE2D_SHADOW(t, s, coord3)``, Direct3D 11's
``Texture2D.SampleCmp(LevelZero)`` with a ``SamplerComparisonState``): GLSL ``sampler2DShadow``
in both languages (the port spells it so; spirv-cross gives it for SampleCmp), bound here as a
depth texture whose comparison is on.

The comparison (Microsoft's HLSL reference, "SampleCmp": the reference value is compared with
each texel the filter reads and the 0/1 results are filtered): Unity's shadow maps compare with
LessEqual where the depth is not reversed, as on OpenGL (UNITY_REVERSED_Z 0), and GreaterEqual
on Direct3D-like targets, whose shadow coordinates' z and stored depths are both reversed
(1 - z), so either reads 1, lit, where the point is no farther than the stored depth. pbrlab
compiles for SHADER_API_GLCORE (not reversed), so: result = (coord.z <= stored) per texel,
GL_LEQUAL (OpenGL 3.3 core, 3.8.16, "Texture Comparison Modes"), with bilinear filtering of
the results (URP's shadow samplers are linear comparison samplers; on GL the 2x2 comparisons
are weighted as a linear filter weights texels). Unity's shadow maps store depth in a depth
format; this one is 24-bit fixed point, whose reference GL clamps to [0, 1].

- URP's own maps (``_MainLightShadowmapTexture``, ``_AdditionalLightsShadowmapTexture``) and any
  other comparison sampler no property binds: URP's empty shadow map, which URP binds while no
  light casts shadows (pbrlab renders no shadow maps): one texel at the far plane's depth, 1.0,
  which every reference in [0, 1] passes: 1, lit.
- A texture property sampled so: its red channel as the stored depth (a constant default's
  texel, or the image file's; clamped to [0, 1], a depth format's range). A property also read
  plainly (compared_textures.py) is two samplers: the plain one takes the property's texture as
  every texture property's does, its comparison view (``<name>_pbrlab_compared``) these depths.
- A shadow-map array or cube (``TEXTURE2D_ARRAY_SHADOW``, ``TEXTURECUBE_SHADOW``) is refused
  by name: pbrlab binds depth textures only as 2D textures.

    bound = bind_compared(program, name, value, cache, unit)   # False: not a comparison sampler
    used = bind_unset_compared(program, cache, unit, properties)  # the empty map on the rest
"""

from __future__ import annotations

import numpy as np

from ...foundation.errors import PbrlabError
from ...foundation.images import read_image
from ...gpu import programs
from ...gpu.programs import set_uniform as _set
from .compared_textures import compared_view
from .properties import TextureValue

# OpenGL 3.3 core, table 2.10: the comparison samplers' types
GL_SAMPLER_2D_SHADOW, GL_SAMPLER_2D_ARRAY_SHADOW, GL_SAMPLER_CUBE_SHADOW = 0x8B62, 0x8DC4, 0x8DC5
COMPARED = (GL_SAMPLER_2D_SHADOW, GL_SAMPLER_2D_ARRAY_SHADOW, GL_SAMPLER_CUBE_SHADOW)
# The far plane's depth on a depth buffer that is not reversed (GL's clear value, 1): the
# empty shadow map's one texel.
FAR_DEPTH = 1.0


def _shader(program) -> str:
    return (getattr(program, "extra", None) or {}).get("shader", "surface shader")


def _refuse_unbindable(program, name: str, gl_type: int) -> None:
    if gl_type != GL_SAMPLER_2D_SHADOW:
        form = "TEXTURE2D_ARRAY_SHADOW" if gl_type == GL_SAMPLER_2D_ARRAY_SHADOW else "TEXTURECUBE_SHADOW"
        raise PbrlabError(f"{_shader(program)}: '{name}' is sampled as a shadow-map "
                          f"{'array' if gl_type == GL_SAMPLER_2D_ARRAY_SHADOW else 'cube'} ({form}); "
                          "pbrlab binds shadow maps (comparison samplers) only as 2D depth textures")


def depth_texture(cache, depths: np.ndarray):
    """A depth texture holding ``depths`` (rows from the bottom, as GL's), comparing with
    LEQUAL, bilinear, clamped at its edges; cached by content."""
    depths = np.ascontiguousarray(np.clip(depths, 0.0, 1.0), np.float32)
    key = ("compared depth", depths.shape, depths.tobytes())

    def make():
        texture = cache.ctx.depth_texture((depths.shape[1], depths.shape[0]), depths.tobytes())
        texture.compare_func = "<="
        texture.repeat_x = texture.repeat_y = False
        return texture
    return cache._textures.get(key, make)


def empty_shadow_map(cache):
    """URP's empty shadow map: one texel at the far plane's depth."""
    return depth_texture(cache, np.full((1, 1), FAR_DEPTH))


def property_depth_texture(cache, value):
    """The depth texture of texture property ``value``: its red channel as the stored depth."""
    if value.path is not None:
        image = read_image(value.path)  # uint8 code values (PNG) or float (EXR): data, not colour
        red = np.asarray(image[..., 0] if image.ndim == 3 else image, np.float64)
        red = red / 255.0 if image.dtype == np.uint8 else red
        depths = red[::-1]  # the file's top row first; GL's first row is the bottom one
    else:
        depths = np.full((1, 1), float(value.texel[0]))
    return depth_texture(cache, depths)


def bind_compared(program, name: str, value, cache, unit: int) -> bool:
    """Bind texture property ``name`` (properties.TextureValue) at ``unit`` as a depth texture
    when the program samples it through a comparison sampler; False when it does not."""
    uniforms = programs.uniforms_named(program, name)
    if not uniforms or uniforms[0].gl_type not in COMPARED:
        return False
    _refuse_unbindable(program, name, uniforms[0].gl_type)
    texture = property_depth_texture(cache, value)
    texture.use(unit)
    _set(program, name, unit)
    if programs.uniforms_named(program, f"{name}_TexelSize"):
        w, h = texture.size
        _set(program, f"{name}_TexelSize", (1.0 / w, 1.0 / h, float(w), float(h)))
    return True


def bind_unset_compared(program, cache, unit: int, properties=None) -> int:
    """The empty shadow map on each comparison sampler still on unit 0 (nothing bound it: URP's
    own maps, a program's map with no property) from ``unit`` on, but the comparison view of a
    texture property also read plainly (compared_textures.compared_view), which takes the
    property's depths (its plain sampler the property's texture, as any); returns the units
    used."""
    for name in program:  # no binder of pbrlab's binds an array or a cube of depths
        if not name.startswith("u_") and getattr(program[name], "gl_type", None) in COMPARED:
            _refuse_unbindable(program, name, program[name].gl_type)
    found = [name for name in program if not name.startswith("u_")
             and getattr(program[name], "gl_type", None) == GL_SAMPLER_2D_SHADOW and program[name].value == 0]
    views = {compared_view(name): value for name, value in (properties or {}).items() if isinstance(value, TextureValue)}
    for i, name in enumerate(found):
        (property_depth_texture(cache, views[name]) if name in views else empty_shadow_map(cache)).use(unit + i)
        _set(program, name, unit + i)
    return len(found)
