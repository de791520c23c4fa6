"""Unity ``GLSLPROGRAM`` snippets (issue 34): both stages in one block under ``#ifdef VERTEX`` /
``#ifdef FRAGMENT``, in the fixed-function era's GLSL (``gl_ModelViewProjectionMatrix``,
``gl_Vertex``, ``gl_MultiTexCoord0``, ``varying``, ``gl_FragColor``), checked per pixel against
a float64 expectation: a plane seen by the corpus camera, the snippet writing its UVs.

The expectation is independent of the harness's matrices: each pixel centre's ray from the
camera (look-at with world up +Y, vertical field of view 40 degrees, square image) meets the
plane y = 0 at (x, z), whose UV is (x / size + 1/2, 1/2 - z / size) (the plane primitive's
mapping: u along +x, v along -z).
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import UnityShaderNote
from pbrlab.render.renderer import render_scene

from unity_inputs import pixel_rays

CAMERA = {"position": [0.0, 1.3, 1.5], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [64, 64]}
SIZE = 1.6
TINT = (1.0, 0.5, 0.25)
# The vertex position through the float32 product unity_MatrixVP * unity_ObjectToWorld and the
# perspective-correct interpolation: each about 10 roundings of 2^-24 relative; a clip
# position off by e (relative) moves the UV by e times its gradient in NDC (here at most 1.2
# per NDC unit) times |NDC| <= 1: (10 + 10 + 10) * 6e-8 * 1.2 = 2.2e-6, bound 3e-6.
# Measured on llvmpipe: 3.7e-7 (both languages; 2 of 4096 pixel centres near the edge left out).
UV_BOUND = 3e-6
# Every drawn snippet notes that both languages run its GLSL (checked in the first test).
pytestmark = pytest.mark.filterwarnings("ignore::pbrlab.importers.unity.UnityShaderNote")
# A pixel centre this close (in pixels) to the plane's edge may fall either way under the
# rasteriser's snapping (llvmpipe: 1/256 px); such pixels are left out.
EDGE_PX = 0.02

SNIPPET = """
Shader "t/{name}" {{
    Properties {{ _Tint ("Tint", Color) = ({tint}, 1) }}
    SubShader {{ Pass {{
        GLSLPROGRAM
        uniform vec4 _Tint;
        #ifdef VERTEX
        varying vec2 uv;
        void main() {{
            gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
            uv = gl_MultiTexCoord0.xy;
        }}
        #endif
        #ifdef FRAGMENT
        varying vec2 uv;
        void main() {{ gl_FragColor = {colour}; }}
        #endif
        ENDGLSL
    }} }}
}}
"""


def _render(tmp_path, language, name, colour="vec4(uv * _Tint.xy, _Tint.z, 1.0)", text=None):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(text or SNIPPET.format(name=name, colour=colour,
                                                             tint=", ".join(map(str, TINT)))))
    data = corpus.scene_for(shader)
    data["camera"] = CAMERA
    data["objects"] = [{"mesh": {"primitive": "plane", "size": SIZE}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def _uv(size, offset=(0.0, 0.0)):
    """(uv, inside, near an edge) per pixel centre (offset in pixels), float64; row 0 the top."""
    eye, d = pixel_rays(CAMERA, size, offset)
    hit = eye + d * (-eye[1] / d[..., 1])[..., None]
    u, v = hit[..., 0] / SIZE + 0.5, 0.5 - hit[..., 2] / SIZE
    return np.stack([u, v], -1), (u >= 0) & (u <= 1) & (v >= 0) & (v <= 1)


def expected(size):
    uv, inside = _uv(size)
    near_edge = np.zeros(size, bool)
    for dx in (-EDGE_PX, EDGE_PX):
        for dy in (-EDGE_PX, EDGE_PX):
            near_edge |= _uv(size, (dx, dy))[1] != inside
    colour = np.concatenate([uv * TINT[:2], np.full(size + (1,), TINT[2])], -1)
    return colour, inside, near_edge


def problems(image, colour, inside, near_edge) -> list[str]:
    kept = ~near_edge
    out = []
    wrong = ((image[..., 3] > 0) != inside) & kept
    if wrong.any():
        out.append(f"{int(wrong.sum())} pixels covered where float64 says otherwise")
    error = np.abs(image[..., :3] - colour).max(-1)
    over = (error > UV_BOUND) & inside & kept
    if over.any():
        out.append(f"{over.mean():.3%} of pixels over {UV_BOUND} (largest {error[over].max():.3g})")
    return out


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_snippet_draws_its_uvs_where_float64_says(tmp_path, language):
    """Both languages run the GLSL as written (Unity has no HLSL of a GLSLPROGRAM), and say so."""
    with pytest.warns(UnityShaderNote, match=r"uv\.shader:\d+: a GLSLPROGRAM: Unity compiles it for OpenGL only"):
        image = _render(tmp_path, language, "uv")
    colour, inside, near_edge = expected(image.shape[:2])
    assert inside.mean() > 0.3
    assert problems(image, colour, inside, near_edge) == []


def test_controls_fail(tmp_path):
    """The expectation with u and v swapped, and a snippet writing v for u, both fail."""
    image = _render(tmp_path, "glsl", "uv")
    colour, inside, near_edge = expected(image.shape[:2])
    assert problems(image, colour[..., [1, 0, 2]], inside, near_edge)
    swapped = _render(tmp_path, "glsl", "vu", colour="vec4(uv.yx * _Tint.xy, _Tint.z, 1.0)")
    assert problems(swapped, colour, inside, near_edge)


def test_the_pass_light_is_the_scenes(tmp_path):
    """_LightColor0 and _WorldSpaceLightPos0 a snippet declares are the pass's light, as in a
    Cg pass: the corpus scene's directional light, colour (1, 1, 1) at intensity 1, shining
    along (-0.4, -0.6, -0.7): _WorldSpaceLightPos0 = (0.4, 0.6, 0.7) normalised, w = 0."""
    text = SNIPPET.replace("uniform vec4 _Tint;", "uniform vec4 _Tint; uniform vec4 _LightColor0; "
                           "uniform vec4 _WorldSpaceLightPos0;")
    light = _render(tmp_path, "glsl", "light", text=text.format(name="light", tint="1, 1, 1",
                                                                colour="vec4(_LightColor0.rgb, 1.0)"))
    direction = _render(tmp_path, "glsl", "direction", text=text.format(
        name="direction", tint="1, 1, 1", colour="vec4(_WorldSpaceLightPos0.xyz, 1.0 + _WorldSpaceLightPos0.w)"))
    covered = light[..., 3] > 0
    np.testing.assert_allclose(light[covered][:, :3], 1.0, rtol=0, atol=1e-7)
    want = np.array([0.4, 0.6, 0.7]) / np.linalg.norm([0.4, 0.6, 0.7])
    np.testing.assert_allclose(direction[covered][:, :3], np.broadcast_to(want, (int(covered.sum()), 3)),
                               rtol=0, atol=3e-7)  # a float32 normalisation: a few 6e-8 roundings


def test_a_rectangle_texture_reads_the_texel_at_unnormalised_coordinates(tmp_path):
    """sampler2DRect at (uv * size) reads what sampler2D reads at uv (GL 3.3 core 3.8.8)."""
    from pbrlab.foundation.images import write_png
    texture = tmp_path / "five_by_three.png"
    rng = np.random.default_rng(7)
    write_png(texture, rng.integers(0, 256, (3, 5, 4), dtype=np.uint8))

    def drawn(name, sampler, read):
        text = SNIPPET.replace("uniform vec4 _Tint;", f"uniform vec4 _Tint; uniform {sampler} _MainTex;")
        shader = tmp_path / f"{name}.shader"
        shader.write_text(textwrap.dedent(text.format(name=name, tint="1, 1, 1", colour=read)))
        data = corpus.scene_for(shader)
        data["camera"] = CAMERA
        data["objects"] = [{"mesh": {"primitive": "plane", "size": SIZE}, "material": "m"}]
        data["materials"]["m"]["properties"] = {"_MainTex": {"path": str(texture)}}
        return render_scene(parse_scene(data, "t", tmp_path), language="glsl").linear

    rect = drawn("rect", "sampler2DRect", "texture(_MainTex, uv * vec2(textureSize(_MainTex)))")
    plain = drawn("plain", "sampler2D", "texture2D(_MainTex, uv)")
    assert (rect[..., 3] > 0).mean() > 0.3 and np.ptp(plain[..., :3]) > 0.1
    np.testing.assert_allclose(rect, plain, rtol=0, atol=1e-6)  # the same texel weights, float32 coordinates


@pytest.mark.parametrize("head, named", [
    ("#pragma only_renderers d3d11 metal", "only_renderers d3d11 metal: Unity compiles this GLSLPROGRAM only for"),
])
@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_what_desktop_gl_lacks_is_named(tmp_path, head, named, language):
    text = SNIPPET.replace("GLSLPROGRAM\n", f"GLSLPROGRAM\n        {head}\n")
    shader = tmp_path / "refused.shader"
    shader.write_text(textwrap.dedent(text.format(name="refused", tint="1, 1, 1", colour="vec4(1.0)")))
    with pytest.raises(PbrlabError, match=r"refused\.shader:\d+: .*" + named):
        render_scene(parse_scene(corpus.scene_for(shader), "t", tmp_path), language=language)


def test_the_names_before_unity_5_4_are_its_matrices(tmp_path):
    """``_Object2World`` (Unity 5.4 renamed it unity_ObjectToWorld) takes the plane's points to
    the world: their (x, z) there give the UVs of the expectation."""
    text = SNIPPET.replace("uniform vec4 _Tint;", "uniform vec4 _Tint; uniform mat4 _Object2World; varying vec3 wp;")
    text = text.replace("uv = gl_MultiTexCoord0.xy;", "wp = (_Object2World * gl_Vertex).xyz;")
    colour = f"vec4(vec2(wp.x / {SIZE} + 0.5, 0.5 - wp.z / {SIZE}) * _Tint.xy, _Tint.z, 1.0)"
    image = _render(tmp_path, "glsl", "old_names", text=text.format(name="old_names", colour=colour,
                                                                  tint=", ".join(map(str, TINT))))
    assert problems(image, *expected(image.shape[:2])) == []


def test_unitycg_glslinc_transforms_texture_coordinates(tmp_path):
    """A GLSLINCLUDE of UnityCG.glslinc (pbrlab's stand-in): TRANSFORM_TEX with the material's
    _MainTex_ST (the default tiling 1, offset 0, so the UVs as they are) draws the UVs."""
    text = SNIPPET.replace("uniform vec4 _Tint;", '#include "UnityCG.glslinc"\n        uniform vec4 _Tint; '
                           "uniform vec4 _MainTex_ST; uniform sampler2D _MainTex;")
    text = text.replace("uv = gl_MultiTexCoord0.xy;", "uv = TRANSFORM_TEX(gl_MultiTexCoord0, _MainTex);")
    image = _render(tmp_path, "glsl", "glslinc", text=text.format(name="glslinc", tint=", ".join(map(str, TINT)),
                                                                  colour="vec4(uv * _Tint.xy, _Tint.z, 1.0)"))
    assert problems(image, *expected(image.shape[:2])) == []


ES_SNIPPET = SNIPPET.replace("GLSLPROGRAM\n", "GLSLPROGRAM\n        #pragma only_renderers {renderers}\n"
                             "        precision mediump float;\n").replace(
    "void main() {{ gl_FragColor = {colour}; }}",
    "void main() {{\n        #ifdef SHADER_API_GLES3\n            gl_FragColor = {colour};\n"
    "        #else\n            gl_FragColor = vec4(uv.yx, 0.0, 1.0);\n        #endif\n        }}")


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_gles3_only_snippet_runs_as_unity_compiles_it_for_gles3(tmp_path, language):
    """``#pragma only_renderers gles3``: compiled as for OpenGL ES 3 (SHADER_API_GLES3 defined, a
    precision statement accepted), its UVs where float64 says, within UV_BOUND; a note says so."""
    text = ES_SNIPPET.format(name="es", renderers="gles3", tint=", ".join(map(str, TINT)),
                             colour="vec4(uv * _Tint.xy, _Tint.z, 1.0)")
    with pytest.warns(UnityShaderNote, match=r"for OpenGL ES only \(SHADER_API_GLES3\)"):
        image = _render(tmp_path, language, "es", text=text)
    assert problems(image, *expected(image.shape[:2])) == []


def test_a_snippet_for_desktop_and_es_takes_the_desktop_branch(tmp_path):
    """The control: with glcore among its renderers the snippet is compiled for desktop GL
    (SHADER_API_GLES3 undefined), whose branch writes (v, u, 0): the expectation fails."""
    text = ES_SNIPPET.format(name="both", renderers="glcore gles3", tint=", ".join(map(str, TINT)),
                             colour="vec4(uv * _Tint.xy, _Tint.z, 1.0)")
    image = _render(tmp_path, "glsl", "both", text=text)
    assert problems(image, *expected(image.shape[:2]))


def _external(tmp_path, name, head, sampler, read, texture):
    text = SNIPPET.replace("GLSLPROGRAM\n", f"GLSLPROGRAM\n        {head}\n").replace(
        "uniform vec4 _Tint;", f'#include "UnityCG.glslinc"\n        uniform vec4 _Tint; uniform {sampler} _MainTex;')
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(text.format(name=name, tint="1, 1, 1", colour=read)))
    data = corpus.scene_for(shader)
    data["camera"] = CAMERA
    data["objects"] = [{"mesh": {"primitive": "plane", "size": SIZE}, "material": "m"}]
    data["materials"]["m"]["properties"] = {"_MainTex": {"path": str(texture)}}
    return render_scene(parse_scene(data, "t", tmp_path), language="glsl").linear


@pytest.mark.parametrize("extension, read", [
    ("#extension GL_OES_EGL_image_external : require", "textureExternal(_MainTex, uv)"),
    ("#extension GL_OES_EGL_image_external_essl3 : require", "texture(_MainTex, uv)"),
])
def test_an_external_image_is_the_materials_2d_texture(tmp_path, extension, read):
    """A ``samplerExternalOES`` reads the texture the material gives the property, as a
    ``sampler2D`` of it reads (the same texels and weights: equal to float32 rounding, 1e-6);
    the control, the same texture read mirrored, differs."""
    from pbrlab.foundation.images import write_png
    texture = tmp_path / "frame.png"
    write_png(texture, np.random.default_rng(3).integers(0, 256, (4, 6, 4), dtype=np.uint8))
    with pytest.warns(UnityShaderNote, match="external image .samplerExternalOES. is the property's 2D texture"):
        external = _external(tmp_path, "external", extension, "samplerExternalOES", read, texture)
    plain = _external(tmp_path, "plain", "", "sampler2D", "texture2D(_MainTex, uv)", texture)
    mirrored = _external(tmp_path, "mirrored", "", "sampler2D", "texture2D(_MainTex, 1.0 - uv)", texture)
    assert (external[..., 3] > 0).mean() > 0.3 and np.ptp(plain[..., :3]) > 0.1
    np.testing.assert_allclose(external, plain, rtol=0, atol=1e-6)
    assert (np.abs(mirrored - plain).max(-1) > 1e-6).mean() > 0.1
