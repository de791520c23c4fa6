"""pbr/unity/unity_cg.glsl and lighting_legacy.glsl: Unity's helper functions against float64
transcriptions of Unity's formulas (pbrlab.maths.reference.unity_cg, .unity_lighting), in GLSL and in
the generated HLSL twin (language="hlsl")."""

import numpy as np
import pytest

from pbrlab import evaluate, vec3, vec4
from pbrlab.gpu.port_hlsl import port_expression, port_text
from pbrlab.maths.reference import color as ref_color
from pbrlab.maths.reference import unity_cg as R
from pbrlab.maths.reference import unity_lighting as L

RNG = np.random.default_rng(12)
N = 20000
LANGUAGES = ("glsl", "hlsl")
INCLUDES = {"glsl": ["pbr/unity/unity_cg.glsl"], "hlsl": ["pbr/unity/unity_cg.hlsl"]}
# float32 evaluation of short formulas on inputs in [0, 1]: a few ulp of values <= ~2; bound
# 2e-6 absolute.
BOUND = 2e-6
# A rebuilt z = sqrt(1 - x^2 - y^2) is ill-conditioned where the radicand nears 0 (dz = d(r)/2z):
# compare z^2, the radicand itself, a sum of three float32 terms <= 1: bound 4 ulp of 1.
RADICAND_BOUND = 4.8e-7


def _assert_normals(got, want):
    assert np.abs(got[:, :2] - want[:, :2]).max() <= BOUND
    assert np.abs(got[:, 2] ** 2 - want[:, 2] ** 2).max() <= RADICAND_BOUND


def _eval(expr, language, **inputs):
    """The GLSL expression, ported by the library's own generator for the HLSL run."""
    expr = expr if language == "glsl" else port_expression(expr)
    return evaluate(expr, language=language, includes=INCLUDES[language], **inputs)


@pytest.mark.parametrize("language", LANGUAGES)
def test_unpack_normal_dxt5nm_and_bc5(language):
    packed = RNG.uniform(0, 1, (N, 4))
    packed[: N // 2, 3] = 1.0  # BC5 / RGB maps: alpha 1, x in r
    got = _eval("vec4(UnpackNormalmapRGorAG(p), 0.0)", language, p=vec4(packed))
    _assert_normals(got, R.unpack_normalmap_rg_or_ag(packed))
    # DXT5nm stores x in alpha with r = 1: the swizzle recovers the same normal as BC5's (x, y)
    xy = RNG.uniform(0.2, 0.8, (N, 2))
    dxt5nm = np.stack([np.ones(N), xy[:, 1], np.zeros(N), xy[:, 0]], -1)
    bc5 = np.stack([xy[:, 0], xy[:, 1], np.zeros(N), np.ones(N)], -1)
    a = _eval("vec4(UnpackNormalmapRGorAG(p), 0.0)", language, p=vec4(dxt5nm))
    b = _eval("vec4(UnpackNormalmapRGorAG(p), 0.0)", language, p=vec4(bc5))
    np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("language", LANGUAGES)
def test_unpack_normal_with_scale_and_blend_normals(language):
    packed = RNG.uniform(0, 1, (N, 4))
    scale = RNG.uniform(0, 2, N)
    got = _eval("vec4(UnpackNormalWithScale(p, s), 0.0)", language, p=vec4(packed), s=scale)
    _assert_normals(got, R.unpack_normal_with_scale(packed, scale))
    n1 = R.unpack_normalmap_rg_or_ag(RNG.uniform(0.1, 0.9, (N, 4)))
    n2 = R.unpack_normalmap_rg_or_ag(RNG.uniform(0.1, 0.9, (N, 4)))
    got = _eval("vec4(BlendNormals(a, b), 0.0)", language, a=vec3(n1), b=vec3(n2))
    assert np.abs(got[:, :3] - R.blend_normals(n1, n2)).max() <= BOUND


@pytest.mark.parametrize("language", LANGUAGES)
def test_luminance_and_unitys_gamma_fits(language):
    c = RNG.uniform(0, 1, (N, 3))
    got = _eval("vec4(Luminance(c), LinearRgbToLuminance(c), 0.0, 0.0)", language, c=vec3(c))
    assert np.abs(got[:, 0] - R.luminance(c)).max() <= BOUND
    assert np.abs(got[:, 1] - R.linear_rgb_to_luminance(c)).max() <= BOUND
    g2l = _eval("vec4(GammaToLinearSpace(c), 0.0)", language, c=vec3(c))[:, :3]
    l2g = _eval("vec4(LinearToGammaSpace(c), 0.0)", language, c=vec3(c))[:, :3]
    assert np.abs(g2l - R.gamma_to_linear_space(c)).max() <= BOUND
    assert np.abs(l2g - R.linear_to_gamma_space(c)).max() <= BOUND
    # Unity's fits beside the exact curves: how far they are (docs/unity.md figures)
    assert 1e-3 < np.abs(R.gamma_to_linear_space(c) - ref_color.srgb_to_linear(c)).max() < 5e-3
    exact = _eval("vec4(GammaToLinearSpaceExact(c.x), LinearToGammaSpaceExact(c.y), 0.0, 0.0)", language, c=vec3(c))
    assert np.abs(exact[:, 0] - ref_color.srgb_to_linear(c[:, 0])).max() <= BOUND
    assert np.abs(exact[:, 1] - ref_color.linear_to_srgb(c[:, 1])).max() <= BOUND


@pytest.mark.parametrize("language", LANGUAGES)
def test_decode_hdr(language):
    data = RNG.uniform(0, 1, (N, 4))
    instr = np.stack([RNG.uniform(0, 8, N), RNG.uniform(0.5, 2.2, N), np.zeros(N), RNG.integers(0, 2, N)], -1)
    got = _eval("vec4(DecodeHDR(d, i), 0.0)", language, d=vec4(data), i=vec4(instr))
    want = R.decode_hdr(data, instr)
    assert np.abs(got[:, :3] - want).max() <= BOUND * max(1.0, np.abs(want).max())
    # the three-argument form (Unity 2018+): 0 is the two-argument (linear) decode, 1 drops the
    # exponent; control: the gamma decode differs from the linear one where alpha is used
    linear = _eval("vec4(DecodeHDR(d, i, 0), 0.0)", language, d=vec4(data), i=vec4(instr))
    gamma = _eval("vec4(DecodeHDR(d, i, 1), 0.0)", language, d=vec4(data), i=vec4(instr))
    want_gamma = R.decode_hdr(data, instr, colorspace_is_gamma=True)
    assert np.array_equal(linear, got)
    assert np.abs(gamma[:, :3] - want_gamma).max() <= BOUND * max(1.0, np.abs(want_gamma).max())
    assert np.abs(want_gamma - want).max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_lambert_and_blinn_phong_are_lighting_cgincs(language, tmp_path):
    n = RNG.normal(size=(N, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    l = RNG.normal(size=(N, 3))
    l /= np.linalg.norm(l, axis=1, keepdims=True)
    v = RNG.normal(size=(N, 3))
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    albedo = RNG.uniform(0, 1, (N, 3))
    spec, gloss = RNG.uniform(0.03, 1, N), RNG.uniform(0, 1, N)
    wrap = """#ifndef PBR_UNITY_TEST_LIT
#define PBR_UNITY_TEST_LIT
#include "pbr/unity/lighting_legacy.SUFFIX"
vec4 pbr_unity_test_lit(vec3 a, vec3 n, vec3 l, vec3 v, float sp, float gl) {
    SurfaceOutput s; s.Albedo = a; s.Normal = n; s.Emission = vec3(0.0, 0.0, 0.0);
    s.Specular = sp; s.Gloss = gl; s.Alpha = 1.0;
    UnityLight light; light.color = vec3(1.0, 1.0, 1.0); light.dir = l;
    return vec4(UnityLambertLight(s, light).r, UnityBlinnPhongLight(s, v, light).rgb);
}
#endif
"""
    suffix = "glsl" if language == "glsl" else "hlsl"
    wrap = wrap.replace("SUFFIX", suffix)
    if language == "hlsl":  # the same wrapper, ported as the library's files are
        wrap = port_text(wrap, "wrap.glsl")
    (tmp_path / f"wrap.{suffix}").write_text(wrap)
    got = evaluate("pbr_unity_test_lit(a, n, l, v, sp, gl)", language=language, includes=[f"wrap.{suffix}"],
                   include_dirs=[tmp_path], a=vec3(albedo), n=vec3(n), l=vec3(l),
                   v=vec3(v), sp=spec, gl=gloss)
    lam = L.lambert(albedo, n, l, 1.0)[:, 0]
    bp = L.blinn_phong(albedo, n, l, v, 1.0, spec[:, None], gloss[:, None], 0.5)
    assert np.abs(got[:, 0] - lam).max() <= BOUND
    # pow(NdotH, up to 128) in float32: relative 128 ulp at worst; bound 2e-5 abs on values <= ~1.5
    assert np.abs(got[:, 1:] - bp).max() <= 2e-5


@pytest.mark.parametrize("language", LANGUAGES)
def test_unpack_normal_dxt5nm_reads_alpha_and_green_only(language):
    packed = RNG.uniform(0, 1, (N, 4))
    got = _eval("vec4(UnpackNormalDXT5nm(p), 0.0)", language, p=vec4(packed))
    _assert_normals(got, R.unpack_normal_dxt5nm(packed))
    # red and blue are ignored: a DXT5nm texel (1, y, 1, x) and (0, y, 0, x) decode alike
    other = packed.copy()
    other[:, [0, 2]] = 1.0 - other[:, [0, 2]]
    np.testing.assert_array_equal(got, _eval("vec4(UnpackNormalDXT5nm(p), 0.0)", language, p=vec4(other)))


@pytest.mark.parametrize("language", LANGUAGES)
def test_parallax_offset(language):
    h, height = RNG.uniform(0, 1, N), RNG.uniform(0, 0.08, N)  # _Parallax: Range (0.005, 0.08)
    v = RNG.normal(size=(N, 3)) * RNG.uniform(0.1, 10, (N, 1))  # any length: normalised inside
    v[:, 2] = np.abs(v[:, 2])  # views from above the surface (tangent-space z >= 0)
    got = _eval("vec4(ParallaxOffset(h, ht, v), 0.0, 0.0)", language, h=h, ht=height, v=vec3(v))
    want = R.parallax_offset(h, height, v)
    # float32 of a few terms divided by z + 0.42 >= 0.42: bound 2e-6 relative to the largest
    # possible shift, height / 2 / 0.42 (<= 0.095)
    assert np.abs(got[:, :2] - want).max() <= BOUND * 0.1
    assert np.abs(want).max() <= 0.08 / 2 / 0.42 + 1e-12  # the offset limit the comment states


@pytest.mark.parametrize("language", LANGUAGES)
def test_compute_grab_screen_pos_is_gl_oriented(language):
    clip = RNG.uniform(-5, 5, (N, 4))
    clip[:, 3] = RNG.uniform(0.1, 5, N)
    got = _eval("ComputeGrabScreenPos(c)", language, c=vec4(clip))
    # values up to ~5: float32 of (x + w) / 2, bound 2 ulp of 8
    assert np.abs(got - R.compute_grab_screen_pos(clip)).max() <= 2e-6
    # UNITY_UV_STARTS_AT_TOP undefined (GL): the same xy as ComputeScreenPos with _ProjectionParams.x = 1
    assert np.abs(got - R.compute_grab_screen_pos(clip, uv_starts_at_top=True))[:, 1].max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_colour_space_constants_are_linear(language):
    got = _eval("vec4(unity_ColorSpaceGrey.x, unity_ColorSpaceDouble.x, unity_ColorSpaceLuminance.w, "
                "unity_ColorSpaceGrey.w * unity_ColorSpaceDouble.w)", language, x=np.zeros(1))[0]
    assert abs(got[0] - ref_color.srgb_to_linear(0.5)) <= 1e-7  # the exact decode of 0.5
    assert abs(got[1] - 2.0 ** 2.2) <= 1e-6  # 2 in gamma space, linear
    assert got[2] == 1.0 and got[3] == 1.0  # linear-mode flag; alphas stay gamma (0.5 * 2)
    lum = _eval("unity_ColorSpaceLuminance.xyz", language, x=np.zeros(1))[0]
    np.testing.assert_array_equal(lum, np.float32(R.LUMINANCE_WEIGHTS))


@pytest.mark.parametrize("language", LANGUAGES)
def test_lerp_one_to_and_lerp_white_to(language):
    b, t = RNG.uniform(0, 1, (N, 3)), RNG.uniform(0, 1, N)
    got = _eval("vec4(LerpWhiteTo(b, t), LerpOneTo(b.x, t))", language, b=vec3(b), t=t)
    assert np.abs(got[:, :3] - R.lerp_one_to(b, t[:, None])).max() <= BOUND
    assert np.abs(got[:, 3] - R.lerp_one_to(b[:, 0], t)).max() <= BOUND
    got = _eval("vec4(LerpOneTo(b, t), 0.0)", language, b=vec3(b), t=t)
    assert np.abs(got[:, :3] - R.lerp_one_to(b, t[:, None])).max() <= BOUND
