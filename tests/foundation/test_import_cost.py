"""What start-up imports, checked by structure, not by time (issue 25; the times are measured by
benchmarks/startup.py): each check runs a fresh Python and reads ``sys.modules``."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pbrlab

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("numpy", "moderngl", "OpenImageIO", "trimesh", "scipy", "PIL", "pyrender", "networkx")


def loaded_after(code: str, env_extra: dict | None = None) -> list[str]:
    """The heavy packages in sys.modules after running ``code`` in a fresh interpreter."""
    probe = f"{code}\nimport sys, json\nprint(json.dumps(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r}))))"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(Path(pbrlab.__file__).parents[1]),
                                                       os.environ.get("PYTHONPATH", "")]))
    env.update(env_extra or {})
    result = subprocess.run([sys.executable, "-c", probe], env=env, check=True, capture_output=True,
                            text=True, cwd=ROOT)
    return json.loads(result.stdout.strip().splitlines()[-1])


def test_the_pytest_plugin_module_imports_nothing_heavy():
    """Every pytest run of an environment with pbrlab installed loads the plugin: it must not
    load numpy, moderngl or OpenImageIO (0.18 s before), only pytest's own modules."""
    assert loaded_after("import pytest\nimport pbrlab.checking.pytest_plugin") == []


def test_import_pbrlab_and_the_cli_parser_load_no_mesh_or_gl_libraries():
    assert loaded_after("import pbrlab") == []
    assert loaded_after("import pbrlab.commands.cli") == ["moderngl"]  # --backend's choices
    assert "trimesh" not in loaded_after("from pbrlab.commands import cli\ncli.build_parser(['render'])")


def test_evaluate_is_still_there_on_first_use():
    assert "moderngl" in loaded_after("import pbrlab\npbrlab.evaluate")


def test_a_render_without_mesh_files_or_cached_meshes_never_imports_trimesh(tmp_path):
    """The lit example's meshes come from the disk cache after the first run; a scene of
    spheres needs no mesh at all. Neither imports trimesh (0.7 s with scipy) nor the glTF reader."""
    cache = {"PBRLAB_CACHE_DIR": str(tmp_path / "cache")}
    lit = ROOT / "scenes" / "unity_example" / "scene.json"
    render = f"from pbrlab.commands import cli\nassert cli.main(['render', {str(lit)!r}, '-o', {str(tmp_path / 'a.png')!r}, '--size', '16x16', '-q']) == 0"
    first = loaded_after(render, cache)
    assert "trimesh" in first  # the control: an empty cache reads the OBJ and primitives with trimesh
    again = loaded_after(render + "\nimport sys\nassert 'pbrlab.importers.gltf' not in sys.modules", cache)
    assert "trimesh" not in again and "scipy" not in again
    spheres = tmp_path / "spheres.json"
    spheres.write_text(json.dumps({"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "size": [8, 8]},
                                   "materials": {"m": {}},
                                   "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}))
    code = (f"from pbrlab.commands import cli\nassert cli.main(['render', {str(spheres)!r}, '-o', "
            f"{str(tmp_path / 'b.png')!r}, '-q']) == 0\nimport sys\nassert 'pbrlab.importers.gltf' not in sys.modules")
    assert "trimesh" not in loaded_after(code, {"PBRLAB_CACHE_DIR": "off"})
