"""Where the shader library, its HLSL twins, its WGSL amalgamation and the example scenes are: the one place that decides.

Each tree is looked up in this order:
  1. an environment variable naming the folder (``PBRLAB_GLSL_ROOT``, ``PBRLAB_HLSL_ROOT``,
     ``PBRLAB_WGSL_ROOT``, ``PBRLAB_SCENES_ROOT``), for a library being edited elsewhere;
  2. the package data of an installed wheel, ``pbrlab/data/<tree>`` in the package
     (setup.py copies ``glsl/``, ``hlsl_ports/``, ``wgsl/`` and ``scenes/`` there);
  3. the checkout this module sits in (``<repo>/<tree>``), for an editable install.

``pbrlab paths`` and ``pbrlab --version`` print the answers.
"""

from __future__ import annotations

import os
from pathlib import Path

from .errors import PbrlabError

# tree name (the folder in the checkout and under pbrlab/data/ in a wheel) -> environment override
TREES = {"glsl": "PBRLAB_GLSL_ROOT", "hlsl_ports": "PBRLAB_HLSL_ROOT", "wgsl": "PBRLAB_WGSL_ROOT",
         "scenes": "PBRLAB_SCENES_ROOT"}
PACKAGE_DATA = "data"
# The package's folder. Not importlib.resources.files("pbrlab"): only a folder on disk counts
# here (below), and resources loads importlib.readers and zipfile, 10 ms of every start-up.
PACKAGE_FOLDER = Path(__file__).resolve().parents[1]


def _packaged(tree: str) -> Path | None:
    candidate = PACKAGE_FOLDER / PACKAGE_DATA / tree
    # An installed wheel is a folder on disk; the compilers need real files, so a zipped
    # install (where this is no folder) does not count.
    if candidate.is_dir():
        return candidate
    return None


def locate(tree: str) -> Path:
    """The folder holding ``tree`` ('glsl', 'hlsl_ports', 'wgsl' or 'scenes'), by the order above."""
    if tree not in TREES:
        raise ValueError(f"unknown tree {tree!r}; expected one of {', '.join(TREES)}")
    override = os.environ.get(TREES[tree])
    if override:
        return Path(override)
    packaged = _packaged(tree)
    if packaged is not None:
        return packaged
    checkout = Path(__file__).resolve().parents[3] / tree
    if checkout.is_dir():
        return checkout
    raise PbrlabError(f"cannot find pbrlab's {tree}/ folder: it is neither package data of the "
                      f"installed pbrlab nor beside a checkout; set {TREES[tree]} to its path "
                      f"or reinstall pbrlab from a wheel or sdist")


def engine_snippets() -> Path:
    """The folder of the engine snippets that sample the tables (``examples/engine``): package
    data in a wheel (setup.py copies it there), else the checkout's."""
    for candidate in (PACKAGE_FOLDER / PACKAGE_DATA / "examples" / "engine",
                      Path(__file__).resolve().parents[3] / "examples" / "engine"):
        if candidate.is_dir():
            return candidate
    raise PbrlabError("cannot find pbrlab's examples/engine/ folder: it is neither package data of the "
                      "installed pbrlab nor beside a checkout; reinstall pbrlab from a wheel or sdist")


def checkout_folder(name: str) -> Path | None:
    """A folder of the checkout this module sits in (``<repo>/<name>``, e.g. ``goldens``), or
    None in an installed wheel, which ships no such folder."""
    folder = Path(__file__).resolve().parents[3] / name
    return folder if folder.is_dir() and (folder.parent / "harness" / "pbrlab").is_dir() else None


def origin(tree: str) -> str:
    """How ``locate(tree)`` found it: 'environment', 'package data' or 'checkout'."""
    if os.environ.get(TREES[tree]):
        return f"${TREES[tree]}"
    return "package data" if _packaged(tree) is not None else "checkout"
