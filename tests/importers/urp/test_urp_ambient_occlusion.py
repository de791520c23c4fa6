"""URP 14's AmbientOcclusion.hlsl names (issue 34, session 45): the AmbientOcclusionFactor, its
constructors CreateAmbientOcclusionFactor(InputData, SurfaceData) and (screen uv, occlusion),
GetScreenSpaceAmbientOcclusion and SampleAmbientOcclusion, and the light and baked-light overloads
that take the factor (GetMainLight(InputData, shadowMask, aoFactor), MixRealtimeAndBakedGI(...,
aoFactor)); brought by Lighting.hlsl as URP 14's is, and readable on its own. pbrlab has no SSAO
pass, so these are URP 14's values with _SCREEN_SPACE_OCCLUSION off: the screen-space factor 1 for
direct and indirect light, the indirect factor min(1, the material's occlusion), and the baked light
times the indirect factor (URP 14 ShaderLibrary/AmbientOcclusion.hlsl, RealtimeLights.hlsl and
GlobalIllumination.hlsl, read for the names and formulas).
"""

from __future__ import annotations

import numpy as np
import pytest

from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24
AO_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/AmbientOcclusion.hlsl"'
LIGHTING_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'
OCCLUSION = 0.35  # the material's occlusion (a float32 value within 2^-24 relative)
HIGH_OCCLUSION = 1.7  # an occlusion over 1, which the min with SSAO's 1 clamps
BAKED = np.array([0.8, 0.6, 0.4])


def _render(tmp_path, language, body, includes, lights=None):
    text = NAMES44_SHADER % {"body": body, "includes": includes, "globals": "", "properties": ""}
    return render_constant(tmp_path, text, language, environment=False, lights=lights)


FACTOR_BODY = (f"InputData inputData = (InputData)0; inputData.normalizedScreenSpaceUV = float2(0.3, 0.4);"
               f" SurfaceData surfaceData = (SurfaceData)0; surfaceData.occlusion = {OCCLUSION};"
               " AmbientOcclusionFactor a = CreateAmbientOcclusionFactor(inputData, surfaceData);"
               f" AmbientOcclusionFactor b = CreateAmbientOcclusionFactor(float2(0.1, 0.2), {HIGH_OCCLUSION});"
               " AmbientOcclusionFactor s = GetScreenSpaceAmbientOcclusion(float2(0.5, 0.5));"
               " return float4(a.indirectAmbientOcclusion, a.directAmbientOcclusion * 0.5,"
               " b.indirectAmbientOcclusion * 0.25 + s.indirectAmbientOcclusion * 0.125"
               " + SampleAmbientOcclusion(float2(0.5, 0.5)) * 0.0625, 1.0);")


@pytest.mark.parametrize("language", LANGUAGES)
def test_factor_without_ssao_is_the_material_occlusion_capped_at_one(tmp_path, language):
    """AmbientOcclusion.hlsl included on its own: the factor of occlusion 0.35 is (indirect 0.35,
    direct 1); of occlusion 1.7, indirect min(1, 1.7) = 1; SSAO's own factor and sample are 1.
    Expected (0.35, 0.5, 0.25 + 0.125 + 0.0625). Bound: 0.35 rounded to float32 (2^-24 relative)
    and the sum's three roundings of values below 1: 4 * 2^-24. Controls: the factor that ignores
    the material (indirect 1) and the one that does not cap it (1.7 * 0.25 in the third channel)."""
    pixels, _ = _render(tmp_path, language, FACTOR_BODY, AO_INCLUDE)
    expected = np.array([OCCLUSION, 0.5, min(1.0, HIGH_OCCLUSION) * 0.25 + 0.125 + 0.0625])
    bound = 4 * EPS
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    for control in (np.array([1.0, 0.5, expected[2]]), np.array([OCCLUSION, 0.5, HIGH_OCCLUSION * 0.25 + 0.1875])):
        assert not (np.abs(pixels[:, :3] - control) <= bound).all()


MIX_BODY = (f"InputData inputData = (InputData)0; SurfaceData surfaceData = (SurfaceData)0;"
            f" surfaceData.occlusion = {OCCLUSION};"
            " AmbientOcclusionFactor aoFactor = CreateAmbientOcclusionFactor(inputData, surfaceData);"
            " Light light = GetMainLight(inputData, float4(1.0, 1.0, 1.0, 1.0), aoFactor);"
            f" float3 bakedGI = float3({BAKED[0]}, {BAKED[1]}, {BAKED[2]});"
            " MixRealtimeAndBakedGI(light, float3(0.0, 1.0, 0.0), bakedGI, aoFactor);"
            " return float4(bakedGI + light.color * 0.25, 1.0);")


@pytest.mark.parametrize("language", LANGUAGES)
def test_baked_light_is_darkened_by_the_indirect_factor(tmp_path, language):
    """Through Lighting.hlsl (as URP 14's brings AmbientOcclusion.hlsl): MixRealtimeAndBakedGI with
    the factor multiplies the baked light by min(1, occlusion) (no lightmap to mix here), and the
    main light taken with the factor is the scene's sun (radiance (0.4, 0.2, 0.8)), undimmed
    without SSAO. Expected (0.8, 0.6, 0.4) * 0.35 + 0.25 * (0.4, 0.2, 0.8). Bound: the inputs'
    float32 roundings (2^-24 relative each) and three products and a sum of values below 1:
    6 * 2^-24. Control: the baked light left as it was (URP 12's overload without the factor)."""
    sun = {"type": "directional", "direction": [0.0, 0.0, -1.0], "color": [0.4, 0.2, 0.8], "intensity": 1.0}
    pixels, _ = _render(tmp_path, language, MIX_BODY, LIGHTING_INCLUDE, lights=[sun])
    radiance = np.array([0.4, 0.2, 0.8])
    expected = BAKED * OCCLUSION + 0.25 * radiance
    bound = 6 * EPS
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    control = BAKED + 0.25 * radiance
    assert not (np.abs(pixels[:, :3] - control) <= bound).all()
