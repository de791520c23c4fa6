"""What Unity fills for every pass and texture, which pbrlab once left unset or ignored (issue
34's built-in gaps): ``<texture>_TexelSize`` (1/w, 1/h, w, h), ``<texture>_HDR`` (DecodeHDR's
instructions: the identity for pbrlab's linear and float textures), and a pass's ``ColorMask``
(the channels it writes; alpha is the target's coverage)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.material import color_mask
from pbrlab.render.renderer import render_scene

PASS = """
Shader "t/{name}" {{
    Properties {{ _MainTex ("Texture", 2D) = "white" {{}} }}
    SubShader {{ Pass {{
        {state}
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        sampler2D _MainTex;
        float4 _MainTex_TexelSize;
        half4 _MainTex_HDR;
        struct v2f {{ float4 pos : SV_POSITION; }};
        v2f vert(appdata_base v) {{ v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }}
        fixed4 frag(v2f i) : SV_Target {{ return {colour}; }}
        ENDCG
    }} }}
}}
"""


def _render(tmp_path, language, name, colour, state="", texture=None):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(PASS.format(name=name, colour=colour, state=state)))
    data = corpus.scene_for(shader)
    if texture is not None:
        data["materials"]["m"]["properties"] = {"_MainTex": {"path": str(texture)}}
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear


@pytest.fixture
def texture(tmp_path):
    from pbrlab.foundation.images import write_png
    path = tmp_path / "five_by_three.png"
    write_png(path, np.full((3, 5, 4), 128, np.uint8))
    return path


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_texel_size_and_hdr_are_unitys(tmp_path, texture, language):
    """A 5 x 3 texture: _TexelSize (0.2, 1/3, 5, 3); _HDR (1, 1, 0, 0), so DecodeHDR is the
    identity (its x multiplies, y is alpha's exponent, w says whether alpha counts)."""
    size = _render(tmp_path, language, "texel", "float4(_MainTex_TexelSize.x * 5, _MainTex_TexelSize.y * 3, "
                   "_MainTex_TexelSize.z / 5, _MainTex_TexelSize.w / 3)", texture=texture)
    covered = size[..., 3] > 0
    assert covered.mean() > 0.3
    np.testing.assert_allclose(size[covered], 1.0, rtol=1e-6)
    hdr = _render(tmp_path, language, "hdr", "float4(_MainTex_HDR)", texture=texture)
    np.testing.assert_array_equal(hdr[hdr[..., 3] > 0][:, :3], np.broadcast_to([1.0, 1.0, 0.0], (int((hdr[..., 3] > 0).sum()), 3)))


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_pass_writes_only_its_colour_mask(tmp_path, language):
    """ColorMask RGB leaves the target's alpha (coverage) as it was; ColorMask 0 writes no
    colour (depth only: the background stays black); the default writes all four."""
    white = "fixed4(1, 1, 1, 1)"
    full = _render(tmp_path, language, "full", white)
    rgb = _render(tmp_path, language, "rgb", white, state="ColorMask RGB")
    none = _render(tmp_path, language, "none", white, state="ColorMask 0")
    covered = full[..., 3] > 0
    assert covered.mean() > 0.3 and (full[covered][:, :3] == 1).all()
    assert (rgb[covered][:, :3] == 1).all() and (rgb[..., 3] == 0).all()
    assert not none.any()


def test_color_mask_words_and_numbers():
    assert color_mask("RGB") == (True, True, True, False)
    assert color_mask("a") == (False, False, False, True)
    assert color_mask("0") == (False, False, False, False)
    assert color_mask("15") == (True, True, True, True)  # ColorWriteMask.All, as a [_ColorMask] property
    assert color_mask("14") == (True, True, True, False)
