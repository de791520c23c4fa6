"""Issue 26 (round two), valid input that failed and paths that gave tracebacks: a Latin-1 OBJ,
an output named only by its extension (`-o .png`), a Unity texture path that is a symlink loop."""

import json

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.commands import cli
from pbrlab.foundation.errors import PbrlabError
from pbrlab.scene.meshes import load_mesh
from pbrlab.scene import load_scene

TRIANGLE_OBJ = "# mod\u00e8le caf\u00e9\no caf\u00e9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"


@pytest.mark.parametrize("encoding", ["latin-1", "utf-8"])
def test_an_obj_in_latin_1_or_utf_8_reads_the_same(tmp_path, encoding, census):
    # trimesh guesses a non-UTF-8 file's encoding with charset_normalizer, which pbrlab does not
    # install: it raised ModuleNotFoundError for the Latin-1 file
    (tmp_path / "m.obj").write_bytes(TRIANGLE_OBJ.encode(encoding))
    scene = base_scene()
    scene["objects"][1]["mesh"] = "m.obj"
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    mesh = load_mesh(load_scene(tmp_path / "scene.json").objects[1])
    np.testing.assert_array_equal(mesh.vertices, [[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    assert len(mesh.faces) == 1
    census["mesh file", "handled"] += 1


def test_outputs_named_only_by_their_extension_are_written(tmp_path, monkeypatch, capsys, census):
    scene = base_scene()
    scene["camera"]["size"] = [16, 16]
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    monkeypatch.chdir(tmp_path)
    assert cli.main(["render", "scene.json", "-o", ".png", "--hdr", ".exr"]) == 0
    from pbrlab.foundation.images import read_image
    assert read_image(tmp_path / ".png").shape[:2] == (16, 16)
    assert read_image(tmp_path / ".exr").shape[:2] == (16, 16)
    assert sorted(p.name for p in tmp_path.iterdir()) == [".exr", ".png", "scene.json"]  # no temporary left
    census["output name", "handled"] += 1


SHADER = """Shader "Test/Loop" {
    Properties { _MainTex ("Albedo", 2D) = "white" {} }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        sampler2D _MainTex;
        struct Input { float2 uv_MainTex; };
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb; }
        ENDCG
    }
}
"""


def test_a_unity_texture_path_that_is_a_symlink_loop_is_refused_by_name(tmp_path, census):
    (tmp_path / "a.png").symlink_to(tmp_path / "b.png")
    (tmp_path / "b.png").symlink_to(tmp_path / "a.png")
    (tmp_path / "loop.shader").write_text(SHADER)
    scene = base_scene()
    scene["materials"]["m"] = {"surface": "loop.shader", "properties": {"_MainTex": {"path": "a.png"}}}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    with pytest.raises(PbrlabError, match=r"properties\._MainTex\.path: cannot follow .*a\.png"):
        load_scene(tmp_path / "scene.json")
    census["unity properties", "refused cleanly"] += 1


SURFACE = {"glsl": "void surf(Input IN, inout SurfaceOutputStandard o) {\n"
                   "    o.Albedo = vec3(0.8, 0.4, 0.2);\n    o.Smoothness = {gloss};\n}\n",
           "hlsl": "void surf(Input IN, inout SurfaceOutputStandard o) {\n"
                   "    o.Albedo = float3(0.8, 0.4, 0.2);\n    o.Smoothness = {gloss};\n}\n"}


def _surface_scene(tmp_path, stem: str, language: str, gloss: str):
    """A scene whose material's surface function is ``stem``.glsl (and its .hlsl twin)."""
    for lang, suffix in (("glsl", ".glsl"), ("hlsl", ".hlsl")):
        (tmp_path / (stem + suffix)).write_text(SURFACE[lang].replace("{gloss}", gloss))
    scene = base_scene()
    scene["camera"]["size"] = [16, 12]
    scene["materials"]["m"] = {"surface": stem + ".glsl"}
    path = tmp_path / f"scene-{len(list(tmp_path.iterdir()))}.json"
    path.write_text(json.dumps(scene))
    return path


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("stem", ['we"ird', "back\\slash"])
def test_a_surface_file_with_a_quote_in_its_name_renders(tmp_path, gl_context, language, stem, census):
    """An #include "..." line cannot carry a double quote (nor a backslash, to glslang): the
    template's include of the surface broke ("unexpected IDENTIFIER"). It renders as the same
    function under a plain name, and its errors name the file."""
    from pbrlab.render.renderer import render_scene
    odd = render_scene(load_scene(_surface_scene(tmp_path, stem, language, "0.5")), gl_context,
                       language=language).linear
    plain = render_scene(load_scene(_surface_scene(tmp_path, "plain", language, "0.5")), gl_context,
                         language=language).linear
    np.testing.assert_array_equal(odd, plain)
    broken = load_scene(_surface_scene(tmp_path, stem, language, "undeclared_gloss"))
    with pytest.raises(PbrlabError, match="undeclared_gloss") as failure:
        render_scene(broken, gl_context, language=language)
    suffix = ".glsl" if language == "glsl" else ".hlsl"
    assert f"{stem}{suffix}:3:" in str(failure.value)
    assert "pbrlab-surface" not in str(failure.value)  # the alias never shows
    census["surface file name", "handled"] += 1


def _unity_scene(tmp_path, surface: str):
    scene = base_scene()
    scene["camera"]["size"] = [16, 12]
    scene["materials"]["m"] = {"surface": surface}
    path = tmp_path / f"scene-{len(list(tmp_path.iterdir()))}.json"
    path.write_text(json.dumps(scene))
    return load_scene(path)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_unity_shader_with_a_quote_in_its_name_renders(tmp_path, gl_context, language, census):
    """The generated program's include of the port (GLSL) and its #line "file" (glslang, HLSL)
    were built from the raw name; a port-unity port (GLSL) was included by its raw name."""
    from pbrlab.render.renderer import render_scene
    (tmp_path / 'u"nity.shader').write_text(SHADER)
    (tmp_path / "plain.shader").write_text(SHADER)
    odd = render_scene(_unity_scene(tmp_path, 'u"nity.shader'), gl_context, language=language).linear
    plain = render_scene(_unity_scene(tmp_path, "plain.shader"), gl_context, language=language).linear
    np.testing.assert_array_equal(odd, plain)
    if language == "glsl":
        port = tmp_path / 'p"ort.glsl'
        assert cli.main(["port-unity", str(tmp_path / 'u"nity.shader'), "-o", str(port)]) == 0
        ported = render_scene(_unity_scene(tmp_path, port.name), gl_context).linear
        np.testing.assert_array_equal(ported, plain)
    (tmp_path / 'u"nity.shader').write_text(SHADER.replace("o.Albedo = tex2D", "o.Albedo = undeclared_colour * tex2D"))
    with pytest.raises(PbrlabError, match="undeclared_colour") as failure:
        render_scene(_unity_scene(tmp_path, 'u"nity.shader'), gl_context, language=language)
    assert 'u"nity.shader:8' in str(failure.value) and "pbrlab-" not in str(failure.value), failure.value
    census["surface file name", "handled"] += 1
