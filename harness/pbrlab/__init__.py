"""pbrlab: the headless harness that proves the pbrlab GLSL/HLSL shading library.

The pieces, one job each (docs/layers.md groups them into layers, bottom up):
  gl          the GL context factory (EGL or OSMesa over Mesa llvmpipe)
  shaders     #include resolution, #line mapping, amalgamation
  evaluator   evaluate(expr, **inputs): a GLSL expression over numpy arrays on the GPU
  reference   float64 numpy references of the library's formulas
  targets     sRGB and HDR render targets, readback
  scene       the JSON scene format and its validation
  render      GPU rendering of scenes;  cpu_render: the float64 numpy ray-tracer
  images      lossless image I/O (OpenImageIO), atomic writes
  compare     image metrics and tolerances;  goldens: the golden store
  cli         the `pbrlab` command

``evaluate`` and the vector helpers are imported on first use (PEP 562 ``__getattr__``), so
``import pbrlab.x`` costs only ``x``: the pytest plugin and ``pbrlab --version`` load
neither numpy nor moderngl.
"""

from .errors import PbrlabError

__all__ = ["evaluate", "vec2", "vec3", "vec4", "PbrlabError"]
__version__ = "0.1.0"
_FROM_EVALUATOR = ("evaluate", "vec2", "vec3", "vec4")


def __getattr__(name: str):
    if name in _FROM_EVALUATOR:
        from . import evaluator
        return getattr(evaluator, name)
    raise AttributeError(f"module 'pbrlab' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_FROM_EVALUATOR))
