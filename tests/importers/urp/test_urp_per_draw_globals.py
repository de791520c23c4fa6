"""URP's UnityPerDraw globals a shader reads directly (issue 34): the ambient probe's SH
coefficients unity_SHAr..unity_SHC, and the lightmap scale-offsets of an object that is not
lightmapped (unity_LightmapST, unity_DynamicLightmapST, unity_LightmapIndex).

Scene: test_urp_library_round2's unit UV sphere drawn with the pass under test, which returns
a constant, so every covered pixel is checked.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.maths.reference.lighting import SH9_C1, SH9_C2, SH9_C3, SH9_C4, SH9_C5, sh9_irradiance
from pbrlab.scene.environment import environment_sh
from test_urp_library_round2 import AMBIENT_INCLUDE, LANGUAGES, render_constant, urp_pass

# A unit direction off every axis, so each of the nine SH terms counts.
DIRECTION = np.array([2.0, -3.0, 6.0]) / 7.0
_D = "float3(2.0, -3.0, 6.0) / 7.0"

# Unity's ShadeSH9 (UnityCG.cginc: SHEvalLinearL0L1 + SHEvalLinearL2) and URP's SampleSH9, by
# hand from the globals, per channel: dot(SHA, (n, 1)) + dot(SHB, n.xyzz * n.yzzx) + SHC (x^2 - y^2).
BY_HAND = f"""float4 n = float4({_D}, 1.0);
                float4 b = n.xyzz * n.yzzx;
                float c = n.x * n.x - n.y * n.y;
                float3 sh = float3(dot(unity_SHAr, n), dot(unity_SHAg, n), dot(unity_SHAb, n))
                          + float3(dot(unity_SHBr, b), dot(unity_SHBg, b), dot(unity_SHBb, b)) + unity_SHC.rgb * c;
                return float4(sh, 1.0);"""
SAMPLE_SH = f"return float4(SampleSH({_D}), 1.0);"
# Chapter14-ToonShading's ambient: the constant terms alone.
CONSTANT = "return float4(unity_SHAr.w, unity_SHAg.w, unity_SHAb.w, 1.0);"


def unity_sh_packed(sh) -> dict:
    """float64: the SH9 radiance coefficients sh[9, 3] (pbr_sh9_irradiance's order) packed as
    Unity's seven globals for irradiance / pi, from Ramamoorthi & Hanrahan 2001 eq. 13 (the
    polynomial sh9_irradiance evaluates) regrouped by Unity's monomials (UnityCG.cginc's
    SHEvalLinearL0L1 / SHEvalLinearL2: (x, y, z, 1), (xy, yz, zz, zx), x^2 - y^2)."""
    sh = np.asarray(sh, np.float64) / np.pi
    a = np.stack([2 * SH9_C2 * sh[3], 2 * SH9_C2 * sh[1], 2 * SH9_C2 * sh[2], SH9_C4 * sh[0] - SH9_C5 * sh[6]])
    b = np.stack([2 * SH9_C1 * sh[4], 2 * SH9_C1 * sh[5], SH9_C3 * sh[6], 2 * SH9_C1 * sh[7]])
    return {"A": a, "B": b, "C": SH9_C1 * sh[8]}   # A, B: [4, 3] (component, channel); C: [3]


def evaluate_packed(packed, n) -> np.ndarray:
    x, y, z = n
    return (packed["A"].T @ np.array([x, y, z, 1.0]) + packed["B"].T @ np.array([x * y, y * z, z * z, z * x])
            + packed["C"] * (x * x - y * y))


# float32: 9 coefficients each rounded to float32 on upload and once more by the packing's
# product (2 ulps), 9 products and 8 sums of terms whose magnitudes add to below 1 (checked
# below): 32 ulps (2^-24) of 1 bounds the by-hand sum, SampleSH's and their difference.
SH_BOUND = 32 * 2.0 ** -24


@pytest.mark.parametrize("language", LANGUAGES)
def test_sh_globals_evaluated_by_hand_equal_sample_sh(tmp_path, language):
    """unity_SHAr..unity_SHC evaluated by hand (ShadeSH9's polynomial) at a direction equal
    SampleSH there (the stand-in's ambient) and the float64 irradiance / pi of the scene's SH,
    within SH_BOUND on every covered pixel; Unity's packing in float64 evaluates to the same
    irradiance to 1e-12. Controls: SHA.w alone (the constant) is the packed float64 constant and
    differs from the full value by far more than the bound; a packing with SHA.x and SHA.z
    swapped misses it; without an environment every global is zero."""
    by_hand, scene = render_constant(tmp_path, urp_pass("sh by hand", BY_HAND, AMBIENT_INCLUDE), language)
    sampled, _ = render_constant(tmp_path, urp_pass("sample sh", SAMPLE_SH, AMBIENT_INCLUDE), language)
    sh = environment_sh(scene.environment)
    expected = sh9_irradiance(sh, DIRECTION) / np.pi
    packed = unity_sh_packed(sh)
    assert np.abs(evaluate_packed(packed, DIRECTION) - expected).max() < 1e-12
    magnitudes = (np.abs(packed["A"]).sum(axis=0) + np.abs(packed["B"]).sum(axis=0) + np.abs(packed["C"]))
    assert expected.min() > 0.01 and magnitudes.max() < 1.0
    for pixels in (by_hand, sampled):
        err = np.abs(pixels[:, :3] - expected).max(axis=1)
        assert (err > SH_BOUND).mean() == 0.0, (err.max(), pixels[0], expected)
    assert (np.abs(by_hand[:, :3] - sampled[:, :3]).max(axis=1) > SH_BOUND).mean() == 0.0

    constant, _ = render_constant(tmp_path, urp_pass("sh constant", CONSTANT, AMBIENT_INCLUDE), language)
    assert (np.abs(constant[:, :3] - packed["A"][3]).max(axis=1) > SH_BOUND).mean() == 0.0
    assert np.abs(packed["A"][3] - expected).max() > 100 * SH_BOUND
    swapped = {**packed, "A": packed["A"][[2, 1, 0, 3]]}
    assert np.abs(evaluate_packed(swapped, DIRECTION) - expected).max() > 100 * SH_BOUND
    dark, _ = render_constant(tmp_path, urp_pass("sh by hand", BY_HAND, AMBIENT_INCLUDE), language,
                              environment=False)
    assert np.abs(dark[:, :3]).max() == 0.0


# UnityPerDraw's lightmap scale-offsets of an object that is not lightmapped: the identity,
# (1, 1, 0, 0) each (Core.hlsl stand-in; Renderer.lightmapScaleOffset's default), read as a
# shader reads them: a lightmap UV scaled and offset (Color.shader's vertex stage), here the
# constant uv (0.25, 0.5).
LIGHTMAP_ST = """float2 uv = float2(0.25, 0.5);
                float2 baked = uv * unity_LightmapST.xy + unity_LightmapST.zw;
                float2 realtime = uv * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
                return float4(baked, realtime.x + 10.0 * realtime.y, 1.0);"""
LIGHTMAP_EXPECTED = np.array([0.25, 0.5, 0.25 + 10.0 * 0.5])
# exact: products by 1 and sums with 0 of values float32 holds exactly; one rounding of 5.25.
LIGHTMAP_BOUND = 2.0 ** -20


@pytest.mark.parametrize("language", LANGUAGES)
def test_lightmap_scale_offsets_of_an_unlightmapped_object_are_the_identity(tmp_path, language):
    """unity_LightmapST and unity_DynamicLightmapST map a lightmap UV to itself. Control: the
    zero an unset global would give, (0, 0, 0), and a swapped scale and offset, (1, 1, 11),
    are far outside the bound."""
    pixels, _ = render_constant(tmp_path, urp_pass("lightmap st", LIGHTMAP_ST), language, environment=False)
    err = np.abs(pixels[:, :3] - LIGHTMAP_EXPECTED).max(axis=1)
    assert (err > LIGHTMAP_BOUND).mean() == 0.0, (err.max(), pixels[0])
    swapped = np.array([0.25 * 0 + 1, 0.5 * 0 + 1, 11.0])  # scale (0, 0), offset (1, 1)
    for wrong in (np.zeros(3), swapped):
        assert np.abs(wrong - LIGHTMAP_EXPECTED).max() > 1000 * LIGHTMAP_BOUND


@pytest.mark.parametrize("language", LANGUAGES)
def test_lightmap_scale_offsets_with_unitycg_after_core(tmp_path, language):
    """A URP program that also includes UnityCG.cginc (whose lightmap stand-ins declare the two
    as uniforms) after Core.hlsl reads the same identity: pixel (0.5, 0.5, 0) from
    unity_LightmapST.xy / 2 and unity_DynamicLightmapST.z. Control: the uniform declaration
    expanded through Core's definition was a compile error before the stand-ins skipped it."""
    body = "return float4(unity_LightmapST.xy * 0.5, unity_DynamicLightmapST.z, 1.0);"
    pixels, _ = render_constant(tmp_path, urp_pass("lightmap st unitycg", body, '#include "UnityCG.cginc"'),
                                language, environment=False)
    assert (np.abs(pixels[:, :3] - [0.5, 0.5, 0.0]).max(axis=1) > LIGHTMAP_BOUND).mean() == 0.0
