"""Real URP shaders nobody on this project wrote (corpus/urp/: public MIT, Apache-2.0 and CC0
repositories, corpus/urp/MANIFEST.json), each rendered in both languages or refused naming what
pbrlab lacks, as pinned in corpus/urp/expected.json (``python -m pbrlab.checking.unity_corpus
corpus/urp --expect corpus/urp/expected.json`` rewrites it after a reviewed change). The rules
are the built-in corpus's (pbrlab.checking.unity_corpus.outcome_problems, tests/importers/unity/
test_corpus.py): a rendered pair agrees (GLSL port against HLSL as written, the same 1e-4
bound and reason) and draws; a refusal names a Unity feature, not a compiler's error, unless
the pin says "defect:" (a known front-end gap, listed in docs/unity.md)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pbrlab.checking import unity_corpus as corpus

ROOT = Path(__file__).resolve().parents[3] / "corpus" / "urp"
EXPECTED = json.loads((ROOT / "expected.json").read_text(encoding="utf-8"))
SHADERS = [p.relative_to(ROOT).as_posix() for p in corpus.corpus_shaders(ROOT)]
# As tests/importers/unity/test_corpus.py: most pairs are bit-identical; the two languages'
# vertex stages place vertices a few ulp apart, moving interpolated values by ~1e-5 relative.
AGREEMENT_BOUND = 1e-4
# Rendered shaders that draw no colour with their Properties' defaults in the corpus scene, each
# as Unity would (tests/importers/unity/test_corpus.py's rule): checked black in both languages,
# failing once they draw colour, so this list only shrinks.
BLANK_BY_DEFAULT = {
    "VKev__Unity-URP-Shaders-Code/Assets/Shaders/Object_Shader/Glow_Shader/URP_Glow.shader":
        "lerp(_BackgroundColor, _CoreColor, ...) * _GlowIntensity: both colours default to (0, 0, 0, 0)",
    "decentraland__unity-renderer/unity-renderer/Assets/Rendering/Shaders/ToonBasicOutline.shader":
        "the outline pass returns _OutlineColor, whose default is (0, 0, 0, 1)",
    "VKev__Unity-URP-Shaders-Code/Assets/Shaders/Object_Shader/Basic_Shader/BlinnPhong_Shader/URP_BlinnPhong.shader":
        "Blend [_SrcBlend] [_DstBlend] with both defaults 0: Blend Zero Zero writes 0 (its CustomEditor "
        "URP_BlinnPhong_Editor sets them in Unity)",
    "Delt06__urp-toon-shader/Packages/com.deltation.toon-shader/Assets/DELTation/ToonShader/Shaders/InvertedHullOutline.shader":
        "the outline shell's colour is _Color, whose default is (0, 0, 0, 0): a black shell around the sphere",
    "VKev__Unity-URP-Shaders-Code/Assets/Shaders/Object_Shader/Toon_Shader/URP_Toon.shader":
        "_LightMaxIntensity defaults to 0, which scales every toon band: black",
    "decentraland__unity-renderer/unity-renderer/Assets/Rendering/Shaders/Toon/Compiled/ToonShaderCompiled.shader":
        "its graph ends in Shader Graph's Fog node, lerp(colour, fog colour, 1 - density): outside fog (no fog "
        "keyword, as here) URP's node gives density 0, so the pixel is the fog colour, black here (pbrlab has no "
        "fog; Unity's is its Lighting settings' colour). Checked with density 1: it draws colour (its default matcaps are white)",
    "ColinLeung-NiloCat__UnityURPUnlitScreenSpaceDecalShader/URP_NiloCatExtension_ScreenSpaceDecal_Unlit.shader":
        "a screen-space decal: it projects the scene's depth (its own sampler2D _CameraDepthTexture, the depth "
        "pre-pass of the opaque queues, render/camera_textures.py) into its box and clips what falls outside; "
        "its own sphere is of queue Transparent-499 (2501), so the depth texture holds the far plane only: black",
}


def test_corpus_lists_every_shader_once():
    assert sorted(EXPECTED) == sorted(SHADERS)
    assert all(EXPECTED[s] == "rendered" for s in BLANK_BY_DEFAULT)
    manifest = json.loads((ROOT / "MANIFEST.json").read_text(encoding="utf-8"))
    assert sorted(entry["path"] for entry in manifest) == sorted(SHADERS)


# Rendered shaders that hash the world position into an angle (frac(sin(dot(p, k)) * 43758.5)):
# the vertex stages' few-ulp difference between the two languages' compilers is multiplied by
# ~43758 in the hash, so each grass blade's angle, and with it its shading, differs by an amount
# no float32 analysis bounds (measured once: 3 of 4096 pixels over AGREEMENT_BOUND, up to 7 %).
# Their two images are not compared per pixel; both must still render and draw.
HASHED_ANGLES = {
    "Cyanilux__URP_GrassGeometryShader/GrassGeometry/GeoGrass.shader":
        "rand(positionWS) turns each grass blade (Grass.hlsl)",
}


# Known defects, each a strict expected failure so that its fix shows.
KNOWN_DEFECTS: dict = {}


@pytest.mark.parametrize("shader", [pytest.param(s, marks=pytest.mark.xfail(strict=True, reason=KNOWN_DEFECTS[s]))
                                    if s in KNOWN_DEFECTS else s for s in SHADERS])
def test_urp_corpus_shader_renders_or_is_refused_by_name(shader):
    outcomes = {lang: corpus.run_shader(ROOT / shader, lang) for lang in corpus.LANGUAGES}
    bound = float("inf") if shader in HASHED_ANGLES else AGREEMENT_BOUND
    problems = corpus.outcome_problems(EXPECTED[shader], outcomes, BLANK_BY_DEFAULT.get(shader), bound)
    assert not problems, problems


def test_the_outcome_check_fails_where_it_should():
    """A control of the shared check: a traceback, a disagreeing pair, a blank render and a
    compiler error unpinned are each reported."""
    import numpy as np
    lit = np.ones((2, 2, 4), np.float32)
    good = {"glsl": corpus.Outcome("s", "glsl", "rendered", image=lit), "hlsl": corpus.Outcome("s", "hlsl", "rendered", image=lit)}
    assert corpus.outcome_problems("rendered", good) == []
    off = dict(good, hlsl=corpus.Outcome("s", "hlsl", "rendered", image=lit * 1.01))
    assert corpus.outcome_problems("rendered", off)
    blank = {k: corpus.Outcome("s", k, "rendered", image=lit * 0) for k in good}
    assert corpus.outcome_problems("rendered", blank) == ["drew nothing"]
    crash = dict(good, glsl=corpus.Outcome("s", "glsl", "traceback", "Traceback ..."))
    assert corpus.outcome_problems("rendered", crash)
    compiler = {k: corpus.Outcome("s", k, "refused", "vertex shader failed to compile:\nx.shader:3:1: error: syntax error")
                for k in good}
    assert corpus.outcome_problems("x", compiler)


def test_black_renders_are_counted_apart(tmp_path):
    """The corpus summary's black count (unity_corpus.draws_black): a render whose RGB rounds to
    sRGB code 0 everywhere is black, alpha notwithstanding; one code step of colour is not
    (the control), nor a NaN (the non-finite outcome's)."""
    import numpy as np
    image = np.zeros((4, 4, 4))
    image[..., 3] = 1.0
    image[0, 0, :3] = corpus.BLACK_LEVEL
    assert corpus.draws_black(image)
    image[0, 0, 1] = 1 / 255 / 12.92  # sRGB code 1
    assert not corpus.draws_black(image)
    image[0, 0, 1] = np.nan
    assert not corpus.draws_black(image)
    # run_corpus reports them apart: a shader of the corpus scene drawing (0, 0, 0, 1)
    (tmp_path / "black.shader").write_text(
        'Shader "t/black" { SubShader { Tags { "RenderPipeline" = "UniversalPipeline" } Pass {\n'
        "HLSLPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n"
        '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"\n'
        "float4 vert(float4 p : POSITION) : SV_POSITION { return TransformObjectToHClip(p.xyz); }\n"
        "float4 frag() : SV_Target { return float4(0.0, 0.0, 0.0, 1.0); }\nENDHLSL } } }\n")
    report = corpus.run_corpus(tmp_path)
    assert (report["rendered_in_both"], report["black_in_both"], report["black"]) == (1, 1, ["black.shader"])
