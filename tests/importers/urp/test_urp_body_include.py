"""An #include inside a function body (issue 34): HLSL's preprocessor pastes the file's
statements there, so its declarations are the function's locals, read with the function's own
locals and parameters. Both languages: the GLSL port splices the file into the function for its
type pass and includes its port at the line (body_includes.py), so an error in it still names
the included file and line.

Scene: test_urp_library_round2's unit sphere; the pass returns a constant, checked at every
covered pixel.
"""

from __future__ import annotations

import pytest

from pbrlab.foundation.errors import PbrlabError
from test_urp_library_round2 import LANGUAGES, render_constant, urp_pass  # pytest puts this folder on sys.path

# The included file: statements that read the function's local `k` and parameter `IN`, and
# declare `shade`, which the function reads after the include.
STATEMENTS = """\
// statements, not declarations: included inside frag()
float3 shade = float3(0.2, 0.4, 0.6) * k;
shade.z += 0.0 * IN.positionCS.x;
"""
BODY = """float k = 0.5;
                #include "statements.hlsl"
                return float4(shade, 1.0);"""
# float32 holds 0.2 * 0.5 etc. within 2^-24 relative; the 8-bit-free linear target adds
# nothing: one float32 ulp of a value below 1, times 4 for the two products and the store.
BOUND = 4 * 2.0 ** -24


@pytest.mark.parametrize("language", LANGUAGES)
def test_include_in_a_function_body_is_statements(tmp_path, language):
    (tmp_path / "statements.hlsl").write_text(STATEMENTS)
    pixels, _ = render_constant(tmp_path, urp_pass("body include", BODY), language, environment=False)
    expected = [0.2 * 0.5, 0.4 * 0.5, 0.6 * 0.5]  # float64
    assert abs(pixels[:, :3] - expected).max() <= BOUND
    # control: the function's local read by the included file is the one the image follows
    pixels, _ = render_constant(tmp_path, urp_pass("body include", BODY.replace("0.5;", "0.25;", 1)), language,
                                environment=False)
    assert abs(pixels[:, 0] - 0.2 * 0.5).min() > 0.04


@pytest.mark.parametrize("language", LANGUAGES)
def test_an_error_in_a_body_include_names_its_file_and_line(tmp_path, language):
    (tmp_path / "statements.hlsl").write_text(STATEMENTS.replace("* k;", "* k_misspelled;"))
    with pytest.raises(PbrlabError, match=r"statements\.hlsl[:(]2\b"):
        render_constant(tmp_path, urp_pass("body include", BODY), language, environment=False)
