"""Property-based evaluator inputs: every value is either refused by name (PbrlabError
naming the input) or evaluated exactly as its float32 conversion, bit for bit; never a
traceback, never a silent rounding of an integer or an overflow to Inf. Also: the program
cache stays bounded over many distinct expressions, and broadcasts larger than one draw
are split and still correct."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hostile_common import FAST, assert_clean_refusal
from pbrlab.gpu import evaluator
from pbrlab.foundation.errors import PbrlabError

values = st.one_of(
    st.none(), st.booleans(), st.text(max_size=3),
    st.integers(min_value=-2 ** 80, max_value=2 ** 80),
    st.sampled_from([2 ** 24, 2 ** 24 + 1, -(2 ** 24) - 1, 2 ** 25, 2 ** 63 - 1, 3.5e38, -1e39, 1e-46]),
    st.floats(allow_nan=True, allow_infinity=True),
    st.builds(complex, st.floats(-1, 1), st.floats(-1, 1)),
    st.lists(st.floats(allow_nan=True, width=32), max_size=5),
    st.lists(st.lists(st.integers(-3, 3), min_size=1, max_size=3), min_size=1, max_size=3),  # ragged or not
    st.builds(np.array, st.lists(st.integers(-2 ** 40, 2 ** 40), min_size=1, max_size=4)),
    st.builds(lambda xs: np.array(xs, dtype=np.float64), st.lists(st.floats(), min_size=1, max_size=4)),
    st.builds(lambda xs: np.array(xs, dtype=np.float16), st.lists(st.floats(width=16), min_size=1, max_size=4)),
    st.builds(lambda xs: np.array(xs, dtype=object), st.lists(st.integers(0, 3), min_size=1, max_size=3)),
    st.just(object()), st.just(np.array(["a", "b"])), st.just(np.datetime64("2020-01-01")),
)


def _expected(value):
    """What an exact float32 evaluation of ``x`` must give, or None where a refusal is due."""
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError):
        return None
    if arr.dtype.kind not in "biuf":
        return None
    if arr.dtype.kind in "iu" and not all(int(np.float32(v)) == int(v) for v in arr.ravel().tolist()):
        return None
    if arr.dtype.kind == "f":
        wide = arr.astype(np.float64)
        if (np.isfinite(wide) & (np.abs(wide) > np.finfo(np.float32).max)).any():
            return None
    return arr.astype(np.float32)


@FAST
@given(value=values)
def test_an_evaluator_input_is_exact_in_float32_or_refused_by_name(value, census):
    expected = _expected(value)
    try:
        got = evaluator.evaluate("x", [], x=value)
    except Exception as exc:  # noqa: BLE001
        assert_clean_refusal(exc)
        assert "'x'" in str(exc) or "x " in str(exc), str(exc)
        assert expected is None, f"refused a value float32 holds exactly: {value!r}: {exc}"
        census["evaluator input", "refused cleanly"] += 1
    else:
        assert expected is not None, f"accepted {value!r} as {got!r}"
        assert got.shape == expected.shape
        assert got.view(np.uint32).tobytes() == expected.view(np.uint32).tobytes()
        census["evaluator input", "handled"] += 1


@pytest.mark.parametrize("value, message", [
    (None, "is None"),
    (2 ** 24 + 1, "no exact float32 value"),
    (np.int64(2 ** 24 + 1), "no exact float32 value"),
    (1e39, "beyond the float32"),
    (1 + 2j, "complex"),
    ([[1, 2], [3]], "not a rectangular array"),
])
def test_the_issue_evaluator_inputs_are_refused_by_name(value, message, census):
    with pytest.raises(PbrlabError, match=message):
        evaluator.evaluate("x", [], x=value)
    census["evaluator input", "refused cleanly"] += 1


def test_vector_inputs_pass_the_same_gate(census):
    with pytest.raises(PbrlabError, match="vec3.*no exact float32"):
        evaluator.vec3([2 ** 25 + 1, 0, 0])
    with pytest.raises(PbrlabError, match="do not broadcast"):
        evaluator.evaluate("x + y", [], x=np.zeros(3), y=np.zeros(4))
    census["evaluator input", "refused cleanly"] += 2


def test_the_program_cache_is_bounded_and_evicted_programs_rebuild(gl_context, monkeypatch, census):
    monkeypatch.setattr(evaluator, "PROGRAMS_CACHED", 6)
    ev = evaluator.Evaluator(gl_context)
    x = np.arange(5, dtype=np.float32)
    for k in range(12):
        np.testing.assert_array_equal(ev(f"x + {k}.0", [], x=x), x + k)
        assert len(ev._programs) <= 6
    np.testing.assert_array_equal(ev("x + 0.0", [], x=x), x)  # evicted long ago: rebuilt
    census["evaluator cache", "handled"] += 13


def test_a_broadcast_larger_than_one_draw_is_split_and_exact(gl_context, monkeypatch, census):
    monkeypatch.setattr(evaluator, "CHUNK", 1000)
    ev = evaluator.Evaluator(gl_context)
    x = np.linspace(-3, 3, 2501, dtype=np.float32)
    y = np.float32(0.5)
    got = ev("x * y + 1.0", [], x=x, y=y)
    assert got.shape == x.shape
    np.testing.assert_array_equal(got, x * y + np.float32(1.0))  # x * 0.5 is exact: FMA or not, one rounding
    vec = ev("vec3(x, x * 2.0, 0.0)", [], x=x)
    assert vec.shape == (2501, 3)
    np.testing.assert_array_equal(vec[:, 1], x * 2)
    census["evaluator batch", "handled"] += 2
