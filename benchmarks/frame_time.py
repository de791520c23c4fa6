"""Frame time of golden scenes at a given size: wall clock of ``render_scene`` (shading,
readback, display encode) and, on a real GPU, the GPU time of the same commands from a GL
timer query. A benchmark: it prints figures and asserts nothing.

    python benchmarks/frame_time.py [--size 1024] [--repeats 7] [NAME ...]

On Mesa llvmpipe the timer query times one tile, not the draw (README, "Measured"), so only
the wall clock means anything there.
"""

from __future__ import annotations

import argparse
import statistics
import time

from pbrlab.gpu import gl
from pbrlab.checking.golden_scenes import GOLDEN_SCENES
from pbrlab.render.renderer import render_scene


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", default=["chart_metallic", "lit_scene_high"])
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    ctx = gl.shared_context()
    info = gl.context_info(ctx)
    print(f"{info['GL_RENDERER']} | {info['GL_VERSION']} | {args.size}x{args.size}, "
          f"median of {args.repeats} after one warm-up")
    for name in args.names:
        scene = GOLDEN_SCENES[name]()
        render_scene(scene, ctx, size=(args.size, args.size))  # compile, upload, cache
        walls, gpus = [], []
        for _ in range(args.repeats):
            query = ctx.query(time=True)
            start = time.perf_counter()
            with query:
                render_scene(scene, ctx, size=(args.size, args.size))
            walls.append(time.perf_counter() - start)
            gpus.append(query.elapsed * 1e-9)
        print(f"{name:18s} wall {1e3 * statistics.median(walls):8.2f} ms   "
              f"GL timer {1e3 * statistics.median(gpus):8.2f} ms")


if __name__ == "__main__":
    main()
