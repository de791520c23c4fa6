"""Evaluate a GLSL expression on the GPU for every element of numpy inputs.

    >>> evaluate("pbr_D_GGX(NdotH, alpha)", NdotH=np.linspace(0, 1, 5), alpha=0.25)

Inputs are floats (any shape) or vectors wrapped with ``vec2``/``vec3``/``vec4`` (the
last axis holds the components). They broadcast against each other like numpy arrays;
the result is float32 shaped like the broadcast, plus a trailing axis for vector results.

``language="hlsl"`` evaluates an HLSL expression over the HLSL ports (``hlsl_ports/``):
the pixel shader of ``templates/evaluate.hlsl`` goes HLSL -> SPIR-V -> GLSL 330
(``hlsl.py``: glslang's HLSL front end, spirv-cross) and then through this same evaluator,
inputs, target and readback included.

Bit-exactness: each input travels in a float32 texture read with ``texelFetch``, and the
result comes back from an RGBA32F target, so ±0, denormals, Inf and NaN pass unchanged
(see tests/harness/test_evaluator.py). Programs are cached per expression, includes,
defines and input types, so a sweep compiles once.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import moderngl
import numpy as np

from . import gl, hlsl, shaders
from .errors import PbrlabError

_IDENTIFIER = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_MAX_WIDTH = 4096  # texels per row of the input/output textures (llvmpipe allows 16384)


@dataclass(frozen=True)
class VectorInput:
    """A float vector input: ``values[..., n]`` holds the n components."""

    values: np.ndarray
    n: int


def _vector(n: int):
    def wrap(values) -> VectorInput:
        arr = np.asarray(values, dtype=np.float32)
        if arr.ndim == 0 or arr.shape[-1] != n:
            raise PbrlabError(f"vec{n} input needs a last axis of length {n}, got shape {arr.shape}")
        return VectorInput(arr, n)
    wrap.__name__ = f"vec{n}"
    wrap.__doc__ = f"Mark an array whose last axis holds vec{n} components."
    return wrap


vec2, vec3, vec4 = _vector(2), _vector(3), _vector(4)
_GLSL_TYPE = {1: "float", 2: "vec2", 3: "vec3", 4: "vec4"}
_HLSL_TYPE = {1: "float", 2: "float2", 3: "float3", 4: "float4"}
LANGUAGES = ("glsl", "hlsl")


def _template(name: str) -> str:
    return resources.files("pbrlab").joinpath("templates", name).read_text(encoding="utf-8")


def _fragment_source(expression, includes, input_types, defines, probe, include_dirs,
                     extensions=()) -> shaders.Source:
    text = _template("evaluate.frag").replace(
        "//@EXTENSIONS", "\n".join(f"#extension {name} : require" for name in extensions))
    define_lines = [f"#define {k} {v}".rstrip() for k, v in sorted(defines.items())]
    if probe:
        define_lines.append("#define PBRLAB_PROBE_WIDTH 1")
    uniforms = "\n".join(f"uniform sampler2D pbrlab_in_{name};" for name, _ in input_types)
    fetches = "\n".join(
        f"    {_GLSL_TYPE[n]} {name} = texelFetch(pbrlab_in_{name}, pbrlab_texel, 0)"
        f"{'.x' if n == 1 else '.' + 'xyzw'[:n]};"
        for name, n in input_types)
    text = (text.replace("//@DEFINES", "\n".join(define_lines))
                .replace("//@INCLUDES", "\n".join(f'#include "{inc}"' for inc in includes))
                .replace("//@UNIFORMS", uniforms)
                .replace("//@FETCHES", fetches)
                .replace("//@EXPRESSION", expression))
    return shaders.expand(text, "<evaluate>", include_dirs=include_dirs)


def _hlsl_fragment_source(expression, includes, input_types, defines, probe,
                          include_dirs) -> shaders.Source:
    """The HLSL template filled in, compiled to GLSL 330 (hlsl.py); one source string."""
    define_lines = [f"#define {k} {v}".rstrip() for k, v in sorted(defines.items())]
    if probe:
        define_lines.append("#define PBRLAB_PROBE_WIDTH 1")
    textures = "\n".join(f"Texture2D<float4> pbrlab_in_{name} : register(t{unit});"
                         for unit, (name, _) in enumerate(input_types))
    fetches = "\n".join(
        f"    {_HLSL_TYPE[n]} {name} = pbrlab_in_{name}.Load(pbrlab_texel)"
        f"{'.x' if n == 1 else '.' + 'xyzw'[:n]};"
        for name, n in input_types)
    text = (_template("evaluate.hlsl").replace("//@DEFINES", "\n".join(define_lines))
            .replace("//@INCLUDES", "\n".join(f'#include "{inc}"' for inc in includes))
            .replace("//@TEXTURES", textures)
            .replace("//@FETCHES", fetches)
            .replace("//@EXPRESSION", expression))
    glsl = hlsl.hlsl_to_glsl(text, "<evaluate>", include_dirs=include_dirs)
    return shaders.Source(glsl, ["<evaluate.hlsl, cross-compiled by spirv-cross>"])


class Evaluator:
    """Compiles and runs evaluation programs on one GL context (cached programs)."""

    def __init__(self, ctx: moderngl.Context):
        self.ctx = ctx
        self._programs: dict = {}
        self._vertex = shaders.expand(_template("fullscreen.vert"), "<fullscreen.vert>")
        self._vao_cache: dict = {}

    def _program(self, expression, includes, input_types, defines, probe, include_dirs=(),
                 extensions=(), language="glsl"):
        key = (expression, includes, input_types, tuple(sorted(defines.items())), probe,
               include_dirs, extensions, language)
        if key not in self._programs:
            if language == "hlsl":
                fragment = _hlsl_fragment_source(expression, includes, input_types, defines,
                                                 probe, include_dirs)
            else:
                fragment = _fragment_source(expression, includes, input_types, defines, probe,
                                            include_dirs, extensions)
            program = shaders.build_program(self.ctx, self._vertex, fragment)
            self._programs[key] = (program, self.ctx.vertex_array(program, []))
        return self._programs[key]

    def result_width(self, expression, includes, input_types, defines, include_dirs=(),
                     extensions=(), language="glsl") -> int:
        """Components of the expression's type (1 for float/int/bool, n for vecn)."""
        program, vao = self._program(expression, includes, input_types, defines, True,
                                     include_dirs, extensions, language)
        textures = [self.ctx.texture((1, 1), n if n != 3 else 4, dtype="f4")
                    for _, n in input_types]
        out = self._run(program, vao, input_types, textures, (1, 1))
        for tex in textures:
            tex.release()
        return int(out[0, 0, 0])

    def _run(self, program, vao, input_types, textures, size):
        for unit, ((name, _), tex) in enumerate(zip(input_types, textures)):
            tex.use(unit)
            uniform = program.get(f"pbrlab_in_{name}", None)
            if uniform is not None:  # unused inputs are optimised away
                uniform.value = unit
        target = self.ctx.texture(size, 4, dtype="f4")
        fbo = self.ctx.framebuffer([target])
        try:
            fbo.use()
            self.ctx.viewport = (0, 0) + size
            vao.render(moderngl.TRIANGLES, vertices=3)
            data = fbo.read(components=4, dtype="f4", viewport=(0, 0) + size)
        finally:
            fbo.release()
            target.release()
        return np.frombuffer(data, dtype=np.float32).reshape(size[1], size[0], 4)

    def __call__(self, expression: str, includes=None, defines=None, include_dirs=(),
                 extensions=(), language="glsl", **inputs) -> np.ndarray:
        gl.make_current(self.ctx)
        include_dirs = tuple(str(d) for d in include_dirs)
        extensions = tuple(extensions)
        if language not in LANGUAGES:
            raise PbrlabError(f"language must be one of {', '.join(LANGUAGES)}, not {language!r}")
        if language == "hlsl" and extensions:
            raise PbrlabError("extensions are GLSL #extension names; the HLSL path takes none")
        if includes is None:
            includes = (hlsl.UMBRELLA_INCLUDE if language == "hlsl" else shaders.UMBRELLA_INCLUDE,)
        includes = tuple(includes)
        defines = dict(defines or {})
        arrays, input_types = {}, []
        for name, value in inputs.items():
            if not _IDENTIFIER.match(name) or name.startswith("gl_") or name.startswith("pbrlab_"):
                raise PbrlabError(f"input name {name!r} is not usable as a {language.upper()} identifier")
            if isinstance(value, VectorInput):
                arrays[name], n = value.values, value.n
            else:
                arrays[name], n = np.asarray(value, dtype=np.float32), 1
            input_types.append((name, n))
        input_types = tuple(input_types)
        shape = np.broadcast_shapes(*[
            a.shape[:-1] if n > 1 else a.shape for (_, n), a in zip(input_types, arrays.values())
        ]) if arrays else ()
        count = int(np.prod(shape, dtype=np.int64))
        width = self.result_width(expression, includes, input_types, defines, include_dirs,
                                  extensions, language)
        if count == 0:
            return np.zeros(shape + ((width,) if width > 1 else ()), np.float32)

        cols = min(count, _MAX_WIDTH)
        rows = math.ceil(count / cols)
        textures = []
        try:
            for (name, n), arr in zip(input_types, arrays.values()):
                full = np.broadcast_to(arr, shape + ((n,) if n > 1 else ())).reshape(count, n)
                channels = 4 if n == 3 else n  # RGB32F rows are not 4-byte aligned in GL
                padded = np.zeros((rows * cols, channels), np.float32)
                padded[:count, :n] = full
                textures.append(self.ctx.texture((cols, rows), channels, padded.tobytes(), dtype="f4"))
            program, vao = self._program(expression, includes, input_types, defines, False,
                                         include_dirs, extensions, language)
            out = self._run(program, vao, input_types, textures, (cols, rows))
        finally:
            for tex in textures:
                tex.release()
        flat = out.reshape(rows * cols, 4)[:count, :width]
        return flat.reshape(shape + ((width,) if width > 1 else ())).copy()


@lru_cache(maxsize=None)
def _shared_evaluator(backend):
    return Evaluator(gl.shared_context(backend))


def evaluate(expression: str, includes=None, *, defines=None, include_dirs=(), extensions=(),
             backend=None, language="glsl", **inputs) -> np.ndarray:
    """Evaluate ``expression`` for every element of the broadcast ``inputs``.

    ``includes`` defaults to the umbrella ``pbr/pbr.glsl``; ``defines`` maps macro names
    to values; ``include_dirs`` are searched for includes before the library's glsl/
    (your own shader files); ``extensions`` names GLSL extensions to require (e.g.
    ``GL_ARB_shading_language_packing``); ``backend`` picks the GL backend (default:
    ``gl.default_backend()``); ``language="hlsl"`` takes an HLSL expression, includes
    resolved against ``include_dirs`` then ``hlsl_ports/`` (default ``pbr/pbr.hlsl``), and
    runs it through the same inputs, target and readback (module docstring).
    """
    return _shared_evaluator(backend)(expression, includes=includes, defines=defines,
                                      include_dirs=include_dirs, extensions=extensions,
                                      language=language, **inputs)
