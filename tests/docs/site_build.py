"""Building the documentation site from a test: the command (``python -m mkdocs build
--strict``, with the interpreter running the tests) and a copy of what the build reads, for
the tests that change a page to show the build fails."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# What the site build reads besides docs/ (mkdocs.yml): the files it includes, glsl/ (the
# library-files page is written from its headers), the hooks, and the goldens the pages show.
# Not harness/: a copy of the package away from glsl/ and hlsl_ports/ would not find its
# shaders, so the copy's build reads the package this interpreter imports (the CLI reference
# from its parser; mkdocstrings finds it on sys.path when the copy has no harness/).
SITE_SOURCES = ["mkdocs.yml", "scripts/mkdocs_hooks.py", "scripts/mkdocs_cli_reference.py",
                "scripts/mkdocs_goldens.py", "docs", "README.md", "glsl", "scenes/example.json",
                "goldens"]
COMMAND_TIMEOUT_S = 300


def env() -> dict:
    """This process's environment for a child, less pytest's own variables (an xdist worker's
    would leak into the child's run), with this interpreter's folder first on PATH, so that
    ``python`` in a snippet is the interpreter running these tests."""
    out = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_")}
    out["PATH"] = os.pathsep.join([str(Path(sys.executable).parent), out.get("PATH", "")])
    # Material for MkDocs 9.x's end-of-life notice (mkdocs.yml's header says why the site stays
    # on it); its own switch, so the logs a failure prints start with the failure.
    out["NO_MKDOCS_2_WARNING"] = "1"
    return out


def run(args, cwd: Path) -> subprocess.CompletedProcess:
    if args[0] == "python":
        args = [sys.executable, *args[1:]]
    return subprocess.run(args, cwd=cwd, env=env(), capture_output=True, text=True,
                          timeout=COMMAND_TIMEOUT_S)


def mkdocs_build(config: Path, site: Path) -> subprocess.CompletedProcess:
    return run(["python", "-m", "mkdocs", "build", "--strict", "--config-file", str(config),
                "--site-dir", str(site)], config.parent)


def copy_site_sources(where: Path) -> None:
    """What the build reads, copied under ``where`` (the goldens' pictures only)."""
    for name in SITE_SOURCES:
        source, copy = ROOT / name, where / name
        copy.parent.mkdir(parents=True, exist_ok=True)
        if source.is_dir():
            skip = shutil.ignore_patterns("__pycache__", "*.exr", "*.json") if name == "goldens" else \
                shutil.ignore_patterns("__pycache__", "*.egg-info")
            shutil.copytree(source, copy, ignore=skip)
        else:
            shutil.copy(source, copy)
