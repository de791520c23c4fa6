"""Fixed-function ShaderLab passes (importers/unity/fixed_function.py): the program pbrlab
generates for ``Lighting On`` / ``Material`` / ``SetTexture`` / ``AlphaTest`` computes what
Unity's manual says, in both languages.

The lit colour is checked on the front face of a box seen head-on (the camera looks down -z at
the +z face; the box's other faces face away): the face is flat, so N.L, and with it the
per-vertex colour, is the same at its four vertices and the interpolated colour equals the
per-vertex value at every pixel of the face (no interpolation error to account for).
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.foundation.images import write_png
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ["glsl", "hlsl"]
LIGHT_DIRECTION = np.array([-0.4, -0.6, -0.7])  # the way the light travels (world space)
LIGHT_COLOUR = np.array([0.9, 0.8, 0.7])
# float32 evaluation of the lit colour: about 30 roundings (transforms, normalisations, the
# dot product, three multiply-adds) of values at most 2, each within 2^-24 relative, so at most
# 30 * 2 * 6e-8 = 3.6e-6 apart from the float64 value.
LIT_BOUND = 3.6e-6
# Interpolated from the vertices: LIT_BOUND at each vertex, plus the rasteriser's interpolation
# of the colour and of the position the expectation is read at, each a few float32 ulps of
# values at most 1.5 (2 x 2 x 1.5 x 6e-8 = 3.6e-7): 4e-6 (measured: 3.5e-7 in both languages).
VERTEX_BOUND = 4e-6

SHADER = """
Shader "t/{name}" {{
    Properties {{
        _MainTex ("Texture", 2D) = "white" {{}}
        _Diffuse ("Diffuse", Color) = (0.6, 0.5, 0.4, 0.8)
        _Cutoff ("Cutoff", Range(0, 1)) = 0.5
    }}
    SubShader {{
        Pass {{
            Tags {{ "LightMode" = "Vertex" }}
            {body}
        }}
    }}
}}
"""


def _render(tmp_path, language, name, body, texture=None, lights=True):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(SHADER.format(name=name, body=body)))
    material = {"surface": str(shader)}
    if texture is not None:
        material["properties"] = {"_MainTex": {"path": str(texture)}}
    scene = {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
        "lights": [{"type": "directional", "direction": LIGHT_DIRECTION.tolist(), "color": LIGHT_COLOUR.tolist(),
                    "intensity": 1.0}] if lights else [],
        "materials": {"m": material},
        "objects": [{"mesh": {"primitive": "box", "size": 1.0}, "material": "m"}],
    }
    return render_scene(parse_scene(scene, "t", tmp_path), language=language).linear


def _face(image):
    """The pixels of the box's front face, one pixel in from its edges (no edge coverage)."""
    covered = image[..., 3] > 0
    rows, cols = np.nonzero(covered)
    inner = np.zeros_like(covered)
    inner[rows.min() + 1:rows.max(), cols.min() + 1:cols.max()] = True
    assert covered.mean() > 0.1 and inner.sum() > 50
    return image[inner & covered]


def lit_colour(diffuse, ambient_term, emission, normal, light_direction, light_colour):
    """Unity's legacy vertex lighting of one directional light (the manual's "ShaderLab: legacy
    lighting"): saturate(Emission + Ambient * ambient light + Diffuse * light * max(0, N.L)),
    alpha the Diffuse alpha; float64."""
    to_light = -np.asarray(light_direction, float) / np.linalg.norm(light_direction)
    n_dot_l = max(0.0, float(np.dot(normal, to_light)))
    rgb = np.asarray(emission[:3]) + ambient_term + np.asarray(diffuse[:3]) * np.asarray(light_colour) * n_dot_l
    return np.clip(np.append(rgb, diffuse[3]), 0.0, 1.0)


LIT = """
            Material {{ Diffuse [_Diffuse] Ambient (0.3, 0.3, 0.3, 1) Emission (0.05, 0.1, 0.0, 0) }}
            Lighting {lighting}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_lighting_on_is_unitys_per_vertex_lighting(tmp_path, language):
    """Lighting On under a directional light, no ambient light (no environment): every pixel of
    the face is the float64 lit colour within LIT_BOUND; the control (the light's colour not
    applied) is far off."""
    image = _render(tmp_path, language, "lit", LIT.format(lighting="On"))
    face = _face(image)
    expected = lit_colour((0.6, 0.5, 0.4, 0.8), 0.0, (0.05, 0.1, 0.0, 0.0), (0.0, 0.0, 1.0), LIGHT_DIRECTION,
                          LIGHT_COLOUR)
    error = np.abs(face[:, :3] - expected[:3]).max(axis=1)
    assert (error > LIT_BOUND).mean() == 0.0, (error.max(), face[0], expected)
    control = lit_colour((0.6, 0.5, 0.4, 0.8), 0.0, (0.05, 0.1, 0.0, 0.0), (0.0, 0.0, 1.0), LIGHT_DIRECTION,
                         (1.0, 1.0, 1.0))
    assert (np.abs(face[:, :3] - control[:3]).max(axis=1) > 100 * LIT_BOUND).mean() == 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_lighting_off_is_white_and_lights_do_not_reach_other_passes(tmp_path, language):
    """Lighting Off: the primary colour is white (no BindChannels Color), whatever the lights."""
    face = _face(_render(tmp_path, language, "unlit", LIT.format(lighting="Off")))
    np.testing.assert_array_equal(face[:, :3], 1.0)


@pytest.fixture
def grey(tmp_path):
    path = tmp_path / "grey.png"
    write_png(path, np.full((4, 4, 4), 90, np.uint8))
    return path


@pytest.mark.parametrize("language", LANGUAGES)
def test_texture_times_primary_double(tmp_path, grey, language):
    """``combine texture * primary DOUBLE`` is twice ``combine texture`` (primary white: Lighting
    Off) at every pixel: the same texel in both renders, so equal to float32 rounding of one
    doubling (exact); the control without DOUBLE is half of it."""
    plain = _face(_render(tmp_path, language, "plain", "SetTexture [_MainTex] { combine texture }", grey))
    double = _face(_render(tmp_path, language, "double", "SetTexture [_MainTex] { combine texture * primary DOUBLE }",
                           grey))
    single = _face(_render(tmp_path, language, "single", "SetTexture [_MainTex] { combine texture * primary }", grey))
    assert 0.05 < plain[:, :3].min() and plain[:, :3].max() < 0.5  # DOUBLE stays below the clamp at 1
    np.testing.assert_array_equal(double[:, :3], 2.0 * plain[:, :3])
    assert (single[:, :3] != 2.0 * plain[:, :3]).all()


@pytest.mark.parametrize("language", LANGUAGES)
def test_alpha_test_discards_what_fails(tmp_path, language):
    """Alpha 0.3 (constantColor's, after the comma): AlphaTest Greater [_Cutoff] (0.5) draws
    nothing, AlphaTest Less [_Cutoff] draws the face (the control)."""
    stage = "SetTexture [_MainTex] { constantColor (1, 1, 1, 0.3) combine texture, constant }"
    kept = _render(tmp_path, language, "kept", stage + "\n AlphaTest Less [_Cutoff]")
    dropped = _render(tmp_path, language, "dropped", stage + "\n AlphaTest Greater [_Cutoff]")
    assert (kept[..., 3] > 0).mean() > 0.1
    assert not (dropped[..., :3] != 0).any() and not (dropped[..., 3] > 0).any()


POSITION_SHADER = """
Shader "t/position" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct v2f { float4 pos : SV_POSITION; float3 p : TEXCOORD0; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.p = v.vertex.xyz + 1.0; return o; }
        float4 frag(v2f i) : SV_Target { return float4(i.p, 1.0); }
        ENDCG
    } }
}
"""
POINT_POSITION = np.array([0.8, 0.6, 1.5])
POINT_COLOUR = np.array([1.0, 0.9, 0.8])
POINT_INTENSITY = 1.5
POINT_RANGE = 10.0
CAMERA = np.array([0.0, 0.0, 3.2])
SPECULAR_LIT = """
            Material { Diffuse [_Diffuse] Ambient (0, 0, 0, 1) Specular (0.5, 0.4, 0.3, 1) Shininess 0.2 }
            Lighting On
            SeparateSpecular On
"""


def _render_two_lights(tmp_path, language, name, text):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(text))
    scene = {
        "camera": {"position": CAMERA.tolist(), "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
        "lights": [{"type": "directional", "direction": LIGHT_DIRECTION.tolist(), "color": LIGHT_COLOUR.tolist(),
                    "intensity": 1.0},
                   {"type": "point", "position": POINT_POSITION.tolist(), "color": POINT_COLOUR.tolist(),
                    "intensity": POINT_INTENSITY, "range": POINT_RANGE}],
        "materials": {"m": {"surface": str(shader)}},
        "objects": [{"mesh": {"primitive": "box", "size": 1.0}, "material": "m"}],
    }
    return render_scene(parse_scene(scene, "t", tmp_path), language=language).linear


def vertex_colours(p, normal, diffuse, specular, shininess, lights):
    """(primary, specular) of Unity's legacy vertex lighting at one vertex, float64: per light
    (to-light direction, colour reaching the vertex) diffuse * colour * max(0, N.L), and where
    N.L > 0 specular * colour * max(0, N.H)^(shininess * 128), H the half vector of L and the
    direction to the eye (the manual's "ShaderLab: legacy lighting"); each sum clamped to [0, 1]."""
    to_eye = (CAMERA - p) / np.linalg.norm(CAMERA - p)
    lit, spec = np.zeros(3), np.zeros(3)
    for to_light, colour in lights(p):
        n_dot_l = max(0.0, float(np.dot(normal, to_light)))
        lit += np.asarray(diffuse) * colour * n_dot_l
        if n_dot_l > 0:
            h = (to_light + to_eye) / np.linalg.norm(to_light + to_eye)
            spec += np.asarray(specular) * colour * max(0.0, float(np.dot(normal, h))) ** (shininess * 128.0)
    return np.clip(lit, 0, 1), np.clip(spec, 0, 1)


def _scene_lights(p):
    from pbrlab.maths.reference.lighting import distance_attenuation
    d = POINT_POSITION - p
    directional = -LIGHT_DIRECTION / np.linalg.norm(LIGHT_DIRECTION)
    # the harness's point light reaching the vertex: its own falloff (pbr/lighting/attenuation)
    point = POINT_COLOUR * POINT_INTENSITY * distance_attenuation(float(np.dot(d, d)), POINT_RANGE)
    return [(directional, LIGHT_COLOUR), (d / np.linalg.norm(d), point)]


@pytest.mark.parametrize("language", LANGUAGES)
def test_vertex_lighting_with_specular_is_interpolated_from_unitys_vertex_values(tmp_path, language):
    """A directional and a point light, SeparateSpecular On: each face pixel is the float64
    per-vertex colours of the face's triangle interpolated at that pixel's surface point (read
    from a second render that writes the object-space position), primary and specular each
    clamped per vertex, added and clamped per pixel; the control (the per-pixel colour at the
    surface point, no vertex interpolation) is off at most pixels."""
    from pbrlab.scene import primitives
    image = _render_two_lights(tmp_path, language, "lit2", SHADER.format(name="lit2", body=SPECULAR_LIT))
    where = _render_two_lights(tmp_path, language, "position", POSITION_SHADER)
    covered = (image[..., 3] > 0) & (where[..., 3] > 0)
    points = where[covered][:, :3].astype(np.float64) - 1.0
    inside = np.abs(points[:, :2]).max(axis=1) < 0.48      # off the face's edges
    points, colours = points[inside], image[covered][inside][:, :3]
    assert len(points) > 200 and np.allclose(points[:, 2], 0.5, atol=1e-6)
    box = primitives.box(1.0)
    front = [f for f in box.faces if np.allclose(box.positions[f][:, 2], 0.5)]
    assert len(front) == 2
    normal = np.array([0.0, 0.0, 1.0])
    expected, control = [], []
    for p in points:
        for f in front:
            a, b, c = box.positions[f][:, :2]
            m = np.array([b - a, c - a]).T
            u, v = np.linalg.solve(m, p[:2] - a)
            weights = np.array([1 - u - v, u, v])
            if weights.min() >= -1e-9:
                break
        per_vertex = [vertex_colours(box.positions[i], normal, (0.6, 0.5, 0.4), (0.5, 0.4, 0.3), 0.2, _scene_lights)
                      for i in f]
        primary = sum(w * pv[0] for w, pv in zip(weights, per_vertex))
        specular = sum(w * pv[1] for w, pv in zip(weights, per_vertex))
        expected.append(np.clip(primary + specular, 0, 1))
        here = vertex_colours(p, normal, (0.6, 0.5, 0.4), (0.5, 0.4, 0.3), 0.2, _scene_lights)
        control.append(np.clip(here[0] + here[1], 0, 1))
    error = np.abs(colours - np.array(expected)).max(axis=1)
    assert (error > VERTEX_BOUND).mean() == 0.0, error.max()
    assert (np.abs(colours - np.array(control)).max(axis=1) > 10 * VERTEX_BOUND).mean() > 0.5


def _read(tmp_path, text):
    from pbrlab.importers.unity import parse
    path = tmp_path / "s.shader"
    path.write_text(textwrap.dedent(text))
    return parse.read_shader(path)


VERTEX_AND_LIGHTMAP = """
Shader "t/vl" {
    SubShader {
        Pass { Tags { "LightMode" = "Vertex" } Lighting On SetTexture [_MainTex] { combine texture * primary } }
        Pass { Tags { "LIGHTMODE" = "VertexLM" } SetTexture [_MainTex] { combine texture } }
        %s
    }
}
"""


def test_vertex_pass_draws_and_lightmap_pass_is_skipped(tmp_path):
    """No object here has a lightmap: the Vertex pass draws (a generated program), the VertexLM
    pass (its tag spelt LIGHTMODE, as in Unity's own shaders) is skipped with a note."""
    shader = _read(tmp_path, VERTEX_AND_LIGHTMAP % "")
    assert [p.light_mode for p in shader.passes] == ["Vertex"]
    assert "pbrlab_ff_vert" in shader.passes[0].program
    assert any("LightMode VertexLM" in n and "lightmapped objects only" in n for n in shader.notes)


def test_vertex_pass_is_skipped_beside_a_forward_base_pass(tmp_path):
    """Unity's forward path draws a SubShader's ForwardBase pass, not its Vertex pass (control:
    without the ForwardBase pass the Vertex pass draws, above)."""
    forward = """Pass { Tags { "LightMode" = "ForwardBase" }
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
        fixed4 frag() : SV_Target { return 1; }
        ENDCG }"""
    shader = _read(tmp_path, VERTEX_AND_LIGHTMAP % forward)
    assert [p.light_mode for p in shader.passes] == ["ForwardBase"]
    assert any("LightMode Vertex) skipped" in n and "ForwardBase" in n for n in shader.notes)


def test_category_commands_reach_its_subshaders(tmp_path):
    """A Category's Blend and Lighting apply to the SubShaders inside it (Unity's Category: a
    group of commands for every SubShader below it); control: the same pass outside a Category."""
    inner = 'SubShader { Pass { Material { Diffuse (1, 0, 0, 1) } SetTexture [_MainTex] { combine primary } } }'
    grouped = _read(tmp_path, 'Shader "t/c" { Category { Blend SrcAlpha One Lighting On %s } }' % inner)
    alone = _read(tmp_path, 'Shader "t/c" { %s }' % inner)
    assert grouped.passes[0].state.blend_factors == ("SrcAlpha", "One")
    assert "UNITY_LIGHTMODEL_AMBIENT" in grouped.passes[0].program
    assert not alone.passes[0].state.blend_factors and "UNITY_LIGHTMODEL_AMBIENT" not in alone.passes[0].program


@pytest.mark.parametrize("combine, cg", [
    ("texture * primary", "s_texture * s_primary"),
    ("previous + constant", "s_previous + s_constant"),
    ("texture - previous", "s_texture - s_previous"),
    ("texture +- primary", "s_texture + s_primary - 0.5"),
    ("texture lerp(constant) previous", "lerp(s_previous, s_texture, (s_constant).a)"),
    ("texture * primary + constant", "s_texture * s_primary + s_constant"),
    ("one - texture", "(1.0 - s_texture)"),
    ("constant alpha", "s_constant.aaaa"),
])
def test_combiner_expressions_are_the_manuals(combine, cg):
    """Each combiner form of "ShaderLab: legacy texture combining" as its Cg expression."""
    from pbrlab.importers.unity.fixed_function import combine_expression
    assert combine_expression(combine, "x") == cg


def test_a_macro_member_before_a_member_does_not_hide_it():
    """UNITY_FOG_COORDS(1) and UNITY_VERTEX_OUTPUT_STEREO have no ';' of their own: the member
    written after them is still read (Reflect-VertexLit's COLOR0 after its fog macro);
    UNITY_POSITION(pos); is HLSLSupport's position member, float4 pos : SV_POSITION
    (tests/importers/unity/test_unity_position.py)."""
    from pbrlab.importers.unity.parse_pass import _structs
    struct = _structs("""struct v2f {
        float2 uv : TEXCOORD0;
        UNITY_FOG_COORDS(1)
        fixed4 diff : COLOR0;
        UNITY_FOG_COORDS(2)
        UNITY_VERTEX_OUTPUT_STEREO
        float4 screenPos : TEXCOORD2;
        UNITY_POSITION(pos);
    };""")["v2f"]
    assert struct.members == [("float2", "uv", "TEXCOORD0"), ("fixed4", "diff", "COLOR0"),
                              ("float4", "screenPos", "TEXCOORD2"), ("float4", "pos", "SV_POSITION")]


@pytest.mark.parametrize("language", LANGUAGES)
def test_lightmodel_ambient_is_the_ambient_probes_mean(tmp_path, language):
    """Material { Ambient (1, 1, 1, 1) }, no light, under the sky: the face is
    UNITY_LIGHTMODEL_AMBIENT, the mean over the six axes of the sky's SH9 irradiance / pi
    (float64), within LIT_BOUND (the SH coefficients reach the GPU as float32: 6e-8 relative);
    that mean is the sphere's mean (checked here against 20,000 Fibonacci directions, 1e-3
    relative, the quadrature's own error); the control (ShadeSH9 along the face's normal, what a
    per-normal ambient would give) differs."""
    from pbrlab.foundation.locations import locate
    from pbrlab.maths.reference.lighting import sh9_irradiance
    from pbrlab.scene.environment import environment_sh
    shader = tmp_path / "ambient.shader"
    shader.write_text(textwrap.dedent(SHADER.format(name="ambient", body="""
            Material { Ambient (1, 1, 1, 1) }
            Lighting On""")))
    scene = parse_scene({
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
        "environment": {"path": str(locate("scenes") / "assets" / "sky.exr"), "intensity": 0.5},
        "materials": {"m": {"surface": str(shader)}},
        "objects": [{"mesh": {"primitive": "box", "size": 1.0}, "material": "m"}],
    }, "t", tmp_path)
    face = _face(render_scene(scene, language=language).linear)
    sh = environment_sh(scene.environment)
    axes = np.concatenate([np.eye(3), -np.eye(3)])
    expected = np.maximum(sh9_irradiance(sh, axes), 0.0).mean(axis=0) / np.pi
    i = np.arange(20000) + 0.5
    z, phi = 1 - 2 * i / 20000, np.pi * (1 + 5 ** 0.5) * i
    sphere = np.stack([np.sqrt(1 - z * z) * np.cos(phi), np.sqrt(1 - z * z) * np.sin(phi), z], axis=1)
    np.testing.assert_allclose(np.maximum(sh9_irradiance(sh, sphere), 0.0).mean(axis=0) / np.pi, expected, rtol=1e-3)
    assert 0.02 < expected.min() and expected.max() < 1.0
    error = np.abs(face[:, :3] - expected).max(axis=1)
    assert (error > LIT_BOUND).mean() == 0.0, (error.max(), face[0], expected)
    control = np.maximum(sh9_irradiance(sh, [0.0, 0.0, 1.0]), 0.0) / np.pi
    assert (np.abs(face[:, :3] - control).max(axis=1) > 100 * LIT_BOUND).all()
