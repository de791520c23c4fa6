"""3D (volume) textures in Unity programs (issue 34): Cg's sampler3D / tex3D / tex3Dlod,
HLSLSupport.cginc's UNITY_DECLARE_TEX3D / UNITY_SAMPLE_TEX3D(_LOD) and Core RP's TEXTURE3D /
SAMPLE_TEXTURE3D(_LOD), with a 3D property bound to a 1x1x1 volume holding its
default texture (Unity's default-texture names: properties.DEFAULT_TEXELS), in both languages.
Before, tex3D was no function of GLSL's and glslang's Texture3D met a 2D texture (refused).

Scene: the corpus scene's sphere (tests/importers/urp/test_urp_scene_textures.py style), every
covered pixel checked. A 1x1x1 texture's every lookup (any uvw, any filter, any mip: it has one
texel and one level) is that texel, so the pixel is texel * 0.5 + 0.25 up to the float32
rounding of that product: 1 ulp of values <= 0.75, bounded by 2^-24.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")

BUILTIN_SHADER = """
Shader "t/volume builtin" {
    Properties { _Volume ("Volume", 3D) = "red" {} }
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            sampler3D _Volume;
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target {
                float4 a = tex3D(_Volume, float3(0.3, 0.6, 0.2));
                float4 b = tex3Dlod(_Volume, float4(0.9, 0.1, 0.7, 0.0));
                return float4(a.rg, b.b, 1.0) * 0.5 + 0.25;
            }
            ENDCG
        }
    }
}
"""

URP_SHADER = """
Shader "t/volume urp" {
    Properties { _Volume ("Volume", 3D) = "red" {} }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" }
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            TEXTURE3D(_Volume); SAMPLER(sampler_Volume);
            float4 vert(float4 v : POSITION) : SV_POSITION { return TransformObjectToHClip(v.xyz); }
            float4 frag() : SV_Target {
                float4 a = SAMPLE_TEXTURE3D(_Volume, sampler_Volume, float3(0.3, 0.6, 0.2));
                float4 b = SAMPLE_TEXTURE3D_LOD(_Volume, sampler_Volume, float3(0.9, 0.1, 0.7), 0.0);
                return float4(a.rg, b.b, 1.0) * 0.5 + 0.25;
            }
            ENDHLSL
        }
    }
}
"""
# HLSLSupport.cginc's macros for the same (the Cg program of BUILTIN_SHADER otherwise)
MACRO_SHADER = BUILTIN_SHADER.replace("sampler3D _Volume;", "UNITY_DECLARE_TEX3D(_Volume);").replace(
    "tex3D(_Volume, float3(0.3, 0.6, 0.2))", "UNITY_SAMPLE_TEX3D(_Volume, float3(0.3, 0.6, 0.2))").replace(
    "tex3Dlod(_Volume, float4(0.9, 0.1, 0.7, 0.0))", "UNITY_SAMPLE_TEX3D_LOD(_Volume, float3(0.9, 0.1, 0.7), 0.0)")
BOUND = 2.0 ** -24


def _scene(shader_text: str, tmp_path, properties=None):
    shader = tmp_path / "volume.shader"
    shader.write_text(textwrap.dedent(shader_text))
    data = corpus.scene_for(shader)
    if properties is not None:
        data["materials"]["m"]["properties"] = properties
    return parse_scene(data, origin="volume-texture test scene", base=shader.parent)


def _covered_rgb(scene, language):
    image = render_scene(scene, language=language).linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 1000
    return image[..., :3][covered]


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("shader", [BUILTIN_SHADER, MACRO_SHADER, URP_SHADER], ids=["cg", "unity_macros", "core_rp"])
def test_volume_property_default_is_its_texel(tmp_path, shader, language):
    """The default "red" (1, 0, 0, 1) gives (0.75, 0.25, 0.25); the material naming "gray"
    (0.5 each, Unity's gray) gives 0.5. Control: each is outside the other's bound (the property's
    value, not a constant, reaches the pixel), and "white" (the value a lookup of a texture
    bound wrongly or a stand-in would give) differs in g and b."""
    red = _covered_rgb(_scene(shader, tmp_path), language)
    gray = _covered_rgb(_scene(shader, tmp_path, {"_Volume": "gray"}), language)
    assert (np.abs(red - [0.75, 0.25, 0.25]) <= BOUND).all(), np.abs(red - [0.75, 0.25, 0.25]).max()
    assert (np.abs(gray - 0.5) <= BOUND).all(), np.abs(gray - 0.5).max()
    assert (np.abs(red - 0.5) > BOUND).any(axis=-1).all()  # control: not the gray
    assert (np.abs(red[:, 1:] - 0.75) > BOUND).all()       # control: not white


def test_volume_property_with_a_file_is_refused(tmp_path):
    """A 3D property given an image file: pbrlab reads no volume format, so it is refused by
    name at the material's property, not bound as a 2D image."""
    (tmp_path / "v.png").write_bytes(b"")
    with pytest.raises(PbrlabError, match=r"properties\._Volume\.path: a 3D \(volume\) texture"):
        _scene(BUILTIN_SHADER, tmp_path, {"_Volume": {"path": "v.png"}})
