"""Issue 38: the prefiltered environment as the shaders read it (textureLod at lod = level) against
the float64 brute force (pbrlab.maths.reference.prefilter), luminance error per level at the
poles, the u = 0 seam, around the brightest texel and at 400 random directions
(pbrlab.checking.prefilter): relative to the reference ("rel"), and relative to the local mean
("local": the error over the larger of the reference and the roughness-1 reference in the same
direction, the cosine-weighted mean around it, so that a near-black direction beside a sun is
not judged by its own darkness). Also the uncached prefilter's process and wall time.
Usage: PYTHONPATH=harness python benchmarks/prefilter_accuracy.py ENV.exr"""
import sys
import time

import numpy as np

from pbrlab.checking import prefilter as check
from pbrlab.foundation.images import read_image
from pbrlab.gpu import gl, ibl
from pbrlab.maths.reference import prefilter as ref


def main(path):
    ctx = gl.shared_context()
    img = np.asarray(read_image(path), np.float64)[..., :3]
    t0, w0 = time.process_time(), time.perf_counter()
    levels = ibl._prefilter_levels(ctx, img.astype(np.float32))  # uncached
    print(f"prefilter (uncached): process {time.process_time() - t0:.2f} s, wall {time.perf_counter() - w0:.2f} s")
    tex = ibl.float_cube_from_levels(ctx, levels)
    sets = check.direction_sets(img)
    cells2 = ref.quadrature_cells(img, 2)
    mean = {name: ref.prefiltered_radiance(img, dirs, 1.0, cells=cells2) @ check.LUMINANCE for name, dirs in sets.items()}
    for level in range(ibl.PREFILTER_LEVELS):
        r = ibl.prefilter_level_roughness(level)
        cells = ref.quadrature_cells(img, 4) if 0 < r < 0.4 else cells2
        print(f"level {level} r={r:.2f} face {ibl.prefilter_level_size(level)}", flush=True)
        for name, dirs in sets.items():
            lw = ref.prefiltered_radiance(img, dirs, r, cells=cells) @ check.LUMINANCE
            lg = check.cube_lookup(ctx, tex, dirs, level) @ check.LUMINANCE
            rel = np.abs(lg - lw) / lw
            local = np.abs(lg - lw) / np.maximum(lw, mean[name])
            print(f"  {name:7s} rel max {rel.max():.3f} p99 {np.percentile(rel, 99):.3f}"
                  f" | local max {local.max():.3f} p99 {np.percentile(local, 99):.3f}", flush=True)


if __name__ == "__main__":
    main(sys.argv[1])
