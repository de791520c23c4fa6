"""HLSLSupport.cginc's ``UNITY_POSITION(pos)``: a struct's clip-space position member, Unity's
``float4 pos : SV_POSITION`` (its built-in shader source, HLSLSupport.cginc; the Standard
shader's VertexOutputForwardBase declares its position so). The fragment stage reads it as the
pixel's window position, as any SV_POSITION member."""

from __future__ import annotations

import numpy as np
import pytest

from test_pass_inputs import PASS, _render  # pytest puts this folder on sys.path

# The fragment's window x over the target's width: (column + 0.5) / width at the pixel centre.
X_OVER_WIDTH = "float4(i.pos.x / _ScreenParams.x, 0.0, 0.0, 1.0)"
# pos.x is the pixel centre exactly (a half-integer, exact in float32) and _ScreenParams.x the
# width (an integer): the float32 quotient is within half an ulp of the float64 one (< 2^-24
# relative, the division correctly rounded).
BOUND = 2.0 ** -24


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_unity_position_is_the_sv_position_member(tmp_path, language, monkeypatch):
    import test_pass_inputs
    macro = PASS.replace("struct v2f {{ float4 pos : SV_POSITION; }};", "struct v2f {{ UNITY_POSITION(pos); }};")
    assert macro != PASS
    monkeypatch.setattr(test_pass_inputs, "PASS", macro)
    image = np.asarray(_render(tmp_path, language, "unity_position", X_OVER_WIDTH), np.float64)
    covered = image[..., 3] > 0
    assert covered.mean() > 0.3
    width = image.shape[1]
    expected = (np.arange(width) + 0.5) / width
    rows, cols = np.nonzero(covered)
    error = np.abs(image[rows, cols, 0] - expected[cols]) / expected[cols]
    assert (error <= BOUND).all(), error.max()
    # control: the member without its semantic is no position (the reader's refusal)
    monkeypatch.setattr(test_pass_inputs, "PASS", PASS.replace(": SV_POSITION;", ";"))
    from pbrlab.foundation.errors import PbrlabError
    with pytest.raises(PbrlabError, match="writes no SV_POSITION"):
        _render(tmp_path, language, "no_semantic", X_OVER_WIDTH)
