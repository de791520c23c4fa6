"""URP and Core RP names real URP shaders read that pbrlab refused (issue 34, session 44's second
round): unity_StereoScaleOffset (both pipelines), URP's LinearDepthToEyeDepth, Core's
LinearEyeDepth(positionWS, viewMatrix), Min3 / Max3, ComputeClipSpacePosition(position[,
transform]), the LWRP "LightweightPipeline" tag, a real3x3 varying and Debug/Debugging3D.hlsl.
Each is rendered in both languages from a minimal shader of our own and compared with its float64
value from Unity's documented meaning, with a control (the value another reading gives, or the
refusal a user's mistake still gets) that the bound rejects.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.render.renderer import scene_frame
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path
from test_urp_names_round44 import _SHADER as NAMES44_SHADER

EPS = 2.0 ** -24

def _template() -> str:
    """Round 44's minimal URP shader (test_urp_names_round44._SHADER) with the SubShader's tag, more
    Varyings members and more vertex statements as parameters."""
    text = NAMES44_SHADER.replace("%(properties)s", "").replace('"UniversalPipeline"', '"%(tag)s"')
    text = text.replace("SV_POSITION; float2 uv : TEXCOORD0; };", "SV_POSITION; float2 uv : TEXCOORD0; %(varyings)s };")
    text = text.replace("OUT.uv = IN.uv;", "OUT.uv = IN.uv; %(vertex)s")
    assert text.count("%(tag)s") == text.count("%(varyings)s") == text.count("%(vertex)s") == 1
    return text


_SHADER = _template()


def _render(tmp_path, language, body, *, tag="UniversalPipeline", includes="", varyings="", vertex=""):
    text = _SHADER % {"tag": tag, "body": body, "includes": includes, "globals": "", "varyings": varyings,
                      "vertex": vertex}
    return render_constant(tmp_path, text, language, environment=False)


# The built-in pipeline's CGPROGRAM reads the same unity_compat globals (UnityCG.cginc)
_BUILTIN = """
Shader "t/names44b_builtin" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target { %(body)s }
            ENDCG
        }
    }
}
"""

# --- unity_StereoScaleOffset ------------------------------------------------------------------------
# TransformStereoScreenSpaceTex as UnityCG.cginc (and the OpenViva shaders) spell it: uv * s.xy + s.zw * w
_STEREO = ("float4 s = unity_StereoScaleOffset[unity_StereoEyeIndex];"
           " float2 uv = float2(0.3, 0.6) * s.xy + s.zw * 2.0;"
           " return float4(uv, s.x * 0.25 + s.w, 1.0);")


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("pipeline", ["urp", "builtin"])
def test_stereo_scale_offset_is_one_eye_covering_the_target(tmp_path, language, pipeline):
    """unity_StereoScaleOffset[eye] = (1, 1, 0, 0): one eye per render target (mono, or each
    slice of single-pass instanced stereo), where the per-eye map uv s.xy + s.zw w is the
    identity. Exact (a product by 1 and a sum with 0). Control: Unity's side-by-side single-pass
    left eye, (0.5, 1, 0, 0), halves u."""
    if pipeline == "urp":
        pixels, _ = _render(tmp_path, language, _STEREO)
    else:
        pixels, _ = render_constant(tmp_path, _BUILTIN % {"body": _STEREO}, language, environment=False)
    expected = np.array([0.3, 0.6, 0.25], np.float32)
    assert np.all(pixels[:, :3] == expected), (pipeline, language, pixels[0, :3])
    side_by_side = np.array([0.3 * 0.5, 0.6, 0.5 * 0.25])
    assert np.abs(side_by_side - expected).max() > 0.1


# --- depths -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_linear_depth_to_eye_depth_spans_near_to_far(tmp_path, language):
    """URP's LinearDepthToEyeDepth(d) for an orthographic camera's linear depth: near + (far - near) d
    on GL (UNITY_REVERSED_Z undefined). Bound: near and far are float32 (2^-24 relative each) and
    the three operations round once each: 5 * 2^-24 * far. Control: the perspective reading,
    LinearEyeDepth(d, _ZBufferParams), which is far from linear in d."""
    pixels, scene = _render(tmp_path, language, "return float4(LinearDepthToEyeDepth(0.25),"
                            " LinearDepthToEyeDepth(0.0), LinearDepthToEyeDepth(1.0), 1.0);")
    frame = scene_frame(scene)
    near, far = float(frame.near), float(frame.far)
    expected = np.array([near + (far - near) * 0.25, near, far])
    bound = 5 * EPS * far
    assert (np.abs(pixels[:, :3] - expected).max(axis=1) <= bound).all(), (pixels[0, :3], expected)
    perspective = 1.0 / ((1.0 - far / near) / far * 0.25 + 1.0 / near)
    assert abs(perspective - expected[0]) > 100 * bound


@pytest.mark.parametrize("language", LANGUAGES)
def test_linear_eye_depth_of_a_world_position(tmp_path, language):
    """Core's LinearEyeDepth(positionWS, viewMatrix): |z| of the point in view space, the distance
    along the camera's axis. Bound: the view matrix's elements are float32 and the product sums 4
    terms: 5 * 2^-24 * (|V| |p|)_z. Control: the signed view z (a right-handed view: negative)."""
    pixels, scene = _render(tmp_path, language,
                            "return float4(LinearEyeDepth(float3(0.1, 0.2, 0.3), GetWorldToViewMatrix()), 0.0, 0.0, 1.0);")
    view = np.asarray(scene_frame(scene).view, np.float64)
    point = np.array([0.1, 0.2, 0.3, 1.0])
    expected = abs((view @ point)[2])
    bound = 5 * EPS * (np.abs(view) @ np.abs(point))[2]
    assert (np.abs(pixels[:, 0] - expected) <= bound).all(), (pixels[0, 0], expected)
    assert abs((view @ point)[2] - expected) > 1.0


# --- Min3, Max3, ComputeClipSpacePosition ----------------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_min3_and_max3_per_component(tmp_path, language):
    """Core's Min3 / Max3: the least and the greatest of three values, per component of a vector.
    Exact (a choice, no arithmetic). Control: the middle values, which a two-argument reading
    (max(a, b), min(b, c)) would give."""
    pixels, _ = _render(tmp_path, language, "float2 lo = Min3(float2(0.5, 0.2), float2(0.125, 0.7), float2(0.25, 0.4));"
                        " return float4(Max3(0.2, 0.7, 0.4), lo, 1.0);")
    expected = np.array([0.7, 0.125, 0.2], np.float32)
    assert np.all(pixels[:, :3] == expected), pixels[0, :3]
    assert np.abs(np.array([0.4, 0.25, 0.4]) - expected).max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_compute_clip_space_position_of_a_position(tmp_path, language):
    """Core's ComputeClipSpacePosition(position[, transform]): mul(transform, (position.xyz, 1)),
    the identity transform when none is given; a float4 argument is truncated to its xyz (FXC's
    implicit truncation, warning X3206), so w is 1 whatever the argument's w. With
    UNITY_MATRIX_VP: the camera's P V (p, 1), whose w (the eye depth) is compared. Bound: the
    product of float32 elements sums 4 terms: 5 * 2^-24 * (|P V| |p|)_w, and the output's own
    rounding (2^-24 of a value below 1: the first channel). Control: the float4's own w (0.5)."""
    pixels, scene = _render(tmp_path, language,
                            "float4 c = ComputeClipSpacePosition(float4(0.1, 0.2, 0.3, 0.5));"
                            " float4 v = ComputeClipSpacePosition(float3(0.1, 0.2, 0.3), UNITY_MATRIX_VP);"
                            " return float4(c.w * 0.5, c.x + c.y + c.z, v.w, 1.0);")
    frame = scene_frame(scene)
    vp = np.asarray(frame.proj, np.float64) @ np.asarray(frame.view, np.float64)
    point = np.array([0.1, 0.2, 0.3, 1.0])
    expected = np.array([0.5, np.float32(np.float32(0.1) + np.float32(0.2)) + np.float32(0.3), (vp @ point)[3]])
    bound = np.array([EPS, 2 * EPS, 5 * EPS * (np.abs(vp) @ np.abs(point))[3]])
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    assert abs(0.5 * 0.5 - expected[0]) > 100 * bound[0]


# --- the LWRP tag -------------------------------------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_the_lightweight_pipeline_tag_runs_under_urp(tmp_path, language):
    """URP sets Shader.globalRenderPipeline to "UniversalPipeline,LightweightPipeline", so a SubShader
    tagged with LWRP's old value runs. Exact constant. Control: a misspelt tag is still refused,
    naming the tag."""
    pixels, _ = _render(tmp_path, language, "return float4(0.25, 0.5, 0.125, 1.0);", tag="LightweightPipeline")
    assert np.all(pixels[:, :3] == np.array([0.25, 0.5, 0.125], np.float32))
    with pytest.raises(PbrlabError, match='"RenderPipeline" = "LightweightPipe"'):
        _render(tmp_path, language, "return float4(0.25, 0.5, 0.125, 1.0);", tag="LightweightPipe")


# --- a real3x3 varying ----------------------------------------------------------------------------------
M = np.array([[0.1, 0.2, 0.3], [0.4, 0.5, 0.6], [0.7, 0.8, 0.9]])
V = np.array([0.5, 0.25, 0.125])


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_real3x3_varying_reaches_the_fragment(tmp_path, language):
    """A real3x3 : TEXCOORD1 member (Core's real is float here) passes as its three vectors, as
    FXC packs it into three interpolators; the fragment's mul(m, v) is the float64 M V. Bound: M
    interpolated between equal values (3 products and 2 sums per element, 5 * 2^-24 relative) and
    the product's 3 terms: 8 * 2^-24 * (|M| |v|). Control: mul(v, m), M^T v, the transposed
    reading a rows-for-columns mix-up gives."""
    rows = ", ".join(f"float3({', '.join(str(x) for x in row)})" for row in M)
    pixels, _ = _render(tmp_path, language, "return float4(mul(IN.tbn, float3(0.5, 0.25, 0.125)), 1.0);",
                        varyings="real3x3 tbn : TEXCOORD1;", vertex=f"OUT.tbn = real3x3({rows});")
    expected = M @ V
    bound = 8 * EPS * (np.abs(M) @ np.abs(V))
    assert (np.abs(pixels[:, :3] - expected) <= bound).all(), (pixels[0, :3], expected)
    assert np.abs(M.T @ V - expected).max() > 100 * bound.max()


# --- Debug/Debugging3D.hlsl -------------------------------------------------------------------------------
DEBUGGING_3D = '#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Debug/Debugging3D.hlsl"'


@pytest.mark.parametrize("language", LANGUAGES)
def test_debugging3d_include_without_the_rendering_debugger(tmp_path, language):
    """URP's Debugging3D.hlsl without DEBUG_DISPLAY (no Rendering Debugger view): only
    SETUP_DEBUG_TEXTURE_DATA, a no-op; the pass draws its own colour. Exact constant. Control: with
    DEBUG_DISPLAY defined the stand-in refuses, naming the debugger."""
    pixels, _ = _render(tmp_path, language, "SETUP_DEBUG_TEXTURE_DATA(inputData, IN.positionCS.xy, _BaseMap);"
                        " return float4(0.5, 0.25, 0.75, 1.0);", includes=DEBUGGING_3D)
    assert np.all(pixels[:, :3] == np.array([0.5, 0.25, 0.75], np.float32))
    with pytest.raises(PbrlabError, match="Rendering Debugger"):
        _render(tmp_path, language, "return float4(0.5, 0.25, 0.75, 1.0);", includes="#define DEBUG_DISPLAY 1\n" + DEBUGGING_3D)
