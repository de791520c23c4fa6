"""Cross-check against a peer renderer: pyrender 0.1.45's metallic-roughness shader.

pyrender (``pyrender/shaders/mesh.frag`` of 0.1.45; line numbers below are that file's)
shades a directional light as

    C = I · c_light · NdotL · [ (1 − F) · c_diff / π  +  F · G · D / (4 · NdotL · NdotV + 0.001) ]
                                                                               (l. 243-261, 357)
    D  GGX, alpha = roughness², roughness = material roughness factor   (l. 228-236, 331;
       compute_brdf gets the perceptual roughness, l. 361: alpha_roughness, l. 334, is unused)
    G  Schlick-GGX, G1(x) = NdotX / (NdotX (1 − k) + k), k = (roughness + 1)² / 8  (l. 216-226)
       (Karis 2013's "hotness" remapping; pbr_k_SchlickGGX_hotness gives the same k)
    F  Schlick at VdotH, F90 = 1 (implicit)                              (l. 209-213)
       f0 = mix(0.04, base, metallic)                                    (l. 343-345)
    diffuse  Lambert weighted by (1 − F(VdotH)), c_diff = base · 0.96 · (1 − metallic)
       (0.04 is ``min_roughness`` reused as the dielectric F0, l. 146, 343-344)
    clamps  roughness to [0.04, 1] (l. 331); NdotL to [0.001, 1] with NO horizon cut, so
       unlit texels get 0.001 of the head-on light (l. 244); NdotV = clamp(|n·v|, 0.001, 1)
       (l. 245); NdotH, LdotH, VdotH saturated (l. 246-248)
    light units  radiance = intensity · color, no π anywhere (l. 357-361): a pyrender light
       of intensity I is a pbrlab light of intensity I / π (pbrlab multiplies by π)
    output  clamp(pow(C, 1/2.2), 0, 1) in the shader (l. 446) into a plain RGBA8 target
       (renderer.py: GL_RGBA renderbuffer, no GL_FRAMEBUFFER_SRGB), 4x MSAA on EGL
       (renderer.py ``_configure_main_framebuffer``), none on OSMesa (no framebuffer
       objects: the front buffer is read). Decode: linear = (code / 255)^2.2.

pbrlab's renderer expresses D, F, f0 and c_diff with its selectors (``specular_d: ggx``,
``specular_f: schlick``, the metallic workflow); two terms have no selector:
  * G with k = (r + 1)² / 8: ``specular_v: schlick_ggx`` takes k = alpha / 2;
  * the (1 − F(VdotH)) weight on the diffuse: pbrlab couples the diffuse to the specular
    lobe's directional albedo instead, ρ (1 − E(NdotV)) with E from the DFG table
    (pbr/shading/energy_conservation.glsl), which this program reads as the renderer does;
and pyrender's 0.001 additions (denominator, cosine floors) are not pbrlab's guards.
``render_pbrlab_terms`` therefore composes pyrender's BRDF from the library's own term
functions (pbr_D_GGX, pbr_G_SchlickGGX + pbr_k_SchlickGGX_hotness, pbr_F_Schlick,
pbr_Fd_Lambert, pbr_f0_from_metallic, pbr_diffuse_from_metallic, PBR_LIGHT_UNIT_SCALE),
with one switch per difference so each one's size is measured separately; with every
switch at pbrlab's choice it is the renderer's nearest-selector render.

pyrender runs in a subprocess per platform (``python -m pbrlab.checking.pyrender.check --worker``)
so its PyOpenGL context never shares a process with pbrlab's moderngl context; arrays come
back through a .npz file. Its uniforms must be floats: pyrender passes a list of Python
ints to glUniform3iv on a vec3 and the light silently goes wrong.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...foundation.errors import PbrlabError

# pyrender 0.1.45 constants (pyrender/shaders/mesh.frag)
PYRENDER_GAMMA = 2.2            # l. 446: pow(color, 1/2.2)
PYRENDER_MIN_ROUGHNESS = 0.04   # l. 146, 331 (also its dielectric F0, l. 343)
PYRENDER_COSINE_FLOOR = 0.001   # l. 244-245
PYRENDER_DENOMINATOR_EPSILON = 0.001  # l. 259

# The scene: base colours (linear) x metallic x roughness (pyrender's = perceptual).
BASE_COLOURS = {"red": (0.8, 0.1, 0.08), "gold": (1.0, 0.766, 0.336), "blue": (0.15, 0.3, 0.8)}
METALLIC = (0.0, 0.5, 1.0)
ROUGHNESS = (0.2, 0.5, 0.9)
PYRENDER_LIGHT_INTENSITY = 2.5    # pyrender units; pbrlab's light is this / π
LIGHT_DIRECTION = (0.5, -0.6, -1.0)  # the way light travels: from the upper left, in front
SPACING = 2.25
ICOSPHERE_SUBDIVISIONS = 4
DEFAULT_SIZE = (288, 96)

# The switches of render_pbrlab_terms: 1 = pyrender's term, 0 = pbrlab's renderer.
TERM_SWITCHES = {
    "PYR_G_HOTNESS": "G's k = (r + 1)^2 / 8 (pyrender) instead of alpha / 2 (schlick_ggx)",
    "PYR_DIFFUSE_ONE_MINUS_F": "diffuse weighted by 1 - F(VdotH) (pbrlab: rho (1 - E(NdotV)))",
    "PYR_DENOMINATOR_EPSILON": "specular denominator 4 NdotL NdotV + 0.001",
    "PYR_COSINE_FLOORS": "NdotL, |NdotV| floored at 0.001, no horizon cut",
}
PYRENDER_TERMS = {name: 1 for name in TERM_SWITCHES}
PBRLAB_SELECTOR_TERMS = {name: 0 for name in TERM_SWITCHES}
# What the renderer path uses for the nearest match (scene "brdf" of every material).
NEAREST_SELECTORS = {"specular_d": "ggx", "specular_v": "schlick_ggx", "specular_f": "schlick",
                     "diffuse": "lambert"}


def grid_scene(size=DEFAULT_SIZE, brdf: dict | None = None) -> dict:
    """The comparison scene as a pbrlab scene dict: rows = base colours, columns =
    metallic-major (metallic, roughness); icosphere meshes; one directional light in
    pbrlab units (pyrender's intensity / π); no environment. ``brdf``: the materials'
    selectors (None: pbrlab's defaults)."""
    columns = [(m, r) for m in METALLIC for r in ROUGHNESS]
    materials, objects = {}, []
    for row, (colour_name, colour) in enumerate(BASE_COLOURS.items()):
        for col, (metallic, roughness) in enumerate(columns):
            name = f"{colour_name}_m{metallic}_r{roughness}"
            materials[name] = {"albedo": list(colour), "metallic": metallic, "smoothness": 1.0 - roughness}
            if brdf:
                materials[name]["brdf"] = dict(brdf)
            x = (col - (len(columns) - 1) / 2) * SPACING
            y = ((len(BASE_COLOURS) - 1) / 2 - row) * SPACING
            objects.append({"mesh": {"primitive": "icosphere", "subdivisions": ICOSPHERE_SUBDIVISIONS,
                                     "radius": 1.0},
                            "material": name, "transform": {"translate": [x, y, 0.0]}})
    distance = 40.0
    half_height = (len(BASE_COLOURS) * SPACING) / 2 * 1.04
    half_width = len(columns) * SPACING / 2 * 1.04
    w, h = size
    half_height = max(half_height, half_width * h / w)
    return {
        "camera": {"position": [0.0, 0.0, distance], "target": [0.0, 0.0, 0.0],
                   "fov_y_deg": math.degrees(2 * math.atan(half_height / distance)), "size": list(size)},
        "lights": [{"type": "directional", "direction": list(LIGHT_DIRECTION),
                    "intensity": PYRENDER_LIGHT_INTENSITY / math.pi}],
        "environment": None,
        "materials": materials,
        "objects": objects,
        "render": {"tonemap": "none"},
    }


# ---------------------------------------------------------------- pyrender side (subprocess)

def _camera_pose(camera) -> np.ndarray:
    """pyrender's camera-to-world pose (looks down its -Z) of a pbrlab camera; the same
    basis as pbrlab.maths.camera.camera_frame."""
    forward = camera.target - camera.position
    forward = forward / np.linalg.norm(forward)
    right = np.cross(forward, camera.up)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    pose = np.eye(4)
    pose[:3, 0], pose[:3, 1], pose[:3, 2], pose[:3, 3] = right, up, -forward, camera.position
    return pose


def _light_pose(direction) -> np.ndarray:
    """A pose whose -Z is ``direction`` (pyrender: direction = -pose[:3, 2], renderer.py)."""
    z = -np.asarray(direction, float) / np.linalg.norm(direction)
    helper = np.array([0.0, 1.0, 0.0]) if abs(z[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    pose = np.eye(4)
    pose[:3, 0], pose[:3, 1], pose[:3, 2] = x, np.cross(z, x), z
    return pose


def _worker(platform: str, scene_path: str, out_path: str) -> None:
    """Render the scene with pyrender (this process only) and save srgb8, coverage, info."""
    from ...gpu import gl
    from ...scene import meshes
    from .compat import import_pyrender
    from ...importers.loader import parse_scene

    gl.pin_llvmpipe_cpu_caps()  # the same llvmpipe code generation as pbrlab's contexts
    pyrender = import_pyrender(platform)
    data = json.loads(Path(scene_path).read_text(encoding="utf-8"))
    scene = parse_scene(data)
    pr_scene = pyrender.Scene(ambient_light=[0.0, 0.0, 0.0], bg_color=[0.0, 0.0, 0.0, 0.0])
    for obj in scene.objects:
        material = scene.materials[obj.material]
        pr_material = pyrender.MetallicRoughnessMaterial(
            baseColorFactor=[float(c) for c in material.albedo] + [1.0],
            metallicFactor=float(material.metallic), roughnessFactor=float(1.0 - material.smoothness))
        mesh = pyrender.Mesh.from_trimesh(meshes.as_trimesh(meshes.load_mesh(obj)), material=pr_material, smooth=True)
        pr_scene.add(mesh, pose=obj.transform)
    for light in scene.lights:
        if light.type != "directional":
            raise PbrlabError("the pyrender cross-check uses directional lights only")
        pr_scene.add(pyrender.DirectionalLight(color=[float(c) for c in light.color],
                                               intensity=float(light.intensity * math.pi)),
                     pose=_light_pose(light.direction))
    w, h = scene.camera.size
    pr_scene.add(pyrender.PerspectiveCamera(yfov=math.radians(scene.camera.fov_y_deg),
                                            aspectRatio=w / h, znear=0.05, zfar=1000.0),
                 pose=_camera_pose(scene.camera))
    renderer = pyrender.OffscreenRenderer(w, h)
    try:
        color, depth = renderer.render(pr_scene, flags=pyrender.RenderFlags.RGBA)
        from OpenGL import GL
        info = {"platform": platform, "GL_RENDERER": GL.glGetString(GL.GL_RENDERER).decode(),
                "GL_VERSION": GL.glGetString(GL.GL_VERSION).decode(),
                "pyrender": getattr(pyrender, "__version__", "?")}
    finally:
        renderer.delete()
    np.savez(out_path, rgb8=np.ascontiguousarray(color[..., :3]), coverage=depth > 0,
             info=json.dumps(info))


@dataclass
class PyrenderImage:
    rgb8: np.ndarray      # HxWx3 uint8, pyrender's display codes (gamma 2.2 in its shader)
    coverage: np.ndarray  # HxW bool: depth written
    info: dict


def render_pyrender(scene_dict: dict, platform: str, timeout: float = 120.0) -> PyrenderImage:
    """Render a (directional-light, mesh) pbrlab scene dict with pyrender on ``platform``
    ('egl' or 'osmesa') in a subprocess."""
    if platform not in ("egl", "osmesa"):
        raise ValueError(f"platform must be 'egl' or 'osmesa', got {platform!r}")
    with tempfile.TemporaryDirectory(prefix="pbrlab-pyrender-") as tmp:
        scene_path, out_path = Path(tmp) / "scene.json", Path(tmp) / "out.npz"
        scene_path.write_text(json.dumps(scene_dict), encoding="utf-8")
        env = dict(os.environ, PYOPENGL_PLATFORM=platform)
        proc = subprocess.run([sys.executable, "-m", "pbrlab.checking.pyrender.check", "--worker", platform,
                               str(scene_path), str(out_path)],
                              capture_output=True, text=True, env=env, timeout=timeout)
        if proc.returncode != 0 or not out_path.is_file():
            raise PbrlabError(f"pyrender ({platform}) failed with exit code {proc.returncode}:\n"
                              f"{proc.stderr[-3000:]}")
        with np.load(out_path) as data:
            return PyrenderImage(data["rgb8"].copy(), data["coverage"].copy(), json.loads(str(data["info"])))


def decode_pyrender(codes: np.ndarray):
    """pyrender's 8-bit codes -> (linear, low, high): the code's value and the linear
    interval that rounds to it (pow 2.2 of code ∓ half a step)."""
    c = np.asarray(codes, np.float64)
    linear = (c / 255.0) ** PYRENDER_GAMMA
    low = (np.maximum(c - 0.5, 0.0) / 255.0) ** PYRENDER_GAMMA
    high = (np.minimum(c + 0.5, 255.0) / 255.0) ** PYRENDER_GAMMA
    return linear, low, high


def encode_pyrender(linear: np.ndarray) -> np.ndarray:
    """pyrender's display encode (float codes, unrounded): 255 · clamp(C)^(1/2.2)."""
    return 255.0 * np.clip(np.asarray(linear, np.float64), 0.0, 1.0) ** (1.0 / PYRENDER_GAMMA)


# ---------------------------------------------------------------- pbrlab side

_TERMS_FRAG = """#version 330 core
// pyrender 0.1.45's metallic-roughness direct lighting for one directional light and a
// constant material: templates/pyrender_brdf.inc, which composes it from pbrlab's terms.
//@DEFINES
uniform sampler2D u_dfg_lut;     // harness/pbrlab/gpu/ibl.py dfg_lut, as the renderer binds it
#define PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness) texture(u_dfg_lut, pbr_dfg_lut_uv(NdotV, perceptualRoughness)).rg
#include "pbr/common/conventions.glsl"
#include "pbr/common/guards.glsl"
#include "pbr/material/workflow.glsl"
#include "pbr/brdf/d_ggx.glsl"
#include "pbr/brdf/g_schlick_ggx.glsl"
#include "pbr/brdf/f_schlick.glsl"
#include "pbr/brdf/fd_lambert.glsl"
#include "pbr/ibl/environment_brdf.glsl"
#include "pbr/shading/energy_conservation.glsl"
#include "pyrender_brdf.inc"

uniform vec3 u_camera_position;
uniform vec3 u_light_l;          // unit, towards the light
uniform vec3 u_light_radiance;   // pbrlab units (pyrender's intensity / pi)
uniform vec3 u_base_color;
uniform float u_metallic;
uniform float u_roughness;       // perceptual (pyrender's roughness factor)
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
out vec4 out_radiance;

void main() {
    vec3 n = normalize(v_normal);
    vec3 v = normalize(u_camera_position - v_position);
    out_radiance = vec4(pyr_direct(n, v, u_light_l, u_light_radiance, u_base_color, u_metallic, u_roughness), 1.0);
}
"""

_TERM_PROGRAMS: dict = {}


def _terms_program(ctx, terms: dict):
    from ...gpu import shaders
    from ...gpu.programs import TEMPLATES

    unknown = set(terms) - set(TERM_SWITCHES)
    if unknown:
        raise ValueError(f"unknown term switches {sorted(unknown)}; use {sorted(TERM_SWITCHES)}")
    switches = {name: int(terms.get(name, 1)) for name in TERM_SWITCHES}
    key = (id(ctx), tuple(sorted(switches.items())))
    if key not in _TERM_PROGRAMS:
        defines = "\n".join(f"#define {k} {v}" for k, v in sorted(switches.items()))
        vert = shaders.expand((TEMPLATES / "mesh.vert").read_text(encoding="utf-8"),
                              "pbrlab/templates/mesh.vert")
        frag = shaders.expand(_TERMS_FRAG.replace("//@DEFINES", defines), "pbrlab/checking/pyrender/check.py",
                              include_dirs=[TEMPLATES])
        _TERM_PROGRAMS[key] = shaders.build_program(ctx, vert, frag)
    return _TERM_PROGRAMS[key]


def render_pbrlab_terms(scene_dict: dict, ctx=None, terms: dict | None = None) -> np.ndarray:
    """pyrender's shading composed from pbrlab's term functions (``terms``: switches of
    TERM_SWITCHES, default all pyrender's) on the scene's meshes; HxWx4 float32 linear,
    alpha = coverage. Same camera, meshes, vertex program and light units as render_scene."""
    import moderngl

    from ...gpu import gl, targets
    from ...scene import meshes
    from ...render import resource_cache
    from ...render.depth_range import scene_frame
    from ...importers.loader import parse_scene

    scene = parse_scene(scene_dict)
    if [light.type for light in scene.lights] != ["directional"]:
        raise PbrlabError("render_pbrlab_terms takes exactly one directional light")
    light = scene.lights[0]
    ctx = gl.make_current(ctx or gl.shared_context())
    program = _terms_program(ctx, terms or PYRENDER_TERMS)
    frame = scene_frame(scene)
    values = {"u_camera_position": tuple(frame.position), "u_light_l": tuple(-light.direction),
              "u_light_radiance": tuple(light.color * light.intensity),
              "u_view_proj": tuple(frame.view_proj.T.reshape(-1)), "u_dfg_lut": 0}
    resource_cache.context_cache(ctx).dfg().use(0)
    with targets.Target(ctx, frame.size, "f32") as hdr:
        hdr.use()
        ctx.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        ctx.disable(moderngl.BLEND)
        ctx.cull_face = "back"
        ctx.front_face = "ccw"
        for obj in scene.objects:
            material = scene.materials[obj.material]
            values.update({"u_model": tuple(obj.transform.T.reshape(-1)),
                           "u_normal_matrix": tuple(np.linalg.inv(obj.transform[:3, :3]).reshape(-1)),
                           "u_base_color": tuple(material.albedo), "u_metallic": material.metallic,
                           "u_roughness": 1.0 - material.smoothness})
            for name, value in values.items():
                uniform = program.get(name, None)
                if uniform is not None:
                    uniform.value = value
            vao, buffers = meshes.vertex_array(ctx, program, obj)
            vao.render(moderngl.TRIANGLES)
            for resource in [vao, *buffers]:
                resource.release()
        ctx.disable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        return hdr.read()


# ---------------------------------------------------------------- comparison

def erode(mask: np.ndarray, radius: int) -> np.ndarray:
    """Pixels whose (2 radius + 1)² neighbourhood lies inside ``mask`` (image border = outside)."""
    padded = np.pad(mask, radius, constant_values=False)
    out = np.ones_like(mask)
    h, w = mask.shape
    for dy in range(2 * radius + 1):
        for dx in range(2 * radius + 1):
            out &= padded[dy:dy + h, dx:dx + w]
    return out


SILHOUETTE_MARGIN_PX = 2       # eroded from both coverages (MSAA edges, polygonal outline)
RELATIVE_FLOOR = 0.01          # linear; relative statistics over pyrender values above it


def comparison_mask(pyr: PyrenderImage, pbrlab_linear: np.ndarray) -> np.ndarray:
    """Pixels compared: inside both coverages, SILHOUETTE_MARGIN_PX from any silhouette,
    and not clipped by pyrender's clamp (no channel at code 255, none above 1 in pbrlab)."""
    covered = erode(pyr.coverage, SILHOUETTE_MARGIN_PX) & erode(pbrlab_linear[..., 3] > 0, SILHOUETTE_MARGIN_PX)
    unclipped = np.all(pyr.rgb8 < 255, axis=-1) & np.all(pbrlab_linear[..., :3] < 1.0, axis=-1)
    return covered & unclipped


@dataclass(frozen=True)
class CodeTolerance:
    """How far pbrlab's radiance, encoded with pyrender's curve, may land outside the
    8-bit code pyrender wrote: ``excess`` = |255 · C^(1/2.2) − code| − 0.5 (0 = inside the
    code's rounding interval, so quantisation itself is never counted), in codes.
    ``max_excess`` binds every compared pixel; ``loose_excess`` may be exceeded by at
    most ``loose_fraction`` of them."""
    max_excess: float
    loose_excess: float
    loose_fraction: float
    reason: str

    def check(self, pyr: PyrenderImage, pbrlab_linear: np.ndarray, mask: np.ndarray) -> tuple[bool, str]:
        excess = pixel_excess(pyr, pbrlab_linear)[mask]
        over = float(np.mean(excess > self.loose_excess))
        ok = excess.max() <= self.max_excess and over <= self.loose_fraction
        return ok, (f"worst excess {excess.max():.3f} code (allowed {self.max_excess}), "
                    f"{100 * over:.2f} % of pixels over {self.loose_excess} code "
                    f"(allowed {100 * self.loose_fraction:g} %): {self.reason}")


def pixel_excess(pyr: PyrenderImage, pbrlab_linear: np.ndarray) -> np.ndarray:
    """Per pixel, the worst channel's |encode(pbrlab) − pyrender's code| − 0.5, in codes."""
    return (np.abs(encode_pyrender(pbrlab_linear[..., :3]) - pyr.rgb8) - 0.5).max(axis=-1)


# Measured (288x96 and 480x160, Mesa 22.3 llvmpipe, SSE4.1 pinned): through OSMesa, pyrender
# reads a single-sample front buffer and every compared pixel of the composition rounds to
# pyrender's code (worst excess 0.000); 0.05 code leaves room for float32 pow/unorm
# rounding at a code boundary. Through EGL, pyrender resolves 4x MSAA, which moves 7.3 % of
# its interior pixels by 1 code and 0.1 % by 2 against its own OSMesa render (pixels on
# internal triangle edges are averaged from two fragment invocations and rounded again);
# measured composition vs pyrender-EGL: 1.0-2.9 % of pixels over 0.05 code, worst 1.88
# (bound: 2 codes of MSAA + the half code of rounding = 2.5).
TOLERANCE = {
    "osmesa": CodeTolerance(0.05, 0.05, 0.0, "single-sample: exact up to float32 rounding at a code boundary"),
    "egl": CodeTolerance(2.5, 0.05, 0.05, "pyrender's 4x MSAA resolve moves codes by up to 2 (measured "
                                          "against its own OSMesa render), plus the half code of rounding"),
}


@dataclass
class Agreement:
    pixels: int
    code_excess_max: float         # max over channels of |encode(pbrlab) - code| - 0.5, in codes
    within_quantisation: float     # fraction of channel values inside the code's decode interval
    rel_median: float
    rel_p99: float
    rel_max: float
    abs_max: float                 # linear

    def summary(self) -> str:
        return (f"{self.pixels} px; |pbrlab - pyrender| linear: max {self.abs_max:.3g}, relative (pyrender >= "
                f"{RELATIVE_FLOOR}) median {self.rel_median:.3g} p99 {self.rel_p99:.3g} max {self.rel_max:.3g}; "
                f"inside pyrender's 8-bit interval: {100 * self.within_quantisation:.2f} %, worst excess "
                f"{self.code_excess_max:.3f} code")


def agreement(pyr: PyrenderImage, pbrlab_linear: np.ndarray, mask: np.ndarray | None = None) -> Agreement:
    """pbrlab's linear radiance against pyrender's 8-bit output decoded exactly."""
    if mask is None:
        mask = comparison_mask(pyr, pbrlab_linear)
    if not mask.any():
        raise PbrlabError("no pixel to compare: coverages do not overlap")
    ours = pbrlab_linear[..., :3][mask].astype(np.float64)
    codes = pyr.rgb8[mask]
    theirs, low, high = decode_pyrender(codes)
    excess = np.abs(encode_pyrender(ours) - codes) - 0.5
    bright = theirs >= RELATIVE_FLOOR
    rel = np.abs(ours - theirs)[bright] / theirs[bright]
    return Agreement(pixels=int(mask.sum()), code_excess_max=float(excess.max()),
                     within_quantisation=float(np.mean((ours >= low) & (ours <= high))),
                     rel_median=float(np.median(rel)), rel_p99=float(np.percentile(rel, 99)),
                     rel_max=float(rel.max()), abs_max=float(np.abs(ours - theirs).max()))


def mean_display_code_difference(pyr: PyrenderImage, srgb8: np.ndarray, mask: np.ndarray) -> float:
    """Mean |Δ code| between the two display images as each renderer writes them
    (pyrender: gamma 2.2 in its shader; pbrlab: the sRGB framebuffer)."""
    return float(np.mean(np.abs(pyr.rgb8[mask].astype(int) - srgb8[..., :3][mask].astype(int))))


# ---------------------------------------------------------------- the figure

def _heat(rel: np.ndarray, mask: np.ndarray, full_scale: float) -> np.ndarray:
    """Relative difference as black -> red -> yellow -> white, 0 .. full_scale; grey
    outside the compared pixels."""
    t = np.clip(rel / full_scale, 0.0, 1.0)
    out = np.empty(rel.shape + (3,), np.float64)
    out[..., 0] = np.clip(3 * t, 0, 1)
    out[..., 1] = np.clip(3 * t - 1, 0, 1)
    out[..., 2] = np.clip(3 * t - 2, 0, 1)
    out = (out * 255 + 0.5).astype(np.uint8)
    out[~mask] = 48
    return out


HEATMAP_FULL_SCALE = 0.5  # relative difference shown as white


def figure(pyr: PyrenderImage, matched_linear: np.ndarray, default_linear: np.ndarray,
           default_srgb8: np.ndarray) -> np.ndarray:
    """Four panels stacked (uint8 RGBA): pyrender's output | pbrlab matched (encoded with
    pyrender's gamma 2.2) | pbrlab default (its own sRGB output) | relative linear
    difference pyrender vs pbrlab default (0 black, HEATMAP_FULL_SCALE white)."""
    h, w = pyr.rgb8.shape[:2]
    matched8 = (encode_pyrender(matched_linear[..., :3]) + 0.5).astype(np.uint8)
    theirs = decode_pyrender(pyr.rgb8)[0]
    mask = erode(pyr.coverage, 1) & erode(default_linear[..., 3] > 0, 1)
    rel = np.max(np.abs(default_linear[..., :3] - theirs) / np.maximum(theirs, RELATIVE_FLOOR), axis=-1)
    panels = [pyr.rgb8, matched8, default_srgb8[..., :3], _heat(rel, mask, HEATMAP_FULL_SCALE)]
    gap = np.full((2, w, 3), 255, np.uint8)
    stacked = np.concatenate([x for p in panels for x in (p, gap)][:-1], axis=0)
    return np.concatenate([stacked, np.full(stacked.shape[:2] + (1,), 255, np.uint8)], axis=-1)


# ---------------------------------------------------------------- one run, all figures

def crosscheck(backend: str, size=DEFAULT_SIZE) -> dict:
    """Render everything on one backend (pbrlab's context and pyrender's platform) and
    measure: pyrender vs the library composition (all terms and each switch alone at
    pbrlab's value), vs the renderer's nearest selectors, vs pbrlab's defaults."""
    from ...gpu import gl
    from ...render.renderer import render_scene
    from ...importers.loader import parse_scene

    ctx = gl.shared_context(backend)
    base = grid_scene(size)
    pyr = render_pyrender(base, backend)
    matched = render_pbrlab_terms(base, ctx)
    mask = comparison_mask(pyr, matched)
    results = {"backend": backend, "pyrender_info": pyr.info, "pbrlab_info": gl.context_info(ctx),
               "pyrender": pyr, "matched": matched, "mask": mask,
               "matched_agreement": agreement(pyr, matched, mask), "switch_off": {}}
    for name in TERM_SWITCHES:
        one_off = render_pbrlab_terms(base, ctx, dict(PYRENDER_TERMS, **{name: 0}))
        results["switch_off"][name] = agreement(pyr, one_off, mask)
    selectors = render_scene(parse_scene(grid_scene(size, NEAREST_SELECTORS)), ctx)
    results["selectors"] = selectors.linear
    results["selectors_agreement"] = agreement(pyr, selectors.linear, mask)
    results["selectors_vs_composition"] = float(np.max(np.abs(
        selectors.linear[..., :3] - render_pbrlab_terms(base, ctx, PBRLAB_SELECTOR_TERMS)[..., :3])[mask]))
    default = render_scene(parse_scene(grid_scene(size)), ctx)
    results["default"] = default
    results["default_agreement"] = agreement(pyr, default.linear, mask)
    results["default_code_difference"] = mean_display_code_difference(pyr, default.srgb8, mask)
    results["default_code_difference_gamma22"] = float(np.mean(np.abs(
        (encode_pyrender(default.linear[..., :3][mask]) + 0.5).astype(int) - pyr.rgb8[mask].astype(int))))
    results["matched_code_difference"] = float(np.mean(np.abs(
        (encode_pyrender(matched[..., :3][mask]) + 0.5).astype(int) - pyr.rgb8[mask].astype(int))))
    return results


def report(results: dict) -> str:
    lines = [f"backend {results['backend']}: pyrender on {results['pyrender_info']['GL_RENDERER']}, "
             f"pbrlab on {results['pbrlab_info']['GL_RENDERER']}",
             f"  matched (library terms, pyrender's form): {results['matched_agreement'].summary()}",
             f"    mean |d code| (both gamma 2.2): {results['matched_code_difference']:.3f}"]
    for name, a in results["switch_off"].items():
        lines.append(f"  matched but {name}=0 ({TERM_SWITCHES[name]} -> pbrlab's): "
                     f"rel median {a.rel_median:.3g} p99 {a.rel_p99:.3g} max {a.rel_max:.3g}, worst excess "
                     f"{a.code_excess_max:.2f} code")
    a = results["selectors_agreement"]
    lines.append(f"  renderer, nearest selectors {NEAREST_SELECTORS}: rel median {a.rel_median:.3g} "
                 f"p99 {a.rel_p99:.3g} max {a.rel_max:.3g}; vs the composition with every switch "
                 f"at pbrlab's form: max abs {results['selectors_vs_composition']:.3g}")
    a = results["default_agreement"]
    lines.append(f"  pbrlab default (high tier): rel median {a.rel_median:.3g} p99 {a.rel_p99:.3g} "
                 f"max {a.rel_max:.3g}; mean |d code| of the display images {results['default_code_difference']:.2f} "
                 f"({results['default_code_difference_gamma22']:.2f} with pbrlab's radiance encoded by pyrender's "
                 f"gamma 2.2: the rest is sRGB vs gamma 2.2)")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="pyrender cross-check (worker entry point)")
    parser.add_argument("--worker", nargs=3, metavar=("PLATFORM", "SCENE_JSON", "OUT_NPZ"), required=True)
    args = parser.parse_args(argv)
    _worker(*args.worker)
    return 0


if __name__ == "__main__":
    sys.exit(main())
