"""URP and Core RP names real URP shaders read that pbrlab refused (issue 34, session 44: the
inverse camera matrices, Core's camera-relative position functions, unity_LODFade, the sky
probe's box (unity_SpecCube0_ProbePosition / _BoxMin / _BoxMax, both pipelines) and URP's
BoxProjectedCubemapDirection, Core's Random.hlsl, the 2D-array and shadow-texture macros, and an
include written with backslashes), each rendered in both languages from a minimal shader of our
own and compared with its float64 value from Unity's documented meaning; each with a control
(the value the construct's absence or another reading gives) that the bound rejects.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene, scene_frame
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

EPS = 2.0 ** -24

_SHADER = """
Shader "t/names44" {
    Properties { %(properties)s }
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            %(includes)s
            %(globals)s
            struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };
            struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
            Varyings vert(Attributes IN) {
                Varyings OUT;
                OUT.positionCS = TransformObjectToHClip(IN.positionOS.xyz);
                OUT.uv = IN.uv;
                return OUT;
            }
            float4 frag(Varyings IN) : SV_Target { %(body)s }
            ENDHLSL
        }
    }
}
"""


def _render(tmp_path, language, body, includes="", globals_="", properties=""):
    text = _SHADER % {"body": body, "includes": includes, "globals": globals_, "properties": properties}
    return render_constant(tmp_path, text, language, environment=False)


# --- the inverse camera matrices -------------------------------------------------------------
CLIP = np.array([0.2, -0.1, 0.5, 1.0])  # a clip-space point (GL: z in [-w, w])
MATRICES = {  # name -> (the matrix it inverts, from the camera's view V and projection P)
    "unity_MatrixInvVP": lambda v, p: p @ v, "UNITY_MATRIX_I_VP": lambda v, p: p @ v,
    "unity_MatrixInvP": lambda v, p: p, "UNITY_MATRIX_I_P": lambda v, p: p,
    "unity_MatrixInvV": lambda v, p: v, "UNITY_MATRIX_I_V": lambda v, p: v,
}


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("name", sorted(MATRICES))
def test_inverse_camera_matrices_invert_the_cameras(tmp_path, language, name):
    """mul(inverse, c), divided by w: (M^-1 c).xyz / w, M the camera's view, projection or their
    product (URP's UnityInput.hlsl names), all from one camera. Bound: each matrix element is the
    float64 inverse rounded to float32 (2^-24 relative) and the product sums 4 terms (4 more
    roundings), so each component is off by at most 5 * 2^-24 * (|M^-1| |c|)_i; the divide by w
    doubles the relative error: 2 * 5 * 2^-24 * max_i (|M^-1| |c|)_i / |w| in the position,
    times the 0.1 the program scales it by, plus the output's own rounding (2^-24 of a value
    below 1). Control: the forward matrix in place of its inverse."""
    pixels, scene = _render(tmp_path, language, f"float4 w = mul({name}, float4(0.2, -0.1, 0.5, 1.0));"
                            " return float4(w.xyz / w.w * 0.1 + 0.5, 1.0);")
    frame = scene_frame(scene)
    forward = MATRICES[name](np.asarray(frame.view, np.float64), np.asarray(frame.proj, np.float64))
    inverse = np.linalg.inv(forward)
    w = inverse @ CLIP
    expected = w[:3] / w[3] * 0.1 + 0.5
    bound = 2 * 5 * EPS * np.max(np.abs(inverse) @ np.abs(CLIP)) / abs(w[3]) * 0.1 + EPS
    err = np.abs(pixels[:, :3] - expected).max(axis=1)
    assert (err <= bound).all(), (name, language, pixels[0, :3], expected, bound)
    f = forward @ CLIP
    control = f[:3] / f[3] * 0.1 + 0.5
    assert np.abs(control - expected).max() > 100 * bound


# --- Core's camera-relative positions, unity_LODFade ---------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_camera_relative_positions_are_the_identity_in_urp(tmp_path, language):
    """GetAbsolutePositionWS and GetCameraRelativePositionWS: URP renders with camera-relative
    rendering off, so both return the position given (exact: no arithmetic). Control: HDRP's
    camera-relative reading (the camera's position, (0, 0, 3.2), added) is off by 3.2 in z."""
    pixels, _ = _render(tmp_path, language, "float3 a = GetAbsolutePositionWS(float3(0.1, 0.2, 0.3));"
                        " float3 r = GetCameraRelativePositionWS(float3(0.25, 0.5, 0.125));"
                        " return float4(a + r, 1.0);")
    expected = np.array([0.1, 0.2, 0.3], np.float32) + np.array([0.25, 0.5, 0.125], np.float32)
    assert np.all(np.abs(pixels[:, :3] - expected) <= 2 * EPS)
    assert np.abs(np.array([0.35, 0.7, 0.425 + 3.2]) - expected).max() > 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_lod_fade_is_unitys_value_for_a_renderer_not_fading(tmp_path, language):
    """unity_LODFade, read without LODCrossFade.hlsl: (1, 1, 0, 0), the value of a renderer that is
    its only level, fully shown (no LOD Group here). Exact. Control: an unset uniform's 0."""
    pixels, _ = _render(tmp_path, language, "return float4(unity_LODFade.xyz * 0.5 + float3(0, 0, 0.25), 1.0);")
    assert np.all(pixels[:, :3] == np.array([0.5, 0.5, 0.25], np.float32))


# --- the sky probe's box and BoxProjectedCubemapDirection ----------------------------------------
def box_projected(direction, position, probe, box_min, box_max):
    """float64 parallax-corrected reflection (Lagarde and Zanuttini, SIGGRAPH 2012): with
    probe.w > 0, the ray position + t direction leaves the box at the least of its exit planes'
    t (the max plane along a positive component, the min plane along a negative one); the
    direction from the probe's centre to that point. With probe.w = 0 the direction as given."""
    direction, position = np.asarray(direction, float), np.asarray(position, float)
    if probe[3] <= 0.0:
        return direction
    with np.errstate(divide="ignore"):
        t = (np.where(direction >= 0.0, box_max[:3], box_min[:3]) - position) / direction
    return position - np.asarray(probe[:3]) + direction * np.min(t)


DIRECTION, POSITION = (0.6, 0.0, 0.8), (0.1, 0.2, 0.3)


@pytest.mark.parametrize("language", LANGUAGES)
def test_the_sky_probe_is_not_box_projected(tmp_path, language):
    """unity_SpecCube0_ProbePosition.w = 0 (box projection off) and BoxMin.w = 1 (no blending with
    a second probe), so URP's BoxProjectedCubemapDirection returns the direction as given. Exact
    (no arithmetic on that branch). Control: the same call with a box-projected probe at the
    origin and the box [-1, 1]^3 (the next test) turns it elsewhere."""
    pixels, _ = _render(tmp_path, language, "float3 d = BoxProjectedCubemapDirection(float3(0.6, 0.0, 0.8),"
                        " float3(0.1, 0.2, 0.3), unity_SpecCube0_ProbePosition, unity_SpecCube0_BoxMin,"
                        " unity_SpecCube0_BoxMax);"
                        " return float4(d * 0.5 + unity_SpecCube0_ProbePosition.w + (1.0 - unity_SpecCube0_BoxMin.w), 1.0);",
                        includes='#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"')
    sky = box_projected(DIRECTION, POSITION, (0, 0, 0, 0), None, None)
    assert np.all(np.abs(pixels[:, :3] - sky * 0.5) <= EPS)
    boxed = box_projected(DIRECTION, POSITION, (0, 0, 0, 1), (-1, -1, -1, 1), (1, 1, 1, 0))
    assert np.abs(boxed - sky).max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_box_projection_meets_the_box(tmp_path, language):
    """A box-projected probe at the origin, box [-1, 1]^3: the float64 exit point's direction.
    Bound: three float32 divides, a multiply-add and subtractions of values below 2 (a few 2^-24
    relative each, 8 in all) times the 0.5 scale. Control: the direction unprojected."""
    pixels, _ = _render(tmp_path, language, "float3 d = BoxProjectedCubemapDirection(float3(0.6, 0.0, 0.8),"
                        " float3(0.1, 0.2, 0.3), float4(0, 0, 0, 1), float4(-1, -1, -1, 1), float4(1, 1, 1, 0));"
                        " return float4(d * 0.5, 1.0);",
                        includes='#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"')
    expected = box_projected(DIRECTION, POSITION, (0, 0, 0, 1), (-1, -1, -1, 1), (1, 1, 1, 0)) * 0.5
    assert np.all(np.abs(pixels[:, :3] - expected) <= 8 * 2 * EPS)
    assert np.abs(np.array(DIRECTION) * 0.5 - expected).max() > 0.05


BUILTIN_PROBE = """
Shader "t/builtin probe" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct v2f { float4 pos : SV_POSITION; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }
        float4 frag(v2f i) : SV_Target {
            return float4(unity_SpecCube0_ProbePosition.w + 0.25, unity_SpecCube0_BoxMin.w * 0.5,
                          saturate(unity_SpecCube0_BoxMax.x) * 0.75, 1);
        }
        ENDCG
    } }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_the_built_in_pipeline_sees_the_same_sky_probe(tmp_path, language):
    """The built-in pipeline's UnityShaderVariables names: ProbePosition.w 0, BoxMin.w 1, an
    unbounded box (BoxMax.x huge, saturated to 1). Exact. Control: unset uniforms' zeros would
    give (0.25, 0, 0)."""
    pixels, _ = render_constant(tmp_path, BUILTIN_PROBE, language, environment=False)
    assert np.all(pixels[:, :3] == np.array([0.25, 0.5, 0.75], np.float32))


# --- Core's Random.hlsl ----------------------------------------------------------------------
M32 = 0xFFFFFFFF


def jenkins(x: int) -> int:
    """One round of Bob Jenkins' one-at-a-time hash on a 32-bit word (Dr. Dobb's 1997)."""
    x = (x + (x << 10)) & M32
    x ^= x >> 6
    x = (x + (x << 3)) & M32
    x ^= x >> 11
    return (x + (x << 15)) & M32


def construct_float(m: int) -> float:
    """The low 23 bits as the mantissa of a float in [1, 2), minus 1: (m mod 2^23) / 2^23."""
    return (m & 0x7FFFFF) / float(1 << 23)


def knuth_hash(s: int) -> float:
    """Core's Hash(uint): xor 2747636419, then multiplies by 2654435769 and xor-shifts by 16."""
    s ^= 2747636419
    s = (s * 2654435769) & M32
    s ^= s >> 16
    s = (s * 2654435769) & M32
    s ^= s >> 16
    s = (s * 2654435769) & M32
    return s / 2.0 ** 32


def gradient_noise(pixel, frame: int) -> float:
    """Jimenez 2014's interleaved gradient noise (float64)."""
    p = np.asarray(pixel, float) + frame * np.array([2.083, 4.867])
    inner = np.dot(p, [0.06711056, 0.00583715])
    return (52.9829189 * (inner - np.floor(inner))) % 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_core_random_functions(tmp_path, language):
    """GenerateHashedRandomFloat(uint2), Hash(uint) and InterleavedGradientNoise from the stand-in
    Random.hlsl against their float64 / exact-integer references. The hashes are integer
    arithmetic, exact, then one float conversion (2^-24 relative; Hash's float(s) rounds the word
    to 24 bits: 2^-24 relative). The gradient noise is frac(52.98 frac(x)) with x about 1: the inner
    frac carries x's float32 error (a few 2^-24 of x, from the sums of products), which the 52.98
    multiplies: 4 * 2 * 2^-24 * 53 bounds it. Control: a neighbouring input's values."""
    pixels, _ = _render(tmp_path, language, "return float4(GenerateHashedRandomFloat(uint2(3u, 7u)), Hash(5u),"
                        " InterleavedGradientNoise(float2(10.5, 20.5), 3), 1.0);",
                        includes='#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Random.hlsl"')
    expected = np.array([construct_float(jenkins(3 ^ jenkins(7))), knuth_hash(5), gradient_noise((10.5, 20.5), 3)])
    bound = np.array([EPS, EPS, 4 * 2 * EPS * 53])
    assert np.all(np.abs(pixels[:, :3] - expected) <= bound), (pixels[0, :3], expected)
    other = np.array([construct_float(jenkins(4 ^ jenkins(7))), knuth_hash(6), gradient_noise((11.5, 20.5), 3)])
    assert np.all(np.abs(other - expected) > 100 * bound)


# --- texture arrays and shadow textures ------------------------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_texture2d_array_is_one_layer_of_its_default(tmp_path, language):
    """TEXTURE2D_ARRAY / SAMPLE_TEXTURE2D_ARRAY(_LOD) and a TEXTURE2D_ARRAY_PARAM function: a
    one-layer array of the property's default colour ("red": (1, 0, 0)), every layer index
    reading it. Exact (0.5 and 0.25 of 1). Control: the material's "gray" in its place."""
    props = '_Layers ("Layers", 2DArray) = "red" {}'
    globals_ = ("TEXTURE2D_ARRAY(_Layers); SAMPLER(sampler_Layers);\n"
                "float4 ReadLayer(TEXTURE2D_ARRAY_PARAM(t, s), float2 uv) { return SAMPLE_TEXTURE2D_ARRAY_LOD(t, s, uv, 1, 0); }")
    body = ("float4 a = SAMPLE_TEXTURE2D_ARRAY(_Layers, sampler_Layers, IN.uv, 3);"
            " float4 b = ReadLayer(TEXTURE2D_ARRAY_ARGS(_Layers, sampler_Layers), IN.uv);"
            " return float4(a.rgb * 0.5 + b.rgb * 0.25, 1.0);")
    pixels, _ = _render(tmp_path, language, body, globals_=globals_, properties=props)
    assert np.all(pixels[:, :3] == np.array([0.75, 0.0, 0.0], np.float32))
    assert np.abs(np.array([0.75, 0.0, 0.0]) - 0.75 * 0.5 ** 1).max() > 0.1  # gray's (0.375, 0.375, 0.375)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_shadow_texture_is_passed_with_its_comparison_sampler(tmp_path, language):
    """TEXTURE2D_SHADOW, SAMPLER_CMP and a function taking TEXTURE2D_SHADOW_PARAM, called with
    TEXTURE2D_SHADOW_ARGS, reading a texel: the property's default ("white"). Exact. Control: an
    unbound texture's black."""
    props = '_ShadowTex ("Shadow", 2D) = "white" {}'
    globals_ = ("TEXTURE2D_SHADOW(_ShadowTex); SAMPLER_CMP(sampler_ShadowTex);\n"
                "float4 Texel(TEXTURE2D_SHADOW_PARAM(t, s)) { return LOAD_TEXTURE2D(t, int2(0, 0)); }")
    body = "return float4(Texel(TEXTURE2D_SHADOW_ARGS(_ShadowTex, sampler_ShadowTex)).rgb * 0.5, 1.0);"
    pixels, _ = _render(tmp_path, language, body, globals_=globals_, properties=props)
    assert np.all(pixels[:, :3] == np.float32(0.5))


# --- an include written with backslashes -------------------------------------------------------
def _project(tmp_path, include: str):
    (tmp_path / "Assets" / "ShaderLibs").mkdir(parents=True)
    (tmp_path / "Assets" / "ShaderLibs" / "Node.hlsl").write_text("float3 NodeColour() { return float3(0.25, 0.5, 0.75); }\n")
    (tmp_path / "Assets" / "Shaders").mkdir()
    text = _SHADER % {"body": "return float4(NodeColour(), 1.0);", "includes": f'#include "{include}"',
                      "globals": "", "properties": ""}
    shader = tmp_path / "Assets" / "Shaders" / "t.shader"
    shader.write_text(text)
    data = {"camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
            "materials": {"m": {"surface": str(shader)}},
            "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]}
    return parse_scene(data, origin="backslash include test", base=tmp_path)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_backslashed_project_include_is_read_from_the_project_root(tmp_path, language):
    """``#include "Assets\\ShaderLibs\\Node.hlsl"``: Unity reads the backslashes as folder
    separators, from the project's root (the folder holding Assets/). Exact colour. Control: a
    backslashed include of a file the project lacks is still refused, naming it."""
    image = render_scene(_project(tmp_path, r"Assets\ShaderLibs\Node.hlsl"), language=language).linear
    covered = image[..., 3] > 0
    assert covered.sum() > 200
    assert np.all(image[covered][:, :3] == np.array([0.25, 0.5, 0.75], np.float32))


def test_a_backslashed_include_of_a_missing_file_is_refused(tmp_path):
    with pytest.raises(PbrlabError, match=r"Assets/ShaderLibs/Missing\.hlsl"):
        render_scene(_project(tmp_path, r"Assets\ShaderLibs\Missing.hlsl"), language="glsl")


# --- URP's DepthNormalsPass.hlsl, included by a forward pass ----------------------------------------
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_forward_pass_may_include_and_call_the_depth_normals_pass(tmp_path, language):
    """Shaders/DepthNormalsPass.hlsl (DepthNormalsVertex / DepthNormalsFragment: the world-space
    normal, w 0), included by a forward pass that calls its fragment function: the unit sphere's
    normal. Each pixel's value is a unit vector (the normalized interpolated normal: |n| within
    4 float32 roundings of 1) whose z faces the camera (> 0 on the camera's side). Control: the
    un-normalized mapping n * 0.5 + 0.5 of the same pixels is no unit vector."""
    body = ("Varyings v; v.positionCS = IN.positionCS; v.uv = IN.uv;"
            " v.normalWS = TransformObjectToWorldNormal(normalize(IN.objectPos));"
            " float4 n; DepthNormalsFragment(v, n); return float4(n.xyz * 0.5 + 0.5, 1.0 - n.w);")
    text = (_SHADER % {"body": body, "globals": "", "properties": "",
                       "includes": '#include "Packages/com.unity.render-pipelines.universal/Shaders/DepthNormalsPass.hlsl"'})
    text = (text.replace("struct Attributes { float4 positionOS : POSITION; float2 uv : TEXCOORD0; };", "")
                .replace("struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };",
                         "struct Out { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; float3 objectPos : TEXCOORD3; };")
                .replace("Varyings vert(Attributes IN) {\n                Varyings OUT;",
                         "Out vert(Attributes IN) {\n                Out OUT; OUT.objectPos = IN.positionOS.xyz;")
                .replace("OUT.uv = IN.uv;", "OUT.uv = IN.texcoord;")
                .replace("float4 frag(Varyings IN)", "float4 frag(Out IN)"))
    pixels, _ = render_constant(tmp_path, text, language, environment=False)
    n = pixels[:, :3] * 2.0 - 1.0
    assert np.all(np.abs(np.linalg.norm(n, axis=1) - 1.0) <= 4 * 4 * EPS * 2)
    assert np.all(pixels[:, 3] == 1.0) and (n[:, 2] > 0.0).mean() > 0.99
    assert np.abs(np.linalg.norm(pixels[:, :3], axis=1) - 1.0).max() > 0.1


# --- UNITY_VERSION in a URP program -------------------------------------------------------------
_VERSIONED_CALL = """#if UNITY_VERSION >= %s
                return UniversalFragmentBlinnPhong(inputData, surfaceData);
                #else
                return UniversalFragmentBlinnPhong(inputData, float4(surfaceData.specular, 1), surfaceData.smoothness, 0, surfaceData.alpha);
                #endif"""


def _versioned_grid(tmp_path, threshold: int):
    import test_urp_shaders as simple_lit
    text = (simple_lit.SHADERS / "urp_blinn_phong_grid.shader").read_text()
    call = "return UniversalFragmentBlinnPhong(inputData, surfaceData);"
    assert call in text
    shader = tmp_path / "versioned_grid.shader"
    shader.write_text(text.replace(call, _VERSIONED_CALL % threshold))
    return simple_lit, shader


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_urp_program_sees_the_unity_version_of_its_urp(tmp_path, language):
    """``#if UNITY_VERSION >= 202120`` (simon-ramirez-afk's ShaderForwardLit.hlsl; Cyanilux's
    templates): a URP program is compiled with the UNITY_VERSION of URP 12 (2021.3: 202130), the
    version the stand-ins follow, so it takes the branch written for URP 12's
    UniversalFragmentBlinnPhong(InputData, SurfaceData); the #else branch's five-argument call is
    no URP version's (URP 7-10 take six), never compiled by the Unity it was written for. The
    pixel is SimpleLit's float64 Blinn-Phong (test_urp_shaders.assert_blinn_phong_grid: its
    transcription and bound, on the same grid). Control: a URP 14 threshold (202220) takes the
    #else branch, which is refused."""
    simple_lit, shader = _versioned_grid(tmp_path, 202120)
    lit = render_scene(parse_scene(simple_lit._grid_scene(shader), "t", tmp_path), language=language).linear
    simple_lit.assert_blinn_phong_grid(lit, language)
    (tmp_path / "later").mkdir()
    _, later = _versioned_grid(tmp_path / "later", 202220)
    with pytest.raises(PbrlabError, match="UniversalFragmentBlinnPhong"):
        render_scene(parse_scene(simple_lit._grid_scene(later), "t", tmp_path), language=language)
