"""Mesa's shader disk cache is kept apart per llvmpipe code path (pbrlab.gpu.gl's module doc):
Mesa 22.3 keys a cached binary by the program's text, not by LP_NATIVE_VECTOR_WIDTH or
GALLIUM_OVERRIDE_CPU_CAPS, and a 256-bit binary loaded by a 128-bit process made the
specialised and full programs differ by 2 ulp (tests/render/specialisation)."""

from __future__ import annotations

import os
import subprocess
import sys

_PRINT_FOLDER = ("import os; from pbrlab.gpu import gl; gl.shared_context(); "
                 "print(os.environ.get('MESA_SHADER_CACHE_DIR'))")


def _folder(tmp_path, **env) -> str:
    clean = {k: v for k, v in os.environ.items()
             if k not in ("MESA_SHADER_CACHE_DIR", "MESA_GLSL_CACHE_DIR", "LP_NATIVE_VECTOR_WIDTH")}
    out = subprocess.run([sys.executable, "-c", _PRINT_FOLDER], env={**clean, "XDG_CACHE_HOME": str(tmp_path), **env},
                         check=True, capture_output=True, text=True)
    return out.stdout.strip().splitlines()[-1]


def test_each_code_path_has_its_own_cache_folder(tmp_path):
    narrow, wide = _folder(tmp_path, LP_NATIVE_VECTOR_WIDTH="128"), _folder(tmp_path, LP_NATIVE_VECTOR_WIDTH="256")
    assert narrow != wide
    assert narrow.startswith(str(tmp_path)) and wide.startswith(str(tmp_path))


def test_a_folder_the_caller_names_is_kept(tmp_path):
    """Control: the caller's own MESA_SHADER_CACHE_DIR is not replaced."""
    mine = str(tmp_path / "mine")
    assert _folder(tmp_path, MESA_SHADER_CACHE_DIR=mine, LP_NATIVE_VECTOR_WIDTH="256") == mine


def test_the_folder_is_made_on_a_machine_without_a_cache_folder(tmp_path):
    """Mesa creates only the last folder of the path: with no ~/.cache (a fresh CI machine) it
    printed "Failed to create ... for shader cache" and disabled the cache. The factory makes
    the whole path; the control is the same path's parent, absent before."""
    home = tmp_path / "fresh" / ".cache"
    assert not home.parent.exists()
    out = subprocess.run([sys.executable, "-c", _PRINT_FOLDER], capture_output=True, text=True, check=True,
                         env={**{k: v for k, v in os.environ.items()
                                 if k not in ("MESA_SHADER_CACHE_DIR", "MESA_GLSL_CACHE_DIR")},
                              "XDG_CACHE_HOME": str(home)})
    folder = out.stdout.strip().splitlines()[-1]
    assert folder.startswith(str(home)) and os.path.isdir(folder)
    assert "Failed to create" not in out.stderr
