"""GLSL -> WGSL with naga, the shader translator of wgpu, Bevy and Firefox's WebGPU.

    wgsl = glsl_to_wgsl(glsl_text, stage="frag", name="sphere.frag.glsl")

naga-cli is pinned (NAGA_VERSION) and installed by scripts/setup.sh into tools/naga with
``cargo install --locked``; ``$PBRLAB_NAGA`` names another binary. naga's GLSL front end reads
Vulkan GLSL 450 (``layout(set, binding)`` resources, ``texture2D`` + ``sampler``); it runs its
own preprocessor (pp-rs), which rejects a quote character anywhere in the text, even in a
skipped ``#if`` branch or an ``#error`` line: the library's ``#error`` messages are bare for
it (harness/pbrlab/gpu/port_hlsl.py, rule 6). It validates the module before it writes WGSL, so
a translation that succeeds is a valid WGSL module.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from ..foundation.errors import PbrlabError, ShaderCompileError

NAGA_VERSION = "30.0.1"  # scripts/setup.sh installs this one
_CHECKOUT_NAGA = Path(__file__).resolve().parents[3] / "tools" / "naga" / "bin" / "naga"
_INSTALL_HINT = f"cargo install --locked naga-cli --version {NAGA_VERSION}, or set $PBRLAB_NAGA " \
                "(in a pbrlab checkout, scripts/setup.sh installs it into tools/naga)"
_TIMEOUT_S = 60
_ANSI = re.compile(r"\x1b\[[0-9;]*m")


def naga_binary() -> str:
    """The naga executable: $PBRLAB_NAGA, the checkout's tools/naga, or naga on PATH."""
    for candidate in (os.environ.get("PBRLAB_NAGA"), str(_CHECKOUT_NAGA), shutil.which("naga")):
        if candidate and Path(candidate).is_file() and os.access(candidate, os.X_OK):
            return candidate
    raise PbrlabError(f"naga (naga-cli {NAGA_VERSION}) is not installed: {_INSTALL_HINT}")


def naga_version(binary: str | None = None) -> str:
    """The version naga reports (``naga --version``: the crate's version)."""
    out = subprocess.run([binary or naga_binary(), "--version"], capture_output=True, text=True,
                         timeout=_TIMEOUT_S)
    return out.stdout.strip()


def glsl_to_wgsl(glsl: str, stage: str = "frag", name: str = "<glsl>") -> str:
    """naga's WGSL for one GLSL shader (a complete program with its ``main``); a rejection is a
    ShaderCompileError with naga's message, naming ``name``."""
    binary = naga_binary()
    with tempfile.TemporaryDirectory(prefix="pbrlab-naga-") as tmp:
        source, target = Path(tmp) / f"shader.{stage}", Path(tmp) / "shader.wgsl"
        source.write_text(glsl, encoding="utf-8")
        run = subprocess.run([binary, "--input-kind", "glsl", "--shader-stage", stage, str(source), str(target)],
                             capture_output=True, text=True, timeout=_TIMEOUT_S)
        if run.returncode != 0 or not target.is_file():
            message = _ANSI.sub("", (run.stderr or run.stdout)).strip().replace(str(source), name)
            raise ShaderCompileError(f"{name}: naga {NAGA_VERSION} could not translate it to WGSL:\n{message}")
        return target.read_text(encoding="utf-8")
