"""The shipped library survives engines' own shader preprocessors (issue 36).

Babylon.js evaluates a shader's conditionals itself before WebGL sees it
(@babylonjs/core Engines/Processors/shaderProcessor.js): it takes any line holding `#if`,
`#else`, `#endif`, ... as that directive, comments included; it splits code lines at `;`
before it reads comments; it records `#define NAME VALUE` only when the line is exactly
those three words; and it resolves a name one level deep (`#if A == B` reads the values of A
and B, not the values of their values; `#if A` means `defined(A)`); a directive written with
blanks after its `#` (`#  if`) it does not recognise and leaves to the driver. The library is
written so that this preprocessor picks exactly the branches a real one picks:

* no comment holds a preprocessor directive word, and no trailing comment holds a `;`
  (checked here on the text, with controls);
* Babylon.js's own preprocessor (tools/babylonjs/preprocess.mjs, the pinned package) and
  glslang's, run on the amalgamated library, give the same token stream, for the defaults
  and for every tier and BRDF model set by number (a selector set by its *name*, which
  Babylon.js cannot resolve, is the control that shows the comparison can fail).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from pbrlab.gpu import shaders

ROOT = Path(__file__).resolve().parents[2]
GLSL = shaders.GLSL_ROOT
FILES = sorted(GLSL.rglob("*.glsl"))
TOOL = ROOT / "tools" / "babylonjs"
TIMEOUT_S = 60

DIRECTIVE_WORD = re.compile(r"#\s*(?:if|ifdef|ifndef|elif|else|endif|define|undef|error|include|pragma|extension|"
                            r"version|line)\b")
# Every file of the library, in an order that compiles as one shader (unity_compat's
# variables before the unity layer that reads them).
EVERY_FILE_ENTRY = "\n".join(
    [f'#include "unity_compat/{p.name}"' for p in sorted((GLSL / "unity_compat").glob("*.glsl"))]
    + ['#include "pbr/pbr.glsl"']
    + [f'#include "pbr/unity/{p.name}"' for p in sorted((GLSL / "pbr" / "unity").glob("*.glsl"))]) + "\n"
# Configurations as a Babylon.js user passes them (ShaderMaterial's `defines`): numbers.
# PBR_QUALITY 1 LOW, 2 HIGH, 3 MEDIUM; PBR_BRDF_MODEL 1 pbrlab, 2 unity.
CONFIGURATIONS = [
    {},
    {"PBR_QUALITY": "1"},
    {"PBR_QUALITY": "3"},
    {"PBR_BRDF_MODEL": "2"},
    {"PBR_BRDF_MODEL": "2", "PBR_QUALITY": "1"},
    {"PBR_BRDF_MODEL": "2", "PBR_QUALITY": "3"},
    {"PBR_SPECULAR_D": "2", "PBR_SPECULAR_V": "5", "PBR_DIFFUSE": "2", "PBR_TONEMAP": "4"},
    {"PBR_ENERGY_COMPENSATION": "1", "PBR_COLOR_TRANSFER": "2"},
]


def comments(text: str) -> list[tuple[int, str]]:
    """(line number, text) of every `//` and `/* */` comment; GLSL has no string literals
    outside `#error` lines, whose quoted message is skipped."""
    found, line, i, n = [], 1, 0, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
        elif c == '"':
            end = text.find('"', i + 1)
            end = n if end < 0 else end
            line += text.count("\n", i, end)
            i = end
        elif text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            found.append((line, text[i + 2:end]))
            i = end
            continue
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end
            found.append((line, text[i + 2:end]))
            line += text.count("\n", i, end)
            i = end + 1
        i += 1
    return found


def directive_words_in_comments(text: str) -> list[str]:
    return [f"line {line}: {DIRECTIVE_WORD.search(body).group(0)}" for line, body in comments(text)
            if DIRECTIVE_WORD.search(body)]


def semicolons_in_trailing_comments(text: str) -> list[int]:
    """Lines of code (not directives, not whole-line comments) whose trailing `//` comment
    holds a `;`: Babylon.js's ShaderCodeCursor splits such a line there, leaving the rest of
    the comment as code."""
    bad = []
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if stripped.startswith(("#", "//")) or "//" not in line:
            continue
        if ";" in line.split("//", 1)[1]:
            bad.append(number)
    return bad


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.relative_to(GLSL).as_posix())
def test_no_comment_holds_a_directive_word_or_a_trailing_semicolon(path):
    text = path.read_text(encoding="utf-8")
    assert not directive_words_in_comments(text), f"{path}: {directive_words_in_comments(text)}"
    assert not semicolons_in_trailing_comments(text), f"{path}: lines {semicolons_in_trailing_comments(text)}"


def test_the_comment_checks_catch_what_babylon_misreads():
    """Controls: the forms the library had before issue 36 are caught; directives, their
    own messages and comment-free code are not."""
    assert directive_words_in_comments("// holds the only #if chain\nfloat x;\n") == ["line 1: #if"]
    assert directive_words_in_comments("float x; /* the #else branch */\n") == ["line 1: #else"]
    assert directive_words_in_comments("#ifndef A\n#  define A 1\n#endif\n") == []
    assert directive_words_in_comments('#error "needs #extension X : require"\n') == []
    assert semicolons_in_trailing_comments("    vec3 color;  // linear; 0: none\n") == [1]
    assert semicolons_in_trailing_comments("    vec3 color;  // linear, 0: none\n// a; b\n") == []


def _setup_problems() -> list[str]:
    problems = []
    if shutil.which("node") is None:
        problems.append("node is not on PATH")
    if shutil.which("glslangValidator") is None:
        problems.append("glslangValidator is missing")
    if not (TOOL / "node_modules" / "@babylonjs" / "core" / "package.json").is_file():
        problems.append(f"npm package @babylonjs/core is not installed in {TOOL}")
    return problems


def _glslang_tokens(source: str, path: Path) -> list[str] | str:
    """glslang's preprocessing of a GLSL ES 3.00 fragment shader, as tokens; a string (the
    error) where glslang rejects it (an #error, an unbalanced conditional)."""
    path.write_text(source, encoding="utf-8")
    run = subprocess.run(["glslangValidator", "-E", str(path)], capture_output=True, text=True, timeout=TIMEOUT_S)
    if run.returncode != 0:
        return (run.stdout + run.stderr).strip()
    return re.findall(r"[A-Za-z_]\w*|\d[\w.]*|\S", run.stdout)


def babylon_matches_glslang(library: str, defines: dict[str, str], tmp: Path) -> tuple[bool, str, list[str]]:
    """Babylon.js's preprocessor then glslang's, against glslang's alone, on the same
    source and defines (placed before the source, as Babylon.js's Effect does): (same?, what
    differs, glslang's tokens)."""
    define_lines = "".join(f"#define {k} {v}\n" for k, v in defines.items())
    (tmp / "in.glsl").write_text(library, encoding="utf-8")
    node = subprocess.run(["node", str(TOOL / "preprocess.mjs"), str(tmp / "in.glsl"), str(tmp / "out.glsl"),
                           *(f"{k}={v}" for k, v in defines.items())],
                          capture_output=True, text=True, timeout=TIMEOUT_S)
    assert node.returncode == 0, node.stderr
    babylon = (tmp / "out.glsl").read_text(encoding="utf-8")
    expected = _glslang_tokens(f"#version 300 es\n{define_lines}precision highp float;\n{library}", tmp / "a.frag")
    assert not isinstance(expected, str), f"glslang rejects the library itself: {expected}"
    got = _glslang_tokens(f"#version 300 es\n{define_lines}{babylon}", tmp / "b.frag")
    if isinstance(got, str):
        return False, f"glslang rejects what Babylon.js made of it: {got[:400]}", expected
    if got == expected:
        return True, f"{len(got)} tokens alike", expected
    first = next((i for i, (a, b) in enumerate(zip(got, expected)) if a != b), min(len(got), len(expected)))
    return False, (f"{len(got)} tokens against {len(expected)}; first difference at token {first}: "
                   f"{' '.join(got[first:first + 12])!r} against {' '.join(expected[first:first + 12])!r}"), expected


@pytest.fixture(scope="module")
def every_file_amalgamated(tmp_path_factory):
    problems = _setup_problems()
    assert not problems, "; ".join(problems) + " (bash scripts/setup.sh installs them)"
    entry = tmp_path_factory.mktemp("entry") / "every_file.glsl"
    entry.write_text(EVERY_FILE_ENTRY, encoding="utf-8")
    return shaders.expand_file(entry, [], line_directives=False).text


@pytest.mark.parametrize("defines", CONFIGURATIONS, ids=lambda d: ",".join(f"{k}={v}" for k, v in d.items()) or "defaults")
def test_babylons_preprocessor_keeps_the_branches_glslang_keeps(every_file_amalgamated, defines, tmp_path):
    ok, detail, _ = babylon_matches_glslang(every_file_amalgamated, defines, tmp_path)
    assert ok, f"{defines or 'defaults'}: {detail}"


def test_the_comparison_fails_where_babylon_cannot_resolve(every_file_amalgamated, tmp_path):
    """Controls: a selector set by its name (two macro levels, which Babylon.js does not
    follow), and the library as it was before issue 36 (a directive word in a comment)."""
    ok, detail, _ = babylon_matches_glslang(every_file_amalgamated, {"PBR_QUALITY": "PBR_QUALITY_LOW"}, tmp_path)
    assert not ok, detail
    commented = every_file_amalgamated.replace("#define PBR_QUALITY_LOW 1\n",
                                               "// the only #if chain\n#define PBR_QUALITY_LOW 1\n", 1)
    assert commented != every_file_amalgamated
    ok, detail, _ = babylon_matches_glslang(commented, {}, tmp_path)
    assert not ok, detail


def test_babylon_sees_the_hooks_as_object_like_macros(every_file_amalgamated, tmp_path):
    """The table hooks defined above the library as examples/babylonjs does (a macro naming a
    function) reach the library's table branch in Babylon.js as in glslang; the function-like
    form, which Babylon.js's define table does not record, is the control that differs (the
    sheen hook's: the DFG hook is tested under a `#  if`, with blanks after the `#`, which
    Babylon.js leaves to the driver's preprocessor)."""
    hooks = "#define PBR_DFG_LUT_LOOKUP example_dfg_lookup\n#define PBR_SHEEN_LUT_LOOKUP example_sheen_lookup\n"
    ok, detail, tokens = babylon_matches_glslang(hooks + every_file_amalgamated, {}, tmp_path)
    assert ok, detail
    assert "example_dfg_lookup" in tokens and "example_sheen_lookup" in tokens  # the hooks are read
    function_like = "#define PBR_SHEEN_LUT_LOOKUP(NdotV, r) example_sheen_lookup(NdotV, r)\n"
    ok, detail, _ = babylon_matches_glslang(function_like + every_file_amalgamated, {}, tmp_path)
    assert not ok, detail


def test_defaults_written_as_numbers_name_their_value():
    """A selector's default is written as its number (one-level preprocessors) under a
    comment naming the value; the number is that name's."""
    values = {}
    for path in FILES:
        for name, value in re.findall(r"^#define (PBR_\w+) (\d+)$", path.read_text(encoding="utf-8"), re.M):
            values.setdefault(name, value)
    checked = 0
    for path in FILES:
        for name, selector, number in re.findall(
                r"^// (PBR_\w+) as a number \(glsl/README\.md, one-level preprocessors\)\n#define (PBR_\w+) (\d+)$",
                path.read_text(encoding="utf-8"), re.M):
            assert values.get(name) == number, f"{path}: {selector} {number} is not {name} ({values.get(name)})"
            assert name.startswith(selector), f"{path}: {name} is not a value of {selector}"
            checked += 1
    assert checked >= 20, checked  # the library's 22 defaults
