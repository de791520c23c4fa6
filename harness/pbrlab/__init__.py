"""pbrlab: the headless harness that proves the pbrlab GLSL/HLSL shading library.

The pieces, one job each:
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
"""

from .evaluator import evaluate, vec2, vec3, vec4
from .errors import PbrlabError

__all__ = ["evaluate", "vec2", "vec3", "vec4", "PbrlabError"]
__version__ = "0.1.0"
