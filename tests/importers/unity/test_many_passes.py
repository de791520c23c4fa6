"""A shader of many passes, one CGINCLUDE before them all (Amplify Shader Editor's preview
shaders: Preview_SwizzleNode has 256 untagged passes, each its own ``frag``): the corpus runner
did not finish it in 40 minutes (docs/unity.md, session 43). Its cost grew with the square of
the passes: each pass's program is its file's text from the first CGINCLUDE on, and the
ShaderLab between (every earlier pass) was kept blanked character by character, so pass k
carried k earlier passes' worth of spaces and newlines into every scan of it; and a global
declaration's pattern (``^\\s*`` under re.M) ran over each run of empty lines once per line.
Now the text between keeps its newlines only (shaderlab.blank_gap: the lines of what follows
are the file's), the pattern starts at a line's own blanks (source_text.declared_globals), and
the corpus scene reads the shader once, not three times, before its render reads it.

What Unity draws: the built-in pipeline draws every untagged pass of the SubShader in order
on the object (ShaderLab: a SubShader's passes are rendered in the order they are written;
"Always" passes are drawn whatever the lights), each over the last at equal depth (ZTest
LEqual): the camera colour is the last pass's. pbrlab does the same (test below)."""

from __future__ import annotations

import re
import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers import unity
from pbrlab.importers.unity.source_text import CGINC, blank_comments, declared_globals, line_of, top_level

HEAD = textwrap.dedent("""\
    Shader "Test/ManyPasses"
    {
        SubShader
        {
            CGINCLUDE
            #include "UnityCG.cginc"
            #pragma vertex vert_img
            #pragma fragment frag
            float4 _Tint;
            ENDCG
    """)
# Each pass its own frag and colour (Amplify's swizzle previews: one swizzle a pass).
PASS = textwrap.dedent("""\
            Pass
            {
                Name "P{k}"
                CGPROGRAM
                float4 frag(v2f_img i) : SV_Target
                {
                    return float4({r}, 0.125, 0.25, 1.0);
                }
                ENDCG
            }
    """)


def _shader(tmp_path, reds, name="many.shader"):
    text = HEAD + "".join(textwrap.indent(PASS.replace("{k}", str(k)).replace("{r}", repr(r)), "    ") for k, r in enumerate(reds)) + "    }\n}\n"
    path = tmp_path / name
    path.write_text(text)
    return path, text


def test_a_later_pass_program_carries_no_earlier_pass(tmp_path):
    """Every pass's program has the same characters but newlines (the bodies are alike), however
    many passes come before it; its lines are still the file's (the frag of pass k is found at
    its line of the .shader). Before: pass k's program held the blanked text of the k before it,
    pass 39's 38 passes' worth more spaces than pass 0's."""
    path, text = _shader(tmp_path, [0.5] * 40)
    passes = unity.read_shader(path).passes
    assert len(passes) == 40
    sizes = {len(p.program) - p.program.count("\n") for p in passes}
    assert len(sizes) == 1, sorted(sizes)
    file_lines = [line_of(text, m.start()) for m in re.finditer(r"float4 frag\(", text)]
    for p, want in zip(passes, file_lines):
        at = p.program.index("float4 frag(")
        assert p.program_line - 1 + line_of(p.program, at) == want
        # (the column survives too: the text on the CGPROGRAM's line is blanked in place)
        assert p.program.splitlines()[line_of(p.program, at) - 1] == text.splitlines()[want - 1]


def test_an_error_in_a_late_pass_names_its_line_of_the_file(tmp_path):
    """Lines of the file survive the gap's squeeze: a missing frag in pass 30 is named at the
    line of the CGINCLUDE's #pragma fragment as before (control: pass 0's is the same line; the
    reader refuses the shader either way)."""
    for k in (0, 30):
        path, text = _shader(tmp_path, [0.5] * 31, name=f"broken{k}.shader")
        broken = text.splitlines(keepends=True)
        starts = [i for i, line in enumerate(broken) if "float4 frag(" in line]
        broken[starts[k]] = broken[starts[k]].replace("frag(", "frog(")
        path.write_text("".join(broken))
        want = f"{path}:{line_of(text, text.index('#pragma fragment frag'))}: #pragma fragment frag: no function frag"
        with pytest.raises(unity.UnityShaderError, match=re.escape(want)):
            unity.read_shader(path)


def test_the_corpus_scene_reads_a_shader_once(tmp_path, monkeypatch):
    """scene_for asks three questions of the shader (lightmap, realtime lightmap, full-screen
    pass): one read answers them all (before: three reads, each parsing every pass)."""
    path, _ = _shader(tmp_path, [0.5] * 3)
    reads = []
    real = unity.read_shader
    monkeypatch.setattr(unity, "read_shader", lambda *a, **k: reads.append(a) or real(*a, **k))
    scene = corpus.scene_for(path)
    assert len(reads) == 1
    assert "lightmap" not in scene["materials"]["m"] and "backdrop" not in scene["materials"]


# Declarations the pattern must find or skip: a run of empty lines (a function body top_level
# blanked), a declaration split over lines, an initialiser, a function (not a variable).
DECLARATIONS = ("uniform float4 _A;\n" + "\n" * 50 + "   static const float\n\n  _B = 2.0;\n"
                "float4 f(float x) { return x; }\n\t\n  sampler2D _C ;\nint\n_D;\n")
_OLD_PATTERN = (r"^\s*(?:uniform\s+)?(?:static\s+)?(?:const\s+)?\w+\s+([A-Za-z_]\w*)\s*(?:=[^;]*)?;")


def test_declared_globals_are_the_names_the_old_pattern_found():
    """declared_globals starts a match at a line's own blanks; the names are the ones the
    ``^\\s*`` pattern found (a match it began lines earlier begins again at its first word).
    Control: without re.M the old pattern finds only the first, so the comparison can tell."""
    masked = DECLARATIONS + blank_comments((CGINC / "UnityCG.cginc").read_text())
    old = frozenset(re.findall(_OLD_PATTERN, top_level(masked), re.M))
    assert {"_A", "_B", "_C", "_D"} <= declared_globals(masked) == old
    assert frozenset(re.findall(_OLD_PATTERN, top_level(masked))) != old


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_the_camera_colour_is_the_last_pass(tmp_path, language):
    """Five untagged passes, each an opaque colour: Unity's built-in pipeline draws them all in
    order at equal depth, so the sphere shows the last pass's colour, (0.375, 0.125, 0.25) exactly
    (short binary fractions; the corpus scene passes a program's colour as written). Control:
    the passes reversed show the first colour, 0.5, instead: the order, not one pass, decides."""
    reds = [0.5, 0.0625, 0.75, 0.875, 0.375]
    for order, want in ((reds, 0.375), (reds[::-1], 0.5)):
        path, _ = _shader(tmp_path, order, name=f"order{want}.shader")
        out = corpus.run_shader(path, language)
        assert out.status == "rendered", out.message
        covered = out.image[..., 3] == 1.0
        assert covered.mean() > 0.1
        assert np.array_equal(out.image[covered][:, :3], np.broadcast_to([want, 0.125, 0.25], (covered.sum(), 3)))
