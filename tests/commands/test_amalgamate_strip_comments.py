"""`pbrlab amalgamate --strip-comments`: the amalgamated library without its comments is the
same program. glslang preprocesses the stripped and the full file to the same tokens (so the
compiler builds the same program, and every image is the same) for the defaults, each tier and
the unity model, in GLSL ES 3.00 and GLSL 330; the stripped file compiles; it keeps no comment
but the licence notice. The stripper's own cases (a comment inside a #define, quoted text, a
division) are checked on small inputs, with the naive regex as the control that fails them."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from pbrlab.commands import cli
from pbrlab.gpu.glsl_comments import strip_comments

ROOT = Path(__file__).resolve().parents[2]
ENTRY = ROOT / "examples" / "babylonjs" / "library_entry.glsl"   # pbr/pbr.glsl and the Unity-style surface API
NOTICE = "// SPDX-License-Identifier: MIT. Part of pbrlab"
CONFIGURATIONS = [{}, {"PBR_QUALITY": "PBR_QUALITY_LOW"}, {"PBR_QUALITY": "PBR_QUALITY_MEDIUM"},
                  {"PBR_BRDF_MODEL": "PBR_BRDF_MODEL_UNITY"}]
VERSIONS = ["#version 300 es\nprecision highp float;\n", "#version 330 core\n"]


def _amalgamate(tmp_path: Path, *flags: str) -> str:
    out = tmp_path / f"single{''.join(flags)}.glsl"
    assert cli.main(["amalgamate", str(ENTRY), *flags, "-o", str(out)]) == 0
    return out.read_text(encoding="utf-8")


def _glslang_tokens(source: str, path: Path) -> list[str]:
    path.write_text(source, encoding="utf-8")
    run = subprocess.run(["glslangValidator", "-E", str(path)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stdout + run.stderr
    return re.findall(r"[A-Za-z_]\w*|\d[\w.]*|\S", run.stdout)


@pytest.fixture(scope="module")
def amalgamations(tmp_path_factory):
    assert shutil.which("glslangValidator"), "glslangValidator is missing: bash scripts/setup.sh installs glslang-tools"
    tmp = tmp_path_factory.mktemp("amalgamate")
    return _amalgamate(tmp), _amalgamate(tmp, "--strip-comments")


@pytest.mark.parametrize("version", VERSIONS, ids=["es300", "glsl330"])
@pytest.mark.parametrize("defines", CONFIGURATIONS, ids=lambda d: ",".join(d.values()) or "defaults")
def test_the_stripped_library_preprocesses_to_the_same_tokens(amalgamations, defines, version, tmp_path):
    full, stripped = amalgamations
    head = version + "".join(f"#define {k} {v}\n" for k, v in defines.items())
    expected = _glslang_tokens(head + full, tmp_path / "full.frag")
    got = _glslang_tokens(head + stripped, tmp_path / "stripped.frag")
    assert len(expected) > 10000 and got == expected


def test_the_stripped_library_compiles_and_holds_only_the_notice(amalgamations, tmp_path):
    full, stripped = amalgamations
    shader = tmp_path / "check.frag"
    shader.write_text(VERSIONS[0] + stripped + "\nout vec4 c;\nvoid main() { c = vec4(pbr_D_GGX(0.5, 0.25)); }\n",
                      encoding="utf-8")
    run = subprocess.run(["glslangValidator", str(shader)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stdout + run.stderr
    code = re.sub(r'"[^"\n]*"', '""', stripped)   # quoted #error messages may hold anything
    commented = [line for line in code.splitlines() if "//" in line]
    assert stripped.startswith(NOTICE) and commented == [stripped.splitlines()[0]]
    assert "/*" not in code
    assert len(stripped) < 0.5 * len(full), (len(stripped), len(full))
    assert "\n\n\n" not in stripped


@pytest.mark.parametrize("source, expected", [
    ("float x; // note\n", "float x;\n"),
    ("// a whole-line comment\nfloat x;\n", "float x;\n"),
    ("#define X /* a\nb */ 1\nint y;\n", "#define X   1\nint y;\n"),        # one space, one logical line
    ("float a = b/*c*/+d;\n", "float a = b +d;\n"),
    ("float h = 1.0/2.0 / x;\n", "float h = 1.0/2.0 / x;\n"),
    ('#error "needs // this"\n', '#error "needs // this"\n'),
    ("int a;\n\n\n\nint b;\n", "int a;\n\nint b;\n"),
])
def test_strip_comments_cases(source, expected):
    assert strip_comments(source) == expected


def test_the_cases_fail_a_naive_stripper():
    """The control: a line-regex stripper gets the quoted and the multi-line cases wrong."""
    def naive(text: str) -> str:
        return re.sub(r"/\*.*?\*/", " ", re.sub(r"//.*", "", text))
    assert naive('#error "needs // this"\n') != strip_comments('#error "needs // this"\n')
    assert naive("#define X /* a\nb */ 1\nint y;\n") != strip_comments("#define X /* a\nb */ 1\nint y;\n")
