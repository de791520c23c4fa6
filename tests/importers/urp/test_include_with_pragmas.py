"""``#include_with_pragmas`` inside an included file (issue 34's hidden6 sample, session 45:
Error-mdl's URP shader template, whose DefaultLitVariants.hlsl includes URP's Fog.hlsl and
ProbeVolumeVariants.hlsl so): Unity reads it as an #include whose file's #pragma lines count as
the pass's (Unity's manual, "Declaring and using shader keywords"). The pass's own text was
respelled before; the compilers read an included file as written, and glslang and GLSL know
only #include. URP's two keyword files have stand-ins: every fog and probe-volume keyword off.

Scene and readback as test_urp_library_round2.py; the fragment returns a constant, exact in
float32 (products of dyadic fractions): EXACT, 2 ulp of 1."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import source_text
from test_urp_library_round2 import LANGUAGES, render_constant, urp_pass  # pytest puts this folder on sys.path

EXACT = 2.5e-7
VARIANTS = """\
#define USE_DYNAMIC_BRANCH_FOG_KEYWORD 1
#include_with_pragmas "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Fog.hlsl"
  # include_with_pragmas "Packages/com.unity.render-pipelines.universal/ShaderLibrary/ProbeVolumeVariants.hlsl"
#include_with_pragmas "tint.hlsl"
#pragma multi_compile_fragment _ MY_UNUSED_KEYWORD
"""
TINT = "float3 my_tint(float3 c) { return c * float3(0.5, 0.25, 1.0); }\n"
BODY = "half fog = ComputeFogFactor(0.5); return float4(MixFog(my_tint(float3(0.5, 1.0, 0.375)), fog), 1);"


def _pass(folder):
    folder.mkdir()
    (folder / "variants.hlsl").write_text(VARIANTS)
    (folder / "tint.hlsl").write_text(TINT)
    return urp_pass("include with pragmas", BODY, '#include_with_pragmas "variants.hlsl"')


@pytest.mark.parametrize("language", LANGUAGES)
def test_include_with_pragmas_in_an_included_file(tmp_path, language, monkeypatch):
    """The included file's own includes are read (tint.hlsl's function, URP's keyword files);
    with the fog keywords off URP's MixFog leaves the colour (ShaderVariablesFunctions.hlsl:
    fog is mixed only under FOG_LINEAR, FOG_EXP or FOG_EXP2): (0.5, 1, 0.375) x (0.5, 0.25, 1).
    Control: the included files read as written, both languages are refused as before (glslang:
    "invalid directive: include_with_pragmas"; GLSL: "Illegal non-directive")."""
    rgba, _ = render_constant(tmp_path / "new", _pass(tmp_path / "new"), language, environment=False)
    expected = np.array([0.5, 1.0, 0.375]) * np.array([0.5, 0.25, 1.0])
    assert np.abs(rgba[:, :3] - expected).max() <= EXACT
    monkeypatch.setattr(source_text, "plain_includes", lambda text: text)
    with pytest.raises(PbrlabError, match="include_with_pragmas|non-directive"):
        render_constant(tmp_path / "old", _pass(tmp_path / "old"), language, environment=False)


def test_the_respelling_keeps_offsets_and_leaves_other_lines():
    """Columns and lines are kept (errors after it name the same place); a comment's mention
    and another directive stay."""
    text = '  #  include_with_pragmas "a.hlsl"\n// include_with_pragmas\n#include "b.hlsl"\n'
    spelled = source_text.plain_includes(text)
    assert len(spelled) == len(text) and spelled.count("\n") == text.count("\n")
    assert spelled.startswith('  #  include              "a.hlsl"') and spelled.endswith(text.split("\n", 1)[1])
