"""URP names real URP shaders read that pbrlab refused (issue 34, session 45, hidden7): URP's
_ScreenSize global and URP 10's four-argument AdditionalLightShadow. Each is rendered in both
languages from a minimal shader of our own and compared with its float64 value from Unity's
documented meaning, with a control (the value another reading gives) that the bound rejects.
"""

from __future__ import annotations

import numpy as np
import pytest

from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24
# render_constant's camera: a 48 x 48 target
SIZE = 48.0
LIGHTING = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'


def _render(tmp_path, language, body, includes=""):
    text = NAMES44_SHADER % {"body": body, "includes": includes, "globals": "", "properties": ""}
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    return pixels


@pytest.mark.parametrize("language", LANGUAGES)
def test_screen_size_is_size_and_reciprocal(tmp_path, language):
    """URP's _ScreenSize (UnityInput.hlsl): (width, height, 1 / width, 1 / height) of the target.
    Bound: the reciprocal is one float32 division and each output one product more, 2 roundings
    of 2^-24 relative each of values below 1. Control: _ScreenParams.z (1 + 1 / width), which a
    reading of _ScreenSize as _ScreenParams gives, is 10 / 48 + 10 away."""
    pixels = _render(tmp_path, language, "return float4(_ScreenSize.x * 0.01, _ScreenSize.y * 0.005,"
                     " _ScreenSize.z * 10.0, 1.0);")
    expected = np.array([SIZE * 0.01, SIZE * 0.005, 10.0 / SIZE])
    bound = 2 * EPS
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    screen_params_z = (1.0 + 1.0 / SIZE) * 10.0
    assert abs(screen_params_z - expected[2]) > 1000 * bound
    height_reciprocal = _render(tmp_path, language, "return float4(_ScreenSize.w * 10.0, 0.0, 0.0, 1.0);")
    assert (np.abs(height_reciprocal[:, 0] - 10.0 / SIZE) <= bound).all()


@pytest.mark.parametrize("language", LANGUAGES)
def test_urp10_additional_light_shadow_is_unshadowed(tmp_path, language):
    """URP 10's AdditionalLightShadow(lightIndex, positionWS, shadowMask, occlusionProbeChannels),
    before URP 12 added the light's direction, called with scalar masks as a URP 10 shader does:
    pbrlab draws no shadow maps, so every light is unshadowed, 1, as the five-argument form.
    Bound: 0.5 * 1 + 0.25 is exact in float32 (and the output). Control: a shadowed light (0)
    gives 0.25."""
    pixels = _render(tmp_path, language, "float s = AdditionalLightShadow(0, float3(0.0, 0.0, 0.0), 0, 0);"
                     " float t = AdditionalLightShadow(0, float3(0.0, 0.0, 0.0), float3(0.0, 1.0, 0.0), 0, 0);"
                     " return float4(0.5 * s + 0.25, t * 0.5, 0.0, 1.0);", includes=LIGHTING)
    assert (pixels[:, :2] == np.array([0.75, 0.5])).all(), pixels[0, :2]
    shadowed = 0.5 * 0.0 + 0.25
    assert shadowed != 0.75


# --- URP 10's PostProcessing/Common.hlsl layout ----------------------------------------------------
_URP10_POST = """
Shader "t/urp10 post" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex %(vertex)s
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/Shaders/PostProcessing/Common.hlsl"
            struct OwnVaryings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
            OwnVaryings OwnVert(Attributes input) {
                OwnVaryings output;
                output.positionCS = TransformObjectToHClip(input.positionOS.xyz);
                output.uv = input.uv;
                return output;
            }
            float4 frag(%(varyings)s input) : SV_Target { return float4(input.uv * 0.5 + 0.25, 0.5, 1.0); }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_urp10_post_processing_layout_is_the_mesh_with_its_uv(tmp_path, language):
    """A shader written for URP 10's PostProcessing/Common.hlsl, which declared a mesh's Attributes
    { positionOS: POSITION, uv: TEXCOORD0 }, Varyings { positionCS, uv } and Vert (the object
    position through TransformObjectToHClip, uv passed on), told by its reading
    Attributes.positionOS: Vert draws the object's mesh with its uv, the pixels of the same
    computation spelled in the shader's own function (identical float32 operations: bound 0).
    Control: URP 13's Blit.hlsl layout would draw the full-screen triangle, covering all 48 x 48
    pixels, where the sphere covers about 64 %."""
    library, _ = render_constant(tmp_path, _URP10_POST % {"vertex": "Vert", "varyings": "Varyings"}, language,
                                 environment=False)
    own, _ = render_constant(tmp_path, _URP10_POST % {"vertex": "OwnVert", "varyings": "OwnVaryings"}, language,
                             environment=False)
    assert library.shape == own.shape
    assert (library == own).all()
    assert len(library) < 0.9 * SIZE * SIZE
    assert np.ptp(library[:, 0]) > 0.1  # the uv varies over the mesh
