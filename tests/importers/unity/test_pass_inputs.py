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


LIT = """
Shader "t/lit" {
    Properties { _NL ("n.l", Float) = 0.5  _NH ("n.h", Float) = 0.5  _M ("m", Float) = 8 }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        float _NL, _NH, _M;
        struct v2f { float4 pos : SV_POSITION; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }
        fixed4 frag(v2f i) : SV_Target { float4 c = lit(_NL, _NH, _M); return float4(c.x, c.y, c.z, c.w * unity_StereoEyeIndex + 1); }
        ENDCG
    } }
}
"""


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("nl, nh, m", [(0.5, 0.5, 8.0), (0.7, 0.9, 20.0), (-0.2, 0.9, 4.0), (0.3, -0.1, 2.0)])
def test_lit_is_hlsls_lighting_coefficients(tmp_path, language, nl, nh, m):
    """HLSL's lit(n.l, n.h, m) = (1, max(n.l, 0), n.l < 0 or n.h < 0 ? 0 : (n.h)^m, 1) in both
    languages (glslang lowers the specular to n.h * m: 4 instead of 0.0039 at 0.5, 8, the
    control); unity_StereoEyeIndex is 0 (mono)."""
    shader = tmp_path / "lit.shader"
    shader.write_text(LIT)
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_NL": nl, "_NH": nh, "_M": m}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear
    covered = image[..., 3] > 0
    assert covered.mean() > 0.3
    want = np.array([1.0, max(nl, 0.0), 0.0 if nl < 0 or nh < 0 else nh ** m])
    np.testing.assert_allclose(image[covered][:, :3], np.broadcast_to(want, (int(covered.sum()), 3)),
                               rtol=1e-6, atol=1e-7)  # one pow in float32: a few ulp
    assert abs(nh * m - want[2]) > 1e-3 or nl < 0 or nh < 0  # the lowering glslang makes would fail here
