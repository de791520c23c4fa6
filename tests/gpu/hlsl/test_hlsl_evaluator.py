"""pbrlab.evaluate(..., language="hlsl"): the HLSL -> SPIR-V -> GLSL path of the evaluator."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab import PbrlabError, evaluate, vec3
from pbrlab.gpu import hlsl
from pbrlab.foundation.errors import ShaderCompileError

SPECIAL = np.array([0.0, -0.0, np.inf, -np.inf, np.nan, 1e-45, -1e-40, 1.17549435e-38, 3.4028235e38, 0.1],
                   np.float32)


def test_transport_is_bit_exact_and_keeps_element_order():
    """±0, denormals, ±Inf, NaN pass unchanged; element i stays element i across texture
    rows (SV_Position -> gl_FragCoord keeps GL's lower-left origin after spirv-cross)."""
    x = np.concatenate([SPECIAL, np.arange(9000, dtype=np.float32)])
    out = evaluate("x", [], language="hlsl", x=x)
    assert np.array_equal(out.view(np.uint32), x.view(np.uint32))
    with np.errstate(over="ignore"):
        v = np.stack([x, -x, x * 2], axis=-1)
    assert np.array_equal(evaluate("v", [], language="hlsl", v=vec3(v)).view(np.uint32), v.view(np.uint32))


@pytest.mark.parametrize("expression, width", [
    ("x", 1), ("float2(x, 1.0)", 2), ("float3(x, x, x)", 3), ("float4(x, x, x, x)", 4),
    ("int(x)", 1), ("x > 0.5", 1), ("uint(2)", 1)])
def test_result_width_and_types(expression, width):
    out = evaluate(expression, [], language="hlsl", x=np.array([0.25, 0.75], np.float32))
    assert out.shape == ((2,) if width == 1 else (2, width))


def test_library_function_matches_glsl_and_broadcasts():
    h = np.linspace(0, 1, 33, dtype=np.float32)[:, None]
    a = np.array([0.01, 0.25, 1.0], np.float32)
    glsl = evaluate("pbr_D_GGX(h, a)", h=h, a=a)
    out = evaluate("pbr_D_GGX(h, a)", language="hlsl", h=h, a=a)
    assert out.shape == (33, 3) and np.array_equal(out, glsl)


def test_defines_and_include_dirs(tmp_path):
    (tmp_path / "mine.hlsl").write_text("float twice(float x) { return MY_SCALE * x; }\n")
    out = evaluate("twice(x)", ["mine.hlsl"], include_dirs=[tmp_path], defines={"MY_SCALE": "2.0"},
                   language="hlsl", x=np.float32(3))
    assert out == 6.0


def test_compile_error_names_the_hlsl_file_and_line(tmp_path):
    (tmp_path / "pbr").mkdir()
    (tmp_path / "pbr" / "broken.hlsl").write_text("#ifndef B\n#define B\nfloat f(float x) {\n    return x + nope;\n}\n#endif\n")
    with pytest.raises(ShaderCompileError, match=r"pbr/broken.hlsl:4: error: 'nope'"):
        evaluate("f(x)", ["pbr/broken.hlsl"], include_dirs=[tmp_path], language="hlsl", x=1.0)
    with pytest.raises(ShaderCompileError, match=r"<evaluate>:\d+: error: 'undefined_thing'"):
        evaluate("undefined_thing + x", [], language="hlsl", x=1.0)


def test_missing_toolchain_is_a_clear_error(monkeypatch):
    monkeypatch.setattr(hlsl, "GLSLANG", "glslangValidator-not-installed")
    hlsl._CROSS_COMPILED.clear()
    with pytest.raises(PbrlabError, match="glslangValidator-not-installed not found on PATH.*setup.sh"):
        evaluate("x * 3.0", [], language="hlsl", x=1.0)
    monkeypatch.undo()
    monkeypatch.setattr(hlsl, "SPIRV_CROSS", "spirv-cross-not-installed")
    hlsl._CROSS_COMPILED.clear()
    with pytest.raises(PbrlabError, match="spirv-cross-not-installed not found"):
        evaluate("x * 5.0", [], language="hlsl", x=1.0)


def test_language_and_extension_arguments_are_checked():
    with pytest.raises(PbrlabError, match="language must be one of glsl, hlsl"):
        evaluate("x", [], language="msl", x=1.0)
    with pytest.raises(PbrlabError, match="extensions"):
        evaluate("x", [], language="hlsl", extensions=["GL_ARB_gpu_shader5"], x=1.0)


def test_programs_are_cached():
    hlsl._CROSS_COMPILED.clear()
    x = np.arange(4, dtype=np.float32)
    evaluate("x * 7.0", [], language="hlsl", x=x)
    builds = hlsl._CROSS_COMPILED.builds
    evaluate("x * 7.0", [], language="hlsl", x=x + 1)
    assert hlsl._CROSS_COMPILED.builds == builds  # no new glslang/spirv-cross run
