"""The sky's own shadowing (render.environment_visibility = K): how much of the environment's
light the scene's own geometry hides from a point, estimated the way a rasteriser can, with K
shadow maps along K directions that stand for the (sun-free) environment.

Directions (``median_cut``): the environment's equirectangular image is cut into K regions of
equal luminous flux (Debevec 2005, "A median cut algorithm for light probe sampling": split
each region along its longer side, measured as an angle on the sphere, where the flux
halves). Region k becomes a direction l_k, its flux-weighted centroid, carrying its RGB flux
F_k = sum over its texels of L dOmega. A constant sky gives K regions of equal solid angle.

Estimator, per point p with shading normal n (scene_lighting.inc, pbrlab_environment_visibility):

    V(p, n) = sum_k F_k max(0, n.l_k) s_k(p)  /  sum_k F_k max(0, n.l_k)     (RGB)

with s_k(p) the share of l_k's shadow map's percentage-closer taps that see the sky from p (as
render/shadow_map.py reads the sun's). It is a ratio: where nothing stands in the way V = 1
exactly and the environment's light is as before; under a constant sky V is the quadrature
over the K directions of the cosine-weighted visible fraction of the hemisphere,
(1/pi) int_{n.l>0} vis(l) n.l dl. The environment's specular light (and the clear coat's) is
multiplied by it (the coat's by V itself; specular occlusion from the visibility: the lobe is not resolved by K
directions, the cosine-weighted estimate stands in for it), through Jimenez et al. 2016's
multi-bounce fit with the specular colour as the albedo (light the surroundings send back);
with render.environment_visibility_diffuse the diffuse and sheen light too, through the same
fit with the diffuse albedo. On the fidelity benchmark the specular alone moved the median
closer to Cycles and the diffuse moved it away (docs/fidelity.md): a path tracer fills the
hidden sky with light bounced off and emitted by the scene.

Error against the true visible fraction (tests/render/test_environment_visibility.py bounds
both): the quadrature's, from K: a region's directions all count with its centroid, so only
regions that straddle the occluder's silhouette (or the horizon) err, each by at most its
weight; and the shadow map's, from its texel footprint t: a direction whose ray passes within
(1 + 1.5 sqrt 2 + NORMAL_OFFSET_TEXELS) t of the occluder's edge may go either way (shadow_map.py).

The maps: K tiles of TILE x TILE texels in one depth texture (a square grid of tiles), each
fitted to the scene's bounds along its direction by shadow_map.light_frame and drawn by
shadow_map.draw_depth; the shader reads tile k through an affine map folded into its uniforms.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import moderngl
import numpy as np

from . import shadow_map
from ..scene.environment import equirect_directions

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # Rec. 709 weights, as the sun's split weighs flux
COUNTS = (0, 16, 32, 64)   # render.environment_visibility's choices (0: off)
# texels per tile side: the benchmark frames a model at 384 drawn pixels, so a texel is about
# 0.75 of a drawn pixel: the sky's shadows are soft (K directions), a coarser map than the sun's
TILE = 512
# the median cut needs rows enough to cut K regions from a small image (a constant colour is 4 x 8)
MIN_ROWS = 64


@dataclass(frozen=True)
class SkyLights:
    directions: np.ndarray   # K x 3 unit, from the surface towards the sky
    flux: np.ndarray         # K x 3 RGB, sum L dOmega over each region
    regions: list            # K (row0, row1, col0, col1) of the image cut


def _summed(a: np.ndarray) -> np.ndarray:
    """Summed-area table with a zero first row and column: sum a[r0:r1, c0:c1] from four reads."""
    out = np.zeros((a.shape[0] + 1, a.shape[1] + 1) + a.shape[2:], np.float64)
    out[1:, 1:] = a.cumsum(0).cumsum(1)
    return out


def _box(table, r0, r1, c0, c1):
    return table[r1, c1] - table[r0, c1] - table[r1, c0] + table[r0, c0]


def median_cut(image: np.ndarray, count: int) -> SkyLights:
    """``count`` (a power of two) regions of equal luminous flux of an equirectangular radiance
    image, as directions and RGB fluxes (module doc)."""
    radiance = np.asarray(image, np.float64)[..., :3]
    if radiance.shape[0] < MIN_ROWS:  # nearest upsampling: the same sky, finer cuts
        repeat = -(-MIN_ROWS // radiance.shape[0])
        radiance = radiance.repeat(repeat, axis=0).repeat(repeat, axis=1)
    height, width = radiance.shape[:2]
    directions, solid_angle = equirect_directions(height, width)
    flux_rgb = radiance * solid_angle[..., None]
    luminance = flux_rgb @ LUMINANCE
    lum = _summed(luminance)
    rgb = _summed(flux_rgb)
    weighted = _summed(directions * np.where(luminance > 0, luminance, 0.0)[..., None])
    plain = _summed(directions * solid_angle[..., None])
    polar = (np.arange(height) + 0.5) / height * np.pi

    def split(region):
        r0, r1, c0, c1 = region
        tall = (r1 - r0) * math.pi / height
        wide = (c1 - c0) * 2 * math.pi / width * math.sin(polar[(r0 + r1 - 1) // 2])
        along_rows = (tall >= wide and r1 - r0 > 1) or c1 - c0 == 1
        if along_rows:
            cumulative = np.array([_box(lum, r0, r, c0, c1) for r in range(r0 + 1, r1)])
        else:
            cumulative = np.array([_box(lum, r0, r1, c0, c) for c in range(c0 + 1, c1)])
        total = _box(lum, r0, r1, c0, c1)
        cut = int(np.argmin(np.abs(cumulative - total / 2))) + 1 if total > 0 else len(cumulative) // 2 + 1
        if along_rows:
            return (r0, r0 + cut, c0, c1), (r0 + cut, r1, c0, c1)
        return (r0, r1, c0, c0 + cut), (r0, r1, c0 + cut, c1)

    if count < 1 or count & (count - 1):
        raise ValueError(f"median_cut: count {count} is not a power of two")
    regions = [(0, height, 0, width)]
    while len(regions) < count:
        regions = [half for region in regions for half in split(region)]
    dirs, fluxes = [], []
    for region in regions:
        d = _box(weighted, *region)
        if not np.linalg.norm(d) > 0:
            d = _box(plain, *region)
        dirs.append(d / np.linalg.norm(d))
        fluxes.append(_box(rgb, *region))
    return SkyLights(np.array(dirs), np.array(fluxes), regions)


def sky_casters(scene) -> list:
    """The sun's casters (shadow_map.casters) less the transmissive: light comes through those in a
    path tracer, and a test grid of glass spheres would darken itself."""
    return [o for o in shadow_map.casters(scene) if not scene.materials[o.material].transmission > 0.0]


class EnvironmentVisibility:
    """The K shadow maps of one render (an atlas of tiles) and how a program reads them."""

    def __init__(self, ctx: moderngl.Context, scene, image: np.ndarray, count: int, sun=None):
        if sun is not None:  # the sky without the sun, as environment_sun.sunless makes it: its texels filled
            image = np.array(image, np.float32)[..., :3]
            image[sun.mask] = np.asarray(sun.fill, np.float32)
        self.lights = median_cut(image, count)
        self.grid = math.ceil(math.sqrt(count))
        size = self.grid * TILE
        self.texture = ctx.depth_texture((size, size))
        self.texture.compare_func = ""
        self.texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
        self.texture.repeat_x = self.texture.repeat_y = False
        rows = {"u": [], "v": [], "w": [], "light": []}
        fbo = ctx.framebuffer(depth_attachment=self.texture)
        objects = sky_casters(scene)
        try:
            fbo.use()
            ctx.clear(depth=1.0)
            for k, direction in enumerate(self.lights.directions):
                tx, ty = k % self.grid, k // self.grid
                frame = shadow_map.light_frame(scene, -direction, TILE)  # light travels from the sky
                shadow_map.draw_depth(ctx, scene, frame, fbo, viewport=(tx * TILE, ty * TILE, TILE, TILE),
                                      objects=objects, single_sided=True)
                u, v, w = frame.axes
                depth_bias = shadow_map.DEPTH_BIAS_TEXELS * frame.texel * float(np.linalg.norm(w))
                rows["u"].append([*(u / self.grid), (tx - frame.origin @ u) / self.grid])
                rows["v"].append([*(v / self.grid), (ty - frame.origin @ v) / self.grid])
                rows["w"].append([*w, -(frame.origin @ w) - depth_bias])
                rows["light"].append([*direction, shadow_map.NORMAL_OFFSET_TEXELS * frame.texel])
        finally:
            fbo.release()
        self.uniforms = {f"u_sky_shadow_{name}": np.array(value, np.float64) for name, value in rows.items()}
        self.uniforms["u_sky_flux"] = self.lights.flux
        self.texel = 1.0 / size

    def bind(self, program, unit: int) -> None:
        from ..gpu.programs import set_uniform, set_uniform_array
        if program.get("u_sky_shadow_map", None) is None:
            return  # a program that reads no environment (an unlit material)
        self.texture.use(unit)
        set_uniform(program, "u_sky_shadow_map", unit)
        for name, value in self.uniforms.items():
            set_uniform_array(program, name, list(value))
        set_uniform(program, "u_sky_shadow_texel", self.texel)

    def release(self):
        self.texture.release()
