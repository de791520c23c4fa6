"""What renders of the same files share, so only the first render of a scene pays for them:
GPU textures per GL context (the environment's GGX prefilter and SH9, the DFG table,
material textures, neutral 1x1 stand-ins) and, in meshes.mesh_data, mesh vertex data per
process.

Entries are keyed by file identity (resolved path, size, modification time in ns, inode), so a
file rewritten between renders is read again and an unchanged one is read once. GPU
entries live in the context's ``extra`` dict and go with the context; each kind is a small
LRU that releases the textures it evicts. Before this cache, ``render_scene`` read,
uploaded and prefiltered the environment, textures and meshes on every call; a warm
1024^2 frame of scenes/unity_example took 0.35 s, now 0.15 s (wall clock, 2 cores), and
the bench's frame figures counted mesh and texture loading as shading.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass
from pathlib import Path

import moderngl
import numpy as np

from ..gpu import ibl, targets
from ..scene.environment import environment_image, environment_sh, project_equirect
from ..foundation.file_identity import file_key as _file_key
from ..foundation.errors import PbrlabError
from ..foundation.images import read_image

ENVIRONMENTS_PER_CONTEXT = 4
TEXTURES_PER_CONTEXT = 64
_EXTRA_KEY = "pbrlab_resource_cache"


def file_key(path: Path) -> tuple:
    """(resolved path, size, mtime_ns, inode): changes when the file is rewritten or
    replaced (file_identity.file_key)."""
    return _file_key(path)


class _LRU:
    """An ordered dict of at most ``size`` entries; ``evict`` receives each one dropped."""

    def __init__(self, size: int, evict):
        self.size, self.evict, self.entries = size, evict, OrderedDict()

    def get(self, key, make):
        if key in self.entries:
            self.entries.move_to_end(key)
            return self.entries[key]
        value = self.entries[key] = make()
        while len(self.entries) > self.size:
            self.evict(self.entries.popitem(last=False)[1])
        return value


@dataclass
class PreparedEnvironment:
    """The environment's light as the scene programs read it."""
    sh: np.ndarray                 # 9x3 float64, SH9 of the radiance (Unity's ambient: ShadeSH9)
    prefiltered: moderngl.Texture  # GGX-prefiltered cube mip chain (ibl.py)
    irradiance: moderngl.Texture   # irradiance / pi cube (ibl.irradiance_environment)

    def release(self):
        self.prefiltered.release()
        self.irradiance.release()


class ContextCache:
    """The shared resources of one GL context (``context_cache(ctx)``)."""

    def __init__(self, ctx: moderngl.Context):
        self.ctx = ctx
        self._dfg = {}
        self._sheen = None
        self._environments = _LRU(ENVIRONMENTS_PER_CONTEXT, PreparedEnvironment.release)
        self._textures = _LRU(TEXTURES_PER_CONTEXT, moderngl.Texture.release)
        self._suns = {}

    def dfg(self, layout: str = "WARPED") -> moderngl.Texture:
        """The DFG table of ``layout`` (PBR_DFG_LUT_LAYOUT: the tier's, ibl.dfg_lut), made once
        per context."""
        if layout not in self._dfg:
            self._dfg[layout] = ibl.dfg_texture(self.ctx, layout)
        return self._dfg[layout]

    def sheen(self) -> moderngl.Texture:
        """The sheen albedo table (sheen_table.sheen_texture), made once per context."""
        if self._sheen is None:
            from ..gpu import sheen_table
            self._sheen = sheen_table.sheen_texture(self.ctx)
        return self._sheen

    def environment(self, environment, sun=None) -> PreparedEnvironment:
        """A scene's environment (constant colour or image file, times its intensity); with
        ``sun`` (scene/environment_sun.py, found in this environment) the sky without it."""
        if environment.color is not None:
            source = ("color", tuple(float(c) for c in environment.color))
        else:
            source = ("file", *file_key(environment.path))
        key = (source, float(environment.intensity), sun is not None)
        def prepare():
            image = environment_image(environment)
            if sun is None:
                return PreparedEnvironment(environment_sh(environment), ibl.prefiltered_environment(self.ctx, image),
                                           ibl.irradiance_environment(self.ctx, image))
            from ..scene.environment_sun import sunless
            image = sunless(image, sun)
            return PreparedEnvironment(project_equirect(image), ibl.prefiltered_environment(self.ctx, image),
                                       ibl.irradiance_environment(self.ctx, image))
        return self._environments.get(key, prepare)

    def environment_sun(self, environment):
        """The sun of an image environment (scene/environment_sun.find_sun), or None; found once."""
        if environment.color is not None:
            return None
        key = ("sun", *file_key(environment.path), float(environment.intensity))
        if key not in self._suns:
            from ..scene.environment_sun import find_sun
            self._suns[key] = find_sun(environment_image(environment))
        return self._suns[key]

    def black_environment(self) -> PreparedEnvironment:
        """No light at all: what the full program samples in a scene without environment."""
        return self._environments.get(("black",), lambda: PreparedEnvironment(
            np.zeros((9, 3)), ibl.black_cube(self.ctx), ibl.black_cube(self.ctx)))

    def texture(self, source, srgb: bool, sampler: tuple | None = None) -> moderngl.Texture:
        """An image as a texture (colour data decoded from sRGB when ``srgb``): a file path
        (checked by _file_texture), or an in-memory image with ``key`` (a tuple naming it)
        and ``pixels()`` (glTF images: pbrlab/importers/gltf). ``sampler``: (repeat_x, repeat_y,
        min_filter, mag_filter) with moderngl's filter constants; None is repeat with
        trilinear filtering."""
        if isinstance(source, (str, Path)):
            key, upload = ("file", *file_key(source)), lambda: _file_texture(self.ctx, source, srgb)
        else:
            key = ("memory", *source.key)
            upload = lambda: targets.upload_texture(self.ctx, source.pixels(), srgb=srgb)  # noqa: E731

        def make():
            tex = upload()
            if sampler is not None:
                tex.repeat_x, tex.repeat_y = bool(sampler[0]), bool(sampler[1])
                tex.filter = (sampler[2], sampler[3])
            return tex
        return self._textures.get((key, srgb, sampler), make)

    def constant_texture(self, texel) -> moderngl.Texture:
        """A 1x1 RGBA32F texture holding ``texel``."""
        texel = tuple(float(x) for x in texel)
        return self._textures.get(("constant", texel), lambda: self.ctx.texture(
            (1, 1), 4, np.array(texel, np.float32).tobytes(), dtype="f4"))

    def constant_volume(self, texel) -> moderngl.Texture:
        """A 1x1x1 RGBA32F 3D texture holding ``texel`` (a 3D property's default texture)."""
        texel = tuple(float(x) for x in texel)
        return self._textures.get(("constant volume", texel), lambda: self.ctx.texture3d(
            (1, 1, 1), 4, np.array(texel, np.float32).tobytes(), dtype="f4"))


def _file_texture(ctx, path: Path, srgb: bool) -> moderngl.Texture:
    """Upload an image file; non-finite texels and oversize images are refused by name
    (a NaN normal map once rendered black without a word)."""
    image = read_image(path)
    if image.dtype != np.uint8:
        bad = int((~np.isfinite(image)).any(axis=-1).sum())
        if bad:
            raise PbrlabError(f"texture {path}: {bad} texel(s) are NaN or Inf; textures must be finite")
    try:
        return targets.upload_texture(ctx, image, srgb=srgb)
    except PbrlabError as exc:
        raise PbrlabError(f"texture {path}: {exc}") from None


def context_cache(ctx: moderngl.Context) -> ContextCache:
    """The cache of ``ctx`` (made on first use, kept in ``ctx.extra``)."""
    extra = ctx.extra if isinstance(ctx.extra, dict) else {}
    if _EXTRA_KEY not in extra:
        extra[_EXTRA_KEY] = ContextCache(ctx)
        ctx.extra = extra
    return extra[_EXTRA_KEY]
