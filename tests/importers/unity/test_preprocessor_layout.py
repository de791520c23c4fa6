"""Where a Unity program's preprocessor lines sit, read as Unity's compiler reads them (session
44, from a seen sample): a ``#pragma multi_compile`` continued on the next line with a
backslash, ``#if`` lines between a signature and its body (a return type or a
``[maxvertexcount]`` chosen by a keyword), and a stage's ``#pragma`` in a file the
program includes.

Each pass is drawn on the corpus scene's sphere into its rgba32f target; a check reads the
colour at every pixel the sphere covers whole (alpha 1), where the fragment's constant shows.
Every colour is a short binary fraction, stored exactly in float32: the checks are equalities.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError

from corpus_sphere import covered_pixels, render_on_corpus_sphere

LANGUAGES = ("hlsl", "glsl")  # HLSL as written, then the GLSL port

PASS = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        CGPROGRAM
{pragmas}
        #include "UnityCG.cginc"
        struct v2f {{ float4 pos : SV_POSITION; }};
        v2f vert(appdata_base v) {{ v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }}
{code}
        ENDCG
    }} }}
}}
"""

RED, GREEN, BLUE = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]


def _shader(tmp_path, name, code, pragmas="        #pragma vertex vert\n        #pragma fragment frag"):
    path = tmp_path / f"{name}.shader"
    path.write_text(textwrap.dedent(PASS.format(name=name, pragmas=pragmas, code=code)))
    return path


def _colour(tmp_path, shader, language, keywords=None):
    """The one colour of the covered pixels (the fragments return constants)."""
    image = render_on_corpus_sphere(tmp_path, shader, language, keywords)
    got = image[covered_pixels(image)][:, :3].astype(np.float64)
    colours = np.unique(got, axis=0)
    assert len(colours) == 1, colours[:4]
    return colours[0].tolist()


TINTS = """        float4 frag(v2f i) : SV_Target {
            #if defined(_TINT_RED)
            return float4(1, 0, 0, 1);
            #elif defined(_TINT_GREEN)
            return float4(0, 1, 0, 1);
            #else
            return float4(0, 0, 1, 1);
            #endif
        }"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_keyword_set_continued_with_a_backslash_is_one_set(tmp_path, language):
    """The preprocessor splices a line ending in a backslash with the next (C99 5.1.1.2, phase
    2; HLSL's preprocessor is C's): ``#pragma multi_compile _TINT_RED \\`` + ``_TINT_GREEN`` is the
    set (_TINT_RED, _TINT_GREEN), with no "_": Unity draws its first keyword, red. Controls: the
    material enabling the second draws green (a keyword declared on the continued line); read
    line by line, the set was (_TINT_RED, "\\") and was not a set, so blue was drawn."""
    pragmas = ("        #pragma vertex vert\n        #pragma fragment frag\n"
               "        #pragma multi_compile _TINT_RED \\\n                              _TINT_GREEN")
    shader = _shader(tmp_path, "continued", TINTS, pragmas)
    assert _colour(tmp_path, shader, language) == RED
    assert _colour(tmp_path, shader, language, keywords=["_TINT_GREEN"]) == GREEN


SIGNATURE_BY_KEYWORD = """        struct two { float4 c : SV_Target; };
        #ifndef _PLAIN
        two frag(v2f i)
        #else
        half4 frag(v2f i) : SV_Target
        #endif
        {
            #ifndef _PLAIN
            two o; o.c = float4(0, 1, 0, 1); return o;
            #else
            return float4(1, 0, 0, 1);
            #endif
        }"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_signature_chosen_by_if_lines_is_read(tmp_path, language):
    """``two frag(v2f i) #else half4 frag(v2f i) : SV_Target #endif {`` (PSX-Enhanced-URP's
    fragment): the #if lines between the signature and its body are the preprocessor's, the
    drawn variant's signature is the one left. ``multi_compile _PLAIN _OTHER`` draws _PLAIN
    (its first keyword): the half4 signature, red. Control: enabling _OTHER draws the struct
    signature, green. Before, the #else line hid the body and the pass was refused."""
    pragmas = "        #pragma vertex vert\n        #pragma fragment frag\n        #pragma multi_compile _PLAIN _OTHER"
    shader = _shader(tmp_path, "signature", SIGNATURE_BY_KEYWORD, pragmas)
    assert _colour(tmp_path, shader, language) == RED
    assert _colour(tmp_path, shader, language, keywords=["_OTHER"]) == GREEN


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_stage_pragma_in_an_included_file_names_the_stage(tmp_path, language):
    """Unity's compiler reads #pragma lines in included files (its caching preprocessor, the
    only one from Unity 2021.2; manual, "HLSL pragma directives reference"): a pass with
    ``#pragma vertex vert`` whose ``#pragma fragment frag`` and frag() are in its own
    FragmentPart.cginc draws that frag, (0.25, 0.5, 0.75). Controls: the program's own
    ``#pragma fragment`` wins over the include's; with the include's pragma removed the pass
    is refused as before, naming the missing pragma."""
    part = "#pragma fragment frag\nfloat4 frag(v2f i) : SV_Target { return float4(0.25, 0.5, 0.75, 1); }\n" \
           "float4 other(v2f i) : SV_Target { return float4(0.5, 0.5, 0.5, 1); }\n"
    (tmp_path / "FragmentPart.cginc").write_text(part)
    include = '        #include "FragmentPart.cginc"'
    shader = _shader(tmp_path, "included", include, "        #pragma vertex vert")
    assert _colour(tmp_path, shader, language) == [0.25, 0.5, 0.75]
    own = _shader(tmp_path, "own", include, "        #pragma vertex vert\n        #pragma fragment other")
    assert _colour(tmp_path, own, language) == [0.5, 0.5, 0.5]
    (tmp_path / "FragmentPart.cginc").write_text(part.replace("#pragma fragment frag\n", ""))
    with pytest.raises(PbrlabError, match=r"needs #pragma vertex and #pragma fragment \(no #pragma fragment\)"):
        _colour(tmp_path, shader, language)


GEOMETRY_BY_KEYWORD = """        #ifdef _TWICE
        [maxvertexcount(6)]
        #else
        [maxvertexcount(3)]
        #endif
        void geom(triangle v2f p[3], inout TriangleStream<v2f> s) {
            s.Append(p[0]); s.Append(p[1]); s.Append(p[2]);
        }
        float4 frag(v2f i) : SV_Target { return float4(0.75, 0.25, 0.5, 1); }"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_maxvertexcount_chosen_by_if_lines_is_read(tmp_path, language):
    """``#ifdef _TWICE [maxvertexcount(6)] #else [maxvertexcount(3)] #endif void geom(...)``
    (PSX-Enhanced-URP's geometry function): the drawn variant's attribute is the one left, and
    the pass draws (0.75, 0.25, 0.5). Control: with the attribute removed altogether the pass
    is refused as HLSL requires, naming it."""
    pragmas = "        #pragma vertex vert\n        #pragma geometry geom\n        #pragma fragment frag"
    shader = _shader(tmp_path, "geometry", GEOMETRY_BY_KEYWORD, pragmas)
    assert _colour(tmp_path, shader, language) == [0.75, 0.25, 0.5]
    bare = GEOMETRY_BY_KEYWORD.replace("[maxvertexcount(6)]", "").replace("[maxvertexcount(3)]", "")
    with pytest.raises(PbrlabError, match=r"geom\(\) has no \[maxvertexcount\(N\)\] attribute"):
        _colour(tmp_path, _shader(tmp_path, "bare", bare, pragmas), language)
