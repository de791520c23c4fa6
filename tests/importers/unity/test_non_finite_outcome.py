"""A corpus outcome of ``non-finite`` says which pixels: how many of the image's are NaN or
infinite and the rows and columns they span (before, its message was empty, and a report could
not tell a shader's own 0/0 over the whole object from one stray pixel)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from colour_pass import colour_pass

from pbrlab.checking import unity_corpus as corpus


def _shader(tmp_path, returned: str):
    (tmp_path / "nothing.cginc").write_text("\n")
    path = tmp_path / "nan.shader"
    path.write_text(colour_pass("NonFinite", "nothing.cginc", returned))
    return path


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_non_finite_render_names_its_pixels(tmp_path, language):
    # sqrt of a negative colour channel: NaN wherever the object covers a pixel (IEEE 754)
    outcome = corpus.run_shader(_shader(tmp_path, "sqrt(_Color - 1.0)"), language)
    assert outcome.status == "non-finite", outcome.message
    bad = ~np.isfinite(outcome.image).all(axis=-1)
    rows, cols = np.nonzero(bad)
    m = re.fullmatch(r"(\d+) of (\d+) pixels are NaN or infinite \(rows (\d+)\.\.(\d+), "
                     r"columns (\d+)\.\.(\d+)\)", outcome.message)
    assert m, outcome.message
    assert [int(g) for g in m.groups()] == [int(bad.sum()), bad.size, rows.min(), rows.max(),
                                            cols.min(), cols.max()]
    # control: the finite twin is rendered, with no message
    finite = corpus.run_shader(_shader(tmp_path, "sqrt(_Color)"), language)
    assert finite.status == "rendered" and finite.message == ""
