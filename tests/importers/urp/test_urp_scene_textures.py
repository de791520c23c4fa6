"""URP's scene-texture includes and Core RP names (issue 34): the DeclareDepthTexture.hlsl
stand-in reads the harness's real depth pre-pass (render/camera_textures.py), and Core RP's
Macros.hlsl constants and TransformWorldToViewDir(dir, doNormalize) exist.

Scene (as tests/importers/unity/test_deferred_path.py): the corpus scene's camera looking at a
ray-traced unit sphere whose material is the shader under test; the depth pre-pass traces that
sphere exactly. Checked on the pixels whose centre ray meets the float64 sphere at least
SILHOUETTE_MARGIN inside its rim.
"""

from __future__ import annotations

import math
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.depth_range import scene_frame
from pbrlab.render.renderer import render_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "unity"))
from sphere_depth import SILHOUETTE_MARGIN, depth_bound, rendered_sphere, sphere_hits  # noqa: E402

LANGUAGES = ("glsl", "hlsl")
SUN = {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}

_URP_PASS = """
Shader "t/%(name)s" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            %(include)s
            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target {
                %(body)s
            }
            ENDHLSL
        }
    }
}
"""

# SampleSceneDepth at the pixel's screen uv, LoadSceneDepth at its integer coordinates.
DEPTH_SHADER = _URP_PASS % {
    "name": "urp depth",
    "include": '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareDepthTexture.hlsl"',
    "body": """float raw = SampleSceneDepth(GetNormalizedScreenSpaceUV(IN.positionCS));
                float loaded = LoadSceneDepth(uint2(IN.positionCS.xy));
                return float4(Linear01Depth(raw, _ZBufferParams), LinearEyeDepth(raw, _ZBufferParams),
                              LinearEyeDepth(loaded, _ZBufferParams), 1.0);""",
}

# Core RP's constants and TransformWorldToViewDir's two forms (the view rotation keeps length).
NAMES_SHADER = _URP_PASS % {
    "name": "urp core names",
    "include": "",
    "body": """float3 d = float3(1.0, 2.0, 3.0);
                return float4(INV_TWO_PI + 10.0 * HALF_PI, FOUR_PI + INV_FOUR_PI + INV_HALF_PI,
                              length(TransformWorldToViewDir(d, true)) + 10.0 * length(TransformWorldToViewDir(d, false)),
                              1.0);""",
}


def _scene(shader_text: str, tmp_path):
    shader = tmp_path / "t.shader"
    shader.write_text(textwrap.dedent(shader_text))
    data = corpus.scene_for(shader)
    data.pop("environment")
    data["lights"] = [SUN]
    data["objects"] = [{"sphere": {"center": [0.0, 0.0, 0.0], "radius": 1.0}, "material": "m"}]
    return parse_scene(data, origin="urp scene-texture test scene", base=shader.parent)


@pytest.mark.parametrize("language", LANGUAGES)
def test_scene_depth_is_ray_sphere_depth(tmp_path, language):
    """Linear01Depth(SampleSceneDepth(uv), _ZBufferParams) = eye depth / far of the float64
    ray-sphere hit; LinearEyeDepth of SampleSceneDepth and of LoadSceneDepth = eye depth. The
    bound is test_deferred_path.py's (the same texture, the same float32 chain): the window depth
    z is stored in float32 after a few roundings (K_DEPTH_ULPS = 6 units of 2^-24: clip product,
    divide, * 0.5 + 0.5, store, and the ray's float32 error through the depth), and 1/e is affine
    in z with slope (1/near - 1/far), so e moves by e^2 (1/near - 1/far) dz; plus 8 ulp of e for
    LinearEyeDepth's own float32 arithmetic. Control: the neighbouring pixel's depth fails it."""
    check_sphere_depths(_scene(DEPTH_SHADER, tmp_path), language)


def check_sphere_depths(scene, language: str) -> None:
    """The pass's red is Linear01Depth (eye depth / far) of the float64 ray-sphere hit, its green
    and blue two eye depths, within depth_bound on every covered pixel; control: the
    neighbouring pixel's depth fails it."""
    frame = scene_frame(scene)
    image, covered, eye = rendered_sphere(scene, frame, language)
    bound = depth_bound(eye, frame)
    err01 = np.abs(image[..., 0] - eye / frame.far)
    assert (err01[covered] <= (bound / frame.far)[covered]).all(), (err01 / bound * frame.far)[covered].max()
    for channel in (1, 2):
        err = np.abs(image[..., channel] - eye)
        assert (err[covered] <= bound[covered]).all(), (channel, (err / bound)[covered].max())
    shifted = np.abs(np.roll(image[..., 2], 1, axis=0) - eye)  # control: the neighbouring pixel's depth
    assert (shifted[covered] > bound[covered]).mean() > 0.9


@pytest.mark.parametrize("language", LANGUAGES)
def test_core_rp_constants_and_view_direction(tmp_path, language):
    """INV_TWO_PI + 10 HALF_PI, FOUR_PI + INV_FOUR_PI + INV_HALF_PI against float64 pi, and
    |TransformWorldToViewDir(d, true)| + 10 |TransformWorldToViewDir(d, false)| = 1 + 10 |d|
    (the view's rotation keeps length). Bound: float32 rounding of sums near 16 and 38, 4 ulp
    (2^-24 relative each) of the result; the constants carry 11-12 digits, below that. Control:
    the unnormalized form alone (10 |d| + |d|) fails it."""
    image = render_scene(_scene(NAMES_SHADER, tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 1000
    expected = np.array([1 / (2 * math.pi) + 10 * math.pi / 2,
                         4 * math.pi + 1 / (4 * math.pi) + 2 / math.pi,
                         1.0 + 10.0 * math.sqrt(14.0)])
    bound = 4 * 2.0 ** -24 * np.abs(expected) * 4  # 4 ulp of each sum's float32 terms (up to 4 terms)
    err = np.abs(image[..., :3][covered] - expected)
    assert (err <= bound).all(), (err / bound).max(axis=0)
    wrong = 11.0 * math.sqrt(14.0)  # control: no normalization
    assert abs(wrong - expected[2]) > bound[2]


# SampleSceneColor: a URP plane over the whole view (ZTest Always, seen straight down, as
# test_deferred_path.py's blit scene) over a pbrlab sphere drawn before it;
# the plane shows 2 SampleSceneColor(uv) + 0.25 in r, g and LoadSceneColor in b.
OPAQUE_SHADER = (_URP_PASS % {
    "name": "urp opaque",
    "include": '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareOpaqueTexture.hlsl"',
    "body": """float3 c = SampleSceneColor(GetNormalizedScreenSpaceUV(IN.positionCS));
                float3 loaded = LoadSceneColor(uint2(IN.positionCS.xy));
                return float4(2.0 * c.rg + 0.25, loaded.b, 1.0);""",
}).replace('Tags { "LightMode" = "UniversalForward" }', 'Tags { "LightMode" = "UniversalForward" }\n            ZTest Always')
SCREEN_DISTANCE = 3.0
SCREEN_FOV_DEG = 40.0


def _opaque_scene(tmp_path, with_plane: bool, plane_shader: str = OPAQUE_SHADER):
    shader = tmp_path / "opaque.shader"
    shader.write_text(textwrap.dedent(plane_shader))
    side = 2 * SCREEN_DISTANCE * np.tan(np.radians(SCREEN_FOV_DEG / 2))
    objects = [{"sphere": {"center": [0.0, 0.0, 0.0], "radius": 0.6}, "material": "s"}]  # drawn first
    if with_plane:
        objects.append({"mesh": {"primitive": "plane", "size": float(side)},
                        "transform": {"translate": [0.0, -1.0, 0.0]}, "material": "m"})
    data = {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, -1.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": SCREEN_FOV_DEG, "size": [64, 64]},
        "lights": [SUN],
        "materials": {"m": {"surface": str(shader)}, "s": {"albedo": [0.5, 0.3, 0.2], "smoothness": 0.7}},
        "objects": objects,
    }
    return parse_scene(data, origin="urp opaque-texture test scene", base=shader.parent)


@pytest.mark.parametrize("language", LANGUAGES)
def test_scene_color_is_the_opaque_copy(tmp_path, language):
    """SampleSceneColor / LoadSceneColor read the copy of the target drawn before the plane (a
    GrabPass's copy: a float blit, exact), so the plane shows 2 L + 0.25 in r and g and L in b,
    where L is the render of the sphere alone. At a pixel centre the bilinear sample's weights
    are exactly (1, 0) (uv = (x + 0.5) / 64 is exact in float32), so the only error is the
    float32 rounding of 2 L + 0.25: 1 ulp, bounded by 2^-23 of the value. Control: the sphere
    image one pixel down fails that bound on the sphere's lit pixels."""
    alone = render_scene(_opaque_scene(tmp_path, False), language=language).linear.astype(np.float64)
    image = render_scene(_opaque_scene(tmp_path, True), language=language).linear.astype(np.float64)
    expected = np.concatenate([2 * alone[..., :2] + 0.25, alone[..., 2:3]], axis=-1)
    bound = 2.0 ** -23 * np.maximum(np.abs(expected), 2.0 ** -10)
    sphere = alone[..., 3] > 0
    assert sphere.sum() > 300 and (alone[..., :3][sphere].max(axis=-1) > 0.01).mean() > 0.5  # lit, not black
    assert (image[..., 3] > 0).all()
    err = np.abs(image[..., :3] - expected)
    assert (err <= bound).all(), (err / bound).max()
    shifted = np.concatenate([2 * np.roll(alone, 1, axis=0)[..., :2] + 0.25, np.roll(alone, 1, axis=0)[..., 2:3]], -1)
    lit = sphere & (alone[..., :3].max(axis=-1) > 0.01)
    assert (np.abs(image[..., :3] - shifted) > bound)[lit].any(axis=-1).mean() > 0.9


# URP's main-light globals against the scene's first directional light.
MAIN_LIGHT_SHADER = _URP_PASS % {
    "name": "urp main light",
    "include": '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"',
    "body": """Light main = GetMainLight();
                float off = abs(_MainLightColor.r - main.color.r) + abs(_MainLightPosition.w);
                return float4(_MainLightPosition.xyz * 0.25 + 0.5 + float3(off, 0.0, 0.0), 1.0);""",
}


@pytest.mark.parametrize("language", LANGUAGES)
def test_main_light_globals_are_the_first_directional_light(tmp_path, language):
    """_MainLightPosition.xyz = the unit direction towards the sun (float64 -normalize(direction)),
    w 0, and _MainLightColor = GetMainLight().color (any difference, or a w, is added to red). Bound: the
    direction's float32 normalization and the * 0.25 + 0.5, a few ulp of 0.5..0.75 (4 * 2^-24 *
    0.75 = 1.8e-7 per ulp counted, 8 counted). Control: the direction not negated (towards the
    light, not from it) fails."""
    image = render_scene(_scene(MAIN_LIGHT_SHADER, tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 1000
    towards = -np.asarray(SUN["direction"], np.float64) / np.linalg.norm(SUN["direction"])
    bound = 8 * 2.0 ** -24
    err = np.abs(image[..., :3][covered] - (towards * 0.25 + 0.5))
    assert (err <= bound).all(), err.max()
    wrong = np.abs(image[..., :3][covered] - (-towards * 0.25 + 0.5))  # control: the light's own direction
    assert (wrong > bound).any(axis=-1).all()


COMMON_SHADER = _URP_PASS % {
    "name": "urp common functions",
    "include": "",
    "body": """float3 grey = Desaturate(float3(0.2, 0.5, 0.8), 0.25);
                return float4(grey.r, grey.b, Remap01(0.6, 2.0, 0.4), 1.0);""",
}


@pytest.mark.parametrize("language", LANGUAGES)
def test_desaturate_and_remap01(tmp_path, language):
    """Desaturate((0.2, 0.5, 0.8), 0.25) = mean 0.5 + deviation / 4 = (0.425, 0.5, 0.575);
    Remap01(0.6, 2, 0.4) = saturate(1.2 - 0.4) = 0.8. Bound: a few float32 roundings of values
    below 1, 4 ulp (4 * 2^-24). Control: desaturating towards Rec. 709 luminance (0.4758)
    instead of the mean gives r 0.407, outside the bound."""
    image = render_scene(_scene(COMMON_SHADER, tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 1000
    expected = np.array([0.425, 0.575, 0.8])
    bound = 4 * 2.0 ** -24
    err = np.abs(image[..., :3][covered] - expected)
    assert (err <= bound).all(), err.max()
    luminance = 0.2126 * 0.2 + 0.7152 * 0.5 + 0.0722 * 0.8
    assert abs(luminance + (0.2 - luminance) * 0.25 - expected[0]) > bound  # control


# SampleSceneNormals at the pixel's screen uv (x, y) and LoadSceneNormals at its integer
# coordinates (z), as rgb = n * 0.25 + 0.5 (the pass's alpha is not the program's: covered pixels).
NORMALS_SHADER = _URP_PASS % {
    "name": "urp normals",
    "include": '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareNormalsTexture.hlsl"',
    "body": """float3 n = SampleSceneNormals(GetNormalizedScreenSpaceUV(IN.positionCS));
                float3 loaded = LoadSceneNormals(uint2(IN.positionCS.xy));
                return float4(float3(n.xy, loaded.z) * 0.25 + 0.5, 1.0);""",
}


@pytest.mark.parametrize("language", LANGUAGES)
def test_scene_normals_are_the_sphere_world_normals(tmp_path, language):
    """SampleSceneNormals (x, y) and LoadSceneNormals (z) = the unit world normal (signed, URP's
    DepthNormals encoding) of the float64 ray-sphere hit at the pixel centre: the sphere's own
    (it is opaque, so in the pre-pass, which traces it). Bound: the texture is half float
    (camera_textures.py), 10 stored mantissa bits, so a component in [0.5, 1) is within one ulp,
    2^-11 (GL leaves the float-to-half rounding to the implementation: truncation costs up to a
    whole ulp), plus the traced normal's float32 error (the hit's t from a quadratic whose
    discriminant is >= 1 - 0.95^2 inside the margin: a few 2^-24 of |o|^2 = 16 through
    1 / (2 sqrt(0.0975)), about 2^-17; counted as 2^-14); after * 0.25: (2^-11 + 2^-14) / 4.
    Control: the built-in deferred path's encoding (n * 0.5 + 0.5, which a built-in program reads
    under the same name) fails it."""
    scene = _scene(NORMALS_SHADER, tmp_path)
    frame = scene_frame(scene)
    d, t, inside = sphere_hits(frame)
    image = render_scene(scene, language=language).linear.astype(np.float64)[..., :3]
    assert inside.sum() > 1000
    normal = np.asarray(frame.position, np.float64) + t[..., None] * d  # the unit sphere's hit = its normal
    bound = (2.0 ** -11 + 2.0 ** -14) / 4
    err = np.abs(image - (normal * 0.25 + 0.5))[inside]
    assert (err <= bound).all(), err.max(axis=0) / bound
    builtin = (normal * 0.5 + 0.5) * 0.25 + 0.5  # control: the built-in pipeline's RT2 encoding
    assert (np.abs(image - builtin)[inside] > bound).any(axis=-1).mean() > 0.9


# The program declares the depth texture itself (no DeclareDepthTexture.hlsl) and reads it with
# Core RP's three- and four-argument depth macros.
OWN_DEPTH_SHADER = _URP_PASS % {
    "name": "urp own depth",
    "include": "TEXTURE2D(_CameraDepthTexture); SAMPLER(sampler_CameraDepthTexture);",
    "body": """float2 uv = GetNormalizedScreenSpaceUV(IN.positionCS);
                float raw = SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, sampler_CameraDepthTexture, uv);
                float lod = SAMPLE_DEPTH_TEXTURE_LOD(_CameraDepthTexture, sampler_CameraDepthTexture, uv, 0.0);
                return float4(Linear01Depth(raw, _ZBufferParams), LinearEyeDepth(raw, _ZBufferParams),
                              LinearEyeDepth(lod, _ZBufferParams), 1.0);""",
}


@pytest.mark.parametrize("language", LANGUAGES)
def test_own_depth_texture_declaration_reads_the_pre_pass(tmp_path, language):
    """A program's own TEXTURE2D(_CameraDepthTexture) read by SAMPLE_DEPTH_TEXTURE(t, s, uv) and
    SAMPLE_DEPTH_TEXTURE_LOD(t, s, uv, 0) (Core RP's forms; UnityCG's take two arguments, which
    the built-in prelude's macros refused as too many) is bound to the same depth pre-pass:
    Linear01Depth and LinearEyeDepth of it = the float64 ray-sphere eye depth (/ far), within
    test_scene_depth_is_ray_sphere_depth's bound (the same texture and float32 chain). Control:
    the neighbouring pixel's depth fails it."""
    scene = _scene(OWN_DEPTH_SHADER, tmp_path)
    frame = scene_frame(scene)
    image, covered, eye = rendered_sphere(scene, frame, language)
    bound = depth_bound(eye, frame)
    expected = np.stack([eye / frame.far, eye, eye], axis=-1)
    err = np.abs(image[..., :3] - expected)[covered]
    limit = np.stack([bound / frame.far, bound, bound], axis=-1)[covered]
    assert (err <= limit).all(), (err / limit).max(axis=0)
    shifted = np.abs(np.roll(image[..., 2], 1, axis=0) - eye)  # control: the neighbouring pixel's depth
    assert (shifted[covered] > bound[covered]).mean() > 0.9


# The camera's colour target declared by the program as a Core RP sampler state and sampled with
# Cg's tex2D (a combined sampler, as FXC's compatibility mode takes it: combined_samplers.py),
# with the _TexelSize Unity sets beside it: the plane shows 2 C + 0.25 in r and g, and in b the
# texel size's x times the target's width (1).
COLOR_TARGET_SHADER = (_URP_PASS % {
    "name": "urp own colour target",
    "include": "SAMPLER(_CameraColorTexture); float4 _CameraColorTexture_TexelSize;",
    "body": """float3 c = tex2D(_CameraColorTexture, GetNormalizedScreenSpaceUV(IN.positionCS)).rgb;
                return float4(2.0 * c.rg + 0.25, _CameraColorTexture_TexelSize.x * _ScreenParams.x, 1.0);""",
}).replace('Tags { "LightMode" = "UniversalForward" }', 'Tags { "LightMode" = "UniversalForward" }\n            ZTest Always')


@pytest.mark.parametrize("language", LANGUAGES)
def test_own_color_target_sampler_reads_the_frame_so_far(tmp_path, language):
    """A program's own SAMPLER(_CameraColorTexture) read by tex2D is bound to the copy of the
    target drawn before the plane (as test_scene_color_is_the_opaque_copy: weights exactly (1, 0)
    at a pixel centre, so 1 ulp of 2 L + 0.25), and its _TexelSize.x is 1 / width (b = 1 within
    1 ulp). Control: the sphere image one pixel down fails that bound on its lit pixels; before
    combined_samplers the declaration was a sampler state, which tex2D refused in both
    languages (the sample's MirrorShader)."""
    alone = render_scene(_opaque_scene(tmp_path, False), language=language).linear.astype(np.float64)
    image = render_scene(_opaque_scene(tmp_path, True, COLOR_TARGET_SHADER), language=language)
    image = image.linear.astype(np.float64)
    expected = np.concatenate([2 * alone[..., :2] + 0.25, np.ones_like(alone[..., :1])], axis=-1)
    bound = 2.0 ** -23 * np.maximum(np.abs(expected), 2.0 ** -10)
    assert (image[..., 3] > 0).all()
    err = np.abs(image[..., :3] - expected)
    assert (err <= bound).all(), (err / bound).max()
    lit = (alone[..., 3] > 0) & (alone[..., :3].max(axis=-1) > 0.01)
    assert lit.sum() > 150
    shifted = 2 * np.roll(alone, 1, axis=0)[..., :2] + 0.25
    assert (np.abs(image[..., :2] - shifted) > bound[..., :2])[lit].any(axis=-1).mean() > 0.9
