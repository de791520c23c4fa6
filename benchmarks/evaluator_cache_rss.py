"""Evaluator memory over many distinct expressions (issue 14): the process's resident set
size (RSS, from /proc/self/status) while ``pbrlab.evaluate`` compiles N distinct
expressions, one after another. With the bounded program cache (evaluator.PROGRAMS_CACHED,
least recently used released) RSS must level off once the cache is full; before it, every
program stayed and RSS grew by about 0.5 MB per expression. A measurement, not a test: it
prints figures and asserts nothing.

    .venv/bin/python benchmarks/evaluator_cache_rss.py [--expressions 10000] [--every 1000]
        [--include pbr/brdf/d_ggx.glsl]

Each expression includes one library file (default d_ggx.glsl: about 0.1 s a compile on
llvmpipe, so 10,000 take some 20 minutes; the umbrella pbr/pbr.glsl takes 0.24 s).

Prints RSS after the first call (compiler and context warm) and every --every expressions,
the growth from the point where the cache first filled to the end, and the cache size.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from pbrlab import evaluate
from pbrlab.gpu import evaluator


def rss_mib() -> float:
    with open("/proc/self/status", encoding="ascii") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    raise RuntimeError("no VmRSS in /proc/self/status (Linux only)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--expressions", type=int, default=10000)
    parser.add_argument("--every", type=int, default=1000)
    parser.add_argument("--include", default="pbr/brdf/d_ggx.glsl")
    args = parser.parse_args()
    x = np.linspace(0.0, 1.0, 64, dtype=np.float32)
    start = time.perf_counter()
    full_at = None
    print(f"cache size (evaluator.PROGRAMS_CACHED): {evaluator.PROGRAMS_CACHED} programs "
          "(two per expression: the width probe and the evaluation)")
    print(f"{'expressions':>11}  {'RSS MiB':>8}  {'programs cached':>15}  {'s':>7}")
    for k in range(args.expressions):
        # distinct source text each time: a new program, never a cache hit
        out = evaluate(f"pbr_D_GGX(x, 0.25) + {k}.0", [args.include], x=x)
        assert out.shape == x.shape
        cached = len(evaluator._shared_evaluator(None)._programs)
        if full_at is None and cached >= evaluator.PROGRAMS_CACHED:
            full_at = (k + 1, rss_mib())
        if k == 0 or (k + 1) % args.every == 0:
            print(f"{k + 1:>11}  {rss_mib():>8.1f}  {cached:>15}  {time.perf_counter() - start:>7.1f}")
    end = rss_mib()
    if full_at:
        print(f"RSS when the cache filled (after {full_at[0]} expressions): {full_at[1]:.1f} MiB; "
              f"at the end: {end:.1f} MiB; growth since: {end - full_at[1]:+.1f} MiB")


if __name__ == "__main__":
    main()
