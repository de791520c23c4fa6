"""URP and Core RP include stand-ins, round 2 (issue 34): names real URP shaders read that the
stand-ins lacked. unity_AmbientSky / Equator / Ground from the scene's ambient SH; the space
transforms' optional doNormalize argument.

Scene: the corpus camera looking at a unit UV sphere (a mesh, so its object transform is the
one given) whose material is the URP pass under test; the pass returns a constant, so every
covered pixel is checked.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.foundation.locations import locate
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene
from test_urp_scene_textures import _URP_PASS as URP_PASS  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")

# URP_PASS (the scene-texture tests'): %(name)s, %(include)s after Core.hlsl, %(body)s the fragment's.


def urp_pass(name: str, body: str, include: str = "") -> str:
    return textwrap.dedent(URP_PASS % {"name": name, "include": include, "body": body})


def render_constant(tmp_path, text: str, language: str, *, environment: bool = True,
                    transform: dict | None = None, lights: list | None = None) -> tuple:
    """(the covered pixels' linear RGBA, the scene) of a unit UV sphere drawn with the shader ``text``."""
    shader = tmp_path / "t.shader"
    shader.write_text(text)
    data = {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
        "lights": lights or [],
        "materials": {"m": {"surface": str(shader)}},
        "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m",
                     **({"transform": transform} if transform else {})}],
    }
    if environment:
        data["environment"] = {"path": str(locate("scenes") / "assets" / "sky.exr"), "intensity": 0.5}
    scene = parse_scene(data, origin="urp library test scene", base=tmp_path)
    image = render_scene(scene, language=language).linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 200
    return image[covered], scene


# Unity's three ambient colours: the scene SH's irradiance (ShadeSH9's, / pi, clamped at 0 as
# pbrlab's PBR_UNITY_SH_IRRADIANCE) from above, the mean of the four horizontal axes, from below.
AMBIENT_AXES = {
    "unity_AmbientSky": [[0.0, 1.0, 0.0]],
    "unity_AmbientEquator": [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]],
    "unity_AmbientGround": [[0.0, -1.0, 0.0]],
    # URP's _GlossyEnvironmentColor: the probe's constant term, its mean over the sphere, which
    # the six axes' mean is for bands 0-2 (test_fixed_function.py checks that against 20,000
    # directions)
    "_GlossyEnvironmentColor": [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0],
                                [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]],
}
AMBIENT_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'
# The SH coefficients reach the GPU as float32 and the lookup sums 9 products (and 4 lookups
# for the equator): 32 float32 ulps (2^-24 relative each) of a value below 1 bounds it.
AMBIENT_BOUND = 32 * 2.0 ** -24


def _expected_ambient(scene, name: str) -> np.ndarray:
    from pbrlab.maths.reference.lighting import sh9_irradiance
    from pbrlab.scene.environment import environment_sh
    sh = environment_sh(scene.environment)
    return (np.maximum(sh9_irradiance(sh, np.asarray(AMBIENT_AXES[name])), 0.0) / np.pi).mean(axis=0)


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("name", sorted(AMBIENT_AXES))
def test_ambient_colours_are_the_sh_from_above_sides_below(tmp_path, language, name):
    """unity_AmbientSky / Equator / Ground (URP UnityInput's globals; RenderSettings' ambient
    "from above", "from the sides", "from below") and _GlossyEnvironmentColor returned as the
    pixel: the float64 SH9 irradiance of the sky along +y, the four horizontal axes' mean, -y,
    the six axes' mean, within AMBIENT_BOUND on
    every covered pixel. Control: the sky's and the ground's colours differ from each other and
    from the other two by far more than the bound (a swapped or flat ambient fails), and with no
    environment the colour is black."""
    text = urp_pass("ambient", f"return float4({name}.rgb, 1.0);", AMBIENT_INCLUDE)
    pixels, scene = render_constant(tmp_path, text, language)
    expected = _expected_ambient(scene, name)
    assert 0.01 < expected.min() and expected.max() < 1.0
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > AMBIENT_BOUND).mean() == 0.0, (err.max(), pixels[0], expected)
    for other in AMBIENT_AXES:
        if other != name:
            assert np.abs(_expected_ambient(scene, other) - expected).max() > 100 * AMBIENT_BOUND
    dark, _ = render_constant(tmp_path, text, language, environment=False)
    assert np.abs(dark[:, :3]).max() == 0.0


# The object scaled by 2 (uniformly: unity_ObjectToWorld = 2 I, unity_WorldToObject = I / 2),
# a unit direction d: each transform's length with and without normalization.
SCALE = 2.0
TRANSFORMS_BODY = """float3 d = float3(1.0, 2.0, 2.0) / 3.0;
                return float4(length(TransformObjectToWorldNormal(d, false)) + 10.0 * length(TransformObjectToWorldNormal(d)),
                              length(TransformWorldToObjectNormal(d, false)) + 10.0 * length(TransformObjectToWorldDir(d, false)),
                              length(TransformWorldToObjectDir(d, false)) + 10.0 * length(TransformObjectToWorldNormal(d, true)),
                              1.0);"""
# n^T M^-1 = d / 2, n^T M = 2 d, M d = 2 d, M^-1 d = d / 2; the one-argument and true forms are unit.
TRANSFORMS_EXPECTED = np.array([1 / SCALE + 10.0, SCALE + 10.0 * SCALE, 1 / SCALE + 10.0])
# float32: the 3x3 product, the length and the sum, each a few ulps of values up to 22:
# 8 ulps (2^-24 relative) of the result.
TRANSFORMS_BOUND = 8 * 2.0 ** -24 * TRANSFORMS_EXPECTED


@pytest.mark.parametrize("language", LANGUAGES)
def test_space_transforms_take_do_normalize(tmp_path, language):
    """Core RP's TransformObjectToWorldNormal(n, doNormalize), TransformWorldToObjectNormal,
    TransformObjectToWorldDir(d, false), TransformWorldToObjectDir(d, false) under a uniform
    scale of 2: lengths 1/2, 2, 2, 1/2 unnormalized, 1 with the default or true. Control: the
    normalized length in place of each unnormalized one (10 + 1 each) fails the bound."""
    pixels, _ = render_constant(tmp_path, urp_pass("transforms", TRANSFORMS_BODY), language,
                                transform={"scale": SCALE})
    err = np.abs(pixels[:, :3] - TRANSFORMS_EXPECTED)
    assert (err <= TRANSFORMS_BOUND).all(), (err / TRANSFORMS_BOUND).max(axis=0)
    normalized = np.array([11.0, 1.0 + 10.0 * SCALE, 11.0])  # control: doNormalize ignored
    assert (np.abs(normalized - TRANSFORMS_EXPECTED) > TRANSFORMS_BOUND).all()


# Core RP's three-argument SAMPLE_DEPTH_TEXTURE and four-argument _LOD on URP's camera depth,
# beside SampleSceneDepth (the stand-in DeclareDepthTexture's, proven against the float64
# ray-sphere depth in test_urp_scene_textures.py) at the same uv.
DEPTH_BODY = """float2 uv = GetNormalizedScreenSpaceUV(IN.positionCS);
                return float4(SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, sampler_CameraDepthTexture, uv),
                              SAMPLE_DEPTH_TEXTURE_LOD(_CameraDepthTexture, sampler_CameraDepthTexture, uv, 0),
                              SampleSceneDepth(uv), 1.0);"""
DEPTH_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/DeclareDepthTexture.hlsl"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_core_sample_depth_texture_takes_a_sampler(tmp_path, language):
    """SAMPLE_DEPTH_TEXTURE(tex, sampler, uv) and SAMPLE_DEPTH_TEXTURE_LOD(tex, sampler, uv, 0)
    in a URP program (Core RP's forms; the built-in two-argument macro would refuse them) read
    the same texel as SampleSceneDepth(uv): equal bit for bit (one texture, one uv, nearest).
    The depth is the sphere's, not a constant: it spans a range inside (0, 1) (the far plane's
    1.0 would be a missing pre-pass). Control: the neighbouring pixel's SampleSceneDepth differs
    on most pixels."""
    pixels, _ = render_constant(tmp_path, urp_pass("depth", DEPTH_BODY, DEPTH_INCLUDE), language)
    assert (pixels[:, 0] == pixels[:, 2]).all() and (pixels[:, 1] == pixels[:, 2]).all()
    assert 0.0 < pixels[:, 2].min() < pixels[:, 2].max() < 1.0
    assert (pixels[:, 0] != np.roll(pixels[:, 2], 1)).mean() > 0.5


# A shader's own PI after Core (FXC: a warning, the new body) and its own struct LightingData
# (a URP 10 shader's name, which URP 12 added to Lighting.hlsl); OutputAlpha's two forms; and
# SurfaceData, declared by SurfaceInput.hlsl alone (URP's SurfaceData.hlsl), before Lighting.hlsl.
OWN_NAMES_INCLUDE = """#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/SurfaceInput.hlsl"
            void FillSurface(out SurfaceData s) { s = (SurfaceData)0; s.alpha = 0.375; }
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"
            #define PI 3.0
            struct LightingData { float3 mine; };"""
OWN_NAMES_BODY = """LightingData d; d.mine = float3(0.5, 0.25, 0.125);
                SurfaceData s; FillSurface(s);
                return float4(PI * 0.1 + d.mine.x, OutputAlpha(s.alpha) - 0.5, OutputAlpha(s.alpha, 1.0), 1.0);"""
# PI 0.1 + 0.5, 1 - 0.5, 0.375: sums of a few float32 roundings near 1, 4 ulps (2^-24 relative).
OWN_NAMES_EXPECTED = np.array([3.0 * 0.1 + 0.5, 0.5, 0.375])
OWN_NAMES_BOUND = 4 * 2.0 ** -24


@pytest.mark.parametrize("language", LANGUAGES)
def test_shaders_own_pi_and_lighting_data_win(tmp_path, language):
    """The shader's #define PI 3.0 after Core is the PI its code reads (0.8 in red; Core's pi
    would give 0.814159), its struct LightingData is the one its code fills (not URP 12's),
    OutputAlpha(a) is 1 (opaque, the default surface type) and OutputAlpha(a, 1) is a. Control:
    Core's PI in red fails the bound, and the same shader with Core's LightingData members
    (no own struct) is refused at the line that reads d.mine."""
    pixels, _ = render_constant(tmp_path, urp_pass("own names", OWN_NAMES_BODY, OWN_NAMES_INCLUDE), language)
    err = np.abs(pixels[:, :3] - OWN_NAMES_EXPECTED).max(axis=1)
    assert (err <= OWN_NAMES_BOUND).all(), err.max()
    assert abs(3.14159265359 * 0.1 + 0.5 - OWN_NAMES_EXPECTED[0]) > OWN_NAMES_BOUND  # control: Core's PI
    from pbrlab.foundation.errors import PbrlabError
    without = OWN_NAMES_INCLUDE.replace("struct LightingData { float3 mine; };", "")
    with pytest.raises(PbrlabError, match="mine"):
        render_constant(tmp_path, urp_pass("own names", OWN_NAMES_BODY, without), language)


def test_user_definitions_are_read_from_the_shaders_own_files(tmp_path):
    """PBRLAB_USER_DEFINES_<name> for a name the program or its own include file defines, not
    for one only pbrlab's stand-ins define, nor one in a comment."""
    from types import SimpleNamespace
    from pbrlab.importers.unity.user_definitions import program_defines
    (tmp_path / "own.hlsl").write_text("#define HALF_PI 1.5\nstruct LightingData { float a; };\n")
    program = ('#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"\n'
               '#include "own.hlsl"\n// #define PI 3\n#define TWO_PI 6.0\n')
    found = program_defines(SimpleNamespace(program=program, path=tmp_path / "t.shader"))
    assert found == {"PBRLAB_USER_DEFINES_HALF_PI": 1, "PBRLAB_USER_DEFINES_LightingData": 1,
                     "PBRLAB_USER_DEFINES_TWO_PI": 1}


# Core RP's BSDF.hlsl and ImageBasedLighting.hlsl names at fixed arguments, one sum a channel.
BSDF_INCLUDE = """#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/BSDF.hlsl"
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/ImageBasedLighting.hlsl\""""
BSDF_BODY = """float f = F_Schlick(float3(0.1, 0.1, 0.1), 0.5).x;
                return float4(f + F_Schlick(0.2, 0.5, 0.3) + Lambert(),
                              D_GGX(0.9, 0.3) + DV_SmithJointGGX(0.9, 0.6, 0.7, 0.3) + V_SmithJointGGX(0.5, 0.8, 0.6),
                              MipmapLevelToPerceptualRoughness(PerceptualRoughnessToMipmapLevel(0.4)) + PerceptualRoughnessToMipmapLevel(0.4, 8u),
                              1.0);"""


def _bsdf_expected() -> np.ndarray:
    """The float64 terms (reference/brdf.py, each from its paper) and the mip's formula."""
    from pbrlab.maths.reference import brdf
    red = brdf.F_Schlick(0.1, 0.5) + brdf.F_Schlick(0.2, 0.3, f90=0.5) + brdf.Fd_Lambert()
    green = (brdf.D_GGX(0.9, 0.3) + brdf.D_GGX(0.9, 0.3) * brdf.V_SmithGGXCorrelated(0.6, 0.7, 0.3)
             + brdf.V_SmithGGXCorrelated(0.5, 0.8, 0.6))
    blue = 0.4 + 0.4 * (1.7 - 0.7 * 0.4) * 8  # the round trip is the identity; 8 levels' mip
    return np.array([red, green, blue], np.float64)


# float32 evaluation of each term (a few ulps: pow5, the squares, a sqrt, a divide) summed: 16
# ulps (2^-24 relative) of each channel's value; the round trip's sqrt near 1.7^2 - 2.8 f loses
# ~1.7^2 / 1.4 / pr = 5 times the float32 rounding of its argument: inside the same bound.
BSDF_BOUND = 16 * 2.0 ** -24


@pytest.mark.parametrize("language", LANGUAGES)
def test_core_bsdf_and_ibl_terms_are_the_papers(tmp_path, language):
    """F_Schlick (Schlick 1994; a float3 and a scalar f0 with f90), Lambert (1/pi), D_GGX
    (Walter 2007), V_SmithJointGGX and DV_SmithJointGGX (Heitz 2014's height-correlated Smith,
    Unity's `roughness` = alpha), PerceptualRoughnessToMipmapLevel in Unity's two forms and
    MipmapLevelToPerceptualRoughness its inverse, against their float64 formulas within
    BSDF_BOUND relative. Control: D_GGX given the perceptual roughness (sqrt 0.3) instead of
    alpha differs by far more than the bound."""
    pixels, _ = render_constant(tmp_path, urp_pass("bsdf", BSDF_BODY, BSDF_INCLUDE), language)
    expected = _bsdf_expected()
    err = np.abs(pixels[:, :3] - expected) / expected
    assert (err <= BSDF_BOUND).all(), err.max(axis=0)
    from pbrlab.maths.reference import brdf
    wrong = expected[1] - brdf.D_GGX(0.9, 0.3) + brdf.D_GGX(0.9, 0.3 ** 0.5)  # control: perceptual roughness as alpha
    assert abs(wrong - expected[1]) / expected[1] > 100 * BSDF_BOUND


# URP_Water's include: Lighting.hlsl written lighting.hlsl (Unity on Windows and macOS reads it).
CASE_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/lighting.hlsl"'
CASE_BODY = "return float4(GetMainLight().color, 1.0);"


@pytest.mark.parametrize("language", LANGUAGES)
def test_package_include_in_another_case_is_read_with_a_warning(tmp_path, language):
    """A Packages/ include whose letter case differs from the stand-in's is read as the stand-in
    (the main light's colour, the scene's first directional light's radiance (0.25, 0.5, 1) in
    float32, exact), with a warning naming the shader file and the include's line. Control: a
    name no stand-in matches in any case is refused, naming it."""
    sun = {"type": "directional", "direction": [0.0, 0.0, -1.0], "color": [0.25, 0.5, 1.0], "intensity": 1.0}
    text = urp_pass("case", CASE_BODY, CASE_INCLUDE)
    line = text.splitlines().index(next(s for s in text.splitlines() if "lighting.hlsl" in s)) + 1
    with pytest.warns(UserWarning, match=rf"t\.shader:{line}: #include .*lighting\.hlsl.* read as .*Lighting\.hlsl"):
        pixels, _ = render_constant(tmp_path, text, language, environment=False, lights=[sun])
    assert (pixels[:, :3] == np.array([0.25, 0.5, 1.0])).all()
    from pbrlab.foundation.errors import PbrlabError
    with pytest.raises(PbrlabError, match="lightingx.hlsl"):
        render_constant(tmp_path, text.replace("lighting.hlsl", "lightingx.hlsl"), language, environment=False)


# URP's shadow-map sampling as a shader calls it itself (Shadows.hlsl's names): no shadow map here.
SHADOW_BODY = """ShadowSamplingData data = GetMainLightShadowSamplingData();
                float4 params = GetMainLightShadowParams();
                float4 coord = TransformWorldToShadowCoord(float3(0.0, 0.0, 0.0));
                float lit = SampleShadowmap(TEXTURE2D_ARGS(_MainLightShadowmapTexture, sampler_MainLightShadowmapTexture),
                                            coord, data, params, false);
                return float4(0.5 * lit, params.x + 0.25, 0.125 * data.shadowmapSize.x, 1.0);"""
SHADOW_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_shadow_map_sampling_is_unshadowed(tmp_path, language):
    """SampleShadowmap with the main light's ShadowSamplingData and _MainLightShadowParams
    (URP 12's names) under a directional light: 1 (no shadow map: lerp(1, 1, strength)), the
    strength 0 as URP's with shadows off; (0.5, 0.25, 0.125) exactly on every pixel (a shadowed
    sample, any strength but 0 or a sampling data left unset fails it)."""
    sun = {"type": "directional", "direction": [0.0, 0.0, -1.0], "color": [1.0, 1.0, 1.0], "intensity": 1.0}
    pixels, _ = render_constant(tmp_path, urp_pass("shadow", SHADOW_BODY, SHADOW_INCLUDE), language,
                                environment=False, lights=[sun])
    assert (pixels[:, :3] == np.array([0.5, 0.25, 0.125])).all()


# URP's Lit shader as projects copy it: its forward pass from URP's Shaders/LitInput.hlsl and
# LitForwardPass.hlsl (stand-ins), beside a pass that fills SurfaceData and InputData itself and
# calls UniversalFragmentPBR (proven against the float64 URP model in test_urp_shaders.py).
LIT_PROPERTIES = """Properties {
        _BaseMap("Base", 2D) = "white" {}
        _BaseColor("Color", Color) = (0.8, 0.5, 0.3, 1)
        _Metallic("Metallic", Range(0, 1)) = 0.3
        _Smoothness("Smoothness", Range(0, 1)) = %(smoothness)s
    }"""
LIT_SHELL = """
Shader "t/lit" {
    %(properties)s
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
%(program)s
            ENDHLSL
        }
    }
}
"""
LIT_COPY = """            #pragma shader_feature _NORMALMAP
            #pragma vertex LitPassVertex
            #pragma fragment LitPassFragment
            #include "Packages/com.unity.render-pipelines.universal/Shaders/LitInput.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/Shaders/LitForwardPass.hlsl"
"""
LIT_DIRECT = """            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"
            float4 _BaseColor;
            float _Metallic, _Smoothness;
            struct Attributes { float4 positionOS : POSITION; float3 normalOS : NORMAL; };
            struct Varyings { float4 positionCS : SV_POSITION; float3 positionWS : TEXCOORD0; float3 normalWS : TEXCOORD1; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionWS = TransformObjectToWorld(IN.positionOS.xyz);
                OUT.positionCS = TransformWorldToHClip(OUT.positionWS);
                OUT.normalWS = TransformObjectToWorldNormal(IN.normalOS);
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target {
                SurfaceData s = (SurfaceData)0;
                s.albedo = _BaseColor.rgb; s.metallic = _Metallic; s.smoothness = _Smoothness;
                s.occlusion = 1.0; s.alpha = 1.0; s.normalTS = float3(0.0, 0.0, 1.0);
                InputData d = (InputData)0;
                d.positionWS = IN.positionWS;
                d.normalWS = normalize(IN.normalWS);
                d.viewDirectionWS = GetWorldSpaceNormalizeViewDir(IN.positionWS);
                d.bakedGI = SampleSH(d.normalWS);
                d.shadowMask = float4(1.0, 1.0, 1.0, 1.0);
                return float4(UniversalFragmentPBR(d, s).rgb, 1.0);
            }
"""
# The same float32 operations in two programs the compiler may order differently (~100 of them
# from the normal to the lit colour): 64 ulps (2^-24 relative) of the colour, floored at 2^-10
# (dark pixels: the absolute rounding of the terms summed there).
LIT_BOUND_ULPS = 64


@pytest.mark.parametrize("language", LANGUAGES)
def test_urp_lit_copy_is_universal_fragment_pbr(tmp_path, language):
    """URP's Lit forward pass (LitInput.hlsl + LitForwardPass.hlsl: base colour times the white
    base map, _Metallic, _Smoothness, no maps) under the corpus's sun and sky equals a pass that
    gives UniversalFragmentPBR the same SurfaceData and InputData itself, on every covered pixel
    within LIT_BOUND_ULPS. Control: the direct pass at smoothness 0.5 instead of 0.6 differs
    beyond the bound on most lit pixels."""
    sun = {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}

    def render(template, smoothness):
        text = textwrap.dedent(LIT_SHELL % {"properties": LIT_PROPERTIES % {"smoothness": smoothness},
                                            "program": template})
        sub = tmp_path / f"{'copy' if template is LIT_COPY else 'direct'}-{smoothness}"
        sub.mkdir(exist_ok=True)
        pixels, _ = render_constant(sub, text, language, lights=[sun])
        return pixels[:, :3]

    copy, direct = render(LIT_COPY, "0.6"), render(LIT_DIRECT, "0.6")
    assert copy.shape == direct.shape and copy.max() > 0.1
    bound = LIT_BOUND_ULPS * 2.0 ** -24 * np.maximum(np.abs(direct), 2.0 ** -10)
    assert (np.abs(copy - direct) <= bound).all(), (np.abs(copy - direct) / bound).max()
    other = render(LIT_DIRECT, "0.5")  # control
    assert (np.abs(other - copy) > bound).any(axis=1).mean() > 0.5
