"""Real Unity shaders nobody on this project wrote (corpus/unity/: Unity's 2019.4 built-in
shaders and shaders from public repositories, corpus/unity/public/MANIFEST.json), each
rendered as a new user would (pbrlab.checking.unity_corpus: a UV sphere under a directional and a
point light and the sky) in HLSL and in GLSL.

Every shader must end in one of two ways, the same in both languages: rendered (every pixel
finite, GLSL and HLSL agreeing), or refused with a message naming the Unity feature that is
missing. A traceback or a non-finite pixel always fails. A compiler's error instead of a
named refusal is a defect of the front end: the ones still there are listed as
``"defect: ..."`` in corpus/unity/expected.json and in docs/unity.md, and must stay exactly
those. Which shaders render is pinned there too (``python -m pbrlab.checking.unity_corpus corpus/unity
--expect corpus/unity/expected.json`` rewrites it after a reviewed change), so a shader that
stops rendering fails, and one that starts to fails until the figures in docs/unity.md move
with it.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pbrlab.checking import unity_corpus as corpus

ROOT = Path(__file__).resolve().parents[3] / "corpus" / "unity"
EXPECTED = json.loads((ROOT / "expected.json").read_text(encoding="utf-8"))
SHADERS = [p.relative_to(ROOT).as_posix() for p in corpus.corpus_shaders(ROOT)]
# GLSL (the port) against HLSL (as written) of one shader, largest relative difference with a
# 1e-3 floor (corpus.agreement): most are bit-identical; a vertex stage of each language
# places vertices a few ulp apart (mul(M, v) vs M * v, fused differently), which moves
# interpolated values by up to ~1e-5 relative (docs/unity.md, "Unity shaders"); bound 1e-4.
AGREEMENT_BOUND = 1e-4
# Rendered shaders that draw no colour with their Properties' defaults in the corpus scene, each
# as Unity would: a blank pair is checked blank in both languages (and fails once it draws,
# so this list only shrinks); every other rendered shader must draw something.
BLANK_BY_DEFAULT = {
    "builtin-2019.4/DefaultResourcesExtra/Internal-GUIRoundedRect.shader":
        "_Rect and _BorderWidths are zero (the IMGUI sets them): a rectangle of no size",
    "builtin-2019.4/DefaultResourcesExtra/Internal-GUIRoundedRectWithColorPerBorder.shader":
        "_Rect and _BorderWidths are zero (the IMGUI sets them): a rectangle of no size",
    "builtin-2019.4/DefaultResourcesExtra/Internal-GUITextureClipText.shader":
        "alpha times _GUIClipTexture, which the IMGUI binds and no Property declares: 0",
    "builtin-2019.4/DefaultResourcesExtra/Flare.shader":
        "_MainTex defaults to black and the pass adds it (Blend One One)",
    "builtin-2019.4/DefaultResourcesExtra/TerrainShaders/Splats/Standard-BaseGen.shader":
        "weights from _Control, which the terrain binds and no Property declares: 0",
    "public/keijiro__Skinner/Assets/Skinner/Shader/GlitchSurface.shader":
        "vertices read from _PositionBuffer (the simulation's render target; default empty): all at one point",
    "public/keijiro__Skinner/Assets/Skinner/Shader/ParticleSurfaceStandard.shader":
        "vertices read from _PositionBuffer (the simulation's render target; default empty): all at one point",
    "public/keijiro__Skinner/Assets/Skinner/Shader/TrailSurface.shader":
        "vertices read from _PositionBuffer (the simulation's render target; default empty): all at one point",
    "public/ronja-tutorials__ShaderTutorials/Assets/038_Dissolve/Dissolve.shader":
        "clip(tex2D(_DissolveTex).r - _DissolveAmount): the texture defaults to black, the amount to 0.5",
    # black in colour (what a person sees) with their defaults, though they cover the sphere
    "builtin-2019.4/DefaultResourcesExtra/Compositing.shader":
        "_AlphaParam * _MainTex + _SecondAlphaParam * _SecondTex: both textures default to black",
    "builtin-2019.4/DefaultResourcesExtra/Internal-StencilWrite.shader":
        "writes the stencil; its fragment returns fixed4(0, 0, 0, 0)",
    "builtin-2019.4/DefaultResourcesExtra/VR/Shaders/SpatialMappingOcclusion.shader":
        "ColorMask 0 and a fragment returning 0: it occludes, it draws no colour",
    "builtin-2019.4/DefaultResourcesExtra/VideoComposite.shader":
        "fixed4(tex2D(_MainTex).rgb, ...): _MainTex defaults to black (the video player binds the frame)",
    "builtin-2019.4/DefaultResourcesExtra/GIDebug/ShowLightMask.shader":
        "discards every fragment: dot(_ChannelSelect, texel) is 0 with _ChannelSelect unset (no Property; the "
        "GI debug view sets it); on the corpus scene's lightmapped sphere (unity_LightmapST)",
    "builtin-2019.4/DefaultResourcesExtra/Internal-BlitToDepth.shader":
        "ColorMask 0 (ZWrite On): it copies a depth texture into the depth buffer, no colour",
    "builtin-2019.4/DefaultResourcesExtra/Internal-BlitToDepth_MSAA.shader":
        "ColorMask 0 (ZWrite On): it resolves a multisampled depth texture into the depth buffer, no colour",
    "builtin-2019.4/DefaultResourcesExtra/VR/Shaders/BlitTexArraySliceToDepth.shader":
        "ColorMask 0 (ZWrite On): it copies a layer of a depth texture array into the depth buffer, no colour",
    "builtin-2019.4/DefaultResourcesExtra/VR/Shaders/BlitTexArraySliceToDepth_MSAA.shader":
        "ColorMask 0 (ZWrite On): it resolves a layer of a multisampled depth texture array into the depth "
        "buffer, no colour (its read is under SHADER_API_D3D11; the variant drawn writes depth 0.9)",
    "builtin-2019.4/DefaultResourcesExtra/TerrainShaders/Utils/CrossBlendNeighbors.shader":
        "PackHeightmap of heights from _TopTex/_BottomTex/_LeftTex/_RightTex, which default to black, plus "
        "_Offsets (no Property; the terrain sets it): 0",
    "builtin-2019.4/DefaultResourcesExtra/TerrainShaders/Utils/TerrainHeightBlitCopy.shader":
        "PackHeightmap(height * _Height_Scale + _Height_Offset): neither has a Property (the terrain sets "
        "them), so both are 0",
    "builtin-2019.4/DefaultResourcesExtra/Internal-MotionVectors.shader":
        "camera motion of a still camera (the previous frame's matrices are this one's): (0, 0, 0, 1) "
        "at every pixel (tests/importers/unity/test_engine_set_inputs.py)",
    "builtin-2019.4/DefaultResourcesExtra/Sprites-Mask.shader":
        "ColorMask 0: a sprite mask writes the stencil only (it drew white while ColorMask was ignored)",
    # their Category's Blend (read since Category commands reach its SubShaders) multiplies what
    # lies behind the sphere: the black background (they drew unblended while it was dropped)
    "builtin-2019.4/DefaultResourcesExtra/Particle Blend.shader":
        "Blend DstColor One (a Category's): colour times the target, the black background",
    "builtin-2019.4/DefaultResourcesExtra/Particle Multiply.shader":
        "Blend Zero SrcColor (a Category's): the target times the colour, the black background",
    "builtin-2019.4/DefaultResourcesExtra/Particle MultiplyDouble.shader":
        "Blend DstColor SrcColor (a Category's): both terms times the target, the black background",
    "builtin-2019.4/DefaultResourcesExtra/Mobile/Mobile-Particle-Multiply.shader":
        "Blend Zero SrcColor (a Category's; a fixed-function pass): the target times the colour, the "
        "black background",
    "builtin-2019.4/DefaultResourcesExtra/UI/UI-Lit-RefractionDetail.shader":
        "the refraction mask defaults to white, so the colour is the GrabPass of what lies behind: the "
        "black background",
    "public/ronja-tutorials__ShaderTutorials/Assets/006_Transparency/transparent.shader":
        "col *= _Color, whose default is (0, 0, 0, 1)",
    "public/ronja-tutorials__ShaderTutorials/Assets/010_Triplanar_Mapping/triplanar_mapping.shader":
        "col *= _Color, whose default is (0, 0, 0, 1)",
    "public/ronja-tutorials__ShaderTutorials/Assets/013_CustomSurfaceLighting/CustomLighting.shader":
        "col *= _Color, whose default is (0, 0, 0, 1)",
    "public/ronja-tutorials__ShaderTutorials/Assets/020_Inverted_Hull/UnlitOutlines.shader":
        "col *= _Color and the outline is _OutlineColor, both defaulting to (0, 0, 0, 1)",
    "public/ronja-tutorials__ShaderTutorials/Assets/040_Halftone_Lighting/HalftoneShading.shader":
        "col *= _Color, whose default is (0, 0, 0, 1)",
    "public/ronja-tutorials__ShaderTutorials/Assets/044_SphereTracingShading/SphereTracingShading.shader":
        "the surface colour is _Color, whose default is (0, 0, 0, 1)",
}


def test_corpus_lists_every_shader_once():
    assert sorted(EXPECTED) == sorted(SHADERS)
    assert all(EXPECTED[s] == "rendered" for s in BLANK_BY_DEFAULT)


@pytest.mark.parametrize("shader", SHADERS)
def test_corpus_shader_renders_or_is_refused_by_name(shader):
    """Rendered in both languages, agreeing and drawing (or known blank); or refused in both,
    each naming what is missing, one naming the pinned outcome (the languages may name different
    parts: the first error of each compiler); or a pinned defect (corpus.outcome_problems)."""
    outcomes = {lang: corpus.run_shader(ROOT / shader, lang) for lang in corpus.LANGUAGES}
    problems = corpus.outcome_problems(EXPECTED[shader], outcomes, BLANK_BY_DEFAULT.get(shader), AGREEMENT_BOUND)
    assert not problems, problems