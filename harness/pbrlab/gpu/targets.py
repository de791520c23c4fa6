"""Render targets and readback: the lecture's "let the GPU handle it" path.

* Display output: a GL_SRGB8_ALPHA8 colour attachment with GL_FRAMEBUFFER_SRGB enabled,
  so shaders write linear values and the hardware encodes them (lecture: "Pixel write:
  GL_EXT_framebuffer_sRGB").
* Colour textures are uploaded as sRGB (hardware decode on sampling); data textures
  (normals, roughness, masks) as linear: the lecture's "when to bypass sRGB sampling".
* HDR: linear RGBA16F or RGBA32F targets, read back as float32.
* Multisampled HDR (``samples`` > 1, the scene's ``render.antialias``): drawing goes to
  multisampled float colour and depth renderbuffers; ``resolve()`` blits them into the
  single-sampled float texture (glBlitFramebuffer from a multisampled to a single-sampled
  framebuffer averages each pixel's samples: OpenGL 4.5 core, section 18.3.1). The average
  is of linear radiance, before exposure, tone mapping and the display encode. With
  ``resolve_filter="blackman_harris"`` the colour is a multisample texture and ``resolve()``
  draws templates/resolve_samples.frag instead: each pixel the Blackman-Harris-weighted sum
  of the samples within 1.5 px of its centre (Cycles' pixel filter), still in linear.

Every readback returns a top-row-first array (image order), flipping GL's bottom-up rows.
"""

from __future__ import annotations

import ctypes

import moderngl
import numpy as np

from . import gl, stencil_state
from ..maths import mipmaps
from ..foundation.errors import PbrlabError

GL_SRGB8_ALPHA8 = 0x8C43  # OpenGL 3.3 core, table 8.13 (sized internal formats)
GL_FRAMEBUFFER_SRGB = 0x8DB9  # OpenGL 3.3 core, section 4.1.8 (sRGB conversion)
HDR_DTYPES = {"f16": "f2", "f32": "f4"}
_BYTES_PER_PIXEL = {"srgb8": 4, "unorm8": 4, "f16": 8, "f32": 16}
GL_SAMPLE_POSITION = 0x8E50  # OpenGL 3.3 core, section 3.3.1 (GetMultisamplefv)
RESOLVE_FILTERS = ("box", "blackman_harris")
BLACKMAN_HARRIS_RADIUS = 1.5  # px either side of the centre: Cycles' default filter width, doubled (film.cpp)


class Target:
    """A framebuffer with one colour attachment (and optionally depth, with an 8-bit stencil:
    ``stencil_state.DepthStencilBuffer``) of a given size;
    with ``samples`` > 1 (float kinds only) a multisampled one, resolved into ``color`` by
    ``resolve()``."""

    def __init__(self, ctx: moderngl.Context, size, kind: str, depth: bool = True, samples: int = 1,
                 resolve_filter: str = "box", downsample: int = 1):
        self.ctx, self.size, self.kind, self.samples = ctx, tuple(int(s) for s in size), kind, int(samples)
        if resolve_filter not in RESOLVE_FILTERS:
            raise PbrlabError(f"resolve_filter={resolve_filter!r}: expected one of {', '.join(RESOLVE_FILTERS)}")
        if resolve_filter != "box" and not (1 < self.samples or downsample > 1) or self.samples > 16:
            raise PbrlabError(f"the {resolve_filter} resolve filters a pixel's samples: it needs 2 to 16 samples "
                              f"per pixel or supersampling, got {self.samples} sample(s)")
        if downsample < 1 or any(s % downsample for s in self.size):
            raise PbrlabError(f"a {self.size[0]}x{self.size[1]} target does not downsample by {downsample}")
        self.resolve_filter, self.downsample = resolve_filter, int(downsample)
        # what resolve() writes and read() returns: the drawn size over the downsampling
        self.output_size = (self.size[0] // self.downsample, self.size[1] // self.downsample)
        shader_resolve = resolve_filter != "box" or self.downsample > 1
        w, h = self.size
        if w <= 0 or h <= 0 or w > 16384 or h > 16384:
            raise PbrlabError(f"render size {w}x{h} is out of range (1..16384 per side)")
        if self.samples != 1 and kind not in HDR_DTYPES:
            raise PbrlabError(f"a {kind} target is single-sampled; multisampling is for f16 and f32")
        if shader_resolve and kind not in HDR_DTYPES:
            raise PbrlabError(f"a {kind} target is resolved as drawn; filtering and downsampling are for f16 and f32")
        if kind == "srgb8":
            self.color = ctx.texture(self.size, 4, dtype="f1", internal_format=GL_SRGB8_ALPHA8)
        elif kind == "unorm8":
            self.color = ctx.texture(self.size, 4, dtype="f1")
        elif kind in HDR_DTYPES:
            self.color = ctx.texture(self.output_size, 4, dtype=HDR_DTYPES[kind])
        else:
            raise PbrlabError(f"unknown target kind {kind!r}; use srgb8, unorm8, f16 or f32")
        self.depth = None
        self._multisampled = None  # the multisampled colour renderbuffer, when samples > 1
        self._resolved = None      # the framebuffer of ``color`` that resolve() blits into
        self._sample_offsets = None
        try:
            if shader_resolve:  # read sample by sample: a (multisample) texture
                many = self.samples if self.samples > 1 else 0  # moderngl: 0 is a single-sampled texture
                self._multisampled = ctx.texture(self.size, 4, samples=many, dtype=HDR_DTYPES[kind])
                if not many:  # texelFetch reads level 0: complete without mipmaps (no mipmap filter)
                    self._multisampled.filter = (moderngl.NEAREST, moderngl.NEAREST)
                self.fbo = ctx.framebuffer([self._multisampled])
                self._resolved = ctx.framebuffer([self.color])
            elif self.samples > 1:
                self._multisampled = ctx.renderbuffer(self.size, 4, samples=self.samples, dtype=HDR_DTYPES[kind])
                self.fbo = ctx.framebuffer([self._multisampled])
                self._resolved = ctx.framebuffer([self.color])
            else:
                self.fbo = ctx.framebuffer([self.color])
            if depth:  # depth and an 8-bit stencil (stencil_state.py); moderngl's fbo writes depth
                self.fbo.depth_mask = True  # as it does for a depth attachment of its own
                self.depth = stencil_state.DepthStencilBuffer(ctx, self.fbo, self.size, self.samples)
        except (moderngl.Error, PbrlabError) as exc:  # e.g. "framebuffer is incomplete": out of memory
            for resource in (self.depth, getattr(self, "fbo", None), self._resolved, self._multisampled, self.color):
                if resource is not None:
                    resource.release()
            mib = w * h * (_BYTES_PER_PIXEL[kind] + (4 if depth else 0)) * self.samples / 2**20
            raise PbrlabError(f"cannot make a {w}x{h} {kind} render target with {self.samples} sample(s) "
                              f"per pixel ({mib:.0f} MiB): {str(exc).strip() or 'GL error'}; "
                              "render smaller (--size) or with fewer samples") from None

    def use(self):
        """Bind for drawing; sRGB encoding is on exactly while an sRGB target is bound."""
        self.fbo.use()
        self.ctx.viewport = (0, 0) + self.size
        if self.kind == "srgb8":
            self.ctx.enable_direct(GL_FRAMEBUFFER_SRGB)
        else:
            self.ctx.disable_direct(GL_FRAMEBUFFER_SRGB)

    def sample_offsets(self) -> list[tuple[float, float]]:
        """Where this target's samples lie in a pixel, as offsets from its centre in pixels
        (glGetMultisamplefv(GL_SAMPLE_POSITION): positions in [0, 1], OpenGL 3.3 core,
        section 3.3.1); [(0, 0)] for a single-sampled target. Binds the target."""
        if self.samples == 1:
            return [(0.0, 0.0)]
        if self._sample_offsets is None:
            self.fbo.use()
            get_multisample = gl.gl_function(self.ctx, "glGetMultisamplefv")
            offsets = []
            for index in range(self.samples):
                position = (ctypes.c_float * 2)()
                get_multisample(GL_SAMPLE_POSITION, index, position)
                offsets.append((position[0] - 0.5, position[1] - 0.5))
            self._sample_offsets = offsets
        return self._sample_offsets

    def resolve(self) -> moderngl.Texture:
        """``color`` holding what was drawn: for a multisampled target, each pixel's samples
        averaged into it by a framebuffer blit. The blit binds framebuffers of its own: bind
        (``use``) the target to draw into after it."""
        if self._resolved is not None and self.resolve_filter == "box" and self.downsample == 1:
            self.ctx.copy_framebuffer(self._resolved, self.fbo)
        elif self._resolved is not None:
            self._filtered_resolve()
        return self.color

    def _filtered_resolve(self) -> None:
        """templates/resolve_samples.frag into ``color``: every pixel from the samples around it."""
        from .programs import program_from_templates  # loaded on use (programs imports targets' users)

        program = program_from_templates(self.ctx, "fullscreen.vert", "resolve_samples.frag",
                                         {} if self.samples > 1 else {"PBRLAB_SINGLE_SAMPLE": 1})
        offsets = self.sample_offsets()
        program["u_sample_count"].value = len(offsets)
        program["u_offsets"].write(np.array(offsets + [(0.0, 0.0)] * (16 - len(offsets)), np.float32).tobytes())
        program["u_scale"].value = self.downsample
        program["u_filter"].value = RESOLVE_FILTERS.index(self.resolve_filter)
        program["u_samples"].value = 0
        self._multisampled.use(location=0)
        self.ctx.disable(moderngl.BLEND | moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        self._resolved.use()
        self.ctx.viewport = (0, 0) + self.output_size
        vao = self.ctx.vertex_array(program, [])
        try:
            vao.render(moderngl.TRIANGLES, vertices=3)
        finally:
            vao.release()

    def read(self) -> np.ndarray:
        """Top-row-first HxWx4: uint8 codes for srgb8/unorm8, float32 linear otherwise
        (a multisampled target is resolved first)."""
        w, h = self.output_size
        if self.kind in ("srgb8", "unorm8"):
            data = self.fbo.read(components=4, dtype="f1")
            img = np.frombuffer(data, np.uint8).reshape(h, w, 4)
        else:
            self.resolve()
            source = self._resolved if self._resolved is not None else self.fbo
            data = source.read(components=4, dtype="f4")
            img = np.frombuffer(data, np.float32).reshape(h, w, 4)
        return img[::-1].copy()

    def release(self):
        self.fbo.release()
        self.color.release()
        for resource in (self._resolved, self._multisampled, self.depth):
            if resource is not None:
                resource.release()

    def __enter__(self):
        return self

    def __exit__(self, *exc_info):
        self.release()


# Pixel transfer enums of the OpenGL 3.3 core specification (tables 8.2, 8.3, 8.12).
_GL_TEXTURE_2D = 0x0DE1
_GL_UNPACK_ALIGNMENT = 0x0CF5
_GL_FORMATS = {1: 0x1903, 2: 0x8227, 3: 0x1907, 4: 0x1908}  # RED, RG, RGB, RGBA
_GL_UNSIGNED_BYTE, _GL_FLOAT = 0x1401, 0x1406
_GL_INTERNAL_FORMATS = {
    "f1": {1: 0x8229, 2: 0x822B, 3: 0x8051, 4: 0x8058},  # R8, RG8, RGB8, RGBA8
    "f4": {1: 0x822E, 2: 0x8230, 3: 0x8815, 4: 0x8814},  # R32F, RG32F, RGB32F, RGBA32F
}


def upload_texture(ctx: moderngl.Context, image: np.ndarray, *, srgb: bool) -> moderngl.Texture:
    """Upload a top-row-first image with its full mip chain: uint8 colour as sRGB
    (srgb=True) or linear data.

    ``srgb=True`` is for colour (albedo, emission): sampling decodes to linear in
    hardware. ``srgb=False`` is for data (normal maps, metallic/smoothness, masks) and
    for float images, which are linear by definition. The mip levels are computed on the
    CPU (``pbrlab.maths.mipmaps``: exact, the same on every machine), not by glGenerateMipmap,
    whose sRGB encode differs between CPU vendors on llvmpipe.
    """
    image = np.ascontiguousarray(image[::-1])  # GL rows are bottom-up
    if image.ndim == 2:
        image = image[..., None]
    h, w, c = image.shape
    most = int(ctx.info.get("GL_MAX_TEXTURE_SIZE", 16384))
    if w > most or h > most:
        raise PbrlabError(f"a {w}x{h} texture: this GL's textures are at most {most} pixels "
                          "per side (GL_MAX_TEXTURE_SIZE)")
    if image.dtype == np.uint8:
        dtype = "f1"
        if srgb:
            if c not in (3, 4):
                raise PbrlabError("an sRGB colour texture needs 3 or 4 channels")
            if c == 3:
                image = np.concatenate([image, np.full((h, w, 1), 255, np.uint8)], axis=2)
                c = 4
            internal_format = GL_SRGB8_ALPHA8
        else:
            internal_format = _GL_INTERNAL_FORMATS["f1"][c]
    else:
        if srgb:
            raise PbrlabError("float images are linear; upload them with srgb=False")
        dtype, internal_format = "f4", _GL_INTERNAL_FORMATS["f4"][c]
        image = image.astype(np.float32)
    levels = mipmaps.mip_chain(image, srgb=srgb)
    tex = ctx.texture((w, h), c, np.ascontiguousarray(levels[0]).tobytes(), dtype=dtype,
                      internal_format=internal_format)
    _upload_levels(ctx, tex, levels[1:], internal_format)
    tex.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    return tex



def lookup_table_texture(ctx: moderngl.Context, table: np.ndarray) -> moderngl.Texture:
    """A precomputed table (the DFG table, the sheen albedo table) as a linear float
    texture: bilinear filtering, clamped to its edge texels, no mips."""
    tex = upload_texture(ctx, table, srgb=False)
    tex.filter = (moderngl.LINEAR, moderngl.LINEAR)
    tex.repeat_x = tex.repeat_y = False
    return tex


def _upload_levels(ctx, tex, levels, internal_format) -> None:
    """glTexImage2D for mip levels 1.. (moderngl only writes levels that already exist)."""
    if not levels:
        return
    tex_image_2d = gl.gl_function(ctx, "glTexImage2D")
    gl.gl_function(ctx, "glPixelStorei")(_GL_UNPACK_ALIGNMENT, 1)
    # Bind on the last unit, as moderngl does for its own writes, so that no texture a
    # caller has bound for drawing is displaced.
    tex.use(ctx.info["GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS"] - 1)
    for index, level in enumerate(levels, start=1):
        data = np.ascontiguousarray(level)
        height, width, channels = data.shape
        gl_type = _GL_UNSIGNED_BYTE if data.dtype == np.uint8 else _GL_FLOAT
        tex_image_2d(_GL_TEXTURE_2D, index, internal_format, width, height, 0,
                     _GL_FORMATS[channels], gl_type, data.ctypes.data)  # copies before returning


_GL_TEXTURE_MAX_LEVEL = 0x813D


def float_texture_from_levels(ctx: moderngl.Context, levels) -> moderngl.Texture:
    """A float texture whose mip levels are ``levels`` (each HxWxC float32, GL row order,
    level 0 first; a chain that may stop before 1x1): glTexImage2D per level and
    GL_TEXTURE_MAX_LEVEL at the last. Not glGenerateMipmap on an empty texture: its first call
    in a process sets up llvmpipe's blitter (about 30 ms of a render's start-up, issue 25)."""
    first = np.ascontiguousarray(levels[0], np.float32)
    height, width, channels = first.shape
    tex = ctx.texture((width, height), channels, first.tobytes(), dtype="f4")
    _upload_levels(ctx, tex, [np.asarray(level, np.float32) for level in levels[1:]],
                   _GL_INTERNAL_FORMATS["f4"][channels])
    tex.use(ctx.info["GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS"] - 1)  # as _upload_levels binds it
    gl.gl_function(ctx, "glTexParameteri")(_GL_TEXTURE_2D, _GL_TEXTURE_MAX_LEVEL, len(levels) - 1)
    return tex
