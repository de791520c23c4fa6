"""Shader Graph's scene nodes through the ShaderGraphFunctions.hlsl stand-in (issue 34):
SHADERGRAPH_SAMPLE_SCENE_DEPTH / SHADERGRAPH_SAMPLE_SCENE_COLOR read the camera's depth and
opaque textures when the program defines REQUIRE_DEPTH_TEXTURE / REQUIRE_OPAQUE_TEXTURE (which
also bring URP's SampleSceneDepth / SampleSceneColor, as URP's file does), 0 without; and Core
RP's BlendNormal, which URP's Lighting.hlsl brings.

Scenes: test_urp_scene_textures.py's (a ray-traced sphere for depth; a full-view plane over a
sphere for colour), with its bounds.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.render.renderer import render_scene
from test_urp_library_round2 import render_constant, urp_pass
from test_urp_scene_textures import (_URP_PASS, LANGUAGES, OPAQUE_SHADER, _opaque_scene, _scene,
                                     check_sphere_depths)

GRAPH_FUNCTIONS = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/ShaderGraphFunctions.hlsl"'

# The graph's depth node and URP's SampleSceneDepth (declared by the REQUIRE_DEPTH_TEXTURE the
# program defines, with no DeclareDepthTexture.hlsl of its own), as eye depths.
GRAPH_DEPTH_SHADER = _URP_PASS % {
    "name": "graph depth",
    "include": "#define REQUIRE_DEPTH_TEXTURE\n            " + GRAPH_FUNCTIONS,
    "body": """float2 uv = GetNormalizedScreenSpaceUV(IN.positionCS);
                return float4(Linear01Depth(SHADERGRAPH_SAMPLE_SCENE_DEPTH(uv), _ZBufferParams),
                              LinearEyeDepth(SHADERGRAPH_SAMPLE_SCENE_DEPTH(uv), _ZBufferParams),
                              LinearEyeDepth(SampleSceneDepth(uv), _ZBufferParams), 1.0);""",
}


@pytest.mark.parametrize("language", LANGUAGES)
def test_graph_scene_depth_is_ray_sphere_depth(tmp_path, language):
    """Linear01Depth / LinearEyeDepth of SHADERGRAPH_SAMPLE_SCENE_DEPTH and of SampleSceneDepth
    = the float64 ray-sphere eye depth (/ far), within test_urp_scene_textures' depth bound
    (depth_bound: the stored window depth's float32 roundings through 1/e's slope, and
    LinearEyeDepth's own). Control: the neighbouring pixel's depth fails it."""
    check_sphere_depths(_scene(GRAPH_DEPTH_SHADER, tmp_path), language)


@pytest.mark.parametrize("language", LANGUAGES)
def test_graph_scene_nodes_read_zero_without_require(tmp_path, language):
    """Without REQUIRE_DEPTH_TEXTURE / REQUIRE_OPAQUE_TEXTURE the nodes read 0 (URP's
    shadergraph functions' #else), exactly: the pixel is (0, 0, 0) + 0.5 from the constant.
    Control: with REQUIRE_DEPTH_TEXTURE the same expression is the sphere's depth (the test above)."""
    body = """float2 uv = GetNormalizedScreenSpaceUV(IN.positionCS);
                return float4(SHADERGRAPH_SAMPLE_SCENE_DEPTH(uv) + 0.5,
                              SHADERGRAPH_SAMPLE_SCENE_COLOR(uv).rg + 0.5, 1.0);"""
    pixels, _ = render_constant(tmp_path, urp_pass("graph nodes off", body, GRAPH_FUNCTIONS), language,
                                environment=False)
    assert (pixels[:, :3] == 0.5).all()


# The opaque test's plane, its scene colour read through the graph's node.
GRAPH_OPAQUE_SHADER = OPAQUE_SHADER.replace(
    '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareOpaqueTexture.hlsl"',
    "#define REQUIRE_OPAQUE_TEXTURE\n            " + GRAPH_FUNCTIONS).replace(
    "float3 c = SampleSceneColor(", "float3 c = SHADERGRAPH_SAMPLE_SCENE_COLOR(")


@pytest.mark.parametrize("language", LANGUAGES)
def test_graph_scene_color_is_the_opaque_copy(tmp_path, language):
    """SHADERGRAPH_SAMPLE_SCENE_COLOR with REQUIRE_OPAQUE_TEXTURE reads the copy drawn before the
    plane: the plane shows 2 L + 0.25 in r and g (LoadSceneColor's L in b), L the sphere's render
    alone; at pixel centres the bilinear weights are exact, so 1 ulp of the result bounds it
    (test_scene_color_is_the_opaque_copy's bound). Control: the sphere one pixel down fails it."""
    assert "SHADERGRAPH_SAMPLE_SCENE_COLOR" in GRAPH_OPAQUE_SHADER and "DeclareOpaque" not in GRAPH_OPAQUE_SHADER
    alone = render_scene(_opaque_scene(tmp_path, False), language=language).linear.astype(np.float64)
    image = render_scene(_opaque_scene(tmp_path, True, GRAPH_OPAQUE_SHADER),
                         language=language).linear.astype(np.float64)
    expected = np.concatenate([2 * alone[..., :2] + 0.25, alone[..., 2:3]], axis=-1)
    bound = 2.0 ** -23 * np.maximum(np.abs(expected), 2.0 ** -10)
    err = np.abs(image[..., :3] - expected)
    assert (err <= bound).all(), (err / bound).max()
    sphere = alone[..., 3] > 0
    lit = sphere & (alone[..., :3].max(axis=-1) > 0.01)
    assert lit.sum() > 300
    shifted = np.concatenate([2 * np.roll(alone, 1, axis=0)[..., :2] + 0.25, np.roll(alone, 1, axis=0)[..., 2:3]], -1)
    assert (np.abs(image[..., :3] - shifted) > bound)[lit].any(axis=-1).mean() > 0.9


def blend_normal(n1, n2) -> np.ndarray:
    """float64 whiteout blend (Barre-Brisebois and Hill, "Blending in Detail", 2012): (n1.xy n2.z
    + n2.xy n1.z, n1.z n2.z), normalized."""
    n1, n2 = np.asarray(n1, np.float64), np.asarray(n2, np.float64)
    v = np.array([*(n1[:2] * n2[2] + n2[:2] * n1[2]), n1[2] * n2[2]])
    return v / np.linalg.norm(v)


N1, N2 = (0.3, -0.2, 0.9327379), (-0.5, 0.1, 0.8602325)
# float32: inputs rounded, 2 products and a sum per component, the normalization (rsqrt): 16 ulps
# (2^-24) of values below 1.
BLEND_BOUND = 16 * 2.0 ** -24


@pytest.mark.parametrize("language", LANGUAGES)
def test_blend_normal_is_the_whiteout_blend(tmp_path, language):
    """BlendNormal (Core RP's CommonMaterial, through URP's Lighting.hlsl) of two tangent-space
    normals = the float64 whiteout blend, mapped to [0, 1]. Control: the normalized sum (a
    linear blend) differs by far more than the bound."""
    body = f"return float4(BlendNormal(float3{N1}, float3{N2}) * 0.5 + 0.5, 1.0);"
    include = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'
    pixels, _ = render_constant(tmp_path, urp_pass("blend normal", body, include), language, environment=False)
    expected = blend_normal(N1, N2) * 0.5 + 0.5
    assert (np.abs(pixels[:, :3] - expected).max(axis=1) > BLEND_BOUND).mean() == 0.0
    linear = np.add(N1, N2) / np.linalg.norm(np.add(N1, N2)) * 0.5 + 0.5
    assert np.abs(linear - expected).max() > 100 * BLEND_BOUND
