"""Shader Graph's texture object read straight off its builder's call (issue 34's hidden7
sample, session 46: ding-yan-qing's Houdini VAT graphs write ``SAMPLE_TEXTURE2D(
UnityBuildTexture2DStructNoScale(_T).tex, UnityBuildTexture2DStructNoScale(_T).samplerstate,
UnityBuildTexture2DStructNoScale(_T).GetTransformedUV(uv))``), which glslang's HLSL front end
refused ("unable to find texture symbol") and the GLSL port too ("unexpected ')'"); and a texture
lookup whose offset is a parameter of its function (HengyuanLee's BilateralBlur), which FXC takes
once it has inlined the calls and GLSL and spirv-cross's GLSL refused. Drawn in both languages
from minimal shaders of ours and checked against float64, with a control.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_spellings, texture_objects
from test_urp_library_round2 import LANGUAGES
from test_urp_front_end import _render as _plane
from test_urp_names_round45 import _render  # pytest puts this folder on sys.path

OBJECTS = """
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Texture.hlsl"
            TEXTURE2D(_Tint); SAMPLER(sampler_Tint); float4 _Tint_TexelSize; float4 _Tint_ST;
"""
BODY = ("float4 s = SAMPLE_TEXTURE2D_LOD(UnityBuildTexture2DStruct(_Tint).tex,"
        " UnityBuildTexture2DStruct(_Tint).samplerstate,"
        " UnityBuildTexture2DStruct(_Tint).GetTransformedUV(float2(0.5, 0.5)), 0);"
        " float2 uv = UnityBuildTexture2DStructNoScale(_Tint).GetTransformedUV(float2(0.25, 0.625));"
        " return float4(uv, s.r * 0.25 + UnityBuildTexture2DStructNoScale(_Tint).texelSize.z * 0.125, 1.0);")
PROPERTIES = '_Tint ("Tint", 2D) = "white" {}'


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_texture_object_s_members_read_off_its_builder(tmp_path, language, monkeypatch):
    """The members are the property's: the unset 2D property's white 1 x 1 texture (texel size
    z = 1) sampled (1), NoScale's tiling 1 and offset 0 (Core RP's Texture.hlsl: uv * xy + zw):
    (0.25, 0.625, 0.25 + 0.125), exact binary fractions (bound: 2^-24, one float32 rounding of values
    below 1). Control: the calls left as written, both paths refuse them."""
    pixels, _ = _render(tmp_path, language, BODY, includes=OBJECTS, properties=PROPERTIES)
    want = np.array([0.25, 0.625, 0.375])
    assert (np.abs(pixels[:, :3] - want) <= 2.0 ** -24).all(), pixels[0, :3]
    monkeypatch.setattr(texture_objects, "_built_members_spelled_out", lambda text: text)
    (tmp_path / "old").mkdir()
    with pytest.raises(PbrlabError):
        _render(tmp_path / "old", language, BODY, includes=OBJECTS, properties=PROPERTIES)


# --- a lookup's offset passed down as a parameter -------------------------------------------------
OFFSET_SHADER = Path(__file__).parent / "shaders" / "urp_sample_offset_parameter.shader"


def _grid(path: Path) -> np.ndarray:
    """A 4 x 4 single-channel grid, texel (x, y) (y up from the image's bottom row, as Unity's v)
    = 17 * (x + 4 y) / 255, written linear; returned as the values the shader reads."""
    values = np.array([[17 * (x + 4 * y) for x in range(4)] for y in range(4)], np.uint8)
    Image.fromarray(np.repeat(values[::-1, :, None], 3, axis=2)).save(path)
    return values / 255.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_lookup_offset_passed_as_a_parameter(tmp_path, language, monkeypatch):
    """FXC inlines every call, so ``t.Sample(s, uv, delta * -1)`` with ``delta`` a parameter is an
    immediate offset (Microsoft's HLSL reference, "Sample": the offset is in texels); uv is texel
    (1, 1)'s centre, so each bilinear read is one texel: across = grid(0,1), grid(2,1), grid(3,1);
    up = grid(1,0), grid(1,2), grid(1,3); the pixel is across * 0.5 + up * 0.25. Bound: the texels
    are k / 255 in float32 (2^-24 relative) and two products and a sum round once each:
    4 * 2^-24. Control: the function as written, refused by both paths (a parameter offset)."""
    grid = _grid(tmp_path / "grid.png")
    across = np.array([grid[1, 0], grid[1, 2], grid[1, 3]])
    up = np.array([grid[0, 1], grid[2, 1], grid[3, 1]])
    want = across * 0.5 + up * 0.25
    shader = tmp_path / OFFSET_SHADER.name
    shader.write_text(OFFSET_SHADER.read_text())
    properties = {"_Grid": {"path": str(tmp_path / "grid.png"), "srgb": False}}
    pixels = _plane(shader, language, properties)
    assert pixels[..., 3].min() > 0
    assert (np.abs(pixels[..., :3] - want) <= 4 * 2.0 ** -24).all(), (pixels[0, 0, :3], want)
    monkeypatch.setattr(cg_spellings, "specialised_offsets", lambda text: text)
    old = tmp_path / "old"
    old.mkdir()
    (old / shader.name).write_text(shader.read_text().replace("offset parameter", "offset parameter old"))
    with pytest.raises(PbrlabError, match="constant|Sample"):
        _plane(old / shader.name, language, properties)
