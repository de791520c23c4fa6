"""The GPU function evaluator: bit-exact transport, broadcasting, types, errors."""

import numpy as np
import pytest

from pbrlab import evaluate, vec2, vec3, vec4
from pbrlab.foundation.errors import PbrlabError, ShaderCompileError

F32 = np.finfo(np.float32)
SPECIAL_FLOATS = np.array([
    0.0, -0.0, F32.smallest_subnormal, -F32.smallest_subnormal, 1e-40, F32.tiny,
    1.0 + F32.eps, 1.0 - F32.epsneg, 65504.0, 1e30, F32.max, np.inf, -np.inf, np.nan,
], np.float32)


def test_special_floats_round_trip_bit_exactly():
    out = evaluate("x", includes=[], x=SPECIAL_FLOATS)
    assert out.dtype == np.float32
    np.testing.assert_array_equal(out.view(np.uint32), SPECIAL_FLOATS.view(np.uint32))


def test_vec4_components_round_trip_bit_exactly():
    data = np.stack([SPECIAL_FLOATS, SPECIAL_FLOATS[::-1], -SPECIAL_FLOATS, SPECIAL_FLOATS], axis=-1)
    out = evaluate("v", includes=[], v=vec4(data))
    np.testing.assert_array_equal(out.view(np.uint32), data.view(np.uint32))


def test_broadcasting_follows_numpy():
    a = np.arange(3, dtype=np.float32)[:, None]
    b = np.arange(4, dtype=np.float32)[None, :]
    out = evaluate("a * 10.0 + b", includes=[], a=a, b=b)
    np.testing.assert_array_equal(out, a * 10 + b)


def test_vector_result_gets_a_trailing_axis():
    out = evaluate("c * s", includes=[], c=vec3([1.0, 2.0, 3.0]), s=np.array([1.0, 2.0]))
    assert out.shape == (2, 3)
    np.testing.assert_array_equal(out, [[1, 2, 3], [2, 4, 6]])


def test_vec2_input_and_int_and_bool_results():
    xy = vec2(np.array([[1.0, 2.0], [3.0, -4.0]]))
    np.testing.assert_array_equal(evaluate("dot(p, p)", includes=[], p=xy), [5.0, 25.0])
    np.testing.assert_array_equal(evaluate("int(p.x) * 2", includes=[], p=xy), [2.0, 6.0])
    np.testing.assert_array_equal(evaluate("p.y > 0.0", includes=[], p=xy), [1.0, 0.0])


def test_many_samples_keep_their_order():
    x = np.arange(1_000_003, dtype=np.float32)  # not a multiple of the texture width
    np.testing.assert_array_equal(evaluate("x + 1.0", includes=[], x=x), x + 1)


def test_defines_reach_the_shader():
    assert evaluate("float(SCALE) * x", includes=[], defines={"SCALE": 3}, x=2.0) == 6.0


def test_library_function_through_default_umbrella_include():
    assert float(evaluate("PBR_PI", x=0.0)) == pytest.approx(np.pi, rel=1e-7)


def test_compile_error_is_reported_not_swallowed():
    with pytest.raises(ShaderCompileError, match="no_such_function"):
        evaluate("no_such_function(x)", includes=[], x=1.0)


def test_bad_input_name_and_vector_shape_are_clear_errors():
    with pytest.raises(PbrlabError, match="not usable as a GLSL identifier"):
        evaluate("x", includes=[], **{"gl_Position": 1.0})
    with pytest.raises(PbrlabError, match="vec3 input needs a last axis of length 3"):
        vec3(np.zeros((4, 2)))


def test_cli_eval_prints_a_table(capsys):
    from pbrlab.commands import cli

    assert cli.main(["eval", "x * y", "--var", "x=0:1:3", "--var", "y=2,4"]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert lines[0].split() == ["x", "y", "x", "*", "y"]
    rows = [list(map(float, line.split())) for line in lines[1:]]
    assert rows == [[0, 2, 0], [0, 4, 0], [0.5, 2, 1], [0.5, 4, 2], [1, 2, 2], [1, 4, 4]]


def test_cli_eval_bad_var_is_a_clear_error(capsys):
    from pbrlab.commands import cli

    assert cli.main(["eval", "x", "--var", "x=zero:1:3"]) == 2
    assert "expected NAME=start:stop:count" in capsys.readouterr().err


def test_cli_eval_reads_your_own_include_directory(tmp_path, capsys):
    """`pbrlab eval -I DIR --include my/f.glsl`: a user's file beside the library (as
    amalgamate's -I), and a directory that does not exist is one clear line."""
    from pbrlab.commands import cli

    (tmp_path / "my").mkdir()
    (tmp_path / "my" / "f.glsl").write_text("float my_twice(float x) { return 2.0 * x; }\n")
    assert cli.main(["eval", "my_twice(x)", "-I", str(tmp_path), "--include", "my/f.glsl",
                     "--var", "x=1,3"]) == 0
    rows = [list(map(float, line.split())) for line in capsys.readouterr().out.strip().splitlines()[1:]]
    assert rows == [[1, 2], [3, 6]]
    assert cli.main(["eval", "x", "-I", str(tmp_path / "nowhere"), "--var", "x=1"]) == 2
    assert "-I " in capsys.readouterr().err
