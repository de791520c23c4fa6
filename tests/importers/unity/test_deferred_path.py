"""Unity's deferred path (issue 34): the camera's depth texture and G-buffer the harness renders
before the frame (render/camera_textures.py) and the deferred light passes that read them
(importers/unity/deferred.py, cginc/UnityDeferredLibrary.cginc, cginc/UnityGBuffer.cginc).

Scene: the corpus scene's camera (pbrlab.checking.unity_corpus.scene_for: 64x64, 40 degrees,
3.2 from the origin) looking at a ray-traced unit sphere whose material is the shader under
test; the depth pre-pass traces that sphere exactly, and the shader's own pass draws over its
tessellation (a light volume). Checked on the pixels whose centre ray meets the float64 sphere
at least SILHOUETTE_MARGIN inside its rim (the tessellation and the exact sphere differ at the
rim; there the ray-sphere depth is ill-conditioned too).

G-buffer readback, two ways: what is stored (read through a framebuffer as floats, code / 255
for the 8-bit targets, code / 1023 for RT2's 10-bit channels, RT0's and RT1's rgb decoded with
the exact sRGB curve, GL 3.3 core 8.24) for the layout check, and what a program samples
(texelFetch into a float target) for the shading check: llvmpipe's sRGB decode on sampling is
approximate (measured: code 251 decodes to 0.964414 where the curve gives 0.964686, -2.8e-4;
code 128 +3.6e-3; code 10 +2.5e-2), and the pass shades what it samples.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import moderngl
import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.gpu import gl
from pbrlab.importers.loader import parse_scene
from pbrlab.maths.camera import camera_rays
from pbrlab.maths.reference import unity_brdf
from pbrlab.render.camera_textures import CameraTextures
from pbrlab.render.depth_range import scene_frame
from pbrlab.render.renderer import render_scene
from pbrlab.scene.gbuffer_surface import DEFAULT_STANDARD_SURFACE

from sphere_depth import SILHOUETTE_MARGIN, depth_bound, rendered_sphere, sphere_hits

LANGUAGES = ("glsl", "hlsl")
ROOT = Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"
DEFERRED_SHADING = ROOT / "Internal-DeferredShading.shader"
SUN = {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}
# the ray's closest approach to the centre at most this share of the radius


def _scene(shader: Path, lights: list) -> dict:
    data = corpus.scene_for(shader)
    data.pop("environment")
    data["lights"] = lights
    data["objects"] = [{"sphere": {"center": [0.0, 0.0, 0.0], "radius": 1.0}, "material": "m"}]
    return data


def _parsed(shader: Path, lights: list):
    return parse_scene(_scene(shader, lights), origin="deferred test scene", base=shader.parent)


def _srgb_decode(c):
    c = np.asarray(c, np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _read_float(ctx, texture, components):
    fbo = ctx.framebuffer([texture])
    try:
        data = np.frombuffer(fbo.read(components=components, dtype="f4"), np.float32)
    finally:
        fbo.release()
    w, h = texture.size
    return data.reshape(h, w, components)[::-1].astype(np.float64)  # top row first


_FULLSCREEN = ("#version 330 core\nvoid main() { vec2 c = vec2(float((gl_VertexID << 1) & 2), "
               "float(gl_VertexID & 2)); gl_Position = vec4(c * 2.0 - 1.0, 0.0, 1.0); }")
_FETCH = ("#version 330 core\nuniform sampler2D s; out vec4 o;\n"
          "void main() { o = texelFetch(s, ivec2(gl_FragCoord.xy), 0); }")


def _sampled(ctx, texture):
    """``texture`` as a program reads it (texelFetch: sRGB decoded by the sampler), HxWx4, top row first."""
    w, h = texture.size
    out = ctx.texture((w, h), 4, dtype="f4")
    fbo = ctx.framebuffer([out])
    program = ctx.program(vertex_shader=_FULLSCREEN, fragment_shader=_FETCH)
    vao = ctx.vertex_array(program, [])
    try:
        fbo.use()
        ctx.viewport = (0, 0, w, h)
        ctx.disable(moderngl.DEPTH_TEST | moderngl.BLEND | moderngl.CULL_FACE)
        texture.use(0)
        program["s"] = 0
        vao.render(moderngl.TRIANGLES, vertices=3)
        data = np.frombuffer(fbo.read(components=4, dtype="f4"), np.float32)
    finally:
        for resource in (vao, program, fbo, out):
            resource.release()
    return data.reshape(h, w, 4)[::-1].astype(np.float64)


def _gbuffer(scene, stored: bool = False):
    """{"gbuffer0".."gbuffer2", "depth"}: the pre-pass of ``scene`` as a program samples it, or
    (``stored``) its stored codes, RT0's and RT1's rgb decoded with the exact sRGB curve."""
    ctx = gl.make_current(gl.shared_context())
    textures = CameraTextures(ctx, scene, scene_frame(scene))
    try:
        if stored:
            out = {f"gbuffer{i}": _read_float(ctx, t, 4) for i, t in enumerate(textures.gbuffer)}
            for i in (0, 1):
                out[f"gbuffer{i}"][..., :3] = _srgb_decode(out[f"gbuffer{i}"][..., :3])
        else:
            out = {f"gbuffer{i}": _sampled(ctx, t) for i, t in enumerate(textures.gbuffer)}
        out["depth"] = _read_float(ctx, textures.depth, 1)[..., 0]
    finally:
        textures.release()
    return out


def test_gbuffer_holds_unity_default_material_in_unity_layout():
    """RT0 (0.96, 0.96, 0.96, 1), RT1 (0.04, 0.04, 0.04, 0.5), RT2 the sphere's normal: each to
    its storage's quantisation. Bounds: RT0/RT1 rgb are sRGB 8-bit codes: one code step of the
    decoded curve around the value (GL 3.3 core, 4.1.8 lets the encode on write be approximate:
    llvmpipe stores 0.96 as code 251, where exact rounding of 250.3 gives 250; half a step
    failed); alpha a linear 8-bit code, 0.5/255;
    RT2 10-bit codes, a normal component within one code, 1/1023 * 2 (the * 2 of n * 0.5 + 0.5),
    of the float64 one (the encode to unorm may round either way: measured 0.99 code on
    llvmpipe, where half a code failed), plus the float32 trace's error (1e-5, well under a code). Control: the wrong
    surface (metallic 1) is out of those bounds."""
    scene = _parsed(DEFERRED_SHADING, [SUN])
    frame = scene_frame(scene)
    d, t, inside = sphere_hits(frame)
    g = _gbuffer(scene, stored=True)
    surface = DEFAULT_STANDARD_SURFACE
    assert surface.diffuse == pytest.approx((0.96, 0.96, 0.96)) and surface.specular == pytest.approx((0.04,) * 3)
    assert surface.smoothness == 0.5 and surface.occlusion == 1.0

    def srgb_step(linear):  # one 8-bit code step of the curve around the value, in linear
        code = np.round(np.where(linear <= 0.0031308, linear * 12.92, 1.055 * linear ** (1 / 2.4) - 0.055) * 255)
        return np.maximum(_srgb_decode((code + 1) / 255) - _srgb_decode(code / 255),
                          _srgb_decode(code / 255) - _srgb_decode((code - 1) / 255)) + 1e-12

    diffuse, specular = np.array(surface.diffuse), np.array(surface.specular)
    assert (np.abs(g["gbuffer0"][inside][:, :3] - diffuse) <= srgb_step(diffuse)).all()
    assert (np.abs(g["gbuffer1"][inside][:, :3] - specular) <= srgb_step(specular)).all()
    assert (np.abs(g["gbuffer0"][inside][:, 3] - 1.0) <= 0.5 / 255).all()
    assert (np.abs(g["gbuffer1"][inside][:, 3] - 0.5) <= 0.5 / 255 + 2.0 ** -24).all()  # 127.5 -> 128, read back in float32
    normal = frame.position + t[..., None] * d
    err = np.abs(g["gbuffer2"][..., :3] * 2 - 1 - normal)[inside]
    assert err.max() <= 2 * 1.0 / 1023 + 1e-5, err.max()
    assert not (g["depth"][inside] >= 1.0).any() and (g["depth"][~np.isfinite(t)] == 1.0).all()
    # control: a metallic surface's specular colour is its albedo (1), not 0.04
    metal = unity_brdf.diffuse_and_specular_from_metallic(np.ones(3), 1.0)[1]
    assert not (np.abs(g["gbuffer1"][inside][:, :3] - metal) <= srgb_step(metal)).any()


# Linear01Depth of the depth texture: a pass that returns it as its colour, screen uv from
# ComputeScreenPos (Unity's own way of reading a screen texture).
DEPTH_SHADER = """
Shader "t/depth01" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
        struct v2f { float4 pos : SV_POSITION; float4 screen : TEXCOORD0; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.screen = ComputeScreenPos(o.pos); return o; }
        float4 frag(v2f i) : SV_Target {
            float raw = SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, i.screen.xy / i.screen.w);
            return float4(Linear01Depth(raw), LinearEyeDepth(raw), raw, 1.0);
        }
        ENDCG
    } }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_depth_prepass_linear01_depth_is_ray_sphere_depth(tmp_path, language):
    """Linear01Depth(_CameraDepthTexture) = eye depth / far of the float64 ray-sphere hit, and
    LinearEyeDepth = eye depth. Bound (relative to the eye depth e): the texture holds window
    depth z in float32 (the trace computes it in float32 too), and 1/e is affine in z with slope
    (1/near - 1/far), so a z error dz moves e by e^2 (1/near - 1/far) dz; dz is the trace's and
    storage's float32 rounding, a few units of 2^-24 (K_DEPTH_ULPS of them: the clip product,
    its divide, the * 0.5 + 0.5 and the store, each <= 1/2 ulp of a number below 1, and the
    ray's own float32 error through the sphere's depth, below 2 ulp inside the rim). Control:
    the pass reading the texture one pixel up differs by more than that."""
    shader = tmp_path / "depth01.shader"
    shader.write_text(textwrap.dedent(DEPTH_SHADER))
    scene = _parsed(shader, [SUN])
    frame = scene_frame(scene)
    image, covered, eye = rendered_sphere(scene, frame, language)
    bound = depth_bound(eye, frame)
    err01 = np.abs(image[..., 0] - eye / frame.far)
    err_eye = np.abs(image[..., 1] - eye)
    assert (err01[covered] <= (bound / frame.far)[covered]).all(), (err01 / bound * frame.far)[covered].max()
    assert (err_eye[covered] <= bound[covered]).all(), (err_eye / bound)[covered].max()
    shifted = np.abs(np.roll(image[..., 1], 1, axis=0) - eye)  # control: the neighbouring pixel's depth
    assert (shifted[covered] > bound[covered]).mean() > 0.9


def _deferred_expected(scene, gbuffer, light):
    """BRDF1_Unity_PBS (float64: pbrlab.maths.reference.unity_brdf) of the G-buffer's surface at
    each pixel, at the float64 ray-sphere point, under ``light`` (no indirect light: the pass
    passes 0)."""
    frame = scene_frame(scene)
    d, t, inside = sphere_hits(frame)
    g0, g1, g2 = gbuffer["gbuffer0"], gbuffer["gbuffer1"], gbuffer["gbuffer2"]
    normal = g2[..., :3] * 2 - 1
    normal = normal / np.linalg.norm(normal, axis=-1, keepdims=True)
    spec = g1[..., :3]
    direction = np.asarray(light["direction"], np.float64)
    light_dir = -direction / np.linalg.norm(direction)
    colour = np.asarray(light["color"], np.float64) * light["intensity"]
    expected = unity_brdf.brdf1_unity_pbs(g0[..., :3], spec, 1.0 - spec.max(axis=-1), g1[..., 3], normal, -d,
                                          colour, light_dir, np.zeros(3), np.zeros(3))
    return expected, inside


# Float32 bound of BRDF1 at a pixel, relative to the pixel's value (the derivation in the
# test's docstring): BRDF1_FLOAT32_RELATIVE, plus BRDF1_FLOAT32_ABSOLUTE where the value is near 0.
BRDF1_FLOAT32_RELATIVE = 2e-5
BRDF1_FLOAT32_ABSOLUTE = 1e-6


@pytest.mark.parametrize("language", LANGUAGES)
def test_deferred_shading_is_brdf1_of_the_gbuffer_surface(language):
    """Internal-DeferredShading under the directional light = BRDF1 of the G-buffer's surface at
    each pixel. Inputs the pass and the float64 side share exactly: the G-buffer texels (read
    back), the light. Inputs it rebuilds: the point (from the depth texture, e^2/near * dz:
    4.4e-7 of e at near 0.3, moving v by as much in angle) and v. Float32 error of BRDF1: its
    worst-conditioned term is GGX's d = nh^2 (a^2 - 1) + 1 >= a^2 = (1 - 0.502)^4 = 0.0615, so
    d's relative error is at most a few u / a^2 = 3 * 6e-8 / 0.0615 = 3e-6 and D's (1/d^2) twice
    that; with the other terms (~20 u = 1.2e-6) and v's direction (D's relative sensitivity to
    the half vector, 4 nh (1 - a^2) sin / d <= 33 per radian, times 4.4e-7) the sum is below
    1.5e-5: BRDF1_FLOAT32_RELATIVE = 2e-5, BRDF1_FLOAT32_ABSOLUTE for values near 0 (u times
    the light's 1). Controls: the flipped normal, and another light, fail at most pixels."""
    scene = _parsed(DEFERRED_SHADING, [SUN])
    gbuffer = _gbuffer(scene)
    expected, inside = _deferred_expected(scene, gbuffer, SUN)
    image = render_scene(scene, language=language).linear.astype(np.float64)[..., :3]
    covered = inside & (gbuffer["depth"] < 1.0)
    assert covered.sum() > 1000
    bound = BRDF1_FLOAT32_RELATIVE * np.abs(expected) + BRDF1_FLOAT32_ABSOLUTE
    err = np.abs(image - expected)
    assert (err[covered] <= bound[covered]).all(), (err / bound)[covered].max()
    # controls: the G-buffer's normal flipped; the light from elsewhere
    flipped = dict(gbuffer, gbuffer2=np.concatenate([1.0 - gbuffer["gbuffer2"][..., :3], gbuffer["gbuffer2"][..., 3:]], -1))
    wrong_normal, _ = _deferred_expected(scene, flipped, SUN)
    other = dict(SUN, direction=[0.6, -0.6, -0.5])
    wrong_light, _ = _deferred_expected(scene, gbuffer, other)
    for wrong in (wrong_normal, wrong_light):
        assert (np.abs(image - wrong)[covered].max(axis=-1) > bound[covered].max(axis=-1)).mean() > 0.5


@pytest.mark.parametrize("language", LANGUAGES)
def test_deferred_shading_adds_each_light(language):
    """Two lights (the corpus scene's directional and point light): the image is the sum of the
    two one-light images (Blend One One per light, as Unity's light passes add onto the light
    buffer), to the float32 sum's rounding (2 u of the sum). Control: the directional image
    alone is not it."""
    point = {"type": "point", "position": [1.5, 1.0, 2.0], "color": [1, 1, 1], "intensity": 2.0, "range": 10}
    images = {}
    for key, lights in (("sun", [SUN]), ("point", [point]), ("both", [SUN, point])):
        images[key] = render_scene(_parsed(DEFERRED_SHADING, lights), language=language).linear.astype(np.float64)
    both, summed = images["both"][..., :3], images["sun"][..., :3] + images["point"][..., :3]
    assert (images["point"][..., :3] > 0).mean() > 0.2
    bound = 2 * 2.0 ** -24 * np.abs(summed) + 1e-12
    assert (np.abs(both - summed) <= bound).all()
    assert (images["both"][..., 3] <= 1.0).all()  # the coverage, not a sum of alphas
    assert (np.abs(both - images["sun"][..., :3]) > bound).any()


COMBINE_DEPTH_NORMALS = ROOT / "Internal-CombineDepthNormals.shader"
STEREO_SCALE = 1.7777  # Unity's manual, "Camera's depth texture": the view normal's stereographic scale


# A screen-filling square (the pass is a full-screen blit: it reads the G-buffer at its mesh's
# uv, ZTest Always): the plane primitive (u along +x, v along -z) seen straight down from
# SCREEN_DISTANCE with up -z, its side 2 d tan(fov / 2), so a pixel centre's uv is its screen
# uv; in front of it a ray-traced pbrlab sphere, which the G-buffer shows (drawn before the
# square, which then covers it: ZTest Always).
SCREEN_DISTANCE = 3.0
SCREEN_FOV_DEG = 40.0


def _blit_scene(shader: Path):
    side = 2 * SCREEN_DISTANCE * np.tan(np.radians(SCREEN_FOV_DEG / 2))
    data = {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, -1.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": SCREEN_FOV_DEG, "size": [64, 64]},
        "lights": [SUN],
        "materials": {"m": {"surface": str(shader)}, "s": {"albedo": [0.5, 0.3, 0.2], "smoothness": 0.7}},
        "objects": [{"sphere": {"center": [0.0, 0.0, 0.0], "radius": 0.6}, "material": "s"},  # drawn first
                    {"mesh": {"primitive": "plane", "size": float(side)}, "transform": {"translate": [0.0, -1.0, 0.0]},
                     "material": "m"}],
        "render": {"quality": "high", "tonemap": "khronos_neutral"},
    }
    return parse_scene(data, origin="deferred blit scene", base=shader.parent)


@pytest.mark.parametrize("language", LANGUAGES)
def test_combine_depth_normals_encodes_the_gbuffer_normal_in_view_space(language):
    """Internal-CombineDepthNormals (Unity builds _CameraDepthNormalsTexture from the G-buffer
    with it: _CameraNormalsTexture is RT2): rg = the stereographic encoding of the sampled RT2
    normal taken into view space (unity_WorldToCamera, z negated: +z towards the camera), b =
    EncodeFloatRG's high part of Linear01Depth (a is the target's coverage here). float64 side
    from the sampled texels and the float64 ray-sphere depth. Bounds: rg is a rotation, a
    divide by 1 + n.z in [1, 2] and a scale: well-conditioned, 16 u of float32 (1e-6); b is
    v - frac(255 v) / 255 with v's error (2.6e-6 of the eye depth, the depth test's bound, over
    far) carried once into each term: 2 * 255 / 255 times that, on pixels whose frac(255 v) is
    not within 1e-3 of a wrap (where the low byte jumps by a whole code). Control: the world
    normal, not the view one, fails."""
    scene = _blit_scene(COMBINE_DEPTH_NORMALS)
    frame = scene_frame(scene)
    d = camera_rays(frame)
    o = np.asarray(frame.position, np.float64)
    b = d @ o
    closest2 = o @ o - b * b
    on_sphere = closest2 <= 0.36
    t_sphere = -b - np.sqrt(np.maximum(0.36 - closest2, 0.0))
    eye = np.where(on_sphere, t_sphere * (d @ frame.forward), SCREEN_DISTANCE)
    rim = np.abs(np.sqrt(closest2) - 0.6) < 0.05  # the sphere's rim: a pixel's depth is ill-conditioned
    inside = ~rim
    gbuffer = _gbuffer(scene)
    image = render_scene(scene, language=language).linear.astype(np.float64)
    covered = inside & (image[..., 3] > 0) & (gbuffer["depth"] < 1.0)
    assert covered.mean() > 0.7 and (covered & on_sphere).sum() > 500
    world = gbuffer["gbuffer2"][..., :3] * 2 - 1   # unnormalised, as the shader takes it
    rotation = np.asarray(frame.view, np.float64)[:3, :3]  # rows right, up, -forward
    view = world @ rotation.T                       # (n.right, n.up, -n.forward): Unity's, z negated

    def encode(n):
        return n[..., :2] / (1.0 + n[..., 2:3]) / STEREO_SCALE * 0.5 + 0.5

    err = np.abs(image[..., :2] - encode(view))[covered]
    assert err.max() <= 1e-6, err.max()
    depth01 = eye / frame.far
    low = np.mod(255.0 * depth01, 1.0)
    high = depth01 - low / 255.0
    away = covered & (np.minimum(low, 1.0 - low) > 1e-3)
    bound = 2 * 2.6e-6 * eye / frame.far + 1e-6
    assert away.sum() > 1000
    assert (np.abs(image[..., 2] - high) <= bound)[away].all(), (np.abs(image[..., 2] - high) / bound)[away].max()
    wrong = np.abs(image[..., :2] - encode(world))[covered]  # control
    assert (wrong.max(axis=-1) > 1e-6).mean() > 0.9


def test_a_transparent_queue_is_not_in_the_depth_texture(tmp_path):
    """Unity's depth texture holds the opaque queues (<= 2500): the depth pass's shader tagged
    Queue Transparent reads the far plane everywhere (Linear01Depth 1, to float32 rounding of
    1 / (x + y) = 1), where its Geometry twin (the depth test above) reads its own sphere."""
    shader = tmp_path / "depth01_transparent.shader"
    shader.write_text(textwrap.dedent(DEPTH_SHADER).replace("SubShader {", 'SubShader { Tags { "Queue"="Transparent" }', 1))
    image = render_scene(_parsed(shader, [SUN]), language="glsl").linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 1000
    assert (np.abs(image[..., 0][covered] - 1.0) <= 4 * 2.0 ** -24).all()


def test_a_textured_material_in_the_gbuffer_is_refused_by_name(tmp_path):
    """The G-buffer takes a pbrlab material's constant values: a textured one in a scene whose
    shader reads the G-buffer is refused, naming the object and the material."""
    from pbrlab.foundation.errors import PbrlabError
    image = Path(__file__).resolve().parents[3] / "scenes" / "assets" / "bricks_albedo.png"
    data = _scene(DEFERRED_SHADING, [SUN])
    data["materials"]["t"] = {"albedo": [1, 1, 1], "textures": {"albedo": str(image)}}
    data["objects"].append({"sphere": {"center": [0.0, 0.0, -3.0], "radius": 0.5}, "material": "t"})
    scene = parse_scene(data, origin="deferred test scene", base=DEFERRED_SHADING.parent)
    with pytest.raises(PbrlabError, match=r"objects\[1\].*material 't'.*textures"):
        render_scene(scene, language="glsl")


def test_deferred_shading_skips_the_ldr_decode_pass_with_a_note():
    """Internal-DeferredShading's second pass decodes the LDR light buffer (_LightBuffer), which
    Unity draws only without HDR: skipped, saying so (the harness's target is float)."""
    with pytest.warns(UserWarning, match=r"skipped: it decodes the LDR light buffer \(_LightBuffer\)"):
        render_scene(_parsed(DEFERRED_SHADING, [SUN]), language="glsl")


DEFERRED_REFLECTIONS = ROOT / "Internal-DeferredReflections.shader"
# A constant environment of colours a float16 cube stores exactly (the prefiltered mips of a
# constant are that constant): the probe's radiance is known in every direction and mip.
CONSTANT_SKY = [0.75, 0.5, 0.25]


@pytest.mark.parametrize("language", LANGUAGES)
def test_deferred_reflections_is_brdf1_indirect_specular_of_the_gbuffer(language):
    """Internal-DeferredReflections, drawn for the default reflection (the scene's environment:
    an unbounded box, falloff 1 in alpha), = BRDF1's indirect specular term of the sampled
    G-buffer surface with the probe's radiance times its occlusion (diffuse colour 0, no light):
    surfaceReduction * env * FresnelLerp(specColor, grazingTerm, n.v). Bound: that term is a
    few float32 products, pow5 and a lerp (about 20 u = 1.2e-6 relative), the probe exact, v
    off by the reconstructed point's 4.4e-7: 4e-6 relative. Control: twice the sky fails."""
    data = _scene(DEFERRED_REFLECTIONS, [SUN])
    data["environment"] = {"color": CONSTANT_SKY}
    scene = parse_scene(data, origin="deferred test scene", base=DEFERRED_REFLECTIONS.parent)
    frame = scene_frame(scene)
    d, t, inside = sphere_hits(frame)
    g = _gbuffer(scene)
    normal = g["gbuffer2"][..., :3] * 2 - 1
    normal = normal / np.linalg.norm(normal, axis=-1, keepdims=True)
    spec = g["gbuffer1"][..., :3]

    def expected(sky):
        return unity_brdf.brdf1_unity_pbs(np.zeros(3), spec, 1.0 - spec.max(axis=-1), g["gbuffer1"][..., 3], normal,
                                          -d, np.zeros(3), np.array([0.0, 1.0, 0.0]), np.zeros(3),
                                          np.asarray(sky, np.float64) * g["gbuffer0"][..., 3:4])

    image = render_scene(scene, language=language).linear.astype(np.float64)
    covered = inside & (g["depth"] < 1.0)
    assert covered.sum() > 1000
    want = expected(CONSTANT_SKY)
    bound = 4e-6 * np.abs(want) + 1e-7
    err = np.abs(image[..., :3] - want)
    assert (err[covered] <= bound[covered]).all(), (err / bound)[covered].max()
    assert (image[..., 3][covered] == 1.0).all()  # the falloff of an unbounded probe
    wrong = np.abs(image[..., :3] - expected(2 * np.asarray(CONSTANT_SKY)))
    assert (wrong[covered].max(axis=-1) > bound[covered].max(axis=-1)).mean() > 0.9
