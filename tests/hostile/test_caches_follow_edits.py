"""Editing any input between two renders (or two evaluations) in one process gives the new
result: the surface file, a file it includes, a texture, a mesh, the environment image,
an evaluated include. Edits are made the hard way too: same size, the modification time
put back, the file replaced by a rename (a new inode), which a (path, size, mtime) key
would miss."""

import json
import os
import re
import warnings

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.gpu import evaluator, programs
from pbrlab.foundation import images
from pbrlab.scene import meshes
from pbrlab.render import resource_cache
from pbrlab.foundation.errors import PbrlabError
from pbrlab.render.renderer import render_scene
from pbrlab.scene import load_scene

SURFACE = """#include "tint.inc"
uniform sampler2D _Tex;
void surf(Input IN, inout SurfaceOutputStandard o) {
    o.Albedo = texture(_Tex, IN.uv).rgb * pbr_test_tint();
    o.Smoothness = 0.3;
}
"""


def _replace(path, data: bytes, keep_mtime=True):
    """Write ``data`` to a new file renamed over ``path``, its mtime set back to the old one."""
    old = os.stat(path)
    tmp = path.with_name(path.name + ".new")
    tmp.write_bytes(data)
    if keep_mtime:
        os.utime(tmp, ns=(old.st_atime_ns, old.st_mtime_ns))
    os.replace(tmp, path)


@pytest.fixture
def surface_scene(tmp_path):
    (tmp_path / "tint.inc").write_text("vec3 pbr_test_tint() { return vec3(1.0, 0.5, 0.25); }\n")
    (tmp_path / "surf.glsl").write_text(SURFACE)
    images.write_png(tmp_path / "tex.png", np.full((4, 4, 3), 200, np.uint8))
    data = base_scene()
    data["environment"] = None
    data["materials"]["m"] = {"surface": "surf.glsl",
                              "textures": {"_Tex": {"path": "tex.png", "srgb": True}}}
    data["objects"] = [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "m"},
                       {"mesh": "tri.obj", "material": "s", "transform": {"translate": [0, 0, 1.5]}}]
    (tmp_path / "tri.obj").write_text("v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n")
    (tmp_path / "scene.json").write_text(json.dumps(data))
    return tmp_path


def _render(folder, ctx):
    return render_scene(load_scene(folder / "scene.json"), ctx).linear


@pytest.mark.parametrize("edit", ["surface", "include", "texture", "mesh"])
def test_an_edit_between_two_renders_gives_the_new_image(surface_scene, gl_context, edit, census):
    folder = surface_scene
    before = _render(folder, gl_context)
    if edit == "surface":  # same length: 0.3 -> 0.9
        path = folder / "surf.glsl"
        _replace(path, path.read_bytes().replace(b"0.3", b"0.9"))
    elif edit == "include":
        path = folder / "tint.inc"
        _replace(path, path.read_bytes().replace(b"0.25", b"0.75"))
    elif edit == "texture":
        images.write_png(folder / "new.png", np.full((4, 4, 3), 20, np.uint8))
        os.replace(folder / "new.png", folder / "tex.png")
    else:
        path = folder / "tri.obj"
        _replace(path, path.read_bytes().replace(b"v 0 1 0", b"v 0 3 0"))
    after = _render(folder, gl_context)
    assert not np.array_equal(before, after), f"the {edit} edit did not reach the image"
    # and the result is that of a fresh process's first render: drop every cache, render again
    programs.program_cache(gl_context).clear()
    gl_context.extra.pop(resource_cache._EXTRA_KEY, None)
    meshes._MESH_DATA.clear()
    np.testing.assert_array_equal(_render(folder, gl_context), after)
    census["cache after edit", "handled"] += 1


UNITY_SHADER = """Shader "Test/IncludedTint" {
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        #include "tint.cginc"
        struct Input { float4 color : COLOR; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = 0;
            o.Emission = float3(PBR_TEST_TINT, 0.5, 0.25);
        }
        ENDCG
    }
}
"""


@pytest.mark.parametrize("language", ["hlsl", "glsl"])
def test_an_edited_cginc_of_a_unity_shader_gives_the_new_image(tmp_path, gl_context, language, census):
    """The Unity program cache keys on the .shader and every file it includes, recursively."""
    # (a local .cginc is not ported for GLSL: macros read alike in both languages)
    (tmp_path / "tint.cginc").write_text('#include "tint_value.cginc"\n#define PBR_TEST_TINT (TINT_R * 1.0)\n')
    (tmp_path / "tint_value.cginc").write_text("#define TINT_R 0.25\n")
    (tmp_path / "tinted.shader").write_text(UNITY_SHADER)
    data = base_scene()
    data["environment"] = None
    data["materials"] = {"m": {"surface": "tinted.shader"}}
    data["objects"] = [{"sphere": {"center": [0, 0, 0], "radius": 1.0}, "material": "m"}]
    (tmp_path / "scene.json").write_text(json.dumps(data))

    def render():
        return render_scene(load_scene(tmp_path / "scene.json"), gl_context, language=language).linear

    before = render()
    _replace(tmp_path / "tint_value.cginc", b"#define TINT_R 0.75\n")  # two includes deep, same size and mtime
    after = render()
    centre = tuple(s // 2 for s in after.shape[:2])
    np.testing.assert_allclose(before[centre][:3], [0.25, 0.5, 0.25], atol=1e-6)
    np.testing.assert_allclose(after[centre][:3], [0.75, 0.5, 0.25], atol=1e-6)
    census["cache after edit", "handled"] += 1


def test_a_nan_texture_is_refused_by_name(tmp_path, gl_context, census):
    images.write_exr(tmp_path / "n.exr", np.full((4, 4, 3), np.nan, np.float32))
    data = base_scene()
    data["materials"]["m"]["textures"] = {"normal": "n.exr"}
    (tmp_path / "scene.json").write_text(json.dumps(data))
    with pytest.raises(PbrlabError, match=r"texture .*n\.exr: 16 texel\(s\) are NaN or Inf"):
        _render(tmp_path, gl_context)
    census["texture", "refused cleanly"] += 1


def test_png_bytes_named_exr_are_refused_by_name(tmp_path, gl_context, census):
    images.write_png(tmp_path / "sky.png", np.full((4, 8, 3), 200, np.uint8))
    os.rename(tmp_path / "sky.png", tmp_path / "sky.exr")
    data = base_scene()
    data["environment"] = {"path": "sky.exr"}
    (tmp_path / "scene.json").write_text(json.dumps(data))
    with pytest.raises(PbrlabError, match=r"sky\.exr: named \.exr but its content is PNG data"):
        _render(tmp_path, gl_context)
    census["texture", "refused cleanly"] += 1


@pytest.mark.parametrize("surface, message", [
    (SURFACE.replace("uniform sampler2D _Tex;", "uniform sampler2D _Tex;\nuniform sampler2D _Unbound;"),
     "declares sampler '_Unbound', and the material binds no texture to it"),
    (SURFACE.replace("_Tex", "_Tx"), r"textures\._Tex: surf\.glsl declares no sampler named '_Tex'"),
    (SURFACE.replace("o.Smoothness = 0.3;", "o.Normal = vec3(0.0) / 0.0;"), "pixels are NaN or Inf"),
    (SURFACE.replace("o.Smoothness = 0.3;", "o.Albedo = vec3(1.0 / 0.0);"), "pixels are NaN or Inf"),
    (SURFACE.replace("0.3", "0.3 \xe9"), "surf.glsl:5: not UTF-8 text"),
])
def test_surface_mistakes_are_reported_by_name(surface_scene, capsys, surface, message, census):
    from pbrlab.commands import cli
    path = surface_scene / "surf.glsl"
    path.write_bytes(surface.encode("latin-1"))
    out = surface_scene / "out.png"
    assert cli.main(["render", str(surface_scene / "scene.json"), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert re.search(message, err), err
    assert not out.exists()
    census["surface", "refused cleanly"] += 1


def test_an_evaluated_include_edited_on_disk_gives_the_new_value(tmp_path, census):
    inc = tmp_path / "f.glsl"
    inc.write_text("float pbr_test_f(float x) { return x * 2.0; }\n")
    x = np.arange(4, dtype=np.float32)
    np.testing.assert_array_equal(evaluator.evaluate("pbr_test_f(x)", ["f.glsl"], include_dirs=[tmp_path], x=x), x * 2)
    _replace(inc, inc.read_bytes().replace(b"2.0", b"3.0"))
    np.testing.assert_array_equal(evaluator.evaluate("pbr_test_f(x)", ["f.glsl"], include_dirs=[tmp_path], x=x), x * 3)
    census["cache after edit", "handled"] += 1


@pytest.mark.parametrize("loop, warned", [("for (int i = 0; i < 70000; ++i)", True),
                                          ("for (int i = 0; i <= 65535; i++)", True),
                                          ("for (int i = 1; i <= 65535; i++)", False)])
def test_a_loop_past_llvmpipes_cap_is_a_named_warning(gl_context, tmp_path, loop, warned, census):
    from pbrlab.foundation.errors import LoopLimitWarning
    if "llvmpipe" not in gl_context.info["GL_RENDERER"].lower():
        pytest.skip("the 65535-iteration cap is llvmpipe's")
    (tmp_path / "loop.glsl").write_text(
        "// header\nfloat pbr_test_count(float x) {\n    float s = 0.0;\n"
        f"    {loop} {{ s += 1.0; }}\n    return s + x;\n}}\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = evaluator.evaluate(f"pbr_test_count(x) + {len(loop)}.0", ["loop.glsl"], include_dirs=[tmp_path],
                                 x=np.zeros(1, np.float32))
    messages = [str(w.message) for w in caught if issubclass(w.category, LoopLimitWarning)]
    assert bool(messages) == warned, messages
    if warned:
        assert "loop.glsl:4: a loop of" in messages[0]
        assert out[0] == 65535 + len(loop)  # the cap the warning talks about, measured
    census["shader loop", "handled"] += 1
