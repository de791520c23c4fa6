"""Evaluator throughput: how long a sweep of N samples of a BRDF term takes, end to end
(upload, draw, readback), through `pbrlab.evaluate`. A benchmark, not a test: it prints
figures and asserts nothing about time.

    .venv/bin/python benchmarks/evaluator_throughput.py [--samples 1000000] [--repeats 7]

Reports the median and spread of wall time per sweep and the derived ns/sample, after a
warm-up call per term (which compiles the program); terms run interleaved in a shuffled
order each round, so machine-load drift spreads over all of them. On llvmpipe the draw uses LP_NUM_THREADS
threads (default: all cores); set LP_NUM_THREADS=1 for single-thread figures.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from pbrlab import evaluate
from pbrlab.gpu import gl

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
    print(f"{'term':28s} {'median s':>9s} {'min s':>8s} {'max s':>8s} {'ns/sample':>10s}")
    prepared = {name: (expression, make_inputs(rng, args.samples))
                for name, (expression, make_inputs) in TERMS.items()}
    for expression, inputs in prepared.values():
        evaluate(expression, backend=args.backend, **inputs)  # warm-up: compile + first draw
    times = {name: [] for name in prepared}
    for _ in range(args.repeats):  # interleaved, in a shuffled order each round
        for name in rng.permutation(list(prepared)):
            expression, inputs = prepared[name]
            start = time.perf_counter()
            evaluate(expression, backend=args.backend, **inputs)
            times[name].append(time.perf_counter() - start)
    for name, samples in times.items():
        median = statistics.median(samples)
        print(f"{name:28s} {median:9.4f} {min(samples):8.4f} {max(samples):8.4f} "
              f"{median / args.samples * 1e9:10.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
