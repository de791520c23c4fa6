"""ShaderLab ``Stencil { ... }`` blocks applied (stencil_block.py, gpu/stencil_state.py): the frame
has an 8-bit stencil, cleared to 0 with depth; each pass draws with its block's test and writes,
in both languages and both pipelines (built-in CGPROGRAM, URP HLSLPROGRAM).

Scenes: the corpus camera (48 x 48, 40 degrees, at z 3.2 looking at the origin). The mask is a UV
sphere of radius 0.5 at z 1.2, listed first (pbrlab draws opaque objects in the scene's order); a
unit sphere behind it reads the stencil. Every pass returns a constant of multiples of 1/4 (exact
in half and float32) into the float target with no blending, so a pixel equals the constant or the
black background exactly: the checks are exact, over every pixel, against the pixel sets the
test derives from separate renders (where the mask covers, where the sphere covers).

Unity's manual, "Stencil command in ShaderLab reference": the test is (Ref & ReadMask) Comp
(stencil & ReadMask); Pass/Fail/ZFail say what is written through WriteMask; a SubShader's block
applies to its passes.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.gpu.stencil_state import StencilFace, StencilState
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import parse, shaderlab
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
COLOUR = (0.25, 0.5, 0.75)
SHELL = (1.0, 0.5, 0.0)

BUILTIN_PASS = """
        Pass {
            %(state)s
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float _Grow;
            float4 vert(float4 p : POSITION, float3 n : NORMAL) : SV_POSITION
            { return UnityObjectToClipPos(float4(p.xyz + n * %(grow)s, 1.0)); }
            fixed4 frag() : SV_Target { return fixed4(%(colour)s, 1); }
            ENDCG
        }"""
URP_PASS = """
        Pass {
            Tags { "LightMode" = "%(light_mode)s" }
            %(state)s
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            float _Grow;
            struct Attributes { float4 positionOS : POSITION; float3 normalOS : NORMAL; };
            float4 vert(Attributes v) : SV_POSITION
            { return TransformObjectToHClip(v.positionOS.xyz + v.normalOS * %(grow)s); }
            half4 frag() : SV_Target { return half4(%(colour)s, 1); }
            ENDHLSL
        }"""
PIPELINES = {"builtin": BUILTIN_PASS, "urp": URP_PASS}
URP_LIGHT_MODES = ("UniversalForward", "SRPDefaultUnlit")


def shader(pipeline: str, passes: list, sub_state: str = "", properties: str = "") -> str:
    """A .shader of ``passes`` [(state lines, colour[, grows])], ``sub_state`` at the SubShader's
    level; a pass that grows (the default) moves vertices along the normal by ``_Grow`` (0: the
    mesh as it is; an outline's shell), one with grows False keeps them."""
    tags = 'Tags { "RenderPipeline" = "UniversalPipeline" }' if pipeline == "urp" else ""
    # URP draws an object's first pass of each LightMode: a second pass is SRPDefaultUnlit
    body = "".join(PIPELINES[pipeline] % {"state": p[0], "colour": ", ".join(map(str, p[1])),
                                          "grow": "_Grow" if len(p) < 3 or p[2] else "0.0",
                                          "light_mode": URP_LIGHT_MODES[index]}
                   for index, p in enumerate(passes))
    return textwrap.dedent(f"""\
        Shader "pbrlab tests/stencil" {{
            Properties {{ _Grow ("Grow", Float) = 0 {properties} }}
            SubShader {{
                {tags}
                {sub_state}
                {body}
            }}
        }}
        """)


MASK = "ColorMask 0\nZWrite Off\nStencil { Ref 1 Comp Always Pass Replace }"
READ_EQUAL = "Stencil { Ref 1 Comp Equal }"


def render(tmp_path, language: str, objects: list) -> np.ndarray:
    """``objects`` [(shader text, radius, z, grow)], drawn in order; the linear image."""
    materials, listed = {}, []
    for index, (text, radius, z, grow) in enumerate(objects):
        path = tmp_path / f"o{index}.shader"
        path.write_text(text)
        materials[f"m{index}"] = {"surface": str(path), "properties": {"_Grow": grow}}
        listed.append({"mesh": {"primitive": "uv_sphere", "radius": radius}, "material": f"m{index}",
                       "transform": {"translate": [0.0, 0.0, z]}})
    data = {"camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
            "lights": [], "materials": materials, "objects": listed}
    scene = parse_scene(data, origin="stencil test scene", base=tmp_path)
    return render_scene(scene, language=language).linear.astype(np.float64)


def covered(image: np.ndarray) -> np.ndarray:
    return image[..., 3] > 0


def shows(image: np.ndarray, mask: np.ndarray, colour) -> bool:
    """Every pixel of ``mask`` is exactly ``colour`` and every other pixel exactly black."""
    expected = np.zeros(image.shape[:2] + (3,))
    expected[mask] = colour
    return bool(np.array_equal(image[..., :3], expected))


@pytest.mark.parametrize("pipeline", sorted(PIPELINES))
@pytest.mark.parametrize("language", LANGUAGES)
def test_a_mask_pass_limits_an_equal_reader_to_its_pixels(tmp_path, language, pipeline):
    """The mask writes Ref 1 where it covers (ColorMask 0: no colour, ZWrite Off: no depth); the
    sphere behind reads Comp Equal 1: it shows COLOUR exactly where both cover, black elsewhere.
    Control: without its Stencil block the reader covers every pixel of the sphere (more pixels,
    the ones outside the mask among them)."""
    reader = shader(pipeline, [(READ_EQUAL, COLOUR)])
    image = render(tmp_path, language, [(shader(pipeline, [(MASK, COLOUR)]), 0.5, 1.2, 0.0), (reader, 1.0, 0.0, 0.0)])
    mask_alone = render(tmp_path, language, [(shader(pipeline, [("", COLOUR)]), 0.5, 1.2, 0.0)])
    sphere_alone = render(tmp_path, language, [(shader(pipeline, [("", COLOUR)]), 1.0, 0.0, 0.0)])
    inside = covered(mask_alone) & covered(sphere_alone)
    assert inside.sum() > 400 and (covered(sphere_alone) & ~inside).sum() > 100  # both sets are there
    assert shows(image, inside, COLOUR)
    unmasked = render(tmp_path, language, [(shader(pipeline, [(MASK, COLOUR)]), 0.5, 1.2, 0.0),
                                          (shader(pipeline, [("", COLOUR)]), 1.0, 0.0, 0.0)])
    assert not shows(unmasked, inside, COLOUR) and shows(unmasked, covered(sphere_alone), COLOUR)


@pytest.mark.parametrize("pipeline", sorted(PIPELINES))
@pytest.mark.parametrize("language", LANGUAGES)
def test_an_outline_shell_with_comp_notequal_draws_only_outside_its_object(tmp_path, language, pipeline):
    """Pass 1 draws the sphere (COLOUR) and writes Ref 1; pass 2 draws it grown along its normals
    (SHELL) where the stencil is NotEqual 1: the sphere's own pixels keep COLOUR, the ring
    around it is SHELL. Control: the shell without its Stencil block hides the sphere (its
    front faces are nearer): every covered pixel SHELL."""
    grow = 0.15
    body = ("Stencil { Ref 1 Comp Always Pass Replace }", COLOUR, False)
    outlined = shader(pipeline, [body, ("Stencil { Ref 1 Comp NotEqual }", SHELL)])
    image = render(tmp_path, language, [(outlined, 1.0, 0.0, grow)])
    sphere = covered(render(tmp_path, language, [(shader(pipeline, [("", COLOUR)]), 1.0, 0.0, 0.0)]))
    shell = covered(render(tmp_path, language, [(shader(pipeline, [("", SHELL)]), 1.0, 0.0, grow)]))
    ring = shell & ~sphere
    assert ring.sum() > 50 and sphere.sum() > 400
    expected = np.zeros(image.shape[:2] + (3,))
    expected[sphere], expected[ring] = COLOUR, SHELL
    assert np.array_equal(image[..., :3], expected)
    control = render(tmp_path, language, [(shader(pipeline, [body, ("", SHELL)]), 1.0, 0.0, grow)])
    assert shows(control, shell, SHELL)


@pytest.mark.parametrize("pipeline", sorted(PIPELINES))
def test_a_stencil_ref_property_is_read_from_the_material(tmp_path, pipeline):
    """The mask writes ``Ref [_StencilRef]`` (the property's default, 1; control: 2): the
    Equal 1 reader shows COLOUR over the mask with 1, nothing with 2 (the control)."""
    prop = '_StencilRef ("Stencil Ref", Int) = 1'
    mask = shader(pipeline, [("ColorMask 0\nZWrite Off\nStencil { Ref [_StencilRef] Comp Always Pass Replace }",
                              COLOUR)], properties=prop)
    reader = shader(pipeline, [(READ_EQUAL, COLOUR)])
    image = render(tmp_path, "glsl", [(mask, 0.5, 1.2, 0.0), (reader, 1.0, 0.0, 0.0)])
    assert covered(image).sum() > 400 and image[24, 24, :3].tolist() == list(COLOUR)
    two = render(tmp_path, "glsl", [(mask.replace("= 1", "= 2"), 0.5, 1.2, 0.0), (reader, 1.0, 0.0, 0.0)])
    assert covered(two).sum() == 0


def _stencil(tmp_path, block: str, properties: str = "", sub_state: str = "") -> StencilState | None:
    path = tmp_path / "s.shader"
    path.write_text(shader("builtin", [(block, COLOUR)], sub_state=sub_state, properties=properties))
    return parse.read_shader(path).passes[0].state.stencil


def test_the_block_reads_every_parameter_per_unity_manual(tmp_path):
    """Defaults (Ref 0, masks 255, Always, Keep); Comp/Pass/Fail/ZFail for both facings, the
    Front/Back words over them whatever the order; names case-insensitive; numbers and the enums'
    own names (LessEqual, IncrementSaturate)."""
    assert _stencil(tmp_path, "Stencil { }") == StencilState()
    block = """Stencil {
        CompBack Less PassBack IncrSat
        Ref 3 ReadMask 7 WriteMask 6
        comp lequal pass REPLACE fail Zero ZFail DecrWrap
        FailFront Invert ZFailBack IncrementWrap CompFront GreaterEqual
    }"""
    assert _stencil(tmp_path, block) == StencilState(
        3, 7, 6, front=StencilFace("gequal", "replace", "invert", "decr_wrap"),
        back=StencilFace("less", "incr", "zero", "incr_wrap"))
    assert _stencil(tmp_path, "Stencil { Comp LessEqual Pass IncrementSaturate }").front == StencilFace("lequal", "incr")


def test_property_values_take_unity_enum_numbers(tmp_path):
    """[_Comp] = 3 is CompareFunction.Equal, [_Op] = 2 StencilOp.Replace, 6 IncrementWrap;
    Comp 0 (Disabled) on both facings turns the test off; a facing of its own keeps it on."""
    props = '_Comp ("c", Float) = 3 _Op ("o", Float) = 2 _Wrap ("w", Int) = 6 _Ref ("r", Range(0, 255)) = 5'
    state = _stencil(tmp_path, "Stencil { Ref [_Ref] Comp [_Comp] Pass [_Op] ZFail [_Wrap] }", props)
    assert state == StencilState(5, front=StencilFace("equal", "replace", depth_fail_op="incr_wrap"),
                                 back=StencilFace("equal", "replace", depth_fail_op="incr_wrap"))
    assert _stencil(tmp_path, "Stencil { Comp [_Comp] Pass [_Op] }", props.replace("= 3", "= 0")) is None
    one_sided = _stencil(tmp_path, "Stencil { Comp [_Comp] CompFront Equal Pass Replace }", props.replace("= 3", "= 0"))
    assert one_sided.front == StencilFace("equal", "replace") and one_sided.back == StencilFace()


def test_a_subshader_block_applies_to_its_passes_and_a_pass_block_replaces_it(tmp_path):
    sub = "Stencil { Ref 2 Comp Equal }"
    assert _stencil(tmp_path, "", sub_state=sub) == StencilState(2, front=StencilFace("equal"),
                                                                  back=StencilFace("equal"))
    assert _stencil(tmp_path, "Stencil { Ref 4 }", sub_state=sub) == StencilState(4)
    assert _stencil(tmp_path, "") is None  # no block: the test off (control)


@pytest.mark.parametrize("block, line, message", [
    ("Stencil {\n Ref 1\n Comp Sometimes\n}", 3, "Stencil Comp Sometimes: expected one of"),
    ("Stencil {\n Ref 256 }", 2, "holds 8 bits"),
    ("Stencil {\n Reference 1 }", 2, "'Reference' is not a Stencil parameter"),
    ("Stencil {\n Ref 1\n Pass }", 3, "no value"),
    ("Stencil {\n Comp [_Tex] }", 2, "names no Float/Int/Range property"),
    ("Stencil {\n Pass [_Big] }", 2, "outside the enum's 0..7"),
])
def test_a_malformed_block_is_refused_naming_file_and_line(tmp_path, block, line, message):
    props = '_Tex ("t", 2D) = "white" {} _Big ("b", Float) = 9'
    path = tmp_path / "s.shader"
    text = shader("builtin", [(block, COLOUR)], properties=props)
    path.write_text(text)
    first = text.splitlines().index(next(t for t in text.splitlines() if t.strip().startswith("Stencil"))) + 1
    with pytest.raises(PbrlabError, match=f"s.shader:{first + line - 1}: .*{message}"):
        parse.read_shader(path)
    path.write_text(shader("builtin", [("Stencil { Ref 1 }", COLOUR)], properties=props))  # control: well formed
    assert parse.read_shader(path).passes[0].state.stencil == StencilState(1)


def test_a_stencil_block_keeps_its_line():
    """The block's '{' line travels with its text (shaderlab.StateCommand.body_line)."""
    text = 'Shader "x" {\n SubShader {\n  Stencil\n  {\n Ref 1 }\n  Pass { }\n }\n}\n'
    layout = shaderlab.read_layout(text, __import__("pathlib").Path("x.shader"))
    command = layout.subshaders[0].state[0]
    assert (command.word, command.line, command.body_line) == ("Stencil", 3, 4)


@pytest.mark.parametrize("pipeline", sorted(PIPELINES))
def test_a_reader_alone_draws_nothing_and_the_corpus_lists_why(tmp_path, pipeline):
    """A shader whose only pass tests Equal 2 draws nothing on its own (the frame's stencil is 0),
    as in Unity: rendered black in both languages, noted, and the corpus lists it by that note
    instead of "drew nothing". Control: Ref 0 passes on the cleared buffer: the sphere shows
    COLOUR and there is no note."""
    from pbrlab.checking import unity_corpus as corpus
    path = tmp_path / "reader.shader"
    path.write_text(shader(pipeline, [("Stencil { Ref 2 Comp Equal ZFail DecrWrap }", COLOUR)]))
    outcomes = {lang: corpus.run_shader(path, lang) for lang in corpus.LANGUAGES}
    assert all(o.status == "rendered" and not np.asarray(o.image)[..., :3].any() for o in outcomes.values())
    assert corpus.no_colour_reason(outcomes).startswith("SubShader draws nothing alone by its Stencil test")
    assert corpus.outcome_problems("rendered", outcomes) == []
    path.write_text(shader(pipeline, [("Stencil { Ref 0 Comp Equal }", COLOUR)]))
    control = {lang: corpus.run_shader(path, lang) for lang in corpus.LANGUAGES}
    assert corpus.no_colour_reason(control) is None
    assert all(np.asarray(o.image)[..., :3].max() == 0.75 for o in control.values())


def test_a_pass_that_writes_first_or_fails_into_a_write_is_not_called_empty():
    """draws_nothing_alone's rule: a pass before the reader that writes the stencil, or a failing
    test whose Fail operation writes, may make it draw: no claim then."""
    from pbrlab.importers.unity import model as M
    from pbrlab.importers.unity.stencil_block import draws_nothing_alone
    reads = M.RenderState(stencil=StencilState(2, front=StencilFace("equal"), back=StencilFace("equal")))
    writes = M.RenderState(color_mask="0", stencil=StencilState(2, front=StencilFace(pass_op="replace"),
                                                                back=StencilFace(pass_op="replace")))
    fails_into_write = M.RenderState(color_mask="0", stencil=StencilState(
        2, front=StencilFace("never", fail_op="replace"), back=StencilFace("never", fail_op="replace")))
    assert draws_nothing_alone([reads])
    assert not draws_nothing_alone([writes, reads])
    assert not draws_nothing_alone([fails_into_write, reads])
    assert not draws_nothing_alone([M.RenderState(), reads])  # a pass without a block draws colour


SURFACE = """
Shader "pbrlab tests/stencil surface" {
    SubShader {
        %s
        CGPROGRAM
        #pragma surface surf Lambert
        struct Input { float3 worldPos; };
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = float3(0.5, 0.5, 0.5); }
        ENDCG
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_surface_program_on_a_traced_sphere_takes_its_subshaders_front_facing_state(tmp_path, language):
    """A surface program's SubShader block applies to it; on a ray-traced sphere (drawn through
    its bounding box's back faces) the front facing's state is the one tested: CompFront Equal 1
    over the mask covers exactly the mask's pixels of the sphere. Control: with the back facing's
    Never on the drawn triangles, as GL alone would test them, nothing would show; CompBack
    Equal / CompFront Never shows nothing here."""
    def scene(stencil: str, with_mask: bool = True) -> np.ndarray:
        (tmp_path / "surface.shader").write_text(SURFACE % stencil)
        (tmp_path / "mask.shader").write_text(shader("builtin", [(MASK, COLOUR)]))
        objects = [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "surface"}]
        if with_mask:
            objects.insert(0, {"mesh": {"primitive": "uv_sphere", "radius": 0.5}, "material": "mask",
                               "transform": {"translate": [0.0, 0.0, 1.2]}})
        data = {"camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40,
                           "size": [48, 48]},
                "lights": [{"type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1], "intensity": 1}],
                "materials": {"surface": {"surface": str(tmp_path / "surface.shader")},
                              "mask": {"surface": str(tmp_path / "mask.shader")}},
                "objects": objects}
        return render_scene(parse_scene(data, origin="stencil surface scene", base=tmp_path),
                            language=language).linear.astype(np.float64)
    image = scene("Stencil { Ref 1 CompFront Equal CompBack Never }")
    mask = covered(render(tmp_path, language, [(shader("builtin", [("", COLOUR)]), 0.5, 1.2, 0.0)]))
    sphere = covered(scene("", with_mask=False))
    assert (mask & sphere).sum() > 400 and np.array_equal(covered(image), mask & sphere)
    assert image[covered(image)][:, :3].min() > 0  # lit, not black
    assert covered(scene("Stencil { Ref 1 CompFront Never CompBack Equal }")).sum() == 0
