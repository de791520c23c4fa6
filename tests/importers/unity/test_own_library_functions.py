"""A function of UnityCG.cginc that a shader's own include file defines again
(own_library_functions.py): FXC takes ``float Luminance(in float3 c)`` beside Unity's
``half Luminance(half3)`` as an overload and gives the shader's float3 calls the shader's
function; glslang refused the pair ("function already has a body", 25 of 234 shaders of an
unseen built-in sample: one project's shared Tools.cginc) and the GLSL port called Unity's."""

from __future__ import annotations

import numpy as np
import pytest

from colour_pass import colour_pass

from pbrlab.checking import unity_corpus as corpus

SHADER = colour_pass("OwnLuminance", "Tools.cginc", "fixed4(Luminance(_Color.rgb).xxx, 1)")
# the project's own Luminance: its green channel (not Unity's weighted sum)
TOOLS = "float Luminance(in float3 c)\n{\n    return c.g;\n}\n"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_the_shaders_own_definition_is_the_one_its_calls_reach(tmp_path, language):
    (tmp_path / "own.shader").write_text(SHADER)
    (tmp_path / "Tools.cginc").write_text(TOOLS)
    out = corpus.run_shader(tmp_path / "own.shader", language)
    assert out.status == "rendered", out.message
    covered = out.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    # _Color.g = 0.25 on every covered pixel (exact); Unity's Luminance would give
    # 0.75 * 0.2126 + 0.25 * 0.7152 + 0.5 * 0.0722 = 0.3743 (the control below)
    assert np.array_equal(out.image[covered][:, :3], np.full((covered.sum(), 3), 0.25, np.float32))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_without_its_own_definition_the_call_reaches_unitys(tmp_path, language):
    (tmp_path / "own.shader").write_text(SHADER)
    (tmp_path / "Tools.cginc").write_text("// nothing\n")
    out = corpus.run_shader(tmp_path / "own.shader", language)
    assert out.status == "rendered", out.message
    covered = out.image[..., 3] == 1.0
    value = out.image[covered][:, 0]
    assert np.all(np.abs(value - 0.25) > 0.05)
