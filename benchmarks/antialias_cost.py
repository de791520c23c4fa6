"""CPU cost of anti-aliasing (render.antialias): process time of ``render_scene`` at 1 sample
per pixel and at each multisampled count this GL takes, for a sphere scene (the metallic
chart: ray-traced spheres covering their samples themselves) and a glTF mesh scene
(rasterised coverage). A benchmark: it prints figures and asserts nothing.

    LP_NUM_THREADS=1 python benchmarks/antialias_cost.py [--size 512] [--repeats 7] [NAME ...]

Run with LP_NUM_THREADS=1 so llvmpipe rasterises on this process's thread and
time.process_time counts its work. The counts are interleaved (1x, 4x, 1x, 4x, ...) after a
warm-up of each, so a slow stretch of a shared machine falls on all of them; medians.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import statistics
import time
import warnings

from pbrlab.gpu import gl, gl_limits
from pbrlab.checking.golden_scenes import GOLDEN_SCENES
from pbrlab.render.renderer import render_scene


def _with_samples(scene, samples):
    return dataclasses.replace(scene, render=dataclasses.replace(scene.render, antialias=samples))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", default=["chart_metallic", "gltf_features_environment"])
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--language", default="glsl")
    args = parser.parse_args()
    ctx = gl.shared_context()
    info = gl.context_info(ctx)
    counts = gl_limits.sample_counts(ctx, "f32")
    print(f"{info['GL_RENDERER']} | {info['GL_VERSION']} | {args.size}x{args.size} | "
          f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'unset')} | samples {counts} | "
          f"median process time of {args.repeats}, interleaved, after one warm-up each")
    for name in args.names:
        scene = GOLDEN_SCENES[name]()
        scenes = {n: _with_samples(scene, n) for n in counts}
        times = {n: [] for n in counts}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for n in counts:  # compile, upload, cache
                render_scene(scenes[n], ctx, size=(args.size, args.size), language=args.language)
            for _ in range(args.repeats):
                for n in counts:
                    start = time.process_time()
                    render_scene(scenes[n], ctx, size=(args.size, args.size), language=args.language)
                    times[n].append(time.process_time() - start)
        base = statistics.median(times[1])
        line = "   ".join(f"{n}x {1e3 * statistics.median(times[n]):8.1f} ms ({statistics.median(times[n]) / base:.2f}x)"
                          for n in counts)
        print(f"{name:26s} {line}")


if __name__ == "__main__":
    main()
