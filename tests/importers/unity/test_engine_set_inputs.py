"""Engine-set inputs filled from the scene (issue 34): each as Unity's engine fills it, checked
by what the shader draws per pixel against a float64 expectation, with a control that fails.

- The terrain imposter's tree lights (Nature/TreeCreator/*Rendertex): the scene's first
  directional lights, towards each light in the tree's object space, colour x intensity
  (engine_inputs.FILLED).
- Motion vectors (Internal-MotionVectors and its per-object functions): a still camera and
  still objects, so the previous frame's matrices are this frame's and the motion is zero; a
  previous view-projection moved in clip space gives the float64-predicted motion.
- Particles/Standard Unlit through pbrlab's UnityStandardParticles.cginc: the colour modes
  (Unity Manual, "Standard Particle Shaders"), on meshes whose vertex colour is white.
"""

from __future__ import annotations

import colorsys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.engine_inputs import FILLED, fill_declared
from pbrlab.render.renderer import render_scene

BUILTIN = Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"
LANGUAGES = ("glsl", "hlsl")


def _render(data: dict, base: Path, language: str) -> np.ndarray:
    return render_scene(parse_scene(data, "test scene", base), language=language).linear


# An opaque pass that writes (1, 1, 1, 1): where a scene's object covers the image, for shaders
# that do not write alpha (ColorMask RGB).
COVERAGE_PASS = textwrap.dedent("""
    Shader "t/coverage" { SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct v2f { float4 pos : SV_POSITION; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }
        fixed4 frag(v2f i) : SV_Target { return fixed4(1, 1, 1, 1); }
        ENDCG
    } } }
""")


def _coverage(data: dict, base: Path) -> np.ndarray:
    """The pixels the scene's objects cover (drawn with COVERAGE_PASS)."""
    shader = base / "coverage.shader"
    shader.write_text(COVERAGE_PASS)
    data = {**data, "materials": {"m": {"surface": str(shader)}}}
    return _render(data, base, "glsl")[..., 3] > 0


def _unit(v):
    v = np.asarray(v, np.float64)
    return v / np.linalg.norm(v)


# --- the terrain imposter's tree lights -------------------------------------------------------

# A plane turned away from its own axes (object space is not world space: a direction given in
# world space would light it differently), facing the camera.
PLANE_ROTATE_DEG = (100.0, 0.0, 35.0)
# Four directional lights (the shaders read three slots: the fourth light must not count) and a
# point light (a billboard's lights are directions: it must not count either).
TREE_LIGHTS = [
    {"type": "directional", "direction": [-0.3, -0.2, -1.0], "color": [1.0, 0.5, 0.25], "intensity": 1.0},
    {"type": "directional", "direction": [0.6, 0.1, -0.8], "color": [0.2, 0.9, 0.4], "intensity": 0.5},
    {"type": "directional", "direction": [0.1, 0.7, 0.7], "color": [0.3, 0.3, 1.0], "intensity": 2.0},
    {"type": "directional", "direction": [0.0, 0.0, -1.0], "color": [5.0, 5.0, 5.0], "intensity": 1.0},
    {"type": "point", "position": [0.0, 0.0, 2.0], "color": [7.0, 7.0, 7.0], "intensity": 1.0, "range": 10},
]


def _rotation(degrees) -> np.ndarray:
    """The scene's rotation (scene/model.py _transform: X, then Y, then Z)."""
    rx, ry, rz = np.radians(degrees)
    cx, sx, cy, sy, cz, sz = np.cos(rx), np.sin(rx), np.cos(ry), np.sin(ry), np.cos(rz), np.sin(rz)
    return (np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]]) @ np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
            @ np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]]))


def _tree_scene(shader: Path, properties: dict) -> dict:
    return {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
        "lights": TREE_LIGHTS,
        "materials": {"m": {"surface": str(shader), "properties": properties}},
        "objects": [{"mesh": {"primitive": "plane", "size": 1.6}, "material": "m",
                     "transform": {"rotate_deg": list(PLANE_ROTATE_DEG)}}],
        "render": {"quality": "high", "tonemap": "none"},
    }


def _expected_tree_light(n_dot_l_of, object_space: bool = True, slots: int = 3) -> np.ndarray:
    """Sum over the first ``slots`` directional lights of colour x intensity x n_dot_l_of(N.L),
    N the plane's normal in object space (+Y), L towards the light in object space
    (the mapping), or, for the control, the world-space direction taken as it is."""
    normal = np.array([0.0, 1.0, 0.0])
    to_object = _rotation(PLANE_ROTATE_DEG).T
    total = np.zeros(3)
    for light in [l for l in TREE_LIGHTS if l["type"] == "directional"][:slots]:
        towards = -_unit(light["direction"])
        if object_space:
            towards = _unit(to_object @ towards)
        total += np.asarray(light["color"]) * light["intensity"] * n_dot_l_of(float(normal @ towards))
    return total


# Bark: albedo (white) x colour x max(0, N.L) per light, the specular off (_SpecColor 0) and no
# ambient (no environment). Leaves: the wrap-around diffuse max(0, 0.6 N.L + 0.4), translucency
# off (_TranslucencyColor 0), the specular off (gloss, _TranslucencyMap's alpha, 0: Leaves has
# no _SpecColor property).
# The soft-occlusion Rendertex passes (UnityBuiltin2xTreeLibrary.cginc's imposter path) sum all
# four slots: bark's colour x max(0, N.L) (_AO tangent.w + _BaseLight), here _AO 0 and _BaseLight
# 1 (the tangent's sign out of it); leaves' colour x (max(0, tangent . (L _Occlusion, _AO)) +
# _BaseLight), here _Occlusion and _AO 0: the colours alone (no direction: the control is the
# count of slots, three instead of four).
TREE_CASES = {
    "TreeCreator/TreeCreatorBarkRendertex": ({"_SpecColor": [0.0, 0.0, 0.0, 1.0]}, lambda nl: max(0.0, nl), 3),
    "TreeCreator/TreeCreatorLeavesRendertex": (
        {"_TranslucencyColor": [0.0, 0.0, 0.0, 1.0], "_TranslucencyMap": "GLOSS_ZERO"},
        lambda nl: max(0.0, 0.6 * nl + 0.4), 3),
    "SoftOcclusion/TreeSoftOcclusionBarkRendertex": ({"_AO": 0.0, "_BaseLight": 1.0}, lambda nl: max(0.0, nl), 4),
    "SoftOcclusion/TreeSoftOcclusionLeavesRendertex": ({"_AO": 0.0, "_Occlusion": 0.0, "_BaseLight": 1.0},
                                                       lambda nl: 1.0, 4),
}
# Float32 bound, relative to the largest channel: N.L is computed per vertex (a normalize of a
# transformed direction, a 3-term dot: each step within 2^-24 relative, about ten steps), then
# interpolated (the same value at every vertex of the plane: exact up to the interpolation's
# weights summing to 1 within a few ulp) and multiplied and summed over three lights in the
# fragment: about 20 rounded operations, 20 x 6e-8 = 1.2e-6; bound 2e-6 of the largest channel.
TREE_RELATIVE_BOUND = 2e-6


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("name", sorted(TREE_CASES))
def test_tree_imposter_lights_are_the_scenes_directional_lights_in_object_space(tmp_path, name, language):
    """Every covered pixel of the turned plane is the float64 sum over the scene's first
    directional lights the shader reads (three, or the soft-occlusion passes' four; the point
    light never counted); the control, the same sum with world-space directions (no object
    transform), or over three slots where no direction is read, is far off."""
    properties, n_dot_l_of, slots = TREE_CASES[name]
    if properties.get("_TranslucencyMap") == "GLOSS_ZERO":  # white, alpha (gloss) 0
        from pbrlab.foundation.images import write_png
        write_png(tmp_path / "gloss_zero.png", np.array([[[255, 255, 255, 0]]], np.uint8))
        properties = {**properties, "_TranslucencyMap": {"path": str(tmp_path / "gloss_zero.png")}}
    data = _tree_scene(BUILTIN / "Nature" / f"{name}.shader", properties)
    image = _render(data, tmp_path, language)
    covered = _coverage(data, tmp_path)
    assert covered.mean() > 0.2, f"the plane covers {covered.mean():.2f} of the image"
    expected = _expected_tree_light(n_dot_l_of, slots=slots)
    bound = TREE_RELATIVE_BOUND * np.abs(expected).max()
    error = np.abs(image[covered][:, :3] - expected).max(axis=1)
    assert (error > bound).mean() == 0.0, f"{(error > bound).mean():.3f} of pixels over {bound:.3g}; worst {error.max():.3g}"
    if slots == 4 and n_dot_l_of(0.0) == 1.0:  # no direction read: the control is the slots' count
        world = _expected_tree_light(n_dot_l_of, slots=3)
    else:
        world = _expected_tree_light(n_dot_l_of, object_space=False, slots=slots)
    control = np.abs(image[covered][:, :3] - world).max(axis=1)
    assert (control > bound).mean() == 1.0, "world-space directions would pass: the test cannot tell the spaces apart"


def test_a_declaration_of_another_type_is_not_filled():
    """Only Unity's declaration is filled (float3[4] directions): a float4 array keeps the
    refusal, and a declaration inside a function is not a global."""
    program = "float4 _TerrainTreeLightDirections[4];\nfloat3 _TerrainTreeLightColors[4];\nvoid f() { float4x4 _PreviousVP; }\n"
    text, filled = fill_declared(program, program)
    assert filled == () and text == program
    text, filled = fill_declared("uniform float4x4 _PreviousVP;\nhalf3 _TerrainTreeLightDirections[4];\n",
                                 "uniform float4x4 _PreviousVP;\nhalf3 _TerrainTreeLightDirections[4];\n")
    assert filled == ("_PreviousVP", "_TerrainTreeLightDirections")
    assert text == "static float4x4 _PreviousVP;\nstatic half3 _TerrainTreeLightDirections[4];\n"
    assert set(FILLED) == {"_TerrainTreeLightDirections", "_TerrainTreeLightColors", "_NonJitteredVP",
                           "_PreviousVP", "_PreviousM", "unity_WorldToLight", "_LightMatrix0",
                           # URP's additional-light arrays (the stand-in Input.hlsl's: test_urp_s47_urpinputs)
                           "_AdditionalLightsPosition", "_AdditionalLightsColor", "_AdditionalLightsAttenuation",
                           "_AdditionalLightsSpotDir"}


def test_a_stereo_motion_matrix_is_still_refused(tmp_path):
    """One eye here: _StereoPreviousVP (USING_STEREO_MATRICES) is not filled, and says so."""
    shader = tmp_path / "stereo.shader"
    shader.write_text(MOTION_PASS.replace("float4x4 _PreviousVP;", "float4x4 _StereoPreviousVP[2];")
                      .replace("mul(mul(_ClipShift(), _PreviousVP)", "mul(mul(_ClipShift(), _StereoPreviousVP[0])"))
    outcome = corpus.run_shader(shader, "glsl")
    assert outcome.status == "refused" and "uses _StereoPreviousVP, part of motion vectors" in outcome.message


# --- motion vectors ------------------------------------------------------------------------------

# Unity's per-object motion (Internal-MotionVectors' VertMotionVectors / FragMotionVectors, the
# pass Unity draws into its motion-vector buffer) as a pass the harness draws, its previous
# view-projection optionally moved in clip space by _Shift (x, y: NDC units), as a camera panned
# between the frames: clip' = T clip, T adding shift * w to x and y.
MOTION_PASS = textwrap.dedent("""
    Shader "t/motion" {
        Properties { _Shift ("NDC shift of the previous frame", Vector) = (0, 0, 0, 0) }
        SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4x4 _NonJitteredVP;
            float4x4 _PreviousVP;
            float4x4 _PreviousM;
            float4 _Shift;
            struct v2f { float4 pos : SV_POSITION; float4 now : TEXCOORD0; float4 before : TEXCOORD1; };
            float4x4 _ClipShift() {
                return float4x4(1, 0, 0, _Shift.x, 0, 1, 0, _Shift.y, 0, 0, 1, 0, 0, 0, 0, 1);
            }
            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.now = mul(_NonJitteredVP, mul(unity_ObjectToWorld, v.vertex));
                o.before = mul(mul(_ClipShift(), _PreviousVP), mul(_PreviousM, v.vertex));
                return o;
            }
            half4 frag(v2f i) : SV_Target {
                float2 now = (i.now.xy / i.now.w + 1.0) / 2.0;
                float2 before = (i.before.xy / i.before.w + 1.0) / 2.0;
                return half4(now - before, 0, 1);
            }
            ENDCG
        } }
    }
""")
# Float32 bound on a motion component (viewport units): each clip coordinate is interpolated
# by the rasterizer to within a few ulp of its magnitude (|x|, |w| <= 4 here: ulp 4.8e-7),
# divided (one rounding) and mapped to [0, 1] (two): an NDC value within ~1.5e-6, the
# difference of two such halved: 1.5e-6. (A still frame's two values are the same computation
# of the same inputs, so they agree exactly; the bound is what a moved one may show.)
MOTION_BOUND = 1.5e-6


def _motion_scene(shader: Path, shift=(0.0, 0.0)) -> dict:
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_Shift": [shift[0], shift[1], 0.0, 0.0]}
    data.pop("environment")
    data["render"]["tonemap"] = "none"
    return data


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_still_frame_has_zero_motion_and_a_moved_previous_matrix_the_predicted_motion(tmp_path, language):
    """Still camera and sphere: every covered pixel is (0, 0) motion (the encoding of none:
    (0, 0, 0, 1)); the previous view-projection moved by an NDC shift d gives -d / 2 at every
    pixel (vPos - vPosOld with vPos = (ndc + 1) / 2), and fails the zero check (the control)."""
    shader = tmp_path / "motion.shader"
    shader.write_text(MOTION_PASS)
    still = _render(_motion_scene(shader), tmp_path, language)
    covered = still[..., 3] > 0
    assert covered.mean() > 0.3
    assert np.abs(still[covered][:, :3]).max() <= MOTION_BOUND
    shift = (0.125, -0.0625)
    moved = _render(_motion_scene(shader, shift), tmp_path, language)
    predicted = np.array([-shift[0] / 2, -shift[1] / 2, 0.0])
    error = np.abs(moved[covered][:, :3] - predicted).max(axis=1)
    assert (error > MOTION_BOUND).mean() == 0.0, f"worst {error.max():.3g}"
    assert (np.abs(moved[covered][:, :3]).max(axis=1) > MOTION_BOUND).mean() == 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_internal_motion_vectors_draws_zero_camera_motion(language):
    """Unity's own shader as a material: its per-object pass (LightMode MotionVectors) is not a
    colour pass and is skipped; its camera-motion passes draw on the sphere and, the camera
    still, write (0, 0, 0, 1) at every covered pixel: exactly, the same matrix times the same
    point on both sides."""
    outcome = corpus.run_shader(BUILTIN / "Internal-MotionVectors.shader", language)
    assert outcome.status == "rendered", outcome.message
    covered = outcome.image[..., 3] > 0
    assert covered.mean() > 0.3
    assert np.all(outcome.image[covered][:, :3] == 0.0)


# --- Particles/Standard Unlit ---------------------------------------------------------------------

PARTICLES_UNLIT = BUILTIN / "Particle Standard Unlit.shader"
# _Color (the albedo: _MainTex is white), channels below and above Overlay's 0.5 knee.
PARTICLE_COLOR = np.array([0.3, 0.7, 0.45])


def _hsv_colour_mode(albedo, particle):
    """Color mode: the particle colour's hue and saturation, the albedo's value (HSV)."""
    h, s, _ = colorsys.rgb_to_hsv(*particle)
    return np.array(colorsys.hsv_to_rgb(h, s, max(albedo)))


# keywords, extra properties, the float64 colour from albedo a and particle colour c (white
# here: pbrlab's meshes carry no vertex colours), as the Unity Manual's Color Mode describes.
PARTICLE_MODES = {
    "multiply": ((), {}, lambda a, c: a * c),
    "overlay": (("_COLOROVERLAY_ON",), {}, lambda a, c: np.where(a <= 0.5, 2 * a * c, 1 - 2 * (1 - a) * (1 - c))),
    "color": (("_COLORCOLOR_ON",), {}, _hsv_colour_mode),
    "additive": (("_COLORADDSUBDIFF_ON",), {"_ColorAddSubDiff": [1.0, 0.0, 0.0, 0.0]}, lambda a, c: a + c),
    "difference": (("_COLORADDSUBDIFF_ON",), {"_ColorAddSubDiff": [-1.0, 1.0, 0.0, 0.0]}, lambda a, c: np.abs(a - c)),
    "emission": (("_EMISSION",), {"_EmissionColor": [0.25, 0.0, 0.5, 1.0]},
                 lambda a, c: a * c + np.array([0.25, 0.0, 0.5])),
}
# Float32: a product and a sum or two of values <= 2, each rounded to 2^-24 relative; the
# HSV round trip is ~15 operations on values <= 1 (and 1e-10 in its divisions): 15 x 6e-8 ~ 1e-6.
PARTICLE_BOUND = 1e-6


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("mode", sorted(PARTICLE_MODES))
def test_standard_particles_unlit_colour_modes(tmp_path, mode, language):
    """Each covered pixel is the mode's float64 colour of _Color and the white particle colour;
    the control: multiply's colour is far from every other mode's render."""
    keywords, extra, colour = PARTICLE_MODES[mode]
    data = corpus.scene_for(PARTICLES_UNLIT)
    data.pop("environment")
    data["render"]["tonemap"] = "none"
    data["materials"]["m"]["properties"] = {"_Color": [*PARTICLE_COLOR, 1.0], **extra}
    data["materials"]["m"]["keywords"] = list(keywords)
    image = _render(data, tmp_path, language)
    covered = _coverage(data, tmp_path)  # the pass writes no alpha (ColorMask RGB)
    assert covered.mean() > 0.3
    assert np.all(image[~covered][:, :3] == 0.0)  # nothing drawn elsewhere
    white = np.ones(3)
    expected = colour(PARTICLE_COLOR, white)
    error = np.abs(image[covered][:, :3] - expected).max(axis=1)
    assert (error > PARTICLE_BOUND).mean() == 0.0, f"worst {error.max():.3g} from {expected}"
    if mode != "multiply":
        control = np.abs(image[covered][:, :3] - PARTICLE_COLOR * white).max(axis=1)
        assert (control > PARTICLE_BOUND).mean() == 1.0


def test_soft_particles_are_refused_without_a_depth_texture(tmp_path):
    """SOFTPARTICLES_ON reads _CameraDepthTexture, which pbrlab does not supply: a material that
    enables it is refused by name, never drawn as if it were off."""
    from pbrlab.foundation.errors import PbrlabError
    data = corpus.scene_for(PARTICLES_UNLIT)
    data["materials"]["m"]["keywords"] = ["SOFTPARTICLES_ON"]
    with pytest.raises(PbrlabError, match="_CameraDepthTexture"):
        parse_scene(data, "test scene", tmp_path)


# Every feature keyword of the particle shaders compiles, draws finite pixels and agrees across
# the languages (the structs hold every variant's members: UnityStandardParticles.cginc).
PARTICLE_VARIANTS = {
    "Particle Standard Unlit.shader": [["_REQUIRE_UV2"], ["_FADING_ON"], ["EFFECT_BUMP"], ["_NORMALMAP"],
                                       ["_ALPHATEST_ON"], ["_ALPHABLEND_ON"], ["_ALPHAPREMULTIPLY_ON"],
                                       ["_ALPHAMODULATE_ON"],
                                       ["_COLORCOLOR_ON", "_REQUIRE_UV2", "_FADING_ON", "EFFECT_BUMP", "_EMISSION"]],
    "Particle Standard Surface.shader": [["_REQUIRE_UV2"], ["_FADING_ON"], ["EFFECT_BUMP"], ["_NORMALMAP"],
                                         ["_METALLICGLOSSMAP"], ["_ALPHABLEND_ON"]],
}


@pytest.mark.parametrize("shader,keywords", [(s, k) for s, ks in sorted(PARTICLE_VARIANTS.items()) for k in ks],
                         ids=lambda x: "+".join(x) if isinstance(x, list) else x.split(".")[0].replace(" ", "_"))
def test_standard_particles_variants_render_in_both_languages(tmp_path, shader, keywords):
    data = corpus.scene_for(BUILTIN / shader)
    data["materials"]["m"]["keywords"] = keywords
    images = [_render(data, tmp_path, language) for language in LANGUAGES]
    assert all(np.isfinite(image).all() for image in images)
    assert corpus.agreement(*images) <= 1e-4  # test_corpus.py AGREEMENT_BOUND


def test_a_motion_matrix_declared_otherwise_is_refused_naming_unitys_declaration(tmp_path):
    """A program declaring _PreviousVP otherwise than Unity (float3x3) reads nothing pbrlab
    fills: refused at its use, saying how Unity declares it."""
    shader = tmp_path / "other.shader"
    shader.write_text(MOTION_PASS.replace("float4x4 _PreviousVP;", "float3x3 _PreviousVP;"))
    outcome = corpus.run_shader(shader, "hlsl")
    assert outcome.status == "refused"
    assert "other.shader:" in outcome.message and "uses _PreviousVP, part of motion vectors" in outcome.message
    assert "declares them as Unity does (float4x4, at global scope)" in outcome.message
