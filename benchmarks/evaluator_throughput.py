"""Evaluator throughput: how long a sweep of N samples of a BRDF term takes, end to end
(upload, draw, readback), through `pbrlab.evaluate`. A benchmark, not a test: it prints
figures and asserts nothing about time.

    .venv/bin/python benchmarks/evaluator_throughput.py [--samples 1000000] [--repeats 7]

Reports the median and spread of wall time per sweep and the derived ns/sample, after a
warm-up call per term (which compiles the program); terms run interleaved in a shuffled
order each round, so machine-load drift spreads over all of them. On llvmpipe the draw uses LP_NUM_THREADS
threads (default: all cores); set LP_NUM_THREADS=1 for single-thread figures.

Beside each term, the same formula in numpy float32 on the same inputs (numpy's element-wise
loops run on one thread: compare with LP_NUM_THREADS=1), interleaved with the evaluator's runs,
and the ratio of the medians (issue 35 asks the evaluator to be within 3x of it). The numpy
forms are the GLSL's own lines (the clamps included), so both do the same arithmetic.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from pbrlab import evaluate
from pbrlab.gpu import gl

INV_PI32 = np.float32(1 / np.pi)
MIN_NDOTV, MIN_ALPHA = np.float32(1e-4), np.float32(1e-7)  # pbr/common/guards.glsl
ZERO, ONE = np.float32(0), np.float32(1)


def _numpy_d_ggx(NdotH, alpha):
    """glsl/pbr/brdf/d_ggx.glsl's pbr_D_GGX (via pbr_D_GGX_fromOneMinusNdotH2), in float32 numpy."""
    NdotH = np.clip(NdotH, ZERO, ONE)
    one_minus = (ONE - NdotH) * (ONE + NdotH)
    alpha = np.clip(alpha, MIN_ALPHA, ONE)
    a = NdotH * alpha
    k = alpha / np.maximum(one_minus + a * a, alpha * alpha)
    return k * k * INV_PI32


def _numpy_v_smith_correlated(NdotL, NdotV, alpha):
    """glsl/pbr/brdf/v_smith_ggx_correlated.glsl's pbr_V_SmithGGXCorrelated, in float32 numpy."""
    NdotL = np.clip(NdotL, MIN_NDOTV, np.float32(1))
    NdotV = np.clip(NdotV, MIN_NDOTV, np.float32(1))
    alpha = np.clip(alpha, MIN_ALPHA, np.float32(1))
    a2 = alpha * alpha
    one_minus = np.float32(1) - a2
    lambda_v = NdotL * np.sqrt(NdotV * NdotV * one_minus + a2)
    lambda_l = NdotV * np.sqrt(NdotL * NdotL * one_minus + a2)
    return np.float32(0.5) / (lambda_v + lambda_l)


NUMPY = {"identity": lambda x: x.copy(), "pbr_D_GGX": _numpy_d_ggx,
         "pbr_V_SmithGGXCorrelated": _numpy_v_smith_correlated}

TERMS = {
    "identity": ("x", lambda rng, n: {"x": rng.random(n, dtype=np.float32)}),
    "pbr_D_GGX": ("pbr_D_GGX(NdotH, alpha)",
                  lambda rng, n: {"NdotH": rng.random(n, dtype=np.float32),
                                  "alpha": rng.random(n, dtype=np.float32)}),
    "pbr_V_SmithGGXCorrelated": ("pbr_V_SmithGGXCorrelated(NdotL, NdotV, alpha)",
                                 lambda rng, n: {"NdotL": rng.random(n, dtype=np.float32),
                                                 "NdotV": rng.random(n, dtype=np.float32),
                                                 "alpha": rng.random(n, dtype=np.float32)}),
}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--backend", choices=gl.BACKENDS, default=None)
    args = parser.parse_args(argv)
    rng = np.random.default_rng(1)
    info = gl.context_info(gl.shared_context(args.backend))
    print(f"{info['GL_RENDERER']} | {info['GL_VERSION']} | backend {info['backend']} | "
          f"llvmpipe caps {info['llvmpipe_cpu_caps']} | {args.samples} samples, {args.repeats} repeats")
    print(f"{'term':28s} {'median s':>9s} {'min s':>8s} {'max s':>8s} {'ns/sample':>10s} "
          f"{'numpy f32 s':>11s} {'x numpy':>8s}")
    prepared = {name: (expression, make_inputs(rng, args.samples))
                for name, (expression, make_inputs) in TERMS.items()}
    for expression, inputs in prepared.values():
        evaluate(expression, backend=args.backend, **inputs)  # warm-up: compile + first draw
    for name, (expression, inputs) in prepared.items():  # same arithmetic, or the ratio means nothing
        got, want = evaluate(expression, backend=args.backend, **inputs), NUMPY[name](**inputs)
        if not np.allclose(got, want, rtol=1e-5, atol=0):
            raise SystemExit(f"{name}: the numpy form is not the GLSL's formula (largest difference "
                             f"{np.abs(got - want).max():.3g})")
    jobs = [(name, "gpu") for name in prepared] + [(name, "numpy") for name in prepared]
    times = {job: [] for job in jobs}
    for _ in range(args.repeats):  # interleaved, in a shuffled order each round
        for index in rng.permutation(len(jobs)):
            name, kind = jobs[index]
            expression, inputs = prepared[name]
            start = time.perf_counter()
            if kind == "gpu":
                evaluate(expression, backend=args.backend, **inputs)
            else:
                NUMPY[name](**inputs)
            times[jobs[index]].append(time.perf_counter() - start)
    for name in prepared:
        samples, numpy_median = times[(name, "gpu")], statistics.median(times[(name, "numpy")])
        median = statistics.median(samples)
        print(f"{name:28s} {median:9.4f} {min(samples):8.4f} {max(samples):8.4f} "
              f"{median / args.samples * 1e9:10.1f} {numpy_median:11.6f} {median / numpy_median:8.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
