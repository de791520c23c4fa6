"""The golden store: reference renders that tests diff against, changed only on request.

A golden named ``NAME`` (letters, digits, ``_ . -``; ``/`` makes sub-folders) is three
files under the golden root (``goldens/`` at the repository root by default):

* ``NAME.exr``  linear float32 render, lossless: what the tests diff (``GOLDEN_TOLERANCE``);
* ``NAME.png``  the exact 8-bit sRGB encode of the same render: what people look at, also
  diffed, in code values (``GOLDEN_SRGB_TOLERANCE``);
* ``NAME.json`` sidecar: the renderer that made it (GL_RENDERER, GL_VERSION, Mesa,
  moderngl, OpenImageIO, llvmpipe CPU caps, as the caller passes them), the tolerance
  profile it was made and checked with (``tolerance_profile``, see
  ``pbrlab.checking.compare.TOLERANCE_PROFILES``) and every profile's numbers.

Which tolerances a check uses: explicit ``tolerance`` / ``srgb_tolerance`` arguments, else
those of ``profile`` (default ``auto``: ``llvmpipe`` when ``info['GL_RENDERER']`` is
llvmpipe or absent, ``gpu`` otherwise).

``check_golden`` writes goldens only when ``update`` is true; a missing golden fails and
says how to create it; a mismatch leaves ``expected.png``, ``obtained.png``, ``diff.png``
and ``obtained.exr`` under ``output_dir/NAME/`` and fails with the metrics. Failures are
``GoldenFailure`` (an ``AssertionError``), so pytest reports them as test failures.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from ..foundation import images, outputs
from .compare import (GOLDEN_SRGB_TOLERANCE, GOLDEN_TOLERANCE, TOLERANCE_PROFILES, DiffResult, Tolerance, ToleranceProfile, diff, tolerance_profile)
from ..foundation.errors import PbrlabError
from ..foundation.golden_names import DEFAULT_OUTPUT_DIR, DEFAULT_ROOT  # noqa: F401 (public here too)

SIDECAR_FORMAT = "pbrlab-golden/1"
# The pytest option of pbrlab's plugin that writes goldens; hints name it, not a Makefile.
UPDATE_OPTION = "--update-goldens"
ARTEFACTS = ("expected.png", "obtained.png", "diff.png", "obtained.exr")

_NAME_PART = r"[A-Za-z0-9_][A-Za-z0-9_.-]*"
_NAME = re.compile(rf"^{_NAME_PART}(/{_NAME_PART})*$")

__all__ = ["GOLDEN_TOLERANCE", "GOLDEN_SRGB_TOLERANCE", "GoldenFailure", "GoldenMissing",
           "GoldenMismatch", "GoldenNonFinite", "GoldenPaths", "golden_paths", "check_golden"]


class GoldenFailure(AssertionError):
    """A golden check failed. ``kind`` is 'missing', 'mismatch' or 'nonfinite'.

    ``linear`` / ``srgb`` hold the DiffResults (None where no comparison ran),
    ``artefacts`` maps 'expected', 'obtained', 'diff', 'obtained_exr' to the files written,
    and ``figures`` is the message without the how-to-update hint (for tools that are not
    pytest, such as ``pbrlab demo``).
    """

    kind = "failure"

    def __init__(self, message: str, *, name: str, paths: "GoldenPaths",
                 linear: DiffResult | None = None, srgb: DiffResult | None = None,
                 artefacts: dict[str, Path] | None = None, figures: str | None = None):
        super().__init__(message)
        self.figures = figures or message
        self.name = name
        self.paths = paths
        self.linear = linear
        self.srgb = srgb
        self.artefacts = dict(artefacts or {})


class GoldenMissing(GoldenFailure):
    kind = "missing"


class GoldenMismatch(GoldenFailure):
    kind = "mismatch"


class GoldenNonFinite(GoldenFailure):
    """``--update-goldens`` refused an image holding NaN or Inf."""

    kind = "nonfinite"


@dataclass(frozen=True)
class GoldenPaths:
    exr: Path
    png: Path
    sidecar: Path

    def all(self) -> tuple[Path, Path, Path]:
        return (self.exr, self.png, self.sidecar)


def validate_name(name: str) -> str:
    if not isinstance(name, str) or not _NAME.match(name) or ".." in name.split("/"):
        raise PbrlabError(
            f"golden name {name!r} is not usable: use letters, digits and _ . - "
            "with / between sub-folders")
    return name


def golden_paths(root, name: str) -> GoldenPaths:
    base = Path(root) / validate_name(name)
    return GoldenPaths(base.with_name(base.name + ".exr"), base.with_name(base.name + ".png"),
                       base.with_name(base.name + ".json"))


def _display(path: Path) -> str:
    """A path as a person at the repository root would type it."""
    try:
        return os.path.relpath(path)
    except ValueError:  # another drive on Windows
        return str(path)


def _mkdir(folder: Path) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise PbrlabError(f"cannot create directory {folder}: {exc.strerror or exc}") from None


def _sidecar(name, linear, srgb8, tolerance, srgb_tolerance, info, profile) -> str:
    data = {
        "format": SIDECAR_FORMAT,
        "name": name,
        "shape": list(linear.shape),
        "srgb_shape": list(srgb8.shape),
        "tolerance_profile": profile.name,
        "tolerance": asdict(tolerance) | {"units": "linear"},
        "srgb_tolerance": asdict(srgb_tolerance) | {"units": "8-bit code values"},
        "tolerance_profiles": {p.name: p.to_dict() for p in TOLERANCE_PROFILES.values()},
        "renderer": info,
    }
    return json.dumps(data, indent=2, sort_keys=True, default=str) + "\n"


def _remove_artefact_files(folder: Path) -> None:
    for artefact in ARTEFACTS:
        try:
            (folder / artefact).unlink()
        except FileNotFoundError:
            pass


def _remove_artefacts(folder: Path) -> None:
    """Drop artefacts of an earlier failed run, so test-output never shows a stale failure."""
    _remove_artefact_files(folder)
    try:
        folder.rmdir()
    except OSError:  # absent, or holds files pbrlab did not write: leave it
        pass


def _hint(nodeid: str | None) -> str:
    target = f" '{nodeid}'" if nodeid else ""
    return (f"rerun pytest with the option {UPDATE_OPTION} (pbrlab's pytest plugin), "
            f"for this test alone:\n"
            f"    python -m pytest {UPDATE_OPTION}{target}")


def _check_inputs(linear, srgb8) -> tuple[np.ndarray, np.ndarray]:
    linear = np.asarray(linear)
    srgb8 = np.asarray(srgb8)
    if not np.issubdtype(linear.dtype, np.floating):
        raise ValueError(f"the linear image must be float, got {linear.dtype}")
    if srgb8.dtype != np.uint8:
        raise ValueError(f"the sRGB image must be uint8 code values, got {srgb8.dtype}")
    linear = linear.astype(np.float32, copy=False)
    if linear.ndim == 2:
        linear = linear[:, :, np.newaxis]
    if srgb8.ndim == 2:
        srgb8 = srgb8[:, :, np.newaxis]
    if linear.ndim != 3 or srgb8.ndim != 3 or linear.shape[:2] != srgb8.shape[:2]:
        raise ValueError(f"linear {linear.shape} and sRGB {srgb8.shape} images must be HxWxC "
                         "arrays of one size")
    return linear, srgb8


def resolve_profile(profile: "str | ToleranceProfile", info: dict) -> ToleranceProfile:
    """The profile a check uses: by name, or ``auto`` from ``info['GL_RENDERER']``."""
    if isinstance(profile, ToleranceProfile):
        return profile
    try:
        return tolerance_profile(profile, info.get("GL_RENDERER", "llvmpipe"))
    except ValueError as exc:
        raise PbrlabError(str(exc)) from None


def check_golden(name: str, linear, srgb8, tolerance: Tolerance | None = None,
                 info: dict | None = None, *, update: bool, root=DEFAULT_ROOT,
                 output_dir=DEFAULT_OUTPUT_DIR,
                 srgb_tolerance: Tolerance | None = None,
                 nodeid: str | None = None,
                 profile: "str | ToleranceProfile" = "auto") -> DiffResult:
    """Check a render against golden ``name``, or store it as the golden when ``update``.

    ``linear`` is the float render (HxWxC), ``srgb8`` its 8-bit sRGB encode (same HxW).
    Returns the linear DiffResult (against itself when updating). Raises GoldenMissing,
    GoldenMismatch or GoldenNonFinite (AssertionErrors) on failure, PbrlabError when a
    file cannot be read or written. ``nodeid`` only improves the how-to-create hint.
    """
    __tracebackhide__ = True  # pytest: show the caller's line and this message, not our code
    linear, srgb8 = _check_inputs(linear, srgb8)
    paths = golden_paths(root, name)
    artefact_dir = Path(output_dir) / name
    info = dict(info or {})
    profile = resolve_profile(profile, info)
    tolerance = tolerance or profile.linear
    srgb_tolerance = srgb_tolerance or profile.srgb

    if update:
        bad = int((~np.isfinite(linear).all(axis=2)).sum())
        if bad:
            artefacts = _write_obtained(artefact_dir, linear, srgb8)
            raise GoldenNonFinite(
                f"golden {name!r} not written: the render has {bad} pixel(s) with NaN or Inf; "
                f"see {_display(artefacts['obtained_exr'])}",
                name=name, paths=paths, artefacts=artefacts)
        _mkdir(paths.exr.parent)
        with outputs.transaction(paths.all()) as tx:  # EXR, PNG and JSON: all three or none
            images.write_exr(paths.exr, linear, {"golden": name, **info}, tx=tx)
            images.write_png(paths.png, srgb8, tx=tx)
            tx.write_text(paths.sidecar, _sidecar(name, linear, srgb8, tolerance, srgb_tolerance, info,
                                                  profile))
        _remove_artefacts(artefact_dir)
        return diff(linear, linear, tolerance)

    missing = [p for p in paths.all() if not p.exists()]
    if missing:
        artefacts = _write_obtained(artefact_dir, linear, srgb8)
        raise GoldenMissing(
            f"golden {name!r} is missing ({', '.join(_display(p) for p in missing)} not found).\n"
            f"Goldens are written only on request: create it, look at the new files and "
            f"commit them:\n{_hint(nodeid)}\n"
            f"The render that would be stored is {_display(artefacts['obtained'])}.",
            name=name, paths=paths, artefacts=artefacts,
            figures=f"golden {name!r} is missing ({', '.join(_display(p) for p in missing)} "
                    f"not found); the render is {_display(artefacts['obtained'])}")

    expected_linear = images.read_image(paths.exr)
    expected_srgb = images.read_image(paths.png)
    if expected_linear.dtype != np.float32 or expected_srgb.dtype != np.uint8:
        raise PbrlabError(f"golden {name!r} is damaged: {_display(paths.exr)} must be a float "
                          f"EXR and {_display(paths.png)} an 8-bit PNG")
    linear_result = diff(expected_linear, linear, tolerance)
    srgb_result = diff(expected_srgb, srgb8, srgb_tolerance)
    if linear_result.passed and srgb_result.passed:
        _remove_artefacts(artefact_dir)
        return linear_result

    srgb_result = diff(expected_srgb, srgb8, srgb_tolerance, flip=srgb_result.problem == "")
    artefacts = _write_obtained(artefact_dir, linear, srgb8)
    artefacts["expected"] = artefact_dir / "expected.png"
    images.write_png(artefacts["expected"], expected_srgb)
    artefacts["diff"] = artefact_dir / "diff.png"
    shown = linear_result if not linear_result.passed else srgb_result
    images.write_png(artefacts["diff"], shown.heatmap())
    figures = (
        f"golden {name!r} does not match {_display(paths.exr)} "
        f"(tolerance profile {profile.name})\n"
        f"  linear EXR  {'ok  ' if linear_result.passed else 'FAIL'}  {linear_result.summary()}\n"
        f"              tolerance {tolerance.describe('linear')}\n"
        f"  sRGB PNG    {'ok  ' if srgb_result.passed else 'FAIL'}  {srgb_result.summary()}\n"
        f"              tolerance {srgb_tolerance.describe('code values')}\n"
        f"  expected / obtained / diff: {_display(artefact_dir)}/"
        f"{{expected,obtained,diff}}.png, obtained.exr")
    raise GoldenMismatch(
        f"{figures}\n"
        f"If the change is intended, update the golden and review it before committing:\n"
        f"{_hint(nodeid)}",
        name=name, paths=paths, linear=linear_result, srgb=srgb_result, artefacts=artefacts,
        figures=figures)


def _write_obtained(folder: Path, linear: np.ndarray, srgb8: np.ndarray) -> dict[str, Path]:
    _mkdir(folder)
    _remove_artefact_files(folder)
    artefacts = {"obtained": folder / "obtained.png", "obtained_exr": folder / "obtained.exr"}
    images.write_png(artefacts["obtained"], srgb8)
    images.write_exr(artefacts["obtained_exr"], linear)
    return artefacts

