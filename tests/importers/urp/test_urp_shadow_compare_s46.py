"""URP's comparison samplers in both languages (issue 34, session 46): TEXTURE2D_SHADOW,
SAMPLER_CMP, SAMPLE_TEXTURE2D_SHADOW, TEXTURE2D_SHADOW_PARAM/ARGS, Direct3D 11's
SamplerComparisonState with Texture2D.SampleCmpLevelZero, and URP's main light shadow map
(_MainLightShadowmapTexture, which pbrlab binds as URP's empty shadow map: importers/unity/
shadow_maps.py).

Scene (test_urp_scene_textures.py's blit scene): tests/importers/urp/shaders/
urp_shadow_compare.shader on a plane filling a 64 x 64 view seen straight down; each pixel's
screen uv is its centre, u = (x + 0.5) / 64. The material's map is a 2 x 1 PNG whose red codes
64 and 192 are the stored depths d = (64/255, 192/255).

Unity's semantics (Microsoft's HLSL reference, "SampleCmp"; OpenGL 3.3 core 3.8.16, "Texture
Comparison Modes"): each texel the bilinear filter reads is compared with the reference z, 1 where
it passes, and the 0/1 results are filtered. The comparison: pbrlab compiles for
SHADER_API_GLCORE, where Unity's depth is not reversed (UNITY_REVERSED_Z 0) and its shadow maps
compare LessEqual, lit where z <= stored; Direct3D-like targets reverse both z and the stored
depth and compare GreaterEqual, the same result. So the float64 reference is the bilinear
(clamp-to-edge) interpolation of [z <= d_k] at u.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.foundation.images import write_png
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
SHADER = Path(__file__).resolve().parent / "shaders" / "urp_shadow_compare.shader"
SIZE = 64
CODES = (64, 192)  # the map's red codes: stored depths code / 255
STEPS = 16  # the shader's _Steps default
# The bilinear weight's precision: OpenGL leaves it to the implementation; Direct3D 11, Unity's
# reference platform, guarantees 8 bits of subtexel precision, so a filtered 0/1 result may sit up
# to one weight step, 2^-8, from the exact interpolation (float32 rounding of a value in [0, 1],
# 2^-24, is below it). The 24-bit depth texture's rounding of d (2^-25) cannot flip a comparison:
# every reference here is >= 0.03 from every stored depth.
BOUND = 2.0 ** -8
_DISTANCE, _FOV_DEG = 3.0, 40.0


def _scene(tmp_path, reference: float, march_own_map: bool = False):
    write_png(tmp_path / "depths.png", np.array([[[CODES[0], 0, 0, 255], [CODES[1], 0, 0, 255]]], np.uint8))
    depths = {"path": str(tmp_path / "depths.png")}
    side = 2 * _DISTANCE * np.tan(np.radians(_FOV_DEG / 2))
    data = {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, -1.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": _FOV_DEG, "size": [SIZE, SIZE]},
        "lights": [{"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": {"surface": str(SHADER), "properties": {
            "_Depths": depths, "_DepthsAgain": depths, "_Reference": reference,
            "_MarchOwnMap": 1.0 if march_own_map else 0.0}}},
        "objects": [{"mesh": {"primitive": "plane", "size": float(side)},
                     "transform": {"translate": [0.0, -1.0, 0.0]}, "material": "m"}],
    }
    return parse_scene(data, origin="urp shadow-compare test scene", base=tmp_path)


def _render(tmp_path, language: str, reference: float, march_own_map: bool = False) -> np.ndarray:
    image = render_scene(_scene(tmp_path, reference, march_own_map), language=language).linear
    return image.astype(np.float64)


def _bilinear(per_texel: np.ndarray) -> np.ndarray:
    """GL's linear filter across the map's 2 texels at each pixel column's u (clamped to the
    edge), for one value per texel: (SIZE,)."""
    u = (np.arange(SIZE) + 0.5) / SIZE
    s = u * len(per_texel) - 0.5
    i0 = np.floor(s).astype(int)
    a = s - i0
    lo = per_texel[np.clip(i0, 0, len(per_texel) - 1)]
    hi = per_texel[np.clip(i0 + 1, 0, len(per_texel) - 1)]
    return (1 - a) * lo + a * hi


def _stored() -> np.ndarray:
    return np.array(CODES, np.float64) / 255.0


def _expected(reference: float, compare=np.less_equal) -> np.ndarray:
    """The float64 comparison of ``reference`` with each stored depth, filtered: (SIZE,)."""
    return _bilinear(compare(reference, _stored()).astype(np.float64))


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("reference", [0.5, 0.9, 0.1])
def test_sample_texture2d_shadow_is_the_filtered_comparison(tmp_path, language, reference):
    """Red (SAMPLE_TEXTURE2D_SHADOW of TEXTURE2D_SHADOW / SAMPLER_CMP) and green (a declared
    Texture2D's SampleCmpLevelZero with a SamplerComparisonState) against the float64 filtered
    comparison on every pixel, within BOUND: at 0.5 shadowed (0) over the first texel, lit (1)
    over the second, the bilinear PCF ramp between; at 0.9 all shadowed; at 0.1 all lit. Where
    the filter reads one texel (u <= 1/4 or u >= 3/4) the result is exactly 0 or 1. Controls:
    the reversed comparison (GreaterEqual on depths not reversed) and the comparison of the
    filtered depth (not of each texel) both fail the bound on the pixels where they differ."""
    image = _render(tmp_path, language, reference)
    expected = np.broadcast_to(_expected(reference), (SIZE, SIZE))
    for channel in (0, 1):
        err = np.abs(image[..., channel] - expected)
        assert (err <= BOUND).all(), (channel, err.max())
    u = (np.arange(SIZE) + 0.5) / SIZE
    one_texel = (u <= 0.25) | (u >= 0.75)
    assert (image[:, one_texel, :2] == expected[:, one_texel, None]).all()
    if reference == 0.5:
        assert (image[..., 0] == 0).any() and (image[..., 0] == 1).any()  # one shadowed, one lit
        reversed_ = np.broadcast_to(_expected(reference, np.greater_equal), (SIZE, SIZE))
        assert (np.abs(image[..., 0] - reversed_) > BOUND).mean() > 0.9
        filtered_first = (reference <= _bilinear(_stored())).astype(np.float64)
        ramp = ~one_texel
        assert (np.abs(image[:, ramp, 0] - filtered_first[ramp]) > BOUND).mean() > 0.9


@pytest.mark.parametrize("language", LANGUAGES)
def test_main_light_shadow_map_is_lit(tmp_path, language):
    """Blue: URP's main light shadow map passed through TEXTURE2D_SHADOW_ARGS and compared at
    16 references spread over the depth range, times its reads at the point's
    TransformWorldToShadowCoord and MainLightRealtimeShadow: 1 on every pixel (URP's empty
    shadow map, the far plane's depth, which every reference passes: what URP binds while no
    light casts shadows, as here). Control: the same march over the material's map is the
    float64 filtered fraction of lit references (1/4 over the first texel, 3/4 over the
    second), which fails the main map's 1 everywhere."""
    image = _render(tmp_path, language, 0.5)
    assert (np.abs(image[..., 2] - 1.0) <= BOUND).all(), np.abs(image[..., 2] - 1.0).max()
    own = _render(tmp_path, language, 0.5, march_own_map=True)
    z = (np.arange(STEPS) + 0.5) / STEPS
    fraction = np.array([(z <= d).mean() for d in _stored()])
    expected = np.broadcast_to(_bilinear(fraction), (SIZE, SIZE))
    err = np.abs(own[..., 2] - expected)
    assert (err <= BOUND).all(), err.max()
    assert (np.abs(1.0 - expected) > BOUND).all()  # control: the main map's value fails here


_ARRAY_SHADER = """
Shader "t/shadow array" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            TEXTURE2D_ARRAY_SHADOW(_Cascades);
            SAMPLER_CMP(sampler_Cascades);
            float4 vert(float4 positionOS : POSITION) : SV_POSITION { return TransformObjectToHClip(positionOS.xyz); }
            float4 frag(float4 positionCS : SV_POSITION) : SV_Target {
                return SAMPLE_TEXTURE2D_ARRAY_SHADOW(_Cascades, sampler_Cascades, float3(0.5, 0.5, 0.5), 1).xxxx;
            }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_shadow_map_array_is_refused_by_name(tmp_path, language):
    """A shadow-map array (TEXTURE2D_ARRAY_SHADOW) compiles in both languages and is refused
    when bound, naming the form: pbrlab binds depth textures only as 2D textures."""
    shader = tmp_path / "array.shader"
    shader.write_text(textwrap.dedent(_ARRAY_SHADER))
    data = {
        "camera": {"position": [0.0, 0.0, 4.0], "target": [0.0, 0.0, 0.0], "size": [16, 16]},
        "lights": [{"type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": {"surface": str(shader)}},
        "objects": [{"sphere": {"center": [0.0, 0.0, 0.0], "radius": 1.0}, "material": "m"}],
    }
    with pytest.raises(PbrlabError, match="TEXTURE2D_ARRAY_SHADOW") as refused:
        render_scene(parse_scene(data, origin="urp shadow-array test scene", base=tmp_path), language=language)
    assert "_Cascades" in str(refused.value)


_PASSED_ON = """
Texture2D _M; SamplerComparisonState sampler_M;
float F(Texture2D t, SamplerComparisonState s, float3 c) { return t.SampleCmpLevelZero(s, c.xy, c.z); }
float4 main(float4 p : SV_Position) : SV_Target { return F(_M, sampler_M, p.xyz).xxxx; }
"""


def test_a_map_passed_on_to_a_comparing_function_is_a_comparison_sampler():
    """A global Texture2D that HLSL compares only inside a function it passes it to: glslang
    (--auto-sampled-textures) declares the global a plain sampler2D and the parameter a
    sampler2DShadow, so the call has no GLSL overload; the cross-compiled GLSL declares the
    global sampler2DShadow (importers/unity/shadow_sampler_globals.py), and a stage that only declares it
    takes the same type. Control: spirv-cross's own text, the plain sampler2D."""
    from pbrlab.gpu import hlsl
    from pbrlab.importers.unity.compared_textures import texture_reads
    from pbrlab.importers.unity.shadow_sampler_globals import same_shadow_globals, typed_shadow_globals
    plain = hlsl.cross_to_glsl(hlsl.compile_spirv(_PASSED_ON, "passed_on.hlsl"))
    assert "uniform sampler2D _M;" in plain  # control: spirv-cross alone
    glsl = typed_shadow_globals(plain, texture_reads(_PASSED_ON))
    assert "uniform sampler2DShadow _M;" in glsl
    vertex = "layout(binding = 0) uniform sampler2D _M;\nvoid main() {}\n"
    assert "uniform sampler2DShadow _M;" in same_shadow_globals({"vertex": vertex, "fragment": glsl})["vertex"]
