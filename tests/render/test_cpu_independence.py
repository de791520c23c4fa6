"""Goldens hold on every x86-64 CPU: proven on one machine, without owning both vendors.

Where can two CPUs make llvmpipe compute different bits? Only in instructions whose result
the ISA leaves to the CPU model: the reciprocal (square-root) estimates RSQRTPS/RCPPS and
kin. llvmpipe uses RSQRTPS in its float -> sRGB8 encode (texture mip generation, sRGB
framebuffers) with 128-bit vectors, and SQRTPS for the same encode with 256-bit vectors
under the pinned SSE4.1 caps. So:

* every golden scene is rendered under both code paths (LP_NATIVE_VECTOR_WIDTH 128 and 256)
  and must be bit-identical, EXR and PNG; a control shows the switch really changes what a
  vendor could change (glGenerateMipmap of an sRGB texture differs between the two paths);
* the JIT code of every golden scene is disassembled stage by stage (pbrlab.checking.codescan) and
  must hold no estimate instruction; the controls must hold them (or the scan is blind).
"""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from pbrlab.foundation import images
from pbrlab.checking.golden_scenes import GOLDEN_SCENES

VECTOR_WIDTHS = ("128", "256")


def _run(args, width, **kwargs):
    env = dict(os.environ, LP_NATIVE_VECTOR_WIDTH=width)
    return subprocess.run([sys.executable, *args], env=env, check=True, capture_output=True,
                          text=True, **kwargs)


@pytest.fixture(scope="module")
def renders_per_width(tmp_path_factory):
    root = tmp_path_factory.mktemp("code_paths")
    for width in VECTOR_WIDTHS:
        _run(["-m", "pbrlab.checking.golden_scenes", str(root / width)], width)
    return root


@pytest.mark.parametrize("name", sorted(GOLDEN_SCENES))
def test_golden_scene_is_bit_identical_on_both_llvmpipe_code_paths(name, renders_per_width):
    narrow, wide = (renders_per_width / width for width in VECTOR_WIDTHS)
    for suffix in ("exr", "png"):
        a = images.read_image(narrow / f"{name}.{suffix}")
        b = images.read_image(wide / f"{name}.{suffix}")
        assert a.shape == b.shape and a.dtype == b.dtype
        differing = int((a.view(np.uint8) != b.view(np.uint8)).any(axis=-1).sum())
        assert differing == 0, f"{name}.{suffix}: {differing} pixels differ between 128- and 256-bit code"


_MIPMAP_CONTROL = """
import numpy as np, sys
from pbrlab.gpu import gl, targets
ctx = gl.shared_context()
data = (np.arange(64 * 64 * 4) * 2654435761 % 251).astype(np.uint8)
tex = ctx.texture((64, 64), 4, data.tobytes(), internal_format=targets.GL_SRGB8_ALPHA8)
tex.build_mipmaps()
sys.stdout.write(b"".join(tex.read(level=l) for l in range(1, 7)).hex())
"""


def test_control_the_two_code_paths_differ_where_a_cpu_vendor_could():
    """glGenerateMipmap's sRGB encode (RSQRTPS at 128 bits, SQRTPS at 256) gives other codes
    on the two paths: the test above compares paths that differ where vendors differ."""
    levels = [bytes.fromhex(_run(["-c", _MIPMAP_CONTROL], width).stdout) for width in VECTOR_WIDTHS]
    narrow, wide = (np.frombuffer(level, np.uint8).astype(int) for level in levels)
    assert np.abs(narrow - wide).max() == 1
    assert (narrow != wide).sum() >= 10  # measured: 90 of 5460 codes differ


@pytest.fixture(scope="module")
def code_scan():
    result = _run(["-m", "pbrlab.checking.codescan", "--json"], "128", timeout=600)
    return json.loads(result.stdout)


def test_scan_finds_the_estimate_instructions_in_the_controls(code_scan):
    for stage, data in code_scan["controls"].items():
        assert data["approximate"].get("rsqrtps", 0) > 0, stage


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("name", sorted(GOLDEN_SCENES))
def test_golden_scene_code_holds_no_estimate_instruction(name, language, code_scan):
    stages = code_scan[name if language == "glsl" else f"{name}:hlsl"]
    assert sum(data["instructions"] for data in stages.values()) > 1000  # the scan saw code
    for stage, data in stages.items():
        assert data["approximate"] == {}, f"{name}, {stage}: {data['approximate_at']}"
