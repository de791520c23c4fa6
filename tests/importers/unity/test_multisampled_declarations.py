"""Direct3D's multisampled texture objects (``Texture2DMS<T>``, ``Texture2DMSArray<T>``;
importers/unity/multisampled_textures.py): a program that declares one and reads it only where
Unity reads it on Direct3D 11 (``#ifdef SHADER_API_D3D11``, which the harness leaves undefined,
compiling as Unity's other platforms do) runs in both languages, its declaration ported as GLSL's
``sampler2DMSArray``; one that reads it in the drawn variant is refused by name (a material
cannot bind a multisampled texture)."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.multisampled_textures import declarations_ported, first_read
from pbrlab.render.renderer import render_scene

COLOUR = (0.25, 0.5, 0.75)
SHADER = """
Shader "t/ms" {{
    Properties {{ _MainTex ("Texture", any) = "" {{}} }}
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #pragma target 5.0
        #include "UnityCG.cginc"
        Texture2DMSArray<float> _MainTex;
        float4 _MainTex_ST;
        struct v2f {{ float4 pos : SV_POSITION; float2 uv : TEXCOORD0; }};
        v2f vert (appdata_base v) {{
            v2f o; o.pos = UnityObjectToClipPos(v.vertex);
            o.uv = TRANSFORM_TEX(v.texcoord.xy, _MainTex); return o;
        }}
        float4 frag (v2f i) : SV_Target {{
        {guard}
            return float4(_MainTex.Load(int3(i.uv * 4, 0), 0).xxx, 1);
        #else
            return float4({colour}, 1);
        #endif
        }}
        ENDCG
    }} }}
}}
"""


def _render(tmp_path, language, guard):
    shader = tmp_path / "ms.shader"
    shader.write_text(textwrap.dedent(SHADER.format(guard=guard, colour=", ".join(map(str, COLOUR)))))
    return render_scene(parse_scene(corpus.scene_for(shader), "t", tmp_path), language=language).linear


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_declared_multisampled_array_read_only_on_d3d11_draws_the_other_branch(tmp_path, language):
    """Every covered pixel is the #else branch's constant (a float32 constant written to a float
    target: exact, 0 tolerance); the sphere covers a third of the image or more."""
    image = _render(tmp_path, language, "#ifdef SHADER_API_D3D11")
    covered = image[..., 3] > 0
    assert covered.mean() > 0.3
    assert np.array_equal(image[covered][:, :3], np.broadcast_to(np.float32(COLOUR), (int(covered.sum()), 3)))


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_multisampled_array_read_in_the_drawn_variant_is_refused_by_name(tmp_path, language):
    """The control: the same program reading the texture in the branch the harness draws."""
    with pytest.raises(PbrlabError, match=r"ms\.shader:\d+: uses _MainTex, part of multisampled textures"):
        _render(tmp_path, language, "#ifndef SHADER_API_D3D11")


def test_the_declaration_is_glsls_multisampled_sampler():
    assert declarations_ported("Texture2DMSArray<float> t;\nTexture2DMS<float4, 4> u;") == \
        "uniform sampler2DMSArray t;\nuniform sampler2DMS u;"
    assert first_read("Texture2DMS<float> t;\nfloat2 uv = TRANSFORM_TEX(v.uv, t);") is None  # t_ST
    assert first_read("Texture2DMS<float> t;\nfloat x = t.Load(int2(0, 0), 0).x;")[0] == "t"
