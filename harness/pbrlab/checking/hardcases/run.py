"""Run the catalogue and the randomised sweeps through the GPU evaluator.

NaN detection is done on the float32 readback (``pbrlab.evaluate`` transports NaN, ±Inf and
denormals bit-exactly) with ``np.isfinite`` and ordered comparisons, never through an 8-bit
image (where NaN becomes 0) nor through min/max/clamp (which hide NaN in implementation-
defined ways): see ``catalogue.Bound.holds``.
"""

from __future__ import annotations

import re
from collections import defaultdict
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ...gpu import evaluator, shaders
from . import catalogue, domains

SWEEP_SAMPLES = 1_000_000  # per function and variant (issue 5: at least 10^6)


@dataclass
class CaseResult:
    case: catalogue.Case
    value: np.ndarray          # float32 as read back
    expected: np.ndarray | None
    ok: bool

    @property
    def status(self) -> str:
        return "ok" if self.ok else "FAIL"

    def value_text(self) -> str:
        return _fmt(self.value)

    def expected_text(self) -> str:
        bound = self.case.function.bound.text
        if self.case.near is not None:
            return f"≈ {_fmt(self.case.near.value)} ({self.case.near.source}) and {bound}"
        if self.expected is None:
            return bound
        return f"== {_fmt(self.expected)} (decided) and {bound}"


def _fmt(x) -> str:
    x = np.atleast_1d(np.asarray(x, np.float64)).ravel()
    if x.size > 1 and (x == x[0]).all() or (np.isnan(x).all()):
        x = x[:1]
    return ", ".join(f"{v:.7g}" for v in x)


@lru_cache(maxsize=None)
def _defining_files() -> dict[str, str]:
    """pbr_* function name -> the library file that defines it (include path)."""
    out = {}
    definition = re.compile(r"^\s*(?:float|vec[234])\s+(pbr_\w+)\s*\(", re.M)
    for path in sorted((shaders.GLSL_ROOT / "pbr").rglob("*.glsl")):
        for name in definition.findall(path.read_text(encoding="utf-8")):
            out.setdefault(name, path.relative_to(shaders.GLSL_ROOT).as_posix())
    return out


def includes_for(function: catalogue.Function) -> tuple[str, ...]:
    """Only the file that defines the function (it includes what it needs, STYLE 2): a
    smaller program compiles ~40 % faster than the umbrella. Expressions of decided values
    use the same file's macros; pbr/common/guards.glsl is added for the guard constants."""
    path = _defining_files().get(function.name)
    if path is None and function.expression.startswith(("(pbr_unity_", "GGXTerm", "SmithJoint", "Disney",
                                                        "PerceptualRoughnessToSpecPower")):
        path = catalogue.UNITY_INCLUDE  # Unity's names (pbr/unity/, outside the umbrella)
    if path is None:  # not a library function (e.g. a test's deliberately broken entry)
        return (shaders.UMBRELLA_INCLUDE,)
    return (path, "pbr/common/guards.glsl", "pbr/shading/dispatch.glsl")


def _inputs_for(function: catalogue.Function, cases: list[catalogue.Case]) -> dict:
    """Stack the cases' inputs into evaluator arrays (one element per case)."""
    out = {}
    for a in function.args:
        values = np.array([c.inputs[a.name] for c in cases], np.float64)
        out[a.name] = evaluator.vec3(values.astype(np.float32)) if (a.vec3 or a.kind == "dir") else values.astype(np.float32)
    if not function.args:
        out["x"] = np.zeros(len(cases), np.float32)
    return out


def run_catalogue(cases=None, evaluate=evaluator.evaluate) -> list[CaseResult]:
    """Evaluate every case (batched per function and call) and check bound and decided value."""
    cases = catalogue.catalogue() if cases is None else cases
    groups = defaultdict(list)
    for case in cases:
        groups[(case.function, case.call)].append(case)
    results = []
    for (function, call), group in groups.items():
        defines = dict(function.defines)
        includes = includes_for(function)
        inputs = _inputs_for(function, group)
        values = np.asarray(evaluate(call, includes, defines=defines, **inputs))
        ok = function.bound.holds(values)
        expected = [None] * len(group)
        by_exact = defaultdict(list)
        for i, case in enumerate(group):
            if case.exact is not None:
                by_exact[case.exact].append(i)
        for exact, idx in by_exact.items():
            if isinstance(exact, catalogue.SameAs):
                ref = [k for k, c in enumerate(group) if c.name == exact.case_name][0]
                want = np.broadcast_to(values[ref], values[idx].shape)
            elif isinstance(exact, str):
                sub = _inputs_for(function, [group[i] for i in idx])
                want = np.asarray(evaluate(exact, includes, defines=defines, **sub), np.float32)
                want = np.broadcast_to(want, values[idx].shape) if want.ndim < values[idx].ndim else want
            else:
                want = np.full(values[idx].shape, exact, np.float32)
            for j, i in enumerate(idx):
                expected[i] = want[j]
                # exact: bit-for-bit equal float32 (NaN is never equal, so it fails)
                ok[i] &= bool(np.array_equal(values[i], want[j]))
        for i, case in enumerate(group):
            if case.near is not None:  # follows the maths: the float64 reference, relative
                want = np.asarray(case.near.value, np.float64)
                got = np.asarray(values[i], np.float64).ravel()
                ok[i] &= bool(np.all(np.abs(got - want) <= case.near.rel * np.abs(want)))
        results += [CaseResult(case, values[i], expected[i], bool(ok[i])) for i, case in enumerate(group)]
    return results


# ---- randomised sweeps ---------------------------------------------------------------

@dataclass
class SweepResult:
    function: catalogue.Function
    samples: int
    nonfinite: int
    out_of_bound: int
    worst_inputs: dict | None

    @property
    def ok(self) -> bool:
        return self.nonfinite == 0 and self.out_of_bound == 0


def _directions(rng, count):
    """Unit vectors for the non-shading vector arguments: n random, h random with 30 %
    replaced by h = n, h = -n, h within 1e-6 of n."""
    n = domains.unit_vectors(rng, count)
    h = domains.unit_vectors(rng, count)
    which = rng.integers(0, 10, count)
    h = np.where((which == 0)[:, None], n, h)
    h = np.where((which == 1)[:, None], -n, h)
    near = n + rng.normal(0.0, 1e-6, (count, 3))
    h = np.where((which == 2)[:, None], near / np.linalg.norm(near, axis=-1, keepdims=True), h)
    return n.astype(np.float32), h.astype(np.float32)


@lru_cache(maxsize=2)
def _shading_geometry(count: int) -> dict[str, np.ndarray]:
    """One geometry set shared by every tier and variant of the shading model (the other
    arguments are drawn per function): the variants are compared on the same directions."""
    return domains.shading_geometry(np.random.default_rng(20250505), count)


def sweep_inputs(function: catalogue.Function, count: int, seed: int) -> dict[str, np.ndarray]:
    """Randomised inputs (float32) mixing each argument's normal domain with adversarial values."""
    rng = np.random.default_rng(seed)
    out = {}
    if (function.name in ("pbr_brdf_standard", "pbr_shade_punctual", "pbr_brdf_standard_f90", "pbr_shade_punctual_f90",
                          "pbr_clearcoat_punctual", "pbr_length2_nonzero", *catalogue.DV_FUNCTIONS)
            or function.name.startswith("pbr_unity_brdf")):
        out.update(_shading_geometry(count))
    elif function.name in catalogue.TRANSMISSION_FUNCTIONS:
        out.update(domains.transmission_geometry(np.random.default_rng(20250506), count))
    elif any(a.kind == "dir" for a in function.args):
        out["n"], out["h"] = _directions(rng, count)
    for a in function.args:
        if a.kind == "dir":
            continue
        kind = domains.KINDS[a.kind]
        out[a.name] = (np.stack([kind.sample(rng, count) for _ in range(3)], axis=-1) if a.vec3
                       else kind.sample(rng, count))
    return out


def run_sweep(function: catalogue.Function, count: int = SWEEP_SAMPLES, seed: int = 0,
              evaluate=evaluator.evaluate) -> SweepResult:
    raw = sweep_inputs(function, count, seed)
    inputs = {k: (evaluator.vec3(v) if v.ndim == 2 else v) for k, v in raw.items()}
    if not function.args:
        inputs["x"] = np.zeros(count, np.float32)
    values = np.asarray(evaluate(function.expression, includes_for(function), defines=dict(function.defines),
                                 **inputs))
    flat = values.reshape(count, -1)
    finite = np.isfinite(flat).all(axis=1)
    holds = function.bound.holds(values)
    bad = np.flatnonzero(~holds)
    worst = None
    if bad.size:
        i = int(bad[0])
        worst = {k: v[i].tolist() for k, v in raw.items()} | {"value": flat[i].tolist()}
    return SweepResult(function, count, int((~finite).sum()), int((finite & ~holds).sum()), worst)
