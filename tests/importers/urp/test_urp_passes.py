"""Which passes of a URP shader draw (issue 34): a program-less ``ColorMask 0`` pass (a stencil/
depth mask) draws as written, depth and no colour; passes of a custom LightMode tag draw as a
Render Objects renderer feature draws them where no other pass would; URP's own special tags stay
skipped. Shaders: tests/importers/urp/shaders/urp_depth_mask.shader and urp_custom_light_mode.shader.

Scenes: the corpus camera; the mask is a sphere of radius 0.5 in front of (and listed before) a
unit sphere whose URP pass returns COLOUR, so the pixel at the image centre shows whether the
mask wrote depth there.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene
from test_urp_library_round2 import urp_pass  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")
SHADERS = Path(__file__).resolve().parent / "shaders"
MASK = SHADERS / "urp_depth_mask.shader"
CUSTOM = SHADERS / "urp_custom_light_mode.shader"
# The colour the behind sphere's pass and the custom-tag pass return: multiples of 1/4, exact in
# half and float32, written to the float target unchanged (no blending, no tonemap in .linear),
# so the pixel equals it exactly.
COLOUR = (0.25, 0.5, 0.75)


def _render(tmp_path, language: str, objects: list, shaders: dict) -> np.ndarray:
    materials = {}
    for name, shader in shaders.items():  # a shader file, or a shader's text written to one
        if isinstance(shader, str):
            (tmp_path / f"{name}.shader").write_text(shader)
            shader = tmp_path / f"{name}.shader"
        materials[name] = {"surface": str(shader)}
    data = {"camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
            "lights": [], "materials": materials, "objects": objects}
    scene = parse_scene(data, origin="urp passes test scene", base=tmp_path)
    return render_scene(scene, language=language).linear.astype(np.float64)


def _mask_scene(tmp_path, language: str, mask) -> np.ndarray:
    colour = urp_pass("behind", f"return float4({COLOUR[0]}, {COLOUR[1]}, {COLOUR[2]}, 1.0);")
    objects = [{"mesh": {"primitive": "uv_sphere", "radius": 0.5}, "material": "mask",
                "transform": {"translate": [0.0, 0.0, 1.2]}},
               {"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "behind"}]
    return _render(tmp_path, language, objects, {"mask": mask, "behind": colour})


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_color_mask_0_pass_writes_depth_and_no_colour(tmp_path, language):
    """The mask's depth hides the sphere behind it and it writes no colour: the centre pixel is
    the black background (0, 0, 0); a pixel beside the mask shows COLOUR. Control: the same mask
    with ZWrite Off (a stencil-only mask, as WoBok's) leaves COLOUR at the centre too."""
    image = _mask_scene(tmp_path, language, MASK)
    centre, beside = image[24, 24, :3], image[24, 4, :3]
    assert centre.tolist() == [0.0, 0.0, 0.0]
    assert beside.tolist() == list(COLOUR)
    stencil_only = MASK.read_text().replace("ZWrite On", "ZWrite Off")
    control = _mask_scene(tmp_path, language, stencil_only)
    assert control[24, 24, :3].tolist() == list(COLOUR)


def test_a_mask_alone_renders_black_and_is_listed_as_drawing_no_colour():
    """The corpus outcome: rendered in both languages, black, and listed by its reason (the
    note says it draws no colour by its ColorMask and what it writes: depth and, by its Stencil
    block, stencil);
    the check then wants it black. Control: a rendered black image without the note is
    "drew nothing"."""
    outcomes = {lang: corpus.run_shader(MASK, lang) for lang in corpus.LANGUAGES}
    assert all(o.status == "rendered" for o in outcomes.values())
    reason = corpus.no_colour_reason(outcomes)
    assert reason is not None and "draws no colour by its ColorMask" in reason and "depth and stencil" in reason
    assert corpus.outcome_problems("rendered", outcomes) == []
    silent = {k: corpus.Outcome("s", k, "rendered", image=o.image) for k, o in outcomes.items()}
    assert corpus.no_colour_reason(silent) is None
    assert corpus.outcome_problems("rendered", silent) == ["drew nothing"]


def _sphere(tmp_path, language: str, shader) -> np.ndarray:
    return _render(tmp_path, language, [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}],
                   {"m": shader})


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_custom_light_mode_pass_draws_as_a_render_objects_feature_would(tmp_path, language):
    """Every pass is of a custom tag or URP's own ShadowCaster: the custom pass draws (the
    feature's), warned with its tag and the feature's name; the centre pixel is its colour."""
    with pytest.warns(UserWarning, match=r'LightMode "PbrlabHighlight".*Render Objects renderer feature'):
        image = _sphere(tmp_path, language, CUSTOM)
    assert image[24, 24, :3].tolist() == list(COLOUR)


def test_urp_own_tags_and_a_drawn_pass_keep_custom_passes_skipped(tmp_path):
    """Controls: the same pass tagged DepthOnly (URP's own) is skipped, so nothing draws (the old
    refusal); with the ShadowCaster pass retagged UniversalForward, the custom pass stays skipped
    (no feature is needed to draw the object) and that pass's red shows."""
    own = tmp_path / "own.shader"
    own.write_text(CUSTOM.read_text().replace('"PbrlabHighlight"', '"DepthOnly"'))
    with pytest.raises(PbrlabError, match="nothing here draws"):
        _sphere(tmp_path, "glsl", own)
    forward = textwrap.dedent(CUSTOM.read_text()).replace(
        'Name "ShadowCaster"\n            Tags { "LightMode" = "ShadowCaster" }',
        'Name "Forward"\n            Tags { "LightMode" = "UniversalForward" }')
    assert '"UniversalForward"' in forward
    image = _sphere(tmp_path, "glsl", forward)
    assert image[24, 24, :3].tolist() == [1.0, 0.0, 0.0]


# A custom Scriptable Render Pipeline's shader, as Unity's manual's SRP example writes one: no
# RenderPipeline tag, no URP include, HLSLPROGRAM declaring the matrices it reads, a custom tag.
SRP_ONLY = """
Shader "t/srp only" {
    SubShader {
        Pass {
            Tags { "LightMode" = "PbrlabCustomPipeline" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4x4 unity_MatrixVP;
            float4x4 unity_ObjectToWorld;
            struct Attributes { float4 positionOS : POSITION; };
            struct Varyings { float4 positionCS : SV_POSITION; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = mul(unity_MatrixVP, mul(unity_ObjectToWorld, IN.positionOS));
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target { return float4(0.25, 0.5, 0.75, 1.0); }
            ENDHLSL
        }
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_srp_shader_naming_no_pipeline_is_read_as_urp(tmp_path, language):
    """HLSLPROGRAM only, no .cginc, no built-in LightMode: URP reads it, and its custom-tag pass
    draws as the feature's (the centre pixel its colour). Controls: a CGPROGRAM, or a
    ForwardBase tag, keeps it the built-in pipeline's."""
    from pbrlab.importers.urp.material import reads
    (tmp_path / "srp.shader").write_text(SRP_ONLY)
    assert reads(tmp_path / "srp.shader")
    image = _sphere(tmp_path, language, SRP_ONLY)
    assert image[24, 24, :3].tolist() == list(COLOUR)
    for builtin in (SRP_ONLY.replace("HLSLPROGRAM", "CGPROGRAM").replace("ENDHLSL", "ENDCG"),
                    SRP_ONLY.replace("PbrlabCustomPipeline", "ForwardBase")):
        (tmp_path / "builtin.shader").write_text(builtin)
        assert not reads(tmp_path / "builtin.shader")


def test_a_long_folder_keeps_the_no_colour_note_readable():
    """The corpus cuts each warning to 300 characters after its place (path:line:), so a mask
    deep in a project is still listed by its reason. Control: cut from the start, as before, the
    note is lost behind a 400-character path."""
    from types import SimpleNamespace
    note = "/" + "deep/" * 80 + "MASK_1.shader:5: Pass draws no colour by its ColorMask (ColorMask 0): drawn as written"
    kept = corpus._messages([SimpleNamespace(message=note)])
    outcomes = {k: corpus.Outcome("s", k, "rendered", warnings=kept) for k in LANGUAGES}
    assert corpus.no_colour_reason(outcomes).startswith("Pass draws no colour by its ColorMask")
    cut = {k: corpus.Outcome("s", k, "rendered", warnings=[note[:300]]) for k in LANGUAGES}
    assert corpus.no_colour_reason(cut) is None
