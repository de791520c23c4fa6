"""unity_compat/shader_variables (GLSL and its hand-written HLSL twin): UnityCG.cginc's helpers
over Unity's camera and object globals against float64 matrix maths (pbrlab.maths.reference.unity_cg
for the depth and pixel-snap formulas), the no-op macros of AutoLight / fog / instancing /
stereo expanding to valid code in both languages, and the harness's bind() values of the
camera globals seen from a rendered surface shader."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from pbrlab import evaluate, vec3, vec4
from pbrlab.render import renderer as render
from pbrlab import scene
from pbrlab.maths.camera import camera_frame, camera_rays
from pbrlab.render.depth_range import scene_frame
from pbrlab.maths.reference import unity_cg as R
from pbrlab.importers.unity.port import port_code_types

RNG = np.random.default_rng(41)
N = 4096
LANGUAGES = ("glsl", "hlsl")
EPS32 = float(np.finfo(np.float32).eps)
SUFFIX = {"glsl": "glsl", "hlsl": "hlsl"}

# A camera and an object transform as the harness builds them (camera.camera_frame; an object
# scaled, rotated and moved), rounded to float32 once: the shaders and the references read
# the same numbers.
_CAMERA = SimpleNamespace(position=np.array([1.5, 2.0, 4.0]), target=np.array([0.0, 0.2, 0.0]),
                          up=np.array([0.0, 1.0, 0.0]), fov_y_deg=40.0, size=(320, 240))
FRAME = camera_frame(_CAMERA, 2.0)


def _model():
    c, s = np.cos(0.7), np.sin(0.7)
    m = np.array([[c, 0, s, 0.3], [0, 1, 0, -0.2], [-s, 0, c, 0.5], [0, 0, 0, 1]]) @ np.diag([1.5, 0.8, 1.2, 1.0])
    return m


def _f32(m):
    return np.asarray(m, np.float32).astype(np.float64)


M = _f32(_model())
M_INV = _f32(np.linalg.inv(M))
V = _f32(FRAME.view)
V_INV = _f32(np.linalg.inv(V))
P = _f32(FRAME.proj)
VP = _f32(FRAME.proj @ FRAME.view)
CAMERA_POS = _f32(FRAME.position)


def _matrix(m, language):
    """A matrix literal: GLSL's mat4 takes columns, HLSL's float4x4 rows."""
    values = (m.T if language == "glsl" else m).reshape(-1)
    return ("mat4(" if language == "glsl" else "float4x4(") + ", ".join(repr(float(v)) for v in values) + ")"


def _wrapper(language, body):
    """The library file with its uniforms made assignable globals (`uniform` defined away in
    GLSL, `static` in HLSL, for this test only), the globals set from literals, then ``body``
    (written in HLSL's spellings: GLSL gets float4 -> vec4 & co. as macros, and MUL)."""
    head = ["#ifndef PBRLAB_TEST_NAMES", "#define PBRLAB_TEST_NAMES"]
    if language == "glsl":
        head += ["#define uniform", '#include "unity_compat/shader_variables.glsl"',
                 '#include "pbr/unity/unity_cg.glsl"', '#include "unity_compat/cg_compat.glsl"', "#undef uniform",
                 "#define float2 vec2", "#define float3 vec3", "#define float4 vec4", "#define float3x3 mat3",
                 "#define fixed float", "#define fixed4 vec4"]
    else:
        head += ["#define uniform static", '#include "unity_compat/shader_variables.hlsl"',
                 '#include "pbr/unity/unity_cg.hlsl"', "#undef uniform"]
    cam = ", ".join(repr(float(v)) for v in CAMERA_POS)
    head += ["void pbrlab_test_globals() {",
             f"    unity_ObjectToWorld = {_matrix(M, language)};",
             f"    unity_WorldToObject = {_matrix(M_INV, language)};",
             f"    unity_MatrixV = {_matrix(V, language)};",
             f"    unity_MatrixInvV = {_matrix(V_INV, language)};",
             f"    glstate_matrix_projection = {_matrix(P, language)};",
             f"    unity_MatrixVP = {_matrix(VP, language)};",
             f"    _WorldSpaceCameraPos = float3({cam});",
             "}", body, "#endif", ""]
    return "\n".join(head)


def _eval(language, body, expr, tmp_path, **inputs):
    name = f"names_test.{SUFFIX[language]}"
    (tmp_path / name).write_text(_wrapper(language, body))
    return evaluate(expr, language=language, includes=[name], include_dirs=[tmp_path], **inputs)


def _h(p):
    """Homogeneous points (w = 1) from (N, 3)."""
    return np.concatenate([p, np.ones((len(p), 1))], -1)


# float32 matrix products of values <= ~10 (4 products and 3 sums per component, two matrices
# chained): a few ulp of the largest partial sum; bound 8 ulp of 16 = 1.5e-5 absolute
# (measured worst 1.5e-6, HLSL UnityWorldToClipPos and UNITY_MATRIX_IT_MV).
TRANSFORM_BOUND = 1.5e-5

TRANSFORMS = """
float4 pbrlab_test_view_pos(float3 p) { pbrlab_test_globals(); return float4(UnityObjectToViewPos(p), 0.0); }
float4 pbrlab_test_view_pos4(float4 p) { pbrlab_test_globals(); return float4(UnityObjectToViewPos(p), 0.0); }
float4 pbrlab_test_world_to_view(float3 p) { pbrlab_test_globals(); return float4(UnityWorldToViewPos(p), 0.0); }
float4 pbrlab_test_world_to_clip(float3 p) { pbrlab_test_globals(); return UnityWorldToClipPos(p); }
float4 pbrlab_test_view_to_clip(float3 p) { pbrlab_test_globals(); return UnityViewToClipPos(p); }
float4 pbrlab_test_obj_view_dir(float4 p) { pbrlab_test_globals(); return float4(ObjSpaceViewDir(p), 0.0); }
float4 pbrlab_test_obj_light_dir(float4 p, float4 l) {
    pbrlab_test_globals(); _WorldSpaceLightPos0 = l; return float4(ObjSpaceLightDir(p), 0.0);
}
float4 pbrlab_test_world_light_dir(float4 p, float4 l) {
    pbrlab_test_globals(); _WorldSpaceLightPos0 = l; return float4(WorldSpaceLightDir(p), 0.0);
}
float4 pbrlab_test_world_to_object_dir(float3 d) { pbrlab_test_globals(); return float4(UnityWorldToObjectDir(d), 0.0); }
struct pbrlab_test_vertex { float4 vertex; float3 normal; };
float4 pbrlab_test_compute_macros(float4 p, float3 n) {
    pbrlab_test_globals();
    _ProjectionParams = float4(1.0, 0.5, 40.0, 1.0 / 40.0);
    pbrlab_test_vertex v; v.vertex = p; v.normal = n;
    float eye; COMPUTE_EYEDEPTH(eye);
    float depth01 = COMPUTE_DEPTH_01;
    float3 viewNormal = COMPUTE_VIEW_NORMAL;
    return float4(eye, depth01, dot(viewNormal, float3(0.6, 0.0, 0.8)), length(viewNormal));
}
float4 pbrlab_test_mv(float4 p) { pbrlab_test_globals(); return MUL(UNITY_MATRIX_MV, p); }
float4 pbrlab_test_t_mv(float4 p) { pbrlab_test_globals(); return MUL(UNITY_MATRIX_T_MV, p); }
float4 pbrlab_test_it_mv(float4 p) { pbrlab_test_globals(); return MUL(UNITY_MATRIX_IT_MV, p); }
float4 pbrlab_test_p(float4 p) { pbrlab_test_globals(); return MUL(UNITY_MATRIX_P, MUL(UNITY_MATRIX_I_V, MUL(UNITY_MATRIX_V, p))); }
"""


def _transforms(language):
    mul = "#define MUL(m, v) ((m) * (v))" if language == "glsl" else "#define MUL(m, v) mul(m, v)"
    return mul + "\n" + TRANSFORMS


@pytest.mark.parametrize("language", LANGUAGES)
def test_view_and_clip_transforms(language, tmp_path):
    p = RNG.uniform(-3, 3, (N, 3))
    body = _transforms(language)
    got = _eval(language, body, "pbrlab_test_view_pos(p)", tmp_path, p=vec3(p))[:, :3]
    want = (_h(p) @ (V @ M).T)[:, :3]
    assert np.abs(got - want).max() <= TRANSFORM_BOUND
    got4 = _eval(language, body, "pbrlab_test_view_pos4(q)", tmp_path, q=vec4(_h(p) * [1, 1, 1, 7]))[:, :3]
    np.testing.assert_array_equal(got4, got)  # the float4 overload ignores w, as Unity's
    got = _eval(language, body, "pbrlab_test_world_to_view(p)", tmp_path, p=vec3(p))[:, :3]
    assert np.abs(got - (_h(p) @ V.T)[:, :3]).max() <= TRANSFORM_BOUND
    got = _eval(language, body, "pbrlab_test_world_to_clip(p)", tmp_path, p=vec3(p))
    assert np.abs(got - _h(p) @ VP.T).max() <= TRANSFORM_BOUND
    got = _eval(language, body, "pbrlab_test_view_to_clip(p)", tmp_path, p=vec3(p))
    assert np.abs(got - _h(p) @ P.T).max() <= TRANSFORM_BOUND


@pytest.mark.parametrize("language", LANGUAGES)
def test_object_and_world_space_directions(language, tmp_path):
    p = _h(RNG.uniform(-2, 2, (N, 3)))
    light = np.concatenate([RNG.uniform(-5, 5, (N, 3)), RNG.integers(0, 2, (N, 1))], -1)  # w 0 or 1
    body = _transforms(language)
    got = _eval(language, body, "pbrlab_test_obj_view_dir(p)", tmp_path, p=vec4(p))[:, :3]
    want = (M_INV @ np.append(CAMERA_POS, 1.0))[:3] - p[:, :3]
    assert np.abs(got - want).max() <= TRANSFORM_BOUND
    got = _eval(language, body, "pbrlab_test_obj_light_dir(p, l)", tmp_path, p=vec4(p), l=vec4(light))[:, :3]
    want = (light @ M_INV.T)[:, :3] - p[:, :3] * light[:, 3:]
    assert np.abs(got - want).max() <= TRANSFORM_BOUND
    got = _eval(language, body, "pbrlab_test_world_light_dir(p, l)", tmp_path, p=vec4(p), l=vec4(light))[:, :3]
    want = light[:, :3] - (p @ M.T)[:, :3] * light[:, 3:]
    assert np.abs(got - want).max() <= TRANSFORM_BOUND
    d = RNG.normal(size=(N, 3))
    got = _eval(language, body, "pbrlab_test_world_to_object_dir(d)", tmp_path, d=vec3(d))[:, :3]
    want = d @ M_INV[:3, :3].T
    assert np.abs(got - want / np.linalg.norm(want, axis=-1, keepdims=True)).max() <= 2e-6


@pytest.mark.parametrize("language", LANGUAGES)
def test_matrix_macros_and_compute_macros(language, tmp_path):
    p = _h(RNG.uniform(-2, 2, (N, 3)))
    n = RNG.normal(size=(N, 3))
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    body = _transforms(language)
    mv = V @ M
    for expr, want in [("pbrlab_test_mv(p)", p @ mv.T), ("pbrlab_test_t_mv(p)", p @ mv),
                       ("pbrlab_test_it_mv(p)", p @ np.linalg.inv(mv)), ("pbrlab_test_p(p)", p @ P.T)]:
        got = _eval(language, body, expr, tmp_path, p=vec4(p))
        assert np.abs(got - want).max() <= TRANSFORM_BOUND, expr
    got = _eval(language, body, "pbrlab_test_compute_macros(p, n)", tmp_path, p=vec4(p), n=vec3(n))
    eye = -(p @ mv.T)[:, 2]
    view_normal = n @ np.linalg.inv(mv)[:3, :3]  # (MV)^-T n, as a row vector
    view_normal /= np.linalg.norm(view_normal, axis=-1, keepdims=True)
    assert np.abs(got[:, 0] - eye).max() <= TRANSFORM_BOUND
    assert np.abs(got[:, 1] - eye / 40.0).max() <= TRANSFORM_BOUND
    assert np.abs(got[:, 2] - view_normal @ [0.6, 0.0, 0.8]).max() <= 2e-6
    assert np.abs(got[:, 3] - 1.0).max() <= 2e-6


PIXEL_SNAP = "float4 pbrlab_test_snap(float4 c, float4 screen) { _ScreenParams = screen; return UnityPixelSnap(c); }"


@pytest.mark.parametrize("language", LANGUAGES)
def test_unity_pixel_snap(language, tmp_path):
    clip = np.concatenate([RNG.uniform(-4, 4, (N, 3)), RNG.uniform(0.5, 4, (N, 1))], -1)
    w, h = 320.0, 240.0
    screen = np.array([w, h, 1 + 1 / w, 1 + 1 / h])
    got = _eval(language, PIXEL_SNAP, "pbrlab_test_snap(c, s)", tmp_path, c=vec4(clip), s=vec4(screen))
    c32 = _f32(clip)
    want = R.pixel_snap(c32, w, h)
    # float32 x/w * (size/2) within 1e-4 of a half-integer may round either way of the
    # reference: leave those out (measured 0 to 4 of 4096); elsewhere the snapped position is
    # (k / (size/2)) w in float32: 4 ulp of |x| <= 4 * 4 = 7.6e-6 (measured 3.5e-7).
    frac = np.abs((c32[:, :2] / c32[:, 3:]) * [w / 2, h / 2] % 1 - 0.5)
    clear = (frac > 1e-4).all(-1)
    assert clear.mean() > 0.99
    assert np.abs(got[clear] - want[clear]).max() <= 4 * EPS32 * 16
    # on a pixel corner: NDC xy a multiple of 2/size
    ndc = got[:, :2] / got[:, 3:]
    k = ndc * [w / 2, h / 2]
    assert np.abs(k - np.round(k)).max() <= 1e-3


DEPTH = "float4 pbrlab_test_depth(float z, float4 zb) { _ZBufferParams = zb; return float4(LinearEyeDepth(z), Linear01Depth(z), 0.0, 0.0); }"


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("near, far", [(0.3, 1000.0), (FRAME.near, FRAME.far)])
def test_linear_eye_depth_inverts_the_gl_depth_buffer(language, near, far, tmp_path):
    eye = np.exp(RNG.uniform(np.log(near), np.log(far), N))
    z = _f32(R.depth_buffer_value(eye, near, far))  # what a float32 depth buffer would hold
    zb = _f32(R.zbuffer_params(near, far))
    got = _eval(language, DEPTH, "pbrlab_test_depth(z, zb)", tmp_path, z=z, zb=vec4(zb))
    want = R.linear_eye_depth(z, near, far)
    # The reference inverts the projection exactly (far from float32 z, eye is recovered)
    assert np.abs(R.depth_buffer_value(want, near, far) - z).max() <= 1e-12
    # GPU: 1/eye = zb.z z + zb.w in float32, terms up to 1/near cancelling to 1/eye: error a
    # few ulp of the terms' size; compared in 1/eye where that bound is linear (measured at
    # most 1.0 such ulp; eye itself within 1.9e-4 relative at far/near 3e3, 3.1e-3 at 5e4).
    scale = np.abs(zb[2] * z) + np.abs(zb[3])
    assert (np.abs(1 / got[:, 0] - 1 / want) <= 4 * EPS32 * scale).all()
    scale01 = np.abs(zb[0] * z) + np.abs(zb[1])
    assert (np.abs(1 / got[:, 1] - 1 / R.linear01_depth(z, near, far)) <= 4 * EPS32 * scale01).all()


MACROS = """
struct pbrlab_test_v2f {
    float4 pos;
    UNITY_FOG_COORDS(1)
    SHADOW_COORDS(2)
    LIGHTING_COORDS(3, 4)
    UNITY_LIGHTING_COORDS(5, 6)
    UNITY_SHADOW_COORDS(7)
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};
UNITY_INSTANCING_BUFFER_START(Props)
    UNITY_DEFINE_INSTANCED_PROP(float4, _PbrlabTestColor)
UNITY_INSTANCING_BUFFER_END(Props)

float4 pbrlab_test_macros(float4 c) {
    appdata_img v;
    v.vertex = float4(c.xyz, 1.0);
    v.texcoord = c.xy;
    pbrlab_test_v2f o;
    UNITY_INITIALIZE_OUTPUT(pbrlab_test_v2f, o);
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(v, o);
    o.pos = c;
    UNITY_TRANSFER_FOG(o, o.pos);
    TRANSFER_SHADOW(o)
    UNITY_TRANSFER_SHADOW(o, v.texcoord);
    TRANSFER_VERTEX_TO_FRAGMENT(o);
    UNITY_TRANSFER_LIGHTING(o, v.texcoord);
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(o);
    fixed4 col = o.pos;
    UNITY_APPLY_FOG(o.fogCoord, col);
    UNITY_APPLY_FOG_COLOR(o.fogCoord, col, fixed4(1, 0, 0, 1));
    UNITY_LIGHT_ATTENUATION(atten, o, v.vertex.xyz)
    half shadow = SHADOW_ATTENUATION(o) * LIGHT_ATTENUATION(o) * UNITY_SHADOW_ATTENUATION(o, v.vertex.xyz);
    UNITY_OPAQUE_ALPHA(col.a);
    float4 tint = UNITY_ACCESS_INSTANCED_PROP(Props, _PbrlabTestColor);
    v2f_img img = vert_img(v);
    return float4(UNITY_PROJ_COORD(col).rgb * atten * shadow, col.a) + 0.0 * tint + 0.0 * img.pos;
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_neutral_macros_expand_to_valid_code(language, tmp_path):
    """AutoLight (no shadows), fog (none), instancing and stereo (one instance, one eye) in a
    v2f struct and a vertex-to-fragment body as Unity's shaders write them: GLSL after
    port-unity's type renames (fixed4 -> vec4, half -> float), HLSL as written. The colour
    passes unchanged (attenuations 1, no fog) and UNITY_OPAQUE_ALPHA writes alpha 1."""
    body = port_code_types(MACROS) if language == "glsl" else MACROS
    c = RNG.uniform(0, 1, (64, 4))
    got = _eval(language, body, "pbrlab_test_macros(c)", tmp_path, c=vec4(c))
    np.testing.assert_array_equal(got[:, :3], np.float32(c[:, :3]))
    np.testing.assert_array_equal(got[:, 3], 1.0)


# --- bind(): the camera globals a rendered surface shader reads --------------------------------

SIZE = 48
DEPTH_SHADER = """Shader "pbrlab/test_depth_names" {
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        #include "UnityCG.cginc"
        struct Input { float4 screenPos; float3 worldPos; };
        void surf (Input IN, inout SurfaceOutput o) {
            float z = IN.screenPos.z / IN.screenPos.w * 0.5 + 0.5;
            o.Albedo = 0;
            o.Emission = float3(EXPR);
            o.Alpha = 1;
        }
        ENDCG
    }
}
"""
# r, g, b of the first render: eye depth three ways (the depth buffer's z through
# _ZBufferParams; the view and projection matrices, clip w = eye depth; Linear01Depth scaled by
# _ProjectionParams.z = far). The second, all zero: unity_MatrixInvV inverting unity_MatrixV;
# unity_CameraInvProjection inverting unity_CameraProjection (= UNITY_MATRIX_P) in x, y; the
# same in z, w, where the inverse's entries grow as 1/near (clip z and w cancel to recover the
# view point), times near (_ProjectionParams.y), plus unity_OrthoParams.w (0: perspective).
ROUND_TRIP = "(mul(unity_CameraInvProjection, mul(unity_CameraProjection, float4(1, 2, -3, 1))) - float4(1, 2, -3, 1))"
EXPRESSIONS = {
    "depth": "LinearEyeDepth(z), UnityViewToClipPos(UnityWorldToViewPos(IN.worldPos)).w, "
             "Linear01Depth(z) * _ProjectionParams.z",
    "inverses": "length(mul(UNITY_MATRIX_I_V, float4(UnityWorldToViewPos(IN.worldPos), 1.0)).xyz - IN.worldPos), "
                f"length({ROUND_TRIP}.xy) "
                "+ length(mul(unity_CameraProjection, float4(1, 2, -3, 1)) - mul(UNITY_MATRIX_P, float4(1, 2, -3, 1))), "
                f"length({ROUND_TRIP}.zw) * _ProjectionParams.y + unity_OrthoParams.w",
}


def _render_expression(expr, language, tmp_path):
    (tmp_path / "names.shader").write_text(DEPTH_SHADER.replace("EXPR", expr))
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [SIZE, SIZE]},
            "lights": [], "materials": {"m": {"surface": "names.shader"}},
            "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}
    s = scene.parse_scene(data, "<test>", tmp_path)
    return s, render.render_scene(s, language=language).linear


@pytest.mark.parametrize("language", LANGUAGES)
def test_bind_sets_the_camera_globals(language, tmp_path):
    s, got = _render_expression(EXPRESSIONS["depth"], language, tmp_path)
    frame = scene_frame(s)  # the planes the render used
    d = camera_rays(frame)
    o = frame.position
    b = d @ o
    disc = b * b - (o @ o - 1.0)
    hit = disc > 1e-3  # away from the silhouette, where 2x2 quads mix hit and miss
    t = -b - np.sqrt(np.maximum(disc, 0))
    eye = t * (d @ frame.forward)  # the hit's distance along the view axis
    assert (got[..., 3] > 0)[hit].all()
    # clip w from float32 matrices of the traced hit: bound 1e-6 relative to eye depths <= 4
    # (measured 9.0e-7 absolute)
    assert np.abs(got[..., 1][hit] - eye[hit]).max() <= 4e-6
    # the depth-buffer route: z = (z_ndc + 1) / 2 in float32, so 1/eye = z (1/far - 1/near) + 1/near
    # cancels terms of size 1/near: one ulp of z moves eye by eye^2 (1/near - 1/far) eps / 2;
    # bound 8 such ulp plus the clip route's 4e-6. With near = far * 1e-5 the ulp term ruled
    # (measured 1.6 of them: 9.8e-3 at near 1e-4); with the planes around the sphere
    # (depth_range.py: near 2.86, far 5.25) both are small (measured 9.0e-7 absolute)
    bound = 8 * EPS32 / 2 * eye[hit] ** 2 * (1 / frame.near - 1 / frame.far)
    assert (np.abs(got[..., 0][hit] - eye[hit]) <= bound + 4e-6).all()
    assert (np.abs(got[..., 2][hit] - eye[hit]) <= bound + 4e-6).all()
    _, inv = _render_expression(EXPRESSIONS["inverses"], language, tmp_path)
    assert np.abs(inv[..., :3][hit]).max() <= 1e-6  # float32 round trips of values <= 4: measured 1.2e-7
