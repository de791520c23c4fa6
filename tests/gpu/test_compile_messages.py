"""A compile failure's text: the first error first, each later error on an already reported
line (a follow-on of the cascade) after it, indented, none dropped (compile_messages.py).
The compiler's own text comes from a real compile (Mesa's cascade after an undeclared name)."""

from __future__ import annotations

import pytest

from pbrlab.foundation.errors import ShaderCompileError
from pbrlab.gpu.compile_messages import compile_failure

from gl_helpers import fullscreen_program

CASCADE = """\
u.glsl:5:52: error: `undefined_thing' undeclared
u.glsl:6:49: error: `y' undeclared
u.glsl:6:9: error: operands to arithmetic operators must be numeric
u.glsl:6:2: error: `return' with wrong type error, in function `my_rim' returning float
u.glsl:2:1: warning: extension `GL_X' unsupported"""


def test_first_errors_lead_and_follow_ons_come_after_indented():
    lines = compile_failure("fragment shader failed to compile", CASCADE).splitlines()
    assert lines[:2] == ["u.glsl:5:52: error: `undefined_thing' undeclared", "u.glsl:6:49: error: `y' undeclared"]
    assert lines[2] == "(fragment shader failed to compile; 3 more lines: follow-ons on the lines above, and warnings)"
    assert lines[3:] == ["  " + line for line in CASCADE.splitlines()[2:]]


def test_nothing_is_reordered_when_every_error_has_its_own_line():
    """Control: distinct lines are all first messages, in the compiler's order, none indented."""
    text = "a.glsl:3:1: error: x\nb.glsl:3:1: error: y\na.glsl:4: error: z"
    assert compile_failure("failed", text).splitlines() == text.splitlines() + ["(failed)"]


def test_unplaced_lines_stay_with_the_message_they_follow():
    text = "a.glsl:3:1: error: x\n  note: x was declared here\nerror: linking failed"
    assert compile_failure("failed", text).splitlines()[:3] == text.splitlines()


def test_a_real_cascade_leads_with_its_first_error(gl_context, tmp_path):
    (tmp_path / "rim.glsl").write_text("float my_rim(float NdotV) {\n"
                                       "    float x = undefined_thing;\n"
                                       "    return pow(1.0 - NdotV, 3.0) + y;\n}\n")
    source = ('#version 330 core\n#include "rim.glsl"\nout vec4 c;\n'
              'void main() { c = vec4(my_rim(0.5)); }\n')
    with pytest.raises(ShaderCompileError) as err:
        fullscreen_program(gl_context, source, "entry.frag", include_dirs=[tmp_path])
    lines = str(err.value).splitlines()
    assert lines[0].startswith(f"{tmp_path / 'rim.glsl'}:2:") and "undefined_thing" in lines[0], lines
    assert lines[1].startswith(f"{tmp_path / 'rim.glsl'}:3:") and "`y'" in lines[1], lines
    assert lines[2].startswith("(fragment shader failed to compile; "), lines
    assert lines[3:] and all(line.startswith(f"  {tmp_path / 'rim.glsl'}:3:") for line in lines[3:]), lines
