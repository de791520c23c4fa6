"""A URP program that places its vertices beyond the mesh's bounds is drawn up to Unity's camera
far plane (Camera.farClipPlane's default, 1000), not clipped at the far side of the mesh's own
bounds (issue 34, the all-black "rendered" shaders: WoBok's cloud billboards push each vertex
several units away from the camera through their UVs; pbrlab's far plane, fitted to the
undisplaced sphere at 4.4 units, clipped all of them: black).

Scene: the corpus camera (3.2 units from the origin, 40 degrees, 48 x 48) and a unit UV sphere
that the pass moves 3 units away from the camera (centre 6.2 away, its back 7.2 away), returning
a constant colour. The covered disc is compared with the sphere's float64 projection.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pbrlab.importers.unity import material as unity_material
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

PUSHED = """
Shader "t/pushed away" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                float3 positionWS = TransformObjectToWorld(IN.positionOS.xyz) - float3(0.0, 0.0, %(push)s);
                OUT.positionCS = TransformWorldToHClip(positionWS);
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target { return float4(0.25, 0.5, 0.75, 1.0); }
            ENDHLSL
        }
    }
}
"""
CAMERA_DISTANCE, PUSH, FOV_Y, SIZE = 3.2, 3.0, 40.0, 48


def disc_radius_pixels(distance: float) -> float:
    """The pixel radius of a unit sphere's outline seen from ``distance`` (float64): its
    angular radius asin(1 / d), through the projection tan(angle) / tan(fov / 2) * size / 2."""
    return math.tan(math.asin(1.0 / distance)) / math.tan(math.radians(FOV_Y / 2)) * SIZE / 2


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_sphere_pushed_past_its_bounds_is_drawn(tmp_path, language):
    pixels, _ = render_constant(tmp_path, PUSHED % {"push": PUSH}, language, environment=False)
    assert np.all(np.abs(pixels - [0.25, 0.5, 0.75, 1.0]) <= 2.0 ** -24)  # a constant, exact
    r = disc_radius_pixels(CAMERA_DISTANCE + PUSH)  # 10.8 pixels
    # a pixel is covered where its centre falls inside the outline: every pixel whose centre is
    # within r - 0.71 (half a diagonal) is, none beyond r + 0.71; the 64-section outline lies
    # within r * cos(pi / 64) (0.013 pixels in) of the circle
    lo, hi = math.pi * (r * math.cos(math.pi / 64) - 0.71) ** 2, math.pi * (r + 0.71) ** 2
    assert lo <= len(pixels) <= hi, (len(pixels), lo, hi)


def test_at_the_bounds_far_plane_it_vanished(tmp_path, monkeypatch):
    """Control: without Unity's far plane (the planes from the mesh's bounds) nothing is drawn."""
    monkeypatch.setattr(unity_material.UnitySource, "camera_far", None)
    with pytest.raises(AssertionError, match=r"assert np.int64\(0\) > 200"):
        render_constant(tmp_path, PUSHED % {"push": PUSH}, "glsl", environment=False)  # covers no pixel
