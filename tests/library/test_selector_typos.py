"""A misspelt selector value is a compile error naming the selector, in GLSL and in the HLSL ports.

The preprocessor reads an undefined name as 0 in ``#if``; every selector family counts from 1,
so ``#define PBR_QUALITY PBR_QUALITY_HGH`` matches no value and the family's ``#error`` fires
(before, LOW was 0 and the typo silently gave the LOW tier). The families are found in the
library itself (``#ifndef X`` / ``// X_... as a number`` / ``#define X N``), so a new selector
is tested too.
"""

import re

import numpy as np
import pytest

from pbrlab import evaluate
from pbrlab.gpu import shaders
from pbrlab.foundation.errors import ShaderCompileError

# A default is written as its value's number under a comment naming the value (glsl/README.md,
# one-level preprocessors): "#ifndef X" / "// X_VALUE as a number ..." / "#define X 2".
_DEFAULT = re.compile(r"#\s*ifndef\s+(PBR_\w+)\s*\n//\s*\1_\w+ as a number[^\n]*\n\s*#\s*define\s+\1\s+\d+\s*\n")
UNITY_INCLUDE = "pbr/unity/surface_standard"  # the unity layer; the core umbrella does not include it


def _selectors() -> dict[str, str]:
    """selector -> the include (without suffix) that reads it; the core umbrella where it is enough."""
    found = {}
    for path in sorted((shaders.GLSL_ROOT / "pbr").rglob("*.glsl")):
        rel = path.relative_to(shaders.GLSL_ROOT).as_posix()
        for name in _DEFAULT.findall(path.read_text(encoding="utf-8")):
            unity = rel.startswith("pbr/unity/")
            if name not in found or not unity:
                found[name] = UNITY_INCLUDE if unity else "pbr/pbr"
    return found


SELECTORS = _selectors()


def test_every_known_selector_family_is_found():
    assert set(SELECTORS) >= {"PBR_QUALITY", "PBR_TONEMAP", "PBR_COLOR_TRANSFER", "PBR_SPECULAR_D",
                              "PBR_SPECULAR_V", "PBR_SPECULAR_F", "PBR_DIFFUSE", "PBR_BRDF_MODEL",
                              "PBR_UNITY_BRDF", "PBR_ALPHA_MODE"}


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("selector", sorted(SELECTORS))
def test_misspelt_selector_value_is_a_compile_error_naming_it(selector, language):
    include = f"{SELECTORS[selector]}.{language}"
    if selector in ("PBR_ALPHA_MODE", "PBR_UNITY_BRDF", "PBR_BRDF_MODEL"):
        include = f"{UNITY_INCLUDE}.{language}"  # read by the unity layer (and the dispatcher)
    typo = f"{selector}_TYPO"  # an undefined name, as a misspelling is
    with pytest.raises(ShaderCompileError) as error:
        evaluate("x", [include], defines={selector: typo}, language=language, x=np.zeros(1, np.float32))
    assert f"{selector}: unknown value" in str(error.value), str(error.value)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_same_shader_compiles_with_a_correct_value(language):
    """The positive control: the error above comes from the typo, not from the set-up."""
    got = evaluate("x", [f"pbr/pbr.{language}", f"{UNITY_INCLUDE}.{language}"], language=language, x=np.ones(1, np.float32),
                   defines={"PBR_QUALITY": "PBR_QUALITY_MEDIUM", "PBR_TONEMAP": "PBR_TONEMAP_HABLE",
                            "PBR_ALPHA_MODE": "PBR_ALPHA_MODE_FADE", "PBR_BRDF_MODEL": "PBR_BRDF_MODEL_UNITY"})
    assert got[0] == 1.0
