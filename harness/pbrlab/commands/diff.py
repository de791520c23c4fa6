"""`pbrlab diff EXPECTED OBTAINED`: compare two images, print metrics, exit 0 when within tolerance.

EXR images are compared in linear units (default tolerance: ``compare.GOLDEN_TOLERANCE``),
PNG images in 8-bit code values (default: ``compare.GOLDEN_SRGB_TOLERANCE``). Exit status:
0 within tolerance, 1 over it (or shapes differ, or NaN/Inf in OBTAINED), 2 for a problem
with the files (printed by the cli).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..checking import compare
from ..foundation import images, outputs
from ..foundation.errors import PbrlabError


def register(subparsers, common) -> None:
    parser = subparsers.add_parser(
        "diff", parents=[common],
        help="Compare two images (EXR in linear units, PNG in 8-bit codes); exit 1 when over tolerance.",
        description=(
            "Compare OBTAINED against EXPECTED and print max abs, RMSE, the fraction of pixels "
            "over tolerance and (8-bit images) mean FLIP. EXR images are compared in linear "
            f"units (default max abs {compare.GOLDEN_TOLERANCE.max_abs:g}, the golden "
            "tolerance), PNG images in 8-bit code values (default max abs "
            f"{compare.GOLDEN_SRGB_TOLERANCE.max_abs:g}). Exit status: 0 within tolerance, 1 "
            "over it (or shapes differ, or NaN/Inf in OBTAINED), 2 when a file is missing or "
            "unreadable."))
    parser.add_argument("expected", help="reference image (.exr or .png)")
    parser.add_argument("obtained", help="image to check, same size and kind")
    parser.add_argument("--heatmap", metavar="OUT.png",
                        help="write the per-pixel error picture (black = identical, blue = "
                             "within, red to yellow = over tolerance, magenta = NaN/Inf)")
    parser.add_argument("--max-abs", type=float, metavar="X",
                        help="largest allowed per-channel difference (EXR: linear, PNG: codes)")
    parser.add_argument("--max-fraction", type=float, metavar="F",
                        help="fraction of pixels (0..1) allowed over --max-abs")
    parser.set_defaults(run=run)


def _tolerance(args, default: compare.Tolerance) -> compare.Tolerance:
    if args.max_abs is None and args.max_fraction is None:
        return default
    max_abs = default.max_abs if args.max_abs is None else args.max_abs
    max_fraction = default.max_fraction if args.max_fraction is None else args.max_fraction
    if not (math.isfinite(max_abs) and max_abs >= 0):
        raise PbrlabError(f"--max-abs must be a finite number >= 0, got {max_abs}")
    if not (0.0 <= max_fraction <= 1.0):
        raise PbrlabError(f"--max-fraction must be between 0 and 1, got {max_fraction}")
    return compare.Tolerance(max_abs, max_fraction, "given on the command line")


def _describe(image: np.ndarray) -> str:
    kind = "8-bit sRGB" if image.dtype == np.uint8 else "float linear"
    return f"{image.shape[1]}x{image.shape[0]}, {image.shape[2]} channel(s), {kind}"


def run(args) -> int:
    if args.heatmap:  # before any work: the heatmap must not replace an image it compares
        outputs.refuse_inputs([args.heatmap], [(args.expected, "the expected image"),
                                               (args.obtained, "the obtained image")])
        outputs.check_writable_target(Path(args.heatmap))
    expected = images.read_image(args.expected)
    obtained = images.read_image(args.obtained)
    if expected.dtype != obtained.dtype:
        raise PbrlabError(
            f"cannot compare {args.expected} ({_describe(expected)}) with {args.obtained} "
            f"({_describe(obtained)}): compare PNG with PNG (code values) or EXR with EXR (linear)")
    ldr = expected.dtype == np.uint8
    tolerance = _tolerance(args, compare.GOLDEN_SRGB_TOLERANCE if ldr else compare.GOLDEN_TOLERANCE)
    result = compare.diff(expected, obtained, tolerance, flip=ldr)

    print(f"expected      {args.expected} ({_describe(expected)})")
    print(f"obtained      {args.obtained} ({_describe(obtained)})")
    print(f"tolerance     {tolerance.describe(result.units)}")
    if result.problem:
        print(f"result        {result.problem}")
    else:
        where = (f" at (y={result.worst_pixel[0]}, x={result.worst_pixel[1]})"
                 if result.worst_pixel else "")
        print(f"max abs       {result.max_abs:.6g} ({result.units}){where}")
        print(f"RMSE          {result.rmse:.6g}")
        print(f"over          {result.pixels_over} of {result.pixel_count} pixels "
              f"({100 * result.fraction_over:.4g}%; allowed {100 * tolerance.max_fraction:.4g}%)")
        print(f"non-finite    {result.nonfinite_obtained} pixel(s) in obtained, "
              f"{result.nonfinite_expected} in expected")
        if result.flip_mean is not None:
            print(f"FLIP mean     {result.flip_mean:.6g}")
        elif ldr:
            print("FLIP mean     n/a (install flip-evaluator)")
        else:
            print("FLIP mean     n/a (reported for 8-bit sRGB images)")
    if args.heatmap:
        images.write_png(args.heatmap, result.heatmap())
        print(f"heatmap       {args.heatmap}")
    print(f"verdict       {'within tolerance' if result.passed else 'OVER TOLERANCE'}")
    return 0 if result.passed else 1
