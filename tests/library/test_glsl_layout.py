"""The library's structure: every include is drop-in (guarded, self-sufficient, no
resources, documented header), the umbrella includes every file, public names are
prefixed, and constants shared with the Python reference are equal."""

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from library_helpers import evaluate
from pbrlab.gpu import shaders
from pbrlab.maths.reference import brdf, color, constants, guards, material, remap, shading, surface, tonemap

ROOT = shaders.GLSL_ROOT
FILES = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "pbr").rglob("*.glsl"))
UMBRELLA = "pbr/pbr.glsl"
# pbr/unity/ holds Unity's own names (SurfaceOutputStandard, LightingStandard, ...), by
# design unprefixed and outside the umbrella, so an engine that defines them skips it.
UNITY_LAYER = "pbr/unity/"


def header_of(text: str) -> str:
    """The leading comment block (everything before the first line of code)."""
    return re.split(r"^\s*#\s*ifndef", text, maxsplit=1, flags=re.M)[0]


def code_without_comments(text: str) -> str:
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


@pytest.mark.parametrize("path", FILES)
def test_include_is_guarded_and_documented(path):
    text = (ROOT / path).read_text(encoding="utf-8")
    guard = "PBR_" + re.sub(r"[^A-Za-z0-9]", "_", path[len("pbr/"):]).upper()
    if path == UMBRELLA:
        guard = "PBR_PBR_GLSL"
    code = code_without_comments(text).strip().splitlines()
    assert code[0].strip() == f"#ifndef {guard}", f"{path}: first code line must be #ifndef {guard}"
    assert code[1].strip() == f"#define {guard}"
    assert code[-1].strip() == "#endif"
    header = header_of(text)
    for field in ("Provides:", "Include:", "Config macros read:"):
        assert field in header, f"{path}: header lacks '{field}'"
    assert header.startswith(f"// {path}:"), f"{path}: header must start with its path"


@pytest.mark.parametrize("path", FILES)
def test_include_declares_no_resources(path):
    code = code_without_comments((ROOT / path).read_text(encoding="utf-8"))
    bad = re.findall(r"^\s*(?:layout\s*\(.*?\)\s*)?(uniform|varying|attribute|in|out|inout|buffer|sampler\w*)\s+\w+[^(\n]*;",
                     code, flags=re.M)
    assert not bad, f"{path}: declares {bad}"
    assert not re.search(r"\bsampler\w*\s+\w+\s*;", code)


@pytest.mark.parametrize("path", [f for f in FILES if not f.startswith(UNITY_LAYER)])
def test_public_names_are_prefixed(path):
    code = code_without_comments((ROOT / path).read_text(encoding="utf-8"))
    functions = re.findall(r"^\s*(?:float|vec[234]|int|bool|void|mat[234])\s+(\w+)\s*\(", code, flags=re.M)
    macros = re.findall(r"^\s*#\s*define\s+(\w+)", code, flags=re.M)
    assert all(f.startswith("pbr_") for f in functions), functions
    assert all(m.startswith("PBR_") for m in macros), macros


@pytest.mark.parametrize("path", FILES)
def test_every_selector_read_has_an_ifndef_default(path):
    code = code_without_comments((ROOT / path).read_text(encoding="utf-8"))
    read = set(re.findall(r"#\s*(?:el)?if\s+(PBR_\w+)\s*[=!]=", code))
    for macro in read:
        assert re.search(rf"#\s*ifndef\s+{macro}\b", code), f"{path}: {macro} has no #ifndef default"
        assert macro in header_of((ROOT / path).read_text()), f"{path}: header does not list {macro}"


def test_umbrella_includes_every_file():
    text = (ROOT / UMBRELLA).read_text(encoding="utf-8")
    included = set(re.findall(r'^\s*#\s*include\s+"([^"]+)"', text, flags=re.M))
    assert included == {f for f in FILES if not f.startswith(UNITY_LAYER)} - {UMBRELLA}


GLSLANG = shutil.which("glslangValidator")


def test_every_include_compiles_standalone(tmp_path):
    """Each file alone (with only the includes it names) compiles as a GLSL 330 fragment
    shader: it includes what it needs. Checked with glslang, independent of Mesa."""
    assert GLSLANG is not None, "glslangValidator is missing: scripts/setup.sh installs glslang-tools"
    failures = []
    for path in FILES:
        wrapper = f'#version 330 core\n#include "{path}"\nout vec4 o;\nvoid main() {{ o = vec4(0.0); }}\n'
        source = shaders.expand(wrapper, f"<standalone {path}>", line_directives=False).text
        shader = tmp_path / (re.sub(r"\W", "_", path) + ".frag")
        shader.write_text(source)
        run = subprocess.run([GLSLANG, str(shader)], capture_output=True, text=True)
        if run.returncode != 0:
            failures.append(f"{path}:\n{run.stdout}{run.stderr}")
    assert not failures, "\n".join(failures)


def test_every_include_compiles_standalone_on_the_gpu():
    for path in FILES:
        if path == UMBRELLA:
            continue
        assert evaluate("1.0", includes=(path,), x=0.0) == 1.0, path


SHARED_CONSTANTS = [
    ("PBR_PI", constants.PI), ("PBR_INV_PI", constants.INV_PI), ("PBR_TWO_PI", constants.TWO_PI),
    ("PBR_HALF_PI", constants.HALF_PI), ("PBR_LIGHT_UNIT_SCALE", constants.LIGHT_UNIT_SCALE),
    ("PBR_SRGB_DECODE_THRESHOLD", color.SRGB_DECODE_THRESHOLD),
    ("PBR_SRGB_ENCODE_THRESHOLD", color.SRGB_ENCODE_THRESHOLD),
    ("PBR_SRGB_LINEAR_SLOPE", color.SRGB_LINEAR_SLOPE), ("PBR_SRGB_OFFSET", color.SRGB_OFFSET),
    ("PBR_SRGB_EXPONENT", color.SRGB_EXPONENT), ("PBR_DISPLAY_GAMMA", color.DISPLAY_GAMMA),
    ("PBR_INV_DISPLAY_GAMMA", 1.0 / color.DISPLAY_GAMMA),  # written out: fl32 of the exact quotient
    ("PBR_CALLOFDUTY_LOG2_MAX_SPEC_POWER", remap.CALLOFDUTY_LOG2_MAX_SPEC_POWER),
    ("PBR_CRYTEK_GLOSS_SCALE", remap.CRYTEK_GLOSS_SCALE), ("PBR_DIELECTRIC_F0", material.DIELECTRIC_F0),
    ("PBR_BURLEY_FD90_BASE", brdf.BURLEY_FD90_BASE), ("PBR_F_SCHLICK_SG_A", brdf.F_SCHLICK_SG_A),
    ("PBR_F_SCHLICK_SG_B", brdf.F_SCHLICK_SG_B),
    ("PBR_F_SCHLICK_SG_MAX_ABS_ERROR", brdf.F_SCHLICK_SG_MAX_ABS_ERROR),
    ("PBR_V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR", brdf.V_SMITH_GGX_CORRELATED_FAST_MAX_REL_ERROR),
    ("PBR_MIN_PERCEPTUAL_ROUGHNESS", shading.MIN_PERCEPTUAL_ROUGHNESS),
    ("PBR_MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP", shading.MIN_PERCEPTUAL_ROUGHNESS_MEDIUMP),
    ("PBR_F90_FROM_F0_SCALE", brdf.F90_FROM_F0_SCALE),
    ("PBR_MIN_ONE_MINUS_REFLECTIVITY", surface.MIN_ONE_MINUS_REFLECTIVITY),
    ("PBR_ANISOTROPY_MIN_SIN", surface.ANISOTROPY_MIN_SIN),
    ("PBR_IRIDESCENCE_MAX_SCHLICK_WEIGHT", surface.IRIDESCENCE_MAX_SCHLICK_WEIGHT),
    ("PBR_DFG_LUT_WIDTH", surface.DFG_LUT_WIDTH), ("PBR_DFG_LUT_HEIGHT", surface.DFG_LUT_HEIGHT),
    # the table's axes, written out: fl32 of the exact (float64) values
    ("PBR_DFG_LUT_NDOTV_INV_SCALE", 1 / surface.DFG_LUT_C_NDOTV),
    ("PBR_DFG_LUT_NDOTV_LOG_NORM", 1 / np.log2(1 + 1 / surface.DFG_LUT_C_NDOTV)),
    ("PBR_DFG_LUT_ALPHA_OFFSET", surface.DFG_LUT_C_ALPHA),
    ("PBR_DFG_LUT_ALPHA_MIN_INV", 1 / (surface.DFG_LUT_ALPHA_MIN + surface.DFG_LUT_C_ALPHA)),
    ("PBR_DFG_LUT_ALPHA_LOG_NORM", 1 / np.log2((1 + surface.DFG_LUT_C_ALPHA)
                                               / (surface.DFG_LUT_ALPHA_MIN + surface.DFG_LUT_C_ALPHA))),
    *guards.SHARED.items(),
    ("PBR_HABLE_WHITE", tonemap.HABLE_WHITE),
    *[(f"PBR_HABLE_{k}", v) for k, v in tonemap.HABLE.items()],
    # the curve's constant products, written out: fl32 of the exact (float64) products
    ("PBR_HABLE_CB", tonemap.HABLE["C"] * tonemap.HABLE["B"]),
    ("PBR_HABLE_DE", tonemap.HABLE["D"] * tonemap.HABLE["E"]),
    ("PBR_HABLE_DF", tonemap.HABLE["D"] * tonemap.HABLE["F"]),
    ("PBR_HABLE_E_OVER_F", tonemap.HABLE["E"] / tonemap.HABLE["F"]),
    *[(f"PBR_ACES_NARKOWICZ_{k.upper()}", v) for k, v in tonemap.ACES_NARKOWICZ.items()],
    ("PBR_KHRONOS_NEUTRAL_F90", tonemap.KHRONOS_NEUTRAL_F90),
    ("PBR_KHRONOS_NEUTRAL_START_COMPRESSION", tonemap.KHRONOS_NEUTRAL_KS),
    ("PBR_KHRONOS_NEUTRAL_ONE_MINUS_START_COMPRESSION", 1 - tonemap.KHRONOS_NEUTRAL_KS),
    ("PBR_KHRONOS_NEUTRAL_DESATURATION", tonemap.KHRONOS_NEUTRAL_KD),
    *[(f"PBR_LUMINANCE_REC709", tuple(color.LUMINANCE_REC709))],
    *[(f"PBR_ACES_INPUT_ROW{i}", tuple(row)) for i, row in enumerate(tonemap.ACES_INPUT)],
    *[(f"PBR_ACES_OUTPUT_ROW{i}", tuple(row)) for i, row in enumerate(tonemap.ACES_OUTPUT)],
]


def test_constants_shared_with_the_reference_are_equal():
    """The GPU sees exactly the float32 rounding of each Python constant."""
    for macro, value in SHARED_CONSTANTS:
        got = evaluate(macro, x=0.0)
        expected = np.float32(value) if np.ndim(value) == 0 else np.asarray(value, np.float32)
        np.testing.assert_array_equal(got, expected, err_msg=macro)


def test_selector_values_match_the_reference_order():
    """Values count from 1: 0 is what the preprocessor reads for a misspelt (undefined) name."""
    for prefix, names in (("PBR_SPECULAR_D_", shading.SPECULAR_D), ("PBR_SPECULAR_V_", shading.SPECULAR_V),
                          ("PBR_SPECULAR_F_", shading.SPECULAR_F), ("PBR_DIFFUSE_", shading.DIFFUSE),
                          ("PBR_QUALITY_", shading.QUALITY), ("PBR_TONEMAP_", tonemap.TONEMAPS),
                          ("PBR_COLOR_TRANSFER_", color.TRANSFERS)):
        for index, name in enumerate(names):
            assert evaluate(f"{prefix}{name}", x=0.0) == index + 1, prefix + name
