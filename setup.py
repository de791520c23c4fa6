"""Build hook: the wheel carries the shader library, its HLSL twins, its WGSL amalgamation, the example
scenes and the engine snippet that samples the tables (examples/engine/).

``glsl/``, ``hlsl_ports/``, ``wgsl/`` and ``scenes/`` sit at the top of the repository (engines copy them
from there); ``build_py`` copies them into the package as ``pbrlab/data/<tree>``, where
``pbrlab.foundation.locations`` finds them through ``importlib.resources``. Everything else about the
package is declared in pyproject.toml.
"""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
DATA_TREES = ("glsl", "hlsl_ports", "wgsl", "scenes", "examples/engine")  # examples/engine: `pbrlab tables` copies it out


class build_py_with_shaders(build_py):
    def run(self):
        super().run()
        for tree in DATA_TREES:
            source = HERE / tree
            if not source.is_dir():
                raise SystemExit(f"setup.py: {tree}/ is missing; build from a checkout or a complete sdist")
            target = Path(self.build_lib) / "pbrlab" / "data" / tree
            shutil.rmtree(target, ignore_errors=True)
            shutil.copytree(source, target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))


setup(cmdclass={"build_py": build_py_with_shaders})
