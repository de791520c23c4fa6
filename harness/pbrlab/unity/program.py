"""Compile a surface shader's programs and feed them (the renderer's one entry to Unity).

    program = build_program(ctx, material.unity, "hlsl", "sphere", defines)
    bind(program, material, obj, frame, cache, first_unit)

HLSL: the generated text (generate.py) through glslang and spirv-cross, as every HLSL scene
program (programs.py). GLSL: the same glue around the ``port-unity`` port of the CGPROGRAM
(port.py), included as its own file so compile errors name it. Both get the harness's GLSL
vertex stage. Unity's stand-in ``.cginc`` files (``cginc/``) resolve the shader's includes.
"""

from __future__ import annotations

import atexit
import re
import shutil
import tempfile
from pathlib import Path

import numpy as np

from .. import hlsl, programs, shaders
from ..errors import PbrlabError
from ..programs import TEMPLATES, template_source
from ..programs import set_uniform as _set
from . import generate, port
from . import model as M
from .properties import TextureValue

CGINC = Path(__file__).parent / "cginc"
VERTEX = {"sphere": "sphere.vert", "mesh": "mesh.vert"}
_PROGRAMS: dict = {}
# The GLSL path's in-memory ports, written where the include resolver finds them; removed at exit.
_PORTS = Path(tempfile.mkdtemp(prefix="pbrlab-unity-ports-"))
atexit.register(shutil.rmtree, _PORTS, ignore_errors=True)
# Unity's _SpecColor when a shader's Properties lack it: Unity's legacy shaders' default
# ("Specular Color", Color) = (0.5, 0.5, 0.5, 1).
DEFAULT_SPEC_COLOR = (0.5, 0.5, 0.5, 1.0)
# unity_SpecCube0_HDR: the harness's environment is float radiance, so DecodeHDR's
# multiplier and exponent are 1 and alpha is unused.
SPECCUBE_HDR = (1.0, 1.0, 0.0, 0.0)


def fragment_text(shader: M.SurfaceShader, language: str, stem: str, defines: dict):
    """(text, include dirs) of the fragment program."""
    dirs = [TEMPLATES, CGINC, shader.path.parent]
    if shader.language == "glsl":  # a port-unity port: GLSL only, included as written
        if language == "hlsl":
            raise PbrlabError(f"surface {shader.path}: a port-unity GLSL port renders only in GLSL; "
                              "for --language hlsl name the original .shader file")
        text = generate.fragment_source(shader, "glsl", stem, f'#include "{shader.path.name}"',
                                        shader.path.name, defines)
        return text, dirs + [shader.path.parent]
    if language == "hlsl":
        return generate.fragment_source(shader, "hlsl", stem, shader.program, shader.path.name, defines), dirs
    ported = _PORTS / f"{abs(hash((str(shader.path), shader.program)))}" / (shader.path.stem + ".glsl")
    ported.parent.mkdir(parents=True, exist_ok=True)
    ported.write_text(port.port_program(shader), encoding="utf-8")
    text = generate.fragment_source(shader, "glsl", stem, f'#include "{ported.name}"', ported.name, defines)
    return text, dirs + [ported.parent]


def _vertex_stage(shader: M.SurfaceShader, language: str, defines: dict, dirs) -> shaders.Source:
    """The vertex stage running the shader's vertex: function (generate.vertex_source)."""
    display = f"{shader.path.name} (generated {language} vertex stage)"
    if language == "hlsl":
        text = generate.vertex_source(shader, "hlsl", shader.program, shader.path.name, defines)
        glsl = hlsl.cross_to_glsl(hlsl.compile_spirv(text, display, dirs, stage="vert"), plain_uniforms=True)
        # Both stages hold a `uniform _Global <id>;` of their own members: rename this one so
        # the program links (programs.set_uniform then sets the member in each stage).
        instance = re.search(r"uniform _Global (\w+);", glsl)
        if instance:
            glsl = re.sub(r"\b_Global\b", "_GlobalVertex", glsl)
            glsl = re.sub(r"\b" + instance.group(1) + r"\b", "pbrlab_vertex_globals", glsl)
        return shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])
    ported = dirs[-1] / (shader.path.name if shader.language == "glsl" else shader.path.stem + ".glsl")
    text = generate.vertex_source(shader, "glsl", f'#include "{ported.name}"', ported.name, defines)
    return shaders.expand(text, display, include_dirs=dirs)


def build_program(ctx, shader: M.SurfaceShader, language: str, stem: str, defines: dict):
    """The program of ``shader`` for a sphere or mesh draw; with a vertex: function always
    the mesh one (spheres are tessellated: tessellate.py)."""
    if shader.vertex is not None:
        stem = "mesh"
    key = (id(ctx), str(shader.path), shader.program, language, stem, tuple(sorted(defines.items())))
    if key not in _PROGRAMS:
        text, dirs = fragment_text(shader, language, stem, defines)
        display = f"{shader.path.name} (generated {language} {stem} program)"
        if language == "hlsl":
            glsl = hlsl.hlsl_to_glsl(text, display, dirs, plain_uniforms=True)
            fragment = shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])
        else:
            fragment = shaders.expand(text, display, include_dirs=dirs)
        if shader.vertex is not None:
            vertex = _vertex_stage(shader, language, defines, dirs)
        else:
            vertex = template_source(VERTEX[stem], defines)
        program = shaders.build_program(ctx, vertex, fragment)
        members: dict = {}
        for gl_name in (n for n in program if "." in n):
            members.setdefault(gl_name.split(".", 1)[1], []).append(gl_name)
        program.extra = {"members": members, "shader": str(shader.path)}
        _PROGRAMS[key] = program
    return _PROGRAMS[key]


def object_matrix(obj) -> np.ndarray:
    """Object to world: a sphere's object space is the unit sphere at its centre."""
    if obj.sphere is not None:
        centre, radius = obj.sphere
        m = np.diag([radius, radius, radius, 1.0])
        m[:3, 3] = centre
        return m
    return obj.transform


def _column_major(m: np.ndarray) -> tuple:
    return tuple(np.asarray(m, np.float64).T.reshape(-1))


def bind(program, material, obj, frame, cache, environment_cube, first_unit: int) -> None:
    """Unity's globals, the material's property values, _ST and textures."""
    model = object_matrix(obj)
    _set(program, "_Time", (0.0, 0.0, 0.0, 0.0))
    _set(program, "_SinTime", (0.0, 0.0, 0.0, 0.0))
    _set(program, "_CosTime", (1.0, 1.0, 1.0, 1.0))
    _set(program, "unity_DeltaTime", (0.0, 0.0, 0.0, 0.0))
    _set(program, "_WorldSpaceCameraPos", tuple(frame.position))
    _set(program, "unity_ObjectToWorld", _column_major(model))
    _set(program, "unity_WorldToObject", _column_major(np.linalg.inv(model)))
    _set(program, "unity_MatrixVP", _column_major(frame.view_proj))
    w, h = frame.size
    _set(program, "_ScreenParams", (float(w), float(h), 1.0 + 1.0 / w, 1.0 + 1.0 / h))
    _set(program, "_ProjectionParams", (1.0, 0.0, 0.0, 0.0))
    _set(program, "unity_SpecCube0_HDR", SPECCUBE_HDR)
    if "_SpecColor" not in material.properties:
        _set(program, "_SpecColor", DEFAULT_SPEC_COLOR)
    unit = first_unit
    for name, value in sorted(material.properties.items()):
        kind = material.unity.properties[name].kind  # properties.resolve: one value per property
        if isinstance(value, TextureValue):
            if _bind_texture(program, name, kind, unit):  # else the compiler dropped the sampler
                if value.cube:
                    environment_cube().use(unit)
                elif value.path is not None:
                    cache.texture(value.path, value.srgb).use(unit)
                else:
                    cache.constant_texture(value.texel).use(unit)
                unit += 1
            _bind_vector(program, f"{name}_ST", f"{kind} property {name}'s tiling/offset _ST", value.st)
        elif kind in ("Color", "Vector"):
            _bind_vector(program, name, f"{kind} property {name}", value)
        else:
            _bind_number(program, name, kind, value)


# How Unity binds a property to the uniform of its name: a Float/Range/Int to a float (or an
# int, truncated as a D3D cast does), a Color/Vector to a float4, float3, float2 or float (the
# leading components: `half3 _Emission;` takes rgb), a texture to a sampler of its dimension.
_FLOAT_VECTORS = {"float": 1, "vec2": 2, "vec3": 3, "vec4": 4}
_SAMPLERS = {"2D": ("sampler2D",), "Cube": ("samplerCube",), "3D": ("sampler3D", "sampler2D")}


def _mismatch(program, what: str, name: str, uniform) -> PbrlabError:
    return PbrlabError(f"{_shader_name(program)}: {what} cannot be bound to the uniform '{name}', "
                       f"declared {programs.uniform_type(uniform)} in the program")


def _shader_name(program) -> str:
    return (getattr(program, "extra", None) or {}).get("shader", "surface shader")


def _bind_vector(program, name: str, what: str, value) -> None:
    """A Color/Vector (or a texture's _ST) to a float4/3/2/1 uniform: its leading components."""
    uniforms = programs.uniforms_named(program, name)
    for uniform in uniforms:
        if programs.uniform_type(uniform) not in _FLOAT_VECTORS:
            raise _mismatch(program, f"{what} (4 numbers)", name, uniform)
    if uniforms:
        n = _FLOAT_VECTORS[programs.uniform_type(uniforms[0])]
        _set(program, name, tuple(value[:n]) if n > 1 else value[0])


def _bind_number(program, name: str, kind: str, value: float) -> None:
    uniforms = programs.uniforms_named(program, name)
    for uniform in uniforms:
        gl_type = programs.uniform_type(uniform)
        if gl_type not in ("float", "int", "uint", "bool"):
            raise _mismatch(program, f"{kind} property {name} (a number)", name, uniform)
    if uniforms:
        gl_type = programs.uniform_type(uniforms[0])
        _set(program, name, value if gl_type == "float" else
             bool(value) if gl_type == "bool" else int(value))


def _bind_texture(program, name: str, kind: str, unit: int) -> bool:
    """The texture unit to a sampler of the property's dimension; False if none is kept."""
    uniforms = programs.uniforms_named(program, name)
    for uniform in uniforms:
        if programs.uniform_type(uniform) not in _SAMPLERS.get(kind, ("sampler2D",)):
            raise _mismatch(program, f"{kind} texture property {name}", name, uniform)
    if uniforms:
        _set(program, name, unit)
    return bool(uniforms)
