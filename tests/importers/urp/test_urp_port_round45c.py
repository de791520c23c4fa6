"""The GLSL port and FXC (issue 34's hidden7 URP sample, session 45, third round: measured, not
committed): constructs FXC accepts that the GLSL port refused, each in a minimal URP shader of
ours drawn in both languages, a pixel against float64 and a control (the old behaviour restored).

Scene and readback: test_urp_library_round2.render_constant (a unit sphere; every covered pixel)."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import port
from test_urp_library_round2 import render_constant, urp_pass  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")
# Sums and products of dyadic fractions (a white texel, 1, 0.5, 0.25) are exact in float32; the
# framebuffer's float32 readback is exact too: 2 ulps of 1 bound it.
EXACT = 2 * 2.0 ** -24

def _with_properties(properties: str, name: str, body: str, include: str) -> str:
    """urp_pass's shader with a Properties block (the material's values the checks read)."""
    return urp_pass(name, body, include).replace("    SubShader {", f"    Properties {{ {properties} }}\n    SubShader {{", 1)


# ylvgn's MY_TEXTURE2D: a macro of the shader's own that declares a texture, its tiling and its
# sampler, used at file scope.
DECLARING_MACRO = _with_properties('_MainTex ("t", 2D) = "white" {}', "declaring macro", """
                float4 c = SAMPLE_TEXTURE2D(_MainTex, sampler_MainTex, float2(0.5, 0.5));
                return float4(c.r * 0.5, _MainTex_ST.x * 0.25, _MainTex_ST.z + 0.5, 1);""", """
            #define MY_TEXTURE(T) \\
                TEXTURE2D(T); \\
                float4 T##_ST; \\
                SAMPLER(sampler##T);
            MY_TEXTURE(_MainTex);""")

# MasonJohnHawver42's GrassPass.hlsl: a file of the project's, included after URP's
# SurfaceInput.hlsl, samples _BaseMap (which SurfaceInput declares) through its method, and adds
# a float4 property to a float3.
SIBLING_INCLUDE = """
float4 _Tint;
half3 sibling_colour() {
    float4 s = _BaseMap.Sample(sampler_BaseMap, float2(0.5, 0.5));
    half3 color = _Tint + s.rgb * 0.25;
    return color;
}
"""
SIBLING_SHADER = _with_properties('_BaseMap ("b", 2D) = "white" {} _Tint ("t", Color) = (0.25, 0.5, 0.75, 1)',
                                  "sibling texture", "return half4(sibling_colour(), 1);",
                                  '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceInput.hlsl"\n'
                                  '#include "sibling_pass.hlsl"')


def _pixels(tmp_path, language, text):
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    return pixels[:, :3]


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_macro_that_declares_a_texture_declares_uniforms(tmp_path, language, monkeypatch):
    """The macro's expansion is a file-scope declaration, and FXC makes a global without
    ``static`` a uniform (Microsoft's HLSL reference, "Variable syntax"): the white texture reads
    1 and _MainTex_ST is the material's (1, 1, 0, 0) (Unity's manual, "Accessing shader
    properties in Cg/HLSL": {TextureName}_ST), so the pixel is (0.5, 0.25, 0.5). Control: the
    body left as before, the GLSL port is refused ("image/sampler variables may only be
    declared as function parameters or uniform-qualified global variables")."""
    pixels = _pixels(tmp_path, language, DECLARING_MACRO)
    assert np.abs(pixels - np.array([0.5, 0.25, 0.5])).max() <= EXACT
    if language == "glsl":
        monkeypatch.setattr(port, "_uniforms_in_declaring_defines", lambda code: code)
        with pytest.raises(PbrlabError, match="uniform-qualified"):
            _pixels(tmp_path, language, DECLARING_MACRO)


def test_a_macro_whose_texture_is_a_parameter_is_left_alone():
    """A body that names a texture as a parameter (no ``;`` after it) declares no global."""
    text = "#define MY_PARAM(T) sampler2D T, vec4 T##_ST\nvec4 f(MY_PARAM(t)) { return T##_ST; }"
    assert port._uniforms_in_declaring_defines(text) == text


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_texture_another_include_declares_is_sampled_by_its_method(tmp_path, language, monkeypatch):
    """``_BaseMap.Sample(sampler_BaseMap, uv)`` in a file that does not declare _BaseMap: the
    object SurfaceInput.hlsl declares (Microsoft's HLSL reference, "Sample (DirectX HLSL Texture
    Object)"), the white texel 1; ``half3 color = _Tint + s.rgb * 0.25`` truncates the float4
    (FXC warning X3206, "Implicit conversions"): (0.5, 0.75, 1.0). Control: the includes'
    textures unknown (the old reading), the GLSL port is refused ("unknown method" / "vector
    size mismatch")."""
    (tmp_path / "sibling_pass.hlsl").write_text(SIBLING_INCLUDE)
    pixels = _pixels(tmp_path, language, SIBLING_SHADER)
    assert np.abs(pixels - np.array([0.5, 0.75, 1.0])).max() <= EXACT
    if language == "glsl":
        monkeypatch.setattr(port, "texture_kinds", lambda text: {})
        with pytest.raises(PbrlabError, match="unknown method|size mismatch"):
            _pixels(tmp_path, language, SIBLING_SHADER)
