"""How a Unity surface shader's program is fed and reported (pbrlab.importers.unity.program): properties
bound to uniforms of fewer components as Unity binds them, binding mismatches and clashes with
the harness's own uniform names as one-line errors, compile errors at the .shader's (or its
.cginc's) own file and line on both paths, and files that start with a UTF-8 byte-order mark."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation import images
from pbrlab.render import renderer as render
from pbrlab import scene
from pbrlab.foundation.errors import PbrlabError, ShaderCompileError

LANGUAGES = ("hlsl", "glsl")
SIZE = 16
# An emission-only surface (albedo 0, so Lambert adds nothing): the centre pixel is the
# emission as float32 arithmetic on exactly representable values; bound 1e-6 absolute.
EXACT = 1e-6


def _render(folder: Path, surface: str, language: str, **material):
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [SIZE, SIZE]},
            "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0}],
            "environment": None,
            "materials": {"m": {"surface": surface, **material}},
            "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}
    return render.render_scene(scene.parse_scene(data, "<test>", folder), language=language).linear


def _shader(properties: str, program: str) -> str:
    return f"""Shader "Test/Program" {{
    Properties {{
{properties}
    }}
    SubShader {{
        CGPROGRAM
        #pragma surface surf Lambert
{program}
        ENDCG
    }}
}}
"""


EMISSION = _shader(
    """        _Emission ("Emission", Color) = (0.25, 0.5, 0.75, 1)
        _Gain ("Gain", Vector) = (2, 3, 4, 5)
        _Scale ("Scale", Vector) = (0.5, 7, 7, 7)""",
    """        half3 _Emission;
        float2 _Gain;
        float _Scale;
        struct Input { float4 color : COLOR; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = 0;
            o.Emission = _Emission * (_Gain.y - _Gain.x) * _Scale * 2.0;
        }""")


@pytest.mark.parametrize("language", LANGUAGES)
def test_color_and_vector_properties_bind_their_leading_components(tmp_path, language):
    """half3 takes a Color's rgb, float2 a Vector's xy, float its x (Unity's binding)."""
    (tmp_path / "emission.shader").write_text(EMISSION)
    centre = _render(tmp_path, "emission.shader", language)[SIZE // 2, SIZE // 2, :3]
    np.testing.assert_allclose(centre, [0.25, 0.5, 0.75], atol=EXACT)


MISMATCHES = {
    "texture to float3": (
        '        _Tex ("Tex", 2D) = "white" {}',
        "        float3 _Tex;\n        struct Input { float4 color : COLOR; };\n"
        "        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = _Tex; }",
        r"2D texture property _Tex cannot be bound to the uniform '_Tex', declared vec3"),
    "number to sampler": (
        '        _Amount ("Amount", Float) = 1',
        "        sampler2D _Amount;\n        struct Input { float4 color : COLOR; };\n"
        "        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_Amount, float2(0, 0)).rgb; }",
        r"Float property _Amount \(a number\) cannot be bound to the uniform '_Amount', declared sampler2D"),
    "color to matrix": (
        '        _Col ("Col", Color) = (1, 1, 1, 1)',
        "        float4x4 _Col;\n        struct Input { float4 color : COLOR; };\n"
        "        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = _Col[0].rgb; }",
        r"Color property _Col \(4 numbers\) cannot be bound to the uniform '_Col', declared mat4"),
    "cube to sampler2D": (
        '        _Cube ("Cube", Cube) = "" {}',
        "        sampler2D _Cube;\n        struct Input { float4 color : COLOR; };\n"
        "        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_Cube, float2(0, 0)).rgb; }",
        r"Cube texture property _Cube cannot be bound to the uniform '_Cube', declared sampler2D"),
}


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("case", sorted(MISMATCHES))
def test_a_binding_mismatch_is_one_line_naming_property_uniform_and_types(tmp_path, language, case):
    properties, program, message = MISMATCHES[case]
    (tmp_path / "bad.shader").write_text(_shader(properties, program))
    with pytest.raises(PbrlabError, match=r"bad\.shader: " + message) as info:
        _render(tmp_path, "bad.shader", language)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_unity_sampler_named_like_a_harness_uniform_is_a_clash_error(tmp_path, language):
    (tmp_path / "clash.shader").write_text(_shader(
        '        u_albedo ("Tex", 2D) = "white" {}',
        "        sampler2D u_albedo;\n        struct Input { float2 uv_u_albedo; };\n"
        "        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(u_albedo, IN.uv_u_albedo).rgb; }"))
    with pytest.raises(PbrlabError, match=r"clash\.shader: uniform 'u_albedo': the program declares it "
                                          r"sampler2D, .*clashes with one of the harness's own uniforms"):
        _render(tmp_path, "clash.shader", language)


def test_a_surface_texture_named_like_a_harness_uniform_is_a_clash_error(tmp_path):
    (tmp_path / "surf.glsl").write_text(
        "uniform sampler2D u_albedo;\n"
        "void surf(Input IN, inout SurfaceOutputStandard o) { o.Albedo = texture(u_albedo, IN.uv).rgb; }\n")
    images.write_png(tmp_path / "tex.png", np.full((4, 4, 3), 200, np.uint8))
    with pytest.raises(PbrlabError, match=r"surf\.glsl: uniform 'u_albedo': the program declares it "
                                          r"sampler2D, and pbrlab sets a uniform of that name to 3 numbers"):
        _render(tmp_path, "surf.glsl", "glsl", textures={"u_albedo": {"path": "tex.png", "srgb": True}})


BROKEN = _shader(
    '        _Tint ("Tint", Float) = 1',
    """        #include "helper.cginc"
        float _Tint;
        struct Input { float4 color : COLOR; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = _Tint * pbr_test_helper();
        }""")
SURF_LINE = BROKEN.splitlines().index("            o.Albedo = _Tint * pbr_test_helper();") + 1  # 1-based


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_compile_error_names_the_shader_file_and_its_line(tmp_path, language):
    (tmp_path / "helper.cginc").write_text("float pbr_test_helper() { return 0.5; }\n")
    (tmp_path / "broken.shader").write_text(BROKEN.replace("_Tint * ", "_Tint * undeclared_thing * "))
    with pytest.raises(ShaderCompileError) as info:
        _render(tmp_path, "broken.shader", language)
    assert f"broken.shader:{SURF_LINE}:" in str(info.value), str(info.value)
    assert "pbrlab-unity-port" not in str(info.value) and "/tmp/pbrlab-" not in str(info.value)


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_compile_error_in_a_local_cginc_names_the_cginc_and_its_line(tmp_path, language):
    (tmp_path / "helper.cginc").write_text("// helper\n\nfloat pbr_test_helper() { return undeclared_in_cginc; }\n")
    (tmp_path / "broken.shader").write_text(BROKEN)
    with pytest.raises(ShaderCompileError, match=r"helper\.cginc:3:"):
        _render(tmp_path, "broken.shader", language)


BOM = b"\xef\xbb\xbf"
BOM_SHADER = _shader(
    "",
    """        #include "tint.cginc"
        struct Input { float4 color : COLOR; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = 0;
            o.Emission = float3(PBR_TEST_TINT, 0.5, 0.25);
        }""")


def _bom_includes(folder: Path):
    """tint.cginc opens with a BOM and an #include on its first line (a second BOM file)."""
    (folder / "tint.cginc").write_bytes(BOM + b'#include "tint_value.cginc"\n#define PBR_TEST_TINT (TINT_R * 1.0)\n')
    (folder / "tint_value.cginc").write_bytes(BOM + b"#define TINT_R 0.75\n")


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("form", ["cginc", "shader", "bare program"])
def test_files_opening_with_a_utf8_byte_order_mark_compile(tmp_path, language, form):
    """Editors on Windows save UTF-8 with a BOM; glslang and Mesa reject it at the first #."""
    _bom_includes(tmp_path)
    if form == "cginc":
        name, data = "tint.shader", BOM_SHADER.encode()
    elif form == "shader":
        name, data = "tint.shader", BOM + BOM_SHADER.encode()
    else:  # the bare CGPROGRAM text, its first line an #include right after the BOM
        name, data = "tint.cgprogram", BOM + b"""#include "tint.cginc"
#pragma surface surf Lambert
struct Input { float4 color : COLOR; };
void surf (Input IN, inout SurfaceOutput o) {
    o.Albedo = 0;
    o.Emission = float3(PBR_TEST_TINT, 0.5, 0.25);
}
"""
    (tmp_path / name).write_bytes(data)
    centre = _render(tmp_path, name, language)[SIZE // 2, SIZE // 2, :3]
    np.testing.assert_allclose(centre, [0.75, 0.5, 0.25], atol=EXACT)


def test_unity_programs_are_bounded_and_released_with_the_scene_programs(tmp_path, gl_context, monkeypatch):
    """The context's one program cache holds Unity programs too: least recently used
    released past its size, and an evicted shader rebuilt on its next render."""
    from pbrlab.gpu import programs
    from pbrlab.foundation.file_identity import FileCache

    released = []
    cache = FileCache(3, lambda program: (released.append(program), program.release()))
    monkeypatch.setitem(gl_context.extra, programs._EXTRA_KEY, cache)
    for k in range(6):
        (tmp_path / f"e{k}.shader").write_text(EMISSION.replace("* 2.0;", f"* {k + 1}.0;"))
    scenes = [scene.parse_scene({"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40,
                                            "size": [SIZE, SIZE]}, "lights": [], "environment": None,
                                 "materials": {"m": {"surface": f"e{k}.shader"}},
                                 "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]},
                                "<test>", tmp_path) for k in range(6)]
    first = render.render_scene(scenes[0], gl_context).linear
    for s in scenes[1:]:
        render.render_scene(s, gl_context)
        assert len(cache) <= 3
    assert len(released) >= 3
    np.testing.assert_array_equal(render.render_scene(scenes[0], gl_context).linear, first)
