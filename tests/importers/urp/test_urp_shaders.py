"""Unity Universal Render Pipeline shaders as written (issue 34, first slice; issue 37: a
material source added in its own importer folder, importers/urp/, without touching the
renderer): HLSLPROGRAM passes with URP's ShaderLibrary includes (pbrlab's stand-ins), drawn
once per forward pass with every light, in both languages; URP's physically based model
against its float64 transcription (pbrlab.maths.reference.urp_brdf)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers import urp
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.urp.material import URPSource
from pbrlab.maths.reference import urp_brdf
from pbrlab.render.renderer import render_scene

HERE = Path(__file__).resolve().parent
SHADERS = HERE / "shaders"
CORPUS = Path(__file__).resolve().parents[3] / "corpus" / "urp"
TEMPLATES = CORPUS / "Cyanilux__URP_ShaderCodeTemplates"
F32_EPS = float(np.finfo(np.float32).eps)
LIGHT_TO = np.array([-0.3, 0.0, -1.0])     # the directional light's direction of travel
LIGHT_RADIANCE = np.array([1.0, 0.9, 0.8]) * 2.0


def _grid_scene(shader: Path, properties=None) -> dict:
    """A unit plane (XZ, UVs over [0, 1]^2) filling an orthographic-like narrow view from above."""
    return {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, 0.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": 20, "size": [48, 48]},
        "lights": [{"type": "directional", "direction": LIGHT_TO.tolist(), "color": (LIGHT_RADIANCE / 2).tolist(),
                    "intensity": 2.0}],
        "materials": {"m": {"surface": str(shader), **({"properties": properties} if properties else {})}},
        "objects": [{"mesh": {"primitive": "plane", "size": 1.0}, "material": "m"}],
    }


def test_a_urp_shader_gets_the_urp_source():
    scene = parse_scene(_grid_scene(SHADERS / "urp_uv.shader"), origin="t", base=SHADERS)
    assert isinstance(scene.materials["m"].source, URPSource)
    assert urp.material.reads(TEMPLATES / "URP_UnlitTemplate.shader")
    assert not urp.material.reads(Path(__file__).resolve().parents[3] / "scenes" / "unity_manual" / "rim.shader")


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("metallic", [0.0, 1.0])
def test_universal_fragment_pbr_matches_its_float64_transcription(language, metallic):
    """Per pixel, the lit colour of UniversalFragmentPBR (the stand-in Lighting.hlsl) equals
    urp_brdf's at the inputs the shader read (its UV, rendered alongside). Bound per value,
    relative: 64 float32 ulp for the chain of roundings (about 40, sin/cos of the view angle
    included) plus the cancellation in URP's d = NdotH^2 (r^2 - 1) + 1.00001, whose absolute
    error (16 ulp: NdotH through a normalize and a dot, doubled by dd/dNdotH = 2 NdotH (r^2 - 1))
    enters the lobe squared: 2 * 16 eps / d. No pixel may exceed it."""
    uv = render_scene(parse_scene(_grid_scene(SHADERS / "urp_uv.shader"), "t", SHADERS), language=language).linear
    props = {"_Metallic": metallic}
    lit = render_scene(parse_scene(_grid_scene(SHADERS / "urp_pbr_grid.shader", props), "t", SHADERS),
                       language=language).linear
    covered = uv[..., 3] > 0
    assert covered.all(), "the plane fills the view"
    u, s = uv[..., 0].astype(np.float64), uv[..., 1].astype(np.float64)
    angle = (u * 2.0 - 1.0) * 1.4
    v = np.stack([np.sin(angle), np.zeros_like(angle), np.cos(angle)], axis=-1)
    n = np.broadcast_to([0.0, 0.0, 1.0], v.shape)
    light = -LIGHT_TO / np.linalg.norm(LIGHT_TO)
    l = np.broadcast_to(light, v.shape)
    albedo = np.broadcast_to([0.8, 0.3, 0.2], v.shape)
    data = urp_brdf.brdf_data(albedo, np.full(s.shape, metallic), s)
    want = urp_brdf.direct_light(data, n, l, v, LIGHT_RADIANCE)
    h = (l + v) / np.linalg.norm(l + v, axis=-1, keepdims=True)
    d = (h[..., 2] ** 2) * (data["roughness2"] - 1.0) + 1.00001
    bound = 64 * F32_EPS + 2 * 16 * F32_EPS / d
    got = lit[..., :3].astype(np.float64)
    rel = np.abs(got - want) / np.maximum(np.abs(want), 1e-6)
    over = rel > bound[..., None]
    assert not over.any(), (f"{over.sum()} values over the bound; worst {rel.max():.3g} "
                            f"(bound there {bound[..., None].repeat(3, -1)[np.unravel_index(rel.argmax(), rel.shape)]:.3g})")
    assert want.max() > 0.5 and np.ptp(want[..., 0]) > 0.1  # lit, and the grid varies


def test_the_transcription_differs_from_a_plain_ggx():
    """A control: URP's folded lobe is not the textbook D*V*F (the 0.1 floor and 1.00001 matter
    at grazing, and the Fresnel is folded), so the check above tells models apart."""
    n = np.array([[0.0, 0.0, 1.0]])
    l = np.array([[0.9, 0.0, 0.2]]) / np.linalg.norm([0.9, 0.0, 0.2])
    v = np.array([[-0.9, 0.0, 0.2]]) / np.linalg.norm([-0.9, 0.0, 0.2])
    data = urp_brdf.brdf_data(np.array([[1.0, 1.0, 1.0]]), np.array([1.0]), np.array([0.5]))
    urp_lobe = urp_brdf.direct_specular(data, n, l, v)[0]
    a2 = data["roughness2"][0]
    NdotH = 1.0
    ggx_d = a2 / (np.pi * (NdotH * NdotH * (a2 - 1) + 1) ** 2)
    NdotL = NdotV = l[0, 2]
    k = np.sqrt(a2)
    vis = 0.5 / (NdotL * np.sqrt(NdotV ** 2 * (1 - k ** 2) + k ** 2) + NdotV * np.sqrt(NdotL ** 2 * (1 - k ** 2) + k ** 2))
    assert abs(urp_lobe - np.pi * ggx_d * vis) / urp_lobe > 0.05


CYANILUX = sorted(TEMPLATES.glob("*.shader"))


@pytest.mark.parametrize("shader", CYANILUX, ids=[p.stem for p in CYANILUX])
def test_cyanilux_templates_render_in_both_languages_and_agree(shader):
    """Cyanilux's URP code templates (CC0, corpus/urp/): unlit, transparent, diffuse-lit,
    simple-lit and PBR-lit, each rendered as written (HLSL) and ported (GLSL), agreeing to
    the Unity corpus's bound, with colour where the sphere is (not only alpha)."""
    outcomes = {language: corpus.run_shader(shader, language) for language in corpus.LANGUAGES}
    for language, outcome in outcomes.items():
        assert outcome.status == "rendered", f"{language}: {outcome.message}"
    image = outcomes["hlsl"].image
    covered = image[..., 3] > 0
    assert covered.mean() > 0.5
    assert image[covered][:, :3].max() > 0.05, "the sphere has colour"
    assert corpus.agreement(outcomes["glsl"].image, image) <= 1e-4


def test_a_urp_pass_the_harness_does_not_draw_is_noted_and_a_missing_include_named(tmp_path):
    shader = tmp_path / "missing.shader"
    shader.write_text('Shader "t/missing" { SubShader { Tags { "RenderPipeline" = "UniversalPipeline" }\n'
                      'Pass { Tags { "LightMode" = "ShadowCaster" } HLSLPROGRAM\nENDHLSL }\n'
                      'Pass { HLSLPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n'
                      '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/NoSuchFile.hlsl"\n'
                      'float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n'
                      'float4 frag() : SV_Target { return 1; }\nENDHLSL } } }\n')
    with pytest.warns(UserWarning, match="ShadowCaster.*skipped: no shadow maps here"):
        with pytest.raises(PbrlabError, match=r"missing\.shader:\d+: cannot find include .*NoSuchFile\.hlsl"):
            render_scene(parse_scene(corpus.scene_for(shader), "t", tmp_path))


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_universal_fragment_blinn_phong_matches_its_float64_transcription(language):
    """SimpleLit's pixel (UniversalFragmentBlinnPhong, _SPECULAR_COLOR: Lambert plus a highlight
    of exponent exp2(10 smoothness + 1)) equals urp_brdf.blinn_phong_light at the inputs the
    shader read. Bound per value, relative: 64 float32 ulp for the chain, plus the exponent's
    amplification of NdotH's error (NdotH^e moves by e * dNdotH / NdotH, dNdotH within 8 ulp:
    a normalize and a dot) on the highlight's share of the value."""
    lit = render_scene(parse_scene(_grid_scene(SHADERS / "urp_blinn_phong_grid.shader"), "t", SHADERS),
                       language=language).linear
    assert_blinn_phong_grid(lit, language)


def assert_blinn_phong_grid(lit, language):
    """``lit`` (urp_blinn_phong_grid.shader's picture, or a variant's) is SimpleLit's float64
    Blinn-Phong at each pixel's inputs (the bound: the test above's)."""
    uv = render_scene(parse_scene(_grid_scene(SHADERS / "urp_uv.shader"), "t", SHADERS), language=language).linear
    u, s = uv[..., 0].astype(np.float64), uv[..., 1].astype(np.float64)
    angle = (u * 2.0 - 1.0) * 1.4
    v = np.stack([np.sin(angle), np.zeros_like(angle), np.cos(angle)], axis=-1)
    n = np.broadcast_to([0.0, 0.0, 1.0], v.shape)
    l = np.broadcast_to(-LIGHT_TO / np.linalg.norm(LIGHT_TO), v.shape)
    albedo = np.broadcast_to([0.8, 0.3, 0.2], v.shape)
    specular = np.broadcast_to([0.5, 0.5, 0.5], v.shape)
    want = urp_brdf.blinn_phong_light(albedo, specular, s, n, l, v, LIGHT_RADIANCE)
    diffuse_only = urp_brdf.blinn_phong_light(albedo, specular, s, n, l, v, LIGHT_RADIANCE, highlights=False)
    exponent = np.exp2(10.0 * s + 1.0)
    share = 1.0 - diffuse_only / np.maximum(want, 1e-30)
    bound = 64 * F32_EPS + (exponent * 8 * F32_EPS)[..., None] * share
    got = lit[..., :3].astype(np.float64)
    rel = np.abs(got - want) / np.maximum(np.abs(want), 1e-6)
    assert not (rel > bound).any(), f"{int((rel > bound).sum())} values over the bound; worst {rel.max():.3g}"
    assert np.ptp(want[..., 0]) > 0.1 and (share > 0.5).any()  # the grid varies and shows highlights
