"""A supplied lightmap's companions (importers/unity/lightmaps.py): a directional lightmap's
direction texture ``unity_LightmapInd`` (the lightmap's ``direction`` image, or a grey texel of
no dominant direction) read through ``DecodeDirectionalLightmap``, and the baked shadow mask
``unity_ShadowMask`` (white: no baked shadow) with ``unity_OcclusionMaskSelector``.

Per pixel against float64, on test_supplied_lightmaps.py's plane and blocks (its helpers: the
expectation's geometry and the pixels compared are explained there). The plane's normal is
+y, so Unity's decode, color (dot(n, d.xyz - 0.5) + 0.5) / max(d.w, 1e-4) (UnityCG.cginc;
Unity manual, "Directional Mode"), is color d.y / d.w at every pixel.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation import images

from test_supplied_lightmaps import BLOCK, N, SCALE_OFFSET, _lightmap, _render, _shader, expected, over_bound

pytestmark = pytest.mark.filterwarnings("ignore::pbrlab.importers.unity.UnityShaderNote")

DIRECTIONAL = """float3 c = DecodeLightmap(UNITY_SAMPLE_TEX2D(unity_Lightmap, i.lm));
                fixed4 d = UNITY_SAMPLE_TEX2D_SAMPLER(unity_LightmapInd, unity_Lightmap, i.lm);
                return float4(DecodeDirectionalLightmap(c, d, normalize(UnityObjectToWorldNormal(float3(0, 1, 0)))), 1);"""
SHADOW_MASK = """float occlusion = saturate(dot(UNITY_SAMPLE_TEX2D(unity_ShadowMask, i.lm), unity_OcclusionMaskSelector));
                return float4(DecodeLightmap(UNITY_SAMPLE_TEX2D(unity_Lightmap, i.lm)) * %s, 1);"""
# A full-HDR lightmap (float texels read as they are) and an 8-bit linear direction image (a
# byte b read as b / 255, one float32 rounding). d.y and d.w lie in [0.4, 1], so the decode
# c (d.y / d.w) after its float32 steps (the read, d - 0.5, the dot's three products and two
# sums, + 0.5, the product and the quotient: nine roundings of 2^-24 relative to values
# >= 0.4 of the result's size, 2.5 x 9 x 2^-24 = 1.3e-6) and the normal's normalisation
# (within a few ulp: its x and z at most 3e-7, times |d - 0.5| <= 0.5, over halfLambert >= 0.4:
# 4e-7) is within 2e-6 of the float64 value, relative.
DIRECTION_BOUND = 2e-6


def _direction(tmp_path):
    """(file, texels in [0, 1] per block, row 0 the image's top)."""
    rng = np.random.default_rng(5)
    blocks = N // BLOCK
    texels = rng.integers(0, 256, (blocks, blocks, 4)).astype(np.uint8)
    texels[..., 1] = rng.integers(102, 256, (blocks, blocks))  # d.y, d.w >= 0.4
    texels[..., 3] = rng.integers(102, 256, (blocks, blocks))
    path = tmp_path / "lightmap_dir.png"
    images.write_png(path, np.repeat(np.repeat(texels, BLOCK, 0), BLOCK, 1))
    return path, texels.astype(np.float64) / 255.0


def _directional_expected(size, colour, direction):
    """The float64 decode per block (as test_supplied_lightmaps.expected picks blocks)."""
    factor = direction[..., 1:2] / direction[..., 3:4]
    (low, _), compared = expected(size, np.concatenate([colour[..., :3] * factor, colour[..., 3:]], -1), "full_hdr")
    return low, compared


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_supplied_direction_image_is_decoded_per_pixel_as_unity(tmp_path, language):
    path, colour = _lightmap(tmp_path, "full_hdr")
    direction_path, direction = _direction(tmp_path)
    lightmap = {"path": str(path), "direction": str(direction_path), "scale_offset": list(SCALE_OFFSET)}
    image = _render(tmp_path, _shader(tmp_path, body=DIRECTIONAL), language, lightmap)
    want, compared = _directional_expected(image.shape[:2], colour, direction)
    assert compared.mean() > 0.05
    outside = (np.abs(image[..., :3] - want) > DIRECTION_BOUND * want).any(-1)
    assert not outside[compared].any()
    # control: the lightmap alone (no direction term) is not what was drawn
    (plain, _), _ = expected(image.shape[:2], colour, "full_hdr")
    assert (np.abs(image[..., :3] - plain) > DIRECTION_BOUND * plain).any(-1)[compared].mean() > 0.5


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_without_a_direction_image_the_decode_is_the_lightmap(tmp_path, language):
    """The grey (0.5, 0.5, 0.5, 0.5) texel: halfLambert 0.5 for any normal, over w 0.5: the
    lightmap's colour exactly (test_supplied_lightmaps' bound). The control: white, the default
    of an unset texture, would give d.y / d.w = 1 too, so the half-Lambert is checked with a
    tilted normal: grey keeps it 1, white (1 + n.x + n.z) / 2 would not."""
    path, colour = _lightmap(tmp_path, "full_hdr")
    lightmap = {"path": str(path), "scale_offset": list(SCALE_OFFSET)}
    tilted = DIRECTIONAL.replace("float3(0, 1, 0)", "float3(0.6, 0.64, 0.48)")
    image = _render(tmp_path, _shader(tmp_path, body=tilted), language, lightmap)
    expectation, compared = expected(image.shape[:2], colour, "full_hdr")
    assert compared.mean() > 0.05
    assert over_bound(image, expectation, compared) == 0.0
    white = tuple(e * (0.5 + 0.5 * (0.6 + 0.64 + 0.48)) for e in expectation)
    assert over_bound(image, white, compared) == 1.0


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_shadow_mask_is_white_and_the_selector_picks_no_shadow(tmp_path, language):
    """Occlusion 1: the decode unchanged; the control 1 - occlusion is black."""
    path, colour = _lightmap(tmp_path, "full_hdr")
    lightmap = {"path": str(path), "scale_offset": list(SCALE_OFFSET)}
    image = _render(tmp_path, _shader(tmp_path, body=SHADOW_MASK % "occlusion"), language, lightmap)
    expectation, compared = expected(image.shape[:2], colour, "full_hdr")
    assert compared.mean() > 0.05
    assert over_bound(image, expectation, compared) == 0.0
    shadowed = _render(tmp_path, _shader(tmp_path, body=SHADOW_MASK % "(1 - occlusion)"), language, lightmap)
    assert not shadowed[compared][:, :3].any()
