"""Image comparison: one tolerance type, one diff, one heatmap.

A ``Tolerance`` is a pair plus its reason (STYLE 12): a pixel *fails* when any channel's
``|obtained - expected|`` exceeds ``max_abs + max_rel * |expected|``; the comparison
*passes* when the fraction of failing pixels is at most ``max_fraction`` (and, for 8-bit
images with ``max_flip`` set, the mean FLIP is at most ``max_flip``). A pixel holding NaN or Inf (in either image)
always fails, and any such pixel in ``obtained`` fails the whole comparison whatever the
fraction allowed. Units follow the images:

* float images (EXR): linear values, compared in float64 after reading the float32 data;
* uint8 images (PNG): 8-bit sRGB code values (0..255), compared as integers.

Comparing two images of different shapes is not an error: it is a failing ``DiffResult``
whose ``problem`` says so. Comparing an 8-bit image with a float one *is* an error
(``TypeError``): the numbers would mean different things.

FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator for Alternating Images",
HPG 2020) is reported for 8-bit sRGB images when the ``flip-evaluator`` package is
installed and ``diff(..., flip=True)`` asks for it; it decides pass/fail only for a
tolerance with ``max_flip`` (the GPU profile), which then needs the package.

``TOLERANCE_PROFILES`` names the pairs of tolerances goldens are checked with: ``llvmpipe``
(the renderer goldens are made with: bit-identical by construction) and ``gpu`` (real GPUs,
measured on NVIDIA's driver); ``profile_for_renderer`` picks one from GL_RENDERER.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np

# Smallest step of the 8-bit sRGB encoding in linear units: code 0 -> 1 lies on the linear
# segment of IEC 61966-2-1, 1/255/12.92 = 3.04e-4. Larger codes have larger steps.
SRGB_SMALLEST_STEP_LINEAR = 1.0 / 255.0 / 12.92


@dataclass(frozen=True)
class Tolerance:
    """How far an obtained image may stray from the expected one, and why.

    Attributes:
        max_abs: largest allowed per-channel deviation, in the images' units (linear for float
            images, code values for uint8 images); a pixel over it *fails*.
        max_fraction: fraction of pixels (0..1) allowed to fail.
        reason: one line saying why the numbers are this size (measured drift, conditioning).
        max_rel: added to max_abs per channel, times |expected| (HDR values: a relative bound).
        max_flip: largest allowed mean FLIP of 8-bit images (None: FLIP does not decide).
    """

    max_abs: float
    max_fraction: float
    reason: str
    max_rel: float = 0.0
    max_flip: float | None = None

    def __post_init__(self):
        if not (np.isfinite(self.max_abs) and self.max_abs >= 0):
            raise ValueError(f"Tolerance.max_abs must be finite and >= 0, got {self.max_abs}")
        if not (0.0 <= self.max_fraction <= 1.0):
            raise ValueError(f"Tolerance.max_fraction must be in [0, 1], got {self.max_fraction}")
        if not self.reason.strip():
            raise ValueError("Tolerance.reason must say why the tolerance is this size")
        if not (np.isfinite(self.max_rel) and self.max_rel >= 0):
            raise ValueError(f"Tolerance.max_rel must be finite and >= 0, got {self.max_rel}")
        if self.max_flip is not None and not (0.0 <= self.max_flip <= 1.0):
            raise ValueError(f"Tolerance.max_flip must be in [0, 1] or None, got {self.max_flip}")

    def describe(self, units: str = "") -> str:
        units = f" {units}" if units else ""
        rel = f" + {self.max_rel:g} x |expected|" if self.max_rel else ""
        flip = f", mean FLIP <= {self.max_flip:g}" if self.max_flip is not None else ""
        return (f"max_abs {self.max_abs:g}{units}{rel}, max_fraction {self.max_fraction:g}{flip} "
                f"({self.reason})")


# Golden tolerance for linear EXR renders on llvmpipe, in linear units. Nothing a golden is
# made of depends on the CPU: llvmpipe's code generation is pinned (pbrlab.gpu.gl), texture mips
# and the display encode are computed exactly on the CPU (pbrlab.maths.mipmaps, pbrlab.maths.srgb8), and
# the JIT code of every golden scene holds no CPU-model-dependent estimate instruction
# (pbrlab.checking.codescan); renders under two llvmpipe code paths (128- and 256-bit vectors) are
# bit-identical (tests/render/test_cpu_independence.py). So with the same Mesa the bound
# only absorbs a different Mesa build reordering or contracting (FMA) a few float32
# operations. 1e-5 is ~84 float32 ulps at 1.0 and 30x below the smallest step an 8-bit sRGB
# display can show (3.04e-4 at black), so any visible change still fails. No pixel may
# exceed it. It is absolute: for HDR values above ~100 it is below one float32 ulp and acts
# as "bit-exact".
GOLDEN_TOLERANCE = Tolerance(
    max_abs=1e-5,
    max_fraction=0.0,
    reason="llvmpipe renders are bit-identical across x86-64 CPUs (pinned code generation, "
           "CPU-built mips, no estimate instructions); 1e-5 linear absorbs float32 reordering "
           "between Mesa builds and is 30x below one 8-bit sRGB step",
)

# Golden tolerance for the 8-bit sRGB PNG next to each EXR, in code values: the PNG is the
# exact encode (pbrlab.maths.srgb8) of the display values, so a linear difference inside
# GOLDEN_TOLERANCE can still cross one rounding boundary and move one code.
GOLDEN_SRGB_TOLERANCE = Tolerance(
    max_abs=1.0,
    max_fraction=0.0,
    reason="8-bit sRGB code values: a sub-tolerance linear change may cross one rounding "
           "boundary of the exact encode",
)

# Real GPUs: measured, not guessed. NVIDIA H200, driver 580.159.04, EGL (the GPU machine's
# run of scripts/gpu_golden_check.sh against the llvmpipe goldens; figures in docs/goldens.md):
# * untextured analytic charts: every pixel within 1e-3 + 1e-3 |expected| but 2e-5 of them,
#   relative error p99.9 <= 8.8e-5 (transcendental precision and FMA);
# * textured scenes (lit_scene_*): texture LOD selection and filtering differ from
#   llvmpipe, and alpha-tested leaf edges with them: 0.658 % of pixels over 1e-2 + 1e-2
#   |expected|, 0.157 % over 3e-2 + 3e-2 |expected|; display 0.667 % of pixels over 1 code,
#   mean FLIP 2.21e-3; the torture chart (1e4 sun) 0.301 % and FLIP 3.05e-4.
# The bounds sit 1.5x above the worst measured fraction and 2.3x above the worst FLIP: a
# changed material, light or texture binding moves far more pixels than 1 %, and FLIP
# catches a visible shift of the whole image.
GPU_TOLERANCE = Tolerance(
    max_abs=1e-2, max_rel=1e-2, max_fraction=0.01,
    reason="real GPU vs llvmpipe golden: measured on NVIDIA H200 (worst 0.658 % of pixels "
           "over 1e-2 + 1e-2|expected|, on textured scenes: LOD selection and filtering)",
)
GPU_SRGB_TOLERANCE = Tolerance(
    max_abs=1.0, max_fraction=0.01, max_flip=5e-3,
    reason="real GPU vs llvmpipe golden: measured on NVIDIA H200 (worst 0.667 % of pixels "
           "over 1 code, mean FLIP 2.21e-3)",
)


@dataclass(frozen=True)
class ToleranceProfile:
    """The pair of tolerances a golden is checked with on one class of renderer."""

    name: str
    linear: Tolerance
    srgb: Tolerance

    def to_dict(self) -> dict:
        return {"name": self.name,
                "linear": asdict(self.linear) | {"units": "linear"},
                "srgb": asdict(self.srgb) | {"units": "8-bit code values"}}


TOLERANCE_PROFILES = {
    "llvmpipe": ToleranceProfile("llvmpipe", GOLDEN_TOLERANCE, GOLDEN_SRGB_TOLERANCE),
    "gpu": ToleranceProfile("gpu", GPU_TOLERANCE, GPU_SRGB_TOLERANCE),
}


def profile_for_renderer(gl_renderer: str) -> ToleranceProfile:
    """``llvmpipe`` for Mesa's llvmpipe (the goldens' renderer), ``gpu`` for anything else."""
    return TOLERANCE_PROFILES["llvmpipe" if "llvmpipe" in gl_renderer else "gpu"]


def tolerance_profile(name: str, gl_renderer: str | None = None) -> ToleranceProfile:
    """A profile by name; ``auto`` picks by ``gl_renderer`` (profile_for_renderer)."""
    if name == "auto":
        if gl_renderer is None:
            raise ValueError("the 'auto' tolerance profile needs the GL_RENDERER string")
        return profile_for_renderer(gl_renderer)
    if name not in TOLERANCE_PROFILES:
        raise ValueError(f"unknown tolerance profile {name!r}; use auto or one of "
                         f"{', '.join(TOLERANCE_PROFILES)}")
    return TOLERANCE_PROFILES[name]


UNITS_LINEAR = "linear"
UNITS_CODES = "8-bit code values"

# Heatmap colours (see DiffResult.heatmap).
_HEAT_NONFINITE = (255, 0, 255)
_HEAT_DECADES = 4.0  # over-tolerance errors from 1x to 10^4 x the tolerance span the ramp


@dataclass(frozen=True)
class DiffResult:
    """Metrics of one comparison. ``passed`` is the verdict; the rest explains it.

    Attributes:
        max_abs: largest per-channel |obtained - expected| over pixels finite in both images
            (``units``); inf when the shapes differ.
        rmse: root mean square of the per-channel differences over the same finite pixels.
        fraction_over: the fraction of pixels that fail (over the tolerance's bound or
            non-finite in either image); ``pixels_over`` of ``pixel_count``.
        worst_pixel: (y, x) of the largest error, a non-finite pixel first; None if none.
        nonfinite_obtained: pixels with a NaN or Inf channel (``nonfinite_expected``: in the
            expected image).
        problem: "" or why the images could not be compared (shape mismatch).
        flip_mean: mean FLIP for 8-bit sRGB images when requested and available, else None.
    """

    passed: bool
    max_abs: float
    rmse: float
    fraction_over: float
    pixels_over: int
    pixel_count: int
    worst_pixel: tuple[int, int] | None
    nonfinite_obtained: int
    nonfinite_expected: int
    tolerance: Tolerance
    units: str
    shape_expected: tuple
    shape_obtained: tuple
    problem: str = ""
    flip_mean: float | None = None
    error: np.ndarray | None = field(default=None, repr=False, compare=False)

    def summary(self) -> str:
        """One line of metrics, for failure messages and the CLI."""
        if self.problem:
            return f"{self.problem} (cannot compare pixels)"
        where = f" at (y={self.worst_pixel[0]}, x={self.worst_pixel[1]})" if self.worst_pixel else ""
        text = (f"max abs {self.max_abs:.6g} {self.units}{where}, RMSE {self.rmse:.6g}, "
                f"{self.pixels_over} of {self.pixel_count} pixels ({100 * self.fraction_over:.4g}%) "
                f"over {self.tolerance.max_abs:g}"
                f"{f' + {self.tolerance.max_rel:g}|expected|' if self.tolerance.max_rel else ''} "
                f"(allowed {100 * self.tolerance.max_fraction:.4g}%)")
        if self.nonfinite_obtained or self.nonfinite_expected:
            text += (f", non-finite pixels: {self.nonfinite_obtained} obtained, "
                     f"{self.nonfinite_expected} expected")
        if self.flip_mean is not None:
            text += f", FLIP mean {self.flip_mean:.6g}"
        return text

    def to_dict(self) -> dict:
        """The metrics as JSON-ready values plus ``summary`` (no per-pixel data)."""
        data = asdict(self)
        data.pop("error")
        data["summary"] = self.summary()
        data["worst_pixel"] = list(self.worst_pixel) if self.worst_pixel else None
        data["shape_expected"] = list(self.shape_expected)
        data["shape_obtained"] = list(self.shape_obtained)
        for key in ("max_abs", "rmse"):  # JSON has no inf/nan
            if not np.isfinite(data[key]):
                data[key] = str(data[key])
        return data

    def heatmap(self) -> np.ndarray:
        """uint8 RGB picture of the per-pixel max abs error (H x W x 3).

        black: identical; blue, brighter with the error: within tolerance; red through
        yellow: over tolerance, log scale from 1x to 10^4 x ``tolerance.max_abs``;
        magenta: NaN or Inf. When the shapes differ, a magenta image of the expected size.
        """
        if self.error is None:
            height, width = self.shape_expected[:2]
            return np.broadcast_to(np.array(_HEAT_NONFINITE, np.uint8), (height, width, 3)).copy()
        err = self.error
        tol = self.tolerance.max_abs
        out = np.zeros(err.shape + (3,), np.uint8)
        nonfinite = ~np.isfinite(err)
        within = np.isfinite(err) & (err > 0) & (err <= tol)
        over = np.isfinite(err) & (err > tol)
        if tol > 0:
            out[within, 2] = (96 + 159 * err[within] / tol).astype(np.uint8)
            ratio = err[over] / tol
        else:  # every non-zero error is over; scale from the smallest one present
            ratio = err[over] / err[over].min() if over.any() else err[over]
        t = np.clip(np.log10(ratio) / _HEAT_DECADES, 0.0, 1.0)
        out[over, 0] = (160 + 95 * np.minimum(1.0, 2 * t)).astype(np.uint8)
        out[over, 1] = (255 * t).astype(np.uint8)
        out[nonfinite] = _HEAT_NONFINITE
        return out


def _as_hwc(image) -> np.ndarray:
    image = np.asarray(image)
    if image.ndim == 2:
        image = image[:, :, np.newaxis]
    if image.ndim != 3:
        raise ValueError(f"images must be HxW or HxWxC arrays, got shape {image.shape}")
    return image


def _kind(image: np.ndarray) -> str:
    if image.dtype == np.uint8:
        return UNITS_CODES
    if np.issubdtype(image.dtype, np.floating):
        return UNITS_LINEAR
    raise TypeError(f"images must be uint8 (sRGB code values) or float (linear), got {image.dtype}")


def _nonfinite_pixels(image: np.ndarray) -> np.ndarray:
    return ~np.isfinite(image).all(axis=2)


def float32_ulps(expected, obtained) -> np.ndarray:
    """|obtained - expected| in float32 spacings of ``expected`` (per element): how many
    float32 roundings apart two renders of the same thing are."""
    expected = np.asarray(expected, np.float32)
    spacing = np.spacing(np.maximum(np.abs(expected), np.float32(1e-30)))
    return np.abs(np.asarray(obtained, np.float32) - expected) / spacing


def flip_available() -> bool:
    try:
        import flip_evaluator  # noqa: F401
    except ImportError:
        return False
    return True


def flip_mean(expected: np.ndarray, obtained: np.ndarray) -> float | None:
    """Mean LDR FLIP of two 8-bit sRGB images (RGB channels), or None without flip-evaluator."""
    try:
        import flip_evaluator
    except ImportError:
        return None
    expected, obtained = _as_hwc(expected), _as_hwc(obtained)
    if expected.dtype != np.uint8 or obtained.dtype != np.uint8 or expected.shape != obtained.shape:
        raise ValueError("FLIP compares two 8-bit sRGB images of one shape")
    if expected.shape[2] < 3:
        expected = np.repeat(expected[:, :, :1], 3, axis=2)
        obtained = np.repeat(obtained[:, :, :1], 3, axis=2)
    reference = np.ascontiguousarray(expected[:, :, :3], dtype=np.float32) / 255.0
    test = np.ascontiguousarray(obtained[:, :, :3], dtype=np.float32) / 255.0
    _, mean, _ = flip_evaluator.evaluate(reference, test, "LDR", inputsRGB=True,
                                         applyMagma=False, computeMeanError=True)
    return float(mean)


def diff(expected, obtained, tolerance: Tolerance, *, flip: bool = False) -> DiffResult:
    """Compare ``obtained`` against ``expected`` (both HxW or HxWxC, top row first).

    ``flip=True`` adds the mean FLIP for 8-bit images when flip-evaluator is installed.
    """
    expected, obtained = _as_hwc(expected), _as_hwc(obtained)
    units = _kind(expected)
    if _kind(obtained) != units:
        raise TypeError(f"cannot compare {expected.dtype} (expected) with {obtained.dtype} "
                        "(obtained): compare 8-bit with 8-bit, float with float")
    nonfinite_obt = _nonfinite_pixels(obtained)
    nonfinite_exp = _nonfinite_pixels(expected)
    common = dict(tolerance=tolerance, units=units, shape_expected=tuple(expected.shape),
                  shape_obtained=tuple(obtained.shape),
                  nonfinite_obtained=int(nonfinite_obt.sum()),
                  nonfinite_expected=int(nonfinite_exp.sum()))
    if expected.shape != obtained.shape:
        count = expected.shape[0] * expected.shape[1]
        return DiffResult(
            passed=False, max_abs=float("inf"), rmse=float("inf"), fraction_over=1.0,
            pixels_over=count, pixel_count=count, worst_pixel=None,
            problem=(f"shape mismatch: expected {_shape_text(expected.shape)}, "
                     f"obtained {_shape_text(obtained.shape)}"),
            **common)

    with np.errstate(invalid="ignore", over="ignore"):
        delta = np.abs(obtained.astype(np.float64) - expected.astype(np.float64))
    finite = ~(nonfinite_obt | nonfinite_exp)
    pixel_error = np.where(finite, delta.max(axis=2), np.inf)  # non-finite pixels: inf
    with np.errstate(invalid="ignore", over="ignore"):
        allowed = tolerance.max_abs + tolerance.max_rel * np.abs(expected.astype(np.float64))
        over_bound = (delta > allowed).any(axis=2)
    finite_delta = delta[finite]
    max_abs = float(finite_delta.max()) if finite_delta.size else 0.0
    rmse = float(np.sqrt(np.mean(finite_delta ** 2))) if finite_delta.size else 0.0
    failing = ~finite | over_bound
    pixels_over = int(failing.sum())
    pixel_count = int(pixel_error.size)
    fraction_over = pixels_over / pixel_count if pixel_count else 0.0
    worst_pixel = None
    if pixel_count and pixel_error.max() > 0:
        y, x = np.unravel_index(int(np.argmax(pixel_error)), pixel_error.shape)
        worst_pixel = (int(y), int(x))
    passed = bool(common["nonfinite_obtained"] == 0 and fraction_over <= tolerance.max_fraction)
    flip_decides = tolerance.max_flip is not None and units == UNITS_CODES
    flip_value = flip_mean(expected, obtained) if ((flip or flip_decides) and units == UNITS_CODES) else None
    if flip_decides:
        if flip_value is None:
            raise RuntimeError("this tolerance bounds FLIP, which needs the flip-evaluator package")
        passed = passed and flip_value <= tolerance.max_flip
    return DiffResult(passed=passed, max_abs=max_abs, rmse=rmse, fraction_over=fraction_over,
                      pixels_over=pixels_over, pixel_count=pixel_count, worst_pixel=worst_pixel,
                      flip_mean=flip_value, error=pixel_error, **common)


def _shape_text(shape) -> str:
    return f"{shape[1]}x{shape[0]} with {shape[2]} channel{'s' if shape[2] != 1 else ''}"
