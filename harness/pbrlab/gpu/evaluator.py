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
(see tests/gpu/test_evaluator.py). Programs are cached per expression, includes,
defines and input types, so a sweep compiles once; the cache holds the
``PROGRAMS_CACHED`` most recently used programs (older ones are released: 10,000 distinct
expressions keep the process's memory flat, benchmarks/evaluator_cache_rss.py) and an
entry is rebuilt when a file it includes changed on disk.

Inputs become float32, and what float32 cannot hold is refused (PbrlabError naming the
input), never rounded in silence: integers are taken when float32 holds them exactly (all
of |n| <= 2^24, and larger ones that happen to be exact), floats are rounded to the
nearest float32 (that is the evaluator's contract) unless finite and beyond the float32
range (|x| > 3.4028235e38, which would become Inf; Inf and NaN themselves pass), booleans
are 0 and 1; complex numbers, None, strings and other objects are refused. Broadcasts of
more than ``CHUNK`` elements run as several draws of at most that many.
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
from ..foundation import safe_paths
from ..foundation.errors import PbrlabError
from ..foundation.file_identity import FileCache, include_closure

_IDENTIFIER = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_MAX_WIDTH = 4096  # texels per row of the input/output textures (llvmpipe allows 16384)
# Elements per draw: 1024 rows of _MAX_WIDTH, i.e. at most 64 MiB per vec4 input texture
# and as much for the RGBA32F target; larger broadcasts are split into draws of this size.
CHUNK = _MAX_WIDTH * 1024
# Programs kept per evaluator (each expression takes two: the width probe and the
# evaluation), about 0.5 MB of llvmpipe code each (issue 14: 2,002 programs, 1,186 MB).
PROGRAMS_CACHED = 128
FLOAT32_MAX = float(np.finfo(np.float32).max)
_EXACT_INT = 2 ** 24  # float32's 24-bit significand holds every integer up to this


def as_float32(name: str, value) -> np.ndarray:
    """``value`` as a float32 array, refusing what float32 cannot hold (module doc)."""
    if value is None:
        raise PbrlabError(f"input {name!r} is None; give a number or an array of numbers")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError) as exc:  # ragged nested lists
        raise PbrlabError(f"input {name!r} is not a rectangular array of numbers ({exc})") from None
    kind = arr.dtype.kind
    if kind == "b":
        return arr.astype(np.float32)
    if kind in "iu":
        out = arr.astype(np.float32)
        big = np.abs(arr.astype(np.float64)) > _EXACT_INT
        if big.any():
            for original, converted in zip(arr[big].tolist(), out[big].tolist()):
                if int(converted) != original:
                    raise PbrlabError(
                        f"input {name!r}: the integer {original} has no exact float32 value "
                        f"(nearest: {int(converted)}); float32 holds every integer up to "
                        f"2^24 = {_EXACT_INT}")
        return out
    if arr.dtype == np.float32:  # every float32 value is the input as given: no copy, no check
        return arr
    if kind == "f":
        wide = arr.astype(np.float64, copy=False)
        over = np.isfinite(wide) & (np.abs(wide) > FLOAT32_MAX)
        if over.any():
            raise PbrlabError(f"input {name!r}: {float(wide[over].flat[0]):g} is beyond the float32 "
                              f"range (|x| <= {FLOAT32_MAX:.8g}) and would become Inf")
        return arr.astype(np.float32)
    what = {"c": "complex numbers", "U": "strings", "S": "bytes", "O": "Python objects",
            "M": "dates", "m": "time spans", "V": "structured records"}.get(kind, arr.dtype.name)
    raise PbrlabError(f"input {name!r} holds {what} ({arr.dtype}); the evaluator takes real "
                      "numbers (float32 on the GPU)")


@dataclass(frozen=True)
class VectorInput:
    """A float vector input: ``values[..., n]`` holds the n components (as given; made
    float32 by the evaluator, which names the input when it refuses a value)."""

    values: object
    n: int


def _vector(n: int):
    def wrap(values) -> VectorInput:
        arr = as_float32(f"vec{n}", values)  # checked again under the input's name
        if arr.ndim == 0 or arr.shape[-1] != n:
            raise PbrlabError(f"vec{n} input needs a last axis of length {n}, got shape {arr.shape}")
        return VectorInput(values, n)
    wrap.__name__ = f"vec{n}"
    wrap.__doc__ = f"Mark an array whose last axis holds vec{n} components."
    return wrap


# One assignment each, so that the API reference (docs/api/evaluate.md) reads the three
# from the source with their docstrings.
vec2 = _vector(2)
"""``vec2(values)``: mark an array whose last axis holds vec2 components (a VectorInput)."""
vec3 = _vector(3)
"""``vec3(values)``: mark an array whose last axis holds vec3 components (a VectorInput)."""
vec4 = _vector(4)
"""``vec4(values)``: mark an array whose last axis holds vec4 components (a VectorInput)."""
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
    return shaders.Source(glsl, ["<evaluate.hlsl, cross-compiled by spirv-cross>"],
                          include_closure(text, [*include_dirs, hlsl.HLSL_ROOT]))


class Evaluator:
    """Compiles and runs evaluation programs on one GL context (cached programs)."""

    def __init__(self, ctx: moderngl.Context):
        self.ctx = ctx
        self._programs = FileCache(PROGRAMS_CACHED, _release_program)
        self._vertex = shaders.expand(_template("fullscreen.vert"), "<fullscreen.vert>")
        self._vao_cache: dict = {}
        self._widths: dict = {}  # probe key -> (the probe program it was measured with, width)

    def _program(self, expression, includes, input_types, defines, probe, include_dirs=(),
                 extensions=(), language="glsl"):
        key = (expression, includes, input_types, tuple(sorted(defines.items())), probe,
               include_dirs, extensions, language)

        def build():
            if language == "hlsl":
                fragment = _hlsl_fragment_source(expression, includes, input_types, defines,
                                                 probe, include_dirs)
            else:
                fragment = _fragment_source(expression, includes, input_types, defines, probe,
                                            include_dirs, extensions)
            program = shaders.build_program(self.ctx, self._vertex, fragment)
            return (program, self.ctx.vertex_array(program, [])), fragment.paths

        # The caller's own shader files and include folders: the folder rule is for a model's
        # files (safe_paths), and a library symlinked into a project is no model's link out.
        with safe_paths.allowing_outside():
            return self._programs.get(key, build)

    def result_width(self, expression, includes, input_types, defines, include_dirs=(),
                     extensions=(), language="glsl") -> int:
        """Components of the expression's type (1 for float/int/bool, n for vecn), from a 1x1
        draw of the probe program, kept while the cache keeps that program (a file it includes
        changed on disk: the program is rebuilt, and the width measured again)."""
        program, vao = self._program(expression, includes, input_types, defines, True,
                                     include_dirs, extensions, language)
        key = (expression, includes, input_types, tuple(sorted(defines.items())), include_dirs,
               extensions, language)
        known = self._widths.get(key)
        if known is not None and known[0] is program:
            return known[1]
        textures = [self.ctx.texture((1, 1), n if n != 3 else 4, dtype="f4")
                    for _, n in input_types]
        out = self._run(program, vao, input_types, textures, (1, 1))
        for tex in textures:
            tex.release()
        if len(self._widths) >= 4 * PROGRAMS_CACHED:  # as bounded as the programs it names
            self._widths.clear()
        self._widths[key] = (program, int(out[0, 0, 0]))
        return self._widths[key][1]

    def _run(self, program, vao, input_types, textures, size, channels=4):
        for unit, ((name, _), tex) in enumerate(zip(input_types, textures)):
            tex.use(unit)
            uniform = program.get(f"pbrlab_in_{name}", None)
            if uniform is not None:  # unused inputs are optimised away
                uniform.value = unit
        # R32F / RG32F / RGBA32F: only the result's components are stored and read back (a
        # float target keeps every float32 bit of the components it has; RGB32F is not
        # colour-renderable in GL 3.3, so a vec3 result takes RGBA32F)
        target = self.ctx.texture(size, channels, dtype="f4")
        fbo = self.ctx.framebuffer([target])
        out = np.empty((size[1], size[0], channels), np.float32)
        try:
            fbo.use()
            self.ctx.viewport = (0, 0) + size
            vao.render(moderngl.TRIANGLES, vertices=3)
            fbo.read_into(out, components=channels, dtype="f4", viewport=(0, 0) + size)
        finally:
            fbo.release()
            target.release()
        return out

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
                arrays[name], n = as_float32(name, value.values), value.n
            else:
                arrays[name], n = as_float32(name, value), 1
            input_types.append((name, n))
        input_types = tuple(input_types)
        shapes = {name: a.shape[:-1] if n > 1 else a.shape
                  for (name, n), a in zip(input_types, arrays.values())}
        try:
            shape = np.broadcast_shapes(*shapes.values()) if arrays else ()
        except ValueError:
            raise PbrlabError("inputs do not broadcast against each other: " + ", ".join(
                f"{name} {shape}" for name, shape in shapes.items())) from None
        count = int(np.prod(shape, dtype=np.int64))
        width = self.result_width(expression, includes, input_types, defines, include_dirs,
                                  extensions, language)
        if count == 0:
            return np.zeros(shape + ((width,) if width > 1 else ()), np.float32)

        flats = [np.broadcast_to(arr, shape + ((n,) if n > 1 else ())).reshape(count, n)
                 for (_, n), arr in zip(input_types, arrays.values())]
        program, vao = self._program(expression, includes, input_types, defines, False,
                                     include_dirs, extensions, language)
        result = np.empty((count, width), np.float32)
        for start in range(0, count, CHUNK):
            stop = min(start + CHUNK, count)
            result[start:stop] = self._run_chunk(program, vao, input_types,
                                                 [f[start:stop] for f in flats],
                                                 4 if width == 3 else width)[:, :width]
        return result.reshape(shape + ((width,) if width > 1 else ()))

    def _run_chunk(self, program, vao, input_types, flats, channels=4) -> np.ndarray:
        """One draw over ``flats`` (each count x n, count <= CHUNK): count x channels results."""
        count = len(flats[0]) if flats else 1
        cols = min(count, _MAX_WIDTH)
        rows = math.ceil(count / cols)
        textures = []
        try:
            for (name, n), full in zip(input_types, flats):
                if n == 3:  # RGB32F rows are not 4-byte aligned in GL: padded to RGBA
                    padded = np.zeros((rows * cols, 4), np.float32)
                    padded[:count, :n] = full
                    textures.append(self.ctx.texture((cols, rows), 4, padded, dtype="f4"))
                    continue
                # the rows the elements fill, written from the input itself (no padded copy),
                # then the last row's remainder; the texels past the end are never read back
                data = np.ascontiguousarray(full, dtype=np.float32)
                texture = self.ctx.texture((cols, rows), n, dtype="f4")
                textures.append(texture)
                whole = count // cols
                if whole:
                    texture.write(data[:whole * cols], viewport=(0, 0, cols, whole))
                if count > whole * cols:
                    texture.write(data[whole * cols:], viewport=(0, whole, count - whole * cols, 1))
            out = self._run(program, vao, input_types, textures, (cols, rows), channels)
        finally:
            for tex in textures:
                tex.release()
        return out.reshape(rows * cols, channels)[:count]


def _release_program(entry) -> None:
    program, vao = entry
    vao.release()
    program.release()


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
