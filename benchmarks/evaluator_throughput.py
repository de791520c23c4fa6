"""Evaluator throughput: how long a sweep of N samples of a BRDF term takes, end to end
(upload, draw, readback), through `pbrlab.evaluate`. A benchmark, not a test: it prints
figures and asserts nothing about time.

    .venv/bin/python benchmarks/evaluator_throughput.py [--samples 1000000] [--repeats 7]

Reports the median and spread of wall time per sweep and the derived ns/sample, after a
warm-up call (which compiles the program). On llvmpipe the draw uses LP_NUM_THREADS
threads (default: all cores); set LP_NUM_THREADS=1 for single-thread figures.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from pbrlab import evaluate, gl

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
    for name, (expression, make_inputs) in TERMS.items():
        inputs = make_inputs(rng, args.samples)
        evaluate(expression, backend=args.backend, **inputs)  # warm-up: compile + first draw
        times = []
        for _ in range(args.repeats):
            start = time.perf_counter()
            evaluate(expression, backend=args.backend, **inputs)
            times.append(time.perf_counter() - start)
        median = statistics.median(times)
        print(f"{name:28s} {median:9.4f} {min(times):8.4f} {max(times):8.4f} "
              f"{median / args.samples * 1e9:10.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
