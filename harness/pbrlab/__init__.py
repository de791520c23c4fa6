"""pbrlab: the headless harness that proves the pbrlab GLSL/HLSL shading library.

The package's folders are its layers, bottom up; a module imports only from its own layer or
the ones below it (docs/layers.md, tests/foundation/test_layers.py):
  foundation  errors, locations, console, outputs, the disk cache, JSON input, images
  maths       the float64 references of the library's formulas, sRGB, camera, exposure
  gpu         the GL context, shader sources and includes, programs, targets, the evaluator,
              the IBL tables, the HLSL port, the AMD instruction counter
  scene       the scene model, its fields and schema, meshes, the environment, the material
              interface (material_passes)
  importers   glTF, Unity shaders, and the loader that picks one
  render      what a material uses (features), resources, the renderer, the CPU renderer
  checking    comparison, goldens and the pytest plugin, cross-checks, corpora, hard cases
  bench       what accuracy costs
  commands    the `pbrlab` command (also `python -m pbrlab`)

The public fronts: ``pbrlab.evaluate`` (and the vector helpers), ``pbrlab.scene.load_scene`` /
``parse_scene``, ``pbrlab.render.render_scene``, the pytest plugin (entry point ``pbrlab``).
Each is imported on first use (PEP 562 ``__getattr__``), so ``import pbrlab.x`` costs only
``x``: the pytest plugin and ``pbrlab --version`` load neither numpy nor moderngl.
"""

from .foundation.errors import PbrlabError
from .foundation.version import __version__

__all__ = ["evaluate", "vec2", "vec3", "vec4", "PbrlabError", "__version__"]
_FROM_EVALUATOR = ("evaluate", "vec2", "vec3", "vec4")


def __getattr__(name: str):
    if name in _FROM_EVALUATOR:
        from .gpu import evaluator
        return getattr(evaluator, name)
    raise AttributeError(f"module 'pbrlab' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_FROM_EVALUATOR))
