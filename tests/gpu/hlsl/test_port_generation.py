"""The generator (pbrlab.gpu.port_hlsl): the committed ports are exactly what it writes, and each
of its rules does what its docstring says (and nothing else)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from pbrlab.gpu import port_hlsl
from pbrlab.gpu.port_hlsl import PortError, port_expression, port_text

import hlsl_helpers as H

GUARDED = "// x.glsl: test\n#ifndef PBR_X_GLSL\n#define PBR_X_GLSL\n{body}\n#endif // PBR_X_GLSL\n"


def test_committed_ports_are_the_generated_ones():
    """Regenerating hlsl_ports/ changes nothing: no hand edit, no drift from glsl/."""
    assert port_hlsl.stale_files() == [], "run: python -m pbrlab.gpu.port_hlsl"


def test_every_glsl_file_has_a_twin_path_for_path():
    glsl = sorted(p.relative_to(H.GLSL_ROOT).with_suffix("").as_posix() for p in (H.GLSL_ROOT / "pbr").rglob("*.glsl"))
    hlsl = sorted(p.relative_to(H.HLSL_ROOT).with_suffix("").as_posix() for p in (H.HLSL_ROOT / "pbr").rglob("*.hlsl"))
    assert hlsl == sorted(glsl + ["pbr/common/shim"])


def test_bodies_read_line_for_line_the_same():
    """Every GLSL line is its HLSL line (after the inserted shim line), changed only by the rules."""
    for path in sorted((H.GLSL_ROOT / "pbr").rglob("*.glsl")):
        rel = path.relative_to(H.GLSL_ROOT)
        g = path.read_text(encoding="utf-8").splitlines()
        h = (H.HLSL_ROOT / rel.with_suffix(".hlsl")).read_text(encoding="utf-8").splitlines()
        assert len(h) == len(g) + 1, rel
        inserted = [i for i, line in enumerate(h) if line.startswith('#include "pbr/common/shim.hlsl"')]
        assert len(inserted) == 1, rel
        i = inserted[0]
        for a, b in zip(g, h[:i] + h[i + 1:]):
            a = port_hlsl._quote_error_messages(a)  # rule 6, before the others
            renamed = port_hlsl._rename_tokens(port_hlsl._rename_files(a))  # a line may open a call it does not close
            assert a == b or renamed == b or _port_line(port_hlsl._rename_files(a)) == b, (rel, a, b)


def _port_line(line):
    """The code rules on one line, or None where the line alone is not an expression."""
    try:
        return port_expression(line)
    except PortError:
        return None


@pytest.mark.parametrize("glsl, hlsl", [
    ("return vec3(0.0);", "return ((float3)(0.0));"),
    ("x = vec3(a, b, c);", "x = float3(a, b, c);"),
    ("x = vec4(vec3(f), 1.0 - f);", "x = float4(((float3)(f)), 1.0 - f);"),
    ("x = vec3(max(a, b)).x;", "x = ((float3)(max(a, b))).x;"),
    ("x = vec3(vec3(1.0));", "x = ((float3)(((float3)(1.0))));"),
    ("u = atan(y, -x);", "u = atan2(y, -x);"),
    ("u = atan(y);", "u = atan(y);"),
    ("u = atan(f(a, b), vec2(c).x);", "u = atan2(f(a, b), ((float2)(c)).x);"),
    ("float f(vec3 v) { return 1.0; }", "float f(float3 v) { return 1.0; }"),
    ("y = 1.0; // vec3(0.0) atan(a, b) mix fract", "y = 1.0; // vec3(0.0) atan(a, b) mix fract"),
    ("ivec2 i; uvec3 u; bvec4 b;", "int2 i; uint3 u; bool4 b;"),
    ("c = mix(a, b, t);", "c = lerp(a, b, t);"),
    ("c = fract(x) + inversesqrt(y);", "c = frac(x) + rsqrt(y);"),
    ("c = mod(x, 2.0);", "c = pbr_mod(x, 2.0);"),
    ("float mixer = fractal;", "float mixer = fractal;"),
])
def test_code_rules(glsl, hlsl):
    assert port_expression(glsl) == hlsl


def test_file_rules_and_the_shim_line():
    text = GUARDED.format(body='#include "pbr/common/math.glsl"  // see glsl/README.md, d_ggx.glsl\nvec3 f() { return vec3(1.0); }')
    out = port_text(text, "pbr/x.glsl")
    assert out.splitlines() == [
        "// x.hlsl: test", "#ifndef PBR_X_HLSL", "#define PBR_X_HLSL",
        '#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/x.glsl by harness/pbrlab/gpu/port_hlsl.py: '
        "edit the GLSL, then regenerate",
        '#include "pbr/common/math.hlsl"  // see glsl/README.md, d_ggx.hlsl',
        "float3 f() { return ((float3)(1.0)); }", "#endif // PBR_X_HLSL"]


def test_a_bare_error_message_is_quoted_and_left_alone():
    """Rule 6: the GLSL's bare #error text (naga rejects quotes) is a quoted string in the twin, which
    the code rules leave as they leave strings (vec3 and mix here would otherwise be renamed)."""
    text = GUARDED.format(body="#if X\n#  error PBR_X: unknown value (vec3 mix)\n#endif")
    lines = port_text(text, "pbr/x.glsl").splitlines()
    assert '#  error "PBR_X: unknown value (vec3 mix)"' in lines
    quoted = GUARDED.format(body='#error "already quoted"')
    assert '#error "already quoted"' in port_text(quoted, "pbr/x.glsl").splitlines()


@pytest.mark.parametrize("body, message", [
    ("mat3 m;", "matrix type 'mat3'"),
    ("vec3 f(mat4x3 m) { return vec3(1.0); }", "matrix type"),
    ("struct S { float a; };\nS f() { return S(1.0); }", "struct constructor S"),
    ("float a[2] = float[2](1.0, 2.0);", "array constructor"),
    ("float sample = 1.0;", "'sample' is reserved in HLSL"),
    ("float line(float x) { return x; }", "'line' is reserved in HLSL"),
    ("vec3 f(vec3 x) { return mix(vec3(0.0), x, greaterThan(x, vec3(0.0))); }", "greaterThan"),
    ("vec3 f(vec3 x, bvec3 s) {\n return mix(vec3(0.0), x, s); }", "mix.. with a boolean selector"),
    ("float f(float x) {\n return mix(0.0, x, x > 0.0); }", "mix.. with a boolean selector"),
])
def test_unportable_glsl_is_refused_with_file_and_line(body, message):
    with pytest.raises(PortError, match=message) as info:
        port_text(GUARDED.format(body=body), "pbr/x.glsl")
    assert "pbr/x.glsl:4" in str(info.value) or "pbr/x.glsl:5" in str(info.value)


def test_a_file_without_include_guard_is_refused():
    with pytest.raises(PortError, match="no include guard"):
        port_text("float f() { return 1.0; }\n", "pbr/x.glsl")


def test_cli_check_reports_stale_and_orphan_ports(tmp_path):
    glsl = tmp_path / "glsl" / "pbr"
    glsl.mkdir(parents=True)
    (glsl / "a.glsl").write_text(GUARDED.format(body="float f() { return 1.0; }").replace("PBR_X", "PBR_A"))
    hlsl_root = tmp_path / "hlsl"
    cmd = [sys.executable, "-m", "pbrlab.gpu.port_hlsl", "--glsl-root", str(tmp_path / "glsl"), "--hlsl-root", str(hlsl_root)]
    check = subprocess.run(cmd + ["--check"], capture_output=True, text=True)
    assert check.returncode == 1 and "pbr/a.hlsl: missing" in check.stdout
    assert subprocess.run(cmd, capture_output=True, text=True).returncode == 0
    assert subprocess.run(cmd + ["--check"], capture_output=True, text=True).returncode == 0
    (hlsl_root / "pbr" / "a.hlsl").write_text("// hand edit\n")
    (hlsl_root / "pbr" / "orphan.hlsl").write_text("// no source\n")
    check = subprocess.run(cmd + ["--check"], capture_output=True, text=True)
    assert check.returncode == 1
    assert "pbr/a.hlsl: differs" in check.stdout and "pbr/orphan.hlsl: no GLSL source" in check.stdout
