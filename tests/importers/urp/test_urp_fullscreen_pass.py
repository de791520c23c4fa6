"""URP full-screen passes (issue 34): a pass whose vertex input is SV_VertexID alone (Core RP's
Blit.hlsl ``Vert``, or a vertex function of one's own over GetFullScreenTriangleVertexPosition)
is drawn as Unity's Blitter draws it: a procedural 3-vertex triangle over the viewport, after
the scene's other objects, reading the camera's colour as _BlitTexture with _BlitScaleBias
(1, 1, 0, 0) (importers/unity/fullscreen_pass.py).

Scene: a pbrlab sphere (standard material, lit) seen by a 64 x 48 camera, and an object whose
material is the full-screen shader, listed FIRST (a draw in scene order would read an empty
target). "alone" is the render of the scene without that object: the camera colour the pass
reads (the grab is a float blit of the target, exact).
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
SIZE = (64, 48)
SUN = {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 2.0}

# An inverted 3-tap horizontal blur of _BlitTexture, 3 - (weights 1/4, 1/2, 1/4, one texel apart;
# 3: above the camera colour, which a half target keeps non-negative),
# through Blit.hlsl's Vert, SAMPLE_TEXTURE2D_X(_LOD) and the global samplers. Its second pass
# (black) is not drawn: the Full Screen Pass Renderer Feature draws Pass Index 0.
BLUR_SHADER = """
Shader "t/fullscreen inverted blur" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        ZTest Always ZWrite Off Cull Off
        HLSLINCLUDE
        #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
        #include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"
        float4 _BlitTexture_TexelSize;
        ENDHLSL
        Pass {
            Name "InvertedBlur"
            HLSLPROGRAM
            #pragma vertex Vert
            #pragma fragment Frag
            float4 Frag(Varyings input) : SV_Target {
                float2 uv = input.texcoord;
                float2 dx = float2(_BlitTexture_TexelSize.x, 0.0);
                float3 c = 0.25 * SAMPLE_TEXTURE2D_X(_BlitTexture, sampler_LinearClamp, uv - dx).rgb
                         + 0.5 * SAMPLE_TEXTURE2D_X_LOD(_BlitTexture, sampler_LinearClamp, uv, _BlitMipLevel).rgb
                         + 0.25 * SAMPLE_TEXTURE2D_X(_BlitTexture, sampler_PointClamp, uv + dx).rgb;
                return float4(3.0 - c, 1.0);
            }
            ENDHLSL
        }
        Pass {
            Name "NotDrawn"
            HLSLPROGRAM
            #pragma vertex Vert
            #pragma fragment Black
            float4 Black(Varyings input) : SV_Target { return float4(0.0, 0.0, 0.0, 1.0); }
            ENDHLSL
        }
    }
}
"""

# A vertex function of its own over Core's full-screen triangle functions (no Blit.hlsl): the
# fragment shows its interpolated texture coordinate.
OWN_VERTEX_SHADER = """
Shader "t/fullscreen texcoord" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            ZTest Always ZWrite Off Cull Off
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            struct Attributes { uint vertexID : SV_VertexID; };
            struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
            Varyings vert(Attributes input) {
                Varyings output;
                output.positionCS = GetFullScreenTriangleVertexPosition(input.vertexID);
                output.uv = GetFullScreenTriangleTexCoord(input.vertexID);
                return output;
            }
            float4 frag(Varyings input) : SV_Target { return float4(input.uv, 0.5, 1.0); }
            ENDHLSL
        }
    }
}
"""


def _scene(tmp_path, shader_text: str | None, hdr_target: str = "rgba32f"):
    objects = [{"sphere": {"center": [0.3, 0.1, 0.0], "radius": 0.7}, "material": "s"}]
    materials = {"s": {"albedo": [0.8, 0.4, 0.2], "smoothness": 0.6}}
    if shader_text is not None:  # the full-screen object first in the list: it draws last anyway
        shader = tmp_path / "fullscreen.shader"
        shader.write_text(textwrap.dedent(shader_text))
        objects.insert(0, {"sphere": {"center": [0.0, 0.0, -5.0], "radius": 0.1}, "material": "f"})
        materials["f"] = {"surface": str(shader)}
    data = {"camera": {"position": [0.0, 0.0, 3.0], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40,
                       "size": list(SIZE)},
            "lights": [SUN], "materials": materials, "objects": objects,
            "render": {"hdr_target": hdr_target}}
    return parse_scene(data, origin="urp full-screen test scene", base=tmp_path)


def _linear(scene, language):
    return render_scene(scene, language=language).linear.astype(np.float64)


def _inverted_blur(alone: np.ndarray) -> np.ndarray:
    """3 - (L(x-1) / 4 + L(x) / 2 + L(x+1) / 4), rgb, the row's ends clamped (clamp to edge)."""
    left = np.concatenate([alone[:, :1], alone[:, :-1]], axis=1)
    right = np.concatenate([alone[:, 1:], alone[:, -1:]], axis=1)
    return 3.0 - (0.25 * left + 0.5 * alone + 0.25 * right)


def _neighbour_range(alone: np.ndarray) -> np.ndarray:
    """Per pixel and channel, the largest |L(neighbour) - L(texel)| over each tap's 3 x 3 texels."""
    padded = np.pad(alone, ((1, 1), (2, 2), (0, 0)), mode="edge")
    h, w = alone.shape[:2]
    out = np.zeros_like(alone)
    for tap in (-1, 0, 1):
        centre = padded[1:1 + h, 2 + tap:2 + tap + w]
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                out = np.maximum(out, np.abs(padded[1 + dy:1 + dy + h, 2 + tap + dx:2 + tap + dx + w] - centre))
    return out


@pytest.mark.parametrize("hdr_target", ["rgba32f", "rgba16f"])
@pytest.mark.parametrize("language", LANGUAGES)
def test_blit_pass_is_the_float64_blur_of_the_camera_colour(tmp_path, language, hdr_target):
    """Every pixel of the render is 3 - the 3-tap blur of "alone" (the camera colour). Bound,
    per pixel and channel: (1) Vert's texcoord is interpolated in float32 from corner values up
    to 2 and offset by one texel: a few ulp of 2, at most 2^-20 in uv, 64 * 2^-20 = 2^-14 of a
    texel, so each tap's bilinear weights are off by at most 2^-14, which moves the tap by 2^-14
    times the largest difference between the texels it filters (_neighbour_range; the taps'
    weights sum to 1); (2) the float32 sums: 4 ulp of values up to 3 + max|c|, 4 * 2^-23 (3 + max|c|);
    (3) with rgba16f the result is stored in half: one ulp, 2^-10 of |result|
    (GL leaves the rounding of a conversion to half to the implementation; llvmpipe truncates). The camera
    colour itself is the target's own storage, read exactly (a float blit). Controls: the
    expected image flipped vertically (a texcoord starting at the top, Direct3D's convention),
    and the camera colour unblurred, fail on the lit sphere's pixels and where the blur moves a
    pixel by over 0.02."""
    alone = _linear(_scene(tmp_path, None, hdr_target), language)[..., :3]
    image = _linear(_scene(tmp_path, BLUR_SHADER, hdr_target), language)
    expected = _inverted_blur(alone)
    bound = 2.0 ** -14 * _neighbour_range(alone) + 4 * 2.0 ** -23 * (3.0 + np.abs(alone).max())
    if hdr_target == "rgba16f":
        bound = bound + 2.0 ** -10 * np.abs(expected)
    lit = alone.max(axis=-1) > 0.05
    assert lit.sum() > 300 and (~lit).sum() > 300  # the sphere and the empty background
    err = np.abs(image[..., :3] - expected)
    assert (err <= bound).all(), (err / bound).max()
    assert (image[..., 3] == 1.0).all()  # every pixel drawn (the triangle covers the viewport)
    flipped = np.abs(image[..., :3] - _inverted_blur(alone[::-1])) > bound  # control: v from the top
    assert flipped.any(axis=-1)[lit | lit[::-1]].mean() > 0.9
    unblurred = np.abs(image[..., :3] - (3.0 - alone)) > bound  # control: no blur
    curved = np.abs(_inverted_blur(alone) - (3.0 - alone)).max(axis=-1) > 0.02  # where the blur moves it
    assert curved.sum() > 50 and unblurred.any(axis=-1)[curved].mean() > 0.9


@pytest.mark.parametrize("language", LANGUAGES)
def test_own_vertex_function_over_the_full_screen_triangle(tmp_path, language):
    """A vertex input of SV_VertexID alone is drawn full-screen: GetFullScreenTriangleTexCoord
    interpolates to each pixel centre's viewport position ((x + 0.5) / 64, (y + 0.5) / 48), y
    up from the bottom row (GL, UNITY_UV_STARTS_AT_TOP undefined), over the whole image. Bound:
    the float32 interpolation of corner values up to 2, a few ulp of 2: 2^-20. Control: the
    coordinate starting at the top (1 - v) fails on every row but the middle one."""
    image = _linear(_scene(tmp_path, OWN_VERTEX_SHADER), language)
    h, w = image.shape[:2]
    # linear's row 0 is the image's top row (rendering.linear is top-down, as the PNG)
    x = (np.arange(w) + 0.5) / w
    y = (np.arange(h)[::-1] + 0.5) / h
    want = np.stack(np.broadcast_arrays(x[None, :], y[:, None], np.full((h, w), 0.5)), axis=-1)
    bound = 2.0 ** -20
    err = np.abs(image[..., :3] - want)
    assert (err <= bound).all(), err.max()
    top_down = np.abs(image[..., 1] - (1.0 - want[..., 1])) > bound  # control
    assert top_down.mean() > 0.95


# Blit.hlsl's quad (VertQuad) and its FragBilinear: a copy of the camera colour.
QUAD_COPY_SHADER = """
Shader "t/fullscreen quad copy" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            ZTest Always ZWrite Off Cull Off
            HLSLPROGRAM
            #pragma vertex VertQuad
            #pragma fragment FragBilinear
            #include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_blit_quad_copies_the_camera_colour(tmp_path, language):
    """VertQuad (the Blitter's quad: 4 ids as triangles (0, 1, 2), (0, 2, 3)) with FragBilinear
    shows "alone" itself at every pixel. Bound: the quad's coordinate is interpolated in float32
    from corner values 0 and 1, a few ulp of 1 (2^-21 in uv, 64 * 2^-21 = 2^-15 of a texel), so
    the bilinear weights move by at most 2^-15 times the texel's largest neighbour difference.
    Controls: the image one row down fails on the lit sphere's rows; a quad drawn as 3 vertices
    (one triangle) would leave half the image at the cleared 0 and fail alpha == 1."""
    alone = _linear(_scene(tmp_path, None), language)[..., :3]
    image = _linear(_scene(tmp_path, QUAD_COPY_SHADER), language)
    bound = 2.0 ** -15 * _neighbour_range(alone) + 2.0 ** -24 * np.abs(alone)
    err = np.abs(image[..., :3] - alone)
    assert (err <= bound).all(), (err / np.maximum(bound, 1e-30)).max()
    assert (image[..., 3] == 1.0).all()
    lit = alone.max(axis=-1) > 0.05
    rows = np.abs(image[..., :3] - np.roll(alone, 1, axis=0)) > bound  # control
    assert rows.any(axis=-1)[lit & (np.abs(alone - np.roll(alone, 1, axis=0)).max(axis=-1) > 0.01)].mean() > 0.9
