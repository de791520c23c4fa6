"""URP and Core RP include stand-ins, round 3 (issue 34): Core RP's ACES.hlsl, URP's
LODCrossFade.hlsl and PostProcessing/Common.hlsl, URP's UnpackNormal; a macro a shader defines
again (FXC's warning, the later body); Shader Graph's scene nodes given a float4.

Scene: test_urp_library_round2's (the corpus camera, a unit UV sphere whose material is the URP
pass under test; the pass returns a constant, so every covered pixel is checked).
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.maths.reference import aces_colorspaces as aces
from test_urp_library_round2 import LANGUAGES, render_constant, urp_pass  # pytest puts this folder on sys.path

ULP = 2.0 ** -24  # float32's unit roundoff


# ---------------------------------------------------------------------------------------------
# Core RP's ACES.hlsl

ACES_INCLUDE = '#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/ACES.hlsl"'
COLOUR = np.array([0.8, 0.35, 0.1])  # a saturated orange, linear sRGB primaries
HLSL_COLOUR = "float3(0.8, 0.35, 0.1)"
ACES_CASES = {
    # body -> its float64 value (aces_colorspaces.py, each from the ACES documents)
    "unity_to_ACES": (f"return float4(unity_to_ACES({HLSL_COLOUR}), 1.0);", aces.unity_to_aces(COLOUR)),
    "ACES_to_ACEScg": (f"return float4(ACES_to_ACEScg(unity_to_ACES({HLSL_COLOUR})), 1.0);",
                       aces.aces_to_acescg(aces.unity_to_aces(COLOUR))),
    "ACEScc": ("return float4(ACES_to_ACEScc(0.18), ACEScc_to_ACES(0.25), ACES_to_ACEScc(0.00001), 1.0);",
               np.array([aces.aces_to_acescc(0.18), aces.acescc_to_aces(0.25), aces.aces_to_acescc(1e-5)])),
    "rrt_helpers": (f"return float4(rgb_2_yc({HLSL_COLOUR}), rgb_2_hue({HLSL_COLOUR}) / 360.0, "
                    f"rgb_2_saturation({HLSL_COLOUR}) + sigmoid_shaper(0.7) + glow_fwd(0.1, RRT_GLOW_GAIN, RRT_GLOW_MID), 1.0);",
                    np.array([aces.rgb_2_yc(COLOUR), aces.rgb_2_hue(COLOUR) / 360.0,
                              aces.rgb_2_saturation(COLOUR) + aces.sigmoid_shaper(0.7)
                              + aces.glow_fwd(0.1, aces.RRT_GLOW_GAIN, aces.RRT_GLOW_MID)])),
    "dim_surround": (f"return float4(darkSurround_to_dimSurround({HLSL_COLOUR}), 1.0);",
                     aces.dark_to_dim_surround(COLOUR)),
}
# Bounds, relative to the largest channel, from the operations' float32 error: the matrices
# are written to 9 decimals (5e-10, under float32's rounding); a 3x3 product of entries and
# inputs below 2.6 sums 3 products: 8 ulps; two products: 16. ACEScc: log2 / exp2 are within 3
# ulps (GLSL 4.60 section 4.7.1's precision table); ACEScc_to_ACES's exp2 argument 17.52 x - 9.72
# carries 17.52 x's rounding (about 2 ulps of 4.4) into a relative error ln 2 * 2 * 4.4 ulps:
# 32 ulps bounds all three. rgb_2_hue: atan2's error (GLSL's table gives atan 4096 ulps of pi) /
# 360 degrees: 4096 * pi * 57.3 / 360 ulps = 2048 ulps; the rest a few ulps each. dim surround:
# xyY's divisions (2.5 ulps), pow = exp2(0.9811 log2 Y) (3 + 3 ulps and the product's), two
# 3x3 products (16): 32 ulps.
ACES_BOUND = {"unity_to_ACES": 8 * ULP, "ACES_to_ACEScg": 16 * ULP, "ACEScc": 32 * ULP,
              "rrt_helpers": 2048 * ULP, "dim_surround": 32 * ULP}


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("case", sorted(ACES_CASES))
def test_core_aces_names_are_the_academys(tmp_path, language, case):
    """unity_to_ACES (BT.709 -> AP0 with the Bradford adaptation D65 -> the ACES white),
    ACES_to_ACEScg (AP0 -> AP1), ACEScc's log encoding and its inverse (S-2014-003), the RRT's
    YC, hue, saturation, sigmoid and glow (aces-dev's RRT_Common) and the ODT's dark-to-dim
    surround (Y^0.9811), against the float64 values of aces_colorspaces.py, which computes the
    matrices from the primaries, within ACES_BOUND of the largest channel on every covered
    pixel. Control: the colour through the un-adapted matrix (XYZ_2_AP0 REC709_2_XYZ, no
    Bradford step) differs from unity_to_ACES by far more than its bound."""
    body, expected = ACES_CASES[case]
    pixels, _ = render_constant(tmp_path, urp_pass("aces " + case, body, ACES_INCLUDE), language, environment=False)
    bound = ACES_BOUND[case] * np.abs(expected).max()
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > bound).mean() == 0.0, (err.max() / bound, pixels[0, :3], expected)
    unadapted = aces.XYZ_2_AP0 @ aces.REC709_2_XYZ @ COLOUR  # control: no chromatic adaptation
    assert np.abs(unadapted - aces.unity_to_aces(COLOUR)).max() > 1000 * ACES_BOUND["unity_to_ACES"]


def test_aces_reference_matrices_meet_the_standards_anchors():
    """The reference's matrices from primaries: AP1's luminance row sums to 1 (Y of the white
    is 1), sRGB white (1, 1, 1) maps to AP0 white (1, 1, 1) through the adaptation, and AP0 ->
    AP1 -> AP0 is the identity, each to float64 rounding (1e-12). Control: without the Bradford
    step the white lands off (1, 1, 1) by more than 1e-3."""
    assert abs(aces.AP1_RGB2Y.sum() - 1.0) < 1e-12
    assert np.abs(aces.SRGB_2_AP0 @ np.ones(3) - 1.0).max() < 1e-12
    assert np.abs(aces.AP1_2_AP0 @ aces.AP0_2_AP1 - np.eye(3)).max() < 1e-12
    assert np.abs(aces.XYZ_2_AP0 @ aces.REC709_2_XYZ @ np.ones(3) - 1.0).max() > 1e-3


# ---------------------------------------------------------------------------------------------
# URP's PostProcessing/Common.hlsl and Core RP Color.hlsl's fast curves

POST_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/Shaders/PostProcessing/Common.hlsl"'
POST_BODY = """return float4(GetSRGBToLinear(float3(0.5, 0.5, 0.5)).r + FastSRGBToLinear(float3(0.25, 0.25, 0.25)).g,
                              ApplyVignette(float3(1.0, 1.0, 1.0), float2(0.7, 0.4), float2(0.5, 0.5), 1.2, 0.8, 2.0,
                                            float3(0.1, 0.2, 0.3)).g,
                              GetLuminance(float3(0.2, 0.5, 0.8)) + ApplyTonemap(float3(1.5, 0.5, -0.5)).r, 1.0);"""


def post_pass(name: str, body: str, include: str) -> str:
    """urp_pass with its own struct names: Blit.hlsl, which Common.hlsl includes (as URP's
    does), declares Attributes and Varyings."""
    return urp_pass(name, body, include).replace("Attributes", "Appdata").replace("Varyings", "V2f")


def _post_expected() -> np.ndarray:
    """sRGB decode (IEC 61966-2-1) + Taylor's fast fit; URP's vignette; Rec. 709 luminance plus
    the clamp ApplyTonemap does with no tonemapping mode."""
    from pbrlab.maths.reference.color import srgb_to_linear
    fast = 0.25 * (0.25 * (0.25 * 0.305306011 + 0.682171111) + 0.012522878)
    d = np.abs(np.array([0.7, 0.4]) - 0.5) * 1.2
    d[0] *= 0.8
    v = max(1.0 - d @ d, 0.0) ** 2.0
    vignette = 0.2 + (1.0 - 0.2) * v  # lerp(colour.g, 1, v) times the input 1
    luminance = np.array([0.2, 0.5, 0.8]) @ np.array([0.2126729, 0.7151522, 0.0721750])
    return np.array([srgb_to_linear(0.5) + fast, vignette, luminance + 1.0])


# pow in the sRGB curve and the vignette: exp2(y log2 x), 3 ulps each and the product's
# rounding amplified by |y log2 x| < 2 times ln 2: under 16 ulps of values below 2.
POST_BOUND = 16 * ULP * 2.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_post_processing_common_functions(tmp_path, language):
    """GetSRGBToLinear (the exact curve without _USE_FAST_SRGB_LINEAR_CONVERSION), Color.hlsl's
    FastSRGBToLinear, ApplyVignette (URP's: |uv - centre| * intensity, x by roundness,
    saturate(1 - d.d)^smoothness from the colour to 1), GetLuminance (Rec. 709) and ApplyTonemap
    with no mode (saturate) against float64 within POST_BOUND. Control: the built-in Luminance's
    weights (unity_ColorSpaceLuminance, linear) in place of Rec. 709's differ by far more."""
    pixels, _ = render_constant(tmp_path, post_pass("post", POST_BODY, POST_INCLUDE), language, environment=False)
    expected = _post_expected()
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > POST_BOUND).mean() == 0.0, (err.max(), pixels[0, :3], expected)
    from pbrlab.maths.reference.unity_cg import LUMINANCE_WEIGHTS
    builtin = np.array([0.2, 0.5, 0.8]) @ LUMINANCE_WEIGHTS + 1.0  # control: the built-in's weights
    assert abs(builtin - expected[2]) > 1000 * POST_BOUND


def test_post_processing_tonemap_modes_are_refused(tmp_path):
    """ApplyTonemap under _TONEMAP_ACES (URP's ACES mode, not provided) is refused at compile
    time naming it, not drawn clamped. Control: without the keyword it renders (test above)."""
    text = post_pass("post aces", "return float4(ApplyTonemap(float3(1.5, 0.5, 0.25)), 1.0);",
                    "#define _TONEMAP_ACES 1\n" + POST_INCLUDE)
    with pytest.raises(PbrlabError, match="ACES and Neutral tonemapping"):
        render_constant(tmp_path, text, "hlsl", environment=False)


# ---------------------------------------------------------------------------------------------
# URP's LODCrossFade.hlsl

LOD_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/LODCrossFade.hlsl"'
LOD_BODY = """LODFadeCrossFade(IN.positionCS);
                return float4(CopySign(0.25, -2.0), CopySign(-0.5, 3.0), unity_LODFade.x, 1.0);"""
# the 4 x 4 Bayer matrix (Bayer 1973's ordered-dither index matrix), row-major
BAYER = np.array([[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]], np.float64)


def _full_image(tmp_path, text, language):
    """The linear RGBA image, every pixel, of render_constant's scene without an environment."""
    from pbrlab.importers.loader import parse_scene
    from pbrlab.render.renderer import render_scene
    shader = tmp_path / "t.shader"
    shader.write_text(text)
    data = {"camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
            "lights": [], "materials": {"m": {"surface": str(shader)}},
            "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]}
    scene = parse_scene(data, origin="urp lod test scene", base=tmp_path)
    return render_scene(scene, language=language).linear.astype(np.float64)


@pytest.mark.parametrize("language", LANGUAGES)
def test_lod_cross_fade_keeps_a_fully_shown_object(tmp_path, language):
    """LODFadeCrossFade at pbrlab's fade 1 (no LOD Group: every object fully shown) discards no
    pixel: the covered pixels are those of the same pass without the call; CopySign is |x| with
    s's sign; unity_LODFade.x is 1. Control: the stand-in's dither pattern at fade 0.5
    (clip(0.5 - n)) keeps exactly the pixels whose Bayer threshold (k + 0.5) / 16 is below 0.5
    (the float64 pattern at the pixel's integer coordinates, y from the bottom row), half of them."""
    image = _full_image(tmp_path, urp_pass("lod", LOD_BODY, LOD_INCLUDE), language)
    plain = _full_image(tmp_path, urp_pass("lod plain", "return float4(-0.25, 0.5, 1.0, 1.0);", LOD_INCLUDE), language)
    covered = image[..., 3] > 0
    assert covered.sum() > 200 and (covered == (plain[..., 3] > 0)).all()
    assert (image[covered][:, :3] == np.array([-0.25, 0.5, 1.0])).all()
    half = urp_pass("lod half", "clip(0.5 - pbrlab_lod_dither(IN.positionCS.xy)); return float4(1.0, 1.0, 1.0, 1.0);",
                    LOD_INCLUDE)
    kept = _full_image(tmp_path, half, language)[..., 3] > 0
    rows, cols = np.indices(covered.shape)
    from_bottom = covered.shape[0] - 1 - rows
    expected = covered & ((BAYER[from_bottom % 4, cols % 4] + 0.5) / 16.0 < 0.5)
    assert (kept == expected).all(), (kept != expected).sum()
    assert 0.4 < kept.sum() / covered.sum() < 0.6


# ---------------------------------------------------------------------------------------------
# URP's UnpackNormal

NORMAL_BODY = """float3 a = UnpackNormal(float4(0.5, 0.5, 0.5, 1.0));
                float3 b = UnpackNormal(float4(1.0, 0.75, 0.2, 0.6));
                return float4(a.z, b.x, b.y + b.z, 1.0);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_urp_unpack_normal_reads_rg_or_ag(tmp_path, language):
    """URP's UnpackNormal (Core RP Packing.hlsl on desktop: UnpackNormalmapRGorAG, scale 1): a
    grey texel is the flat normal (z = 1), and (1, 0.75, 0.2, 0.6) gives x = 2 a r - 1 = 0.2,
    y = 2 g - 1 = 0.5, z = sqrt(1 - x^2 - y^2), blue ignored (unity_cg.py's float64
    unpack_normalmap_rg_or_ag). Bound: a sqrt and a few products of values below 1, 8 ulps.
    Control: the built-in RGB form gives z = 0 for grey and x = 1 for the second texel."""
    from pbrlab.maths.reference.unity_cg import unpack_normalmap_rg_or_ag
    pixels, _ = render_constant(tmp_path, urp_pass("unpack", NORMAL_BODY), language, environment=False)
    a = unpack_normalmap_rg_or_ag(np.array([0.5, 0.5, 0.5, 1.0]))
    b = unpack_normalmap_rg_or_ag(np.array([1.0, 0.75, 0.2, 0.6]))
    expected = np.array([a[2], b[0], b[1] + b[2]])
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > 8 * ULP * 2.0).mean() == 0.0, (err.max(), pixels[0, :3], expected)
    rgb = np.array([0.5 * 2 - 1, 1.0 * 2 - 1])  # control: the built-in's xyz * 2 - 1 (z of grey, x)
    assert np.abs(rgb - expected[:2]).max() > 0.5


# ---------------------------------------------------------------------------------------------
# A macro defined again (FXC: warning X1519, the later body)

REDEFINE_INCLUDE = """float before() { return unity_ColorSpaceDouble.w; }
            #define UNITY_PI 3.0
            #define unity_ColorSpaceDouble float4(0.25, 0.5, 0.75, 1.0)
            """
REDEFINE_BODY = "return float4(unity_ColorSpaceDouble.x + UNITY_PI, unity_ColorSpaceDouble.w * 0.5, before() * 0.25, 1.0);"


@pytest.mark.parametrize("language", LANGUAGES)
def test_shaders_own_macro_body_wins_from_its_line(tmp_path, language):
    """A shader that #defines unity_ColorSpaceDouble and UNITY_PI (names pbrlab's Unity layer
    defines) with other bodies renders, as under FXC: the code after the #define reads the
    shader's body (0.25 + 3, 1 * 0.5), the function before it the layer's (w = 2: 0.5), exact;
    a note names the line. Control: without the two #defines the layer's bodies are read (red
    4.59 + pi), and the glslang/Mesa refusal the #undef avoids is what a redefinition gets when
    the transform is not applied (the compiler's "Macro redefined" / "Redefinition of macro")."""
    text = urp_pass("redefine", REDEFINE_BODY, REDEFINE_INCLUDE)
    line = text.splitlines().index(next(l for l in text.splitlines() if "#define unity_ColorSpaceDouble" in l)) + 1
    with pytest.warns(UserWarning, match=rf"t\.shader:{line}: #define unity_ColorSpaceDouble .*X1519"):
        pixels, _ = render_constant(tmp_path, text, language, environment=False)
    assert (pixels[:, :3] == np.array([3.25, 0.5, 0.5])).all(), pixels[0]
    layer, _ = render_constant(tmp_path, urp_pass("layer", REDEFINE_BODY, REDEFINE_INCLUDE.replace("#define", "// #define")),
                               language, environment=False)
    assert abs(layer[0, 0] - 3.25) > 1.0  # control: the layer's bodies
    from pbrlab.importers.unity import macro_redefinitions
    from unittest import mock
    with mock.patch.object(macro_redefinitions, "provided_macros", return_value={}), \
            pytest.raises(PbrlabError, match=r"(?i)redefin"):  # control: no #undef, the compilers refuse
        render_constant(tmp_path, urp_pass("refused", REDEFINE_BODY, REDEFINE_INCLUDE), language, environment=False)


def test_undef_keeps_the_lines_after_it(tmp_path):
    """The #undef takes a blank line directly above the #define, else the first blank line below
    is dropped: the line count and every line after that blank line are unchanged, and the
    #define's body is kept. Control: a shader without a redefinition is returned as it is."""
    from pbrlab.importers.unity.macro_redefinitions import undefined_before_redefinition
    program = "#pragma vertex v\n#define UNITY_PI 3.0\n#define unity_ColorSpaceDouble 1.0\nfloat a;\n\n\nfloat b;\n"
    out, _, notes = undefined_before_redefinition(program, tmp_path / "t.shader", 10, {})
    before, after = program.split("\n"), out.split("\n")
    assert len(after) == len(before) and after[6:] == before[6:]
    assert "#define UNITY_PI 3.0" in after and "#define unity_ColorSpaceDouble 1.0" in after
    assert after.index("#undef UNITY_PI") + 1 == after.index("#define UNITY_PI 3.0")
    assert after.index("#undef unity_ColorSpaceDouble") + 1 == after.index("#define unity_ColorSpaceDouble 1.0")
    assert [n.split(": ")[0] for n in notes] == [f"{tmp_path / 't.shader'}:11", f"{tmp_path / 't.shader'}:12"]
    plain = "#define MY_OWN 1\n\nfloat b;\n"
    assert undefined_before_redefinition(plain, tmp_path / "t.shader", 1, {})[0] == plain


# ---------------------------------------------------------------------------------------------
# Shader Graph's scene nodes given a float4

SCENE_INCLUDE = """#define REQUIRE_DEPTH_TEXTURE
            #define REQUIRE_OPAQUE_TEXTURE
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/ShaderGraphFunctions.hlsl\""""
SCENE_BODY = """float4 p = float4(GetNormalizedScreenSpaceUV(IN.positionCS), 0.75, 0.25);
                return float4(SHADERGRAPH_SAMPLE_SCENE_DEPTH(p), SampleSceneDepth(p.xy),
                              SHADERGRAPH_SAMPLE_SCENE_COLOR(p).g - SampleSceneColor(p.xy).g + SampleSceneDepth(p.zw), 1.0);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_scene_nodes_read_a_float4_positions_xy(tmp_path, language):
    """SHADERGRAPH_SAMPLE_SCENE_DEPTH / _COLOR given a float4 read its xy (FXC's implicit
    truncation to the float2 parameter): the same texel as SampleSceneDepth / SampleSceneColor
    at xy, bit for bit. The depth is the sphere's, spanning a range inside (0, 1). Control: the
    position's zw (another screen point) reads a different depth on most pixels."""
    pixels, _ = render_constant(tmp_path, urp_pass("scene", SCENE_BODY, SCENE_INCLUDE), language, environment=False)
    assert (pixels[:, 0] == pixels[:, 1]).all()
    assert 0.0 < pixels[:, 1].min() < pixels[:, 1].max() < 1.0
    assert (pixels[:, 2] != pixels[:, 1]).mean() > 0.5  # control: zw's depth (colour difference 0)


# ---------------------------------------------------------------------------------------------
# Core RP's ParallaxMapping.hlsl

PARALLAX_INCLUDE = '#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/ParallaxMapping.hlsl"'
PARALLAX_BODY = """float2 o = ParallaxOffset1Step(0.8, 0.1, float3(0.3, -0.2, 0.9));
                float3 v = GetViewDirectionTangentSpace(float4(1.0, 0.0, 0.0, -1.0), float3(0.0, 0.0, 2.0), float3(0.3, 0.4, 0.5));
                return float4(o.x, o.y, v.x + 10.0 * v.y + 100.0 * v.z, 1.0);"""


def _parallax_expected() -> np.ndarray:
    """ParallaxOffset1Step: unity_cg.parallax_offset (Kaneko 2001, Unity's 0.42 bias); the
    tangent-space view: rows t / |n|, sign(w) cross(n, t) / |n|, n / |n| (the surface-gradient
    framework's scaling of the unnormalized frame) times the view direction."""
    from pbrlab.maths.reference.unity_cg import parallax_offset
    o = parallax_offset(0.8, 0.1, np.array([0.3, -0.2, 0.9]))
    t, n, w = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 2.0]), -1.0
    frame = np.stack([t, np.sign(w) * np.cross(n, t), n]) / np.linalg.norm(n)
    v = frame @ np.array([0.3, 0.4, 0.5])
    return np.array([o[0], o[1], v[0] + 10.0 * v[1] + 100.0 * v[2]])


@pytest.mark.parametrize("language", LANGUAGES)
def test_parallax_offset_and_tangent_view(tmp_path, language):
    """ParallaxOffset1Step and GetViewDirectionTangentSpace against float64 within 16 ulps of
    the largest magnitude (a normalize, a divide, 3x3 products: a few ulps each, the sum
    weighted up to 100 times). Control: the bitangent without tangentWS.w's sign (the mirrored
    frame) moves the third channel by 8."""
    pixels, _ = render_constant(tmp_path, urp_pass("parallax", PARALLAX_BODY, PARALLAX_INCLUDE), language,
                                environment=False)
    expected = _parallax_expected()
    bound = 16 * ULP * np.abs(expected).max()
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > bound).mean() == 0.0, (err.max() / bound, pixels[0, :3], expected)
    assert abs(expected[2] - (expected[2] + 2 * 10.0 * 0.4)) > 1000 * bound  # control: sign(w) dropped


# ---------------------------------------------------------------------------------------------
# Core RP's GeometricTools.hlsl and Tessellation.hlsl

GEOMETRY_INCLUDE = '#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Tessellation.hlsl"'
GEOMETRY_CASES = {
    "rotation": """float3 r = Rotate(float3(1.0, 0.0, 0.0), float3(2.0, 1.0, 0.5), float3(0.0, 0.0, 2.0), 0.7);
                float3 m = mul(RotationFromAxisAngle(float3(0.6, 0.0, 0.8), sin(1.1), cos(1.1)), float3(0.2, 0.9, -0.4));
                return float4(r.x + 10.0 * m.x, r.y + 10.0 * m.y, r.z + 10.0 * m.z, 1.0);""",
    "intersections": """float2 roots; bool hit = IntersectRaySphere(float3(0.0, 0.0, -3.0), float3(0.1, 0.0, 1.0), 1.5, roots);
                float t; bool ahead = IntersectRayPlane(float3(0.0, 1.0, 0.0), float3(0.0, -0.5, 0.5), float3(0.0, 0.2, 0.0), float3(0.0, 1.0, 0.0), t);
                float3 q = ProjectPointOnPlane(float3(1.0, 2.0, 3.0), float3(0.0, 0.5, 0.0), float3(0.0, 0.6, 0.8));
                return float4(roots.x + 10.0 * roots.y, t + (hit && ahead ? 100.0 : 0.0),
                              q.y + 10.0 * DistanceFromPlane(float3(1.0, 2.0, 3.0), float4(0.0, 0.6, 0.8, -0.3)), 1.0);""",
    "tessellation": """float3 p0 = float3(0.0, 0.0, 0.0), p1 = float3(1.0, 0.0, 0.0), p2 = float3(0.0, 1.0, 0.0);
                float4 f = CalcTriTessFactorsFromEdgeTessFactors(GetDistanceBasedTessFactor(p0, p1, p2, float3(0.2, 0.3, 2.0), 1.5, 3.0));
                float3 ph = PhongTessellation(float3(0.3, 0.3, 0.0), p0, p1, p2, normalize(float3(-1.0, -1.0, 1.0)),
                                              normalize(float3(1.0, 0.0, 1.0)), normalize(float3(0.0, 1.0, 1.0)), float3(0.4, 0.3, 0.3), 0.75);
                return float4(f.x + 10.0 * f.y, f.z + 10.0 * f.w, ph.z + 10.0 * ph.x, 1.0);""",
}


def _geometry_expected(case: str) -> np.ndarray:
    from pbrlab.maths.reference import geometric_tools as g
    if case == "rotation":
        r = g.rotate_about([1.0, 0.0, 0.0], [2.0, 1.0, 0.5], [0.0, 0.0, 2.0], 0.7)
        m = g.rotation_matrix([0.6, 0.0, 0.8], 1.1) @ np.array([0.2, 0.9, -0.4])
        return r + 10.0 * m
    if case == "intersections":
        roots = g.quadratic_roots(1.01, 2.0 * -3.0, 9.0 - 1.5 ** 2)
        t = (0.2 - 1.0) / -0.5  # (plane y - origin y) / direction y
        q = g.project_on_plane([1.0, 2.0, 3.0], [0.0, 0.5, 0.0], [0.0, 0.6, 0.8])
        return np.array([roots[0] + 10.0 * roots[1], t + 100.0, q[1] + 10.0 * (0.6 * 2.0 + 0.8 * 3.0 - 0.3)])
    p = [np.zeros(3), np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])]
    e = g.distance_tess_factors(*p, [0.2, 0.3, 2.0], 1.5, 3.0)
    n = [v / np.linalg.norm(v) for v in (np.array([-1.0, -1.0, 1.0]), np.array([1.0, 0.0, 1.0]), np.array([0.0, 1.0, 1.0]))]
    ph = g.phong_tessellation([0.3, 0.3, 0.0], p, n, [0.4, 0.3, 0.3], 0.75)
    return np.array([e[0] + 10.0 * e[1], e[2] + 10.0 * e.mean(), ph[2] + 10.0 * ph[0]])


# float32: each term is a few operations (sqrt, normalize, divides: within 3 ulps each by GLSL
# 4.60's precision table; sin and cos of the angles 0.7 and 1.1, which the table leaves to the
# implementation, are llvmpipe's float32 library calls, a few ulps), weighted by up to 10 and
# summed: 64 ulps of the largest channel bounds each case. The "intersections" case carries the
# exact 100 of two true tests.
GEOMETRY_BOUND = 64 * ULP


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("case", sorted(GEOMETRY_CASES))
def test_geometric_tools_and_tessellation_factors(tmp_path, language, case):
    """Rotate (about an axis through a pivot) and RotationFromAxisAngle (Rodrigues),
    IntersectRaySphere's two roots (the quadratic formula), IntersectRayPlane's t and hit,
    ProjectPointOnPlane, DistanceFromPlane, GetDistanceBasedTessFactor (linear between 1.5 and 3)
    with CalcTriTessFactorsFromEdgeTessFactors (the inside factor the edges' mean) and
    PhongTessellation (Boubekeur and Alexa 2008) against float64 (maths/reference/
    geometric_tools.py) within GEOMETRY_BOUND of the largest channel. Control: the rotation by
    the opposite angle (a transposed matrix) moves the first case's channels by far more."""
    pixels, _ = render_constant(tmp_path, urp_pass("geometry " + case, GEOMETRY_CASES[case], GEOMETRY_INCLUDE),
                                language, environment=False)
    expected = _geometry_expected(case)
    bound = GEOMETRY_BOUND * np.abs(expected).max()
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > bound).mean() == 0.0, (err.max() / bound, pixels[0, :3], expected)
    from pbrlab.maths.reference import geometric_tools as g
    v = np.array([0.2, 0.9, -0.4])
    transposed = g.rotation_matrix([0.6, 0.0, 0.8], 1.1).T @ v  # control: the opposite rotation
    assert np.abs(10.0 * (transposed - g.rotation_matrix([0.6, 0.0, 0.8], 1.1) @ v)).max() > 1000 * bound


# ---------------------------------------------------------------------------------------------
# Core RP's RgbToHsv / HsvToRgb (Color.hlsl), BlendNormalRNM (CommonMaterial.hlsl), SharpenAlpha

NAMES_INCLUDE = """#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Color.hlsl"
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonMaterial.hlsl\""""
N1, N2 = np.array([0.3, -0.2, 0.9]), np.array([-0.4, 0.1, 0.8])
NAMES_CASES = {
    "rgb_to_hsv": "return float4(RgbToHsv(float3(0.2, 0.9, 0.5)), 1.0);",
    "hsv_to_rgb": "return float4(HsvToRgb(float3(0.3, 0.6, 0.8)), 1.0);",
    "rnm_sharpen": """float3 n = BlendNormalRNM(normalize(float3(0.3, -0.2, 0.9)), normalize(float3(-0.4, 0.1, 0.8)));
                return float4(n.x, n.y + 10.0 * n.z, SharpenAlpha(0.5 + 1.0 / 32768.0, 0.5), 1.0);""",
}


def _rnm(n1, n2):
    """Barre-Brisebois and Hill 2012: n2 rotated by the shortest-arc rotation taking (0, 0, 1)
    to n1 (Rodrigues about (0, 0, 1) x n1), in float64."""
    from pbrlab.maths.reference.geometric_tools import rotation_matrix
    z = np.array([0.0, 0.0, 1.0])
    axis = np.cross(z, n1)
    return rotation_matrix(axis, np.arccos(n1 @ z)) @ n2


def _names_expected(case: str) -> np.ndarray:
    import colorsys
    if case == "rgb_to_hsv":  # the hexcone with Unity's 1e-4 in both divisors (colorsys: the control)
        r, g, b = 0.2, 0.9, 0.5
        chroma = 0.9 - 0.2
        return np.array([1.0 / 3.0 + (b - r) / (6.0 * chroma + 1e-4), chroma / (0.9 + 1e-4), 0.9])
    if case == "hsv_to_rgb":
        return np.array(colorsys.hsv_to_rgb(0.3, 0.6, 0.8))
    n = _rnm(N1 / np.linalg.norm(N1), N2 / np.linalg.norm(N2))
    # SharpenAlpha of a constant alpha (fwidth 0, floored at 1e-4): 2^-15 / 1e-4 + 1/2
    return np.array([n[0], n[1] + 10.0 * n[2], 2.0 ** -15 / 1e-4 + 0.5])


# float32: a few operations per channel, each within 3 ulps (GLSL 4.60 precision table), the
# RNM channel weighted by 10: 32 ulps of the largest channel.
NAMES_BOUND = 32 * ULP


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("case", sorted(NAMES_CASES))
def test_core_hsv_rnm_and_sharpen_alpha(tmp_path, language, case):
    """RgbToHsv (the hexcone, Smith 1978, with Unity's 1e-4 in the divisors), HsvToRgb (Python's
    colorsys), BlendNormalRNM (the rotation of n2 by the one taking (0, 0, 1) to n1, computed by
    Rodrigues' formula) and SharpenAlpha of a constant alpha against float64 within NAMES_BOUND
    of the largest channel. Control: the whiteout blend (BlendNormal) differs from RNM by far
    more; colorsys' HSV without the 1e-4 agrees with RgbToHsv to 1e-4 only."""
    import colorsys
    pixels, _ = render_constant(tmp_path, urp_pass("names " + case, NAMES_CASES[case], NAMES_INCLUDE), language,
                                environment=False)
    expected = _names_expected(case)
    bound = NAMES_BOUND * np.abs(expected).max()
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err > bound).mean() == 0.0, (err.max() / bound, pixels[0, :3], expected)
    n1, n2 = N1 / np.linalg.norm(N1), N2 / np.linalg.norm(N2)
    whiteout = np.array([*(n1[:2] * n2[2] + n2[:2] * n1[2]), n1[2] * n2[2]])
    whiteout /= np.linalg.norm(whiteout)
    assert np.abs(whiteout - _rnm(n1, n2)).max() > 1000 * NAMES_BOUND  # control: another blend
    plain = np.array(colorsys.rgb_to_hsv(0.2, 0.9, 0.5))
    assert 10 * NAMES_BOUND < np.abs(plain - _names_expected("rgb_to_hsv")).max() < 1e-4


# ---------------------------------------------------------------------------------------------
# URP's AlphaDiscard's return value (URP 12 and later) and AlphaModulate

ALPHA_BODY = "return float4(AlphaDiscard(0.3, 0.5), AlphaModulate(float3(0.2, 0.4, 0.6), 0.5).g, 0.25, 1.0);"
CORE_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"'


def keyword_pass(name: str, body: str, keyword: str) -> str:
    """urp_pass with ``keyword`` defined before Core.hlsl, as a keyword the material enables is."""
    return urp_pass(name, body).replace(CORE_INCLUDE, f"#define {keyword} 1\n{CORE_INCLUDE}", 1)


@pytest.mark.parametrize("language", LANGUAGES)
def test_alpha_discard_returns_alpha_and_alpha_modulate(tmp_path, language):
    """AlphaDiscard(a, cutoff) is a value, a (URP 12+; without _ALPHATEST_ON nothing is clipped),
    AlphaModulate(albedo, a) is the albedo without _ALPHAMODULATE_ON and lerp(1, albedo, a) with
    it (0.4 -> 0.7), within 2 ulps. Control: under _ALPHATEST_ON the 0.3 < 0.5 alpha discards
    every pixel (the sphere is not drawn)."""
    pixels, _ = render_constant(tmp_path, urp_pass("alpha", ALPHA_BODY), language, environment=False)
    assert (np.abs(pixels[:, :3] - np.array([0.3, 0.4, 0.25])) <= 2 * ULP).all(), pixels[0]
    modulated, _ = render_constant(tmp_path, keyword_pass("alpha modulate", ALPHA_BODY, "_ALPHAMODULATE_ON"),
                                   language, environment=False)
    assert (np.abs(modulated[:, 1] - 0.7) <= 2 * ULP).all(), modulated[0]
    with pytest.raises(AssertionError):  # control: render_constant finds no covered pixel
        render_constant(tmp_path, keyword_pass("alpha test", ALPHA_BODY, "_ALPHATEST_ON"), language,
                        environment=False)


# URP 12+'s InitializeInputDataFog, IsSurfaceTypeTransparent, and URP 14's world-position varying
LIT_NAMES_INCLUDE = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"'
LIT_NAMES_BODY = """float p = 0.0;
                #if defined(REQUIRES_WORLD_SPACE_POS_INTERPOLATOR)
                p = 0.125;
                #endif
                SETUP_DEBUG_TEXTURE_DATA(p, IN.positionCS.xy, _NoSuchTexture);
                return float4(InitializeInputDataFog(float4(1.0, 2.0, 3.0, 1.0), 0.375),
                              (IsSurfaceTypeTransparent(1.0) ? 0.5 : 0.25) + (IsSurfaceTypeTransparent(0.0) ? 4.0 : 2.0), p, 1.0);"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_urp_lit_pass_names(tmp_path, language):
    """A pass copied from URP 14's Lit: InitializeInputDataFog gives the vertex stage's factor
    (no per-pixel fog here), IsSurfaceTypeTransparent is true for 1 only, SETUP_DEBUG_TEXTURE_DATA
    is nothing (no rendering debugger: its texture argument is not read), and Lighting.hlsl
    defines REQUIRES_WORLD_SPACE_POS_INTERPOLATOR as URP 14's Shadows.hlsl does: (0.375, 2.5,
    0.125), exact. Control: a program that does not include Lighting.hlsl does not get the
    define (blue 0)."""
    pixels, _ = render_constant(tmp_path, urp_pass("lit names", LIT_NAMES_BODY, LIT_NAMES_INCLUDE), language,
                                environment=False)
    assert (pixels[:, :3] == np.array([0.375, 2.5, 0.125])).all(), pixels[0]
    bare, _ = render_constant(tmp_path, urp_pass("lit names bare", LIT_NAMES_BODY), language, environment=False)
    assert (bare[:, 2] == 0.0).all()
