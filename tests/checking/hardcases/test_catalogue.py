"""Issue 5: the hard-case catalogue and the randomised sweeps, for every public function and
every tier and variant of the shading model, through the GPU evaluator (pbrlab.checking.hardcases).

Failure messages list the function, case, value and expected bound (as `pbrlab hardcases`).
"""

import re

import numpy as np
import pytest

from pbrlab.gpu import shaders
from pbrlab.commands.cli import main as cli_main
from pbrlab.checking.hardcases import catalogue, domains, run

FUNCTIONS = catalogue.functions()
# Folders and files of other issues (the surface API, IBL, light attenuation, SH lighting),
# catalogued with their own issue; every other public function must be in the catalogue.
OTHER_ISSUES = ("pbr/ibl/", "pbr/surface/", "pbr/unity/", "pbr/lighting/attenuation.glsl", "pbr/lighting/sh9.glsl")


def test_catalogue_covers_every_public_function():
    defined = set()
    for path in (shaders.GLSL_ROOT / "pbr").rglob("*.glsl"):
        rel = path.relative_to(shaders.GLSL_ROOT).as_posix()
        if not rel.startswith(OTHER_ISSUES):
            defined |= set(re.findall(r"^\s*(?:float|vec[234])\s+(pbr_\w+)\s*\(", path.read_text(), re.M))
    assert defined - {f.name for f in FUNCTIONS} == set()


def test_every_case_says_why_it_is_hard_and_every_function_has_cases():
    cases = catalogue.catalogue()
    assert all(len(c.why) > 10 for c in cases)
    assert {c.function.label for c in cases} == {f.label for f in FUNCTIONS}
    assert len(cases) >= 1500  # the catalogue's size (2005 cases when written)


def test_shading_model_is_catalogued_at_every_tier_and_variant():
    for name in ("pbr_brdf_standard", "pbr_shade_punctual"):
        variants = {f.variant for f in FUNCTIONS if f.name == name}
        assert {"quality=HIGH", "quality=LOW", "specular_v=KELEMEN", "diffuse=BURLEY"} <= variants


def test_bound_rejects_nan_and_inf_without_min_max():
    """NaN must be caught in the float readback: the bound check fails NaN and ±Inf."""
    values = np.array([[0.5], [np.nan], [np.inf], [-np.inf], [1.5], [-0.0]], np.float32)
    assert catalogue.Bound("x", 0.0, 1.0).holds(values).tolist() == [True, False, False, False, False, True]


def _failures(results):
    return "\n".join(f"{r.case.function.label} | {r.case.name} | value {r.value_text()} | expected "
                     f"{r.expected_text()}" for r in results if not r.ok)


@pytest.mark.parametrize("function", FUNCTIONS, ids=lambda f: f.label)
def test_catalogue_cases_finite_bounded_and_decided_for(function):
    results = run.run_catalogue(catalogue.cases_of(function))
    assert results and all(r.ok for r in results), _failures(results)


@pytest.mark.parametrize("function", FUNCTIONS, ids=lambda f: f.label)
def test_sweep_of_a_million_adversarial_samples_is_finite_and_bounded_for(function):
    result = run.run_sweep(function, seed=sum(map(ord, function.label)))
    assert result.samples >= 10 ** 6
    assert result.ok, (f"{function.label}: {result.nonfinite} non-finite, {result.out_of_bound} out of "
                       f"'{function.bound.text}'; first: {result.worst_inputs}")


def test_sweep_inputs_mix_normal_domain_and_adversarial_floats():
    """About 30 % of each argument comes from the adversarial pool (0, denormals, 1 ± ulp,
    huge, negative), the rest from the normal domain."""
    x = domains.KINDS["cosine"].sample(np.random.default_rng(0), 100_000)
    adversarial = np.isin(x, domains.KINDS["cosine"].pool().astype(np.float32))
    assert 0.25 < adversarial.mean() < 0.35
    for value in (0.0, domains.DENORMAL, domains.ULP_ABOVE_ONE, 1e30, -0.5):
        assert (x == np.float32(value)).any(), value


# ---- the command ------------------------------------------------------------------------

def test_hardcases_command_passes_on_the_library(capsys):
    assert cli_main(["hardcases", "--function", "pbr_D_GGX", "--function", "pbr_linear_to_srgb"]) == 0
    out = capsys.readouterr().out
    assert "alpha = 0 at the peak" in out and "FAIL" not in out and " 0 failed" in out


BROKEN = catalogue.Function("broken_sqrt", "sqrt(x - 2.0)", catalogue._a("x:unit"), catalogue.Bound("y >= 0", 0.0))


def test_hardcases_command_fails_on_a_broken_expression(monkeypatch, capsys):
    """A deliberately broken entry (sqrt of a negative: NaN) must make the command exit 1 and
    print the failing case; the JSON form reports NaN as a string."""
    monkeypatch.setattr(catalogue, "catalogue", lambda: catalogue.cases_of(BROKEN))
    assert cli_main(["hardcases"]) == 1
    assert "FAIL" in capsys.readouterr().out
    assert cli_main(["hardcases", "--json", "--failures-only"]) == 1
    out = capsys.readouterr().out
    assert '"status": "FAIL"' in out and '"nan"' in out


def test_a_wrong_decided_value_fails_the_catalogue():
    function = next(f for f in FUNCTIONS if f.name == "pbr_linear_to_srgb")
    case = catalogue.Case(function, "NaN (wrongly expected 1)", "test", {"c": (np.nan,) * 3}, 1.0)
    assert not run.run_catalogue([case])[0].ok
