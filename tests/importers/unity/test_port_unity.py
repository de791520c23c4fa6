"""`pbrlab port-unity`: the mechanical GLSL renames of a Unity surface shader, as one tested
tool; its output renders on the GLSL path exactly as the in-memory port does."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.render import renderer as render
from pbrlab import scene
from pbrlab.importers.unity import parse, port

MANUAL = Path(__file__).resolve().parents[3] / "scenes" / "unity_manual"
SHADERS = sorted(p.name for p in MANUAL.glob("*.shader"))


def _program(body: str, pragma="surf Lambert", inputs="float2 uv_MainTex;"):
    text = f"#pragma surface {pragma}\nstruct Input {{ {inputs} }};\n{body}"
    return parse.parse_text(text, Path("x.cginc"))


@pytest.mark.parametrize("hlsl, glsl", [
    ("void surf (Input IN, inout SurfaceOutput o) { o.Albedo = 1; }",
     "void surf (Input IN, inout SurfaceOutput o) { o.Albedo = vec3(1); }"),
    ("fixed4 _Color;\nvoid surf (Input IN, inout SurfaceOutput o) { half3 c = 0.5; o.Albedo = c * _Color.rgb; }",
     "uniform vec4 _Color;\nvoid surf (Input IN, inout SurfaceOutput o) { vec3 c = vec3(0.5); o.Albedo = c * _Color.rgb; }"),
    ("float4x4 _M;\nsampler2D _MainTex;\nvoid surf (Input IN, inout SurfaceOutput o) { o.Alpha = 1; }",
     "uniform mat4 _M;\nuniform sampler2D _MainTex;\nvoid surf (Input IN, inout SurfaceOutput o) { o.Alpha = 1; }"),
    ("inline float3 G (in float3 c) { return pow(c, 2.2); }\nvoid surf (Input IN, inout SurfaceOutput o) { o.Gloss = (half)IN.uv_MainTex.x; }",
     "vec3 G (in vec3 c) { return pbr_unity_pow(c, 2.2); }\nvoid surf (Input IN, inout SurfaceOutput o) { o.Gloss = float(IN.uv_MainTex.x); }"),
])
def test_renames(hlsl, glsl):
    shader = _program(hlsl)
    assert port.port_program(shader).split("\n", 2)[2] == glsl


def test_semantics_are_dropped_and_comments_kept():
    shader = _program("void surf (Input IN, inout SurfaceOutput o) { o.Gloss = IN.uv_MainTex.x > 0.5 ? 1.0 : UNITY_PI; }"
                      " // half3 stays", inputs="float4 color : COLOR; float2 uv_MainTex : TEXCOORD0;")
    out = port.port_program(shader)
    assert "vec4 color;" in out and "vec2 uv_MainTex;" in out and "// half3 stays" in out
    assert "? 1.0 : UNITY_PI;" in out  # a ternary's upper-case operand is not a semantic


@pytest.mark.filterwarnings("ignore:.*Cull Off is not applied to a ray-traced sphere")
@pytest.mark.parametrize("name", SHADERS)
def test_port_unity_output_renders_like_the_in_memory_port(name, tmp_path, capsys):
    out = tmp_path / (Path(name).stem + ".glsl")
    assert cli.main(["port-unity", str(MANUAL / name), "-o", str(out)]) == 0
    assert "wrote" in capsys.readouterr().out

    def scene_with(surface):
        return scene.parse_scene({
            "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [48, 48]},
            "lights": [{"type": "directional", "direction": [-0.5, -0.3, -1.0]}],
            "environment": {"color": [0.2, 0.3, 0.4]},
            "materials": {"m": {"surface": surface}},
            "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}, "<test>", MANUAL)

    ported = render.render_scene(scene_with(str(out)), language="glsl").linear
    direct = render.render_scene(scene_with(name), language="glsl").linear
    assert np.array_equal(ported, direct)
    assert (ported[..., 3] > 0).sum() > 100


def test_a_port_refuses_the_hlsl_path(tmp_path):
    out = tmp_path / "rim.glsl"
    assert cli.main(["port-unity", str(MANUAL / "rim.shader"), "-o", str(out)]) == 0
    s = scene.parse_scene({"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "size": [16, 16]},
                           "lights": [], "materials": {"m": {"surface": str(out)}},
                           "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]},
                          "<test>", MANUAL)
    with pytest.raises(Exception, match="renders only in GLSL"):
        render.render_scene(s, language="hlsl")


def test_port_unity_reports_a_broken_shader_without_traceback(tmp_path, capsys):
    bad = tmp_path / "bad.shader"
    bad.write_text('Shader "x" { SubShader { CGPROGRAM\nstruct Input { float2 uv_MainTex; };\nENDCG } }')
    assert cli.main(["port-unity", str(bad)]) == 2
    assert "no '#pragma surface" in capsys.readouterr().err
