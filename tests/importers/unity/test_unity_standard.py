"""Unity's own Standard shaders (corpus/unity/builtin-2019.4: Standard, StandardSpecular,
AutodeskInteractive) run as written through pbrlab's stand-ins for UnityStandardCore.cginc and
its neighbours (harness/pbrlab/importers/unity/cginc/UnityStandard*.cginc).

What each must show, stated independently of the stand-in: a surface shader
``#pragma surface surf Standard`` (or StandardSpecular) whose surf() writes what Unity's
documentation says the Standard shader's inputs mean (albedo = _Color x _MainTex; metallic and
smoothness from _Metallic/_Glossiness, or the metallic map's red and alpha x _GlossMapScale;
occlusion = lerp(1, map.g, _OcclusionStrength); emission = map x _EmissionColor with _EMISSION;
a tangent-space normal from the normal map scaled in xy by _BumpScale; the detail albedo x2 in
linear space: x unity_ColorSpaceDouble, 4.59479380; AutodeskInteractive reads _Glossiness as a
roughness). The two are drawn on the same mesh under a directional light and the environment,
and must agree pixel for pixel. Alpha test cuts what it must; the one keyword the stand-in does
not honour is refused by name. Both languages: HLSL as written, GLSL through port-unity.
"""

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.foundation.images import write_png
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

BUILTIN = Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"
LANGUAGES = ("hlsl", "glsl")
SIZE = (48, 48)
# The two programs run the same lighting function on the same rasterised mesh; they differ in
# the vertex stage (unity_ObjectToWorld products against the harness's u_model / normal
# matrix) and in where the normal is normalised, which moves values by float32 rounding.
# Measured on llvmpipe, both languages, every case below: worst 5.2e-6 relative (floor 1e-2;
# 6.7e-5 absolute, in a highlight). A wrong input (a map's channel, a scale, x2 against x4.59
# detail) moves pixels by more than 1e-2 relative, so 2e-5 separates the two.
RTOL = 2e-5


def _png(path: Path, rgba) -> dict:
    """A 4x4 PNG of one linear colour, bound without sRGB decoding. The cases use multiples of
    1/5 (51/255), which 8 bits hold exactly, so the surface shader's literals are the texels."""
    codes = np.round(np.asarray(rgba, np.float64) * 255).astype(np.uint8)
    write_png(path, np.broadcast_to(codes, (4, 4, 4)).copy())
    return {"path": str(path), "srgb": False}


SUN = {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 0.9, 0.8], "intensity": 1.2}
# Unity's forward path draws these in the ForwardAdd pass, one draw per light, added
MORE_LIGHTS = [
    {"type": "directional", "direction": [0.8, 0.1, -0.5], "color": [0.2, 0.3, 1.0], "intensity": 0.7},
    {"type": "point", "position": [1.5, 1.0, 1.5], "color": [1.0, 0.5, 0.2], "intensity": 6.0, "range": 8.0},
    {"type": "spot", "position": [-1.2, 0.4, 2.0], "direction": [0.5, -0.1, -0.8], "color": [0.3, 1.0, 0.4],
     "intensity": 5.0, "inner_cone_deg": 15, "outer_cone_deg": 30},
]


def _scene(surface, properties=None, keywords=None, lights=(SUN,)):
    material = {"surface": str(surface), "properties": properties or {}}
    if keywords:
        material["keywords"] = keywords
    return {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": list(SIZE)},
        "lights": list(lights),
        "materials": {"m": material},
        "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}],
        "environment": {"color": [0.2, 0.25, 0.3]},
        "render": {"quality": "high", "tonemap": "none"},
    }


def _render(scene, ctx, language, base):
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the notes on skipped passes are not under test here
        return render_scene(parse_scene(scene, origin="test scene", base=base), ctx,
                            language=language).linear.astype(np.float64)


def _surface(tmp_path: Path, output: str, body: str, properties: str) -> Path:
    shader = tmp_path / "equivalent.shader"
    shader.write_text(f"""Shader "Test/StandardEquivalent" {{
    Properties {{ {properties} }}
    SubShader {{
        CGPROGRAM
        #pragma surface surf {output.removeprefix("SurfaceOutput")}
        struct Input {{ float2 uv_MainTex; }};
        {body}
        ENDCG
    }}
}}
""")
    return shader


# (shader, its properties and keywords, the surface shader's Properties, its surf() body)
CASES = {
    "metallic constants": (
        "Standard.shader", {"_Color": [0.8, 0.3, 0.2, 1], "_Metallic": 0.35, "_Glossiness": 0.7}, [],
        "_Color (\"c\", Color) = (0.8, 0.3, 0.2, 1)", "SurfaceOutputStandard",
        "o.Albedo = fixed3(0.8, 0.3, 0.2); o.Metallic = 0.35; o.Smoothness = 0.7;"),
    "specular constants": (
        "StandardSpecular.shader", {"_Color": [0.3, 0.5, 0.7, 1], "_SpecColor": [0.5, 0.4, 0.2, 1],
                                    "_Glossiness": 0.6}, [],
        "_Color (\"c\", Color) = (1, 1, 1, 1)", "SurfaceOutputStandardSpecular",
        "o.Albedo = fixed3(0.3, 0.5, 0.7); o.Specular = fixed3(0.5, 0.4, 0.2); o.Smoothness = 0.6;"),
    "roughness workflow": (
        "AutodeskInteractive.shader", {"_Color": [0.6, 0.6, 0.5, 1], "_Metallic": 0.9, "_Glossiness": 0.25}, [],
        "_Color (\"c\", Color) = (1, 1, 1, 1)", "SurfaceOutputStandard",
        "o.Albedo = fixed3(0.6, 0.6, 0.5); o.Metallic = 0.9; o.Smoothness = 1.0 - 0.25;"),
    "maps": (
        "Standard.shader",
        {"_Color": [0.9, 0.8, 0.7, 1], "_MainTex": ("albedo", [0.4, 0.6, 0.8, 1]),
         "_MetallicGlossMap": ("metal", [0.8, 0.0, 0.0, 0.6]), "_GlossMapScale": 0.5,
         "_OcclusionMap": ("occl", [0.0, 0.4, 0.0, 1]), "_OcclusionStrength": 0.75,
         "_EmissionMap": ("emit", [0.2, 0.6, 1.0, 1]), "_EmissionColor": [0.5, 0.25, 0.1, 1]},
        ["_METALLICGLOSSMAP", "_EMISSION"],
        "_MainTex (\"a\", 2D) = \"white\" {}",
        "SurfaceOutputStandard",
        "o.Albedo = fixed3(0.9, 0.8, 0.7) * tex2D(_MainTex, IN.uv_MainTex).rgb; "
        "o.Metallic = 0.8; o.Smoothness = 0.6 * 0.5; o.Occlusion = 1.0 + (0.4 - 1.0) * 0.75; "
        "o.Emission = fixed3(0.2, 0.6, 1.0) * fixed3(0.5, 0.25, 0.1);"),
    "normal map": (
        "Standard.shader", {"_BumpMap": ("bump", [0.8, 0.4, 1.0, 1]), "_BumpScale": 0.6, "_Glossiness": 0.8},
        ["_NORMALMAP"],
        "_MainTex (\"a\", 2D) = \"white\" {}", "SurfaceOutputStandard",
        "o.Albedo = fixed3(1, 1, 1); o.Smoothness = 0.8; "
        # Unity's desktop unpack of the map as the editor stores it (DXT5nm: x = r, y = g, z rebuilt
        # from the scaled xy; docs/unity.md, "Normal maps as Unity stores them")
        "float2 xy = (float2(0.8, 0.4) * 2.0 - 1.0) * 0.6; o.Normal = float3(xy, sqrt(1.0 - saturate(dot(xy, xy))));"),
    "detail x2": (
        "Standard.shader", {"_Color": [0.5, 0.5, 0.5, 1], "_DetailAlbedoMap": ("detail", [0.2, 0.2, 0.4, 1]),
                            "_DetailMask": ("mask", [1, 1, 1, 0.6])},
        ["_DETAIL_MULX2"],
        "_MainTex (\"a\", 2D) = \"white\" {}", "SurfaceOutputStandard",
        "float3 d = float3(0.2, 0.2, 0.4) * 4.59479380; "
        "o.Albedo = fixed3(0.5, 0.5, 0.5) * (1.0 + (d - 1.0) * 0.6); o.Smoothness = 0.5;"),
    "specular map": (
        "StandardSpecular.shader", {"_Color": [0.6, 0.6, 0.8, 1], "_SpecGlossMap": ("spec", [0.4, 0.2, 0.2, 0.8]),
                                    "_GlossMapScale": 0.6}, ["_SPECGLOSSMAP"],
        "_Color (\"c\", Color) = (1, 1, 1, 1)", "SurfaceOutputStandardSpecular",
        "o.Albedo = fixed3(0.6, 0.6, 0.8); o.Specular = fixed3(0.4, 0.2, 0.2); o.Smoothness = 0.8 * 0.6;"),
    "smoothness in albedo alpha": (
        "Standard.shader", {"_Color": [1, 1, 1, 0.6], "_MainTex": ("albedo", [0.6, 0.4, 0.2, 0.4]),
                            "_Metallic": 0.4, "_GlossMapScale": 0.8},
        ["_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A"],
        "_MainTex (\"a\", 2D) = \"white\" {}", "SurfaceOutputStandard",
        "o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb; o.Metallic = 0.4; o.Smoothness = 0.4 * 0.8;"),
}


def _resolved(props: dict, tmp_path: Path) -> dict:
    out = {}
    for name, value in props.items():
        out[name] = _png(tmp_path / f"{value[0]}.png", value[1]) if isinstance(value, tuple) else value
    return out


@pytest.mark.parametrize("case", sorted(CASES))
@pytest.mark.parametrize("language", LANGUAGES)
def test_standard_shader_shows_what_its_inputs_mean(case, language, gl_context, tmp_path):
    shader, props, keywords, surface_props, output, body = CASES[case]
    standard = _render(_scene(BUILTIN / shader, _resolved(props, tmp_path), keywords), gl_context, language, tmp_path)
    props_surface = {"_MainTex": _resolved({"_MainTex": props["_MainTex"]}, tmp_path)["_MainTex"]} \
        if "_MainTex" in props else {}
    equivalent = _surface(tmp_path, output, f"sampler2D _MainTex; void surf (Input IN, inout {output} o) {{ {body} }}",
                          surface_props)
    expected = _render(_scene(equivalent, props_surface), gl_context, language, tmp_path)
    covered = standard[..., 3] > 0
    assert covered.mean() > 0.3 and np.array_equal(covered, expected[..., 3] > 0)
    err = np.abs(standard - expected)[covered][:, :3] / np.maximum(np.abs(expected[covered][:, :3]), 1e-2)
    assert err.max() <= RTOL, err.max()
    assert standard[covered][:, :3].max() > 0.1  # lit, not black


@pytest.mark.parametrize("language", LANGUAGES)
def test_standard_forward_add_adds_each_further_light(language, gl_context, tmp_path):
    # the ForwardAdd pass draws once per light after the first directional one (a directional,
    # a point and a spot here), blended One One; the surface shader shades them in its programs
    lights = (SUN, *MORE_LIGHTS)
    props = {"_Color": [0.7, 0.6, 0.5, 1], "_Metallic": 0.2, "_Glossiness": 0.75}
    standard = _render(_scene(BUILTIN / "Standard.shader", props, lights=lights), gl_context, language, tmp_path)
    equivalent = _surface(tmp_path, "SurfaceOutputStandard",
                          "void surf (Input IN, inout SurfaceOutputStandard o) { o.Albedo = fixed3(0.7, 0.6, 0.5); "
                          "o.Metallic = 0.2; o.Smoothness = 0.75; }", "_Color (\"c\", Color) = (1, 1, 1, 1)")
    expected = _render(_scene(equivalent, lights=lights), gl_context, language, tmp_path)
    sun_only = _render(_scene(BUILTIN / "Standard.shader", props), gl_context, language, tmp_path)
    covered = standard[..., 3] > 0
    assert covered.mean() > 0.3 and np.array_equal(covered, expected[..., 3] > 0)
    assert np.all(standard[..., 3][covered] == 1.0)  # the added light keeps the coverage
    err = np.abs(standard - expected)[covered][:, :3] / np.maximum(np.abs(expected[covered][:, :3]), 1e-2)
    assert err.max() <= RTOL, err.max()
    assert (standard - sun_only)[covered][:, :3].max() > 0.05  # the further lights do show


PARALLAX_EQUIVALENT = """Shader "Test/ParallaxEquivalent" {
    Properties { _MainTex ("a", 2D) = "white" {} }
    SubShader {
        CGPROGRAM
        #pragma surface surf Standard
        sampler2D _MainTex;
        struct Input { float2 uv_MainTex; float3 viewDir; };
        void surf (Input IN, inout SurfaceOutputStandard o) {
            // Unity's parallax step: the height (0.6) centred and scaled by _Parallax (0.05), along
            // the tangent-space view direction (a surface that writes o.Normal gets it so)
            float2 offset = ParallaxOffset(0.6, 0.05, IN.viewDir);
            o.Albedo = tex2D(_MainTex, IN.uv_MainTex + offset).rgb;
            o.Smoothness = 0.5;
            o.Normal = float3(0.0, 0.0, 1.0);
        }
        ENDCG
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_standard_parallax_shifts_the_texture_by_unitys_step(language, gl_context, tmp_path):
    ramp = np.zeros((8, 8, 4), np.uint8)
    ramp[..., 3] = 255
    ramp[..., 0] = np.linspace(0, 255, 8).astype(np.uint8)[None, :]
    ramp[..., 1] = np.linspace(255, 0, 8).astype(np.uint8)[:, None]
    write_png(tmp_path / "ramp.png", ramp)
    props = {"_MainTex": {"path": str(tmp_path / "ramp.png"), "srgb": False},
             "_ParallaxMap": _png(tmp_path / "height.png", [0, 0.6, 0, 1]), "_Parallax": 0.05}
    shifted = _render(_scene(BUILTIN / "Standard.shader", props, ["_PARALLAXMAP"]), gl_context, language, tmp_path)
    flat = _render(_scene(BUILTIN / "Standard.shader", props), gl_context, language, tmp_path)
    equivalent = tmp_path / "parallax.shader"
    equivalent.write_text(PARALLAX_EQUIVALENT)
    expected = _render(_scene(equivalent, {"_MainTex": props["_MainTex"]}), gl_context, language, tmp_path)
    covered = shifted[..., 3] > 0
    err = np.abs(shifted - expected)[covered][:, :3] / np.maximum(np.abs(expected[covered][:, :3]), 1e-2)
    assert err.max() <= RTOL, err.max()
    assert np.abs(shifted - flat)[covered][:, :3].max() > 0.02  # the shift shows


@pytest.mark.parametrize("language", LANGUAGES)
def test_standard_alpha_test_cuts_below_the_cutoff(language, gl_context, tmp_path):
    props = {"_MainTex": _png(tmp_path / "a.png", [1, 1, 1, 0.4])}
    kept = _render(_scene(BUILTIN / "Standard.shader", {**props, "_Cutoff": 0.3}, ["_ALPHATEST_ON"]),
                   gl_context, language, tmp_path)
    cut = _render(_scene(BUILTIN / "Standard.shader", {**props, "_Cutoff": 0.5}, ["_ALPHATEST_ON"]),
                  gl_context, language, tmp_path)
    assert (kept[..., 3] > 0).mean() > 0.3
    assert not np.any(cut[..., 3] > 0) and not np.any(cut[..., :3] > 0)


def test_a_keyword_the_stand_in_does_not_honour_is_refused(tmp_path):
    with pytest.raises(PbrlabError, match=r"'_SPECULARHIGHLIGHTS_OFF': the Standard shader's Specular "
                                          r"Highlights toggle .* not honoured"):
        parse_scene(_scene(BUILTIN / "Standard.shader", keywords=["_SPECULARHIGHLIGHTS_OFF"]),
                    origin="test scene", base=tmp_path)


def test_standard_runs_its_first_subshader_and_names_the_passes_it_skips():
    from pbrlab.importers import unity
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        shader = unity.load_shader(BUILTIN / "Standard.shader")
    assert [p.light_mode for p in shader.passes] == ["ForwardBase", "ForwardAdd"]
    notes = "\n".join(shader.notes)
    assert "SubShader 1 of 2 runs" in notes
    for skipped in ("ShadowCaster", "Deferred", "Meta"):
        assert f"(LightMode {skipped})" in notes, notes
